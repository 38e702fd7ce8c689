#pragma once
// A simulated HiPNUC IMU module (serial/UART side) that behaves as the v1.7.1 (zh-CN)
// and v1.6.6 (zh-TW) manuals describe. Plain value class, no event loop: the owner
// feeds host bytes with receive(), moves simulated time with advanceTo() and collects
// what the module sends with takeOutput(). PtySimulator serves one on a pseudo-terminal.
//
// Manual edition: firmware >= 1.7.1 speaks the v1.7.1 command set, anything older the
// v1.6.6 one (core/model/device_identity.h). MCAL commands and MAIN_STATUS need >= 1.7.0.
//
// Command rules
//   * A command is one line ending in "\r\n" (a lone "\n" is accepted too). Keywords are
//     matched case-insensitively; lines longer than 256 bytes are discarded.
//   * A reply is zero or more info lines, then "OK\r\n"; a failure is "ERR\r\n".
//   * A keyword the running firmware's manual does not have gets no reply at all
//     (silence, as the real device does for unknown commands). The keyword is the first
//     word, and for CONFIG and LOG the sub-command word(s): e.g. on 1.7.1 "CONFIG YAW",
//     "CONFIG IMU_EN_MCAL" and "LOG MAGCONFIG" are silent; on 1.6.6 "CONFIG IMU COORD",
//     "CONFIG MCAL" and "LOG MCAL" are silent.
//   * A known keyword with a bad or unsupported argument gets "ERR": out-of-range values,
//     a message the firmware does not output (LOG HI92 ... on 1.7.1, LOG HI81 ... on 1.6.6),
//     a value the edition does not list (ATT MODE 4 and ATT RST 1 on 1.6.6), and features
//     the model lacks (v1.7.1 chapter 3 table: HI02/HI50 have no magnetometer, HI02 no user
//     attitude calibration, HI02/HI50/HI7x/9x no PMUX).
//   * "LOG [COMn] <MSG> ..." accepts an optional COM1..COM4 port word; only COM1 is this UART.
//
// Effect of commands
//   * LOG ... takes effect at once and is not saved unless SAVECONFIG follows (LOG ENABLE/
//     DISABLE is never saved: output is enabled after every start). LOG DISABLE stops
//     periodic (ONTIME) and SYNC_IN (ONMARK 1) frames; ONMARK ONCE is an explicit request
//     and is answered even while output is disabled.
//   * CONFIG IMU URFR, CONFIG IMU COORD and CONFIG ATT MODE change the running
//     configuration; the output keeps using the configuration that was active at the last
//     start (save, then REBOOT, as the manual says). CONFIG ATT RST, CONFIG YAW act at once.
//     ATT RST 1 / CONFIG YAW and ATT RST 2 are runtime corrections (RST 2 is kept in the
//     running configuration and saved by SAVECONFIG); ATT RST 3 is permanent (the v1.6.6
//     manual: RST 5 does not undo it); FRESET clears it.
//   * In 6-axis modes (ATT MODE 0/4) the heading starts at 0 at every start.
//   * SERIALCONFIG: OK is sent at the old baud, then baud() switches at once.
//   * REBOOT: OK, kRebootUs of silence, then a restart from the saved configuration.
//     REBOOT BL: OK, then (after kBootloaderEntryUs) the KBOOT bootloader (sim/kboot_bootloader.h):
//     no output, ASCII ignored, KBOOT packets answered at the current baud. Its Reset command,
//     powerCycle() and a power loss restart the application if the flash holds a valid one,
//     else the bootloader (at the saved baud). The application reports the version found in
//     its image (KbootBootloader::kVersionMarker) as APP_VER; the initial image carries
//     SimOptions::firmware.
//   * FRESET: OK, factory defaults written to running and saved configuration, then REBOOT.
//
// LOG COMCONFIG reply (ImuDesk's simulator format; the manuals do not print one): one
// KEY=VALUE line per setting of the running configuration, in this order, then OK:
//   BAUD=115200
//   LOG=ENABLE | DISABLE
//   <MSG>=ONTIME <period> | ONMARK 1 | OFF     one per message of the edition:
//                                              1.6.6 HI91 HI92; 1.7.1 HI91 HI81 HI83 GGA RMC SXT
//   HI83_MAP=0x000000FF                        (1.7.1)
//   ATT_MODE=1
//   URFR=24 (1.7.1) | URFR=1,0,0,0,1,0,0,0,1 (1.6.6, C00..C22)
//   COORD=0                                    (1.7.1)
//   PMUX1=IO1  PMUX2=IO2  PMUX3=IO5            (only on models with PMUX)
//   PMUX2_DIV=1                                (1.7.1, models with PMUX)
//   IMU_EN_MCAL=1                              (1.6.6)
//
// UART model: the module sends at most baud/10 bytes per second of simulated time from
// a kTxBufferSize transmit buffer. A data frame (binary or NMEA) that does not fit is
// dropped and counted (droppedFrames()); replies are always queued. A reset (REBOOT,
// FRESET, power cycle) loses the bytes not yet sent.
//
// Output data: HI91/HI92/HI81/HI83 and GGA/RMC/SXT from MotionModel + SensorModel, each
// message in its own frame. Vectors are in the user frame (mounting), attitude from the
// true motion (no filter), Euler angles from the quaternion (appendix 1, ENU-312).
// system_time is ms since the last start, or the ms of the UTC day once a PPS input has
// aligned the clock (SimOptions::ppsInput). UTC (NMEA, HI81, HI83) is kUtcBase plus the
// simulation clock. MAIN_STATUS (firmware >= 1.7.0, else 0): UTC_UNSYNC until PPS aligned it,
// MAG_AIDING in mode 1, STATIC for a static motion (not while a fixture turns it), WB_CONV for
// 3 s after a start, MAG_DIST in mode 1 until a magnetometer calibration succeeded and while a
// magnetic disturbance is present.
//
// Magnetometer calibration (MCAL, firmware >= 1.7.0): STAT=1 while the field directions are
// collected (PROGRESS = covered direction cells, kMagCalCellsNeeded of kMagCalCells for 100;
// kMagCalTimeoutUs without reaching 100 ends in STAT=4), STAT=2 for kMagCalVerifyUs while the
// fit is checked, then STAT=3 (calibrated: MAG_DIST clears, the hard iron leaves the output) or
// STAT=4. The check: the fit removes the hard and soft iron (the simulated one recovers them
// exactly), so the field magnitudes it collected must agree; a spread (RMS about their mean)
// above kMagCalMaxSpreadUt means the field itself changed while they were collected (a
// magnetic disturbance) and the calibration fails. The v1.6.6 background calibration makes the
// same check when its coverage is complete and starts collecting again when it fails.
//
// Faults (SimOptions::faults, per instance; imudesk-cli simulate --pty --faults LIST):
//   * noisy gyro: the gyro's white noise times gyroNoiseFactor.
//   * wrong mounting: the module sits in its fixture rotated by mountingErrorDeg relative to
//     the body the motion model moves. The rotation is applied where the motion state becomes
//     the module's state (moduleStateAt), so acc, gyr, mag, the attitude of every message and
//     the calibrations all see the rotated body.
//   * magnetic disturbance: a field of magDisturbanceUt whose direction turns (about the
//     vertical every kMagDisturbanceTurnS, tilting up and down every kMagDisturbanceTiltS), as a
//     motor beside the station, added to the field the magnetometer measures (soft iron applies
//     to it as to the earth's field). MCAL collects its directions but ends in STAT=4; MAG_DIST
//     stays set.
//   * unplugged cable: only PtySimulator acts on unplugAtS (pty_simulator.h).
//   * rotation fixture (magCalFixture): the module rests at the static attitude (Motion::Static,
//     whatever SimOptions::motion says) except while an MCAL collects (STAT=1): then the fixture
//     turns it as Motion::Tumble does, counted from the MCAL start (the fixture first moves it to
//     the tumble's start attitude), so that an MCAL on a bench tray completes: about 49.5 s of
//     simulated time from START to STAT=3 with seed 1, kMagCalVerifyUs included. From STAT=2 on
//     (the manual's "hold still"), and after a failure or a restart, it is at rest at the
//     static attitude again.
#include "model/device_identity.h"
#include "model/mounting.h"
#include "protocol/hipnuc/ascii_command.h"
#include "protocol/hipnuc/payloads.h"
#include "sim/kboot_bootloader.h"
#include "sim/motion_model.h"
#include "sim/sensor_model.h"
#include "sim/sim_clock.h"

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace imudesk::sim {

// Faults of one simulated module, so that a production-station test can run several modules
// of which some fail (see "Faults" above). The defaults are a good module.
struct SimFaults {
    static constexpr double kNoisyGyroFactor = 20;      // "noisy-gyro": 0.4 deg/s per axis
    static constexpr double kWrongMountingRollDeg = 90; // "wrong-mounting": on its side
    static constexpr double kMagDisturbanceUt = 40;     // "mag-disturbance": a motor close by

    // The gyro's white noise (SensorModel::kGyrNoiseDps per axis) is multiplied by this.
    double gyroNoiseFactor = 1;
    // Roll, pitch, yaw (deg, ENU 3-1-2) of the module's body in its fixture, relative to the
    // body the motion model moves: {90, 0, 0} makes a static module read a roll of about 90 deg
    // more than the static tilt.
    std::array<double, 3> mountingErrorDeg{0, 0, 0};
    // Magnitude (uT) of a time-varying disturbing field added to the magnetometer; 0: none.
    double magDisturbanceUt = 0;
    // The USB cable is pulled this many seconds after PtySimulator::start(); < 0: never.
    double unplugAtS = -1;
    // A rotation fixture turns the module through every attitude while its MCAL collects.
    bool magCalFixture = false;
    // How LOG COMCONFIG answers (the manuals print no format but URFR=<CODE>): ImuDesk's
    // KEY=VALUE lines; Spaced: lower-case keys, " : " between key and value, three settings a
    // line separated by "; "; Unlabelled: the values alone, on one line.
    enum class ComConfigStyle { KeyValue, Spaced, Unlabelled };
    ComConfigStyle comConfigStyle = ComConfigStyle::KeyValue;
    // A module whose sensors and attitude are wrong (issue 55; SensorModel::AccError): the
    // accelerometer's bias (mg), scale error (%) and misalignment (deg: y towards x, z towards x,
    // z towards y), the gyro's scale error per axis (%, on top of SimOptions::gyroScaleError),
    // offsets added to the attitude it reports (roll, pitch, heading clockwise; deg) and a lag
    // of its attitude behind the motion (ms).
    std::array<double, 3> accBiasMg{0, 0, 0};
    std::array<double, 3> accScalePct{0, 0, 0};
    std::array<double, 3> accMisalignmentDeg{0, 0, 0};
    std::array<double, 3> gyroScalePct{0, 0, 0};
    std::array<double, 3> gyroMisalignmentDeg{0, 0, 0}; // as accMisalignmentDeg
    std::array<double, 3> attitudeBiasDeg{0, 0, 0};
    double filterLagMs = 0;

    friend bool operator==(const SimFaults &, const SimFaults &) = default;
};

// Reads a comma-separated fault list (case-insensitive words, blanks around items ignored):
//   noisy-gyro        gyroNoiseFactor = kNoisyGyroFactor      noisy-gyro=F      factor F >= 0
//   wrong-mounting    mountingErrorDeg = {90, 0, 0}           mounting=R/P/Y    degrees
//   mag-disturbance   magDisturbanceUt = kMagDisturbanceUt    mag-disturbance=U uT >= 0
//   unplug=T          unplugAtS = T (seconds >= 0)            fixture           magCalFixture
//   comconfig=spaced|unlabelled   comConfigStyle (LOG COMCONFIG in another format)
//   acc-bias=X/Y/Z (mg)  acc-scale=X/Y/Z (%)  acc-misalignment=YX/ZX/ZY (deg)  acc-error=MG/PCT (all axes)
//   gyro-scale=PCT or X/Y/Z (%)  gyro-misalignment=YX/ZX/ZY (deg)  attitude-bias=R/P/H (deg, heading clockwise)
//   filter-lag=MS
// An empty text is no fault. Words not in `text` keep their value in `out`. On a word or value
// it does not accept it returns false, and *error (if given) says which and what is accepted.
bool parseSimFaults(std::string_view text, SimFaults &out, std::string *error = nullptr);
// The same faults as parseSimFaults reads them back ("" when there is none), e.g.
// "noisy-gyro=20,mounting=90/0/0,mag-disturbance=40,unplug=2.5,fixture".
std::string simFaultsText(const SimFaults &faults);
// The accelerometer's errors the faults give (SensorModel units: G, fractions, radians).
SensorModel::AccError accErrorOf(const SimFaults &faults);

struct SimOptions {
    std::string model = "HI14";       // product name without the hardware revision
    std::string firmware = "1.7.1";   // "1.7.1", "171", "1.6.6", ...
    int baud = 115200;                // saved baud at construction
    Motion motion = Motion::Static;
    uint64_t seed = 1;                // sensor noise, bias, iron, UUID, motion phases
    // Reported as the UUID (the serial number) instead of the one made from the seed, byte for
    // byte: a station's tests give it hostile values (SQL, bytes that are not UTF-8).
    std::string serial;
    double gyroScaleError = 0;        // fraction: the gyro reads (1 + e) * the true rate
    // A GNSS receiver wired to SYNC_IN/PPS and to RX (v1.7.1 manual 2.2.2): a PPS rising edge
    // at every whole UTC second with its RMC inside the 200 ms window. At the first edge after
    // a start the module aligns to UTC: UTC_UNSYNC clears and the HI91 system_time becomes the
    // ms of the UTC day. Each edge is also a SYNC_IN pulse (ONMARK 1 messages, 2.2.1).
    bool ppsInput = false;
    SimFaults faults;                 // none by default
    // The module's oscillator (sim_clock.h): the simulator's time is the module's own, so its
    // output periods and system_time follow it; its motion is taken at the true time. Whoever
    // moves the simulator's time (PtySimulator, a test) moves it to clock.deviceUs(true time).
    ClockError clock;
    // Added to the true time where the motion is taken (µs): simulators started at different
    // instants feel one fixture's motion together (PtySimulator sets it for Motion::Twists).
    int64_t motionEpochUs = 0;
};

class HipnucSimulator {
public:
    enum class State { App, Rebooting, Bootloader };

    static constexpr size_t kTxBufferSize = 4096;
    static constexpr int64_t kRebootUs = 300000;
    static constexpr int64_t kBootloaderEntryUs = 20000;
    static constexpr int64_t kPowerOffUs = 200000;        // power loss: off this long
    static constexpr size_t kInitialAppSize = 64 * 1024;  // image in flash at construction
    static constexpr int64_t kTickUs = 10000;            // calibration bookkeeping
    static constexpr int64_t kWbConvUs = 3000000;         // WB_CONV after a start
    static constexpr int64_t kMagCalTimeoutUs = 120000000; // MCAL fails after this
    static constexpr int64_t kMagCalVerifyUs = 1000000;   // STAT=2 before STAT=3
    static constexpr size_t kMaxLine = 256;
    static constexpr size_t kMessageCount = 7;            // protocol::hipnuc::Message values
    static constexpr int kMagCalCells = 72;               // 6 bands x 12 sectors of field directions
    static constexpr int kMagCalCellsNeeded = 50;         // PROGRESS=100 here
    static constexpr double kMagCalMaxSpreadUt = 2.5;     // fitted field magnitudes must agree to this (RMS)
    static constexpr double kMagDisturbanceTurnS = 3.0;   // the disturbance turns about the vertical
    static constexpr double kMagDisturbanceTiltS = 7.0;   // and tilts up and down, with these periods

    struct MessageSetting {
        enum class Mode { Off, OnTime, OnMark };
        Mode mode = Mode::Off;
        int periodMs = 0; // OnTime: 1..1000
        friend bool operator==(const MessageSetting &, const MessageSetting &) = default;
    };

    struct Config {
        int baud = 115200;
        std::array<MessageSetting, kMessageCount> messages{}; // indexed by Message
        uint32_t hi83Map = protocol::hipnuc::Hi83::kDefaultMap;
        int attMode = 1;
        int urfrCode = model::Mounting::kDefaultCode;   // v1.7.1 form
        model::Matrix3 urfrMatrix = model::Mounting::identity(); // v1.6.6 form: X_B = C * X_U
        int coord = 0;                                  // 0 ENU, 4 NWU
        std::array<int, 5> pmux{1, 2, 5, 0, 0};         // IO pin of PMUX1..5 (0: none)
        int pmux2Div = 1;
        bool backgroundMagCal = true;                   // v1.6.6 IMU_EN_MCAL
        std::array<double, 4> relativeLevel{1, 0, 0, 0}; // ATT RST 2 correction (w, x, y, z)

        const MessageSetting &message(protocol::hipnuc::Message m) const { return messages[size_t(m)]; }
        MessageSetting &message(protocol::hipnuc::Message m) { return messages[size_t(m)]; }
        friend bool operator==(const Config &, const Config &) = default;
    };

    // Bytes the module sent, in order, tagged with the baud they were sent at. A chunk
    // is one frame, sentence or reply; it may be split over several segments.
    struct OutputSegment {
        int baud = 0;
        std::vector<uint8_t> bytes;
        uint64_t chunk = 0;
        bool chunkStart = false; // the first byte of the chunk is in this segment
        bool chunkEnd = false;   // the last byte of the chunk is in this segment
        bool data = false;       // a data frame or sentence (not a reply)
    };

    struct MagCalStatus {
        int stat = 0;     // 0 idle, 1 calibrating, 2 verifying, 3 done, 4 failed
        int progress = 0; // 0..100
    };

    static constexpr int64_t kUtcBaseUnixS = 1731571200; // 2024-11-14 08:00:00 UTC

    explicit HipnucSimulator(SimOptions options = {});

    // Bytes from the host, received at the right baud, at the current simulated time.
    void receive(const uint8_t *data, size_t n);
    void receive(std::string_view text) { receive(reinterpret_cast<const uint8_t *>(text.data()), text.size()); }
    // Runs simulated time forward to nowUs (monotonic; earlier values are ignored).
    void advanceTo(int64_t nowUs);
    // The bytes sent up to now.
    std::vector<uint8_t> takeOutput();
    std::vector<OutputSegment> takeOutputSegments();
    // Current UART baud of the module.
    int baud() const { return m_baud; }
    // Power off and on: restart the application from the saved configuration now.
    void powerCycle();
    // The bootloader and its flash (fault injection, flash content).
    KbootBootloader &bootloader() { return m_bootloader; }
    const KbootBootloader &bootloader() const { return m_bootloader; }
    // A rising edge on SYNC_IN: one frame of every message configured ONMARK 1.
    void syncInPulse();
    // Connects or disconnects the PPS receiver (SimOptions::ppsInput). The manual does not
    // say what a module does when PPS stops; the simulated one keeps its UTC alignment.
    void setPpsInput(bool on) { m_options.ppsInput = on; }
    bool utcSynced() const { return m_utcSyncedAtUs >= 0; }
    // Test hook for link recovery: what SERIALCONFIG does to this UART after its OK.
    // 0 (default): switches to the requested rate; -1: keeps the old rate (a module that
    // ignores the new one); > 0: switches to this rate instead.
    void setBaudChangeOverride(int baud) { m_baudOverride = baud; }
    // Test hook: commands starting with this text (upper case, e.g. "CONFIG IMU COORD") are
    // answered ERR, as a delivery configuration that locks a setting; empty: none.
    void setRefusedCommand(std::string prefix) { m_refusedPrefix = std::move(prefix); }

    // Read-only state, mostly for tests.
    const SimOptions &options() const { return m_options; }
    State state() const { return m_state; }
    const Config &runningConfig() const { return m_running; }
    const Config &savedConfig() const { return m_saved; }
    const Config &activeConfig() const { return m_active; } // the configuration of the last start
    bool logEnabled() const { return m_logEnabled; }
    uint64_t droppedFrames() const { return m_dropped; }
    // Data frames and sentences accepted for sending (the module's output, before any pty loss).
    uint64_t framesQueued() const { return m_framesQueued; }
    int64_t nowUs() const { return m_nowUs; }
    int64_t startedAtUs() const { return m_startUs; }
    uint32_t systemTimeMs() const;
    const model::FirmwareVersion &firmware() const { return m_firmware; }
    model::ManualEdition edition() const { return m_edition; }
    model::ProductFamily family() const { return m_family; }
    bool hasMagnetometer() const;
    bool hasPmux() const;
    bool supportsMessage(protocol::hipnuc::Message m) const;
    bool supportsBaud(int baud) const;
    const std::string &uuid() const { return m_uuid; }
    // PNAME: the model with hardware revision R3 ("HI14" -> "HI14R3"; "HI14R2" stays).
    std::string productName() const;
    MagCalStatus magCalStatus() const { return {m_mcalStat, m_mcalProgress}; }
    bool magCalibrated() const { return m_magCalibrated; }
    Eigen::Vector3d magBiasEstimate() const { return m_magBias; } // LOG MAGCONFIG "MB"
    bool gyroCalActive() const { return m_usrcalActive; }
    double gyroCalAngleDeg() const { return m_usrcalAngle; }
    uint16_t mainStatus() const { return mainStatusAt(m_nowUs); }
    size_t txQueuedBytes() const { return m_txQueued; }
    const MotionModel &motionModel() const { return m_motion; }
    const SensorModel &sensorModel() const { return m_sensor; }

    // Factory defaults for this model and firmware (baud 115200).
    Config factoryConfig() const;
    // Output attitude (user frame, world frame, corrections) at the current time, no noise.
    Eigen::Quaterniond currentAttitude() const { return attitudeAt(m_nowUs, true); }
    // The true state of the module's own body at t (us): the motion, turned by the rotation
    // fixture while it runs and by the mounting error. Everything measured derives from it.
    MotionState moduleStateAt(int64_t t) const;
    // The disturbing field (SimFaults::magDisturbanceUt) at t, navigation frame (ENU, uT).
    Eigen::Vector3d magDisturbanceAt(int64_t t) const;

private:
    enum class Outcome { Silent, Ok, Err };
    struct Reply {
        Outcome outcome = Outcome::Silent;
        std::vector<std::string> lines;
        std::function<void()> after; // runs once the reply is queued
    };
    struct Snapshot {
        int64_t tUs = 0;
        uint32_t systemTimeMs = 0;
        uint64_t systemTimeUs = 0;
        Eigen::Vector3d acc, gyr, mag; // user frame: G, deg/s, uT
        Eigen::Quaterniond q;          // canonical, w >= 0
        EulerAngles euler;
        double pressurePa = 0, temperatureC = 0;
        uint16_t mainStatus = 0;
    };
    // What a magnetometer calibration has collected: the field directions it saw (progress)
    // and the magnitudes of the fitted field (their spread is the fit's residual).
    struct Coverage {
        std::array<bool, kMagCalCells> cells{};
        int visited = 0;
        int samples = 0;
        double meanUt = 0, sumSquaresUt = 0; // Welford's running mean and sum of squared deviations
        void reset();
        void add(const Eigen::Vector3d &direction, double fieldUt);
        int progress() const;
        double spreadUt() const; // RMS deviation of the magnitudes from their mean
    };
    struct Chunk {
        std::vector<uint8_t> bytes;
        double startUs = 0;
        double byteUs = 0;
        int baud = 0;
        size_t sent = 0;
        uint64_t id = 0;
        bool data = false;
    };

    // time and state
    void runEventsAt(int64_t t);
    int64_t nextEventUs() const;
    void startApp(int64_t t);
    void beginReset(State after, int64_t delayUs);
    void tick(int64_t t);
    void integrateGyroCal(int64_t t);
    void scheduleMessage(size_t index, int64_t t);

    // input
    void appByte(uint8_t c);
    void enterBootloader(int64_t t);
    void runBootloader(int64_t t);
    void processLine(const std::string &line);
    Reply dispatch(const std::vector<std::string> &tok);
    Reply cmdConfig(const std::vector<std::string> &tok);
    Reply cmdLog(const std::vector<std::string> &tok);
    Reply cmdLogMessage(protocol::hipnuc::Message m, const std::vector<std::string> &tok, size_t at);
    Reply cmdSerialConfig(const std::vector<std::string> &tok);
    std::vector<std::string> comConfigLines() const;

    // output
    Eigen::Vector3d disturbanceInSensor(int64_t t, const MotionState &state) const;
    double fittedFieldUt(int64_t t, const MotionState &state) const;
    Snapshot snapshotAt(int64_t t);
    Eigen::Quaterniond attitudeAt(int64_t t, bool withYawOffset) const;
    Eigen::Matrix3d userFromSensor() const;
    Eigen::Matrix3d levelMatrix() const;
    uint16_t mainStatusAt(int64_t t) const;
    void emitMessage(protocol::hipnuc::Message m, int64_t t);
    std::vector<uint8_t> buildMessage(protocol::hipnuc::Message m, const Snapshot &s) const;
    std::string utcFields(int64_t t, int &year, int &month, int &day, int &hour, int &minute, int &ms) const;

    // UART
    bool enqueue(std::vector<uint8_t> bytes, bool data);
    void enqueueText(const std::string &text);
    void drainTo(int64_t t);
    void dropUnsent(int64_t t);

    SimOptions m_options;
    model::FirmwareVersion m_firmware;
    model::ManualEdition m_edition = model::ManualEdition::V171;
    model::ProductFamily m_family = model::ProductFamily::Unknown;
    MotionModel m_motion;
    MotionModel m_fixtureMotion;                                      // SimFaults::magCalFixture
    Eigen::Quaterniond m_mounting = Eigen::Quaterniond::Identity();   // motion body <- module body
    bool m_mounted = false;                                           // a mounting error is set
    SensorModel m_sensor;
    std::string m_uuid;

    State m_state = State::App;
    State m_afterReset = State::App;
    int64_t m_nowUs = 0;
    int64_t m_startUs = 0;
    int64_t m_resetDoneUs = 0;
    int64_t m_nextTickUs = kTickUs;
    std::array<int64_t, kMessageCount> m_nextDueUs{};

    Config m_running, m_saved, m_active;
    int m_baud = 115200;
    int m_baudOverride = 0;
    std::string m_refusedPrefix;
    bool m_logEnabled = true;

    // attitude corrections
    double m_yawOffsetDeg = 0;                                // ATT RST 1, CONFIG YAW, 6-axis start
    Eigen::Quaterniond m_level = Eigen::Quaterniond::Identity(); // ATT RST 3 (permanent)

    // magnetometer calibration
    bool m_magCalibrated = false;
    int64_t m_utcSyncedAtUs = -1;      // the PPS edge the clock aligned at, -1: not aligned
    Eigen::Vector3d m_magBias = Eigen::Vector3d::Zero();
    int m_mcalStat = 0;
    int m_mcalProgress = 0;
    int64_t m_mcalStartUs = 0;
    int64_t m_mcalVerifyUntilUs = 0;
    Coverage m_mcalCoverage;
    Coverage m_bgCoverage;

    // gyro calibration (CONFIG USRCAL)
    bool m_usrcalActive = false;
    int m_usrcalTarget = 0;
    double m_usrcalAngle = 0;
    int64_t m_usrcalStartUs = 0;
    int64_t m_usrcalLastUs = 0;
    double m_usrcalLastRate = 0;

    // input
    std::string m_line;
    bool m_lineOverflow = false;
    KbootBootloader m_bootloader;

    // UART
    std::deque<Chunk> m_tx;
    size_t m_txQueued = 0;
    double m_lineFreeUs = 0;
    uint64_t m_nextChunkId = 1;
    uint64_t m_dropped = 0;
    uint64_t m_framesQueued = 0;
    std::vector<OutputSegment> m_out;

    // one sensor sample per instant, shared by the messages due then
    int64_t m_sampleUs = -1;
    SensorReading m_sample;
};

const char *stateName(HipnucSimulator::State s);

} // namespace imudesk::sim
