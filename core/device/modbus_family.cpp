#include "modbus_family.h"

#include "clock/clock_model.h"
#include "clock/host_clock.h"
#include "device/modbus_session.h"
#include "device/session_engine.h"
#include "protocol/modbus/hipnuc_writes.h"
#include "protocol/modbus/identity_block.h"
#include "protocol/modbus/register_decoder.h"
#include "protocol/modbus/rtu_adu.h"

#include <QLoggingCategory>

#include <algorithm>
#include <cmath>
#include <utility>

namespace imudesk::device {

namespace {

Q_LOGGING_CATEGORY(lcModbus, "imudesk.core.device.modbus", QtInfoMsg)

using protocol::modbus::DeviceKind;
using protocol::modbus::HipnucWrites;
using protocol::modbus::IdentityBlock;
using protocol::modbus::RegisterBlock;
using protocol::modbus::RegisterDecoder;
using protocol::modbus::RegisterDef;
using protocol::modbus::RegisterMap;
using protocol::modbus::RtuAdu;
namespace reg = protocol::modbus::reg;

constexpr uint8_t kReadHolding = 0x03;
constexpr uint8_t kWriteSingle = 0x06;
constexpr uint8_t kExceptionBit = 0x80;
constexpr int kMaxAdu = 256;

const ModbusFamily::Op &opOf(const Request &r)
{
    return *std::any_cast<ModbusFamily::Op>(&r.command);
}

ModbusFamily::Reply replyOf(const RequestResult &r)
{
    return r.reply.value<ModbusFamily::Reply>();
}

std::vector<uint16_t> toVector(const QList<quint16> &v)
{
    return std::vector<uint16_t>(v.begin(), v.end());
}

} // namespace

ModbusFamily::ModbusFamily()
{
    qRegisterMetaType<Reply>();
    m_pollTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_pollTimer, &QTimer::timeout, this, &ModbusFamily::onPollTick);
    m_baudSwitch.setSingleShot(true);
    connect(&m_baudSwitch, &QTimer::timeout, this, [this] { followBaud(m_pendingBaud); });
    m_resume.setSingleShot(true);
    connect(&m_resume, &QTimer::timeout, this, &ModbusFamily::startPolling);
}

void ModbusFamily::configure(const ModbusOptions &options)
{
    m_options = options;
    m_frameType = RegisterDecoder::sample(options.kind, {}).source; // "MODBUS" or "HEC495"
    m_requestedHz = options.pollHz;
    engine().transport().setFraming(options.parity, options.stopBits);
}

QString ModbusFamily::linkKind() const
{
    return m_options.kind == DeviceKind::Hec495 ? QStringLiteral("HEC495 Modbus") : QStringLiteral("HiPNUC Modbus");
}

int ModbusFamily::firstBaud(int requestedBaud) const
{
    return requestedBaud > 0 ? requestedBaud : m_options.effectiveBaud();
}

model::ManualEdition ModbusFamily::edition() const
{
    return m_identity.firmware ? m_identity.edition() : model::ManualEdition::V171;
}

int ModbusFamily::pollCount() const
{
    if (m_options.kind == DeviceKind::Hec495)
        return reg::kHecAngleCount;
    return m_options.shipMotion ? reg::kShipCount : reg::kSensorCount;
}

int ModbusFamily::pollStart() const
{
    return m_options.kind == DeviceKind::Hec495 ? reg::kHecAngles : reg::kSensorStart;
}

// ---------------------------------------------------------------------------------------
// The link

void ModbusFamily::opened(int)
{
    m_nodeId = m_options.effectiveNodeId();
    m_identity = {};
    m_consecutiveTimeouts = 0;
    m_pollQueued = false;
    m_clock.start();
    m_lastTraffic.start();
    const int baud = engine().transport().baud();
    engine().setWorkingBaud(baud);
    qCInfo(lcModbus) << "opened" << m_options.port << "at" << baud << "baud, node" << m_nodeId;
    Q_EMIT baudChanged(baud);
    Q_EMIT nodeIdChanged(m_nodeId);
    if (!m_options.identify) {
        engine().setState(SessionState::Connected, ModbusSession::tr("Port open at %1 baud").arg(baud));
        startPolling();
        return;
    }
    identify();
}

