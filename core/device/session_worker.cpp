#include "session_worker.h"

#include "device/device_session.h"
#include "protocol/hipnuc/ascii_command.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFileInfo>
#include <QLoggingCategory>
#include <QRegularExpression>
#include <QSerialPortInfo>

#include <chrono>
#include <utility>

Q_LOGGING_CATEGORY(lcSession, "imudesk.core.device")

namespace imudesk::device {

using protocol::StreamEvent;
namespace hp = protocol::hipnuc;

namespace {
constexpr int kListenMs = 150;
constexpr int kDetectQueryTimeoutMs = 500;
constexpr int kIdentityTimeoutMs = 1000;
constexpr int kStatsPeriodMs = 500;
// A module sends a frame without pauses, but a USB adapter's latency timer (16 ms on FTDI
// parts) and a loaded host can split one in two deliveries tens of ms apart: only a pause
// longer than this gives up an unfinished frame (30 ms lost frames under load).
constexpr int kLineIdleMs = 120;
constexpr int kReconnectPollMs = 500;
// A configured rate whose frames need more of the line than this cannot all arrive, so the
// frames that do no longer show the period: the gap counter is told the configured one.
constexpr double kSaturatedLinkLoad = 0.9;

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
    m_reconnectTimer.setInterval(kReconnectPollMs);
    connect(&m_reconnectTimer, &QTimer::timeout, this, &SessionWorker::tryReconnect);
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
    m_requestedPort = portName;
    m_workingBaud = 0;
    m_deviceSerial.clear();
    m_checkSameDevice = false;
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
    rememberDevice(portName);
    m_demux.reset();
    m_demux.resetCounters();
    m_payloadErrors = 0;
    m_gaps.clear();
    m_frameBytes.clear();
    m_reconnects = 0;
    m_statsClock.start();
    m_lastStatsMs = 0;
    m_lastStats = SessionStats{};
    m_statsTimer.start();
    if (baud > 0) {
        m_workingBaud = baud;
        setState(SessionState::Connected, portName);
        listenThenQueryIdentity();
    } else {
        m_detecting = true;
        setState(SessionState::Detecting, portName);
        detectAt(0);
    }
}

void SessionWorker::listenThenQueryIdentity()
{
    // Listen first, as the detection does: joining a stream mid-frame, the tail of that
    // frame must not be mistaken for the start of the reply.
    m_detectTimer.disconnect();
    connect(&m_detectTimer, &QTimer::timeout, this, [this] { queryIdentity(1); });
    m_detectTimer.start(kListenMs);
}

void SessionWorker::close()
{
    m_detecting = false;
    m_detectTimer.stop();
    m_detectTimer.disconnect();
    const bool waiting = m_reconnectTimer.isActive() || m_state == SessionState::Reconnecting;
    m_reconnectTimer.stop();
    cancelAll(Reply::Status::Cancelled, tr("the connection was closed"));
    if (LinkDone done = std::exchange(m_afterDetect, {}))
        done(false, 0);
    if (m_recorder)
        finishRecording(QString());
    if (m_transport && m_transport->isOpen()) {
        m_transport->close();
        publishStats();
        m_statsTimer.stop();
        setState(SessionState::Closed);
    } else if (waiting) {
        setState(SessionState::Closed); // no longer waiting for the device
    }
}

void SessionWorker::setHostBaud(int baud)
{
    if (!m_transport || !m_transport->isOpen())
        return;
    m_transport->setBaud(baud);
    m_workingBaud = baud;
    m_demux.reset();
    m_gaps.resetTiming(); // bytes were lost while the two sides disagreed
    publishStats();
}

void SessionWorker::setAutoReconnect(bool on)
{
    m_autoReconnect = on;
    if (!on && m_state == SessionState::Reconnecting) {
        m_reconnectTimer.stop();
        setState(SessionState::Disconnected, tr("automatic reconnection was turned off"));
    }
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
    m_demux.endQuarantine(); // what answers now starts after a boundary the device keeps
    noteCommandSent(m_current->text);
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
    noteCommandDone(p.text, reply);
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
    const int64_t arrivedNs = monotonicNs();
    m_rawLog.append(RawByteLog::Direction::Rx, bytes, arrivedNs);
    if (m_recorder)
        m_recorder->append(bytes.constData(), size_t(bytes.size()), arrivedNs,
                           QDateTime::currentMSecsSinceEpoch() * 1000);
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
    if (m_recorder)
        m_recorder->appendLineIdle(monotonicNs(), QDateTime::currentMSecsSinceEpoch() * 1000);
    m_events.clear();
    m_demux.flushPending(m_events);
    m_demux.endQuarantine(); // the line went quiet: the next byte starts something new
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
            const size_t first = m_batch.size();
            const auto res = hp::forEachPacket(e.payload, [&](const hp::Packet &p) {
                m_batch.push_back(hp::toSample(p));
                m_batch.back().hostTimeNs = now;
            });
            if (!res.ok())
                ++m_payloadErrors;
            for (size_t i = first; i < m_batch.size(); ++i) {
                const model::Sample &sample = m_batch[i];
                m_frameBytes[sample.source] = e.payload.size() + hp::FrameDecoder::kHeaderSize;
                if (sample.has(model::FieldDeviceTime))
                    m_gaps.add(sample.source, sample.deviceTimeMs);
            }
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
    if (!m_batch.empty())
        m_store.append(m_batch); // the views read the store on their clock
}

void SessionWorker::onTransportFailed(const QString &message)
{
    m_detecting = false;
    m_detectTimer.stop();
    m_idleTimer.stop();
    cancelAll(Reply::Status::NotSent, message);
    if (m_transport)
        m_transport->close();
    publishStats();
    m_statsTimer.stop();
    setState(SessionState::Disconnected, message);
    Q_EMIT errorOccurred(message);
    if (m_autoReconnect && m_workingBaud > 0)
        startWaiting();
}

// ---------------------------------------------------------------------------------------
// Recording

void SessionWorker::startRecording(const QString &path, const record::CaptureHeader &header,
                                   const record::CaptureWriter::Options &options)
{
    if (m_recorder)
        finishRecording(QString());
    record::CaptureHeader h;
    h.setIdentity(m_identity);
    h.set(record::CaptureHeader::kLinkKind, "HiPNUC serial");
    h.set(record::CaptureHeader::kPort, m_portName.toStdString());
    h.set(record::CaptureHeader::kBaud, std::to_string(m_transport ? m_transport->baud() : 0));
    h.set(record::CaptureHeader::kStartedUtc,
          QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs).toStdString());
    h.set(record::CaptureHeader::kIdleMarkers, "1");
    h.set(record::CaptureHeader::kApplication,
          (QCoreApplication::applicationName() + QLatin1Char(' ') + QCoreApplication::applicationVersion())
              .trimmed()
              .toStdString());
    for (const auto &[k, v] : header.values)
        h.set(k, v);
    auto writer = std::make_unique<record::CaptureWriter>();
    writer->setStoppedHandler([this](const QString &reason) {
        QMetaObject::invokeMethod(this, [this, reason] { finishRecording(reason); }, Qt::QueuedConnection);
    });
    QString error;
    if (!writer->start(path, h, options, &error)) {
        Q_EMIT errorOccurred(error);
        Q_EMIT recordingStopped(error);
        return;
    }
    m_recorder = std::move(writer);
    m_framesAtRecordStart = m_demux.frameCounters().frames;
    Q_EMIT recordingStarted(path);
}

