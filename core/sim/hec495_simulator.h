#pragma once
// A simulated Witlink HEC495 compass on its RS-232/RS-485 UART, as the manual's "通讯协议"
// and calibration chapters describe. Plain value class (no event loop); PtySimulator serves
// it on a pseudo-terminal through SimulatedSerialDevice.
//
// Behaviour
//   * Frames 77 LEN ADDR CMD DATA SUM (protocol/witlink). A frame is answered when its
//     address is the module's, or when it is "query address" (0x1F) sent to 0x00 (2.17).
//     Unknown commands get no reply; a known command with a bad argument gets status FF.
//   * Settings (baud, address, declination, output rate and content) change at once and are
//     lost at power-off unless "save settings" (0x0A) follows (2.18). Factory reset (0x0E)
//     writes the defaults (9600, address 0, declination 0, question/answer, content 0) to
//     the running and the saved settings; the reply goes out at the old baud. It keeps the
//     magnetic calibration (that is cleared with 0x10).
//   * Baud (0x0B): the reply is sent at the old rate, then the new rate applies (2.13).
//   * Set address (0x0F): the reply carries address FF (as 2.16 prints it).
//   * Auto-output (0x0C) at 5-100 Hz, or question/answer (0). With auto-output configured
//     the module is silent for kQuietAfterPowerOnUs after power-on (2.14).
//     Content (0x49): 00 the 0x84 angles frame, 01 the 0x14 record with the uncompensated
//     magnetometer ("internal"), 02 the 0x14 record, 03 NMEA 0183 $HCHDT (true heading).
//   * UART timing: the module sends at most baud/10 bytes per second; a chunk (frame, reply,
//     sentence) is handed out when its last byte has been sent, as a receiver gets it. A
//     data frame that would wait more than kMaxBacklogUs for the line is dropped.
//   * RS-485 (Options::rs485): half duplex, so a command that arrives while the module is
//     transmitting is lost (2.14 advises repeating commands); RS-232 hears everything.
//   * Calibration (Hec495Calibration): the five methods; an automatically collected point
//     and the answer to "collect point" are 0x66 frames (15 bytes: the raw field as three
//     floats, in the field's relative unit, and three zero bytes; then the point count).
//     Stop (0x12) abandons the run (reply printed as 72). Save (0x09) fits, applies the
//     hard-iron offset to the heading from then on, keeps it over power cycles and replies
//     89 + fit error + points, or 89 FF. The calibration start reply is 88 (as 2.8 prints it).
//
// Output values come from MotionModel + SensorModel (the module's own hard and soft iron).
// Pitch and roll are the true ENU-312 angles; heading is tilt-compensated from the
// magnetometer after the saved hard-iron correction, plus the declination, clockwise from
// north: so an uncalibrated module shows the heading error of its iron. Angles frames carry
// heading 0..360, the record +-180. The record's magnetometer is relative (horizontal
// field = 1), time is ms since power-on.
//
// setPose() stands for an operator holding the compass in a pose (e.g. the calibration
// tables); the motion model drives it otherwise.
#include "protocol/witlink/commands.h"
#include "protocol/witlink/frame.h"
#include "protocol/witlink/frame_decoder.h"
#include "sim/hec495_calibration.h"
#include "sim/motion_model.h"
#include "sim/sensor_model.h"
#include "sim/simulated_serial_device.h"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace imudesk::sim {

struct Hec495Options {
    int baud = 9600;       // saved settings at construction
    uint8_t address = 0x00;
    int rateHz = 0;        // 0: question/answer
    protocol::witlink::OutputContent content = protocol::witlink::OutputContent::Default;
    Motion motion = Motion::Static;
    uint64_t seed = 1;
    bool rs485 = false;
    bool calibrated = false; // calibrated and saved before: the hard iron of its sensor corrected
    bool echo = false;       // a 2-wire RS-485 adapter: the host hears what it sends, at once
    double headingBiasDeg = 0; // a compass whose heading is off by this much (issue 55, verify)
};