void ModbusFamily::stopping()
{
    m_pollTimer.stop();
    m_baudSwitch.stop();
    m_resume.stop();
    m_pollQueued = false;
    if (m_scanning)
        finishScan(true, false);
}

void ModbusFamily::followBaud(int baud)
{
    if (!engine().transport().setBaud(baud)) {
        engine().fail(ModbusSession::tr("The serial port %1 cannot run at %2 baud. Connect again at the device's new "
                                        "rate.")
                          .arg(engine().transport().address())
                          .arg(baud));
        return;
    }
    engine().setWorkingBaud(baud);
    m_rx.clear();
    Q_EMIT baudChanged(baud);
    startPolling();
    engine().releaseHeldWrite();
}

// ---------------------------------------------------------------------------------------
// Requests on the line

Request ModbusFamily::makeRequest(const Op &op, int attempts, Done done) const
{
    Request r;
    r.command = op;
    r.timeoutMs = op.timeoutMs;
    r.maxAttempts = std::max(1, attempts);
    r.done = std::move(done);
    return r;
}

QString ModbusFamily::prepare(Request &r)
{
    const Op &op = opOf(r);
    if (op.nodeId < 0 || op.nodeId > 247)
        return ModbusSession::tr("a Modbus node ID is 0 to 247 (got %1)").arg(op.nodeId);
    r.wire = op.write ? RtuAdu::writeSingleRequest(uint8_t(op.nodeId), uint16_t(op.start), uint16_t(op.value))
                      : RtuAdu::readRequest(uint8_t(op.nodeId), uint16_t(op.start), uint16_t(op.count));
    return {};
}

int ModbusFamily::frameGapMs() const
{
    // 3.5 characters of 11 bits; above 19200 baud the standard fixes it at 1.75 ms.
    const int baud = std::max(1, engine().transport().baud());
    return baud > 19200 ? 2 : int(std::ceil(3.5 * 11.0 * 1000.0 / baud));
}

int ModbusFamily::holdWriteMs(const Request &) const
{
    if (m_baudSwitch.isActive()) // the read-back after a baud write goes out at the new rate
        return m_baudSwitch.remainingTime() + 100;
    const qint64 quiet = m_lastTraffic.isValid() ? m_lastTraffic.elapsed() : frameGapMs();
    return quiet >= frameGapMs() ? 0 : int(frameGapMs() - quiet);
}

void ModbusFamily::writing(const Request &r)
{
    m_rx.clear();
    // A write's reply is its request repeated: only a read's request can be told from its reply.
    m_echo = opOf(r).write ? QByteArray() : r.wire;
    m_lastTraffic.restart();
}

void ModbusFamily::unanswered(const Request &r, RequestResult &result)
{
    result.reply = QVariant::fromValue(Reply{});
    result.message = failureText(opOf(r), result);
}

QString ModbusFamily::failureText(const Op &op, const RequestResult &r) const
{
    const QString where = ModbusSession::tr("register 0x%1").arg(op.start, 4, 16, QLatin1Char('0'));
    const Reply reply = replyOf(r);
    if (reply.exception)
        return ModbusSession::describeException(reply.exception, where);
    if (r.status == RequestStatus::Timeout)
        return ModbusSession::tr("No reply from node %1 at %2 baud within %3 ms. Check the node ID, the baud rate and "
                                 "parity, and the RS-485 wiring (A/B).")
            .arg(op.nodeId)
            .arg(engine().transport().baud())
            .arg(op.timeoutMs);
    return ModbusSession::tr("The request to node %1 failed: %2").arg(op.nodeId).arg(r.message);
}

// ---------------------------------------------------------------------------------------
// Received bytes

void ModbusFamily::resetCounters()
{
    m_rx.clear();
    m_responses = m_exceptions = m_crcErrors = m_polls = m_pollTimeouts = 0;
    m_bytesIn = m_bytesSkipped = 0;
}

void ModbusFamily::feed(const QByteArray &bytes, int64_t)
{
    m_bytesIn += uint64_t(bytes.size());
    m_lastTraffic.restart();
    m_rx.append(bytes);
    parseReplies();
}

