#include "modbus_worker.h"

#include "device/modbus_session.h"
#include "protocol/modbus/hipnuc_writes.h"
#include "protocol/modbus/identity_block.h"
#include "protocol/modbus/register_decoder.h"

#include <QLoggingCategory>
#include <QModbusReply>
#include <QModbusRtuSerialClient>
#include <QVariant>

#include <algorithm>
#include <chrono>
#include <cmath>

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
namespace reg = protocol::modbus::reg;

int64_t steadyNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::vector<uint16_t> toVector(const QList<quint16> &v)
{
    return std::vector<uint16_t>(v.begin(), v.end());
}

} // namespace

ModbusWorker::ModbusWorker(SampleStore &store, QObject *parent) : QObject(parent), m_store(store), m_pollTimer(this), m_statsTimer(this)
{
    m_pollTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_pollTimer, &QTimer::timeout, this, &ModbusWorker::onPollTick);
    m_statsTimer.setInterval(500);
    connect(&m_statsTimer, &QTimer::timeout, this, &ModbusWorker::publishStats);
}

ModbusWorker::~ModbusWorker()
{
    close();
}

void ModbusWorker::setState(SessionState s, const QString &detail)
{
    Q_EMIT stateChanged(s, detail);
}

bool ModbusWorker::connectClient(int baud, QString *error)
{
    if (m_client) {
        m_client->disconnectDevice();
        delete m_client;
    }
    m_client = new QModbusRtuSerialClient(this);
    m_client->setConnectionParameter(QModbusDevice::SerialPortNameParameter, m_options.port);
    m_client->setConnectionParameter(QModbusDevice::SerialBaudRateParameter, baud);
    m_client->setConnectionParameter(QModbusDevice::SerialDataBitsParameter, QSerialPort::Data8);
    m_client->setConnectionParameter(QModbusDevice::SerialParityParameter, m_options.parity);
    m_client->setConnectionParameter(QModbusDevice::SerialStopBitsParameter, m_options.stopBits);
    m_client->setTimeout(m_options.timeoutMs);
    m_client->setNumberOfRetries(m_scanning ? 0 : m_options.retries);
    connect(m_client, &QModbusDevice::errorOccurred, this, [this](QModbusDevice::Error e) {
        if (e == QModbusDevice::ConnectionError && m_open) {
            const QString msg = ModbusSession::tr("The serial port %1 failed (%2). Check that the adapter is plugged in, then "
                                                  "connect again.")
                                    .arg(m_options.port, m_client->errorString());
            Q_EMIT errorOccurred(msg);
            setState(SessionState::Disconnected, msg);
        }
    });
    if (!m_client->connectDevice()) {
        if (error)
            *error = ModbusSession::tr("Cannot open %1: %2. Check the port name and that no other program uses it.")
                         .arg(m_options.port, m_client->errorString());
        return false;
    }
    m_baud = baud;
    return true;
}

void ModbusWorker::open(const ModbusOptions &options)
{
    close();
    m_options = options;
    m_nodeId = options.effectiveNodeId();
    m_requestedHz = options.pollHz;
    m_clock.start();
    setState(SessionState::Opening, options.port);
    QString error;
    if (!connectClient(options.effectiveBaud(), &error)) {
        Q_EMIT errorOccurred(error);
        setState(SessionState::Failed, error);
        return;
    }
    m_open = true;
    qCInfo(lcModbus) << "opened" << m_options.port << "at" << m_baud << "baud, node" << m_nodeId;
    m_statsTimer.start();
    Q_EMIT baudChanged(m_baud);
    Q_EMIT nodeIdChanged(m_nodeId);
    if (!options.identify) {
        setState(SessionState::Connected, ModbusSession::tr("Port open at %1 baud").arg(m_baud));
        startPolling();
        return;
    }
    identify();
}

void ModbusWorker::close()
{
    ++m_generation;
    m_pollTimer.stop();
    m_statsTimer.stop();
    m_queue.clear();
    m_busy = false;
    m_pollQueued = false;
    if (m_scanning)
        finishScan(true);
    if (m_reply) {
        m_reply->disconnect(this);
        m_reply->deleteLater();
    }
    if (m_client) {
        m_client->disconnect(this);
        m_client->disconnectDevice();
        delete m_client;
        m_client = nullptr;
    }
    if (m_open) {
        m_open = false;
        setState(SessionState::Closed, QString());
    }
}

model::ManualEdition ModbusWorker::edition() const
{
    return m_identity.firmware ? m_identity.edition() : model::ManualEdition::V171;
}