void SessionWorker::stopRecording()
{
    if (m_recorder)
        finishRecording(QString());
}

void SessionWorker::finishRecording(const QString &reason)
{
    if (!m_recorder)
        return;
    const QString error = m_recorder->stop();
    const auto st = m_recorder->status();
    m_recorder.reset();
    const uint64_t frames = m_demux.frameCounters().frames;
    Q_EMIT recordingProgress(st.bytesWritten,
                             frames >= m_framesAtRecordStart ? frames - m_framesAtRecordStart : frames);
    const QString why = reason.isEmpty() ? error : reason;
    if (!why.isEmpty())
        Q_EMIT errorOccurred(why);
    Q_EMIT recordingStopped(why);
}

// ---------------------------------------------------------------------------------------
// Reconnection

void SessionWorker::rememberDevice(const QString &portName)
{
    // The USB identity of the port, when it has one (QSerialPortInfo lists USB and
    // on-board ports, not pseudo-terminals). A by-id symlink is matched by its target.
    m_serialNumber.clear();
    m_hasUsbIds = false;
    const QString location = io::SerialTransport::systemLocation(portName);
    const QString canonical = QFileInfo(location).canonicalFilePath();
    const auto ports = QSerialPortInfo::availablePorts();
    for (const QSerialPortInfo &info : ports) {
        if (info.systemLocation() != location && info.systemLocation() != canonical && info.portName() != portName)
            continue;
        m_serialNumber = info.serialNumber();
        m_hasUsbIds = info.hasVendorIdentifier() && info.hasProductIdentifier();
        m_vendorId = info.vendorIdentifier();
        m_productId = info.productIdentifier();
        break;
    }
}

