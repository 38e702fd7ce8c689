#include "calib/gyro_cal_session.h"
#include "protocol/hipnuc/ascii_command.h"

#include "device/device_session.h"

#include <QLoggingCategory>

Q_DECLARE_LOGGING_CATEGORY(lcCalib)

namespace imudesk::calib {

using protocol::hipnuc::AsciiReply;

GyroCalSession::GyroCalSession(device::DeviceSession &session, QObject *parent)
    : QObject(parent),
      m_session(session)
{
    connect(&m_session, &device::DeviceSession::commandFinished, this, &GyroCalSession::onCommandFinished);
}

bool GyroCalSession::start(int angleDeg)
{
    if (angleDeg < kMinAngle || angleDeg > kMaxAngle) {
        m_message = tr("The angle must be %1..%2 deg (2 to 5 turns); %3 is not.").arg(kMinAngle).arg(kMaxAngle).arg(angleDeg);
        return false;
    }
    if (m_state == State::Starting || m_state == State::Running || m_state == State::Stopping) {
        m_message = tr("A gyro calibration is already running.");
        return false;
    }
    m_angle = angleDeg;
    m_pending = m_session.sendCommand(protocol::hipnuc::commands::gyroCalStart(angleDeg),
                                      device::DeviceSession::kBusyLinkReplyTimeoutMs);
    setState(State::Starting, tr("Starting the gyro calibration (%1 deg).").arg(angleDeg));
    return true;
}

bool GyroCalSession::stop()
{
    if (m_state != State::Running)
        return false;
    m_pending = m_session.sendCommand(protocol::hipnuc::commands::gyroCalStop(),
                                      device::DeviceSession::kBusyLinkReplyTimeoutMs);
    setState(State::Stopping, tr("Stopping the gyro calibration."));
    return true;
}

void GyroCalSession::setState(State s, const QString &message)
{
    m_state = s;
    m_message = message;
    Q_EMIT stateChanged(s, message);
    if (s == State::Succeeded || s == State::Failed) {
        qCInfo(lcCalib) << "gyro USRCAL" << (s == State::Succeeded ? "succeeded" : "failed") << message;
        Q_EMIT finished(s == State::Succeeded, message);
    }
}

void GyroCalSession::onCommandFinished(quint64 id, const AsciiReply &reply)
{
    if (id != m_pending || m_pending == 0)
        return;
    m_pending = 0;
    if (m_state == State::Starting) {
        if (reply.ok())
            setState(State::Running, tr("Turn the module %1 deg at an even 20-100 deg/s, then stop on the mark.").arg(m_angle));
        else if (reply.status == AsciiReply::Status::Timeout)
            setState(State::Failed, tr("The device did not answer CONFIG USRCAL START: check the link."));
        else
            setState(State::Failed, tr("The device refused CONFIG USRCAL START %1 (%2).")
                                        .arg(m_angle)
                                        .arg(QString::fromStdString(reply.errorLine)));
        return;
    }
    if (m_state == State::Stopping) {
        if (reply.ok())
            setState(State::Succeeded, tr("The device accepted the calibration (OK)."));
        else if (reply.status == AsciiReply::Status::Timeout)
            setState(State::Failed, tr("The device did not answer CONFIG USRCAL STOP: check the link, then repeat."));
        else
            setState(State::Failed, tr("The device rejected the run (ERR): the angle turned was not within 5 deg of "
                                       "%1 deg, or the rate was outside 20-100 deg/s or uneven. Repeat it.")
                                        .arg(m_angle));
    }
}

} // namespace imudesk::calib
