#include "qt_can_frame_link.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QEventLoop>
#include <QLoggingCategory>
#include <QTimer>
#include <QVariant>

namespace imudesk::firmware {

namespace {
Q_LOGGING_CATEGORY(lcCanLink, "imudesk.core.firmware.canlink", QtInfoMsg)
}

QtCanFrameLink::QtCanFrameLink(QString plugin, QString interfaceName, int bitrate)
    : m_plugin(std::move(plugin)), m_interface(std::move(interfaceName)), m_bitrate(bitrate)
{
    m_clock.start();
}

QtCanFrameLink::~QtCanFrameLink()
{
    close();
}

bool QtCanFrameLink::open(QString *error)
{
    close();
    if (!QCanBus::instance()->plugins().contains(m_plugin)) {
        *error = tr("the CAN plugin \"%1\" is not installed (available: %2)")
                     .arg(m_plugin, QCanBus::instance()->plugins().join(QStringLiteral(", ")));
        return false;
    }
    QString err;
    m_bus.reset(QCanBus::instance()->createDevice(m_plugin, m_interface, &err));
    if (!m_bus) {
        *error = tr("cannot create the CAN device %1:%2: %3").arg(m_plugin, m_interface, err);
        return false;
    }
    if (m_bitrate > 0)
        m_bus->setConfigurationParameter(QCanBusDevice::BitRateKey, m_bitrate);
    if (!m_bus->connectDevice()) {
        *error = tr("cannot open the CAN device %1:%2: %3. Check the interface name and that it is up")
                     .arg(m_plugin, m_interface, m_bus->errorString());
        m_bus.reset();
        return false;
    }
    QElapsedTimer t;
    t.start();
    while (m_bus->state() == QCanBusDevice::ConnectingState && t.elapsed() < kConnectTimeoutMs) {
        QEventLoop loop;
        QTimer::singleShot(10, &loop, &QEventLoop::quit);
        QObject::connect(m_bus.get(), &QCanBusDevice::stateChanged, &loop, &QEventLoop::quit);
        loop.exec();
    }
    if (m_bus->state() != QCanBusDevice::ConnectedState) {
        *error = tr("the CAN device %1:%2 did not connect within %3 ms: %4")
                     .arg(m_plugin, m_interface)
                     .arg(kConnectTimeoutMs)
                     .arg(m_bus->errorString());
        m_bus.reset();
        return false;
    }
    qCInfo(lcCanLink) << "opened" << m_plugin << m_interface << "bitrate" << m_bitrate;
    return true;
}

void QtCanFrameLink::close()
{
    if (!m_bus)
        return;
    if (m_bus->state() != QCanBusDevice::UnconnectedState)
        m_bus->disconnectDevice();
    m_bus.reset();
    m_queue.clear();
}

bool QtCanFrameLink::isOpen() const
{
    return m_bus && m_bus->state() == QCanBusDevice::ConnectedState;
}

bool QtCanFrameLink::connectedOrError(QString *error) const
{
    if (isOpen())
        return true;
    *error = tr("the CAN device %1:%2 is not connected (%3); check the cable and the adapter")
                 .arg(m_plugin, m_interface, m_bus ? m_bus->errorString() : tr("closed"));
    return false;
}

bool QtCanFrameLink::send(const protocol::can::CanFrame &frame, QString *error)
{
    if (!connectedOrError(error))
        return false;
    if (!m_bus->writeFrame(protocol::can::toQt(frame))) {
        *error = tr("sending a CAN frame failed: %1").arg(m_bus->errorString());
        return false;
    }
    return true;
}

void QtCanFrameLink::drain()
{
    while (m_bus && m_bus->framesAvailable()) {
        const QCanBusFrame q = m_bus->readFrame();
        if (q.frameType() != QCanBusFrame::DataFrame)
            continue;
        if (m_queue.size() >= kMaxQueued)
            m_queue.pop_front();
        m_queue.push_back(protocol::can::fromQt(q));
    }
}

bool QtCanFrameLink::receive(std::vector<protocol::can::CanFrame> &out, int timeoutMs, QString *error)
{
    if (!connectedOrError(error))
        return false;
    drain();
    if (m_queue.empty() && timeoutMs > 0) {
        QEventLoop loop;
        QTimer timer;
        timer.setSingleShot(true);
        QObject::connect(&timer, &QTimer::timeout, &loop, &QEventLoop::quit);
        QObject::connect(m_bus.get(), &QCanBusDevice::framesReceived, &loop, &QEventLoop::quit);
        QObject::connect(m_bus.get(), &QCanBusDevice::stateChanged, &loop, &QEventLoop::quit);
        timer.start(timeoutMs);
        loop.exec();
        drain();
    }
    out.insert(out.end(), m_queue.begin(), m_queue.end());
    m_queue.clear();
    return connectedOrError(error);
}

void QtCanFrameLink::clearInput()
{
    drain();
    m_queue.clear();
}

void QtCanFrameLink::sleepMs(int ms)
{
    if (ms <= 0)
        return;
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
    drain();
}

int64_t QtCanFrameLink::nowUs() const
{
    return m_clock.nsecsElapsed() / 1000;
}

} // namespace imudesk::firmware
