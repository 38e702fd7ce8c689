#include "replay_session.h"

#include "record/replay_worker.h"

#include <algorithm>

namespace imudesk::record {

ReplaySession::ReplaySession(QObject *parent) : DeviceLink(parent)
{
    qRegisterMetaType<CaptureHeader>();
    m_thread.setObjectName(QStringLiteral("imudesk-replay"));
    m_worker = new ReplayWorker(store());
    m_worker->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    connect(m_worker, &ReplayWorker::stateChanged, this,
            [this](device::SessionState s, const QString &detail) { setState(s, detail); });
    connect(m_worker, &ReplayWorker::identityChanged, this, &ReplaySession::identityChanged);
    connect(m_worker, &ReplayWorker::opened, this, &ReplaySession::opened);
    connect(m_worker, &ReplayWorker::positionChanged, this, &ReplaySession::positionChanged);
    connect(m_worker, &ReplayWorker::playingChanged, this, &ReplaySession::playingChanged);
    connect(m_worker, &ReplayWorker::finished, this, &ReplaySession::finished);
    connect(m_worker, &ReplayWorker::statsUpdated, this, &ReplaySession::statsUpdated);
    connect(m_worker, &ReplayWorker::nmeaReceived, this, &ReplaySession::nmeaReceived);
    connect(m_worker, &ReplayWorker::errorOccurred, this, &ReplaySession::errorOccurred);
    m_thread.start();
}

ReplaySession::~ReplaySession()
{
    QMetaObject::invokeMethod(m_worker, &ReplayWorker::close, Qt::BlockingQueuedConnection);
    m_thread.quit();
    m_thread.wait();
}

void ReplaySession::open(const QString &path)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, path] { w->open(path); }, Qt::QueuedConnection);
}

void ReplaySession::close()
{
    QMetaObject::invokeMethod(m_worker, &ReplayWorker::close, Qt::QueuedConnection);
}

void ReplaySession::play()
{
    QMetaObject::invokeMethod(m_worker, &ReplayWorker::play, Qt::QueuedConnection);
}

void ReplaySession::pause()
{
    QMetaObject::invokeMethod(m_worker, &ReplayWorker::pause, Qt::QueuedConnection);
}

void ReplaySession::setSpeed(double factor)
{
    const double f = factor <= 0 ? kAsFastAsPossible : std::clamp(factor, kMinSpeed, kMaxSpeed);
    QMetaObject::invokeMethod(m_worker, [w = m_worker, f] { w->setSpeed(f); }, Qt::QueuedConnection);
}

void ReplaySession::seek(double seconds)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, seconds] { w->seek(seconds); }, Qt::QueuedConnection);
}

void ReplaySession::setLoop(bool on)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, on] { w->setLoop(on); }, Qt::QueuedConnection);
}

} // namespace imudesk::record
