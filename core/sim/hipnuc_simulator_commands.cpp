// HipnucSimulator: the ASCII command interpreter (both manuals' commands, replies,
// LOG COMCONFIG). The clock, motion and output side is in hipnuc_simulator.cpp.
#include "hipnuc_simulator.h"

#include <cctype>

#include "protocol/hipnuc/crc16.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"
#include "simulator_detail.h"

#include <algorithm>

namespace imudesk::sim {

namespace {

// The KEY=VALUE lines in the style a fault asks for (SimFaults::ComConfigStyle).
std::vector<std::string> styledComConfig(std::vector<std::string> lines, SimFaults::ComConfigStyle style)
{
    if (style == SimFaults::ComConfigStyle::KeyValue)
        return lines;
    std::vector<std::string> out;
    std::string joined;
    for (size_t i = 0; i < lines.size(); ++i) {
        const size_t eq = lines[i].find('=');
        std::string key = lines[i].substr(0, eq);
        const std::string value = eq == std::string::npos ? std::string() : lines[i].substr(eq + 1);
        if (style == SimFaults::ComConfigStyle::Unlabelled) {
            joined += (joined.empty() ? "" : " ") + value;
            continue;
        }
        for (char &c : key)
            c = char(std::tolower(uint8_t(c)));
        joined += (joined.empty() ? "" : "; ") + key + " : " + value;
        if (i % 3 == 2) {
            out.push_back(joined);
            joined.clear();
        }
    }
    if (!joined.empty())
        out.push_back(joined);
    return out;
}

} // namespace

using namespace detail;

// ---------------------------------------------------------------------------------------
// Input

void HipnucSimulator::receive(const uint8_t *data, size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        switch (m_state) {
        case State::App: appByte(data[i]); break;
        case State::Rebooting: break; // nobody listens while the MCU resets
        case State::Bootloader: m_bootloader.receive(data + i, n - i, m_nowUs); return;
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

void HipnucSimulator::processLine(const std::string &line)
{
    const auto tok = tokenize(line);
    if (tok.empty())
        return;
    std::string joined;
    for (const auto &t : tok)
        joined += (joined.empty() ? "" : " ") + t;
    Reply r = (!m_refusedPrefix.empty() && joined.rfind(m_refusedPrefix, 0) == 0) ? Reply{Outcome::Err, {}, {}}
                                                                                 : dispatch(tok);
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
                     const int to = m_baudOverride == 0 ? baud : (m_baudOverride < 0 ? m_baud : m_baudOverride);
                     qCDebug(lcSim) << "baud" << m_baud << "->" << to;
                     m_baud = to;
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
            r.lines = styledComConfig(comConfigLines(), m_options.faults.comConfigStyle);
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
            u += formatNumber(c.urfrMatrix[i / 3][i % 3]);
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

} // namespace imudesk::sim
