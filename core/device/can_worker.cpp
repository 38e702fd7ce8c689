#include "can_worker.h"

#include "protocol/can/canopen.h"
#include "protocol/can/hec495_can.h"
#include "protocol/can/j1939_config.h"
#include "protocol/can/sdo.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QCoreApplication>
#include <QLoggingCategory>
#include <QThread>
#include <QVariant>

Q_LOGGING_CATEGORY(lcCan, "imudesk.core.device.can")

namespace imudesk::device {

using namespace protocol::can;

namespace {
QThread *g_canThread = nullptr;

void stopCanThread()
{
    if (!g_canThread)
        return;
    g_canThread->quit();
    g_canThread->wait();
    delete g_canThread;
    g_canThread = nullptr;
}

const char *kindName(FrameKind k)
{
    switch (k) {
    case FrameKind::J1939Data: return "J1939 data";
    case FrameKind::J1939Config: return "J1939 config";
    case FrameKind::TpdoData: return "TPDO";
    case FrameKind::Hec495Data: return "HEC495 PDO";
    case FrameKind::Sdo: return "SDO";
    case FrameKind::Hec495Sdo: return "HEC495 SDO";
    case FrameKind::Nmt: return "NMT";
    case FrameKind::Sync: return "SYNC";
    case FrameKind::Heartbeat: return "heartbeat";
    case FrameKind::Unknown: break;
    }
    return "other";
}

void merge(model::Sample &dst, const model::Sample &src, uint32_t c)
{
    if (c & CompAccX) dst.acc.x = src.acc.x;
    if (c & CompAccY) dst.acc.y = src.acc.y;
    if (c & CompAccZ) dst.acc.z = src.acc.z;
    if (c & CompGyrX) dst.gyr.x = src.gyr.x;
    if (c & CompGyrY) dst.gyr.y = src.gyr.y;
    if (c & CompGyrZ) dst.gyr.z = src.gyr.z;
    if (c & CompMagX) dst.mag.x = src.mag.x;
    if (c & CompMagY) dst.mag.y = src.mag.y;
    if (c & CompMagZ) dst.mag.z = src.mag.z;
    if (c & CompRoll) dst.roll = src.roll;
    if (c & CompPitch) dst.pitch = src.pitch;
    if (c & CompYaw) dst.yaw = src.yaw;
    if (c & CompQuat) dst.quat = src.quat;
    if (c & CompPressure) dst.pressurePa = src.pressurePa;
    if (c & CompTemperature) dst.temperatureC = src.temperatureC;
    if (c & CompInclination) {
        dst.inclinationX = src.inclinationX;
        dst.inclinationY = src.inclinationY;
    }
    if (c & CompDeviceTime) dst.deviceTimeMs = src.deviceTimeMs;
    if (c & CompMainStatus) dst.mainStatus = src.mainStatus;
    dst.fields |= src.fields;
    dst.source = src.source;
}
} // namespace

QThread *canThread()
{
    if (!g_canThread) {
        g_canThread = new QThread;
        g_canThread->setObjectName(QStringLiteral("imudesk-can"));
        g_canThread->start();
        qAddPostRoutine(stopCanThread);
    }
    return g_canThread;
}

CanWorker::CanWorker(SampleStore *store) : m_store(store)
{
    m_clock.start();
    m_stepTimer.setSingleShot(true);
    connect(&m_stepTimer, &QTimer::timeout, this, [this] {
        if (!m_job)
            return;
        const CanJobStep &s = m_job->steps[m_step];
        if (s.expect == CanJobStep::Expect::Nothing) {
            stepDone(true, m_lastValue, QString());
            return;
        }
        const int node = s.expect == CanJobStep::Expect::TrafficFrom ? s.node : m_target;
        finishJob(false, tr("no answer from node %1 to \"%2\" within %3 ms: check the node ID, the bit rate and the wiring")
                             .arg(node).arg(s.what).arg(s.timeoutMs));
    });
    m_syncTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_syncTimer, &QTimer::timeout, this, [this] { write(canopen::encodeSync()); });
    m_statsTimer.setInterval(500);
    connect(&m_statsTimer, &QTimer::timeout, this, &CanWorker::emitStats);
    m_scanTimer.setInterval(kScanSpacingMs);
    connect(&m_scanTimer, &QTimer::timeout, this, &CanWorker::scanTick);
}

CanWorker::~CanWorker()
{
    close();
}

qint64 CanWorker::nowNs() const
{
    return m_clock.nsecsElapsed();
}

