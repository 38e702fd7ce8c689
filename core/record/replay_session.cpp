#include "replay_session.h"

#include "jobs/thread_sync.h"
#include "record/replay_worker.h"

#include <algorithm>

namespace imudesk::record {

ReplaySession::ReplaySession(QObject *parent) : DeviceLink(parent)
{
    qRegisterMetaType<capture::CaptureHeader>();
    m_thread.setObjectName(QStringLiteral("imudesk-replay"));
    m_worker = new ReplayWorker(store());
    m_worker->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    connect(m_worker, &ReplayWorker::stateChanged, this,
            [this](device::SessionState s, const QString &detail) { setState(s, detail); });
    connect(m_worker, &ReplayWorker::identityChanged, this, &ReplaySession::identityChanged);
    // The link is named by the family of the bytes it plays ("HiPNUC serial replay"), before
    // anyone hears it opened.
    connect(m_worker, &ReplayWorker::opened, this, [this](double, const capture::CaptureHeader &header) {
        m_linkKind = QString::fromStdString(header.family()) + QStringLiteral(" replay");
    });
    connect(m_worker, &ReplayWorker::opened, this, &ReplaySession::opened);
    connect(m_worker, &ReplayWorker::positionChanged, this, &ReplaySession::positionChanged);
    connect(m_worker, &ReplayWorker::playingChanged, this, &ReplaySession::playingChanged);
    connect(m_worker, &ReplayWorker::finished, this, &ReplaySession::finished);
    connect(m_worker, &ReplayWorker::statsUpdated, this, &ReplaySession::statsUpdated);
    connect(m_worker, &ReplayWorker::nmeaReceived, this, &ReplaySession::nmeaReceived);
    connect(m_worker, &ReplayWorker::errorOccurred, this, &ReplaySession::errorOccurred);
    jobs::announceJoin(m_thread);
    m_thread.start();
}

ReplaySession::~ReplaySession()
{
    if (m_group)
        m_group->remove(this);
    jobs::callAndWait(m_worker, [w = m_worker] { w->close(); });
    jobs::joinThread(m_thread);
}

void ReplaySession::open(const QString &path, const ReplayTimeline &timeline)
{
    jobs::postTo(m_worker, [w = m_worker, path, timeline] { w->open(path, timeline); });
}

void ReplaySession::setGroup(std::shared_ptr<ReplayGroup> group)
{
    if (m_group)
        m_group->remove(this);
    m_group = std::move(group);
    if (m_group)
        m_group->add(this);
}

void ReplaySession::close()
{
    jobs::postTo(m_worker, [w = m_worker] { w->close(); });
}

void ReplaySession::play()
{
    if (m_group)
        m_group->play();
    else
        playAlone();
}

void ReplaySession::pause()
{
    if (m_group)
        m_group->pause();
    else
        pauseAlone();
}

void ReplaySession::setSpeed(double factor)
{
    if (m_group)
        m_group->setSpeed(factor);
    else
        setSpeedAlone(factor);
}

void ReplaySession::seek(double seconds)
{
    if (m_group)
        m_group->seek(seconds);
    else
        seekAlone(seconds);
}

void ReplaySession::setLoop(bool on)
{
    if (m_group)
        m_group->setLoop(on);
    else
        setLoopAlone(on);
}

void ReplaySession::playAlone()
{
    jobs::postTo(m_worker, [w = m_worker] { w->play(); });
}

void ReplaySession::pauseAlone()
{
    jobs::postTo(m_worker, [w = m_worker] { w->pause(); });
}

void ReplaySession::setSpeedAlone(double factor)
{
    const double f = factor <= 0 ? kAsFastAsPossible : std::clamp(factor, kMinSpeed, kMaxSpeed);
    jobs::postTo(m_worker, [w = m_worker, f] { w->setSpeed(f); });
}

void ReplaySession::seekAlone(double seconds)
{
    jobs::postTo(m_worker, [w = m_worker, seconds] { w->seek(seconds); });
}

void ReplaySession::setLoopAlone(bool on)
{
    jobs::postTo(m_worker, [w = m_worker, on] { w->setLoop(on); });
}

} // namespace imudesk::record