void ModbusFamily::lineIdle(int64_t)
{
    // The line went quiet in the middle of a reply: what came is not a frame.
    m_bytesSkipped += uint64_t(m_rx.size());
    ++m_crcErrors;
    m_rx.clear();
}

void ModbusFamily::parseReplies()
{
    while (!m_rx.isEmpty()) {
        const Request *current = engine().current();
        if (!current) { // nothing asked: a late reply, another master, noise
            // A scan between two probes: a whole reply still names an id that answered late.
            if (m_scanning) {
                const RtuAdu::Parsed p = RtuAdu::parseResponse(m_rx.left(kMaxAdu));
                if (p.error == RtuAdu::Error::Incomplete)
                    return;
                if (p.ok() && (p.functionCode & ~kExceptionBit) == kReadHolding)
                    noteLateAnswer(p.serverAddress);
            }
            m_bytesSkipped += uint64_t(m_rx.size());
            m_rx.clear();
            return;
        }
        if (!m_echo.isEmpty() && m_rx.startsWith(m_echo)) { // the request heard back on a 2-wire bus
            m_rx.remove(0, m_echo.size());
            m_echo.clear();
            continue;
        }
        if (m_echo.startsWith(m_rx))
            return; // maybe the start of the echo
        RtuAdu::Parsed p = RtuAdu::parseResponse(m_rx.left(kMaxAdu));
        if (p.error == RtuAdu::Error::TooLong && p.expectedSize > 0)
            p = RtuAdu::parseResponse(m_rx.left(p.expectedSize));
        if (p.error == RtuAdu::Error::Incomplete)
            return;
        if (!p.ok()) {
            if (p.error == RtuAdu::Error::CrcMismatch) {
                ++m_crcErrors;
                if (m_scanning && m_scanCurrentId > 0)
                    ++m_scanDamaged[m_scanCurrentId];
            }
            m_bytesSkipped += uint64_t(m_rx.size());
            m_rx.clear(); // the frame is damaged: the request times out and goes again
            return;
        }
        const int used = p.expectedSize; // a whole frame was parsed: the header said its size
        m_rx.remove(0, used);
        const Op &op = opOf(*current);
        const uint8_t expected = op.write ? kWriteSingle : kReadHolding;
        if (p.serverAddress != op.nodeId || (p.functionCode & ~kExceptionBit) != expected) {
            m_bytesSkipped += uint64_t(used); // another node's or another request's answer
            if (p.serverAddress != op.nodeId && (p.functionCode & ~kExceptionBit) == kReadHolding)
                noteLateAnswer(p.serverAddress);
            continue;
        }
        ++m_responses;
        RequestResult result;
        Reply reply;
        if (p.functionCode & kExceptionBit) {
            ++m_exceptions;
            reply.exception = p.data.isEmpty() ? 0 : uint8_t(p.data.at(0));
            result.status = RequestStatus::Refused;
        } else if (op.write) {
            reply.values = {quint16(op.value)};
            result.status = RequestStatus::Ok;
        } else if (const auto regs = RtuAdu::readRegisters(p.response()); regs && int(regs->size()) == op.count) {
            reply.values = QList<quint16>(regs->begin(), regs->end());
            result.status = RequestStatus::Ok;
        } else {
            result.status = RequestStatus::Invalid;
            result.message = ModbusSession::tr("the reply carries another number of registers than asked for");
        }
        result.reply = QVariant::fromValue(reply);
        engine().finishCurrent(std::move(result));
    }
}

void ModbusFamily::fillCounters(SessionStats &s) const
{
    const std::string &type = m_frameType;
    s.bytesIn = m_bytesIn;
    s.frames = m_responses;
    s.crcErrors = m_crcErrors;
    s.bytesSkipped = m_bytesSkipped;
    s.payloadErrors = m_exceptions;
    s.framesLost = m_pollTimeouts;
    s.framesLostByType[type] = m_pollTimeouts;
    s.framesByType[type] = m_polls;
    ClockStats::addBrackets(s.clocks, "Modbus", m_brackets);
}

// ---------------------------------------------------------------------------------------
// Identity and polling

