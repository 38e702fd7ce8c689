#include "serial_transport.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QSerialPort>
#include <QSerialPortInfo>

#include <cerrno>
#ifdef Q_OS_UNIX
#include <poll.h>
#include <unistd.h>
#endif

namespace imudesk::io {

SerialTransport::SerialTransport(QObject *parent) : Transport(parent) {}

SerialTransport::~SerialTransport()
{
    close();
}

QString SerialTransport::describeOpenError(const QString &portName, OpenErrorKind kind, const QString &osText)
{
    switch (kind) {
    case OpenErrorKind::NotFound:
        return QCoreApplication::translate("imudesk::io::SerialTransport",
                                           "Port %1 was not found. Check that the device is plugged in and "
                                           "choose the port again from the list.")
            .arg(portName);
    case OpenErrorKind::Busy:
        return QCoreApplication::translate("imudesk::io::SerialTransport",
                                           "Port %1 is in use by another program (a serial terminal, CHCenter or "
                                           "another ImuDesk). Close that program and connect again.")
            .arg(portName);
    case OpenErrorKind::Permission:
        return QCoreApplication::translate("imudesk::io::SerialTransport",
                                           "No permission to open %1. On Linux add your user to the dialout "
                                           "group (sudo usermod -aG dialout $USER), then log out and in again; or "
                                           "install the udev rule that docs/INSTALLING.md describes (60-imudesk-serial.rules).")
            .arg(portName);
    case OpenErrorKind::Other:
    case OpenErrorKind::None:
        break;
    }
    return QCoreApplication::translate("imudesk::io::SerialTransport", "Could not open %1: %2").arg(portName, osText);
}

OpenErrorKind SerialTransport::classifyOpenError(int serialPortError, bool accessible)
{
    switch (QSerialPort::SerialPortError(serialPortError)) {
    case QSerialPort::NoError: return OpenErrorKind::None;
    case QSerialPort::DeviceNotFoundError: return OpenErrorKind::NotFound;
    case QSerialPort::PermissionError:
        // "Permission error while locking the device" (another QSerialPort, in this or
        // another process, holds the lock file) and EBUSY (TIOCEXCL) come here too.
        return accessible ? OpenErrorKind::Busy : OpenErrorKind::Permission;
    default: return OpenErrorKind::Other;
    }
}

QString SerialTransport::systemLocation(const QString &portName)
{
    if (portName.startsWith(QLatin1Char('/')))
        return portName;
    return QStringLiteral("/dev/") + portName;
}

bool SerialTransport::isAccessible(const QString &portName)
{
#ifdef Q_OS_UNIX
    const QByteArray path = QFile::encodeName(systemLocation(portName));
    if (::access(path.constData(), R_OK | W_OK) == 0)
        return true;
    return errno != EACCES && errno != EPERM && errno != EROFS;
#else
    Q_UNUSED(portName)
    return true; // Windows reports a port in use as access denied
#endif
}

bool SerialTransport::open(const QString &portName, int baud, QString *error, OpenErrorKind *kind)
{
    if (!openPort(portName, baud, error, kind))
        return false;
    m_requestedPort = portName;
    rememberDevice(portName);
    return true;
}

bool SerialTransport::reopen(int baud, QString *error)
{
    const QString path = locateAgain();
    if (path.isEmpty()) {
        if (error)
            error->clear();
        return false;
    }
    return openPort(path, baud, error, nullptr);
}

void SerialTransport::rememberDevice(const QString &portName)
{
    // The USB identity of the port, when it has one (QSerialPortInfo lists USB and on-board
    // ports, not pseudo-terminals). A by-id symlink is matched by its target.
    m_serialNumber.clear();
    m_hasUsbIds = false;
    const QString location = systemLocation(portName);
    const QString canonical = QFileInfo(location).canonicalFilePath();
    const auto ports = QSerialPortInfo::availablePorts();
    for (const QSerialPortInfo &info : ports) {
        if (info.systemLocation() != location && info.systemLocation() != canonical && info.portName() != portName)
            continue;
        m_serialNumber = info.serialNumber();
        m_hasUsbIds = info.hasVendorIdentifier() && info.hasProductIdentifier();
        m_vendorId = info.vendorIdentifier();
        m_productId = info.productIdentifier();
        break;
    }
}

QString SerialTransport::locateAgain() const
{
    if (!m_serialNumber.isEmpty()) {
        const auto ports = QSerialPortInfo::availablePorts();
        for (const QSerialPortInfo &info : ports) {
            if (info.serialNumber() != m_serialNumber)
                continue;
            if (m_hasUsbIds && (info.vendorIdentifier() != m_vendorId || info.productIdentifier() != m_productId))
                continue;
            // The path the user chose, if it leads there (a by-id symlink), else the device.
            const QString wanted = systemLocation(m_requestedPort);
            return QFileInfo(wanted).canonicalFilePath() == info.systemLocation() ? m_requestedPort
                                                                                   : info.systemLocation();
        }
        return {};
    }
    return QFileInfo::exists(systemLocation(m_requestedPort)) ? m_requestedPort : QString();
}

bool SerialTransport::openPort(const QString &portName, int baud, QString *error, OpenErrorKind *kind)
{
    close();
    auto fail = [&](OpenErrorKind k, const QString &osText) {
        if (kind)
            *kind = k;
        if (error)
            *error = describeOpenError(portName, k, osText);
        return false;
    };
    // QSerialPort accepts bare names ("ttyUSB0") and paths; a missing path is reported clearly.
    if (portName.startsWith(QLatin1Char('/')) && !QFileInfo::exists(portName))
        return fail(OpenErrorKind::NotFound, QString());

    m_port = new QSerialPort(this);
    m_port->setPortName(portName);
    m_port->setBaudRate(baud);
    m_port->setDataBits(QSerialPort::Data8);
    m_port->setParity(m_parity);
    m_port->setStopBits(m_stopBits);
    m_port->setFlowControl(QSerialPort::NoFlowControl);
    m_port->setReadBufferSize(0);
    if (!m_port->open(QIODevice::ReadWrite)) {
        const auto err = m_port->error();
        const QString osText = m_port->errorString();
        delete m_port;
        m_port = nullptr;
        const bool accessible = err != QSerialPort::PermissionError || isAccessible(portName);
        return fail(classifyOpenError(int(err), accessible), osText);
    }
    m_portName = portName;
    m_baud = baud;
    connect(m_port, &QSerialPort::readyRead, this, &SerialTransport::onReadyRead);
    connect(m_port, &QSerialPort::errorOccurred, this, &SerialTransport::onError);
    if (kind)
        *kind = OpenErrorKind::None;
    return true;
}

void SerialTransport::close()
{
    if (!m_port)
        return;
    m_port->disconnect(this);
    if (m_port->isOpen())
        m_port->close();
    m_port->deleteLater();
    m_port = nullptr;
}

bool SerialTransport::isOpen() const
{
    return m_port && m_port->isOpen();
}

bool SerialTransport::setBaud(int baud)
{
    if (!m_port)
        return false;
    if (!m_port->setBaudRate(baud))
        return false;
    m_baud = baud;
    return true;
}

qint64 SerialTransport::write(const QByteArray &bytes)
{
    if (!isOpen())
        return -1;
    return m_port->write(bytes);
}

void SerialTransport::clear()
{
    if (m_port)
        m_port->clear();
}

bool SerialTransport::bytesWaiting() const
{
    if (!m_port || !m_port->isOpen())
        return false;
    if (m_port->bytesAvailable() > 0)
        return true;
#ifdef Q_OS_UNIX
    pollfd p{int(m_port->handle()), POLLIN, 0};
    return ::poll(&p, 1, 0) > 0 && (p.revents & POLLIN) != 0;
#else
    return false;
#endif
}

bool SerialTransport::hungUp() const
{
#ifdef Q_OS_UNIX
    pollfd p{int(m_port->handle()), POLLIN, 0};
    return ::poll(&p, 1, 0) < 0 || (p.revents & (POLLHUP | POLLERR | POLLNVAL)) != 0;
#else
    return true; // no way to ask: every read error is taken for a lost link
#endif
}

QByteArray SerialTransport::takeAvailable()
{
    // Everything the port holds, in one chunk, never a read per frame: with an unlimited read
    // buffer (setReadBufferSize(0)) QSerialPort reads up to 32 KiB per notification. On Linux a
    // tty's line discipline hands out at most 4 KiB per read(2) (what is behind it waits in the
    // tty's flip buffer until a kernel worker moves it on), so after a delay the bytes arrive
    // as a few 4 KiB chunks in quick succession, each decoded in one feed.
    // Exactly what is buffered, in an allocation of that size: QIODevice::readAll() reads
    // into a 16 KiB block per call and keeps it as spare capacity, which every holder of the
    // chunk (raw-byte log, queued signals) then keeps too; at 1 kHz that was 200 MB held for
    // 256 KiB of bytes, and a heap that kept fragmenting.
    const qint64 available = m_port->bytesAvailable();
    if (available <= 0)
        return {};
    QByteArray bytes(available, Qt::Uninitialized);
    const qint64 n = m_port->read(bytes.data(), available);
    if (n <= 0)
        return {};
    if (n < available)
        bytes.truncate(n);
    return bytes;
}

void SerialTransport::onReadyRead()
{
    const QByteArray bytes = takeAvailable();
    if (!bytes.isEmpty())
        Q_EMIT bytesReceived(bytes);
}

void SerialTransport::onError()
{
    if (!m_port)
        return;
    const auto err = m_port->error();
    if (err == QSerialPort::NoError || err == QSerialPort::TimeoutError)
        return;
    if (err == QSerialPort::ReadError && !hungUp()) {
        // A read that found nothing, not a lost link: QSerialPort reads when its notifier says
        // bytes arrived, and reports a ReadError (with whatever errno an earlier call left, often
        // "Inappropriate ioctl for device") when the read returns none, which happens when the
        // input was flushed (clear(): a baud scan's next rate) between the notification and the
        // read. A cable pulled or a device gone shows as a hang-up of the port (or a
        // ResourceError, below).
        m_port->clearError();
        return;
    }
    if (err == QSerialPort::ResourceError || err == QSerialPort::ReadError || err == QSerialPort::WriteError) {
        const QString msg = QCoreApplication::translate("imudesk::io::SerialTransport",
                                                        "The connection to %1 was lost (%2). Check the cable; "
                                                        "everything received so far is kept.")
                                .arg(m_portName, m_port->errorString());
        // Read what is still buffered before reporting.
        const QByteArray rest = takeAvailable();
        if (!rest.isEmpty())
            Q_EMIT bytesReceived(rest);
        m_port->clearError();
        Q_EMIT failed(msg);
    }
}

} // namespace imudesk::io
