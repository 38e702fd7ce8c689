#include "hipnuc_simulator.h"

#include "model/main_status.h"
#include "model/sample.h"
#include "protocol/hipnuc/crc16.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/nmea/nmea_parser.h"

#include <QLoggingCategory>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

namespace imudesk::sim {
namespace {

Q_LOGGING_CATEGORY(lcSim, "imudesk.core.sim", QtInfoMsg)

using protocol::hipnuc::Hi81;
using protocol::hipnuc::Hi83;
using protocol::hipnuc::Hi91;
using protocol::hipnuc::Hi92;
using protocol::hipnuc::Message;
using model::MainStatus;
using model::ManualEdition;

constexpr double kDeg = 0.017453292519943295;
constexpr int64_t kNever = std::numeric_limits<int64_t>::max();

constexpr Message kMessages171[] = {Message::HI91, Message::HI81, Message::HI83, Message::GGA, Message::RMC, Message::SXT};
constexpr Message kMessages166[] = {Message::HI91, Message::HI92};

uint64_t mix(uint64_t x)
{
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

std::string upper(std::string s)
{
    for (char &c : s)
        c = char(std::toupper(uint8_t(c)));
    return s;
}

std::vector<std::string> tokenize(const std::string &line)
{
    std::vector<std::string> out;
    std::string cur;
    for (char c : line) {
        if (c == ' ' || c == '\t' || c == '\r') {
            if (!cur.empty())
                out.push_back(upper(std::move(cur)));
            cur.clear();
        } else {
            cur.push_back(c);
        }
    }
    if (!cur.empty())
        out.push_back(upper(std::move(cur)));
    return out;
}

bool parseInt(std::string_view s, int &out)
{
    if (s.empty())
        return false;
    if (s.front() == '+')
        s.remove_prefix(1);
    const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
    return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

bool parseDouble(std::string_view s, double &out)
{
    if (s.empty())
        return false;
    if (s.front() == '+')
        s.remove_prefix(1);
    const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
    return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(out);
}

// "0x1F", "0X1F" or decimal.
bool parseU32(std::string_view s, uint32_t &out)
{
    int base = 10;
    if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
        s.remove_prefix(2);
        base = 16;
    }
    if (s.empty())
        return false;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), out, base);
    return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

// "COM1".."COM9" -> n; -1 when the word is not a port word ("COMCONFIG").
int comNumber(const std::string &w)
{
    if (w.size() < 4 || w.compare(0, 3, "COM") != 0)
        return -1;
    for (size_t i = 3; i < w.size(); ++i)
        if (w[i] < '0' || w[i] > '9')
            return -1;
    int n = 0;
    return parseInt(std::string_view(w).substr(3), n) ? n : -1;
}

// "PMUX2" -> 2, "IO5" -> 5; -1 when the prefix differs, 0 when the number is bad.
int suffixNumber(const std::string &w, std::string_view prefix)
{
    if (w.compare(0, prefix.size(), prefix) != 0)
        return -1;
    int n = 0;
    return parseInt(std::string_view(w).substr(prefix.size()), n) ? n : 0;
}

std::string number(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    std::string s = buf;
    if (s == "-0")
        s = "0";
    return s;
}

int16_t clamp16(double v)
{
    return int16_t(std::clamp(std::lround(v), -32768L, 32767L));
}

int32_t round32(double v)
{
    return int32_t(std::clamp<long long>(std::llround(v), std::numeric_limits<int32_t>::min(),
                                         std::numeric_limits<int32_t>::max()));
}

Eigen::Matrix3d toEigen(const model::Matrix3 &m)
{
    Eigen::Matrix3d r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r(i, j) = m[size_t(i)][size_t(j)];
    return r;
}

Eigen::Quaterniond qAxis(double deg, const Eigen::Vector3d &axis)
{
    return Eigen::Quaterniond(Eigen::AngleAxisd(deg * kDeg, axis));
}

// ENU -> NWU: N = ENU y, W = -ENU x, U = ENU z.
Eigen::Quaterniond enuToNwu()
{
    Eigen::Matrix3d t;
    t << 0, 1, 0, -1, 0, 0, 0, 0, 1;
    return Eigen::Quaterniond(t);
}

// Days since 1970-01-01 -> civil date (Howard Hinnant's algorithm).
void civilFromDays(int64_t z, int &y, int &m, int &d)
{
    z += 719468;
    const int64_t era = (z >= 0 ? z : z - 146096) / 146097;
    const int64_t doe = z - era * 146097;
    const int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    const int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    const int64_t mp = (5 * doy + 2) / 153;
    d = int(doy - (153 * mp + 2) / 5 + 1);
    m = int(mp < 10 ? mp + 3 : mp - 9);
    y = int(yoe + era * 400 + (m <= 2 ? 1 : 0));
}

HipnucSimulator::MessageSetting onTime(int ms)
{
    HipnucSimulator::MessageSetting s;
    s.mode = HipnucSimulator::MessageSetting::Mode::OnTime;
    s.periodMs = ms;
    return s;
}

} // namespace

const char *stateName(HipnucSimulator::State s)
{
    switch (s) {
    case HipnucSimulator::State::App: return "app";
    case HipnucSimulator::State::Rebooting: return "rebooting";
    case HipnucSimulator::State::Bootloader: return "bootloader";
    }
    return "?";
}

// ---------------------------------------------------------------------------------------
// Coverage of field directions for the magnetometer calibration progress

void HipnucSimulator::Coverage::reset()
{
    cells.fill(false);
    visited = 0;
}

void HipnucSimulator::Coverage::add(const Eigen::Vector3d &d)
{
    constexpr int kBands = 6, kSectors = kMagCalCells / kBands;
    const int band = std::clamp(int(std::floor((d.z() + 1.0) * 0.5 * kBands)), 0, kBands - 1);
    const double az = std::atan2(d.y(), d.x()); // -pi..pi
    const int sector = std::clamp(int(std::floor((az + M_PI) / (2 * M_PI) * kSectors)), 0, kSectors - 1);
    bool &cell = cells[size_t(band * kSectors + sector)];
    if (!cell) {
        cell = true;
        ++visited;
    }
}

int HipnucSimulator::Coverage::progress() const
{
    return std::min(100, visited * 100 / kMagCalCellsNeeded);
}

// ---------------------------------------------------------------------------------------
// Construction, identity, gates

HipnucSimulator::HipnucSimulator(SimOptions options)
    : m_options(std::move(options)),
      m_motion(MotionModel::Options{m_options.seed, m_options.motion}),
      m_sensor(m_options.seed)
{
    auto fw = model::FirmwareVersion::parse(m_options.firmware);
    if (!fw) {
        qCWarning(lcSim) << "unparsable firmware version" << m_options.firmware.c_str() << "- simulating 1.7.1";
        fw = model::FirmwareVersion{1, 7, 1};
    }
    m_firmware = *fw;
    m_edition = m_firmware >= model::FirmwareVersion{1, 7, 1} ? ManualEdition::V171 : ManualEdition::V166;
    m_family = model::familyOfProduct(m_options.model);
    char buf[20];
    std::snprintf(buf, sizeof buf, "%016llX", static_cast<unsigned long long>(mix(m_options.seed ^ 0x0439956980000000ull)));
    m_uuid = buf;

    m_saved = factoryConfig();
    if (m_options.baud > 0)
        m_saved.baud = m_options.baud;
    m_running = m_saved;
    startApp(0);
}

bool HipnucSimulator::hasMagnetometer() const
{
    return m_family != model::ProductFamily::HI02 && m_family != model::ProductFamily::HI50;
}

bool HipnucSimulator::hasPmux() const
{
    return m_family != model::ProductFamily::HI02 && m_family != model::ProductFamily::HI50
        && m_family != model::ProductFamily::HI7x_9x;
}

bool HipnucSimulator::supportsMessage(Message m) const
{
    if (m_edition == ManualEdition::V171)
        return std::find(std::begin(kMessages171), std::end(kMessages171), m) != std::end(kMessages171);
    return std::find(std::begin(kMessages166), std::end(kMessages166), m) != std::end(kMessages166);
}

bool HipnucSimulator::supportsBaud(int baud) const
{
    return protocol::hipnuc::commands::isSupportedBaud(baud, m_edition);
}

HipnucSimulator::Config HipnucSimulator::factoryConfig() const
{
    Config c;
    c.baud = 115200;
    for (auto &m : c.messages)
        m = MessageSetting{};
    c.message(Message::HI91) = onTime(10);
    c.hi83Map = Hi83::kDefaultMap;
    c.attMode = hasMagnetometer() ? 1 : 0;
    c.urfrCode = model::Mounting::kDefaultCode;
    c.urfrMatrix = model::Mounting::identity();
    c.coord = 0;
    c.pmux = {1, 2, 5, 0, 0};
    c.pmux2Div = 1;
    c.backgroundMagCal = true;
    c.relativeLevel = {1, 0, 0, 0};
    return c;
}

std::string HipnucSimulator::productName() const
{
    const std::string &m = m_options.model;
    const size_t r = m.find_last_of('R');
    if (r != std::string::npos && r >= 4 && r + 1 < m.size()
        && std::all_of(m.begin() + long(r) + 1, m.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return m;
    return m + "R3";
}

uint32_t HipnucSimulator::systemTimeMs() const
{
    return uint32_t((m_nowUs - m_startUs) / 1000);
}

// ---------------------------------------------------------------------------------------
// Time

void HipnucSimulator::startApp(int64_t t)
{
    m_state = State::App;
    m_startUs = t;
    m_running = m_saved;
    m_active = m_saved;
    m_baud = m_saved.baud;
    m_logEnabled = true;
    m_yawOffsetDeg = 0;
    m_mcalStat = 0;
    m_mcalProgress = 0;
    m_mcalCoverage.reset();
    m_bgCoverage.reset();
    m_usrcalActive = false;
    m_line.clear();
    m_lineOverflow = false;
    m_sampleUs = -1;
    for (size_t i = 0; i < kMessageCount; ++i)
        scheduleMessage(i, t);
    if (m_active.attMode != 1) {
        // 6-axis modes have no absolute heading: it starts at zero.
        m_yawOffsetDeg = -eulerEnu312(attitudeAt(t, false)).yaw;
    }
    qCDebug(lcSim) << "started" << productName().c_str() << m_firmware.toString().c_str() << "at" << t << "us, baud"
                   << m_baud;
}

void HipnucSimulator::beginReset(State after, int64_t delayUs)
{
    m_state = State::Rebooting;
    m_afterReset = after;
    m_resetDoneUs = m_nowUs + delayUs;
    m_usrcalActive = false;
    m_line.clear();
}

void HipnucSimulator::powerCycle()
{
    dropUnsent(m_nowUs);
    startApp(m_nowUs);
}

void HipnucSimulator::scheduleMessage(size_t i, int64_t t)
{
    const MessageSetting &s = m_running.messages[i];
    if (s.mode != MessageSetting::Mode::OnTime || s.periodMs <= 0) {
        m_nextDueUs[i] = kNever;
        return;
    }
    // Due on the grid of the period, counted from the start (a 1 kHz base tick).
    const int64_t p = int64_t(s.periodMs) * 1000;
    const int64_t k = (t - m_startUs) / p + 1;
    m_nextDueUs[i] = m_startUs + k * p;
}

int64_t HipnucSimulator::nextEventUs() const
{
    int64_t n = m_nextTickUs;
    if (m_state == State::Rebooting)
        n = std::min(n, m_resetDoneUs);
    if (m_state == State::App)
        for (size_t i = 0; i < kMessageCount; ++i)
            if (m_running.messages[i].mode == MessageSetting::Mode::OnTime)
                n = std::min(n, m_nextDueUs[i]);
    return n;
}

void HipnucSimulator::advanceTo(int64_t nowUs)
{
    if (nowUs > m_nowUs) {
        for (;;) {
            const int64_t next = nextEventUs();
            if (next > nowUs)
                break;
            m_nowUs = std::max(m_nowUs, next);
            runEventsAt(m_nowUs);
        }
        m_nowUs = nowUs;
    }
    drainTo(m_nowUs);
}

void HipnucSimulator::runEventsAt(int64_t t)
{
    if (m_state == State::Rebooting && t >= m_resetDoneUs) {
        dropUnsent(t);
        if (m_afterReset == State::App) {
            startApp(t);
        } else {
            m_state = State::Bootloader;
            m_blPrev = 0;
            qCDebug(lcSim) << "bootloader at" << t << "us";
        }
    }
    while (t >= m_nextTickUs) {
        tick(m_nextTickUs);
        m_nextTickUs += kTickUs;
    }
    if (m_state != State::App)
        return;
    for (size_t i = 0; i < kMessageCount; ++i) {
        const MessageSetting &s = m_running.messages[i];
        if (s.mode != MessageSetting::Mode::OnTime)
            continue;
        while (m_nextDueUs[i] <= t) {
            if (m_logEnabled)
                emitMessage(Message(i), t);
            m_nextDueUs[i] += int64_t(s.periodMs) * 1000;
        }
    }
}

void HipnucSimulator::integrateGyroCal(int64_t t)
{
    if (!m_usrcalActive || t <= m_usrcalLastUs)
        return;
    const double rate = m_motion.at(double(t) * 1e-6).rateDps.z();
    m_usrcalAngle += 0.5 * (m_usrcalLastRate + rate) * double(t - m_usrcalLastUs) * 1e-6;
    m_usrcalLastUs = t;
    m_usrcalLastRate = rate;
}

void HipnucSimulator::tick(int64_t t)
{
    if (m_state != State::App)
        return;
    integrateGyroCal(t);

    const MotionState ms = m_motion.at(double(t) * 1e-6);
    const Eigen::Vector3d dir = (ms.q.toRotationMatrix().transpose() * SensorModel::fieldNav()).normalized();
    auto calibrated = [this] {
        m_magCalibrated = true;
        const Eigen::Vector3d h = m_sensor.hardIron();
        for (int i = 0; i < 3; ++i)
            m_magBias[i] = std::round(h[i] * 100.0) / 100.0;
    };

    if (m_mcalStat == 1) {
        m_mcalCoverage.add(dir);
        m_mcalProgress = std::max(m_mcalProgress, m_mcalCoverage.progress());
        if (m_mcalProgress >= 100) {
            m_mcalStat = 2;
            m_mcalVerifyUntilUs = t + kMagCalVerifyUs;
        } else if (t - m_mcalStartUs >= kMagCalTimeoutUs) {
            m_mcalStat = 4;
            qCDebug(lcSim) << "MCAL failed at progress" << m_mcalProgress;
        }
    } else if (m_mcalStat == 2 && t >= m_mcalVerifyUntilUs) {
        m_mcalStat = 3;
        calibrated();
    }

    // v1.6.6: background calibration while in 9-axis mode with IMU_EN_MCAL 1.
    if (m_edition == ManualEdition::V166 && hasMagnetometer() && !m_magCalibrated && m_running.backgroundMagCal
        && m_active.attMode == 1) {
        m_bgCoverage.add(dir);
        if (m_bgCoverage.progress() >= 100) {
            calibrated();
            qCDebug(lcSim) << "background magnetometer calibration done at" << t << "us";
        }
    }
}

// ---------------------------------------------------------------------------------------
// Input

void HipnucSimulator::receive(const uint8_t *data, size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        switch (m_state) {
        case State::App: appByte(data[i]); break;
        case State::Rebooting: break; // nobody listens while the MCU resets
        case State::Bootloader: bootloaderByte(data[i]); break;
        }
    }
}

void HipnucSimulator::appByte(uint8_t c)
{
    if (c == '\n') {
        if (!m_lineOverflow) {
            std::string line;
            line.swap(m_line);
            while (!line.empty() && line.back() == '\r')
                line.pop_back();
            processLine(line);
        }
        m_line.clear();
        m_lineOverflow = false;
        return;
    }
    if (m_line.size() >= kMaxLine) {
        m_lineOverflow = true;
        return;
    }
    m_line.push_back(char(c));
}

void HipnucSimulator::bootloaderByte(uint8_t c)
{
    if (m_blPrev == 0x5A && c == 0xA6) {
        // KBOOT ping response: P2.0.0, options 0, CRC-16/XMODEM over the first 8 bytes.
        std::vector<uint8_t> r = {0x5A, 0xA7, 0x00, 0x00, 0x02, 0x50, 0x00, 0x00};
        const uint16_t crc = protocol::hipnuc::crc16(r.data(), r.size());
        r.push_back(uint8_t(crc & 0xFF));
        r.push_back(uint8_t(crc >> 8));
        enqueue(std::move(r), false);
        m_blPrev = 0;
        return;
    }
    m_blPrev = c;
}

void HipnucSimulator::processLine(const std::string &line)
{
    const auto tok = tokenize(line);
    if (tok.empty())
        return;
    Reply r = dispatch(tok);
    switch (r.outcome) {
    case Outcome::Silent:
        qCDebug(lcSim) << "no reply to" << line.c_str();
        break;
    case Outcome::Ok: {
        std::string text;
        for (const auto &l : r.lines)
            text += l + "\r\n";
        text += "OK\r\n";
        enqueueText(text);
        break;
    }
    case Outcome::Err:
        qCDebug(lcSim) << "ERR for" << line.c_str();
        enqueueText("ERR\r\n");
        break;
    }
    if (r.outcome == Outcome::Ok && r.after)
        r.after();
}

HipnucSimulator::Reply HipnucSimulator::dispatch(const std::vector<std::string> &tok)
{
    const Reply ok{Outcome::Ok, {}, {}};
    const Reply err{Outcome::Err, {}, {}};
    const Reply silent{};
    const std::string &k = tok[0];

    if (k == "REBOOT") {
        if (tok.size() == 1)
            return Reply{Outcome::Ok, {}, [this] { beginReset(State::App, kRebootUs); }};
        if (tok.size() == 2 && tok[1] == "BL")
            return Reply{Outcome::Ok, {}, [this] { beginReset(State::Bootloader, kBootloaderEntryUs); }};
        return err;
    }
    if (k == "SAVECONFIG") {
        if (tok.size() != 1)
            return err;
        m_saved = m_running;
        return ok;
    }
    if (k == "FRESET") {
        if (tok.size() != 1)
            return err;
        m_running = factoryConfig();
        m_saved = m_running;
        m_level = Eigen::Quaterniond::Identity();
        return Reply{Outcome::Ok, {}, [this] { beginReset(State::App, kRebootUs); }};
    }
    if (k == "SERIALCONFIG")
        return cmdSerialConfig(tok);
    if (k == "CONFIG")
        return cmdConfig(tok);
    if (k == "LOG")
        return cmdLog(tok);
    return silent;
}

HipnucSimulator::Reply HipnucSimulator::cmdSerialConfig(const std::vector<std::string> &tok)
{
    const Reply err{Outcome::Err, {}, {}};
    int com = 1, baud = 0;
    if (tok.size() == 2) {
        if (!parseInt(tok[1], baud))
            return err;
    } else if (tok.size() == 3) {
        com = comNumber(tok[1]);
        if (com < 1 || com > 4 || !parseInt(tok[2], baud))
            return err;
    } else {
        return err;
    }
    if (!supportsBaud(baud))
        return err;
    if (com != 1)
        return Reply{Outcome::Ok, {}, {}}; // another port of the module; this UART is unchanged
    m_running.baud = baud;
    return Reply{Outcome::Ok, {}, [this, baud] {
                     qCDebug(lcSim) << "baud" << m_baud << "->" << baud;
                     m_baud = baud;
                 }};
}

HipnucSimulator::Reply HipnucSimulator::cmdConfig(const std::vector<std::string> &tok)
{
    const Reply ok{Outcome::Ok, {}, {}};
    const Reply err{Outcome::Err, {}, {}};
    const Reply silent{};
    const bool v171 = m_edition == ManualEdition::V171;
    if (tok.size() < 2)
        return err;
    const std::string &sub = tok[1];

    if (sub == "ATT") {
        if (tok.size() != 4)
            return err;
        int v = 0;
        if (!parseInt(tok[3], v))
            return err;
        if (tok[2] == "MODE") {
            if (!(v == 0 || v == 1 || (v == 4 && v171)))
                return err;
            if (v == 1 && !hasMagnetometer())
                return err;
            m_running.attMode = v;
            return ok;
        }
        if (tok[2] == "RST") {
            if (m_family == model::ProductFamily::HI02)
                return err; // no user attitude calibration
            const Eigen::Quaterniond q = attitudeAt(m_nowUs, true);
            const EulerAngles e = eulerEnu312(q);
            switch (v) {
            case 1:
                if (!v171)
                    return err;
                m_yawOffsetDeg -= e.yaw;
                return ok;
            case 2: {
                const Eigen::Quaterniond tilt = qAxis(e.pitch, Eigen::Vector3d::UnitX()) * qAxis(e.roll, Eigen::Vector3d::UnitY());
                const auto &r = m_running.relativeLevel;
                const Eigen::Quaterniond rel(r[0], r[1], r[2], r[3]);
                const Eigen::Quaterniond next = canonical(m_level.conjugate() * tilt * m_level * rel);
                m_running.relativeLevel = {next.w(), next.x(), next.y(), next.z()};
                return ok;
            }
            case 3: {
                if (std::fabs(e.pitch) >= 5.0)
                    return err;
                double target = 0;
                if (std::fabs(e.roll) < 5.0)
                    target = 0;
                else if (std::fabs(e.roll) > 175.0)
                    target = 180.0;
                else
                    return err;
                const Eigen::Quaterniond c = qAxis(-target, Eigen::Vector3d::UnitY()) * qAxis(e.pitch, Eigen::Vector3d::UnitX())
                    * qAxis(e.roll, Eigen::Vector3d::UnitY());
                m_level = canonical(c * m_level);
                return ok;
            }
            case 5:
                m_running.relativeLevel = {1, 0, 0, 0};
                return ok;
            default:
                return err;
            }
        }
        return err;
    }

    if (sub == "IMU") {
        if (tok.size() >= 3 && tok[2] == "COORD") {
            if (!v171)
                return silent;
            int v = 0;
            if (tok.size() != 4 || !parseInt(tok[3], v) || (v != 0 && v != 4))
                return err;
            m_running.coord = v;
            return ok;
        }
        if (tok.size() >= 3 && tok[2] == "URFR") {
            if (v171) {
                if (tok.size() != 4)
                    return err;
                const auto code = model::Mounting::parseCode(tok[3]);
                if (!code)
                    return err;
                m_running.urfrCode = *code;
                return ok;
            }
            std::string joined;
            for (size_t i = 3; i < tok.size(); ++i)
                joined += tok[i];
            std::vector<double> v;
            size_t start = 0;
            for (;;) {
                const size_t comma = joined.find(',', start);
                double x = 0;
                if (!parseDouble(std::string_view(joined).substr(start, comma == std::string::npos ? std::string::npos : comma - start), x))
                    return err;
                v.push_back(x);
                if (comma == std::string::npos)
                    break;
                start = comma + 1;
            }
            if (v.size() != 9)
                return err;
            model::Matrix3 m{};
            for (size_t i = 0; i < 9; ++i) {
                if (std::fabs(v[i]) > 1.0 + 1e-9)
                    return err;
                m[i / 3][i % 3] = v[i];
            }
            if (!model::Mounting::isRotation(m))
                return err;
            m_running.urfrMatrix = m;
            return ok;
        }
        return err;
    }

    if (sub == "IMU_EN_MCAL") {
        if (v171)
            return silent;
        int v = 0;
        if (tok.size() != 3 || !parseInt(tok[2], v) || (v != 0 && v != 1) || !hasMagnetometer())
            return err;
        m_running.backgroundMagCal = v == 1;
        return ok;
    }

    if (sub == "YAW") {
        if (v171)
            return silent;
        int mode = 0;
        double deg = 0;
        if (tok.size() != 4 || !parseInt(tok[2], mode) || (mode != 0 && mode != 1) || !parseDouble(tok[3], deg)
            || deg < -180.0 || deg > 180.0)
            return err;
        if (mode == 1)
            m_yawOffsetDeg += deg - eulerEnu312(attitudeAt(m_nowUs, true)).yaw;
        else
            m_yawOffsetDeg += deg;
        return ok;
    }

    if (const int fn = suffixNumber(sub, "PMUX"); fn >= 0) {
        if (!hasPmux())
            return err;
        const int maxFn = v171 ? 3 : 5;
        const int maxIo = v171 ? 5 : 9;
        if (fn < 1 || fn > maxFn)
            return err;
        if (tok.size() == 3) {
            const int io = suffixNumber(tok[2], "IO");
            if (io < 1 || io > maxIo)
                return err;
            m_running.pmux[size_t(fn - 1)] = io;
            return ok;
        }
        if (tok.size() == 4 && v171 && fn == 2 && tok[2] == "DIV") {
            int div = 0;
            if (!parseInt(tok[3], div) || div < 1 || div > 1000)
                return err;
            m_running.pmux2Div = div;
            return ok;
        }
        return err;
    }

    if (sub == "MCAL") {
        if (m_firmware < model::FirmwareVersion{1, 7, 0})
            return silent;
        if (tok.size() != 3 || tok[2] != "START" || !hasMagnetometer())
            return err;
        m_mcalStat = 1;
        m_mcalProgress = 0;
        m_mcalStartUs = m_nowUs;
        m_mcalCoverage.reset();
        return ok;
    }

    if (sub == "USRCAL") {
        if (tok.size() == 4 && tok[2] == "START") {
            int angle = 0;
            if (!parseInt(tok[3], angle) || angle < 720 || angle > 1800)
                return err;
            m_usrcalActive = true;
            m_usrcalTarget = angle;
            m_usrcalAngle = 0;
            m_usrcalStartUs = m_usrcalLastUs = m_nowUs;
            m_usrcalLastRate = m_motion.at(double(m_nowUs) * 1e-6).rateDps.z();
            return ok;
        }
        if (tok.size() == 3 && tok[2] == "STOP") {
            if (!m_usrcalActive)
                return err;
            integrateGyroCal(m_nowUs);
            m_usrcalActive = false;
            const double secs = double(m_nowUs - m_usrcalStartUs) * 1e-6;
            const double turned = std::fabs(m_usrcalAngle);
            const double meanRate = secs > 0 ? turned / secs : 0;
            const bool good = std::fabs(turned - m_usrcalTarget) <= 5.0 && meanRate >= 20.0 && meanRate <= 100.0;
            qCDebug(lcSim) << "USRCAL" << turned << "deg in" << secs << "s, target" << m_usrcalTarget << (good ? "ok" : "failed");
            return good ? ok : err;
        }
        return err;
    }

    return silent;
}

HipnucSimulator::Reply HipnucSimulator::cmdLog(const std::vector<std::string> &tok)
{
    const Reply ok{Outcome::Ok, {}, {}};
    const Reply err{Outcome::Err, {}, {}};
    const Reply silent{};
    const bool v171 = m_edition == ManualEdition::V171;
    if (tok.size() < 2)
        return err;

    size_t at = 1;
    int com = 1;
    if (const int n = comNumber(tok[1]); n >= 0) {
        if (n < 1 || n > 4 || tok.size() < 3)
            return err;
        com = n;
        at = 2;
    }
    const std::string &w = tok[at];

    if (at == 1) {
        if (w == "ENABLE" || w == "DISABLE") {
            if (tok.size() != 2)
                return err;
            m_logEnabled = w == "ENABLE";
            return ok;
        }
        if (w == "VERSION") {
            if (tok.size() != 2)
                return err;
            Reply r = ok;
            r.lines = {"PNAME=" + productName(), "BUILD=Oct 15 2024", "UUID=" + m_uuid,
                       "APP_VER=" + std::to_string(m_firmware.major) + std::to_string(m_firmware.minor)
                           + std::to_string(m_firmware.patch),
                       "BL_VER=109"};
            return r;
        }
        if (w == "COMCONFIG") {
            if (tok.size() != 2)
                return err;
            Reply r = ok;
            r.lines = comConfigLines();
            return r;
        }
        if (w == "MAGCONFIG") {
            if (v171)
                return silent;
            if (tok.size() != 2)
                return err;
            char buf[96];
            std::snprintf(buf, sizeof buf, "MB=%.2f, %.2f, %.2f", m_magBias.x(), m_magBias.y(), m_magBias.z());
            Reply r = ok;
            r.lines = {buf};
            return r;
        }
        if (w == "MCAL") {
            if (m_firmware < model::FirmwareVersion{1, 7, 0})
                return silent;
            if (tok.size() != 3 || tok[2] != "STAT")
                return err;
            Reply r = ok;
            r.lines = {"STAT=" + std::to_string(m_mcalStat), "PROGRESS=" + std::to_string(m_mcalProgress)};
            return r;
        }
    }

    Message m{};
    const bool known = protocol::hipnuc::parseMessage(w, m);
    const bool shaped = tok.size() > at + 1 && (tok[at + 1] == "ONTIME" || tok[at + 1] == "ONMARK" || tok[at + 1] == "MAP");
    if (!known && !shaped)
        return silent;
    if (!known || !supportsMessage(m) || tok.size() != at + 3)
        return err;

    const std::string &type = tok[at + 1];
    const std::string &val = tok[at + 2];
    MessageSetting &setting = m_running.message(m);
    const bool apply = com == 1;
    if (type == "ONTIME") {
        double s = 0;
        if (!parseDouble(val, s) || s < 0)
            return err;
        const double ms = s * 1000.0;
        const long rounded = std::lround(ms);
        if (std::fabs(ms - double(rounded)) > 1e-6 || rounded > 1000 || (rounded == 0 && s != 0))
            return err;
        if (apply) {
            setting = rounded == 0 ? MessageSetting{} : onTime(int(rounded));
            scheduleMessage(size_t(m), m_nowUs);
        }
        return ok;
    }
    if (type == "ONMARK") {
        if (val == "1") {
            if (apply) {
                setting = MessageSetting{MessageSetting::Mode::OnMark, 0};
                scheduleMessage(size_t(m), m_nowUs);
            }
            return ok;
        }
        if (val == "ONCE") {
            if (!apply)
                return ok;
            return Reply{Outcome::Ok, {}, [this, m] { emitMessage(m, m_nowUs); }};
        }
        return err;
    }
    if (type == "MAP") {
        uint32_t map = 0;
        if (m != Message::HI83 || !parseU32(val, map) || map == 0 || (map & ~Hi83::kSupportedMask))
            return err;
        if (apply)
            m_running.hi83Map = map;
        return ok;
    }
    return err;
}

std::vector<std::string> HipnucSimulator::comConfigLines() const
{
    const bool v171 = m_edition == ManualEdition::V171;
    const Config &c = m_running;
    std::vector<std::string> out;
    out.push_back("BAUD=" + std::to_string(c.baud));
    out.push_back(std::string("LOG=") + (m_logEnabled ? "ENABLE" : "DISABLE"));
    auto messageLine = [&](Message m) {
        const MessageSetting &s = c.message(m);
        std::string v;
        switch (s.mode) {
        case MessageSetting::Mode::Off: v = "OFF"; break;
        case MessageSetting::Mode::OnTime: v = "ONTIME " + protocol::hipnuc::commands::formatPeriod(s.periodMs / 1000.0); break;
        case MessageSetting::Mode::OnMark: v = "ONMARK 1"; break;
        }
        out.push_back(std::string(protocol::hipnuc::messageName(m)) + "=" + v);
    };
    if (v171)
        for (Message m : kMessages171)
            messageLine(m);
    else
        for (Message m : kMessages166)
            messageLine(m);
    char buf[48];
    if (v171) {
        std::snprintf(buf, sizeof buf, "HI83_MAP=0x%08X", unsigned(c.hi83Map));
        out.push_back(buf);
    }
    out.push_back("ATT_MODE=" + std::to_string(c.attMode));
    if (v171) {
        out.push_back("URFR=" + model::Mounting::codeText(c.urfrCode));
    } else {
        std::string u = "URFR=";
        for (size_t i = 0; i < 9; ++i) {
            if (i)
                u += ',';
            u += number(c.urfrMatrix[i / 3][i % 3]);
        }
        out.push_back(u);
    }
    if (v171)
        out.push_back("COORD=" + std::to_string(c.coord));
    if (hasPmux()) {
        for (size_t i = 0; i < 3; ++i)
            out.push_back("PMUX" + std::to_string(i + 1) + "=IO" + std::to_string(c.pmux[i]));
        if (v171)
            out.push_back("PMUX2_DIV=" + std::to_string(c.pmux2Div));
    }
    if (!v171)
        out.push_back(std::string("IMU_EN_MCAL=") + (c.backgroundMagCal ? "1" : "0"));
    return out;
}

void HipnucSimulator::syncInPulse()
{
    if (m_state != State::App || !m_logEnabled)
        return;
    for (size_t i = 0; i < kMessageCount; ++i)
        if (m_running.messages[i].mode == MessageSetting::Mode::OnMark)
            emitMessage(Message(i), m_nowUs);
}

// ---------------------------------------------------------------------------------------
// Output data

Eigen::Matrix3d HipnucSimulator::userFromSensor() const
{
    Eigen::Matrix3d r;
    if (m_edition == ManualEdition::V171)
        r = toEigen(model::Mounting::userFromSensor(m_active.urfrCode));
    else
        r = toEigen(m_active.urfrMatrix).transpose(); // X_U = C^T X_B
    // A v1.6.6 matrix is only a rotation to 1e-3: keep the output exactly orthonormal.
    return Eigen::Quaterniond(r).normalized().toRotationMatrix();
}

Eigen::Matrix3d HipnucSimulator::levelMatrix() const
{
    return m_level.toRotationMatrix();
}

Eigen::Quaterniond HipnucSimulator::attitudeAt(int64_t t, bool withYawOffset) const
{
    const MotionState ms = m_motion.at(double(t) * 1e-6);
    const Eigen::Quaterniond qus(userFromSensor());
    // R_nav<-user = R_nav<-sensor * R_user<-sensor^T
    Eigen::Quaterniond q = ms.q * qus.conjugate();
    const auto &r = m_running.relativeLevel;
    const Eigen::Quaterniond rel(r[0], r[1], r[2], r[3]);
    q = q * rel.conjugate() * m_level.conjugate();
    if (m_active.coord == 4)
        q = enuToNwu() * q;
    if (withYawOffset)
        q = qAxis(m_yawOffsetDeg, Eigen::Vector3d::UnitZ()) * q;
    return canonical(q);
}

uint16_t HipnucSimulator::mainStatusAt(int64_t t) const
{
    if (m_firmware < model::FirmwareVersion{1, 7, 0})
        return 0; // reserved before 1.7.0
    uint16_t s = uint16_t(1u << MainStatus::UtcUnsync);
    if (m_active.attMode == 1)
        s |= uint16_t(1u << MainStatus::MagAiding);
    if (m_motion.motion() == Motion::Static)
        s |= uint16_t(1u << MainStatus::Static);
    if (t - m_startUs < kWbConvUs)
        s |= uint16_t(1u << MainStatus::WbConv);
    if (m_active.attMode == 1 && !m_magCalibrated)
        s |= uint16_t(1u << MainStatus::MagDist);
    return s;
}

HipnucSimulator::Snapshot HipnucSimulator::snapshotAt(int64_t t)
{
    if (m_sampleUs != t) {
        m_sample = m_sensor.sample(m_motion.at(double(t) * 1e-6));
        m_sampleUs = t;
    }
    Snapshot s;
    s.tUs = t;
    s.systemTimeUs = uint64_t(t - m_startUs);
    s.systemTimeMs = uint32_t((t - m_startUs) / 1000);
    const Eigen::Matrix3d m = levelMatrix() * userFromSensor();
    const Eigen::Vector3d mag = m_magCalibrated ? Eigen::Vector3d(m_sample.mag - m_magBias) : m_sample.mag;
    s.acc = m * m_sample.acc;
    s.gyr = m * m_sample.gyr;
    s.mag = m * mag;
    s.q = attitudeAt(t, true);
    s.euler = eulerEnu312(s.q);
    s.pressurePa = m_sample.pressurePa;
    s.temperatureC = m_sample.temperatureC;
    s.mainStatus = mainStatusAt(t);
    return s;
}

std::string HipnucSimulator::utcFields(int64_t t, int &year, int &month, int &day, int &hour, int &minute, int &ms) const
{
    const int64_t totalMs = kUtcBaseUnixS * 1000 + t / 1000;
    const int64_t days = totalMs / 86400000;
    const int64_t msOfDay = totalMs % 86400000;
    civilFromDays(days, year, month, day);
    hour = int(msOfDay / 3600000);
    minute = int(msOfDay / 60000 % 60);
    ms = int(msOfDay % 60000); // second * 1000 + ms
    char buf[16];
    std::snprintf(buf, sizeof buf, "%02d%02d%02d.%02d", hour, minute, ms / 1000, (ms % 1000) / 10);
    return buf;
}

std::vector<uint8_t> HipnucSimulator::buildMessage(Message m, const Snapshot &s) const
{
    const double radPerDeg = kDeg;
    const double g = model::kGravity;
    int year = 0, month = 0, day = 0, hour = 0, minute = 0, msOfMinute = 0;
    const std::string hhmmss = utcFields(s.tUs, year, month, day, hour, minute, msOfMinute);
    const int8_t temperature = int8_t(std::clamp(std::lround(s.temperatureC), -128L, 127L));
    const int16_t pressure16 = clamp16(s.pressurePa - 100000.0);
    double heading = -s.euler.yaw; // clockwise from north, 0..360
    if (heading < 0)
        heading += 360.0;

    switch (m) {
    case Message::HI91: {
        Hi91 p;
        p.mainStatus = s.mainStatus;
        p.temperature = temperature;
        p.pressure = float(s.pressurePa);
        p.systemTime = s.systemTimeMs;
        for (int i = 0; i < 3; ++i) {
            p.acc[size_t(i)] = float(s.acc[i]);
            p.gyr[size_t(i)] = float(s.gyr[i]);
            p.mag[size_t(i)] = float(s.mag[i]);
        }
        p.roll = float(s.euler.roll);
        p.pitch = float(s.euler.pitch);
        p.yaw = float(s.euler.yaw);
        p.quat = {float(s.q.w()), float(s.q.x()), float(s.q.y()), float(s.q.z())};
        return protocol::hipnuc::buildFrame(protocol::hipnuc::encode(p));
    }
    case Message::HI92: {
        Hi92 p;
        p.status = 0;
        p.temperature = temperature;
        p.pressure = pressure16;
        for (int i = 0; i < 3; ++i) {
            p.gyr[size_t(i)] = clamp16(s.gyr[i] * radPerDeg / 0.001);
            p.acc[size_t(i)] = clamp16(s.acc[i] * g / 0.0048828);
            p.mag[size_t(i)] = clamp16(s.mag[i] / 0.030517);
        }
        p.roll = round32(s.euler.roll * 1000.0);
        p.pitch = round32(s.euler.pitch * 1000.0);
        p.yaw = round32(s.euler.yaw * 1000.0);
        p.quat = {clamp16(s.q.w() * 1e4), clamp16(s.q.x() * 1e4), clamp16(s.q.y() * 1e4), clamp16(s.q.z() * 1e4)};
        return protocol::hipnuc::buildFrame(protocol::hipnuc::encode(p));
    }
    case Message::HI81: {
        Hi81 p;
        p.mainStatus = s.mainStatus;
        p.insStatus = 0;
        for (int i = 0; i < 3; ++i) {
            p.gyr[size_t(i)] = clamp16(s.gyr[i] * radPerDeg / 0.001);
            p.acc[size_t(i)] = clamp16(s.acc[i] * g / 0.0048828);
            p.mag[size_t(i)] = clamp16(s.mag[i] / 0.030517);
        }
        p.pressure = pressure16;
        p.temperature = temperature;
        p.utcYear = uint8_t(year - 2000);
        p.utcMonth = uint8_t(month);
        p.utcDay = uint8_t(day);
        p.utcHour = uint8_t(hour);
        p.utcMinute = uint8_t(minute);
        p.utcMs = uint16_t(msOfMinute);
        p.roll = clamp16(s.euler.roll * 100.0);
        p.pitch = clamp16(s.euler.pitch * 100.0);
        p.yaw = uint16_t(std::lround(heading * 100.0) % 36000);
        p.quat = {clamp16(s.q.w() * 1e4), clamp16(s.q.x() * 1e4), clamp16(s.q.y() * 1e4), clamp16(s.q.z() * 1e4)};
        return protocol::hipnuc::buildFrame(protocol::hipnuc::encode(p));
    }
    case Message::HI83: {
        Hi83 p;
        p.mainStatus = s.mainStatus;
        p.insStatus = 0;
        p.bitmap = m_running.hi83Map;
        for (int i = 0; i < 3; ++i) {
            p.accB[size_t(i)] = float(s.acc[i] * g);
            p.gyrB[size_t(i)] = float(s.gyr[i] * radPerDeg);
            p.magB[size_t(i)] = float(s.mag[i]);
        }
        p.rpy = {float(s.euler.roll), float(s.euler.pitch), float(s.euler.yaw)};
        p.quat = {float(s.q.w()), float(s.q.x()), float(s.q.y()), float(s.q.z())};
        p.systemTimeUs = s.systemTimeUs;
        p.utc = {uint8_t(year - 2000), uint8_t(month), uint8_t(day), uint8_t(hour), uint8_t(minute),
                 uint8_t(msOfMinute & 0xFF), uint8_t(msOfMinute >> 8), 0};
        p.pressure = float(s.pressurePa);
        p.temperature = float(s.temperatureC);
        p.inclination = {float(s.euler.pitch), float(s.euler.roll), 0.0f};
        p.nodeInfo = {8, 0, 0, 0};
        return protocol::hipnuc::buildFrame(protocol::hipnuc::encode(p));
    }
    case Message::GGA: {
        const std::string body = "GPGGA," + hhmmss + ",3112.5000,N,12127.5000,E,1,12,0.8,40.000,M,0.000,M,,";
        const std::string s1 = protocol::nmea::buildSentence(body);
        return {s1.begin(), s1.end()};
    }
    case Message::RMC: {
        char buf[128];
        std::snprintf(buf, sizeof buf, "GPRMC,%s,A,3112.5000,N,12127.5000,E,0.0,%.1f,%02d%02d%02d,0.0,E,A", hhmmss.c_str(),
                      heading, day, month, year % 100);
        const std::string s1 = protocol::nmea::buildSentence(buf);
        return {s1.begin(), s1.end()};
    }
    case Message::SXT: {
        // date-time, lon, lat, alt, heading, pitch, track, speed, roll, solq, solq_heading,
        // nv, nv_heading, gyr x y z (deg/s), vel E N U, ins_stat, ant_stat. Kept below the
        // 120 characters protocol::nmea accepts.
        char buf[160];
        std::snprintf(buf, sizeof buf,
                      "GPSXT,%04d%02d%02d%s,121.458333,31.208333,40.0,%.2f,%.2f,0,0,%.2f,1,0,12,0,%.1f,%.1f,%.1f,0,0,0,0,0",
                      year, month, day, hhmmss.c_str(), heading, s.euler.pitch, s.euler.roll, s.gyr.x(), s.gyr.y(),
                      s.gyr.z());
        const std::string s1 = protocol::nmea::buildSentence(buf);
        return {s1.begin(), s1.end()};
    }
    }
    return {};
}

void HipnucSimulator::emitMessage(Message m, int64_t t)
{
    if (!supportsMessage(m))
        return;
    // A binary frame that cannot fit is dropped before it is built (a saturated link at
    // 1 kHz would otherwise synthesise every frame only to throw it away).
    size_t size = 0;
    switch (m) {
    case Message::HI91: size = Hi91::kSize; break;
    case Message::HI92: size = Hi92::kSize; break;
    case Message::HI81: size = Hi81::kSize; break;
    case Message::HI83: size = Hi83::payloadSize(m_running.hi83Map).value_or(0); break;
    default: break;
    }
    if (size > 0) {
        drainTo(m_nowUs);
        if (m_txQueued + size + protocol::hipnuc::FrameDecoder::kHeaderSize > kTxBufferSize) {
            ++m_dropped;
            return;
        }
    }
    const Snapshot s = snapshotAt(t);
    enqueue(buildMessage(m, s), true);
}

// ---------------------------------------------------------------------------------------
// UART

bool HipnucSimulator::enqueue(std::vector<uint8_t> bytes, bool data)
{
    if (bytes.empty())
        return true;
    drainTo(m_nowUs);
    if (data && m_txQueued + bytes.size() > kTxBufferSize) {
        ++m_dropped;
        return false;
    }
    Chunk c;
    c.baud = m_baud;
    c.byteUs = 1e7 / double(m_baud); // 10 bits per byte (8N1)
    c.startUs = std::max(double(m_nowUs), m_lineFreeUs);
    c.id = m_nextChunkId++;
    c.data = data;
    m_lineFreeUs = c.startUs + double(bytes.size()) * c.byteUs;
    m_txQueued += bytes.size();
    c.bytes = std::move(bytes);
    m_tx.push_back(std::move(c));
    return true;
}

void HipnucSimulator::enqueueText(const std::string &text)
{
    enqueue(std::vector<uint8_t>(text.begin(), text.end()), false);
}

void HipnucSimulator::drainTo(int64_t t)
{
    while (!m_tx.empty()) {
        Chunk &c = m_tx.front();
        const size_t n = c.bytes.size();
        const double elapsed = double(t) - c.startUs;
        size_t k = 0;
        if (elapsed > 0)
            k = std::min(n, size_t(std::floor(elapsed / c.byteUs + 1e-9)));
        if (k > c.sent) {
            const bool start = c.sent == 0;
            if (!start && !m_out.empty() && m_out.back().chunk == c.id) {
                m_out.back().bytes.insert(m_out.back().bytes.end(), c.bytes.begin() + long(c.sent), c.bytes.begin() + long(k));
                m_out.back().chunkEnd = k == n;
            } else {
                OutputSegment seg;
                seg.baud = c.baud;
                seg.bytes.assign(c.bytes.begin() + long(c.sent), c.bytes.begin() + long(k));
                seg.chunk = c.id;
                seg.chunkStart = start;
                seg.chunkEnd = k == n;
                seg.data = c.data;
                m_out.push_back(std::move(seg));
            }
            m_txQueued -= k - c.sent;
            c.sent = k;
        }
        if (c.sent < n)
            break; // later chunks start after this one ends
        m_tx.pop_front();
    }
}

void HipnucSimulator::dropUnsent(int64_t t)
{
    drainTo(t);
    m_tx.clear();
    m_txQueued = 0;
    m_lineFreeUs = double(t);
}

std::vector<HipnucSimulator::OutputSegment> HipnucSimulator::takeOutputSegments()
{
    drainTo(m_nowUs);
    std::vector<OutputSegment> out;
    out.swap(m_out);
    return out;
}

std::vector<uint8_t> HipnucSimulator::takeOutput()
{
    std::vector<uint8_t> out;
    for (auto &seg : takeOutputSegments())
        out.insert(out.end(), seg.bytes.begin(), seg.bytes.end());
    return out;
}

} // namespace imudesk::sim