int ModbusWorker::pollCount() const
{
    if (m_options.kind == DeviceKind::Hec495)
        return reg::kHecAngleCount;
    return m_options.shipMotion ? reg::kShipCount : reg::kSensorCount;
}

// ---- the request queue --------------------------------------------------------------------

void ModbusWorker::enqueue(Op op)
{
    m_queue.push_back(std::move(op));
    startNext();
}

void ModbusWorker::startNext()
{
    if (m_busy || m_queue.empty() || !m_client)
        return;
    m_current = std::move(m_queue.front());
    m_queue.pop_front();
    m_busy = true;
    m_client->setTimeout(m_current.timeoutMs);
    QModbusReply *reply = nullptr;
    if (m_current.write) {
        reply = m_client->sendWriteRequest(
            QModbusDataUnit(QModbusDataUnit::HoldingRegisters, m_current.start, QList<quint16>{quint16(m_current.value)}),
            m_current.nodeId);
        m_bytesOut += 8;
    } else {
        reply = m_client->sendReadRequest(
            QModbusDataUnit(QModbusDataUnit::HoldingRegisters, m_current.start, quint16(m_current.count)), m_current.nodeId);
        m_bytesOut += 8;
    }
    if (!reply) {
        Result r;
        r.error = QModbusDevice::ConnectionError;
        r.errorText = m_client->errorString();
        finishCurrent(r);
        return;
    }
    m_reply = reply;
    if (reply->isFinished()) {
        QMetaObject::invokeMethod(this, &ModbusWorker::onReplyFinished, Qt::QueuedConnection);
        return;
    }
    connect(reply, &QModbusReply::finished, this, &ModbusWorker::onReplyFinished);
}

void ModbusWorker::onReplyFinished()
{
    QModbusReply *reply = m_reply;
    if (!reply)
        return;
    m_reply = nullptr;
    Result r;
    r.error = reply->error();
    r.errorText = reply->errorString();
    for (QModbusDevice::IntermediateError e : reply->intermediateErrors())
        if (e == QModbusDevice::ResponseCrcError)
            ++m_crcErrors;
    const QModbusResponse raw = reply->rawResult();
    if (raw.isException())
        r.exception = int(raw.exceptionCode());
    if (r.ok())
        r.values = reply->result().values();
    reply->deleteLater();
    if (r.ok() || r.exception) {
        ++m_responses;
        m_bytesIn += uint64_t(r.exception ? 5 : (m_current.write ? 8 : 5 + 2 * r.values.size()));
    }
    if (r.exception)
        ++m_exceptions;
    if (r.error == QModbusDevice::TimeoutError)
        ++m_timeouts;
    finishCurrent(r);
}

void ModbusWorker::finishCurrent(const Result &r)
{
    Op op = std::move(m_current);
    m_current = Op{};
    m_busy = false;
    const quint64 gen = m_generation;
    if (op.done)
        op.done(r);
    if (gen == m_generation)
        startNext();
}

QString ModbusWorker::failureText(const Op &op, const Result &r) const
{
    const QString where = ModbusSession::tr("register 0x%1").arg(op.start, 4, 16, QLatin1Char('0'));
    if (r.exception)
        return ModbusSession::describeException(r.exception, where);
    if (r.error == QModbusDevice::TimeoutError)
        return ModbusSession::tr("No reply from node %1 at %2 baud within %3 ms. Check the node ID, the baud rate and parity, "
                                 "and the RS-485 wiring (A/B).")
            .arg(op.nodeId)
            .arg(m_baud)
            .arg(op.timeoutMs);
    return ModbusSession::tr("The request to node %1 failed: %2").arg(op.nodeId).arg(r.errorText);
}

// ---- identity and polling -----------------------------------------------------------------