void ModbusFamily::identify()
{
    engine().setState(SessionState::Detecting, ModbusSession::tr("Reading the identity of node %1").arg(m_nodeId));
    Op op;
    op.nodeId = m_nodeId;
    if (m_options.kind == DeviceKind::Hec495) {
        op.start = reg::kHecAngles;
        op.count = reg::kHecAngleCount;
    } else {
        op.start = reg::kIdentityStart;
        op.count = reg::kIdentityCount;
    }
    op.timeoutMs = m_options.timeoutMs;
    engine().submit(makeRequest(op, m_options.retries + 1, [this, op](const RequestResult &r) {
        if (r.status == RequestStatus::Cancelled)
            return;
        const Reply reply = replyOf(r);
        if (!r.ok() && !reply.exception) {
            engine().fail(failureText(op, r));
            return;
        }
        model::DeviceIdentity id;
        if (m_options.kind == DeviceKind::Hec495) {
            id.productName = "HEC495";
        } else if (r.ok()) {
            if (const auto block = IdentityBlock::decode(RegisterBlock(uint16_t(op.start), toVector(reply.values))))
                id = block->toDeviceIdentity();
        }
        if (id.productName.empty())
            id.productName = ModbusSession::tr("Modbus node %1").arg(m_nodeId).toStdString();
        id.busAddress = m_nodeId; // its name without a serial number (capture/device_name.h)
        m_identity = id;
        engine().setIdentity(id);
        engine().setState(SessionState::Connected,
                          ModbusSession::tr("Node %1 at %2 baud").arg(m_nodeId).arg(engine().transport().baud()));
        startPolling();
    }));
}

void ModbusFamily::setPollRate(double hz)
{
    m_requestedHz = hz;
    if (engine().transport().isOpen() && !m_scanning)
        startPolling();
}

void ModbusFamily::startPolling()
{
    const double limit = ModbusSession::maxPollRate(engine().transport().baud(), pollCount(), m_options.parity);
    m_pollHz = std::clamp(m_requestedHz, 0.0, limit);
    Q_EMIT pollRateChanged(m_pollHz);
    if (m_pollHz <= 0 || !engine().transport().isOpen()) {
        m_pollTimer.stop();
        return;
    }
    m_pollTimer.setInterval(std::max(1, int(std::lround(1000.0 / m_pollHz))));
    m_pollTimer.start();
}

void ModbusFamily::onPollTick()
{
    if (m_pollQueued || m_scanning || !engine().transport().isOpen())
        return;
    m_pollQueued = true;
    Op op;
    op.nodeId = m_nodeId;
    op.start = pollStart();
    op.count = pollCount();
    op.timeoutMs = m_options.timeoutMs;
    engine().submit(makeRequest(op, m_options.retries + 1,
                                [this](const RequestResult &r) { onPollResult(r); }));
}

void ModbusFamily::onPollResult(const RequestResult &r)
{
    m_pollQueued = false;
    if (r.status == RequestStatus::Cancelled)
        return;
    if (!r.ok()) {
        ++m_pollTimeouts;
        if (++m_consecutiveTimeouts == kTimeoutsBeforeLost) {
            Op op;
            op.nodeId = m_nodeId;
            op.start = pollStart();
            op.timeoutMs = m_options.timeoutMs;
            const QString msg = failureText(op, r);
            engine().reportError(msg);
            engine().setState(SessionState::Disconnected, msg);
        }
        return;
    }
    if (std::exchange(m_consecutiveTimeouts, 0) >= kTimeoutsBeforeLost) // it had been given up as lost
        engine().setState(SessionState::Connected, ModbusSession::tr("Node %1 answers again").arg(m_nodeId));
    model::Sample s =
        RegisterDecoder::sample(m_options.kind, RegisterBlock(uint16_t(pollStart()), toVector(replyOf(r).values)));
    s.hostTimeNs = hostNowNs();
    s.deviceTimeMs = double(m_clock.elapsed());
    // The registers were read between the request's send and the answer's arrival.
    if (r.sentNs > 0) {
        const clock::BracketTime b = clock::bracketTime(r.sentNs, s.hostTimeNs);
        s.commonTimeNs = b.hostNs;
        s.commonUncertaintyNs = b.uncertaintyNs;
        m_brackets.add(b);
    }
    ++m_polls;
    m_batch.clear();
    m_batch.push_back(std::move(s));
    engine().appendSamples(m_batch);
}

