#include "simulated_transport.h"

#include "io/serial_transport.h"

namespace imudesk::sim {

SimulatedTransport::SimulatedTransport(std::unique_ptr<SimulatedSerialDevice> device, QObject *parent)
    : io::Transport(parent), m_device(std::move(device))
{
    m_timer.setInterval(kTickMs);
    connect(&m_timer, &QTimer::timeout, this, &SimulatedTransport::tick);
    m_clock.start();
}

SimulatedTransport::~SimulatedTransport() = default;

int64_t SimulatedTransport::deviceNowUs() const
{
    return m_baseUs + int64_t(double(m_clock.nsecsElapsed()) * m_timeScale / 1000.0);
}

void SimulatedTransport::setTimeScale(double scale)
{
    m_baseUs = deviceNowUs(); // the device's clock goes on from where it is
    m_clock.restart();
    m_timeScale = scale > 0 ? scale : 1.0;
}

bool SimulatedTransport::open(const QString &address, int baud, QString *error)
{
    if (!m_plugged) {
        if (error)
            *error = io::SerialTransport::describeOpenError(address, io::OpenErrorKind::NotFound, QString());
        return false;
    }
    m_address = address;
    m_baud = baud;
    m_open = true;
    m_device->takeOutputSegments(); // what it sent while nobody listened is lost
    m_timer.start();
    return true;
}

bool SimulatedTransport::reopen(int baud, QString *error)
{
    if (error)
        error->clear();
    return m_plugged && open(m_address, baud, error);
}

void SimulatedTransport::close()
{
    m_open = false;
    m_timer.stop();
}

bool SimulatedTransport::setBaud(int baud)
{
    m_baud = baud;
    return true;
}

qint64 SimulatedTransport::write(const QByteArray &bytes)
{
    if (!m_open)
        return -1;
    m_device->advanceTo(deviceNowUs());
    if (m_baud == m_device->baud() && !m_deaf)
        m_device->receive(reinterpret_cast<const uint8_t *>(bytes.constData()), size_t(bytes.size()));
    m_written += quint64(bytes.size());
    return bytes.size();
}

void SimulatedTransport::clear()
{
    if (m_open)
        m_device->takeOutputSegments();
}

void SimulatedTransport::unplug()
{
    m_plugged = false;
    if (!m_open)
        return;
    close();
    Q_EMIT failed(tr("The connection to %1 was lost (simulated unplug). Check the cable; everything received so "
                     "far is kept.")
                      .arg(m_address));
}

void SimulatedTransport::tick()
{
    if (!m_open)
        return;
    if (m_unplugAtUs >= 0 && deviceNowUs() >= m_unplugAtUs) {
        m_unplugAtUs = -1;
        unplug();
        return;
    }
    m_device->advanceTo(deviceNowUs());
    QByteArray out;
    for (const SerialSegment &s : m_device->takeOutputSegments()) {
        if (s.baud == m_baud) {
            out.append(reinterpret_cast<const char *>(s.bytes.data()), qsizetype(s.bytes.size()));
            continue;
        }
        for (size_t i = 0; i < s.bytes.size(); ++i) { // heard at the wrong rate
            m_garbage = uint8_t(m_garbage * 37u + 101u);
            out.append(char(0x80u | m_garbage));
        }
    }
    if (!out.isEmpty())
        Q_EMIT bytesReceived(out);
}

} // namespace imudesk::sim