void CanWorker::open(const CanSessionOptions &options)
{
    close();
    m_options = options;
    m_decoder = CanDecoder(options.protocol);
    m_decoder.setHec495Mode(options.hec495Mode);
    m_lastDetected = CanProtocol::Auto;
    m_target = options.node;
    m_merged = model::Sample{};
    m_stats = SessionStats{};
    m_stats.baud = options.bitrate;
    m_seenNodes.clear();
    Q_EMIT stateChanged(SessionState::Opening, tr("opening %1:%2").arg(options.plugin, options.interfaceName));
    QString err;
    if (!QCanBus::instance()->plugins().contains(options.plugin)) {
        Q_EMIT stateChanged(SessionState::Failed, tr("the CAN plugin \"%1\" is not installed (available: %2)")
                                                       .arg(options.plugin, QCanBus::instance()->plugins().join(QStringLiteral(", "))));
        return;
    }
    m_bus.reset(QCanBus::instance()->createDevice(options.plugin, options.interfaceName, &err));
    if (!m_bus) {
        Q_EMIT stateChanged(SessionState::Failed, tr("cannot create CAN interface %1:%2: %3").arg(options.plugin, options.interfaceName, err));
        return;
    }
    if (options.bitrate > 0)
        m_bus->setConfigurationParameter(QCanBusDevice::BitRateKey, options.bitrate);
    if (options.canFd) {
        m_bus->setConfigurationParameter(QCanBusDevice::CanFdKey, true);
        if (options.dataBitrate > 0)
            m_bus->setConfigurationParameter(QCanBusDevice::DataBitRateKey, options.dataBitrate);
    }
    connect(m_bus.get(), &QCanBusDevice::framesReceived, this, &CanWorker::onFramesReceived);
    connect(m_bus.get(), &QCanBusDevice::errorOccurred, this, [this](QCanBusDevice::CanBusError e) { onErrorOccurred(int(e)); });
    connect(m_bus.get(), &QCanBusDevice::stateChanged, this, [this](QCanBusDevice::CanBusDeviceState s) {
        if (s == QCanBusDevice::ConnectedState) {
            Q_EMIT stateChanged(SessionState::Connected, tr("connected to %1:%2").arg(m_options.plugin, m_options.interfaceName));
            m_statsTimer.start();
            startNextJob();
        } else if (s == QCanBusDevice::UnconnectedState && m_bus) {
            m_statsTimer.stop();
            Q_EMIT stateChanged(SessionState::Disconnected, tr("the CAN interface closed; received data is kept"));
        }
    });
    if (!m_bus->connectDevice()) {
        const QString why = m_bus->errorString();
        m_bus.reset();
        Q_EMIT stateChanged(SessionState::Failed, tr("cannot open CAN interface %1:%2: %3 (check the interface name, that it is up, "
                                                     "and your permissions)").arg(options.plugin, options.interfaceName, why));
        return;
    }
}

void CanWorker::close()
{
    m_syncTimer.stop();
    m_statsTimer.stop();
    m_stepTimer.stop();
    if (m_scanning)
        cancelScan();
    if (m_job)
        finishJob(false, tr("the session was closed"));
    while (!m_jobs.empty()) {
        const quint64 id = m_jobs.front().id;
        m_jobs.pop_front();
        Q_EMIT jobFinished(CanRequestResult{id, false, 0, tr("the session was closed")});
    }
    if (m_bus) {
        auto bus = std::move(m_bus);
        bus->disconnect(this);
        if (bus->state() != QCanBusDevice::UnconnectedState)
            bus->disconnectDevice();
        Q_EMIT stateChanged(SessionState::Closed, tr("closed"));
    }
}

void CanWorker::onErrorOccurred(int error)
{
    if (!m_bus || error == QCanBusDevice::NoError)
        return;
    Q_EMIT errorOccurred(tr("CAN interface error: %1").arg(m_bus->errorString()));
}

bool CanWorker::write(const CanFrame &f, CanFrameEvents *events)
{
    if (!m_bus || m_bus->state() != QCanBusDevice::ConnectedState)
        return false;
    if (!m_bus->writeFrame(toQt(f)))
        return false;
    const CanFrameEvent ev{f, nowNs(), true};
    if (events)
        events->append(ev);
    else
        Q_EMIT framesSeen(CanFrameEvents{ev});
    return true;
}

void CanWorker::sendFrame(const CanFrame &f)
{
    if (!write(f))
        Q_EMIT errorOccurred(tr("could not send frame %1: the CAN interface is not connected").arg(f.idText()));
}

void CanWorker::setSyncPeriod(int ms)
{
    if (ms <= 0) {
        m_syncTimer.stop();
        return;
    }
    m_syncTimer.start(ms);
}

