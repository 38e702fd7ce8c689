#include "session_worker.h"

#include "device/device_session.h"
#include "protocol/hipnuc/payloads.h"

#include <QCoreApplication>
#include <QLoggingCategory>

#include <chrono>

Q_LOGGING_CATEGORY(lcSession, "imudesk.core.device")

namespace imudesk::device {

using protocol::StreamEvent;
namespace hp = protocol::hipnuc;

namespace {
constexpr int kListenMs = 150;
constexpr int kDetectQueryTimeoutMs = 500;
constexpr int kIdentityTimeoutMs = 1000;
constexpr int kStatsPeriodMs = 500;
constexpr int kLineIdleMs = 30;

int64_t monotonicNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}
} // namespace

SessionWorker::SessionWorker(SampleStore &store, RawByteLog &rawLog, QObject *parent)
    : QObject(parent), m_store(store), m_rawLog(rawLog)
{
    m_commandTimer.setSingleShot(true);
    connect(&m_commandTimer, &QTimer::timeout, this, &SessionWorker::onCommandTimeout);
    m_detectTimer.setSingleShot(true);
    m_idleTimer.setSingleShot(true);
    m_idleTimer.setInterval(kLineIdleMs);
    connect(&m_idleTimer, &QTimer::timeout, this, &SessionWorker::onLineIdle);
    m_statsTimer.setInterval(kStatsPeriodMs);
    connect(&m_statsTimer, &QTimer::timeout, this, &SessionWorker::publishStats);
}

SessionWorker::~SessionWorker() = default;

void SessionWorker::setState(SessionState s, const QString &detail)
{
    m_state = s;
    Q_EMIT stateChanged(s, detail);
}

void SessionWorker::open(const QString &portName, int baud)
{
    close();
    m_portName = portName;
    setState(SessionState::Opening, portName);
    if (!m_transport) {
        m_transport = new io::SerialTransport(this);
        connect(m_transport, &io::SerialTransport::bytesReceived, this, &SessionWorker::onBytes);
        connect(m_transport, &io::SerialTransport::failed, this, &SessionWorker::onTransportFailed);
    }
    QString error;
    const int firstBaud = baud > 0 ? baud : DeviceSession::detectionBauds().front();
    if (!m_transport->open(portName, firstBaud, &error)) {
        setState(SessionState::Failed, error);
        Q_EMIT errorOccurred(error);
        return;
    }
    m_demux.reset();
    m_demux.resetCounters();
    m_payloadErrors = 0;
    m_statsClock.start();
    m_lastStatsMs = 0;
    m_lastStats = SessionStats{};
    m_statsTimer.start();
    if (baud > 0) {
        setState(SessionState::Connected, portName);
        // Listen first, as the detection does: joining a stream mid-frame, the tail of that
        // frame must not be mistaken for the start of the reply.
        m_detectTimer.disconnect();
        connect(&m_detectTimer, &QTimer::timeout, this, [this] { queryIdentity(1); });
        m_detectTimer.start(kListenMs);
    } else {
        m_detecting = true;
        setState(SessionState::Detecting, portName);
        detectAt(0);
    }
}

void SessionWorker::close()
{
    m_detecting = false;
    m_detectTimer.stop();
    m_detectTimer.disconnect();
    cancelAll(Reply::Status::Cancelled, tr("the connection was closed"));
    if (m_transport && m_transport->isOpen()) {
        m_transport->close();
        publishStats();
        m_statsTimer.stop();
        setState(SessionState::Closed);
    }
}

void SessionWorker::setHostBaud(int baud)
{
    if (!m_transport || !m_transport->isOpen())
        return;
    m_transport->setBaud(baud);
    m_demux.reset();
    publishStats();
}

void SessionWorker::sendCommand(quint64 id, const QString &text, int timeoutMs)
{
    Pending p;
    p.id = id;
    p.text = text.trimmed();
    p.timeoutMs = timeoutMs;
    enqueue(std::move(p));
}

void SessionWorker::enqueue(Pending p)
{
    if (!m_transport || !m_transport->isOpen()) {
        Reply r;
        r.command = p.text.toStdString();
        r.status = Reply::Status::NotSent;
        r.errorLine = tr("the port is not open").toStdString();
        if (p.done)
            p.done(r);
        if (p.id)
            Q_EMIT commandFinished(p.id, r);
        return;
    }
    m_queue.push_back(std::move(p));
    if (!m_current)
        startNext();
}

void SessionWorker::startNext()
{
    if (m_current || m_queue.empty())
        return;
    m_current = std::move(m_queue.front());
    m_queue.pop_front();
    m_collector.emplace(m_current->text.toStdString());
    const QByteArray wire = m_current->text.toLatin1() + "\r\n";
    m_rawLog.append(RawByteLog::Direction::Tx, wire, monotonicNs());
    if (m_transport->write(wire) != wire.size()) {
        Reply r = m_collector->take();
        r.status = Reply::Status::NotSent;
        r.errorLine = tr("writing to the port failed").toStdString();
        finishCurrent(std::move(r));
        return;
    }
    m_commandTimer.start(m_current->timeoutMs);
}

