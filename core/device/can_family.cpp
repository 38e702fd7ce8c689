#include "can_family.h"

#include "clock/host_clock.h"
#include "device/session_engine.h"
#include "device/stream_counters.h"
#include "io/can_transport.h"
#include "protocol/can/canopen.h"
#include "protocol/can/hec495_can.h"
#include "protocol/can/j1939.h"
#include "protocol/can/j1939_config.h"
#include "protocol/can/sdo.h"
#include "capture/capture_header.h"

#include <QLoggingCategory>

#include <algorithm>

Q_LOGGING_CATEGORY(lcCan, "imudesk.core.device.can")

namespace imudesk::device {

using namespace protocol::can;

namespace {

// A node's periodic data: CANopen TPDOs, HEC495 PDOs, J1939 data PGNs.
bool isDataFrame(const protocol::can::DecodedFrame &d)
{
    return d.kind == protocol::can::FrameKind::TpdoData || d.kind == protocol::can::FrameKind::Hec495Data
        || d.kind == protocol::can::FrameKind::J1939Data;
}

} // namespace

CanFamily::CanFamily()
{
    m_decoder.setHook(this);
    m_syncTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_syncTimer, &QTimer::timeout, this, [this] { write(canopen::encodeSync()); });
    m_scanTimer.setInterval(kScanSpacingMs);
    connect(&m_scanTimer, &QTimer::timeout, this, &CanFamily::scanTick);
}

void CanFamily::configure(const CanSessionOptions &options)
{
    m_options = options;
    if (auto *t = qobject_cast<io::CanTransport *>(&engine().transport()))
        t->setFd(options.canFd, options.dataBitrate);
}

// ---------------------------------------------------------------------------------------
// The link

void CanFamily::opened(int)
{
    m_decoder.decoder() = CanDecoder(m_options.protocol);
    m_decoder.decoder().setHec495Mode(m_options.hec495Mode);
    m_lastDetected = CanProtocol::Auto;
    m_decoder.setNode(m_options.node);
    m_seenNodes.clear();
    m_dataNodes.clear();
    engine().setState(SessionState::Connected, tr("connected to %1").arg(engine().transport().address()));
    startJob();
}

void CanFamily::stopping()
{
    m_syncTimer.stop();
    if (m_scanning)
        cancelScan();
    if (m_job)
        finishJob(false, tr("the session was closed"), RequestStatus::Cancelled);
    while (!m_jobs.empty()) {
        const quint64 id = m_jobs.front().id;
        m_jobs.pop_front();
        Q_EMIT jobFinished(CanRequestResult{id, false, 0, tr("the session was closed"), RequestStatus::Cancelled, {}, {}});
    }
}

bool CanFamily::write(const CanFrame &f)
{
    const QByteArray record = toRecord(f);
    if (!engine().transport().isOpen() || engine().transport().write(record) != record.size())
        return false;
    Q_EMIT framesSeen(CanFrameEvents{CanFrameEvent{f, hostNowNs(), true}});
    return true;
}

void CanFamily::sendFrame(const CanFrame &f)
{
    if (!write(f))
        engine().reportError(tr("could not send frame %1: the CAN interface is not connected").arg(f.idText()));
}

void CanFamily::setSyncPeriod(int ms)
{
    if (ms <= 0) {
        m_syncTimer.stop();
        return;
    }
    m_syncTimer.start(ms);
}

// ---------------------------------------------------------------------------------------
// Received frames

void CanFamily::resetCounters()
{
    m_decoder.resetCounters();
}

void CanFamily::feed(const QByteArray &bytes, int64_t now)
{
    m_batch.clear();
    m_frameEvents.clear();
    // Stamped with the arrival time the engine took on the host clock (clock/host_clock.h).
    m_decoder.setBaud(engine().transport().baud());
    m_decoder.feed(reinterpret_cast<const uint8_t *>(bytes.constData()), size_t(bytes.size()), now, *this);
    engine().appendSamples(m_batch);
    if (!m_frameEvents.isEmpty())
        Q_EMIT framesSeen(m_frameEvents);
}

void CanFamily::onSample(const model::Sample &sample, const decode::Record &)
{
    m_batch.push_back(sample);
}