void CanWorker::onFramesReceived()
{
    if (!m_bus)
        return;
    CanFrameEvents events;
    std::vector<model::Sample> batch;
    const qint64 now = nowNs();
    while (m_bus && m_bus->framesAvailable()) {
        const QCanBusFrame q = m_bus->readFrame();
        if (q.frameType() == QCanBusFrame::ErrorFrame) {
            ++m_stats.payloadErrors;
            continue;
        }
        const CanFrame f = fromQt(q);
        events.append(CanFrameEvent{f, now, false});
        handleFrame(f, now, batch);
    }
    if (!batch.empty())
        m_store->append(batch);
    if (!events.isEmpty())
        Q_EMIT framesSeen(events);
}

void CanWorker::handleFrame(const CanFrame &f, qint64 now, std::vector<model::Sample> &batch)
{
    ++m_stats.frames;
    m_stats.bytesIn += f.len;
    const DecodedFrame d = m_decoder.decode(f);
    ++m_stats.framesByType[kindName(d.kind)];
    if (m_decoder.detected() != m_lastDetected) {
        m_lastDetected = m_decoder.detected();
        Q_EMIT protocolDetected(int(m_lastDetected));
    }
    if (d.kind == FrameKind::Heartbeat && f.data[0] == canopen::StateBootUp)
        noteNode(d.protocol == CanProtocol::Auto ? CanProtocol::CanOpen : d.protocol, d.node, tr("boot-up"));
    else if (d.kind == FrameKind::Heartbeat)
        noteNode(m_decoder.detected() == CanProtocol::Hec495 ? CanProtocol::Hec495 : CanProtocol::CanOpen, d.node, tr("heartbeat"));
    else if (d.sample && d.node >= 0)
        noteNode(d.protocol, d.node, tr("data"));
    if (m_scanning && d.kind == FrameKind::Sdo && d.node >= m_scanFrom && d.node <= m_scanTo) {
        if (const auto s = canopen::parseSdo(f); s && s->fromDevice && !m_scanFound.contains(d.node)) {
            m_scanFound.append(d.node);
            noteNode(CanProtocol::CanOpen, d.node, tr("SDO scan"));
        }
    }
    if (m_job && matchStep(f, d))
        return;
    if (!d.sample)
        return;
    if (m_target < 0 && d.node >= 0) {
        m_target = d.node;
        Q_EMIT targetNodeChanged(m_target);
    }
    if (d.node >= 0 && d.node != m_target)
        return;
    merge(m_merged, *d.sample, d.components);
    model::Sample s = m_merged;
    s.hostTimeNs = now;
    batch.push_back(std::move(s));
}

void CanWorker::noteNode(CanProtocol p, int node, const QString &how)
{
    if (node < 0)
        return;
    const QString key = QStringLiteral("%1/%2").arg(int(p)).arg(node);
    if (m_seenNodes.contains(key) || m_seenNodes.size() > 1024)
        return;
    m_seenNodes.insert(key);
    Q_EMIT nodeDiscovered(CanNodeInfo{p, node, how});
}

void CanWorker::submit(const CanJob &job)
{
    if (int(m_jobs.size()) >= kMaxQueuedJobs) {
        Q_EMIT jobFinished(CanRequestResult{job.id, false, 0, tr("too many requests are waiting; try again when they are done")});
        return;
    }
    m_jobs.push_back(job);
    startNextJob();
}

void CanWorker::startNextJob()
{
    if (m_job || m_jobs.empty() || !m_bus || m_bus->state() != QCanBusDevice::ConnectedState)
        return;
    m_job = std::move(m_jobs.front());
    m_jobs.pop_front();
    m_step = 0;
    m_lastValue = 0;
    if (m_job->steps.empty()) {
        finishJob(true, QString());
        return;
    }
    startStep();
}

void CanWorker::startStep()
{
    const CanJobStep &s = m_job->steps[m_step];
    if (s.hasTx && !write(s.tx)) {
        finishJob(false, tr("could not send \"%1\": the CAN interface is not connected").arg(s.what));
        return;
    }
    m_stepTimer.start(s.expect == CanJobStep::Expect::Nothing ? s.pauseMs : s.timeoutMs);
}

