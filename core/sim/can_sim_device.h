#pragma once
// The protocol side of a simulated CAN device, without any I/O: frames in (handle), frames
// out (replies, and poll() for what is due at time t). Models a HiPNUC module speaking J1939
// (v1.7.1 chapter 7) or CANopen (chapter 8; v1.6.6 chapter 5 for firmware 1.6.6), or a Witlink
// HEC495 on CAN (standard frames, or the extended-frame variant 0x18FA.... when the protocol
// is J1939). Settings live in RAM; "save" copies them to flash, a reset or power cycle loads
// flash, so node ID and baud changes take effect after save + reset as the manuals say
// (HEC495 stores its writes at once and applies node and baud at the next power cycle).
// J1939 also answers the registers 7.22.41 maps to the Modbus register list (UART1_BAUD, MD_ID,
// HEADING_MODE, the sensor block 0x34..0x51, PNAME..SN 0x70..0x82, URFR 0xA6), each J1939
// register one Modbus register in VAL, as ModbusDeviceModel holds them.
#include "can_bootloader.h"
#include "modbus_device_model.h"
#include "motion_model.h"
#include "protocol/can/can_decoder.h"
#include "protocol/can/can_frame.h"
#include "sensor_model.h"

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace imudesk::sim {

struct CanSimOptions {
    protocol::can::CanProtocol protocol = protocol::can::CanProtocol::J1939; // J1939 or CanOpen
    bool hec495 = false;
    int node = -1;             // -1: the device's default (HiPNUC 8, HEC495 5)
    std::string firmware = "1.7.1";
    bool canFd = false;        // HiPNUC J1939: also send the 64-byte PGN 0xFF5A
    Motion motion = Motion::Static;
    uint64_t seed = 1;
};

class CanSimDevice {
public:
    struct HipnucConfig {
        int node = 8;
        uint32_t baudCode = 2; // 500K
        bool outputEnabled = true;
        std::map<uint32_t, uint32_t> pgnIntervalMs; // 0 = off
        std::array<uint16_t, 6> tpdoPeriodMs{10, 10, 10, 10, 50, 10};
        std::array<uint8_t, 6> tpdoType{0xFE, 0xFE, 0xFE, 0xFE, 0xFE, 0xFE};
        uint16_t heartbeatMs = 0;
        uint32_t inclSignX = 0, inclSignY = 0;
    };
    struct Hec495Config {
        int node = 5;
        uint32_t baudCode = 2;  // 250K
        uint32_t pdoMode = 0;   // float
        uint32_t heartbeatN = 9;
        bool pdoStarted = true;
        uint32_t rateCode = 1;  // 5 Hz
        uint32_t workMode = 2;
    };

    explicit CanSimDevice(CanSimOptions options = {});

    const CanSimOptions &options() const { return m_options; }
    bool isHec495() const { return m_options.hec495; }
    bool isJ1939() const { return m_options.protocol == protocol::can::CanProtocol::J1939; }
    int node() const;          // the address in use now
    int bitrate() const;       // the CAN bit rate in use now
    const HipnucConfig &hipnuc() const { return m_ram; }
    const Hec495Config &hec() const { return m_hec; }
    uint8_t nmtState() const { return m_nmtState; }

    // A frame from the bus at tSeconds; returns what the device sends in answer.
    std::vector<protocol::can::CanFrame> handle(const protocol::can::CanFrame &in, double tSeconds);
    // Everything whose time has come at tSeconds (periodic data, heartbeats, boot-up).
    std::vector<protocol::can::CanFrame> poll(double tSeconds);
    // Power cycle: loads the saved settings, restarts the schedule, sends boot-up (CANopen).
    // A HiPNUC CANopen module without a valid application starts in its bootloader instead.
    void powerCycle(double tSeconds);

    // HiPNUC CANopen: the CAN bootloader (firmware update over SDO 0x1F51, notes 4.5) and its
    // flash. 0x1F51:05 to the application enters it; 0x1F51:09 starts the application, which
    // then reports the version its image carries (KbootBootloader::kVersionMarker), if any.
    CanBootloader &bootloader() { return m_boot; }
    bool inBootloader() const { return m_inBootloader; }
    // The firmware version the application reports (0x1018:3, see readHipnucObject).
    const std::string &firmware() const { return m_options.firmware; }

    // The true sample at tSeconds (after attitude zeroing), in ImuDesk's units.
    model::Sample sampleAt(double tSeconds);
    // The HEC495's PDO contents: heading clockwise from north, relative magnetic field.
    model::Sample hec495SampleAt(double tSeconds);

    static HipnucConfig hipnucDefaults(bool canFd);

private:
    using Frame = protocol::can::CanFrame;
    std::vector<Frame> handleJ1939(const Frame &in, double t);
    std::vector<Frame> handleCanOpen(const Frame &in, double t);
    std::vector<Frame> handleHec495(const Frame &in, double t);
    bool writeHipnucObject(uint16_t index, uint8_t sub, uint32_t value, uint32_t *abort, double t, bool *resetAfter);
    bool readHipnucObject(uint16_t index, uint8_t sub, uint32_t *value, int *size, uint32_t *abort) const;
    Frame tpdoFrame(int channel, double t);
    void rescheduleAll(double t);
    bool due(const std::string &key, double periodMs, double t);
    void attitudeReset(uint32_t mode, double t);
    std::vector<Frame> pollBootloader(double t);

    CanSimOptions m_options;
    MotionModel m_motion;
    SensorModel m_sensor;
    HipnucConfig m_ram, m_flash;
    Hec495Config m_hec, m_hecFlash;
    bool m_hecExtFormat2 = false;
    int m_activeNode = 8;
    uint32_t m_activeBaudCode = 2;
    uint8_t m_nmtState = 0x05;
    bool m_bootPending = true;
    std::array<uint32_t, 6> m_syncCount{};
    std::map<std::string, double> m_nextDueMs;
    double m_yawOffset = 0, m_rollOffset = 0, m_pitchOffset = 0;
    CanBootloader m_boot;
    bool m_inBootloader = false;
    // J1939 7.22.41: the registers of the Modbus register list (6.16), one J1939 register each:
    // the same register side as the Modbus simulator's, on the same motion.
    ModbusDeviceModel m_registers;
};

} // namespace imudesk::sim
