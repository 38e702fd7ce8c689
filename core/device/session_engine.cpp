#include "session_engine.h"

#include "clock/host_clock.h"
#include "device/stream_counters.h"
#include "io/reading_priority.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QLoggingCategory>
#include <QThread>

#include <atomic>
#include <utility>

Q_LOGGING_CATEGORY(lcEngine, "imudesk.core.device")

namespace imudesk::device {

namespace {

int64_t utcUs()
{
    return QDateTime::currentMSecsSinceEpoch() * 1000;
}

// The worker thread reads the device: ask once for a prompt wake-up (io/reading_priority.h says
// what the OS offers and why). A refusal is logged once per process.
void raiseReadingThread()
{
    thread_local bool raised = false;
    if (raised)
        return;
    raised = true;
    const io::ReadingPriority p = io::raiseCurrentThreadForReading();
    static std::atomic<bool> told{false};
    if (p.sliceErrno != 0 && !told.exchange(true))
        qCInfo(lcEngine).noquote() << p.describe();
}

} // namespace

SessionEngine::SessionEngine(FamilyPlugin *family, io::Transport *transport, SampleStore &store,
                             RawByteLog &rawLog, int lineIdleMs)
    : m_family(family), m_transport(transport), m_store(store), m_rawLog(rawLog), m_reconnector(*transport, this)
{
    qRegisterMetaType<RequestResult>();
    m_family->setParent(this);
    m_family->attach(this);
    m_transport->setParent(this);
    connect(m_transport, &io::Transport::bytesReceived, this, &SessionEngine::onBytes);
    connect(m_transport, &io::Transport::failed, this, &SessionEngine::onTransportFailed);
    connect(m_transport, &io::Transport::notice, this, &SessionEngine::errorOccurred);
    m_replyTimer.setSingleShot(true);
    connect(&m_replyTimer, &QTimer::timeout, this, &SessionEngine::onReplyTimeout);
    m_holdTimer.setSingleShot(true);
    connect(&m_holdTimer, &QTimer::timeout, this, [this] {
        if (m_current)
            writeCurrent(); // no gap came within the hold
    });
    m_idleTimer.setSingleShot(true);
    m_idleTimer.setInterval(lineIdleMs);
    connect(&m_idleTimer, &QTimer::timeout, this, &SessionEngine::onLineIdle);
    m_statsTimer.setInterval(kStatsPeriodMs);
    connect(&m_statsTimer, &QTimer::timeout, this, &SessionEngine::publishStats);
}

SessionEngine::~SessionEngine()
{
    if (m_tap)
        m_tap->end(); // what is queued is written; nobody is left to tell
}

void SessionEngine::setState(SessionState s, const QString &detail)
{
    m_state = s;
    Q_EMIT stateChanged(s, detail);
}

void SessionEngine::setIdentity(const model::DeviceIdentity &identity)
{
    m_identity = identity;
    Q_EMIT identityChanged(identity);
}

// ---------------------------------------------------------------------------------------
// The link

void SessionEngine::open(const QString &address, int baud)
{
    raiseReadingThread();
    if (!m_transport)
        return; // handed over (releaseTransport): this engine has no link any more
    // A transport handed over open by a detection (LinkOpener) to a session that never opened:
    // taken as it is, so that the port is opened once.
    const bool adopted = m_state == SessionState::Closed && m_transport->isOpen() && m_transport->address() == address;
    if (!adopted)
        close();
    m_workingBaud = 0;
    m_identity = {};
    setState(SessionState::Opening, address);
    QString error;
    const int first = m_family->firstBaud(baud);
    if (adopted) {
        if (m_transport->baud() != first)
            m_transport->setBaud(first);
    } else if (!m_transport->open(address, first, &error)) {
        setState(SessionState::Failed, error);
        Q_EMIT errorOccurred(error);
        return;
    }
    m_family->restartStream();
    m_reconnector.resetCount();
    restartStatistics();
    m_statsTimer.start();
    m_family->opened(baud);
}

void SessionEngine::stopActivity(const QString &why)
{
    m_reconnector.stop();
    m_idleTimer.stop();
    cancelAll(RequestStatus::Cancelled, why);
    if (m_tap)
        finishRecording(QString());
}

std::unique_ptr<io::Transport> SessionEngine::releaseTransport(QThread *thread)
{
    if (!m_transport)
        return {};
    m_family->stopping();
    stopActivity(tr("the link went to the device's own session"));
    m_reconnector.setEnabled(false);
    m_statsTimer.stop();
    m_transport->disconnect(this);
    io::Transport *t = std::exchange(m_transport, nullptr);
    t->setParent(nullptr);
    t->moveToThread(thread);
    setState(SessionState::Closed);
    return std::unique_ptr<io::Transport>(t);
}

void SessionEngine::close()
{
    if (!m_transport)
        return; // handed over (releaseTransport)
    m_family->stopping();
    withdrawGarbageWarning();
    const bool waiting = m_reconnector.waiting() || m_state == SessionState::Reconnecting;
    stopActivity(tr("the connection was closed"));
    if (m_transport->isOpen()) {
        m_transport->close();
        publishStats();
        m_statsTimer.stop();
        setState(SessionState::Closed);
    } else if (waiting) {
        setState(SessionState::Closed); // no longer waiting for the device
    }
}

void SessionEngine::fail(const QString &message)
{
    m_transport->close();
    m_statsTimer.stop();
    setState(SessionState::Failed, message);
    Q_EMIT errorOccurred(message);
}

void SessionEngine::onTransportFailed(const QString &message)
{
    m_family->stopping();
    m_idleTimer.stop();
    cancelAll(RequestStatus::NotSent, message);
    m_transport->close();
    publishStats();
    m_statsTimer.stop();
    setState(SessionState::Disconnected, message);
    Q_EMIT errorOccurred(message);
    if (m_reconnector.enabled() && m_family->reconnects() && m_workingBaud > 0) {
        setState(SessionState::Reconnecting, tr("disconnected — waiting for the device to come back"));
        m_reconnector.start(m_workingBaud, [this] { onReopened(); });
    }
}

void SessionEngine::setAutoReconnect(bool on)
{
    m_reconnector.setEnabled(on);
    if (!on && m_state == SessionState::Reconnecting)
        setState(SessionState::Disconnected, tr("automatic reconnection was turned off"));
}

void SessionEngine::onReopened()
{
    // Counters and samples carry on; only the stream state starts afresh, and the outage
    // does not count in the rates.
    m_family->restartStream();
    SessionStats now;
    m_family->fillCounters(now);
    m_lastStats.bytesIn = now.bytesIn;
    m_lastStats.framesByType = now.framesByType;
    m_lastStatsMs = m_statsClock.isValid() ? m_statsClock.elapsed() : 0;
    m_statsTimer.start();
    setState(SessionState::Connected,
             tr("%1 at %2 baud (reconnected)").arg(m_transport->address()).arg(m_workingBaud));
    Q_EMIT reconnected();
    m_family->reconnected();
}

// ---------------------------------------------------------------------------------------
// Received bytes

void SessionEngine::onBytes(const QByteArray &bytes)
{
    const int64_t arrivedNs = hostNowNs();
    m_rawLog.append(RawByteLog::Direction::Rx, bytes, arrivedNs);
    if (m_tap)
        m_tap->received(bytes, arrivedNs, utcUs());
    m_family->feed(bytes, arrivedNs);
    if (m_family->midUnit())
        m_idleTimer.start();
    else
        m_idleTimer.stop();
}

void SessionEngine::onLineIdle()
{
    // The timer ran out, but bytes waiting to be read mean the line was not quiet: this thread
    // ran late (a busy host stopped the process for longer than the idle time) and the rest of
    // the frame is in the kernel. Releasing the unfinished frame now would drop it, and mark the
    // recording idle where the wire was not; read first (onBytes stops or restarts the timer).
    if (m_transport->bytesWaiting()) {
        m_idleTimer.start();
        return;
    }
    const int64_t now = hostNowNs();
    if (m_tap)
        m_tap->lineIdle(now, utcUs());
    m_family->lineIdle(now);
}

void SessionEngine::appendSamples(std::vector<model::Sample> &batch)
{
    if (batch.empty())
        return;
    if (m_tap)
        m_tap->samples(batch); // a live MCAP recording takes them (a capture records the bytes instead)
    m_store.append(batch); // the views read the store on their clock
}

// ---------------------------------------------------------------------------------------
// Requests

void SessionEngine::submit(Request r, bool first)
{
    if (const QString why = m_family->prepare(r); !why.isEmpty()) {
        refuse(std::move(r), why);
        return;
    }
    if (!m_transport->isOpen()) {
        refuse(std::move(r), tr("the port is not open"));
        return;
    }
    if (first)
        m_queue.push_front(std::move(r));
    else
        m_queue.push_back(std::move(r));
    startNext();
}

void SessionEngine::refuse(Request r, const QString &why)
{
    RequestResult result;
    result.status = RequestStatus::NotSent;
    result.message = why;
    end(r, std::move(result));
}

void SessionEngine::startNext()
{
    if (m_current || m_queue.empty())
        return;
    m_current = std::move(m_queue.front());
    m_queue.pop_front();
    sendCurrent();
}

void SessionEngine::sendCurrent()
{
    ++m_current->attempts;
    const int holdMs = m_family->holdWriteMs(*m_current);
    if (holdMs > 0) {
        m_holdTimer.start(holdMs); // written in the next gap (releaseHeldWrite) or after holdMs
        return;
    }
    writeCurrent();
}

void SessionEngine::releaseHeldWrite()
{
    if (m_current && m_holdTimer.isActive())
        writeCurrent();
}

void SessionEngine::writeCurrent()
{
    m_holdTimer.stop();
    m_family->writing(*m_current);
    m_current->sentNs = hostNowNs();
    m_rawLog.append(RawByteLog::Direction::Tx, m_current->wire, m_current->sentNs);
    if (m_tap)
        m_tap->sent(m_current->wire, m_current->sentNs, utcUs());
    if (m_transport->write(m_current->wire) != m_current->wire.size()) {
        RequestResult r;
        r.status = RequestStatus::NotSent;
        r.message = tr("writing to the port failed");
        finishCurrent(std::move(r));
        return;
    }
    m_replyTimer.start(m_current->timeoutMs);
}

void SessionEngine::onReplyTimeout()
{
    if (!m_current)
        return;
    if (m_current->attempts < m_current->maxAttempts) {
        qCDebug(lcEngine) << "no reply - sending again" << m_current->wire.toHex(' ');
        sendCurrent();
        return;
    }
    RequestResult r;
    r.status = RequestStatus::Timeout;
    r.message = tr("no reply within %1 ms").arg(m_current->timeoutMs);
    finishCurrent(std::move(r));
}

void SessionEngine::finishCurrent(RequestResult result)
{
    m_replyTimer.stop();
    m_holdTimer.stop();
    if (!m_current)
        return;
    Request r = std::move(*m_current);
    m_current.reset();
    end(r, std::move(result));
    startNext();
}

void SessionEngine::end(Request &r, RequestResult result)
{
    result.id = r.id;
    result.attempts = r.attempts;
    result.sentNs = r.sentNs;
    if (!result.reply.isValid()) // ended without an answer: the family says it in its own terms
        m_family->unanswered(r, result);
    m_family->finished(r, result);
    if (r.done)
        r.done(result);
    if (r.id)
        Q_EMIT requestFinished(result);
}

void SessionEngine::cancelAll(RequestStatus status, const QString &why)
{
    m_replyTimer.stop();
    m_holdTimer.stop();
    std::deque<Request> all;
    if (m_current)
        all.push_back(std::move(*m_current));
    m_current.reset();
    for (auto &r : m_queue)
        all.push_back(std::move(r));
    m_queue.clear();
    for (auto &r : all) {
        RequestResult result;
        result.status = status;
        result.message = why;
        end(r, std::move(result));
    }
}

// ---------------------------------------------------------------------------------------
// Statistics

void SessionEngine::restartStatistics()
{
    m_family->resetCounters();
    m_statsClock.restart();
    m_lastStatsMs = 0;
    m_lastStats = SessionStats{};
}

void SessionEngine::watchForGarbage(const SessionStats &now, qint64 nowMs)
{
    constexpr qint64 kGarbageReportMs = 1500;
    const bool decoded = now.frames > m_lastStats.frames || now.nmeaSentences > m_lastStats.nmeaSentences;
    const bool damaged = now.bytesSkipped > m_lastStats.bytesSkipped || now.crcErrors > m_lastStats.crcErrors;
    if (decoded || now.bytesIn < m_lastStats.bytesIn + 64 || !damaged) {
        m_garbageSinceMs = -1;
        if (decoded)
            withdrawGarbageWarning();
        return;
    }
    if (m_garbageSinceMs < 0)
        m_garbageSinceMs = m_lastStatsMs;
    if (!m_garbageReported && nowMs - m_garbageSinceMs >= kGarbageReportMs) {
        m_garbageReported = true;
        Q_EMIT streamWarning(tr("Bytes keep arriving on %1 but none of them form a frame: the device probably runs at "
                                "another baud rate now. Disconnect and connect again with the baud rate set to Auto.")
                                 .arg(m_transport->address()));
    }
}

void SessionEngine::withdrawGarbageWarning()
{
    m_garbageSinceMs = -1;
    if (!m_garbageReported)
        return;
    m_garbageReported = false;
    Q_EMIT streamWarning(QString());
}

void SessionEngine::publishStats()
{
    m_family->statsTick();
    SessionStats s;
    m_family->fillCounters(s);
    s.reconnects = m_reconnector.count();
    s.baud = m_transport ? m_transport->baud() : 0;
    const qint64 nowMs = m_statsClock.isValid() ? m_statsClock.elapsed() : 0;
    const double dt = double(nowMs - m_lastStatsMs) / 1000.0;
    if (addRates(s, m_lastStats, dt)) {
        watchForGarbage(s, nowMs);
        m_lastStats = s;
        m_lastStatsMs = nowMs;
    }
    Q_EMIT statsUpdated(s);
    if (m_tap) {
        const StreamTap::Progress p = m_tap->progress();
        Q_EMIT recordingProgress(p.bytesWritten, p.frames);
    }
}

// ---------------------------------------------------------------------------------------
// Recording

void SessionEngine::startRecording(const QString &path, std::shared_ptr<StreamTap> tap,
                                   const capture::CaptureHeader &header)
{
    if (m_tap)
        finishRecording(QString());
    if (!m_transport || !tap)
        return;
    capture::CaptureHeader h;
    h.setIdentity(m_identity);
    h.set(capture::CaptureHeader::kLinkKind, m_family->linkKind().toStdString());
    h.set(capture::CaptureHeader::kPort, m_transport->address().toStdString());
    h.set(capture::CaptureHeader::kBaud, std::to_string(m_transport->baud()));
    h.set(capture::CaptureHeader::kStartedUtc,
          QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs).toStdString());
    h.set(capture::CaptureHeader::kIdleMarkers, "1");
    h.set(capture::CaptureHeader::kApplication,
          (QCoreApplication::applicationName() + QLatin1Char(' ') + QCoreApplication::applicationVersion())
              .trimmed()
              .toStdString());
    m_family->describeCapture(h);
    for (const auto &[k, v] : header.values)
        h.set(k, v);
    tap->setStoppedHandler([this, t = tap.get()](const QString &reason) {
        QMetaObject::invokeMethod(this, [this, t, reason] { onTapStopped(t, reason); }, Qt::QueuedConnection);
    });
    QString error;
    if (!tap->begin(h, &error)) {
        Q_EMIT errorOccurred(error);
        Q_EMIT recordingStopped(error);
        return;
    }
    m_tap = std::move(tap);
    Q_EMIT recordingStarted(path);
}

void SessionEngine::stopRecording()
{
    if (m_tap)
        finishRecording(QString());
}

void SessionEngine::onTapStopped(const StreamTap *tap, const QString &reason)
{
    if (m_tap.get() == tap)
        finishRecording(reason);
}

void SessionEngine::finishRecording(const QString &reason)
{
    if (!m_tap)
        return;
    const std::shared_ptr<StreamTap> tap = std::move(m_tap);
    const QString error = tap->end();
    const StreamTap::Progress p = tap->progress();
    Q_EMIT recordingProgress(p.bytesWritten, p.frames);
    const QString why = reason.isEmpty() ? error : reason;
    if (!why.isEmpty())
        Q_EMIT errorOccurred(why);
    Q_EMIT recordingStopped(why);
}

} // namespace imudesk::device