bool CanWorker::matchStep(const CanFrame &f, const DecodedFrame &d)
{
    const CanJobStep &s = m_job->steps[m_step];
    switch (s.expect) {
    case CanJobStep::Expect::Nothing: return false;
    case CanJobStep::Expect::J1939Reply: {
        const auto rep = j1939::parseReg(f);
        const auto req = j1939::parseReg(s.tx);
        if (!rep || !req || !j1939::answers(*rep, *req))
            return false;
        if (rep->status != 0)
            stepDone(false, rep->value, tr("the device refused \"%1\" (status %2)").arg(s.what).arg(rep->status));
        else
            stepDone(true, rep->value, QString());
        return true;
    }
    case CanJobStep::Expect::SdoReply: {
        const auto rep = canopen::parseSdo(f);
        const auto req = canopen::parseSdo(s.tx);
        if (!rep || !req || !canopen::sdoAnswers(*rep, *req))
            return false;
        if (rep->kind == canopen::SdoKind::Abort)
            stepDone(false, rep->value, tr("the device aborted \"%1\": %2").arg(s.what, canopen::abortText(rep->value)));
        else
            stepDone(true, rep->value, QString());
        return true;
    }
    case CanJobStep::Expect::Hec495Reply: {
        const auto req = hec495::parseWrite(s.tx);
        if (const auto rep = hec495::parseWrite(f); rep && req && rep->reply && rep->extended == req->extended
            && rep->index == req->index && rep->node == req->node) {
            stepDone(true, req->value, QString());
            return true;
        }
        if (const auto ab = canopen::parseSdo(f); ab && req && ab->fromDevice && ab->kind == canopen::SdoKind::Abort
            && ab->node == req->node && ab->index == req->index) {
            stepDone(false, ab->value, tr("the device refused \"%1\": %2").arg(s.what, canopen::abortText(ab->value)));
            return true;
        }
        return false;
    }
    case CanJobStep::Expect::TrafficFrom:
        if (d.node == s.node && d.kind != FrameKind::Unknown && d.kind != FrameKind::Nmt) {
            stepDone(true, uint32_t(s.node), QString());
            return false; // the frame still counts as data
        }
        return false;
    }
    return false;
}

void CanWorker::stepDone(bool ok, uint32_t value, const QString &message)
{
    m_stepTimer.stop();
    if (!ok) {
        finishJob(false, message);
        return;
    }
    const CanJobStep &s = m_job->steps[m_step];
    m_lastValue = value;
    if (s.expectValue && *s.expectValue != value) {
        finishJob(false, tr("\"%1\" read back %2, expected %3").arg(s.what).arg(value).arg(*s.expectValue));
        return;
    }
    if (s.followNode >= 0 && s.followNode != m_target) {
        m_target = s.followNode;
        m_merged = model::Sample{};
        Q_EMIT targetNodeChanged(m_target);
    }
    if (++m_step >= m_job->steps.size()) {
        finishJob(true, tr("%1: done").arg(m_job->title));
        return;
    }
    startStep();
}

void CanWorker::finishJob(bool ok, const QString &message)
{
    if (!m_job)
        return;
    m_stepTimer.stop();
    const CanRequestResult r{m_job->id, ok, m_lastValue, ok ? message : tr("%1 failed: %2").arg(m_job->title, message)};
    m_job.reset();
    if (!ok)
        qCInfo(lcCan) << r.message;
    Q_EMIT jobFinished(r);
    QMetaObject::invokeMethod(this, &CanWorker::startNextJob, Qt::QueuedConnection);
}

void CanWorker::scan(int from, int to)
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

void CanWorker::scanTick()
{
    if (!m_scanning)
        return;
    const int total = m_scanTo - m_scanFrom + 1;
    if (m_scanNext <= m_scanTo) {
        write(canopen::sdoRead(uint8_t(m_scanNext), 0x1000, 0));
        ++m_scanNext;
        Q_EMIT scanProgress(m_scanNext - m_scanFrom, total);
        if (m_scanNext > m_scanTo)
            m_scanTailUntil = nowNs() + qint64(kScanTailMs) * 1000000;
        return;
    }
    if (nowNs() < m_scanTailUntil)
        return;
    m_scanTimer.stop();
    m_scanning = false;
    std::sort(m_scanFound.begin(), m_scanFound.end());
    Q_EMIT scanFinished(m_scanFound, false);
}

void CanWorker::cancelScan()
{
    if (!m_scanning)
        return;
    m_scanTimer.stop();
    m_scanning = false;
    std::sort(m_scanFound.begin(), m_scanFound.end());
    Q_EMIT scanFinished(m_scanFound, true);
}

void CanWorker::emitStats()
{
    const qint64 now = nowNs();
    const double dt = m_rateBaseNs ? double(now - m_rateBaseNs) * 1e-9 : 0;
    if (dt > 0) {
        for (const auto &[k, n] : m_stats.framesByType)
            m_stats.rateByType[k] = double(n - m_rateBase[k]) / dt;
        m_stats.bytesPerSecond = 0;
    }
    m_rateBase = m_stats.framesByType;
    m_rateBaseNs = now;
    m_stats.bytesSkipped = m_decoder.counters().unknownFrames;
    m_stats.lengthErrors = m_decoder.counters().malformed;
    Q_EMIT statsUpdated(m_stats);
}

} // namespace imudesk::device