void CanFamily::nodeFollowed(int node)
{
    Q_EMIT targetNodeChanged(node);
}

void CanFamily::follow(int node)
{
    m_decoder.setNode(node);
    Q_EMIT targetNodeChanged(node);
}

void CanFamily::describeCapture(capture::CaptureHeader &h) const
{
    const CanProtocol p = m_options.protocol == CanProtocol::Auto ? m_decoder.decoder().detected() : m_options.protocol;
    h.set(capture::CaptureHeader::kCanProtocol, protocolName(p));
    if (m_decoder.node() >= 0)
        h.set(capture::CaptureHeader::kCanNode, std::to_string(m_decoder.node()));
    if (m_options.hec495Mode >= 0)
        h.set(capture::CaptureHeader::kCanHec495Mode, std::to_string(m_options.hec495Mode));
}

bool CanFamily::frame(const CanFrame &f, const DecodedFrame &d, int64_t now)
{
    m_frameEvents.append(CanFrameEvent{f, now, false});
    const CanProtocol detected = m_decoder.decoder().detected();
    if (detected != m_lastDetected) {
        m_lastDetected = detected;
        Q_EMIT protocolDetected(int(m_lastDetected));
    }
    if (d.kind == FrameKind::Heartbeat && f.data[0] == canopen::StateBootUp)
        noteNode(d.protocol == CanProtocol::Auto ? CanProtocol::CanOpen : d.protocol, d.node, tr("boot-up"));
    else if (d.kind == FrameKind::Heartbeat)
        noteNode(detected == CanProtocol::Hec495 ? CanProtocol::Hec495 : CanProtocol::CanOpen, d.node, tr("heartbeat"));
    else if (d.sample && d.node >= 0)
        noteNode(d.protocol, d.node, tr("data"));
    if (m_scanning && d.kind == FrameKind::Sdo && d.node >= m_scanFrom && d.node <= m_scanTo) {
        if (const auto s = canopen::parseSdo(f); s && s->fromDevice && !m_scanFound.contains(d.node)) {
            m_scanFound.append(d.node);
            noteNode(CanProtocol::CanOpen, d.node, tr("SDO scan"));
        }
    }
    if (isDataFrame(d) && (d.node >= 0 || m_options.hec495Extended))
        m_dataNodes.insert(dataSource(d));
    return matchStep(f, d); // a job's answer is not a sample
}

void CanFamily::noteNode(CanProtocol p, int node, const QString &how)
{
    if (node < 0)
        return;
    const QString key = QStringLiteral("%1/%2").arg(int(p)).arg(node);
    if (m_seenNodes.contains(key) || m_seenNodes.size() > 1024)
        return;
    m_seenNodes.insert(key);
    Q_EMIT nodeDiscovered(CanNodeInfo{p, node, how});
}

void CanFamily::fillCounters(SessionStats &s) const
{
    addDecodeCounters(m_decoder.counters(), s);
    const uint64_t stamped = m_decoder.stampedSamples();
    if (stamped + m_decoder.unstampedSamples() > 0) {
        ClockStats k;
        k.source = "CAN";
        k.method = ClockStats::Method::Stamp;
        // Without the interface's stamps the samples have their arrival alone.
        k.state = stamped > 0 ? clock::ClockModel::State::Aligned : clock::ClockModel::State::FreeRunning;
        k.samples = stamped;
        s.clocks.push_back(std::move(k));
    }
}

// ---------------------------------------------------------------------------------------
// Jobs: each step one request of the engine

void CanFamily::submitJob(const CanJob &job)
{
    if (int(m_jobs.size()) >= kMaxQueuedJobs) {
        Q_EMIT jobFinished(
            CanRequestResult{job.id, false, 0, tr("too many requests are waiting; try again when they are done"),
                             RequestStatus::NotSent, {}, {}});
        return;
    }
    m_jobs.push_back(job);
    startJob();
}

void CanFamily::startJob()
{
    if (m_job || m_jobs.empty() || !engine().transport().isOpen())
        return;
    m_job = std::move(m_jobs.front());
    m_jobs.pop_front();
    m_step = 0;
    m_lastValue = 0;
    m_answers.clear();
    m_values.clear();
    if (m_job->steps.empty()) {
        finishJob(true, QString());
        return;
    }
    submitStep(false);
}