void SessionWorker::finishCurrent(Reply reply)
{
    m_commandTimer.stop();
    if (!m_current)
        return;
    Pending p = std::move(*m_current);
    m_current.reset();
    m_collector.reset();
    if (p.done)
        p.done(reply);
    if (p.id)
        Q_EMIT commandFinished(p.id, reply);
    startNext();
}

void SessionWorker::onCommandTimeout()
{
    if (!m_current || !m_collector)
        return;
    Reply r = m_collector->take();
    r.status = Reply::Status::Timeout;
    r.errorLine = tr("no reply within %1 ms (the device ignores commands it does not know)")
                      .arg(m_current->timeoutMs)
                      .toStdString();
    finishCurrent(std::move(r));
}

void SessionWorker::cancelAll(Reply::Status status, const QString &why)
{
    m_commandTimer.stop();
    std::deque<Pending> all;
    if (m_current)
        all.push_back(std::move(*m_current));
    m_current.reset();
    m_collector.reset();
    for (auto &p : m_queue)
        all.push_back(std::move(p));
    m_queue.clear();
    for (auto &p : all) {
        Reply r;
        r.command = p.text.toStdString();
        r.status = status;
        r.errorLine = why.toStdString();
        if (p.done)
            p.done(r);
        if (p.id)
            Q_EMIT commandFinished(p.id, r);
    }
}

void SessionWorker::onBytes(const QByteArray &bytes)
{
    m_rawLog.append(RawByteLog::Direction::Rx, bytes, monotonicNs());
    m_events.clear();
    m_demux.feed(reinterpret_cast<const uint8_t *>(bytes.constData()), size_t(bytes.size()), m_events);
    if (m_demux.pendingBytes() > 0)
        m_idleTimer.start();
    else
        m_idleTimer.stop();
    handleEvents();
}

void SessionWorker::onLineIdle()
{
    m_events.clear();
    m_demux.flushPending(m_events);
    handleEvents();
}

void SessionWorker::handleEvents()
{
    if (m_events.empty())
        return;
    const int64_t now = monotonicNs();
    m_batch.clear();
    for (auto &e : m_events) {
        switch (e.kind) {
        case StreamEvent::Kind::Frame: {
            hp::Hi91 h;
            if (hp::decodeHi91(e.payload.data(), e.payload.size(), h)) {
                m_batch.push_back(hp::toSample(h));
                m_batch.back().hostTimeNs = now;
                break;
            }
            const auto res = hp::decodePayload(e.payload);
            for (const auto &p : res.packets) {
                m_batch.push_back(hp::toSample(p));
                m_batch.back().hostTimeNs = now;
            }
            if (!res.ok())
                ++m_payloadErrors;
            break;
        }
        case StreamEvent::Kind::Nmea:
            Q_EMIT nmeaReceived(QString::fromStdString(e.text));
            break;
        case StreamEvent::Kind::NmeaError:
            break;
        case StreamEvent::Kind::Line:
            if (m_collector && m_collector->addLine(e.text))
                finishCurrent(m_collector->take());
            else if (!m_collector)
                Q_EMIT textReceived(QString::fromStdString(e.text));
            break;
        }
    }
    if (!m_batch.empty()) {
        m_store.append(m_batch);
        Q_EMIT samplesAppended(m_store.totalAppended());
    }
}

void SessionWorker::onTransportFailed(const QString &message)
{
    m_detecting = false;
    m_detectTimer.stop();
    cancelAll(Reply::Status::NotSent, message);
    if (m_transport)
        m_transport->close();
    publishStats();
    m_statsTimer.stop();
    setState(SessionState::Disconnected, message);
    Q_EMIT errorOccurred(message);
}

