#include "ascii_command.h"

#include "payloads.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <charconv>
#include <vector>

namespace imudesk::protocol::hipnuc {

const char *messageName(Message m)
{
    switch (m) {
    case Message::HI91: return "HI91";
    case Message::HI92: return "HI92";
    case Message::HI81: return "HI81";
    case Message::HI83: return "HI83";
    case Message::GGA: return "GGA";
    case Message::RMC: return "RMC";
    case Message::SXT: return "SXT";
    }
    return "?";
}

bool parseMessage(std::string_view name, Message &out)
{
    for (Message m : {Message::HI91, Message::HI92, Message::HI81, Message::HI83, Message::GGA, Message::RMC,
                      Message::SXT})
        if (name == messageName(m)) {
            out = m;
            return true;
        }
    return false;
}

namespace commands {

namespace {

OutputEffect changesOutput()
{
    OutputEffect e;
    e.changesOutput = true;
    return e;
}

OutputEffect setsOutput(Message m, double periodS)
{
    OutputEffect e = changesOutput();
    e.message = messageName(m);
    e.periodS = periodS;
    return e;
}

std::vector<std::string> upperWords(std::string_view text)
{
    std::vector<std::string> words;
    std::string w;
    for (char c : text) {
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
            if (!w.empty())
                words.push_back(std::move(w));
            w.clear();
        } else {
            w.push_back(char(std::toupper(static_cast<unsigned char>(c))));
        }
    }
    if (!w.empty())
        words.push_back(std::move(w));
    return words;
}

std::string_view trimmed(std::string_view t)
{
    const auto first = t.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos)
        return {};
    const auto last = t.find_last_not_of(" \t\r\n");
    return t.substr(first, last - first + 1);
}

} // namespace

Command typed(std::string_view text)
{
    const std::string_view t = trimmed(text);
    const std::vector<std::string> w = upperWords(t);
    OutputEffect e;
    if (!w.empty()) {
        const std::string &verb = w.front();
        if (verb == "REBOOT" || verb == "FRESET" || verb == "SERIALCONFIG") {
            e = changesOutput();
        } else if (verb == "LOG" && w.size() >= 2
                   && !(w[1] == "VERSION" || w[1] == "COMCONFIG" || w[1] == "MAGCONFIG" || w[1] == "MCAL")) {
            e = changesOutput();
            size_t i = 1;
            if (w[i].rfind("COM", 0) == 0) {
                e.thisPort = false;
                ++i;
            }
            Message m;
            if (i < w.size() && parseMessage(w[i], m)) { // else LOG ENABLE / DISABLE
                e.message = messageName(m);
                if (i + 2 < w.size() && w[i + 1] == "ONTIME") {
                    const std::string &word = w[i + 2];
                    double p = -1; // from_chars: the C locale's decimal point, whatever the user's
                    const auto [end, err] = std::from_chars(word.data(), word.data() + word.size(), p);
                    if (err == std::errc() && end == word.data() + word.size() && p >= 0)
                        e.periodS = p;
                }
            }
        }
    }
    return Command::make(std::string(t), std::move(e));
}

bool isSupportedBaud(int baud, model::ManualEdition edition)
{
    if (edition == model::ManualEdition::V166) {
        for (int b : {9600, 115200, 256000, 460800, 921600})
            if (b == baud)
                return true;
        return false;
    }
    for (int b : {4800, 9600, 19200, 38400, 57600, 115200, 230400, 256000, 460800, 921600})
        if (b == baud)
            return true;
    return false;
}

Command reboot() { return Command::make("REBOOT", changesOutput()); }
Command rebootBootloader() { return Command::make("REBOOT BL", changesOutput()); }
Command saveConfig() { return Command::make("SAVECONFIG"); }
Command factoryReset() { return Command::make("FRESET", changesOutput()); }

Command serialConfig(int baud, model::ManualEdition edition)
{
    if (!isSupportedBaud(baud, edition))
        return Command::fail("unsupported baud rate " + std::to_string(baud));
    return Command::make("SERIALCONFIG " + std::to_string(baud), changesOutput());
}

Command serialConfig(int com, int baud)
{
    if (com < 1 || com > 4)
        return Command::fail("serial port COM" + std::to_string(com) + " does not exist (1-4)");
    if (!isSupportedBaud(baud))
        return Command::fail("unsupported baud rate " + std::to_string(baud));
    return Command::make("SERIALCONFIG COM" + std::to_string(com) + " " + std::to_string(baud), changesOutput());
}

Command attMode(int mode)
{
    if (mode != 0 && mode != 1 && mode != 4)
        return Command::fail("working mode must be 0 (VRU, 6-axis), 1 (AHRS, 9-axis) or 4 (humanoid robot)");
    return Command::make("CONFIG ATT MODE " + std::to_string(mode));
}

Command attReset(int action)
{
    if (action != 1 && action != 2 && action != 3 && action != 5)
        return Command::fail("attitude reset action must be 1, 2, 3 or 5");
    return Command::make("CONFIG ATT RST " + std::to_string(action));
}

Command imuUrfr(int code)
{
    if (!model::Mounting::isValidCode(code))
        return Command::fail("URFR code " + std::to_string(code) + " is not one of the 24 right-handed mountings");
    return Command::make("CONFIG IMU URFR " + model::Mounting::codeText(code));
}

