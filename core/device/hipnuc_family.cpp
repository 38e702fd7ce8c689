#include "hipnuc_family.h"

#include "device/session_engine.h"
#include "device/stream_counters.h"
#include "model/main_status.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"
#include "protocol/nmea/nmea_sample.h"

#include <utility>

namespace imudesk::device {

using protocol::StreamEvent;
namespace hp = protocol::hipnuc;

namespace {

constexpr int kListenMs = 150;
constexpr int kIdentityTimeoutMs = 1000;
// A configured rate whose frames need more of the line than this cannot all arrive, so the
// frames that do no longer show the period: the gap counter is told the configured one.
constexpr double kSaturatedLinkLoad = 0.9;

const hp::Command &commandOf(const Request &r)
{
    return *std::any_cast<hp::Command>(&r.command);
}

size_t defaultFrameBytes(const std::string &message)
{
    const size_t header = hp::FrameDecoder::kHeaderSize;
    if (message == "HI91")
        return hp::Hi91::kSize + header;
    if (message == "HI92")
        return hp::Hi92::kSize + header;
    if (message == "HI81")
        return hp::Hi81::kSize + header;
    return 0; // HI83: its size depends on the MAP
}

} // namespace

const std::vector<int> &HipnucSerialFamily::detectionBauds()
{
    static const std::vector<int> bauds = {115200, 921600, 460800, 230400, 256000, 57600, 38400, 19200, 9600, 4800};
    return bauds;
}

Request HipnucSerialFamily::makeRequest(const hp::Command &command, int timeoutMs,
                                        std::function<void(const Reply &)> done)
{
    Request r;
    r.wire = QByteArray::fromStdString(command.wire());
    r.timeoutMs = timeoutMs;
    r.command = command;
    if (done)
        r.done = [done = std::move(done)](const RequestResult &res) { done(res.reply.value<Reply>()); };
    return r;
}

HipnucSerialFamily::HipnucSerialFamily()
{
    m_listenTimer.setSingleShot(true);
    m_decoder.setNmeaSamples(true); // positions, fixes and times in the values
}

// ---------------------------------------------------------------------------------------
// The link

int HipnucSerialFamily::firstBaud(int requestedBaud) const
{
    return requestedBaud > 0 ? requestedBaud : detectionBauds().front();
}

void HipnucSerialFamily::opened(int requestedBaud)
{
    m_decoder.reset(); // a new link: the device's clocks start again
    m_deviceSerial.clear();
    m_checkSameDevice = false;
    const QString port = engine().transport().address();
    if (requestedBaud > 0) {
        engine().setWorkingBaud(requestedBaud);
        engine().setState(SessionState::Connected, port);
        listenThenQueryIdentity();
    } else {
        engine().setState(SessionState::Detecting, port);
        m_scan.start(detectionPlan());
    }
}

void HipnucSerialFamily::stopping()
{
    m_scan.stop();
    m_listenTimer.stop();
    m_listenTimer.disconnect();
    finishLink(false, 0);
}

void HipnucSerialFamily::reconnected()
{
    m_checkSameDevice = true;
    listenThenQueryIdentity();
}

void HipnucSerialFamily::setHostBaud(int baud)
{
    if (!engine().transport().isOpen())
        return;
    engine().transport().setBaud(baud);
    engine().setWorkingBaud(baud);
    restartStream(); // bytes were lost while the two sides disagreed
    engine().publishStats();
}

void HipnucSerialFamily::listenThenQueryIdentity()
{
    // Listen first, as the detection does: joining a stream mid-frame, the tail of that
    // frame must not be mistaken for the start of the reply.
    m_listenTimer.disconnect();
    connect(&m_listenTimer, &QTimer::timeout, this, [this] { queryIdentity(1); });
    m_listenTimer.start(kListenMs);
}

void HipnucSerialFamily::queryIdentity(int attempt)
{
    constexpr int kAttempts = 3;
    engine().submit(makeRequest(hp::commands::logVersion(), kIdentityTimeoutMs, [this, attempt](const Reply &r) {
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
        if (!answered) {
            Q_EMIT identityQueryFinished(false);
            return;
        }
        // The frame before "connected": the first sample shown is labelled right.
        queryWorldFrame([this] { Q_EMIT identityQueryFinished(true); });
    }));
}

void HipnucSerialFamily::queryWorldFrame(std::function<void()> then)
{
    m_coordChangePending = false; // (re)connected: what the module reports now is in effect
    if (engine().identity().edition() != model::ManualEdition::V171) {
        then(); // COORD is a setting of firmware 1.7.1 and later; before, always ENU
        return;
    }
    engine().submit(makeRequest(hp::commands::logComConfig(), kIdentityTimeoutMs, [this, then](const Reply &r) {
        if (r.status == Reply::Status::Cancelled || r.status == Reply::Status::NotSent)
            return; // the session stopped or the port closed meanwhile: nothing to go on with
        if (r.ok())
            noteWorldFrame(r);
        else
            noteWorldFrameAssumed(); // no answer: the frame stays as it was (ENU at first), unconfirmed
        then();
    }));
}

void HipnucSerialFamily::noteWorldFrame(const Reply &r)
{
    if (m_coordChangePending)
        return;
    // The reply's pairs were read tolerantly (keyValuePairs) as its lines came.
    std::optional<model::WorldFrame> frame;
    if (const auto coord = r.values.find("COORD"); coord != r.values.end())
        frame = model::worldFrameOfCoord(coord->second);
    // A reply that names no COORD (or a value of none of the manual's frames): ENU, the default,
    // is assumed, and the identity says so (the attitude view and the status bar warn).
    const bool assumed = !frame;
    if (!frame)
        frame = model::WorldFrame::Enu;
    if (*frame == engine().identity().worldFrame && assumed == engine().identity().worldFrameAssumed)
        return;
    model::DeviceIdentity id = engine().identity();
    id.worldFrame = *frame;
    id.worldFrameAssumed = assumed;
    engine().setIdentity(id);
}

void HipnucSerialFamily::noteWorldFrameAssumed()
{
    if (m_coordChangePending || engine().identity().worldFrameAssumed)
        return;
    model::DeviceIdentity id = engine().identity();
    id.worldFrameAssumed = true;
    engine().setIdentity(id);
}

void HipnucSerialFamily::noteIdentity(const model::DeviceIdentity &id)
{
    // A path without a USB serial number may come back with another module behind it.
    if (m_checkSameDevice && !m_deviceSerial.empty() && !id.serial.empty() && id.serial != m_deviceSerial)
        engine().reportError(tr("The device that came back on %1 is a different one (serial %2, before %3). Its data "
                                "continues in this session.")
                                 .arg(engine().transport().address(), QString::fromStdString(id.serial),
                                      QString::fromStdString(m_deviceSerial)));
    m_checkSameDevice = false;
    if (!id.serial.empty())
        m_deviceSerial = id.serial;
    model::DeviceIdentity kept = id;
    kept.worldFrame = engine().identity().worldFrame; // LOG VERSION does not tell it; LOG COMCONFIG does
    kept.worldFrameAssumed = engine().identity().worldFrameAssumed;
    engine().setIdentity(kept);
}

// ---------------------------------------------------------------------------------------
// Requests

void HipnucSerialFamily::writing(const Request &r)
{
    m_collector.emplace(commandOf(r).text);
    m_decoder.endQuarantine(); // what answers now starts after a boundary the device keeps
    if (commandOf(r).effect.changesOutput)
        m_gaps.resetTiming();
}

void HipnucSerialFamily::unanswered(const Request &r, RequestResult &result)
{
    Reply reply = r.attempts > 0 && m_collector ? m_collector->take() : Reply{};
    reply.command = commandOf(r).text;
    switch (result.status) {
    case RequestStatus::Timeout:
        reply.status = Reply::Status::Timeout;
        result.message = tr("no reply within %1 ms (the device ignores commands it does not know)").arg(r.timeoutMs);
        break;
    case RequestStatus::Cancelled: reply.status = Reply::Status::Cancelled; break;
    default: reply.status = Reply::Status::NotSent; break;
    }
    reply.errorLine = result.message.toStdString();
    result.reply = QVariant::fromValue(reply);
}

void HipnucSerialFamily::finished(const Request &r, const RequestResult &result)
{
    if (r.attempts > 0)
        m_collector.reset();
    if (!result.ok())
        return;
    const hp::Command &command = commandOf(r);
    noteCommandDone(command.effect);
    // LOG VERSION asked for by someone (the console, a menu, a script) refreshes the identity
    // too; the family's own queries (id 0) set it where they are made.
    const QString text = QString::fromStdString(command.text).simplified().toUpper();
    if (r.id != 0 && text == QLatin1String("LOG VERSION")) {
        const auto id = model::DeviceIdentity::fromKeyValues(result.reply.value<Reply>().values);
        if (id.usable())
            noteIdentity(id);
    }
    if (text.startsWith(QLatin1String("CONFIG IMU COORD ")))
        m_coordChangePending = true;
    else if (r.id != 0 && text == QLatin1String("LOG COMCONFIG"))
        noteWorldFrame(result.reply.value<Reply>());
}

void HipnucSerialFamily::noteCommandDone(const hp::OutputEffect &c)
{
    if (!c.changesOutput)
        return;
    m_gaps.resetTiming();
    if (c.message.empty() || !c.thisPort)
        return;
    // Can the link carry the new rate? If not, the frames that arrive no longer show it.
    double expectedMs = 0;
    const int baud = engine().transport().baud();
    if (c.periodS > 0 && baud > 0) {
        const auto seen = m_frameBytes.find(c.message);
        const size_t bytes = seen != m_frameBytes.end() ? seen->second : defaultFrameBytes(c.message);
        const double load = double(bytes) * 10.0 / c.periodS / double(baud);
        if (bytes > 0 && load > kSaturatedLinkLoad)
            expectedMs = c.periodS * 1000.0;
    }
    m_gaps.setExpectedPeriod(c.message, expectedMs);
}

// ---------------------------------------------------------------------------------------
// The stream

void HipnucSerialFamily::restartStream()
{
    m_decoder.restart();
    m_gaps.resetTiming(); // an outage or a rate change is not lost frames
}

void HipnucSerialFamily::resetCounters()
{
    m_decoder.resetCounters();
    m_gaps.clear();
    m_frameBytes.clear();
}

void HipnucSerialFamily::feed(const QByteArray &bytes, int64_t nowNs)
{
    m_batch.clear();
    m_decoder.setBaud(engine().workingBaud());
    m_decoder.feed(reinterpret_cast<const uint8_t *>(bytes.constData()), size_t(bytes.size()), nowNs, *this);
    engine().appendSamples(m_batch);
}

void HipnucSerialFamily::lineIdle(int64_t nowNs)
{
    m_batch.clear();
    m_decoder.lineIdle(nowNs, *this);
    engine().appendSamples(m_batch);
}

void HipnucSerialFamily::onSample(const model::Sample &sample, const decode::Record &record)
{
    m_batch.push_back(sample);
    if (!record.native)
        return; // an NMEA sentence's position, fix and time
    m_frameBytes[sample.source] = record.unitBytes;
    if (sample.has(model::FieldDeviceTime))
        m_gaps.add(sample.source, sample.deviceTimeMs,
                   model::MainStatus::timeBase(sample.has(model::FieldMainStatus), sample.mainStatus));
}

void HipnucSerialFamily::onText(decode::TextKind kind, const std::string &text, int64_t)
{
    switch (kind) {
    case decode::TextKind::NmeaUndecoded:
        Q_EMIT textReceived(QString::fromStdString(text)); // a sentence ImuDesk does not decode: shown raw
        Q_EMIT nmeaReceived(QString::fromStdString(text));
        break;
    case decode::TextKind::Nmea:
        Q_EMIT nmeaReceived(QString::fromStdString(text));
        break;
    case decode::TextKind::Line:
        if (m_collector && engine().current() && m_collector->addLine(text)) {
            RequestResult r;
            Reply reply = m_collector->take();
            r.status = reply.ok() ? RequestStatus::Ok : RequestStatus::Refused;
            if (!reply.ok())
                r.message = QString::fromStdString(reply.errorLine);
            r.reply = QVariant::fromValue(std::move(reply));
            engine().finishCurrent(std::move(r));
        } else if (!m_collector) {
            Q_EMIT textReceived(QString::fromStdString(text));
        }
        break;
    }
}

void HipnucSerialFamily::fillCounters(SessionStats &s) const
{
    addDecodeCounters(m_decoder.counters(), s);
    addGapCounters(m_gaps, s);
    for (const clock::SampleClocks::Stream &c : m_decoder.frameClocks().clocks().streams()) {
        ClockStats k;
        k.source = c.source;
        k.method = ClockStats::Method::Counter;
        k.state = c.state;
        k.driftPpm = c.fit.valid ? c.fit.deviceDriftPpm() : 0;
        k.jitterNs = c.fit.jitterNs;
        k.resets = c.resets;
        k.spanS = c.fit.spanS;
        k.needSpanS = clock::ClockModel::Options{}.minSpanS;
        s.clocks.push_back(std::move(k));
    }
}

} // namespace imudesk::device
