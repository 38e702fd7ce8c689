#include "session.h"

#include "device/session_engine.h"
#include "io/serial_transport.h"
#include "jobs/thread_sync.h"

namespace imudesk::device {

Session::Session(std::unique_ptr<FamilyPlugin> family, std::unique_ptr<io::Transport> transport,
                 const QString &threadName, int lineIdleMs, QObject *parent, QThread *sharedThread)
    : DeviceLink(parent), m_sharedThread(sharedThread)
{
    if (!transport)
        transport = std::make_unique<io::SerialTransport>();
    m_family = family.get();
    m_linkKind = m_family->linkKind();
    m_thread.setObjectName(threadName);
    m_engine = new SessionEngine(family.release(), transport.release(), store(), m_rawLog, lineIdleMs);
    m_engine->moveToThread(m_sharedThread ? m_sharedThread : &m_thread);
    if (!m_sharedThread)
        connect(&m_thread, &QThread::finished, m_engine, &QObject::deleteLater);

    connect(m_engine, &SessionEngine::stateChanged, this,
            [this](SessionState s, const QString &detail) { setState(s, detail); });
    connect(m_engine, &SessionEngine::identityChanged, this, &Session::identityChanged);
    connect(m_engine, &SessionEngine::statsUpdated, this, &Session::statsUpdated);
    connect(m_engine, &SessionEngine::errorOccurred, this, &Session::errorOccurred);
    connect(m_engine, &SessionEngine::streamWarning, this, &Session::streamWarning);
    connect(m_engine, &SessionEngine::requestFinished, this, &Session::requestEnded);
    connect(m_engine, &SessionEngine::reconnected, this, &Session::reconnected);
    connect(m_engine, &SessionEngine::recordingStarted, this, &Session::recordingStarted);
    connect(m_engine, &SessionEngine::recordingStopped, this, &Session::recordingStopped);
    connect(m_engine, &SessionEngine::recordingProgress, this, &Session::recordingProgress);
    if (!m_sharedThread) {
        jobs::announceJoin(m_thread);
        m_thread.start();
    }
}

Session::~Session()
{
    m_engine->disconnect(this);
    if (m_sharedThread) {
        // The thread goes on for other sessions: close and delete the engine in it, now.
        SessionEngine *e = m_engine;
        const auto finish = [e] {
            e->close();
            delete e;
        };
        if (m_sharedThread == QThread::currentThread() || !m_sharedThread->isRunning())
            finish();
        else
            jobs::callAndWait(e, finish);
        return;
    }
    jobs::callAndWait(m_engine, [e = m_engine] { e->close(); });
    jobs::joinThread(m_thread);
}

void Session::openLink(const QString &address, int baud)
{
    jobs::postTo(m_engine, [e = m_engine, address, baud] { e->open(address, baud); });
}

std::unique_ptr<io::Transport> Session::releaseTransport()
{
    std::unique_ptr<io::Transport> taken;
    QThread *here = QThread::currentThread();
    jobs::callAndWait(m_engine, [e = m_engine, &taken, here] { taken = e->releaseTransport(here); });
    return taken;
}

void Session::close()
{
    jobs::postTo(m_engine, [e = m_engine] { e->close(); });
}

void Session::setAutoReconnect(bool on)
{
    m_autoReconnect = on;
    jobs::postTo(m_engine, [e = m_engine, on] { e->setAutoReconnect(on); });
}

void Session::startRecording(const QString &path, std::shared_ptr<StreamTap> tap, const capture::CaptureHeader &header)
{
    jobs::postTo(m_engine, [e = m_engine, path, tap = std::move(tap), header]() mutable {
        e->startRecording(path, std::move(tap), header);
    });
}

void Session::stopRecording()
{
    jobs::postTo(m_engine, [e = m_engine] { e->stopRecording(); });
}

quint64 Session::submit(Request request)
{
    const quint64 id = m_nextId++;
    request.id = id;
    jobs::postTo(m_engine, [e = m_engine, r = std::move(request)]() mutable { e->submit(std::move(r)); });
    return id;
}

quint64 Session::refuse(const QVariant &reply, const QString &why)
{
    RequestResult r;
    r.id = m_nextId++;
    r.status = RequestStatus::NotSent;
    r.message = why;
    r.reply = reply;
    QTimer::singleShot(0, this, [this, r] { Q_EMIT requestEnded(r); });
    return r.id;
}

} // namespace imudesk::device
