#include "commands.h"

#include "bcd.h"
#include "frame.h"

#include <algorithm>
#include <array>
#include <utility>

namespace imudesk::protocol::witlink::commands {

namespace {

struct Entry {
    uint8_t cmd;
    const char *name;
};

constexpr std::array<Entry, 23> kCommands{{
    {0x01, "read pitch"},
    {0x02, "read roll"},
    {0x03, "read heading"},
    {0x04, "read angles"},
    {0x14, "read all"},
    {0x06, "set declination"},
    {0x07, "read declination"},
    {0x63, "start automatic 12-point calibration"},
    {0x65, "start manual calibration"},
    {0x08, "start automatic all-orientation calibration"},
    {0x64, "start 12-point small-tilt calibration"},
    {0x60, "start planar calibration"},
    {0x67, "collect calibration point"},
    {0x12, "stop calibration"},
    {0x09, "save calibration"},
    {0x10, "clear calibration"},
    {0x0B, "set baud"},
    {0x0C, "set output rate"},
    {0x49, "set output content"},
    {0x0F, "set address"},
    {0x1F, "query address"},
    {0x0A, "save settings"},
    {0x0E, "factory reset"},
}};

constexpr std::array<std::pair<int, uint8_t>, 5> kBauds{{{2400, 0}, {4800, 1}, {9600, 2}, {19200, 3}, {115200, 4}}};
constexpr std::array<std::pair<int, uint8_t>, 7> kRates{{{0, 0}, {5, 1}, {10, 2}, {15, 3}, {25, 4}, {50, 5}, {100, 6}}};

constexpr std::array<std::pair<std::string_view, CalibrationMethod>, 5> kMethods{{
    {"auto12", CalibrationMethod::Auto12},
    {"manual", CalibrationMethod::Manual},
    {"all", CalibrationMethod::AllOrientation},
    {"small-tilt", CalibrationMethod::SmallTilt12},
    {"planar", CalibrationMethod::Planar},
}};

constexpr std::array<std::pair<std::string_view, OutputContent>, 4> kContents{{
    {"default", OutputContent::Default},
    {"internal", OutputContent::Internal},
    {"all", OutputContent::AllData},
    {"nmea", OutputContent::Nmea0183},
}};

} // namespace

bool isKnownCommand(uint8_t cmd)
{
    return std::any_of(kCommands.begin(), kCommands.end(), [cmd](const Entry &e) { return e.cmd == cmd; });
}

const char *commandName(uint8_t cmd)
{
    for (const auto &e : kCommands)
        if (e.cmd == cmd)
            return e.name;
    return "unknown";
}

bool isCalibrationStart(uint8_t cmd)
{
    return cmd == 0x63 || cmd == 0x65 || cmd == 0x08 || cmd == 0x64 || cmd == 0x60;
}

std::vector<uint8_t> expectedReplies(uint8_t request)
{
    switch (request) {
    case 0x14:
        return {0x14};
    case 0x67:
        return {kReplyCalibrationPoint, kReplyCalibrationPointAlt};
    case 0x12:
        return {kReplyStopCalibration, 0x92};
    case 0x49:
        return {0x49, 0xC9};
    case 0x1F:
        return {0x1F, 0x9F};
    default:
        break;
    }
    if (isCalibrationStart(request))
        return request == 0x08 ? std::vector<uint8_t>{kReplyCalibrationStarted}
                                : std::vector<uint8_t>{kReplyCalibrationStarted, uint8_t(request | 0x80)};
    if (!isKnownCommand(request))
        return {};
    return {uint8_t(request | 0x80)};
}

std::optional<uint8_t> baudCode(int baud)
{
    for (const auto &[b, c] : kBauds)
        if (b == baud)
            return c;
    return std::nullopt;
}

int baudFromCode(uint8_t code)
{
    for (const auto &[b, c] : kBauds)
        if (c == code)
            return b;
    return -1;
}

const std::vector<int> &supportedBauds()
{
    static const std::vector<int> v{2400, 4800, 9600, 19200, 115200};
    return v;
}

std::optional<uint8_t> rateCode(int hz)
{
    for (const auto &[r, c] : kRates)
        if (r == hz)
            return c;
    return std::nullopt;
}

int rateFromCode(uint8_t code)
{
    for (const auto &[r, c] : kRates)
        if (c == code)
            return r;
    return -1;
}

const std::vector<int> &supportedRates()
{
    static const std::vector<int> v{0, 5, 10, 15, 25, 50, 100};
    return v;
}

bool parseCalibrationMethod(std::string_view text, CalibrationMethod &out)
{
    for (const auto &[n, m] : kMethods)
        if (n == text) {
            out = m;
            return true;
        }
    return false;
}

const char *calibrationMethodName(CalibrationMethod m)
{
    for (const auto &[n, mm] : kMethods)
        if (mm == m)
            return n.data();
    return "unknown";
}

bool parseOutputContent(std::string_view text, OutputContent &out)
{
    for (const auto &[n, c] : kContents)
        if (n == text) {
            out = c;
            return true;
        }
    return false;
}

const char *outputContentName(OutputContent c)
{
    for (const auto &[n, cc] : kContents)
        if (cc == c)
            return n.data();
    return "unknown";
}

std::vector<uint8_t> request(Command cmd, uint8_t address, const std::vector<uint8_t> &data)
{
    return encodeFrame(address, uint8_t(cmd), data);
}

std::vector<uint8_t> readPitch(uint8_t address) { return request(Command::ReadPitch, address); }
std::vector<uint8_t> readRoll(uint8_t address) { return request(Command::ReadRoll, address); }
std::vector<uint8_t> readHeading(uint8_t address) { return request(Command::ReadHeading, address); }
std::vector<uint8_t> readAngles(uint8_t address) { return request(Command::ReadAngles, address); }
std::vector<uint8_t> readAll(uint8_t address) { return request(Command::ReadAll, address); }
std::vector<uint8_t> readDeclination(uint8_t address) { return request(Command::ReadDeclination, address); }
std::vector<uint8_t> collectPoint(uint8_t address) { return request(Command::CollectPoint, address); }
std::vector<uint8_t> stopCalibration(uint8_t address) { return request(Command::StopCalibration, address); }
std::vector<uint8_t> saveCalibration(uint8_t address) { return request(Command::SaveCalibration, address); }
std::vector<uint8_t> clearCalibration(uint8_t address) { return request(Command::ClearCalibration, address); }
std::vector<uint8_t> queryAddress() { return request(Command::QueryAddress, kDefaultAddress); }
std::vector<uint8_t> saveSettings(uint8_t address) { return request(Command::SaveSettings, address); }
std::vector<uint8_t> factoryReset(uint8_t address) { return request(Command::FactoryReset, address); }

std::vector<uint8_t> setDeclination(double deg, uint8_t address)
{
    const auto d = encodeDeclination(deg);
    if (!d)
        return {};
    return request(Command::SetDeclination, address, {(*d)[0], (*d)[1]});
}

std::vector<uint8_t> startCalibration(CalibrationMethod m, uint8_t address)
{
    return encodeFrame(address, uint8_t(m));
}

std::vector<uint8_t> setBaud(int baud, uint8_t address)
{
    const auto c = baudCode(baud);
    if (!c)
        return {};
    return request(Command::SetBaud, address, {*c});
}

std::vector<uint8_t> setOutputRate(int hz, uint8_t address)
{
    const auto c = rateCode(hz);
    if (!c)
        return {};
    return request(Command::SetOutputRate, address, {*c});
}

std::vector<uint8_t> setOutputContent(OutputContent c, uint8_t address)
{
    if (uint8_t(c) > uint8_t(OutputContent::Nmea0183))
        return {};
    return request(Command::SetOutputContent, address, {uint8_t(c)});
}

std::vector<uint8_t> setAddress(uint8_t newAddress, uint8_t address)
{
    return request(Command::SetAddress, address, {newAddress});
}

} // namespace imudesk::protocol::witlink::commands