void ModbusWorker::identify()
{
    setState(SessionState::Detecting, ModbusSession::tr("Reading the identity of node %1").arg(m_nodeId));
    Op op;
    op.nodeId = m_nodeId;
    op.timeoutMs = m_options.timeoutMs;
    if (m_options.kind == DeviceKind::Hec495) {
        op.start = reg::kHecAngles;
        op.count = reg::kHecAngleCount;
    } else {
        op.start = reg::kIdentityStart;
        op.count = reg::kIdentityCount;
    }
    op.done = [this, op](const Result &r) {
        if (!r.ok() && !r.exception) {
            const QString msg = failureText(op, r);
            Q_EMIT errorOccurred(msg);
            setState(SessionState::Failed, msg);
            return;
        }
        model::DeviceIdentity id;
        if (m_options.kind == DeviceKind::Hec495) {
            id.productName = "HEC495";
        } else if (r.ok()) {
            if (const auto block = IdentityBlock::decode(RegisterBlock(uint16_t(op.start), toVector(r.values))))
                id = block->toDeviceIdentity();
        }
        if (id.productName.empty())
            id.productName = ModbusSession::tr("Modbus node %1").arg(m_nodeId).toStdString();
        m_identity = id;
        Q_EMIT identityChanged(id);
        setState(SessionState::Connected, ModbusSession::tr("Node %1 at %2 baud").arg(m_nodeId).arg(m_baud));
        startPolling();
    };
    enqueue(std::move(op));
}

void ModbusWorker::setPollRate(double hz)
{
    m_requestedHz = hz;
    if (m_open && !m_scanning)
        startPolling();
}

void ModbusWorker::startPolling()
{
    const double limit = ModbusSession::maxPollRate(m_baud, pollCount(), m_options.parity);
    m_pollHz = std::clamp(m_requestedHz, 0.0, limit);
    Q_EMIT pollRateChanged(m_pollHz);
    if (m_pollHz <= 0 || !m_open) {
        m_pollTimer.stop();
        return;
    }
    m_pollTimer.setInterval(std::max(1, int(std::lround(1000.0 / m_pollHz))));
    m_pollTimer.start();
}

void ModbusWorker::onPollTick()
{
    if (m_pollQueued || m_scanning || !m_client)
        return;
    m_pollQueued = true;
    Op op;
    op.poll = true;
    op.nodeId = m_nodeId;
    op.start = m_options.kind == DeviceKind::Hec495 ? reg::kHecAngles : reg::kSensorStart;
    op.count = pollCount();
    op.timeoutMs = m_options.timeoutMs;
    op.done = [this](const Result &r) { onPollResult(r); };
    enqueue(std::move(op));
}

void ModbusWorker::onPollResult(const Result &r)
{
    m_pollQueued = false;
    if (!r.ok()) {
        ++m_pollTimeouts;
        if (++m_consecutiveTimeouts == kTimeoutsBeforeLost && !m_lost) {
            m_lost = true;
            Op op;
            op.nodeId = m_nodeId;
            op.start = m_options.kind == DeviceKind::Hec495 ? reg::kHecAngles : reg::kSensorStart;
            op.timeoutMs = m_options.timeoutMs;
            const QString msg = failureText(op, r);
            Q_EMIT errorOccurred(msg);
            setState(SessionState::Disconnected, msg);
        }
        return;
    }
    m_consecutiveTimeouts = 0;
    if (m_lost) {
        m_lost = false;
        setState(SessionState::Connected, ModbusSession::tr("Node %1 answers again").arg(m_nodeId));
    }
    const uint16_t start = m_options.kind == DeviceKind::Hec495 ? reg::kHecAngles : reg::kSensorStart;
    model::Sample s = RegisterDecoder::sample(m_options.kind, RegisterBlock(start, toVector(r.values)));
    s.hostTimeNs = steadyNs();
    s.deviceTimeMs = double(m_clock.elapsed());
    ++m_polls;
    m_store.append({s});
}

void ModbusWorker::publishStats()
{
    const qint64 now = m_clock.elapsed();
    const double dt = double(now - m_lastStatsMs) / 1000.0;
    if (dt > 0) {
        m_pollRateMeasured = double(m_polls - m_lastPolls) / dt;
        m_bytesPerSecond = double(m_bytesIn + m_bytesOut - m_lastBytes) / dt;
    }
    m_lastStatsMs = now;
    m_lastPolls = m_polls;
    m_lastBytes = m_bytesIn + m_bytesOut;
    SessionStats st;
    st.bytesIn = m_bytesIn;
    st.frames = m_responses;
    st.crcErrors = m_crcErrors;
    st.payloadErrors = m_exceptions;
    st.framesLost = m_pollTimeouts;
    st.framesLostByType[RegisterDecoder::sample(m_options.kind, {}).source] = m_pollTimeouts;
    const std::string type = RegisterDecoder::sample(m_options.kind, {}).source;
    st.framesByType[type] = m_polls;
    st.rateByType[type] = m_pollRateMeasured;
    st.bytesPerSecond = m_bytesPerSecond;
    const int bits = m_options.parity == QSerialPort::NoParity ? 10 : 11;
    st.linkLoad = m_baud > 0 ? m_bytesPerSecond * bits / m_baud : 0;
    st.baud = m_baud;
    Q_EMIT statsUpdated(st);
}

