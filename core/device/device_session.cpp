#include "device_session.h"

#include "device/session_worker.h"

namespace imudesk::device {

const char *stateName(SessionState s)
{
    switch (s) {
    case SessionState::Closed: return "closed";
    case SessionState::Opening: return "opening";
    case SessionState::Detecting: return "detecting";
    case SessionState::Connected: return "connected";
    case SessionState::Disconnected: return "disconnected";
    case SessionState::Failed: return "failed";
    case SessionState::Reconnecting: return "reconnecting";
    }
    return "?";
}

const std::vector<int> &DeviceSession::detectionBauds()
{
    static const std::vector<int> bauds = {115200, 921600, 460800, 230400, 256000, 57600, 38400, 19200, 9600, 4800};
    return bauds;
}

DeviceSession::DeviceSession(QObject *parent) : DeviceLink(parent)
{
    qRegisterMetaType<protocol::hipnuc::AsciiReply>();

    m_thread.setObjectName(QStringLiteral("imudesk-session"));
    m_worker = new SessionWorker(store(), m_rawLog);
    m_worker->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);

    connect(m_worker, &SessionWorker::stateChanged, this, [this](SessionState s, const QString &detail) {
        setState(s, detail);
    });
    connect(m_worker, &SessionWorker::baudDetected, this, &DeviceSession::baudDetected);
    connect(m_worker, &SessionWorker::identityChanged, this, &DeviceSession::identityChanged);
    connect(m_worker, &SessionWorker::identityQueryFinished, this, &DeviceSession::identityQueryFinished);
    connect(m_worker, &SessionWorker::commandFinished, this, &DeviceSession::commandFinished);
    connect(m_worker, &SessionWorker::statsUpdated, this, &DeviceSession::statsUpdated);
    connect(m_worker, &SessionWorker::nmeaReceived, this, &DeviceSession::nmeaReceived);
    connect(m_worker, &SessionWorker::textReceived, this, &DeviceSession::textReceived);
    connect(m_worker, &SessionWorker::errorOccurred, this, &DeviceSession::errorOccurred);
    connect(m_worker, &SessionWorker::reconnected, this, &DeviceSession::reconnected);
    connect(m_worker, &SessionWorker::baudChangeFinished, this, &DeviceSession::baudChangeFinished);
    connect(m_worker, &SessionWorker::linkRecovered, this, &DeviceSession::linkRecovered);
    connect(m_worker, &SessionWorker::recordingStarted, this, &DeviceSession::recordingStarted);
    connect(m_worker, &SessionWorker::recordingStopped, this, &DeviceSession::recordingStopped);
    connect(m_worker, &SessionWorker::recordingProgress, this, &DeviceSession::recordingProgress);
    m_thread.start();
}

DeviceSession::~DeviceSession()
{
    QMetaObject::invokeMethod(m_worker, &SessionWorker::close, Qt::BlockingQueuedConnection);
    m_thread.quit();
    m_thread.wait();
}

void DeviceSession::open(const QString &portName, int baud)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, portName, baud] { w->open(portName, baud); },
                              Qt::QueuedConnection);
}

void DeviceSession::close()
{
    QMetaObject::invokeMethod(m_worker, &SessionWorker::close, Qt::QueuedConnection);
}

quint64 DeviceSession::sendCommand(const QString &text, int timeoutMs)
{
    const quint64 id = m_nextId++;
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, id, text, timeoutMs] { w->sendCommand(id, text, timeoutMs); },
        Qt::QueuedConnection);
    return id;
}

quint64 DeviceSession::sendCommand(const protocol::hipnuc::Command &command, int timeoutMs, QString *error)
{
    if (!command.ok()) {
        if (error)
            *error = QString::fromStdString(command.error);
        return 0;
    }
    return sendCommand(QString::fromStdString(command.text), timeoutMs);
}

void DeviceSession::setHostBaud(int baud)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, baud] { w->setHostBaud(baud); }, Qt::QueuedConnection);
}

void DeviceSession::changeBaud(int baud)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, baud] { w->changeBaud(baud); }, Qt::QueuedConnection);
}

void DeviceSession::recoverLink(const QList<int> &bauds, int settleMs)
{
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, bauds, settleMs] { w->recoverLink(bauds, settleMs); }, Qt::QueuedConnection);
}

void DeviceSession::setAutoReconnect(bool on)
{
    m_autoReconnect = on;
    QMetaObject::invokeMethod(m_worker, [w = m_worker, on] { w->setAutoReconnect(on); }, Qt::QueuedConnection);
}

void DeviceSession::startRecording(const QString &path, const record::CaptureHeader &header,
                                   const record::CaptureWriter::Options &options)
{
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, path, header, options] { w->startRecording(path, header, options); },
        Qt::QueuedConnection);
}

void DeviceSession::stopRecording()
{
    QMetaObject::invokeMethod(m_worker, &SessionWorker::stopRecording, Qt::QueuedConnection);
}

} // namespace imudesk::device