// ---------------------------------------------------------------------------------------
// Raw reads and verified writes

void ModbusFamily::readRegisters(quint64 id, int start, int count)
{
    Op op;
    op.nodeId = m_nodeId;
    op.start = start;
    op.count = count;
    op.timeoutMs = m_options.timeoutMs;
    auto done = [this, id, op](const RequestResult &r) {
        ModbusRegisterReply reply;
        reply.id = id;
        reply.start = op.start;
        reply.ok = r.ok();
        reply.values = replyOf(r).values;
        reply.exceptionCode = replyOf(r).exception;
        reply.status = r.status;
        if (!r.ok())
            reply.message = failureText(op, r);
        Q_EMIT registersRead(reply);
    };
    if (!engine().transport().isOpen() || start < 0 || start > 0xFFFF || count < 1 || count > 125) {
        RequestResult r;
        r.message = !engine().transport().isOpen() ? ModbusSession::tr("not connected")
                                                   : ModbusSession::tr("a read takes 1 to 125 registers");
        done(r);
        return;
    }
    engine().submit(makeRequest(op, m_options.retries + 1, std::move(done)));
}

void ModbusFamily::writeRegister(quint64 id, int address, int value, bool verify)
{
    ModbusRegisterReply reply;
    reply.id = id;
    reply.start = address;
    reply.values = {quint16(value)};
    const bool open = engine().transport().isOpen();
    const RegisterMap &map = RegisterMap::forDevice(m_options.kind, edition());
    const RegisterDef *def = (address >= 0 && address <= 0xFFFF) ? map.find(uint16_t(address)) : nullptr;
    if (!open || address < 0 || address > 0xFFFF || value < 0 || value > 0xFFFF
        || (def && !RegisterMap::accepts(*def, uint16_t(value)))) {
        reply.message = !open ? ModbusSession::tr("Not connected: connect first.")
            : def ? ModbusSession::tr("%1 is not a valid value for %2 (%3).")
                        .arg(value)
                        .arg(QLatin1String(def->name), RegisterMap::describe(*def))
                  : ModbusSession::tr("Register address and value must be 0..65535.");
        Q_EMIT writeFinished(reply);
        return;
    }
    Op op;
    op.write = true;
    op.nodeId = m_nodeId;
    op.start = address;
    op.value = value;
    op.timeoutMs = m_options.timeoutMs;
    const bool readable = def && def->readable();
    auto done = [this, reply, op, verify, readable](const RequestResult &r) mutable {
        if (!r.ok()) {
            reply.exceptionCode = replyOf(r).exception;
            reply.message = failureText(op, r);
            reply.status = r.status;
            Q_EMIT writeFinished(reply);
            return;
        }
        const protocol::modbus::WriteRequest w{uint16_t(op.start), uint16_t(op.value)};
        const bool hipnuc = m_options.kind == DeviceKind::Hipnuc;
        if (hipnuc && op.start == reg::kNodeId) {
            m_nodeId = op.value; // the module answers at the new ID at once
            Q_EMIT nodeIdChanged(m_nodeId);
        } else if (hipnuc && op.start == reg::kBaud) {
            // The reply came at the old rate; the module switches after it, the host follows.
            m_pendingBaud = HipnucWrites::baudForCode(uint16_t(op.value)).value_or(engine().transport().baud());
            m_pollTimer.stop();
            m_baudSwitch.start(kBaudSwitchDelayMs);
        } else if (hipnuc && op.start == reg::kCtrl && op.value != 0) {
            m_pollTimer.stop();
            m_resume.start(kResetPauseMs);
        }
        reply.ok = true;
        reply.status = RequestStatus::Ok;
        reply.message = ModbusSession::tr("Done: %1.").arg(HipnucWrites::describe(w));
        if (!verify || !readable) {
            Q_EMIT writeFinished(reply);
            return;
        }
        Op check;
        check.nodeId = m_nodeId;
        check.start = op.start;
        check.timeoutMs = m_options.timeoutMs;
        auto checked = [this, reply, check, expected = op.value](const RequestResult &rr) mutable {
            const QList<quint16> values = replyOf(rr).values;
            if (!rr.ok()) {
                reply.ok = false;
                reply.status = rr.status;
                reply.message =
                    ModbusSession::tr("Written, but reading it back failed: %1").arg(failureText(check, rr));
            } else if (values.value(0) != expected) {
                reply.ok = false;
                reply.status = RequestStatus::Invalid;
                reply.message = ModbusSession::tr("Written, but the device reads back %1 instead of %2.")
                                    .arg(values.value(0))
                                    .arg(expected);
            } else {
                reply.message += QLatin1Char(' ') + ModbusSession::tr("Read back: %1.").arg(expected);
            }
            Q_EMIT writeFinished(reply);
        };
        // Directly after the write; after a baud write it is held until the host has switched.
        engine().submit(makeRequest(check, m_options.retries + 1, std::move(checked)), true);
    };
    engine().submit(makeRequest(op, m_options.retries + 1, std::move(done)));
}

