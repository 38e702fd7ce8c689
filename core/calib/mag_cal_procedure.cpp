#include "calib/mag_cal_procedure.h"
#include "protocol/hipnuc/ascii_command.h"

#include <QStringList>

#include <algorithm>
#include <cmath>

namespace imudesk::calib {

using protocol::hipnuc::AsciiReply;

namespace {
namespace commands = protocol::hipnuc::commands;
const protocol::hipnuc::Command kStart = commands::magCalStart();
const protocol::hipnuc::Command kStat = commands::logMagCalStatus();
const protocol::hipnuc::Command kMagConfig = commands::logMagConfig();

bool parseInt(const std::map<std::string, std::string> &values, const char *key, int &out)
{
    const auto it = values.find(key);
    if (it == values.end())
        return false;
    bool ok = false;
    const int v = QString::fromStdString(it->second).trimmed().toInt(&ok);
    if (ok)
        out = v;
    return ok;
}
} // namespace

MagCalProcedure::Flow MagCalProcedure::flowFor(const model::FirmwareVersion &fw)
{
    return fw >= model::FirmwareVersion{1, 7, 0} ? Flow::Mcal : Flow::Background;
}

const char *MagCalProcedure::stateName(State s)
{
    switch (s) {
    case State::Idle: return "idle";
    case State::Starting: return "starting";
    case State::Calibrating: return "calibrating";
    case State::Verifying: return "verifying";
    case State::Succeeded: return "succeeded";
    case State::Failed: return "failed";
    }
    return "?";
}

MagCalProcedure::MagCalProcedure() = default;

MagCalProcedure::MagCalProcedure(Options options)
    : m_options(options)
{
}

QString MagCalProcedure::troubleshooting()
{
    return tr("1. Check the field at the calibration spot: hold the module still and read |B|; 20-60 µT is normal. "
              "Below 20 or above 60 µT a magnetic object is near: move away from it or choose another place.\n"
              "2. Check the rotation: turn about every axis at least 360 deg at 20-100 deg/s, without pausing.\n"
              "3. Check for spatial interference: measure |B| at the same spot in different orientations. If it "
              "varies by more than 10 µT, choose another place or use 6-axis mode.\n"
              "Keep the module in place while turning it, and calibrate it together with everything mounted to it.");
}

MagCalProcedure::Step MagCalProcedure::start(Flow flow)
{
    m_flow = flow;
    m_state = State::Starting;
    m_stat = -1;
    m_progress = 0;
    m_missed = 0;
    m_bias.setZero();
    if (flow == Flow::Mcal) {
        m_message = tr("Starting the calibration on the device.");
        return {kStart, 0};
    }
    m_message = tr("This firmware calibrates in the background in 9-axis mode: turn the module slowly through as "
                   "many orientations as you can.");
    return {kMagConfig, 0};
}

MagCalProcedure::Step MagCalProcedure::fail(const QString &why)
{
    m_state = State::Failed;
    m_message = why;
    return {};
}

MagCalProcedure::Step MagCalProcedure::poll()
{
    return {m_flow == Flow::Mcal ? kStat : kMagConfig, m_options.pollIntervalMs};
}

MagCalProcedure::Step MagCalProcedure::handleReply(const AsciiReply &reply, qint64 elapsedMs)
{
    if (finished() || m_state == State::Idle)
        return {};
    if (elapsedMs > m_options.timeoutMs)
        return fail(tr("The device did not finish the calibration within %1 s.").arg(m_options.timeoutMs / 1000));

    if (m_state == State::Starting && m_flow == Flow::Mcal) {
        if (reply.status == AsciiReply::Status::Ok) {
            m_state = State::Calibrating;
            m_message = tr("Calibrating: turn the module slowly about every axis.");
            return poll();
        }
        if (reply.status == AsciiReply::Status::Timeout)
            return fail(tr("The device did not answer CONFIG MCAL START: its firmware is older than 1.7.0 or the "
                           "link is down."));
        return fail(tr("The device refused CONFIG MCAL START (%1): it may have no magnetometer.")
                        .arg(QString::fromStdString(reply.errorLine)));
    }

    if (reply.status != AsciiReply::Status::Ok) {
        if (++m_missed > m_options.maxMissedPolls)
            return fail(tr("The device stopped answering %1 (%2 times in a row).")
                            .arg(QString::fromStdString((m_flow == Flow::Mcal ? kStat : kMagConfig).text))
                            .arg(m_missed));
        return poll();
    }
    m_missed = 0;

    if (m_flow == Flow::Background) {
        m_state = State::Calibrating;
        const auto it = reply.values.find("MB");
        if (it == reply.values.end())
            return fail(tr("LOG MAGCONFIG gave no MB line."));
        const QStringList parts = QString::fromStdString(it->second).split(QLatin1Char(','));
        if (parts.size() != 3)
            return fail(tr("LOG MAGCONFIG gave an unreadable MB line: %1").arg(QString::fromStdString(it->second)));
        for (int i = 0; i < 3; ++i) {
            bool ok = false;
            m_bias[i] = parts[i].trimmed().toDouble(&ok);
            if (!ok || !std::isfinite(m_bias[i]))
                return fail(tr("LOG MAGCONFIG gave an unreadable MB line: %1").arg(QString::fromStdString(it->second)));
        }
        if (!m_bias.isZero()) {
            m_progress = 100;
            m_state = State::Succeeded;
            m_message = tr("The device calibrated itself: bias %1, %2, %3 µT.")
                            .arg(m_bias.x(), 0, 'f', 2)
                            .arg(m_bias.y(), 0, 'f', 2)
                            .arg(m_bias.z(), 0, 'f', 2);
            return {};
        }
        return poll();
    }

    int stat = -1, progress = m_progress;
    if (!parseInt(reply.values, "STAT", stat))
        return fail(tr("LOG MCAL STAT gave no STAT line."));
    parseInt(reply.values, "PROGRESS", progress);
    m_stat = stat;
    m_progress = std::clamp(progress, 0, 100);
    switch (stat) {
    case 0:
        return fail(tr("The device is idle: the calibration stopped (was the device restarted?). Start again."));
    case 1:
        m_state = State::Calibrating;
        m_message = tr("Calibrating (%1 %): keep turning the module slowly about every axis.").arg(m_progress);
        return poll();
    case 2:
        m_state = State::Verifying;
        m_message = tr("Verifying the result: hold the module still.");
        return poll();
    case 3:
        m_state = State::Succeeded;
        m_message = tr("The device reports the calibration done.");
        return {};
    case 4:
        return fail(tr("The device reports the calibration failed (STAT=4)."));
    default:
        return fail(tr("LOG MCAL STAT gave an unknown state %1.").arg(stat));
    }
}

} // namespace imudesk::calib
