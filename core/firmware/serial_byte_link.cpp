#include "serial_byte_link.h"

#include "io/serial_transport.h"

#include <QSerialPort>
#include <QThread>

namespace imudesk::firmware {

SerialByteLink::SerialByteLink(QString portName) : m_name(std::move(portName))
{
    m_clock.start();
}

SerialByteLink::~SerialByteLink()
{
    close();
}

bool SerialByteLink::open(int baud, QString *error)
{
    close();
    m_port = std::make_unique<QSerialPort>();
    m_port->setPortName(m_name);
    if (!m_port->open(QIODevice::ReadWrite)) {
        if (error) {
            // The words of a session's open: a port in use says so, a refused one names the group
            // to join (dialout) and the command that does it.
            const auto err = m_port->error();
            const bool accessible = err != QSerialPort::PermissionError || io::SerialTransport::isAccessible(m_name);
            *error = io::SerialTransport::describeOpenError(
                m_name, io::SerialTransport::classifyOpenError(int(err), accessible), m_port->errorString());
        }
        m_port.reset();
        return false;
    }
    m_port->setBaudRate(baud);
    m_port->setDataBits(QSerialPort::Data8);
    m_port->setParity(QSerialPort::NoParity);
    m_port->setStopBits(QSerialPort::OneStop);
    m_port->setFlowControl(QSerialPort::NoFlowControl);
    return true;
}

void SerialByteLink::close()
{
    if (m_port) {
        m_port->close();
        m_port.reset();
    }
}

bool SerialByteLink::isOpen() const
{
    return m_port && m_port->isOpen();
}

bool SerialByteLink::write(const std::vector<uint8_t> &bytes, QString *error)
{
    if (!isOpen()) {
        if (error)
            *error = tr("the port %1 is not open").arg(m_name);
        return false;
    }
    const qint64 n = m_port->write(reinterpret_cast<const char *>(bytes.data()), qint64(bytes.size()));
    if (n != qint64(bytes.size())) {
        if (error)
            *error = tr("writing to %1 failed: %2").arg(m_name, m_port->errorString());
        return false;
    }
    // Hand the bytes to the driver now; the UART sends them at the baud rate.
    while (m_port->bytesToWrite() > 0) {
        if (!m_port->waitForBytesWritten(2000)) {
            if (error)
                *error = tr("writing to %1 stalled: %2").arg(m_name, m_port->errorString());
            return false;
        }
    }
    return true;
}

bool SerialByteLink::read(std::vector<uint8_t> &out, int timeoutMs, QString *error)
{
    if (!isOpen()) {
        if (error)
            *error = tr("the port %1 is not open").arg(m_name);
        return false;
    }
    if (m_port->bytesAvailable() == 0 && !m_port->waitForReadyRead(timeoutMs)) {
        const auto e = m_port->error();
        if (e != QSerialPort::NoError && e != QSerialPort::TimeoutError) {
            if (error)
                *error = tr("reading from %1 failed: %2 (was the device unplugged?)").arg(m_name, m_port->errorString());
            return false;
        }
        m_port->clearError();
    }
    const QByteArray b = m_port->readAll();
    out.insert(out.end(), b.begin(), b.end());
    return true;
}

void SerialByteLink::clearInput()
{
    if (!isOpen())
        return;
    m_port->readAll();
    m_port->clear(QSerialPort::Input);
}

void SerialByteLink::sleepMs(int ms)
{
    QThread::msleep(ulong(std::max(0, ms)));
}

int64_t SerialByteLink::nowUs() const
{
    return m_clock.nsecsElapsed() / 1000;
}

} // namespace imudesk::firmware