// ---------------------------------------------------------------------------------------
// Scan

int ModbusFamily::probeTimeoutMs(int baud) const
{
    if (m_scan.timeoutMs > 0)
        return m_scan.timeoutMs;
    // request (8) + a short reply (9) + gaps, twice over, plus the device's turnaround and the
    // host's scheduling (a busy machine easily adds tens of ms; a missed device costs more than time)
    const double frameMs = 25.0 * 11.0 * 1000.0 / std::max(1, baud);
    return int(std::ceil(2.0 * frameMs)) + 100;
}

void ModbusFamily::scan(const ModbusScanOptions &options)
{
    if (m_scanning || !engine().transport().isOpen()) {
        Q_EMIT scanFinished({}, true);
        return;
    }
    m_scan = options;
    m_scan.firstId = std::clamp(options.firstId, 1, 247);
    m_scan.lastId = std::clamp(options.lastId, m_scan.firstId, 247);
    m_scanRestoreBaud = engine().transport().baud();
    m_scanPlan = options.plan;
    if (m_scanPlan.isEmpty()) {
        const QList<int> bauds = options.bauds.isEmpty() ? QList<int>{m_scanRestoreBaud} : options.bauds;
        for (int baud : bauds)
            for (int id = m_scan.firstId; id <= m_scan.lastId; ++id)
                m_scanPlan.append({baud, id, 0});
    }
    m_scanAt = 0;
    m_scanRecheck.clear();
    m_scanAsked.clear();
    m_scanDamaged.clear();
    m_scanHitBaud = 0;
    m_scanCurrentId = -1;
    m_scanDone = 0;
    m_scanTotal = int(m_scanPlan.size());
    m_hits.clear();
    m_scanCancel = false;
    m_scanning = true;
    m_pollTimer.stop();
    Q_EMIT scanProgress(0, m_scanTotal);
    scanNext();
}

void ModbusFamily::noteLateAnswer(int nodeId)
{
    // A valid reply from another id than the one asked: that id answered after its probe's
    // time (a slow device, a busy host). It is asked again, slowly, before the plan goes on.
    if (!m_scanning || nodeId == m_scanCurrentId || !m_scanAsked.contains(nodeId))
        return;
    for (const auto &hit : std::as_const(m_hits))
        if (hit.nodeId == nodeId)
            return;
    for (const auto &r : std::as_const(m_scanRecheck))
        if (r.id == nodeId)
            return;
    m_scanRecheck.append({engine().transport().baud(), nodeId, -1});
}