QString SessionWorker::locateDevice() const
{
    if (!m_serialNumber.isEmpty()) {
        // The same adapter, wherever it enumerated this time (ttyUSB0 may come back as ttyUSB1).
        const auto ports = QSerialPortInfo::availablePorts();
        for (const QSerialPortInfo &info : ports) {
            if (info.serialNumber() != m_serialNumber)
                continue;
            if (m_hasUsbIds && (info.vendorIdentifier() != m_vendorId || info.productIdentifier() != m_productId))
                continue;
            // The path the user chose, if it leads there (a by-id symlink), else the device.
            const QString wanted = io::SerialTransport::systemLocation(m_requestedPort);
            return QFileInfo(wanted).canonicalFilePath() == info.systemLocation() ? m_requestedPort
                                                                                   : info.systemLocation();
        }
        return {};
    }
    // No USB identity (a pseudo-terminal, an on-board UART): the same path, once it exists.
    return QFileInfo::exists(io::SerialTransport::systemLocation(m_requestedPort)) ? m_requestedPort : QString();
}

void SessionWorker::noteIdentity(const model::DeviceIdentity &id)
{
    // A path without a USB serial number may come back with another module behind it.
    if (m_checkSameDevice && !m_deviceSerial.empty() && !id.serial.empty() && id.serial != m_deviceSerial)
        Q_EMIT errorOccurred(tr("The device that came back on %1 is a different one (serial %2, before %3). Its data "
                                "continues in this session.")
                                 .arg(m_portName, QString::fromStdString(id.serial),
                                      QString::fromStdString(m_deviceSerial)));
    m_checkSameDevice = false;
    if (!id.serial.empty())
        m_deviceSerial = id.serial;
    m_identity = id;
    Q_EMIT identityChanged(id);
}

void SessionWorker::startWaiting()
{
    m_lastReconnectError.clear();
    setState(SessionState::Reconnecting, tr("disconnected — waiting for the device to come back"));
    m_reconnectTimer.start();
}

void SessionWorker::tryReconnect()
{
    if (m_state != SessionState::Reconnecting || !m_autoReconnect) {
        m_reconnectTimer.stop();
        return;
    }
    const QString path = locateDevice();
    if (path.isEmpty())
        return;
    QString error;
    if (!m_transport->open(path, m_workingBaud, &error)) {
        // Just plugged in: udev may not have set the permissions yet. Keep trying.
        if (error != m_lastReconnectError)
            qCInfo(lcSession) << "reconnect attempt failed:" << error;
        m_lastReconnectError = error;
        return;
    }
    m_reconnectTimer.stop();
    m_portName = path;
    ++m_reconnects;
    // Counters and samples carry on; only the stream state starts afresh.
    m_demux.reset();
    m_gaps.resetTiming(); // the outage is a disconnection, not lost frames
    const qint64 nowMs = m_statsClock.isValid() ? m_statsClock.elapsed() : 0;
    const SessionStats before = counterSnapshot();
    m_lastStats.bytesIn = before.bytesIn;
    m_lastStats.framesByType = before.framesByType;
    m_lastStatsMs = nowMs;
    m_statsTimer.start();
    setState(SessionState::Connected, tr("%1 at %2 baud (reconnected)").arg(path).arg(m_workingBaud));
    m_checkSameDevice = true;
    Q_EMIT reconnected();
    listenThenQueryIdentity();
}

