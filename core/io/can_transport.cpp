#include "can_transport.h"

#include "clock/host_clock.h"
#include "protocol/can/can_record.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QCoreApplication>
#include <QVariant>

#include <chrono>
#include <utility>
#include <vector>

namespace imudesk::io {

namespace can = protocol::can;

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

} // namespace

CanAddress CanAddress::parse(const QString &address)
{
    const qsizetype colon = address.indexOf(QLatin1Char(':'));
    if (colon <= 0)
        return {address, QString()};
    return {address.left(colon), address.mid(colon + 1)};
}

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

CanTransport::CanTransport(QObject *parent) : Transport(parent) {}

CanTransport::~CanTransport()
{
    close();
}

bool CanTransport::open(const QString &address, int bitrate, QString *error)
{
    close();
    m_address = address;
    m_bitrate = bitrate;
    const CanAddress parsed = CanAddress::parse(address);
    const QString &plugin = parsed.plugin;
    const QString &interfaceName = parsed.interfaceName;
    const auto fail = [error](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    if (!QCanBus::instance()->plugins().contains(plugin))
        return fail(tr("the CAN plugin \"%1\" is not installed (available: %2)")
                        .arg(plugin, QCanBus::instance()->plugins().join(QStringLiteral(", "))));
    QString why;
    m_bus.reset(QCanBus::instance()->createDevice(plugin, interfaceName, &why));
    if (!m_bus)
        return fail(tr("cannot create CAN interface %1: %2").arg(address, why));
    if (bitrate > 0)
        m_bus->setConfigurationParameter(QCanBusDevice::BitRateKey, bitrate);
    if (m_fd) {
        m_bus->setConfigurationParameter(QCanBusDevice::CanFdKey, true);
        if (m_dataBitrate > 0)
            m_bus->setConfigurationParameter(QCanBusDevice::DataBitRateKey, m_dataBitrate);
    }
    connect(m_bus.get(), &QCanBusDevice::framesReceived, this, &CanTransport::onFramesReceived);
    connect(m_bus.get(), &QCanBusDevice::errorOccurred, this, [this](QCanBusDevice::CanBusError e) {
        if (m_bus && e != QCanBusDevice::NoError)
            Q_EMIT notice(tr("CAN interface error: %1").arg(m_bus->errorString()));
    });
    connect(m_bus.get(), &QCanBusDevice::stateChanged, this, [this](QCanBusDevice::CanBusDeviceState s) {
        if (s == QCanBusDevice::ConnectedState)
            sendBacklog();
        if (s == QCanBusDevice::UnconnectedState && m_bus)
            Q_EMIT failed(tr("the CAN interface %1 closed; received data is kept").arg(m_address));
    });
    if (!m_bus->connectDevice()) {
        why = m_bus->errorString();
        m_bus->disconnect(this);
        m_bus.reset();
        return fail(tr("cannot open CAN interface %1: %2 (check the interface name, that it is up, and your "
                       "permissions)")
                        .arg(address, why));
    }
    return true;
}

void CanTransport::close()
{
    if (!m_bus)
        return;
    auto bus = std::move(m_bus);
    m_backlog.clear();
    bus->disconnect(this);
    if (bus->state() != QCanBusDevice::UnconnectedState)
        bus->disconnectDevice();
}

bool CanTransport::isOpen() const
{
    return m_bus
        && (m_bus->state() == QCanBusDevice::ConnectedState || m_bus->state() == QCanBusDevice::ConnectingState);
}

qint64 CanTransport::write(const QByteArray &records)
{
    if (records.isEmpty())
        return 0;
    if (!isOpen())
        return -1;
    if (m_bus->state() == QCanBusDevice::ConnectingState) {
        if (m_backlog.size() + records.size() > kBacklogBytes)
            return -1;
        m_backlog.append(records);
        return records.size();
    }
    can::CanRecordReader reader;
    std::vector<can::CanRecord> frames;
    reader.feed(records, frames);
    for (const auto &r : frames)
        if (!m_bus->writeFrame(can::toQt(r.frame)))
            return -1;
    return records.size();
}

void CanTransport::sendBacklog()
{
    const QByteArray backlog = std::exchange(m_backlog, QByteArray());
    if (!backlog.isEmpty() && write(backlog) != backlog.size())
        Q_EMIT notice(tr("frames written while the CAN interface %1 was connecting could not be sent").arg(m_address));
}

void CanTransport::onFramesReceived()
{
    QByteArray out;
    // The interface's stamp (SocketCAN: the kernel's, taken when the frame came in) is on the
    // wall clock; the sessions' clock is the steady one: one offset, taken now, carries it over.
    const int64_t wallToHost = clock::hostNowNs()
        - std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
    while (m_bus && m_bus->framesAvailable()) {
        const QCanBusFrame q = m_bus->readFrame();
        const QCanBusFrame::TimeStamp t = q.timeStamp();
        const int64_t wallNs = t.seconds() * 1'000'000'000 + t.microSeconds() * 1000;
        out.append(can::toRecord(can::fromQt(q), q.frameType() == QCanBusFrame::ErrorFrame,
                                 wallNs > 0 ? wallNs + wallToHost : 0));
    }
    if (!out.isEmpty())
        Q_EMIT bytesReceived(out);
}

} // namespace imudesk::io