void CanFamily::submitStep(bool first)
{
    const CanJobStep &s = m_job->steps[m_step];
    Request r;
    r.command = Step{m_job->id, s};
    r.timeoutMs = s.expect == CanJobStep::Expect::Nothing ? std::max(0, s.pauseMs) : s.timeoutMs;
    r.maxAttempts = 1;
    r.done = [this, job = m_job->id](const RequestResult &res) {
        if (m_job && m_job->id == job && res.status != RequestStatus::Cancelled)
            stepEnded(res);
    };
    engine().submit(std::move(r), first);
}

QString CanFamily::prepare(Request &r)
{
    const Step &s = *std::any_cast<Step>(&r.command);
    r.wire = s.step.hasTx ? toRecord(s.step.tx) : QByteArray();
    return {};
}

void CanFamily::writing(const Request &r)
{
    const CanJobStep &s = std::any_cast<Step>(&r.command)->step;
    if (s.hasTx) // on the monitor as sent (a write that then fails ends the step at once)
        Q_EMIT framesSeen(CanFrameEvents{CanFrameEvent{s.tx, hostNowNs(), true}});
}

void CanFamily::unanswered(const Request &r, RequestResult &result)
{
    const CanJobStep &s = std::any_cast<Step>(&r.command)->step;
    const auto reg = s.expect == CanJobStep::Expect::J1939Reply ? j1939::parseReg(s.tx) : std::nullopt;
    if (result.status == RequestStatus::Timeout && reg && reg->da == j1939::kBroadcast) {
        // A broadcast request ends with its timeout: the answers that came are its result.
        if (!m_answers.isEmpty()) {
            result.status = RequestStatus::Ok;
            result.message.clear();
            result.reply = m_answers.front().value;
            return;
        }
        result.message = tr("no node answered \"%1\" to every node (address 255) within %2 ms: check the bit rate and "
                            "the wiring")
                             .arg(s.what)
                             .arg(s.timeoutMs);
        return;
    }
    if (result.status == RequestStatus::Timeout && s.expect == CanJobStep::Expect::NoPdoFrom
        && !m_dataNodes.contains(m_decoder.node())) {
        result.message = tr("node %1 sent no data before \"%2\" either, so its effect cannot be seen: check the node ID")
                             .arg(m_decoder.node())
                             .arg(s.what);
        return;
    }
    if (result.status == RequestStatus::Timeout
        && (s.expect == CanJobStep::Expect::Nothing || s.expect == CanJobStep::Expect::NoPdoFrom
            || s.expect == CanJobStep::Expect::DataSeen)) {
        result.status = RequestStatus::Ok; // the pause is over; no data came
        result.message.clear();
        result.reply = m_lastValue;
        return;
    }
    if (result.status == RequestStatus::Timeout && s.expect == CanJobStep::Expect::PgnFrom) {
        result.message = tr("no answer within %1 ms: node %2 sent no PGN %3 after \"%4\" (a PGN its firmware or "
                            "configuration does not send, or output off)")
                             .arg(s.timeoutMs)
                             .arg(m_decoder.node())
                             .arg(QString::number(s.pgn, 16).toUpper())
                             .arg(s.what);
    } else if (result.status == RequestStatus::Timeout && s.expect == CanJobStep::Expect::PdoFrom) {
        result.message = tr("node %1 sent no data within %2 ms of \"%3\": if its TPDOs wait for SYNC, send one; "
                            "otherwise check the node ID, its output intervals and that the module is powered")
                             .arg(m_decoder.node())
                             .arg(s.timeoutMs)
                             .arg(s.what);
    } else if (result.status == RequestStatus::Timeout) {
        const int node = s.expect == CanJobStep::Expect::TrafficFrom ? s.node : m_decoder.node();
        result.message = tr("no answer from node %1 to \"%2\" within %3 ms: check the node ID, the bit rate and the "
                            "wiring")
                             .arg(node)
                             .arg(s.what)
                             .arg(s.timeoutMs);
    } else if (result.status == RequestStatus::NotSent) {
        result.message = tr("could not send \"%1\": the CAN interface is not connected").arg(s.what);
    }
    result.reply = m_lastValue;
}

