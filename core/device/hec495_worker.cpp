#include "hec495_worker.h"

#include "protocol/witlink/commands.h"

#include <QLoggingCategory>

#include <chrono>

namespace imudesk::device {

namespace {

Q_LOGGING_CATEGORY(lcHec495, "imudesk.core.device.hec495")

namespace wl = protocol::witlink;

constexpr int kStreamingLostMs = 1500; // no auto-output frame for this long: question/answer again

int64_t monotonicNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

const char *frameType(uint8_t command)
{
    return command == 0x84 ? "HEC495 angles" : "HEC495 record";
}

} // namespace

const char *statusName(Hec495Result::Status s)
{
    switch (s) {
    case Hec495Result::Status::Ok: return "ok";
    case Hec495Result::Status::Failed: return "failed";
    case Hec495Result::Status::Invalid: return "invalid";
    case Hec495Result::Status::Timeout: return "timeout";
    case Hec495Result::Status::NotSent: return "not sent";
    case Hec495Result::Status::Cancelled: return "cancelled";
    }
    return "?";
}

const std::vector<int> &Hec495Worker::detectionBauds()
{
    static const std::vector<int> bauds = {9600, 115200, 19200, 4800, 2400};
    return bauds;
}

Hec495Worker::Hec495Worker(SampleStore &store, RawByteLog &rawLog, QObject *parent)
    : QObject(parent), m_store(store), m_rawLog(rawLog)
{
    m_replyTimer.setSingleShot(true);
    connect(&m_replyTimer, &QTimer::timeout, this, &Hec495Worker::onTimeout);
    m_idleTimer.setSingleShot(true);
    m_idleTimer.setInterval(kLineIdleMs);
    connect(&m_idleTimer, &QTimer::timeout, this, &Hec495Worker::onLineIdle);
    m_statsTimer.setInterval(kStatsPeriodMs);
    connect(&m_statsTimer, &QTimer::timeout, this, &Hec495Worker::publishStats);
    connect(&m_pollTimer, &QTimer::timeout, this, &Hec495Worker::poll);
    m_identifyTimer.setSingleShot(true);
    m_gapTimer.setSingleShot(true);
    connect(&m_gapTimer, &QTimer::timeout, this, [this] {
        if (m_current && m_waitingForGap)
            writeCurrent();
    });
}

Hec495Worker::~Hec495Worker() = default;

void Hec495Worker::setState(SessionState s, const QString &detail)
{
    m_state = s;
    Q_EMIT stateChanged(s, detail);
}

void Hec495Worker::open(const QString &portName, int baud, int address)
{
    close();
    m_portName = portName;
    m_address = address & 0xFF;
    setState(SessionState::Opening, portName);
    if (!m_transport) {
        m_transport = new io::SerialTransport(this);
        connect(m_transport, &io::SerialTransport::bytesReceived, this, &Hec495Worker::onBytes);
        connect(m_transport, &io::SerialTransport::failed, this, &Hec495Worker::onTransportFailed);
    }
    m_identifyBauds = baud > 0 ? std::vector<int>{baud} : detectionBauds();
    QString error;
    if (!m_transport->open(portName, m_identifyBauds.front(), &error)) {
        setState(SessionState::Failed, error);
        Q_EMIT errorOccurred(error);
        return;
    }
    m_decoder = wl::FrameDecoder{};
    m_framesByType.clear();
    m_frameBytes.clear();
    m_payloadErrors = 0;
    m_streaming = false;
    m_identityKnown = false;
    m_statsClock.start();
    m_lastStatsMs = 0;
    m_lastStats = SessionStats{};
    m_statsTimer.start();
    setState(SessionState::Detecting, portName);
    identifyAt(0);
}

void Hec495Worker::identifyAt(size_t index)
{
    if (index >= m_identifyBauds.size()) {
        identifyFailed();
        return;
    }
    m_identifying = true;
    const int baud = m_identifyBauds[index];
    m_transport->setBaud(baud);
    m_transport->clear();
    m_decoder.reset();
    qCDebug(lcHec495) << "listening at" << baud;
    m_identifyTimer.disconnect();
    connect(&m_identifyTimer, &QTimer::timeout, this, [this, index, baud] {
        if (!m_identifying)
            return;
        Pending p;
        p.command = uint8_t(wl::Command::ReadAll);
        // A single rate given: use the 3 s window after power-on; scanning rates: two tries each.
        p.maxAttempts = m_identifyBauds.size() == 1 ? kIdentifyWindowMs / kReplyTimeoutMs : 2;
        p.done = [this, index, baud](const Hec495Result &r) {
            if (!m_identifying)
                return;
            if (r.status == Hec495Result::Status::Ok)
                identified(baud, &r.reply);
            else if (r.status != Hec495Result::Status::Cancelled)
                identifyAt(index + 1);
        };
        enqueue(std::move(p));
    });
    m_identifyTimer.start(kListenMs);
}

void Hec495Worker::identified(int baud, const wl::Reply *reply)
{
    m_identifying = false;
    m_identifyTimer.stop();
    m_identityKnown = true;
    model::DeviceIdentity id;
    id.productName = "HEC495";
    id.busAddress = m_address;
    if (reply && reply->address != m_address && reply->address != wl::kReplySetAddressAddress)
        id.busAddress = m_address = reply->address;
    Q_EMIT identityChanged(id);
    Q_EMIT addressChanged(m_address);
    Q_EMIT baudChanged(baud);
    setState(SessionState::Connected, m_portName);
    qCInfo(lcHec495) << "HEC495 at" << baud << "baud, address" << m_address << (m_streaming ? "streaming" : "polled");
    if (!m_streaming && m_pollHz > 0)
        m_pollTimer.start(1000 / m_pollHz);
}

void Hec495Worker::identifyFailed()
{
    m_identifying = false;
    const QString msg =
        tr("no HEC495 answered on %1 at %2 baud: check the wiring (RS-232 TXD/RXD or RS-485 A/B), the power, "
           "the baud rate and the module address (%3)")
            .arg(m_portName)
            .arg(m_identifyBauds.size() == 1 ? QString::number(m_identifyBauds.front()) : tr("any supported"))
            .arg(m_address);
    if (m_transport)
        m_transport->close();
    m_statsTimer.stop();
    setState(SessionState::Failed, msg);
    Q_EMIT errorOccurred(msg);
}

void Hec495Worker::close()
{
    m_identifying = false;
    m_identifyTimer.stop();
    m_identifyTimer.disconnect();
    m_pollTimer.stop();
    m_idleTimer.stop();
    cancelAll(Hec495Result::Status::Cancelled, tr("the connection was closed"));
    if (m_transport && m_transport->isOpen()) {
        m_transport->close();
        publishStats();
        m_statsTimer.stop();
        setState(SessionState::Closed);
    }
}

void Hec495Worker::setPollingRate(int hz)
{
    m_pollHz = std::clamp(hz, 0, 100);
    m_pollTimer.stop();
    if (m_pollHz > 0 && m_identityKnown && !m_streaming)
        m_pollTimer.start(1000 / m_pollHz);
}

void Hec495Worker::setStreaming(bool on)
{
    if (on == m_streaming)
        return;
    m_streaming = on;
    if (on)
        m_pollTimer.stop();
    else if (m_pollHz > 0 && m_identityKnown)
        m_pollTimer.start(1000 / m_pollHz);
    Q_EMIT streamingChanged(on);
}

void Hec495Worker::poll()
{
    if (m_streaming || m_current || !m_queue.empty() || !m_transport || !m_transport->isOpen())
        return;
    Pending p;
    p.command = uint8_t(wl::Command::ReadAll);
    p.maxAttempts = 1; // the next poll is the retry
    enqueue(std::move(p));
}

void Hec495Worker::request(quint64 id, uint8_t command, const QByteArray &data, int timeoutMs)
{
    Pending p;
    p.id = id;
    p.command = command;
    p.data.assign(data.begin(), data.end());
    p.timeoutMs = timeoutMs > 0 ? timeoutMs : kReplyTimeoutMs;
    enqueue(std::move(p));
}

void Hec495Worker::enqueue(Pending p)
{
    const uint8_t address = p.command == uint8_t(wl::Command::QueryAddress) ? 0 : uint8_t(m_address);
    p.wire = wl::encodeFrame(address, p.command, p.data);
    QString problem;
    if (p.wire.empty())
        problem = tr("the request's data is longer than a Witlink frame can carry");
    else if (!m_transport || !m_transport->isOpen())
        problem = tr("the port is not open");
    if (!problem.isEmpty()) {
        Hec495Result r;
        r.request = p.command;
        r.status = Hec495Result::Status::NotSent;
        r.message = problem;
        if (p.done)
            p.done(r);
        if (p.id)
            Q_EMIT commandFinished(p.id, r);
        return;
    }
    m_queue.push_back(std::move(p));
    startNext();
}

void Hec495Worker::startNext()
{
    if (m_current || m_queue.empty())
        return;
    m_current = std::move(m_queue.front());
    m_queue.pop_front();
    sendCurrent();
}

void Hec495Worker::sendCurrent()
{
    ++m_current->attempts;
    if (m_streaming) {
        m_waitingForGap = true; // written after the next auto-output frame (handleFrames)
        m_gapTimer.start(kGapWaitMs);
        return;
    }
    writeCurrent();
}

void Hec495Worker::writeCurrent()
{
    m_waitingForGap = false;
    m_gapTimer.stop();
    Pending &p = *m_current;
    const QByteArray wire(reinterpret_cast<const char *>(p.wire.data()), qsizetype(p.wire.size()));
    m_rawLog.append(RawByteLog::Direction::Tx, wire, monotonicNs());
    if (m_transport->write(wire) != wire.size()) {
        Hec495Result r;
        r.status = Hec495Result::Status::NotSent;
        r.message = tr("writing to the port failed");
        finishCurrent(std::move(r));
        return;
    }
    m_replyTimer.start(p.timeoutMs);
}

void Hec495Worker::finishCurrent(Hec495Result r)
{
    m_replyTimer.stop();
    m_gapTimer.stop();
    m_waitingForGap = false;
    if (!m_current)
        return;
    Pending p = std::move(*m_current);
    m_current.reset();
    r.request = p.command;
    r.attempts = p.attempts;
    if (r.status == Hec495Result::Status::Ok)
        applyEffects(p, r);
    if (p.done)
        p.done(r);
    if (p.id)
        Q_EMIT commandFinished(p.id, r);
    startNext();
}

void Hec495Worker::onTimeout()
{
    if (!m_current)
        return;
    if (m_current->attempts < m_current->maxAttempts) {
        qCDebug(lcHec495) << "no reply to" << wl::commands::commandName(m_current->command) << "- sending again";
        sendCurrent();
        return;
    }
    Hec495Result r;
    r.status = Hec495Result::Status::Timeout;
    r.message = tr("no reply to \"%1\" after %2 attempts of %3 ms (check the baud rate and the module address; "
                   "an RS-485 module that streams may miss commands: set question/answer mode)")
                    .arg(QString::fromLatin1(wl::commands::commandName(m_current->command)))
                    .arg(m_current->attempts)
                    .arg(m_current->timeoutMs);
    finishCurrent(std::move(r));
}

void Hec495Worker::cancelAll(Hec495Result::Status status, const QString &why)
{
    m_replyTimer.stop();
    m_gapTimer.stop();
    m_waitingForGap = false;
    std::deque<Pending> all;
    if (m_current)
        all.push_back(std::move(*m_current));
    m_current.reset();
    for (auto &p : m_queue)
        all.push_back(std::move(p));
    m_queue.clear();
    for (auto &p : all) {
        Hec495Result r;
        r.request = p.command;
        r.attempts = p.attempts;
        r.status = status;
        r.message = why;
        if (p.done)
            p.done(r);
        if (p.id)
            Q_EMIT commandFinished(p.id, r);
    }
}

void Hec495Worker::applyEffects(const Pending &p, const Hec495Result &r)
{
    using C = wl::Command;
    switch (C(p.command)) {
    case C::SetBaud: {
        const int baud = p.data.size() == 1 ? wl::commands::baudFromCode(p.data[0]) : -1;
        if (baud > 0 && m_transport) {
            m_transport->setBaud(baud); // the reply came at the old rate (2.13)
            m_decoder.reset();
            Q_EMIT baudChanged(baud);
        }
        break;
    }
    case C::SetAddress:
        if (p.data.size() == 1) {
            m_address = p.data[0];
            Q_EMIT addressChanged(m_address);
        }
        break;
    case C::QueryAddress:
        if (r.reply.deviceAddress != m_address) {
            m_address = r.reply.deviceAddress;
            Q_EMIT addressChanged(m_address);
        }
        break;
    case C::FactoryReset:
        m_address = wl::commands::kDefaultAddress;
        Q_EMIT addressChanged(m_address);
        if (m_transport && m_transport->baud() != wl::commands::kDefaultBaud) {
            m_transport->setBaud(wl::commands::kDefaultBaud);
            m_decoder.reset();
            Q_EMIT baudChanged(wl::commands::kDefaultBaud);
        }
        setStreaming(false);
        break;
    case C::SetOutputRate:
        if (p.data.size() == 1)
            setStreaming(wl::commands::rateFromCode(p.data[0]) > 0);
        break;
    default:
        break;
    }
}

void Hec495Worker::onBytes(const QByteArray &bytes)
{
    m_rawLog.append(RawByteLog::Direction::Rx, bytes, monotonicNs());
    std::vector<wl::Frame> frames;
    m_decoder.feed(reinterpret_cast<const uint8_t *>(bytes.constData()), size_t(bytes.size()), frames);
    if (m_decoder.pendingBytes() > 0)
        m_idleTimer.start();
    else
        m_idleTimer.stop();
    m_decoder.takeSkipped(); // text (NMEA output) and noise: counted, not kept
    handleFrames(frames);
}

void Hec495Worker::onLineIdle()
{
    std::vector<wl::Frame> frames;
    m_decoder.flushIdle(frames);
    m_decoder.takeSkipped();
    handleFrames(frames);
}

bool Hec495Worker::answersCurrent(const wl::Frame &f) const
{
    if (!m_current)
        return false;
    const auto expected = wl::commands::expectedReplies(m_current->command);
    if (std::find(expected.begin(), expected.end(), f.command) == expected.end())
        return false;
    const bool anyAddress = m_current->command == uint8_t(wl::Command::SetAddress)
        || m_current->command == uint8_t(wl::Command::QueryAddress) || m_identifying;
    if (!anyAddress && f.address != m_address)
        return false;
    return true;
}

void Hec495Worker::handleFrames(const std::vector<wl::Frame> &frames)
{
    if (frames.empty())
        return;
    const int64_t now = monotonicNs();
    m_batch.clear();
    bool unsolicitedData = false;
    for (const auto &f : frames) {
        if (m_current && wl::encodeFrame(f) == m_current->wire)
            continue; // our own request heard back (RS-485 echo)
        const wl::Reply r = wl::decodeReply(f);
        const bool data = r.ok() && (r.kind == wl::Reply::Kind::AllData || r.kind == wl::Reply::Kind::Angles);
        if (data) {
            const std::string type = frameType(f.command);
            ++m_framesByType[type];
            m_frameBytes[type] = f.data.size() + 5;
            if (r.kind == wl::Reply::Kind::AllData) {
                m_batch.push_back(r.record.toSample(now));
            } else {
                model::Sample s;
                s.source = "HEC495";
                s.hostTimeNs = now;
                s.fields = model::FieldEuler;
                s.pitch = r.pitch;
                s.roll = r.roll;
                s.yaw = r.heading;
                m_batch.push_back(s);
            }
        } else if (!r.ok()) {
            ++m_payloadErrors;
        }
        if (answersCurrent(f)) {
            Hec495Result res;
            res.reply = r;
            if (!r.ok()) {
                res.status = Hec495Result::Status::Invalid;
                res.message = tr("the module answered with an invalid reply: %1").arg(wl::Reply::errorText(r.error));
            } else if (!r.success) {
                res.status = Hec495Result::Status::Failed;
                res.message = tr("the module reported failure (FF) for \"%1\"")
                                  .arg(QString::fromLatin1(wl::commands::commandName(m_current->command)));
            } else {
                res.status = Hec495Result::Status::Ok;
                res.message = r.describe();
            }
            finishCurrent(std::move(res));
            continue;
        }
        if (data) {
            unsolicitedData = true;
        } else if (r.ok() && r.kind == wl::Reply::Kind::CalibrationPoint) {
            Q_EMIT calibrationPoint(r.points);
        }
    }
    if (unsolicitedData) {
        m_lastStreamFrame.restart();
        setStreaming(true);
        if (m_identifying) {
            cancelAll(Hec495Result::Status::Cancelled, tr("the module streams: identified without a request"));
            identified(m_transport->baud(), nullptr);
        } else if (m_current && m_waitingForGap) {
            writeCurrent(); // the line is quiet until the next frame
        }
    }
    if (!m_batch.empty())
        m_store.append(m_batch);
}

void Hec495Worker::onTransportFailed(const QString &message)
{
    m_identifying = false;
    m_identifyTimer.stop();
    m_pollTimer.stop();
    m_idleTimer.stop();
    cancelAll(Hec495Result::Status::NotSent, message);
    if (m_transport)
        m_transport->close();
    m_statsTimer.stop();
    setState(SessionState::Disconnected, message);
    Q_EMIT errorOccurred(message);
}

void Hec495Worker::publishStats()
{
    // Auto-output stopped (another tool set question/answer, or the module restarted): poll again.
    if (m_streaming && m_identityKnown && m_lastStreamFrame.isValid() && m_lastStreamFrame.elapsed() > kStreamingLostMs)
        setStreaming(false);
    const auto &c = m_decoder.counters();
    SessionStats s;
    s.bytesIn = c.bytesIn;
    s.frames = c.frames;
    s.crcErrors = c.checksumErrors;
    s.lengthErrors = c.lengthErrors;
    s.bytesSkipped = c.bytesSkipped;
    s.payloadErrors = m_payloadErrors;
    s.framesByType = m_framesByType;
    s.baud = m_transport ? m_transport->baud() : 0;
    const qint64 nowMs = m_statsClock.isValid() ? m_statsClock.elapsed() : 0;
    const double dt = double(nowMs - m_lastStatsMs) / 1000.0;
    if (dt > 0) {
        // Counters restart with a new decoder (baud change): never a negative rate.
        const uint64_t prevBytes = m_lastStats.bytesIn <= s.bytesIn ? m_lastStats.bytesIn : 0;
        s.bytesPerSecond = double(s.bytesIn - prevBytes) / dt;
        for (const auto &[type, n] : s.framesByType) {
            const auto it = m_lastStats.framesByType.find(type);
            const uint64_t before = it == m_lastStats.framesByType.end() ? 0 : it->second;
            s.rateByType[type] = double(n - std::min(n, before)) / dt;
        }
    } else {
        s.bytesPerSecond = m_lastStats.bytesPerSecond;
        s.rateByType = m_lastStats.rateByType;
    }
    s.linkLoad = s.baud > 0 ? s.bytesPerSecond * 10.0 / double(s.baud) : 0;
    m_lastStats = s;
    m_lastStatsMs = nowMs;
    Q_EMIT statsUpdated(s);
}

} // namespace imudesk::device
