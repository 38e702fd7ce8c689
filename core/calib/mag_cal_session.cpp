#include "calib/mag_cal_session.h"

#include "device/device_session.h"

#include <QLoggingCategory>

Q_DECLARE_LOGGING_CATEGORY(lcCalib)

namespace imudesk::calib {

MagCalSession::MagCalSession(device::DeviceSession &session, MagCalProcedure::Options options, QObject *parent)
    : QObject(parent),
      m_session(session),
      m_procedure(options)
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &MagCalSession::sendNext);
    connect(&m_session, &device::DeviceSession::commandFinished, this, &MagCalSession::onCommandFinished);
}

void MagCalSession::start(MagCalProcedure::Flow flow)
{
    m_running = true;
    m_pending = 0;
    m_clock.start();
    follow(m_procedure.start(flow));
    Q_EMIT progressChanged(m_procedure.stat(), m_procedure.progress(), m_procedure.message());
}

void MagCalSession::cancel()
{
    m_timer.stop();
    m_pending = 0;
    m_running = false;
}

void MagCalSession::follow(const MagCalProcedure::Step &step)
{
    if (!step.hasCommand()) {
        m_running = false;
        const bool ok = m_procedure.state() == MagCalProcedure::State::Succeeded;
        qCInfo(lcCalib) << "device magnetometer calibration" << (ok ? "succeeded" : "failed") << m_procedure.message();
        Q_EMIT finished(ok, m_procedure.message());
        return;
    }
    m_next = step.command;
    if (step.delayMs > 0)
        m_timer.start(step.delayMs);
    else
        sendNext();
}

void MagCalSession::sendNext()
{
    if (!m_running)
        return;
    m_pending = m_session.sendCommand(m_next, 1000);
}

void MagCalSession::onCommandFinished(quint64 id, const protocol::hipnuc::AsciiReply &reply)
{
    if (!m_running || id != m_pending)
        return;
    m_pending = 0;
    const MagCalProcedure::Step step = m_procedure.handleReply(reply, m_clock.elapsed());
    Q_EMIT progressChanged(m_procedure.stat(), m_procedure.progress(), m_procedure.message());
    follow(step);
}

} // namespace imudesk::calib