std::string formatNumber(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    std::string s = buf;
    if (s == "-0")
        s = "0";
    return s;
}

Command imuUrfrMatrix(const model::Matrix3 &c)
{
    for (const auto &row : c)
        for (double v : row)
            if (!std::isfinite(v) || std::fabs(v) > 1.0 + 1e-9)
                return Command::fail("URFR matrix elements must be finite numbers in -1..1");
    if (!model::Mounting::isRotation(c))
        return Command::fail("URFR matrix is not a rotation (rows must be orthonormal, determinant +1)");
    std::string t = "CONFIG IMU URFR ";
    for (size_t i = 0; i < 3; ++i)
        for (size_t j = 0; j < 3; ++j) {
            if (i || j)
                t += ',';
            t += formatNumber(c[i][j]);
        }
    return Command::make(t);
}

Command imuCoord(int coord)
{
    if (coord != 0 && coord != 4)
        return Command::fail("world frame must be 0 (ENU) or 4 (NWU)");
    return Command::make("CONFIG IMU COORD " + std::to_string(coord));
}

Command pmux(int function, int io, bool legacy)
{
    const int maxFn = legacy ? 5 : 3;
    const int maxIo = legacy ? 9 : 5;
    if (function < 1 || function > maxFn)
        return Command::fail("PMUX function must be 1.." + std::to_string(maxFn));
    if (io < 1 || io > maxIo)
        return Command::fail("IO pin must be 1.." + std::to_string(maxIo));
    return Command::make("CONFIG PMUX" + std::to_string(function) + " IO" + std::to_string(io));
}

Command pmux2Div(int divider)
{
    if (divider < 1 || divider > 1000)
        return Command::fail("SOUT divider must be 1..1000");
    return Command::make("CONFIG PMUX2 DIV " + std::to_string(divider));
}

Command magCalStart() { return Command::make("CONFIG MCAL START"); }

Command gyroCalStart(int angleDeg)
{
    if (angleDeg < 720 || angleDeg > 1800)
        return Command::fail("gyro calibration angle must be 720..1800 deg (2 to 5 turns)");
    return Command::make("CONFIG USRCAL START " + std::to_string(angleDeg));
}

Command gyroCalStop() { return Command::make("CONFIG USRCAL STOP"); }

Command setYaw(int mode, double deg)
{
    if (mode != 0 && mode != 1)
        return Command::fail("yaw mode must be 0 (relative) or 1 (absolute)");
    if (!std::isfinite(deg) || deg < -180.0 || deg > 180.0)
        return Command::fail("yaw must be -180..180 deg");
    return Command::make("CONFIG YAW " + std::to_string(mode) + " " + formatNumber(deg));
}

Command enableBackgroundMagCal(bool on) { return Command::make(std::string("CONFIG IMU_EN_MCAL ") + (on ? "1" : "0")); }

Command logEnable() { return Command::make("LOG ENABLE", changesOutput()); }
Command logDisable() { return Command::make("LOG DISABLE", changesOutput()); }
Command logVersion() { return Command::make("LOG VERSION"); }
Command logComConfig() { return Command::make("LOG COMCONFIG"); }
Command logMagConfig() { return Command::make("LOG MAGCONFIG"); }
Command logMagCalStatus() { return Command::make("LOG MCAL STAT"); }

std::string formatPeriod(double periodS)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", periodS);
    std::string s = buf;
    while (!s.empty() && s.back() == '0')
        s.pop_back();
    if (!s.empty() && s.back() == '.')
        s.pop_back();
    return s;
}

Command logOnTime(Message m, double periodS)
{
    if (!std::isfinite(periodS) || (periodS != 0 && (periodS < 0.001 - 1e-12 || periodS > 1.0 + 1e-12)))
        return Command::fail("output period must be 0 (off) or 0.001..1 s");
    if (periodS != 0 && std::fabs(periodS * 1000.0 - std::round(periodS * 1000.0)) > 1e-6)
        return Command::fail("output period must be a whole number of milliseconds");
    return Command::make(std::string("LOG ") + messageName(m) + " ONTIME " + formatPeriod(periodS),
                         setsOutput(m, periodS));
}

Command logOnMark(Message m, bool once)
{
    return Command::make(std::string("LOG ") + messageName(m) + " ONMARK " + (once ? "ONCE" : "1"), setsOutput(m, -1));
}

Command logHi83Map(uint32_t bitmap)
{
    if (bitmap == 0)
        return Command::fail("the HI83 bitmap needs at least one field");
    if (bitmap & ~Hi83::kSupportedMask) {
        char buf[16];
        std::snprintf(buf, sizeof buf, "0x%08X", unsigned(bitmap & ~Hi83::kSupportedMask));
        return Command::fail(std::string("HI83 bits ") + buf + " are not documented with a size");
    }
    char buf[40];
    std::snprintf(buf, sizeof buf, "LOG HI83 MAP 0x%08X", unsigned(bitmap));
    return Command::make(buf, setsOutput(Message::HI83, -1));
}

} // namespace commands
} // namespace imudesk::protocol::hipnuc