void SessionWorker::publishStats()
{
    SessionStats s;
    const auto &fc = m_demux.frameCounters();
    const auto &dc = m_demux.counters();
    s.bytesIn = fc.bytesIn;
    s.frames = fc.frames;
    s.crcErrors = fc.crcErrors;
    s.lengthErrors = fc.lengthErrors;
    s.bytesSkipped = fc.bytesSkipped;
    s.nmeaSentences = dc.nmeaSentences;
    s.nmeaErrors = dc.nmeaErrors;
    s.payloadErrors = m_payloadErrors;
    for (int tag = 0; tag < 256; ++tag) {
        if (!fc.perTag[size_t(tag)])
            continue;
        char name[8];
        std::snprintf(name, sizeof name, "HI%02X", tag);
        s.framesByType[name] = fc.perTag[size_t(tag)];
    }
    if (dc.nmeaSentences)
        s.framesByType["NMEA"] = dc.nmeaSentences;
    s.baud = m_transport ? m_transport->baud() : 0;
    const qint64 nowMs = m_statsClock.isValid() ? m_statsClock.elapsed() : 0;
    const double dt = double(nowMs - m_lastStatsMs) / 1000.0;
    if (dt > 0.05) {
        for (const auto &[name, count] : s.framesByType) {
            const auto it = m_lastStats.framesByType.find(name);
            const uint64_t before = it == m_lastStats.framesByType.end() ? 0 : it->second;
            s.rateByType[name] = double(count - before) / dt;
        }
        s.bytesPerSecond = double(s.bytesIn - m_lastStats.bytesIn) / dt;
        s.linkLoad = s.baud > 0 ? s.bytesPerSecond * 10.0 / s.baud : 0;
        m_lastStats = s;
        m_lastStatsMs = nowMs;
    } else {
        s.rateByType = m_lastStats.rateByType;
        s.bytesPerSecond = m_lastStats.bytesPerSecond;
        s.linkLoad = m_lastStats.linkLoad;
    }
    Q_EMIT statsUpdated(s);
}

void SessionWorker::queryIdentity(int attempt)
{
    constexpr int kAttempts = 3;
    Pending p;
    p.text = QStringLiteral("LOG VERSION");
    p.timeoutMs = kIdentityTimeoutMs;
    p.done = [this, attempt](const Reply &r) {
        bool answered = false;
        if (r.ok()) {
            const auto id = model::DeviceIdentity::fromKeyValues(r.values);
            answered = id.usable();
            if (answered)
                Q_EMIT identityChanged(id);
        }
        // An OK whose lines were damaged (noise on the line) is asked again; silence is not.
        if (!answered && r.status == Reply::Status::Ok && attempt < kAttempts) {
            queryIdentity(attempt + 1);
            return;
        }
        Q_EMIT identityQueryFinished(answered);
    };
    enqueue(std::move(p));
}

void SessionWorker::detectAt(size_t index)
{
    const auto &bauds = DeviceSession::detectionBauds();
    if (!m_detecting)
        return;
    if (index >= bauds.size()) {
        m_detecting = false;
        const QString msg = tr("No HiPNUC device answered on %1 at any baud rate (115200, 921600, 460800, 230400, "
                               "256000, 57600, 38400, 19200, 9600, 4800). Check the cable and the power, and that "
                               "no other program uses the port.")
                                .arg(m_portName);
        m_transport->close();
        m_statsTimer.stop();
        setState(SessionState::Failed, msg);
        Q_EMIT errorOccurred(msg);
        return;
    }
    m_detectIndex = index;
    m_transport->setBaud(bauds[index]);
    m_transport->clear();
    m_demux.reset();
    m_framesAtDetectStart = m_demux.frameCounters().frames;
    setState(SessionState::Detecting, tr("trying %1 baud").arg(bauds[index]));
    // Listen first: a module that streams is recognised by a CRC-valid frame.
    m_detectTimer.disconnect();
    connect(&m_detectTimer, &QTimer::timeout, this, [this] { detectQuery(false); });
    m_detectTimer.start(kListenMs);
}

void SessionWorker::detectQuery(bool retry)
{
    if (!m_detecting)
        return;
    Pending p;
    p.text = QStringLiteral("LOG VERSION");
    p.timeoutMs = kDetectQueryTimeoutMs;
    const size_t index = m_detectIndex;
    p.done = [this, retry, index](const Reply &r) {
        if (!m_detecting || index != m_detectIndex)
            return;
        const int baud = DeviceSession::detectionBauds()[index];
        if (r.ok()) {
            const auto id = model::DeviceIdentity::fromKeyValues(r.values);
            if (id.usable()) {
                detectFinished(baud, id);
                return;
            }
        }
        const bool sawFrames = m_demux.frameCounters().frames > m_framesAtDetectStart;
        if (sawFrames && !retry) {
            detectQuery(true);
            return;
        }
        if (sawFrames) {
            detectFinished(baud, std::nullopt); // streams valid frames but does not answer
            return;
        }
        if (r.status == Reply::Status::Cancelled || r.status == Reply::Status::NotSent)
            return;
        detectAt(index + 1);
    };
    enqueue(std::move(p));
}

void SessionWorker::detectFinished(int baud, const std::optional<model::DeviceIdentity> &id)
{
    m_detecting = false;
    m_demux.resetCounters();
    m_lastStats = SessionStats{};
    m_statsClock.restart();
    m_lastStatsMs = 0;
    Q_EMIT baudDetected(baud);
    if (id)
        Q_EMIT identityChanged(*id);
    setState(SessionState::Connected, tr("%1 at %2 baud").arg(m_portName).arg(baud));
}

} // namespace imudesk::device