void ModbusFamily::scanNext()
{
    if (!m_scanning)
        return;
    if (m_scanCancel) {
        finishScan(true, true);
        return;
    }
    ModbusScanOptions::Probe next;
    bool recheck = false;
    if (!m_scanRecheck.isEmpty()) {
        next = m_scanRecheck.takeFirst();
        recheck = true;
    } else {
        while (m_scanAt < m_scanPlan.size() && m_scan.oneRate && m_scanHitBaud > 0
               && m_scanPlan.at(m_scanAt).baud != m_scanHitBaud) {
            ++m_scanAt; // the bus's rate is known: the others are skipped
            Q_EMIT scanProgress(++m_scanDone, m_scanTotal);
        }
        if (m_scanAt >= m_scanPlan.size()) {
            finishScan(false, true);
            return;
        }
        next = m_scanPlan.at(m_scanAt++);
    }
    const int baud = next.baud > 0 ? next.baud : engine().transport().baud();
    if (baud != engine().transport().baud()) {
        if (!engine().transport().setBaud(baud)) {
            engine().reportError(ModbusSession::tr("The serial port %1 cannot run at %2 baud.")
                                     .arg(engine().transport().address())
                                     .arg(baud));
            finishScan(true, true);
            return;
        }
        m_rx.clear();
        m_scanAsked.clear();
    }
    const int id = next.id;
    m_scanCurrentId = id;
    if (!m_scanAsked.contains(id))
        m_scanAsked.append(id);
    Op probe;
    probe.nodeId = id;
    probe.start = reg::kHecAngles; // HiPNUC: UART1_BAUD, MD_ID; HEC495: pitch
    probe.count = 2;
    // A recheck waits as long as a careful scan would, and twice that for a slow device.
    probe.timeoutMs = recheck ? 2 * probeTimeoutMs(baud) : next.timeoutMs > 0 ? next.timeoutMs : probeTimeoutMs(baud);
    auto advance = [this, recheck] {
        if (!recheck)
            Q_EMIT scanProgress(++m_scanDone, m_scanTotal);
        QMetaObject::invokeMethod(this, &ModbusFamily::scanNext, Qt::QueuedConnection);
    };
    engine().submit(makeRequest(probe, 1, [this, id, baud, advance](const RequestResult &r) {
        if (!m_scanning)
            return;
        const Reply reply = replyOf(r);
        if (!r.ok() && !reply.exception) {
            advance();
            return;
        }
        if (m_scanHitBaud == 0)
            m_scanHitBaud = baud;
        ModbusScanHit hit;
        hit.nodeId = id;
        hit.baud = baud;
        hit.damaged = m_scanDamaged.count(id) ? m_scanDamaged.at(id) : 0;
        hit.exception = reply.exception != 0;
        hit.probeValues = reply.values;
        if (m_options.kind == DeviceKind::Hec495 || reply.exception) {
            hit.summary = reply.exception
                ? ModbusSession::tr("answers with Modbus exception %1").arg(reply.exception)
                : ModbusSession::tr("HEC495 compass (pitch %1 deg)")
                      .arg(double(RegisterBlock(0, toVector(reply.values)).f32le(0).value_or(0)), 0, 'f', 1);
            if (!reply.exception)
                hit.identity.productName = "HEC495";
            m_hits.append(hit);
            Q_EMIT scanFound(hit);
            advance();
            return;
        }
        Op ident;
        ident.nodeId = id;
        ident.start = reg::kIdentityStart;
        ident.count = reg::kIdentityCount;
        ident.timeoutMs = probeTimeoutMs(baud) + 40;
        engine().submit(makeRequest(ident, 1, [this, hit, advance](const RequestResult &ri) mutable {
            if (!m_scanning)
                return;
            if (ri.ok()) {
                const auto b = IdentityBlock::decode(RegisterBlock(reg::kIdentityStart, toVector(replyOf(ri).values)));
                if (b) {
                    hit.identified = true;
                    hit.identity = b->toDeviceIdentity();
                    hit.summary = QStringLiteral("%1 %2 SN %3")
                                      .arg(QString::fromStdString(b->productName),
                                           QString::fromStdString(IdentityBlock::versionText(b->swVersion)),
                                           QString::fromStdString(b->serial));
                }
            }
            if (!hit.identified)
                hit.summary = ModbusSession::tr("answers, identity unreadable");
            m_hits.append(hit);
            Q_EMIT scanFound(hit);
            advance();
        }), true);
    }));
}

void ModbusFamily::finishScan(bool cancelled, bool linkStaysOpen)
{
    m_scanning = false;
    if (linkStaysOpen && engine().transport().isOpen() && engine().transport().baud() != m_scanRestoreBaud) {
        if (!engine().transport().setBaud(m_scanRestoreBaud))
            engine().reportError(ModbusSession::tr("The serial port %1 cannot return to %2 baud.")
                                     .arg(engine().transport().address())
                                     .arg(m_scanRestoreBaud));
        m_rx.clear();
    }
    Q_EMIT scanFinished(m_hits, cancelled);
    if (linkStaysOpen && engine().transport().isOpen())
        startPolling();
}

} // namespace imudesk::device
