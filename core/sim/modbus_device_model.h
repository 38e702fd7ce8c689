#pragma once
// The register side of a simulated Modbus RTU device: a HiPNUC module (v1.7.1 chapter 6 or
// v1.6.6 chapter 4, by firmware) or a HEC495 compass ("Modbus 通讯协议"). Plain value class:
// ModbusRtuServer (QModbusRtuSerialServer) asks it for registers and hands it writes.
//
// Registers follow MotionModel + SensorModel at the time of the request: acc, gyr, mag in
// the user frame (mounting), Euler angles (ENU-312) and quaternion of the output attitude,
// temperature, pressure; INCL_X/INCL_Y carry roll and pitch; HEAVE/HEAVE_PERIOD read 0
// (the motion model has no heave). HEC495: pitch, roll and heading (0..360, clockwise from
// north) as floats from 0x0004; (0x0005, 2) answers pitch as in the manual's example.
//
// Reads: a request may span registers of the map and the reserved gaps inside the sensor
// block (0x34..0x51) and the identity block (0x70..0x83), which read 0 (the manual's identity
// request covers 0x7A..0x7E and 0x83); any other address is ILLEGAL DATA ADDRESS, a count of 0
// or above 125 ILLEGAL DATA VALUE, write-only registers (CTRL, 0xA5, 0xA6) ILLEGAL DATA ADDRESS.
// Writes (HiPNUC; the HEC495 has none: ILLEGAL FUNCTION):
//   CTRL 0      running configuration -> saved
//   CTRL 1      factory configuration -> running and saved, then a reset
//   CTRL 0xFF   reset: the saved configuration becomes the running one, time restarts
//   UART1_BAUD  switches after the reply (the reply still goes at the old rate)
//   MD_ID       switches after the reply (the reply carries the old ID)
//   HEADING_MODE at once; 6-axis: heading relative to the attitude when the mode was set / at start
//   0xA5        2 or 3: level once when pitch and roll are within 15 deg of 0/0 (or 0/180); 5 cancels
//   0xA6        mounting at once (v1.6.6: 0..4; v1.7.1: a URFR code)
// Everything written is lost at a reset unless CTRL 0 saved it. A value outside the
// register's range is ILLEGAL DATA VALUE and changes nothing.
#include "model/device_identity.h"
#include "protocol/modbus/register_map.h"
#include "sim/motion_model.h"
#include "sim/sensor_model.h"

#include <Eigen/Geometry>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace imudesk::sim {

struct ModbusSimOptions {
    protocol::modbus::DeviceKind kind = protocol::modbus::DeviceKind::Hipnuc;
    std::string model = "HI14";      // HiPNUC product (PNAME gets "R3N-485")
    std::string firmware = "1.7.1";  // HiPNUC firmware: >= 1.7.1 speaks the v1.7.1 map
    int nodeId = 0;                  // 0: the device's default (80 HiPNUC, 1 HEC495)
    int baud = 0;                    // 0: the device's default (115200 HiPNUC, 9600 HEC495)
    Motion motion = Motion::Static;
    uint64_t seed = 1;
};

class ModbusDeviceModel {
public:
    struct Config {
        int nodeId = protocol::modbus::kHipnucDefaultId;
        int baud = 115200;
        int headingMode = 1;      // 1: 9-axis
        int mountingCode = 24;    // as a v1.7.1 code
        bool levelled = false;
        Eigen::Quaterniond level = Eigen::Quaterniond::Identity();
    };
    // What a write asks the serving side to do after the reply went out.
    struct Effects {
        std::optional<int> nodeId;
        std::optional<int> baud;
        bool reset = false;
    };
    struct ReadResult {
        int exception = 0; // QModbusPdu::ExceptionCode, 0 = none
        std::vector<uint16_t> values;
    };
    struct WriteResult {
        int exception = 0;
        Effects effects;
    };

    explicit ModbusDeviceModel(ModbusSimOptions options = {});

    ReadResult read(uint16_t start, uint16_t count, int64_t nowUs);
    WriteResult write(uint16_t address, uint16_t value, int64_t nowUs);
    // Restart from the saved configuration (also what CTRL 0xFF does).
    void reset(int64_t nowUs);

    protocol::modbus::DeviceKind kind() const { return m_options.kind; }
    model::ManualEdition edition() const { return m_edition; }
    const Config &running() const { return m_running; }
    const Config &saved() const { return m_saved; }
    Config factory() const;
    std::string productName() const;
    std::string serial() const { return m_serial; }
    uint16_t swVersion() const;
    uint64_t resets() const { return m_resets; }
    uint64_t reads() const { return m_reads; }
    uint64_t writes() const { return m_writes; }

    // The output attitude (user frame, level and heading mode applied) at a time.
    Eigen::Quaterniond attitudeAt(int64_t nowUs) const;

private:
    std::optional<uint16_t> registerAt(uint16_t address, int64_t nowUs);
    void refreshSnapshot(int64_t nowUs);
    Eigen::Matrix3d userFromSensor() const;
    Eigen::Quaterniond rawAttitudeAt(int64_t nowUs) const; // before the heading mode

    ModbusSimOptions m_options;
    model::ManualEdition m_edition = model::ManualEdition::V171;
    model::FirmwareVersion m_firmware;
    MotionModel m_motion;
    SensorModel m_sensor;
    std::string m_serial;
    Config m_running, m_saved;
    int64_t m_startUs = 0;
    double m_yawRefDeg = 0; // 6-axis: heading when the mode was set or the device started

    int64_t m_snapshotUs = -1;
    std::vector<uint16_t> m_sensorRegs; // 0x34..0x51
    std::vector<uint16_t> m_hecRegs;    // 0x04..0x09
    uint64_t m_resets = 0, m_reads = 0, m_writes = 0;
};

} // namespace imudesk::sim