bool CanFamily::matchStep(const CanFrame &f, const DecodedFrame &d)
{
    const Request *current = engine().current();
    if (!current || !m_job)
        return false;
    const Step *step = std::any_cast<Step>(&current->command);
    if (!step || step->job != m_job->id)
        return false;
    const CanJobStep &s = step->step;
    const auto answer = [this](bool ok, uint32_t value, const QString &message) {
        RequestResult r;
        r.status = ok ? RequestStatus::Ok : RequestStatus::Refused;
        r.message = message;
        r.reply = value;
        engine().finishCurrent(std::move(r));
    };
    switch (s.expect) {
    case CanJobStep::Expect::Nothing: return false;
    case CanJobStep::Expect::J1939Reply: {
        const auto rep = j1939::parseReg(f);
        const auto req = j1939::parseReg(s.tx);
        if (!rep || !req || !j1939::answers(*rep, *req))
            return false;
        if (req->da == j1939::kBroadcast) {
            // Every node answers a request to 255: each answer is kept until the step's timeout.
            m_answers.append(CanNodeAnswer{rep->sa, rep->status == 0, rep->value, rep->status});
            return true;
        }
        if (rep->status != 0)
            answer(false, rep->value, tr("the device refused \"%1\" (status %2)").arg(s.what).arg(rep->status));
        else
            answer(true, rep->value, QString());
        return true;
    }
    case CanJobStep::Expect::SdoReply: {
        const auto rep = canopen::parseSdo(f);
        const auto req = canopen::parseSdo(s.tx);
        if (!rep || !req || !canopen::sdoAnswers(*rep, *req))
            return false;
        if (rep->kind == canopen::SdoKind::Abort)
            answer(false, rep->value, tr("the device aborted \"%1\": %2").arg(s.what, canopen::abortText(rep->value)));
        else
            answer(true, rep->value, QString());
        return true;
    }
    case CanJobStep::Expect::Hec495Reply: {
        const auto req = hec495::parseWrite(s.tx);
        if (const auto rep = hec495::parseWrite(f); rep && req && rep->reply && rep->extended == req->extended
            && rep->index == req->index && rep->node == req->node) {
            answer(true, req->value, QString());
            return true;
        }
        if (const auto ab = canopen::parseSdo(f); ab && req && ab->fromDevice && ab->kind == canopen::SdoKind::Abort
            && ab->node == req->node && ab->index == req->index) {
            answer(false, ab->value, tr("the device refused \"%1\": %2").arg(s.what, canopen::abortText(ab->value)));
            return true;
        }
        return false;
    }
    case CanJobStep::Expect::PgnFrom:
        // The frame the trigger asked for, from the module it was sent to (7.23: the request has
        // no reply; the data frame is the answer).
        if (f.extended && j1939::parseId(f.id).pgn() == s.pgn && d.node == m_decoder.node())
            answer(true, s.pgn, QString());
        return false; // the frame still counts as data
    case CanJobStep::Expect::TrafficFrom:
        if (d.node == s.node && d.kind != FrameKind::Unknown && d.kind != FrameKind::Nmt)
            answer(true, uint32_t(s.node), QString());
        return false; // the frame still counts as data
    case CanJobStep::Expect::PdoFrom:  // the timeouts differ (unanswered): here the same
    case CanJobStep::Expect::DataSeen:
        if (isDataFrame(d) && dataSource(d) == m_decoder.node())
            answer(true, 1, QString());
        return false;
    case CanJobStep::Expect::NoPdoFrom:
        if (isDataFrame(d) && dataSource(d) == m_decoder.node())
            answer(false, 1, tr("node %1 still sends data after \"%2\": check the node ID").arg(m_decoder.node()).arg(s.what));
        return false;
    }
    return false;
}

int CanFamily::dataSource(const DecodedFrame &d) const
{
    // The HEC495's extended variant names no node in its data frames: on that bus they are the
    // target's (the session talks to one such module).
    return m_options.hec495Extended && d.kind == FrameKind::Hec495Data ? m_decoder.node() : d.node;
}