class Hec495Simulator : public SimulatedSerialDevice {
public:
    static constexpr int64_t kQuietAfterPowerOnUs = 3000000;
    static constexpr int64_t kTickUs = 10000;      // calibration bookkeeping
    static constexpr int64_t kMaxBacklogUs = 60000; // a data frame that would wait longer is dropped
    static constexpr double kFieldUnitUt = 28.0;    // relative unit: the horizontal field
    static constexpr int64_t kRxIdleUs = 20000;     // a pause this long ends an unfinished input frame

    struct Settings {
        int baud = 9600;
        uint8_t address = 0;
        double declination = 0; // deg
        int rateHz = 0;
        protocol::witlink::OutputContent content = protocol::witlink::OutputContent::Default;
        friend bool operator==(const Settings &, const Settings &) = default;
    };
    // What the module outputs at an instant.
    struct Reading {
        double pitch = 0, roll = 0, heading = 0; // heading 0..360
        Eigen::Vector3d acc, gyr;                // G, deg/s
        Eigen::Vector3d rawMag, mag;             // uT: as measured / after the calibration
        double magRoll = 0;
        uint32_t timeMs = 0;
    };

    explicit Hec495Simulator(Hec495Options options = {});

    void receive(const uint8_t *data, size_t n) override;
    void advanceTo(int64_t nowUs) override;
    std::vector<SerialSegment> takeOutputSegments() override;
    int baud() const override { return m_running.baud; }
    std::string productName() const override { return "HEC495"; }

    // All bytes sent up to now (tests).
    std::vector<uint8_t> takeOutput();
    void powerCycle();
    void setPose(std::optional<Hec495Calibration::Pose> pose) { m_pose = pose; }

    const Settings &runningSettings() const { return m_running; }
    const Settings &savedSettings() const { return m_saved; }
    static Settings factorySettings() { return {}; }
    const Hec495Calibration &calibration() const { return m_calibration; }
    bool calibrated() const { return m_calibrated; }
    const Eigen::Vector3d &hardIronCorrection() const { return m_hardIron; }
    float lastFitError() const { return m_lastFitError; }
    const SensorModel &sensorModel() const { return m_sensor; }
    Reading readingAt(int64_t tUs);
    // The true compass heading (deg, 0..360) of the motion, without declination.
    double trueHeadingAt(int64_t tUs) const;
    int64_t nowUs() const { return m_nowUs; }
    uint64_t framesQueued() const { return m_framesQueued; }
    uint64_t framesDropped() const { return m_dropped; }
    uint64_t commandsLost() const { return m_commandsLost; }
    const protocol::witlink::FrameDecoder &inputDecoder() const { return m_decoder; }

private:
    void handle(const protocol::witlink::Frame &f);
    void reply(const protocol::witlink::Frame &f);
    void send(std::vector<uint8_t> bytes, bool data);
    void emitOutput(int64_t t);
    void calibrationTick(int64_t t);
    void scheduleOutput(int64_t fromUs);
    Hec495Calibration::Pose poseAt(int64_t tUs) const;
    MotionState motionAt(int64_t tUs) const;
    std::vector<uint8_t> recordFrame(const Reading &r, bool raw) const;
    void sendPoint(const Eigen::Vector3d &rawMag);

    Hec495Options m_options;
    MotionModel m_motion;
    SensorModel m_sensor;
    protocol::witlink::FrameDecoder m_decoder;
    Settings m_running, m_saved;
    Hec495Calibration m_calibration;
    bool m_calibrated = false;
    Eigen::Vector3d m_hardIron = Eigen::Vector3d::Zero();
    float m_lastFitError = 0;
    std::optional<Hec495Calibration::Pose> m_pose;

    int64_t m_nowUs = 0;
    int64_t m_lastRxUs = 0;
    int64_t m_powerOnUs = 0;
    int64_t m_nextOutputUs = -1;
    int64_t m_nextTickUs = kTickUs;
    int64_t m_sampleUs = -1;
    SensorReading m_sample;

    double m_lineFreeUs = 0;
    uint64_t m_nextChunk = 1;
    uint64_t m_framesQueued = 0;
    uint64_t m_dropped = 0;
    uint64_t m_commandsLost = 0;
    struct Timed {
        int64_t releaseUs = 0; // when the last byte has left the UART
        SerialSegment segment;
    };
    std::vector<Timed> m_out; // in release order
};

} // namespace imudesk::sim
