#include "can_simulator.h"

#include "clock/host_clock.h"
#include "io/can_transport.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QVariant>
#include <QEventLoop>
#include <QLoggingCategory>

#include <cstdio>

Q_LOGGING_CATEGORY(lcCanSim, "imudesk.core.sim.can", QtInfoMsg)

namespace imudesk::sim {

using protocol::can::CanFrame;

CanSimulator::CanSimulator(CanSimOptions options, QObject *parent) : QObject(parent), m_device(std::move(options))
{
    m_tick.setTimerType(Qt::PreciseTimer);
    m_tick.setInterval(kTickMs);
    connect(&m_tick, &QTimer::timeout, this, &CanSimulator::onTick);
    m_reconnect.setSingleShot(true);
    m_reconnect.setInterval(200);
    connect(&m_reconnect, &QTimer::timeout, this, [this] {
        if (m_bus && m_bus->state() == QCanBusDevice::UnconnectedState && !m_stopping)
            m_bus->connectDevice();
    });
}

CanSimulator::~CanSimulator()
{
    stop();
}

bool CanSimulator::start(const QString &plugin, const QString &interfaceName, QString *error)
{
    stop();
    m_stopping = false;
    QString err;
    m_bus.reset(QCanBus::instance()->createDevice(plugin, interfaceName, &err));
    if (!m_bus) {
        if (error)
            *error = tr("cannot create CAN device %1:%2: %3").arg(plugin, interfaceName, err);
        return false;
    }
    if (m_device.options().canFd)
        m_bus->setConfigurationParameter(QCanBusDevice::CanFdKey, true);
    m_bitrate = m_device.bitrate();
    m_bus->setConfigurationParameter(QCanBusDevice::BitRateKey, m_bitrate);
    connect(m_bus.get(), &QCanBusDevice::framesReceived, this, &CanSimulator::onFramesReceived);
    connect(m_bus.get(), &QCanBusDevice::stateChanged, this, [this](QCanBusDevice::CanBusDeviceState s) { onStateChanged(int(s)); });
    if (!m_bus->connectDevice()) {
        if (error)
            *error = tr("cannot open CAN device %1:%2: %3").arg(plugin, interfaceName, m_bus->errorString());
        m_bus.reset();
        return false;
    }
    m_clock.start();
    m_tick.start();
    qCInfo(lcCanSim) << "CAN simulator on" << plugin << interfaceName << "node" << m_device.node();
    return true;
}

void CanSimulator::stop()
{
    m_stopping = true;
    m_tick.stop();
    m_reconnect.stop();
    if (m_bus) {
        m_bus->disconnect(this);
        if (m_bus->state() != QCanBusDevice::UnconnectedState)
            m_bus->disconnectDevice();
        m_bus.reset();
    }
}

bool CanSimulator::isRunning() const
{
    return m_bus && m_bus->state() == QCanBusDevice::ConnectedState;
}

double CanSimulator::elapsedSeconds() const
{
    return m_clock.isValid() ? double(m_clock.nsecsElapsed()) * 1e-9 : 0.0;
}

void CanSimulator::powerCycle()
{
    m_device.powerCycle(elapsedSeconds());
    applyBitrate();
}

void CanSimulator::onStateChanged(int state)
{
    const bool connected = state == QCanBusDevice::ConnectedState;
    Q_EMIT connectedChanged(connected);
    if (state == QCanBusDevice::UnconnectedState && !m_stopping)
        m_reconnect.start();
}

void CanSimulator::onFramesReceived()
{
    if (!m_bus)
        return;
    const double t = elapsedSeconds();
    const int nodeBefore = m_device.node();
    while (m_bus && m_bus->framesAvailable()) {
        const QCanBusFrame q = m_bus->readFrame();
        if (q.frameType() != QCanBusFrame::DataFrame && q.frameType() != QCanBusFrame::RemoteRequestFrame)
            continue;
        ++m_received;
        send(m_device.handle(protocol::can::fromQt(q), t));
    }
    if (m_device.node() != nodeBefore)
        qCInfo(lcCanSim) << "node" << nodeBefore << "->" << m_device.node();
    applyBitrate();
}

void CanSimulator::onTick()
{
    send(m_device.poll(elapsedSeconds()));
}

void CanSimulator::send(const std::vector<CanFrame> &frames)
{
    if (!m_bus || m_bus->state() != QCanBusDevice::ConnectedState)
        return;
    for (const CanFrame &f : frames)
        if (m_bus->writeFrame(protocol::can::toQt(f))) {
            ++m_sent;
            if (m_sentObserver)
                m_sentObserver(f, clock::hostNowNs());
        }
}

void CanSimulator::applyBitrate()
{
    // After a reset with a new saved baud the module talks at the new rate: reopen the bus.
    if (!m_bus || m_device.bitrate() == m_bitrate)
        return;
    m_bitrate = m_device.bitrate();
    qCInfo(lcCanSim) << "bit rate now" << m_bitrate;
    if (m_bus->state() == QCanBusDevice::ConnectedState) {
        m_bus->setConfigurationParameter(QCanBusDevice::BitRateKey, m_bitrate);
    }
}

int runCanSimulatorCommand(const QString &canSpec, const QString &protocolText, const QString &deviceKind, int node,
                           Motion motion, uint64_t seed, const QString &firmware, bool canFd, QString *error,
                           const std::function<bool()> &stopRequested, const std::function<void(CanSimDevice &)> &atExit)
{
    const io::CanAddress address = io::CanAddress::parse(canSpec);
    if (!address.complete()) {
        *error = CanSimulator::tr("--can needs PLUGIN:INTERFACE, e.g. virtualcan:can0");
        return 2;
    }
    CanSimOptions o;
    const auto p = protocol::can::parseProtocol(protocolText);
    if (!p || (*p != protocol::can::CanProtocol::J1939 && *p != protocol::can::CanProtocol::CanOpen)) {
        *error = CanSimulator::tr("--protocol must be j1939 or canopen");
        return 2;
    }
    o.protocol = *p;
    const QString kind = deviceKind.toLower();
    if (kind != QLatin1String("hipnuc") && kind != QLatin1String("hec495")) {
        *error = CanSimulator::tr("--device must be hipnuc or hec495");
        return 2;
    }
    o.hec495 = kind == QLatin1String("hec495");
    if (node != -1 && (node < 1 || node > 127)) {
        *error = CanSimulator::tr("--node must be 1..127");
        return 2;
    }
    o.node = node;
    o.motion = motion;
    o.seed = seed;
    o.firmware = firmware.toStdString();
    o.canFd = canFd;
    CanSimulator sim(o);
    if (!sim.start(address.plugin, address.interfaceName, error))
        return 1;
    std::printf("can: %s node %d protocol %s%s%s\n", qPrintable(canSpec), sim.device().node(),
                qPrintable(protocolText.toLower()), o.hec495 ? " device hec495" : "", o.canFd ? " fd" : "");
    std::fflush(stdout);
    QEventLoop loop;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
        if (stopRequested())
            loop.quit();
    });
    poll.start(50);
    loop.exec();
    sim.stop();
    if (atExit)
        atExit(sim.device());
    return 0;
}

} // namespace imudesk::sim