void CanFamily::stepEnded(const RequestResult &r)
{
    const CanJobStep &s = m_job->steps[m_step];
    if (!r.ok() && s.optional) {
        qCInfo(lcCan) << "optional step not answered:" << r.message;
        if (const auto adapt = s.adapt)
            adapt(std::nullopt, *m_job, m_step);
        if (++m_step >= m_job->steps.size()) {
            finishJob(true, tr("%1: done").arg(m_job->title));
            return;
        }
        submitStep(true);
        return;
    }
    if (!r.ok()) {
        finishJob(false, r.message, r.status);
        return;
    }
    const uint32_t value = r.reply.toUInt();
    m_lastValue = value;
    if (s.expect == CanJobStep::Expect::J1939Reply || s.expect == CanJobStep::Expect::SdoReply)
        m_values.append(value);
    if (s.expectValue && *s.expectValue != value) {
        finishJob(false, tr("\"%1\" read back %2, expected %3").arg(s.what).arg(value).arg(*s.expectValue),
                  RequestStatus::Invalid);
        return;
    }
    if (s.followNode >= 0 && s.followNode != m_decoder.node())
        follow(s.followNode);
    // An HEC495 PDO mode the module took (0x1080 on standard frames): the decoder reads its
    // PDOs in that format from now on instead of guessing float or fixed point per frame.
    const auto written = s.expect == CanJobStep::Expect::Hec495Reply ? hec495::parseWrite(s.tx) : std::nullopt;
    if (written && !written->extended && written->index == hec495::ObjPdoMode) {
        m_options.hec495Mode = int(written->value); // kept for a reopen: the module saves it at once
        m_decoder.decoder().setHec495Mode(m_options.hec495Mode);
    }
    if (const auto adapt = s.adapt)
        adapt(value, *m_job, m_step);
    if (++m_step >= m_job->steps.size()) {
        finishJob(true, tr("%1: done").arg(m_job->title));
        return;
    }
    submitStep(true);
}

void CanFamily::finishJob(bool ok, const QString &message, RequestStatus status)
{
    if (!m_job)
        return;
    CanRequestResult r{m_job->id, ok, m_lastValue, ok ? message : tr("%1 failed: %2").arg(m_job->title, message),
                       ok ? RequestStatus::Ok : status, {}, {}};
    r.answers = m_answers;
    r.values = m_values;
    std::sort(r.answers.begin(), r.answers.end(), [](const CanNodeAnswer &a, const CanNodeAnswer &b) { return a.node < b.node; });
    m_job.reset();
    if (!ok)
        qCInfo(lcCan) << r.message;
    Q_EMIT jobFinished(r);
    QMetaObject::invokeMethod(this, &CanFamily::startJob, Qt::QueuedConnection);
}

// ---------------------------------------------------------------------------------------
// SDO scan

void CanFamily::scan(int from, int to)
{
    if (m_scanning)
        cancelScan();
    m_scanFrom = std::clamp(from, 1, 127);
    m_scanTo = std::clamp(to, m_scanFrom, 127);
    m_scanNext = m_scanFrom;
    m_scanFound.clear();
    m_scanTailUntil = 0;
    m_scanning = true;
    m_scanTimer.start();
}

void CanFamily::scanTick()
{
    if (!m_scanning)
        return;
    const int total = m_scanTo - m_scanFrom + 1;
    if (m_scanNext <= m_scanTo) {
        write(canopen::sdoRead(uint8_t(m_scanNext), 0x1000, 0));
        ++m_scanNext;
        Q_EMIT scanProgress(m_scanNext - m_scanFrom, total);
        if (m_scanNext > m_scanTo)
            m_scanTailUntil = hostNowNs() + qint64(kScanTailMs) * 1000000;
        return;
    }
    if (hostNowNs() < m_scanTailUntil)
        return;
    m_scanTimer.stop();
    m_scanning = false;
    std::sort(m_scanFound.begin(), m_scanFound.end());
    Q_EMIT scanFinished(m_scanFound, false);
}

void CanFamily::cancelScan()
{
    if (!m_scanning)
        return;
    m_scanTimer.stop();
    m_scanning = false;
    std::sort(m_scanFound.begin(), m_scanFound.end());
    Q_EMIT scanFinished(m_scanFound, true);
}

} // namespace imudesk::device
