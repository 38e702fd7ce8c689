#include "hec495_family.h"

#include "clock/clock_model.h"
#include "device/session_engine.h"
#include "protocol/nmea/nmea_sample.h"
#include "protocol/witlink/commands.h"

#include <QLoggingCategory>

#include <algorithm>

namespace imudesk::device {

namespace {

Q_LOGGING_CATEGORY(lcHec495, "imudesk.core.device.hec495")

namespace wl = protocol::witlink;

constexpr int kStreamingLostMs = 1500; // no auto-output frame for this long: question/answer again

const char *frameType(uint8_t command)
{
    return command == 0x84 ? "HEC495 angles" : "HEC495 record";
}

const Hec495Family::Command &commandOf(const Request &r)
{
    return *std::any_cast<Hec495Family::Command>(&r.command);
}

QString commandText(const Request &r)
{
    return QString::fromLatin1(wl::commands::commandName(commandOf(r).command));
}

} // namespace

const std::vector<int> &Hec495Family::detectionBauds()
{
    static const std::vector<int> bauds = {9600, 115200, 19200, 4800, 2400};
    return bauds;
}

Hec495Family::Hec495Family()
{
    connect(&m_pollTimer, &QTimer::timeout, this, &Hec495Family::poll);
}

Request Hec495Family::makeRequest(uint8_t command, const QByteArray &data, int timeoutMs)
{
    Request r;
    r.command = Command{command, std::vector<uint8_t>(data.begin(), data.end())};
    r.timeoutMs = timeoutMs > 0 ? timeoutMs : kReplyTimeoutMs;
    r.maxAttempts = kAttempts;
    if (command == uint8_t(wl::Command::CollectPoint)) {
        r.maxAttempts = 1;
        r.timeoutMs = std::max(r.timeoutMs, kCollectTimeoutMs);
    }
    return r;
}

QString Hec495Family::prepare(Request &r)
{
    const Command &c = commandOf(r);
    const uint8_t address = c.command == uint8_t(wl::Command::QueryAddress) ? 0 : uint8_t(m_address);
    const std::vector<uint8_t> wire = wl::encodeFrame(address, c.command, c.data);
    if (wire.empty())
        return tr("the request's data is longer than a Witlink frame can carry");
    r.wire = QByteArray(reinterpret_cast<const char *>(wire.data()), qsizetype(wire.size()));
    return {};
}

// ---------------------------------------------------------------------------------------
// Opening

int Hec495Family::firstBaud(int requestedBaud) const
{
    return requestedBaud > 0 ? requestedBaud : detectionBauds().front();
}

void Hec495Family::opened(int requestedBaud)
{
    m_streaming = false;
    m_linkEchoes = false;
    m_identityKnown = false;
    engine().setState(SessionState::Detecting, engine().transport().address());
    BaudScan::Plan p;
    p.bauds = requestedBaud > 0 ? std::vector<int>{requestedBaud} : detectionBauds();
    p.listenMs = kListenMs; // a streaming module identifies itself (handleFrames)
    p.tune = [this](int baud) {
        engine().transport().setBaud(baud);
        engine().transport().clear();
        m_decoder.reset();
        qCDebug(lcHec495) << "listening at" << baud;
    };
    // A single rate given: use the 3 s window after power-on; scanning rates: two tries each.
    const int attempts = p.bauds.size() == 1 ? kIdentifyWindowMs / kReplyTimeoutMs : 2;
    p.probe = [this, attempts](int, BaudScan::Answer answer) {
        Request r = makeRequest(uint8_t(wl::Command::ReadAll), {}, 0);
        r.maxAttempts = attempts;
        r.done = [this, answer](const RequestResult &res) {
            if (res.ok())
                m_identifyReply = res.reply.value<Hec495Result>().reply;
            answer(res.ok() ? BaudScan::Outcome::Found
                   : res.status == RequestStatus::Cancelled ? BaudScan::Outcome::Stop
                                                            : BaudScan::Outcome::TryNext);
        };
        engine().submit(std::move(r));
    };
    p.found = [this](int baud) { identified(baud, &m_identifyReply); };
    p.exhausted = [this, single = p.bauds.size() == 1 ? QString::number(p.bauds.front()) : tr("any supported")] {
        engine().fail(tr("no HEC495 answered on %1 at %2 baud: check the wiring (RS-232 TXD/RXD or RS-485 A/B), the "
                         "power, the baud rate and the module address (%3)")
                          .arg(engine().transport().address())
                          .arg(single)
                          .arg(m_address));
    };
    m_scan.start(std::move(p));
}

void Hec495Family::identified(int baud, const wl::Reply *reply)
{
    m_scan.stop();
    m_identityKnown = true;
    engine().setWorkingBaud(baud);
    model::DeviceIdentity id;
    id.productName = "HEC495";
    id.busAddress = m_address;
    if (reply && reply->address != m_address && reply->address != wl::kReplySetAddressAddress)
        id.busAddress = m_address = reply->address;
    engine().setIdentity(id);
    Q_EMIT addressChanged(m_address);
    Q_EMIT baudChanged(baud);
    engine().setState(SessionState::Connected, engine().transport().address());
    qCInfo(lcHec495) << "HEC495 at" << baud << "baud, address" << m_address << (m_streaming ? "streaming" : "polled");
    if (!m_streaming && m_pollHz > 0)
        m_pollTimer.start(1000 / m_pollHz);
}

void Hec495Family::stopping()
{
    m_scan.stop();
    m_pollTimer.stop();
}

// ---------------------------------------------------------------------------------------
// Polling and streaming

void Hec495Family::setPollingRate(int hz)
{
    m_pollHz = std::clamp(hz, 0, 100);
    m_pollTimer.stop();
    if (m_pollHz > 0 && m_identityKnown && !m_streaming)
        m_pollTimer.start(1000 / m_pollHz);
}

void Hec495Family::setStreaming(bool on)
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

void Hec495Family::poll()
{
    if (m_streaming || !engine().idle() || !engine().transport().isOpen())
        return;
    Request r = makeRequest(uint8_t(wl::Command::ReadAll), {}, 0);
    r.maxAttempts = 1; // the next poll is the retry
    engine().submit(std::move(r));
}

void Hec495Family::statsTick()
{
    // Auto-output stopped (another tool set question/answer, or the module restarted): poll again.
    if (m_streaming && m_identityKnown && m_lastStreamFrame.isValid() && m_lastStreamFrame.elapsed() > kStreamingLostMs)
        setStreaming(false);
}

// ---------------------------------------------------------------------------------------
// Requests

void Hec495Family::unanswered(const Request &r, RequestResult &result)
{
    if (result.status == RequestStatus::Timeout)
        result.message = tr("no reply to \"%1\" after %2 attempts of %3 ms (check the baud rate and the module "
                            "address; an RS-485 module that streams may miss commands: set question/answer mode)")
                             .arg(commandText(r))
                             .arg(r.attempts)
                             .arg(r.timeoutMs);
    Hec495Result typed;
    typed.request = commandOf(r).command;
    result.reply = QVariant::fromValue(typed);
}

void Hec495Family::followBaud(int baud)
{
    engine().transport().setBaud(baud);
    engine().setWorkingBaud(baud);
    m_decoder.reset();
    Q_EMIT baudChanged(baud);
}

void Hec495Family::finished(const Request &r, const RequestResult &result)
{
    if (!result.ok())
        return;
    using C = wl::Command;
    const Command &c = commandOf(r);
    switch (C(c.command)) {
    case C::SetBaud: {
        const int baud = c.data.size() == 1 ? wl::commands::baudFromCode(c.data[0]) : -1;
        if (baud > 0)
            followBaud(baud); // the reply came at the old rate (2.13)
        break;
    }
    case C::SetAddress:
        if (c.data.size() == 1) {
            m_address = c.data[0];
            Q_EMIT addressChanged(m_address);
        }
        break;
    case C::QueryAddress: {
        const int address = result.reply.value<Hec495Result>().reply.deviceAddress;
        if (address != m_address) {
            m_address = address;
            Q_EMIT addressChanged(m_address);
        }
        break;
    }
    case C::FactoryReset:
        m_address = wl::commands::kDefaultAddress;
        Q_EMIT addressChanged(m_address);
        if (engine().transport().baud() != wl::commands::kDefaultBaud)
            followBaud(wl::commands::kDefaultBaud);
        setStreaming(false);
        break;
    case C::SetOutputRate:
        // NMEA output is text beside which the family keeps polling (handleText).
        if (c.data.size() == 1)
            setStreaming(wl::commands::rateFromCode(c.data[0]) > 0 && m_content != uint8_t(wl::OutputContent::Nmea0183));
        break;
    case C::SetOutputContent:
        if (c.data.size() == 1) {
            m_content = c.data[0];
            if (m_content == uint8_t(wl::OutputContent::Nmea0183))
                setStreaming(false);
        }
        break;
    default:
        break;
    }
}

// ---------------------------------------------------------------------------------------
// Received frames

void Hec495Family::resetCounters()
{
    m_decoder = wl::FrameDecoder{};
    m_framesByType.clear();
    m_payloadErrors = 0;
    m_text.resetCounters();
}

void Hec495Family::feed(const QByteArray &bytes, int64_t nowNs)
{
    m_frames.clear();
    m_batch.clear();
    m_decoder.feed(reinterpret_cast<const uint8_t *>(bytes.constData()), size_t(bytes.size()), m_frames);
    handleText(nowNs);
    handleFrames(m_frames, nowNs);
    if (!m_batch.empty())
        engine().appendSamples(m_batch);
}

void Hec495Family::lineIdle(int64_t nowNs)
{
    m_frames.clear();
    m_batch.clear();
    m_decoder.flushIdle(m_frames);
    handleText(nowNs);
    handleFrames(m_frames, nowNs);
    if (!m_batch.empty())
        engine().appendSamples(m_batch);
}

void Hec495Family::handleText(int64_t nowNs)
{
    namespace nmea = protocol::nmea;
    // The bytes that belong to no frame: NMEA output, or noise. The same demultiplexer as a
    // replay's (capture::CaptureDecoder) splits them into sentences, so both see the same ones.
    const std::string text = m_decoder.takeSkipped();
    if (text.empty())
        return;
    m_textEvents.clear();
    m_text.feed(reinterpret_cast<const uint8_t *>(text.data()), text.size(), m_textEvents);
    for (const protocol::StreamEvent &e : m_textEvents) {
        if (e.kind != protocol::StreamEvent::Kind::Nmea)
            continue;
        const nmea::ParseResult parsed = nmea::parseSentence(e.text);
        if (!parsed.sentence)
            continue;
        ++m_framesByType["NMEA " + parsed.sentence->type];
        if (auto sample = nmea::toSample(*parsed.sentence)) {
            sample->hostTimeNs = nowNs;
            m_batch.push_back(std::move(*sample));
        }
        Q_EMIT nmeaReceived(QString::fromStdString(e.text));
    }
}

bool Hec495Family::answersCurrent(const wl::Frame &f) const
{
    const Request *current = engine().current();
    if (!current)
        return false;
    const uint8_t command = commandOf(*current).command;
    const auto expected = wl::commands::expectedReplies(command);
    if (std::find(expected.begin(), expected.end(), f.command) == expected.end())
        return false;
    const bool anyAddress =
        command == uint8_t(wl::Command::SetAddress) || command == uint8_t(wl::Command::QueryAddress) || m_scan.running();
    return anyAddress || f.address == m_address;
}

void Hec495Family::handleFrames(const std::vector<wl::Frame> &frames, int64_t nowNs)
{
    if (frames.empty())
        return;
    bool unsolicitedData = false;
    for (const auto &f : frames) {
        if (const Request *current = engine().current()) {
            const std::vector<uint8_t> heard = wl::encodeFrame(f);
            if (QByteArray::fromRawData(reinterpret_cast<const char *>(heard.data()), qsizetype(heard.size()))
                == current->wire) {
                // Our own request heard back (an RS-485 echo), or, for a command the manual
                // answers with its own bytes (0x49 prints 49: "77 05 00 49 00 4E" is both "set
                // content 00" and its success), the reply itself. A request that is no valid
                // reply (the identification's "read all" has no record) is an echo, and then
                // the link echoes everything: there the first identical frame is the echo.
                const bool validReply = wl::decodeReply(f).ok() && answersCurrent(f);
                if (!validReply) {
                    m_linkEchoes = true;
                    continue;
                }
                // An echoing link: the first identical frame of this attempt is the echo.
                const std::pair<const Request *, int> attempt{current, current->attempts};
                if (m_linkEchoes && m_echoHeard != attempt) {
                    m_echoHeard = attempt;
                    continue;
                }
            }
        }
        const wl::Reply r = wl::decodeReply(f);
        const bool data = r.ok() && (r.kind == wl::Reply::Kind::AllData || r.kind == wl::Reply::Kind::Angles);
        if (data) {
            ++m_framesByType[frameType(f.command)];
            model::Sample s = *wl::sampleOf(r, nowNs);
            // Asked for: the module measured between the question and its answer. Sent on its
            // own (continuous output) it has no bracket and keeps its arrival alone.
            if (const Request *current = engine().current(); current && current->sentNs > 0 && answersCurrent(f)) {
                const clock::BracketTime b = clock::bracketTime(current->sentNs, nowNs);
                s.commonTimeNs = b.hostNs;
                s.commonUncertaintyNs = b.uncertaintyNs;
                m_brackets.add(b);
            }
            m_batch.push_back(std::move(s));
        } else if (!r.ok()) {
            ++m_payloadErrors;
        }
        if (answersCurrent(f)) {
            RequestResult res;
            Hec495Result typed;
            typed.request = commandOf(*engine().current()).command;
            typed.reply = r;
            res.reply = QVariant::fromValue(typed);
            if (!r.ok()) {
                res.status = RequestStatus::Invalid;
                res.message = tr("the module answered with an invalid reply: %1").arg(wl::Reply::errorText(r.error));
            } else if (!r.success) {
                res.status = RequestStatus::Refused;
                res.message = tr("the module reported failure (FF) for \"%1\"").arg(commandText(*engine().current()));
            } else {
                res.status = RequestStatus::Ok;
                res.message = r.describe();
            }
            m_echoHeard = {};
            engine().finishCurrent(std::move(res));
            continue;
        }
        if (data)
            unsolicitedData = true;
        else if (r.ok() && r.kind == wl::Reply::Kind::CalibrationPoint)
            Q_EMIT calibrationPoint(r.points);
    }
    if (unsolicitedData) {
        m_lastStreamFrame.restart();
        setStreaming(true);
        if (m_scan.running()) {
            m_scan.stop();
            engine().cancelAll(RequestStatus::Cancelled, tr("the module streams: identified without a request"));
            identified(engine().transport().baud(), nullptr);
        } else {
            engine().releaseHeldWrite(); // the line is quiet until the next frame
        }
    }
}

void Hec495Family::fillCounters(SessionStats &s) const
{
    const auto &c = m_decoder.counters();
    s.bytesIn = c.bytesIn;
    s.frames = c.frames;
    s.crcErrors = c.checksumErrors;
    s.lengthErrors = c.lengthErrors;
    s.bytesSkipped = c.bytesSkipped;
    s.payloadErrors = m_payloadErrors;
    s.framesByType = m_framesByType;
    s.nmeaSentences = m_text.counters().nmeaSentences;
    s.nmeaErrors = m_text.counters().nmeaErrors;
    ClockStats::addBrackets(s.clocks, "HEC495", m_brackets);
}

} // namespace imudesk::device
