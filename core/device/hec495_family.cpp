#include "hec495_family.h"

#include "clock/clock_model.h"
#include "device/session_engine.h"
#include "device/stream_counters.h"
#include "protocol/witlink/commands.h"

#include <QLoggingCategory>

#include <algorithm>

namespace imudesk::device {

namespace {

Q_LOGGING_CATEGORY(lcHec495, "imudesk.core.device.hec495")

namespace wl = protocol::witlink;

constexpr int kStreamingLostMs = 1500; // no auto-output frame for this long: question/answer again

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
    m_decoder.setHook(this);
    m_decoder.setNmeaSamples(true); // positions, fixes and times in the values
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
        m_decoder.restart();
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
    m_decoder.restart();
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
    m_decoder.resetCounters();
}

void Hec495Family::feed(const QByteArray &bytes, int64_t nowNs)
{
    m_batch.clear();
    m_unsolicitedData = false;
    m_decoder.feed(reinterpret_cast<const uint8_t *>(bytes.constData()), size_t(bytes.size()), nowNs, *this);
    afterFrames();
}

void Hec495Family::lineIdle(int64_t nowNs)
{
    m_batch.clear();
    m_unsolicitedData = false;
    m_decoder.lineIdle(nowNs, *this);
    afterFrames();
}

void Hec495Family::onSample(const model::Sample &sample, const decode::Record &)
{
    m_batch.push_back(sample);
}

void Hec495Family::onText(decode::TextKind kind, const std::string &text, int64_t)
{
    // The bytes that belong to no frame: NMEA output (its positions already among the samples), or noise.
    if (kind != decode::TextKind::Line)
        Q_EMIT nmeaReceived(QString::fromStdString(text));
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

decode::WitlinkStreamDecoder::FrameVerdict Hec495Family::frame(const wl::Frame &f, const wl::Reply &r)
{
    decode::WitlinkStreamDecoder::FrameVerdict v;
    const Request *current = engine().current();
    if (current) {
        const std::vector<uint8_t> heard = wl::encodeFrame(f);
        if (QByteArray::fromRawData(reinterpret_cast<const char *>(heard.data()), qsizetype(heard.size()))
            == current->wire) {
            // Our own request heard back (an RS-485 echo), or, for a command the manual
            // answers with its own bytes (0x49 prints 49: "77 05 00 49 00 4E" is both "set
            // content 00" and its success), the reply itself. A request that is no valid
            // reply (the identification's "read all" has no record) is an echo, and then
            // the link echoes everything: there the first identical frame is the echo.
            const bool validReply = r.ok() && answersCurrent(f);
            if (!validReply) {
                m_linkEchoes = true;
                v.skip = true;
                return v;
            }
            // An echoing link: the first identical frame of this attempt is the echo.
            const std::pair<const Request *, int> attempt{current, current->attempts};
            if (m_linkEchoes && m_echoHeard != attempt) {
                m_echoHeard = attempt;
                v.skip = true;
                return v;
            }
        }
    }
    const bool data = r.ok() && (r.kind == wl::Reply::Kind::AllData || r.kind == wl::Reply::Kind::Angles);
    if (answersCurrent(f)) {
        // Asked for: the module measured between the question and its answer (the decoder
        // stamps the sample with the bracket).
        v.answers = current->sentNs > 0;
        v.sentNs = current->sentNs;
        RequestResult res;
        Hec495Result typed;
        typed.request = commandOf(*current).command;
        typed.reply = r;
        res.reply = QVariant::fromValue(typed);
        if (!r.ok()) {
            res.status = RequestStatus::Invalid;
            res.message = tr("the module answered with an invalid reply: %1").arg(wl::Reply::errorText(r.error));
        } else if (!r.success) {
            res.status = RequestStatus::Refused;
            res.message = tr("the module reported failure (FF) for \"%1\"").arg(commandText(*current));
        } else {
            res.status = RequestStatus::Ok;
            res.message = r.describe();
        }
        m_echoHeard = {};
        engine().finishCurrent(std::move(res));
        return v;
    }
    if (data)
        m_unsolicitedData = true;
    else if (r.ok() && r.kind == wl::Reply::Kind::CalibrationPoint)
        Q_EMIT calibrationPoint(r.points);
    return v;
}

void Hec495Family::afterFrames()
{
    if (m_unsolicitedData) {
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
    if (!m_batch.empty())
        engine().appendSamples(m_batch);
}

void Hec495Family::fillCounters(SessionStats &s) const
{
    addDecodeCounters(m_decoder.counters(), s);
    ClockStats::addBrackets(s.clocks, "HEC495", m_decoder.brackets());
}

} // namespace imudesk::device
