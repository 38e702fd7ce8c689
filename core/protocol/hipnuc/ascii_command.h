#pragma once
// Builders for every ASCII command of the v1.7.1 and v1.6.6 manuals. Each builder
// checks its arguments against the manual's ranges and returns either the command
// text (without CR/LF) or an error message.
#include "model/device_identity.h"
#include "model/mounting.h"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace imudesk::protocol::hipnuc {

// What a command does to the device's output stream: the session's lost-frame counter must
// not count a gap that a command made (device/frame_gap_counter.h).
struct OutputEffect {
    bool changesOutput = false; // the stream may stop, restart or change its timing here
    bool thisPort = true;       // no COMn word: the port the command came in on
    std::string message;        // "HI91", ...: the message whose own output it sets; empty otherwise
    double periodS = -1;        // LOG <MSG> ONTIME period; -1 when not ONTIME
};

struct Command {
    std::string text;   // e.g. "LOG HI91 ONTIME 0.01"
    std::string error;  // non-empty when the arguments were refused
    OutputEffect effect;
    bool ok() const { return error.empty(); }
    std::string wire() const { return text + "\r\n"; }
    static Command make(std::string t) { return Command{std::move(t), {}, {}}; }
    static Command make(std::string t, OutputEffect e) { return Command{std::move(t), {}, std::move(e)}; }
    static Command fail(std::string e) { return Command{{}, std::move(e), {}}; }
};

// Output messages that LOG <MSG> accepts.
enum class Message { HI91, HI92, HI81, HI83, GGA, RMC, SXT };
const char *messageName(Message m);
bool parseMessage(std::string_view name, Message &out);

namespace commands {

// Text typed by a user (the console): sent as typed, trimmed. Its output effect is read from
// the words, as the device reads them (LOG [COMn] <MSG> ONTIME <s>, LOG ENABLE/DISABLE,
// REBOOT, FRESET, SERIALCONFIG; the LOG queries VERSION, COMCONFIG, MAGCONFIG and MCAL change
// nothing).
Command typed(std::string_view text);

// Baud rates of SERIALCONFIG: the v1.7.1 list, or the v1.6.6 one (9600, 115200, 256000, 460800, 921600).
bool isSupportedBaud(int baud, model::ManualEdition edition = model::ManualEdition::V171);

Command reboot();
Command rebootBootloader();              // REBOOT BL
Command saveConfig();
Command serialConfig(int baud, model::ManualEdition edition = model::ManualEdition::V171);
Command serialConfig(int com, int baud); // SERIALCONFIG COMn <baud>, n = 1..4
Command factoryReset();                  // FRESET

Command attMode(int mode);               // CONFIG ATT MODE 0 | 1 | 4
Command attReset(int action);            // CONFIG ATT RST 1 | 2 | 3 | 5
Command imuUrfr(int code);               // CONFIG IMU URFR <code>, one of the 24 codes
Command imuUrfrMatrix(const model::Matrix3 &c); // v1.6.6: CONFIG IMU URFR c00,...,c22
Command imuCoord(int coord);             // CONFIG IMU COORD 0 (ENU) | 4 (NWU)
Command pmux(int function, int io, bool legacy = false); // CONFIG PMUXn IOm (v1.7.1: 1-3/1-5; v1.6.6: 1-5/1-9)
Command pmux2Div(int divider);           // CONFIG PMUX2 DIV 1..1000
Command magCalStart();                   // CONFIG MCAL START (firmware >= 1.7.0)
Command gyroCalStart(int angleDeg);      // CONFIG USRCAL START 720..1800
Command gyroCalStop();                   // CONFIG USRCAL STOP
Command setYaw(int mode, double deg);    // v1.6.6: CONFIG YAW 0|1 <-180..180>
Command enableBackgroundMagCal(bool on); // v1.6.6: CONFIG IMU_EN_MCAL 0|1

Command logEnable();
Command logDisable();
Command logVersion();
Command logComConfig();
Command logMagConfig();                  // v1.6.6: LOG MAGCONFIG
Command logMagCalStatus();               // LOG MCAL STAT
Command logOnTime(Message m, double periodS);   // 0 (off) or 0.001 .. 1 s
Command logOnMark(Message m, bool once);        // ONMARK 1 | ONMARK ONCE
Command logHi83Map(uint32_t bitmap);            // LOG HI83 MAP 0x........

// Formats a command argument: up to 6 significant digits, "0" for -0 ("1.5", "-1", "16").
std::string formatNumber(double v);

// Formats a period the way the manual writes it ("0.01", "0.005", "1").
std::string formatPeriod(double periodS);

} // namespace commands
} // namespace imudesk::protocol::hipnuc