// ---------------------------------------------------------------------------------------
// Frames lost

namespace {

struct OutputCommand {
    bool changesOutput = false;   // the stream's timing may jump here
    bool setsMessage = false;     // LOG <MSG> ...: the message's own setting
    bool thisPort = true;         // no COMn word: the port the command came in on
    std::string message;          // HI91, ...
    double periodS = -1;          // ONTIME period; -1 when not ONTIME
};

OutputCommand parseOutputCommand(const QString &text)
{
    static const QRegularExpression space(QStringLiteral("\\s+"));
    const QStringList w = text.trimmed().toUpper().split(space, Qt::SkipEmptyParts);
    OutputCommand c;
    if (w.isEmpty())
        return c;
    const QString &verb = w.front();
    if (verb == QLatin1String("REBOOT") || verb == QLatin1String("FRESET") || verb == QLatin1String("SERIALCONFIG")) {
        c.changesOutput = true;
        return c;
    }
    if (verb != QLatin1String("LOG") || w.size() < 2)
        return c;
    // Queries leave the output alone.
    static const QStringList queries = {QStringLiteral("VERSION"), QStringLiteral("COMCONFIG"),
                                        QStringLiteral("MAGCONFIG"), QStringLiteral("MCAL")};
    if (queries.contains(w.at(1)))
        return c;
    c.changesOutput = true;
    qsizetype i = 1;
    if (w.at(i).startsWith(QLatin1String("COM"))) {
        c.thisPort = false;
        ++i;
    }
    protocol::hipnuc::Message m;
    if (i >= w.size() || !protocol::hipnuc::parseMessage(w.at(i).toStdString(), m))
        return c; // LOG ENABLE / DISABLE
    c.setsMessage = true;
    c.message = protocol::hipnuc::messageName(m);
    if (i + 2 < w.size() && w.at(i + 1) == QLatin1String("ONTIME")) {
        bool ok = false;
        const double p = w.at(i + 2).toDouble(&ok);
        if (ok && p >= 0)
            c.periodS = p;
    }
    return c;
}

size_t defaultFrameBytes(const std::string &message)
{
    const size_t header = protocol::hipnuc::FrameDecoder::kHeaderSize;
    if (message == "HI91")
        return protocol::hipnuc::Hi91::kSize + header;
    if (message == "HI92")
        return protocol::hipnuc::Hi92::kSize + header;
    if (message == "HI81")
        return protocol::hipnuc::Hi81::kSize + header;
    return 0; // HI83: its size depends on the MAP
}

} // namespace

void SessionWorker::noteCommandSent(const QString &text)
{
    if (parseOutputCommand(text).changesOutput)
        m_gaps.resetTiming();
}

void SessionWorker::noteCommandDone(const QString &text, const Reply &reply)
{
    const OutputCommand c = parseOutputCommand(text);
    if (!c.changesOutput || !reply.ok())
        return;
    m_gaps.resetTiming();
    if (!c.setsMessage || !c.thisPort)
        return;
    // Can the link carry the new rate? If not, the frames that arrive no longer show it.
    double expectedMs = 0;
    if (c.periodS > 0 && m_transport && m_transport->baud() > 0) {
        const auto seen = m_frameBytes.find(c.message);
        const size_t bytes = seen != m_frameBytes.end() ? seen->second : defaultFrameBytes(c.message);
        const double load = double(bytes) * 10.0 / c.periodS / double(m_transport->baud());
        if (bytes > 0 && load > kSaturatedLinkLoad)
            expectedMs = c.periodS * 1000.0;
    }
    m_gaps.setExpectedPeriod(c.message, expectedMs);
}