// ---- raw reads and verified writes ---------------------------------------------------------

void ModbusWorker::readRegisters(quint64 id, int start, int count)
{
    Op op;
    op.nodeId = m_nodeId;
    op.start = start;
    op.count = count;
    op.timeoutMs = m_options.timeoutMs;
    op.done = [this, id, op](const Result &r) {
        ModbusRegisterReply reply;
        reply.id = id;
        reply.start = op.start;
        reply.ok = r.ok();
        reply.values = r.values;
        reply.exceptionCode = r.exception;
        if (!r.ok())
            reply.message = failureText(op, r);
        Q_EMIT registersRead(reply);
    };
    if (!m_client || start < 0 || start > 0xFFFF || count < 1 || count > 125) {
        Result r;
        r.error = QModbusDevice::ProtocolError;
        r.errorText = !m_client ? ModbusSession::tr("not connected") : ModbusSession::tr("a read takes 1 to 125 registers");
        op.done(r);
        return;
    }
    enqueue(std::move(op));
}

void ModbusWorker::writeRegister(quint64 id, int address, int value, bool verify)
{
    ModbusRegisterReply reply;
    reply.id = id;
    reply.start = address;
    reply.values = {quint16(value)};
    const RegisterMap &map = RegisterMap::forDevice(m_options.kind, edition());
    const RegisterDef *def = (address >= 0 && address <= 0xFFFF) ? map.find(uint16_t(address)) : nullptr;
    if (!m_client || address < 0 || address > 0xFFFF || value < 0 || value > 0xFFFF
        || (def && !RegisterMap::accepts(*def, uint16_t(value)))) {
        reply.message = !m_client ? ModbusSession::tr("Not connected: connect first.")
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
    op.done = [this, reply, op, verify, readable](const Result &r) mutable {
        if (!r.ok()) {
            reply.exceptionCode = r.exception;
            reply.message = failureText(op, r);
            Q_EMIT writeFinished(reply);
            return;
        }
        const protocol::modbus::WriteRequest w{uint16_t(op.start), uint16_t(op.value)};
        if (m_options.kind == DeviceKind::Hipnuc && op.start == reg::kNodeId) {
            m_nodeId = op.value; // the module answers at the new ID at once
            Q_EMIT nodeIdChanged(m_nodeId);
        } else if (m_options.kind == DeviceKind::Hipnuc && op.start == reg::kBaud) {
            const int newBaud = HipnucWrites::baudForCode(uint16_t(op.value)).value_or(m_baud);
            m_busy = true; // hold the queue until the host has followed
            const quint64 gen = m_generation;
            QTimer::singleShot(kBaudSwitchDelayMs, this, [this, newBaud, gen] {
                if (gen != m_generation)
                    return;
                QString error;
                if (!connectClient(newBaud, &error)) {
                    Q_EMIT errorOccurred(error);
                    setState(SessionState::Failed, error);
                    return;
                }
                Q_EMIT baudChanged(newBaud);
                m_busy = false;
                startPolling();
                startNext();
            });
        } else if (m_options.kind == DeviceKind::Hipnuc && op.start == reg::kCtrl && op.value != 0) {
            m_pollTimer.stop();
            const quint64 gen = m_generation;
            QTimer::singleShot(kResetPauseMs, this, [this, gen] {
                if (gen == m_generation)
                    startPolling();
            });
        }
        reply.ok = true;
        reply.message = ModbusSession::tr("Done: %1.").arg(HipnucWrites::describe(w));
        if (!verify || !readable) {
            Q_EMIT writeFinished(reply);
            return;
        }
        Op check;
        check.nodeId = m_nodeId;
        check.start = op.start;
        check.count = 1;
        check.timeoutMs = m_options.timeoutMs;
        check.done = [this, reply, check, expected = op.value](const Result &rr) mutable {
            if (!rr.ok()) {
                reply.ok = false;
                reply.message = ModbusSession::tr("Written, but reading it back failed: %1").arg(failureText(check, rr));
            } else if (rr.values.value(0) != expected) {
                reply.ok = false;
                reply.message = ModbusSession::tr("Written, but the device reads back %1 instead of %2.")
                                    .arg(rr.values.value(0))
                                    .arg(expected);
            } else {
                reply.message += QLatin1Char(' ') + ModbusSession::tr("Read back: %1.").arg(expected);
            }
            Q_EMIT writeFinished(reply);
        };
        // After a baud change the read-back waits in the queue until the host has switched.
        m_queue.push_front(std::move(check));
    };
    enqueue(std::move(op));
}

// ---- scan ---------------------------------------------------------------------------------

int ModbusWorker::probeTimeoutMs(int baud) const
{
    if (m_scan.timeoutMs > 0)
        return m_scan.timeoutMs;
    // request (8) + a short reply (9) + gaps, twice over, plus the device's turnaround and the
    // host's scheduling (a busy machine easily adds tens of ms; a missed device costs more than time)
    const double frameMs = 25.0 * 11.0 * 1000.0 / std::max(1, baud);
    return int(std::ceil(2.0 * frameMs)) + 100;
}

void ModbusWorker::scan(const ModbusScanOptions &options)
{
    if (m_scanning || !m_client) {
        Q_EMIT scanFinished({}, true);
        return;
    }
    m_scan = options;
    m_scan.firstId = std::clamp(options.firstId, 1, 247);
    m_scan.lastId = std::clamp(options.lastId, m_scan.firstId, 247);
    m_scanBauds = options.bauds.isEmpty() ? QList<int>{m_baud} : options.bauds;
    m_scanBaudIndex = 0;
    m_scanId = m_scan.firstId;
    m_scanDone = 0;
    m_scanTotal = int(m_scanBauds.size()) * (m_scan.lastId - m_scan.firstId + 1);
    m_scanRestoreBaud = m_baud;
    m_hits.clear();
    m_scanCancel = false;
    m_scanning = true;
    m_pollTimer.stop();
    m_client->setNumberOfRetries(0);
    Q_EMIT scanProgress(0, m_scanTotal);
    scanNext();
}

void ModbusWorker::scanNext()
{
    if (!m_scanning)
        return;
    if (m_scanCancel) {
        finishScan(true);
        return;
    }
    if (m_scanId > m_scan.lastId) {
        ++m_scanBaudIndex;
        m_scanId = m_scan.firstId;
    }
    if (m_scanBaudIndex >= m_scanBauds.size()) {
        finishScan(false);
        return;
    }
    const int baud = m_scanBauds.at(m_scanBaudIndex);
    if (baud != m_baud) {
        QString error;
        if (!connectClient(baud, &error)) {
            Q_EMIT errorOccurred(error);
            finishScan(true);
            return;
        }
    }
    const int id = m_scanId++;
    Op probe;
    probe.nodeId = id;
    probe.start = reg::kHecAngles; // HiPNUC: UART1_BAUD, MD_ID; HEC495: pitch
    probe.count = 2;
    probe.timeoutMs = probeTimeoutMs(baud);
    probe.done = [this, id, baud](const Result &r) {
        auto advance = [this] {
            Q_EMIT scanProgress(++m_scanDone, m_scanTotal);
            QMetaObject::invokeMethod(this, &ModbusWorker::scanNext, Qt::QueuedConnection);
        };
        if (!r.ok() && !r.exception) {
            advance();
            return;
        }
        ModbusScanHit hit;
        hit.nodeId = id;
        hit.baud = baud;
        hit.exception = r.exception != 0;
        if (m_options.kind == DeviceKind::Hec495 || r.exception) {
            hit.summary = r.exception ? describeHitException(r.exception)
                                      : ModbusSession::tr("HEC495 compass (pitch %1 deg)")
                                            .arg(double(RegisterBlock(0, toVector(r.values)).f32le(0).value_or(0)), 0, 'f', 1);
            if (!r.exception)
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
        ident.done = [this, hit, advance](const Result &ri) mutable {
            if (ri.ok()) {
                if (const auto b = IdentityBlock::decode(RegisterBlock(reg::kIdentityStart, toVector(ri.values)))) {
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
        };
        enqueue(std::move(ident));
    };
    enqueue(std::move(probe));
}

QString ModbusWorker::describeHitException(int code)
{
    return ModbusSession::tr("answers with Modbus exception %1").arg(code);
}

void ModbusWorker::finishScan(bool cancelled)
{
    m_scanning = false;
    if (m_client && m_baud != m_scanRestoreBaud) {
        QString error;
        if (!connectClient(m_scanRestoreBaud, &error))
            Q_EMIT errorOccurred(error);
    }
    if (m_client)
        m_client->setNumberOfRetries(m_options.retries);
    Q_EMIT scanFinished(m_hits, cancelled);
    if (m_open && m_client)
        startPolling();
}

} // namespace imudesk::device