SessionStats SessionWorker::counterSnapshot() const
{
    SessionStats s;
    const auto &fc = m_demux.frameCounters();
    const auto &dc = m_demux.counters();
    s.bytesIn = fc.bytesIn;
    s.frames = fc.frames;
    s.crcErrors = fc.crcErrors;
    s.lengthErrors = fc.lengthErrors;
    // Bytes that were neither a frame nor a reply or NMEA line (a command's OK is not damage).
    s.bytesSkipped = fc.bytesSkipped > dc.lineBytes ? fc.bytesSkipped - dc.lineBytes : 0;
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
    s.framesLost = m_gaps.lost();
    s.framesLostByType = m_gaps.lostByType();
    s.deviceResets = m_gaps.resets();
    s.reconnects = m_reconnects;
    s.baud = m_transport ? m_transport->baud() : 0;
    return s;
}

void SessionWorker::watchForGarbage(const SessionStats &now, qint64 nowMs)
{
    constexpr qint64 kGarbageReportMs = 1500;
    const bool decoded = now.frames > m_lastStats.frames || now.nmeaSentences > m_lastStats.nmeaSentences;
    const bool damaged = now.bytesSkipped > m_lastStats.bytesSkipped || now.crcErrors > m_lastStats.crcErrors;
    if (decoded || now.bytesIn < m_lastStats.bytesIn + 64 || !damaged) {
        m_garbageSinceMs = -1;
        if (decoded)
            m_garbageReported = false;
        return;
    }
    if (m_garbageSinceMs < 0)
        m_garbageSinceMs = m_lastStatsMs;
    if (!m_garbageReported && nowMs - m_garbageSinceMs >= kGarbageReportMs) {
        m_garbageReported = true;
        Q_EMIT errorOccurred(tr("Bytes keep arriving on %1 but none of them form a frame: the device probably runs at "
                                "another baud rate now. Disconnect and connect again with the baud rate set to Auto.")
                                 .arg(m_portName));
    }
}

void SessionWorker::publishStats()
{
    SessionStats s = counterSnapshot();
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
        watchForGarbage(s, nowMs);
        m_lastStats = s;
        m_lastStatsMs = nowMs;
    } else {
        s.rateByType = m_lastStats.rateByType;
        s.bytesPerSecond = m_lastStats.bytesPerSecond;
        s.linkLoad = m_lastStats.linkLoad;
    }
    Q_EMIT statsUpdated(s);
    if (m_recorder)
        Q_EMIT recordingProgress(m_recorder->status().bytesWritten,
                                 s.frames >= m_framesAtRecordStart ? s.frames - m_framesAtRecordStart : s.frames);
}

void SessionWorker::queryIdentity(int attempt)
{
    constexpr int kAttempts = 3;
    Pending p;
    p.text = QString::fromStdString(hp::commands::logVersion().text);
    p.timeoutMs = kIdentityTimeoutMs;
    p.done = [this, attempt](const Reply &r) {
        bool answered = false;
        if (r.ok()) {
            const auto id = model::DeviceIdentity::fromKeyValues(r.values);
            answered = id.usable();
            if (answered)
                noteIdentity(id);
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
        if (LinkDone done = std::exchange(m_afterDetect, {}))
            done(false, 0);
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
    p.text = QString::fromStdString(hp::commands::logVersion().text);
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
    m_workingBaud = baud;
    m_demux.resetCounters();
    m_gaps.clear();
    m_lastStats = SessionStats{};
    m_statsClock.restart();
    m_lastStatsMs = 0;
    Q_EMIT baudDetected(baud);
    if (id)
        noteIdentity(*id);
    setState(SessionState::Connected, tr("%1 at %2 baud").arg(m_portName).arg(baud));
    if (LinkDone done = std::exchange(m_afterDetect, {}))
        done(true, baud);
}

} // namespace imudesk::device
