#pragma once
// Moves bytes to and from a serial port (QSerialPort); nothing else. Lives in the
// session's worker thread.
#include "io/transport.h"

#include <QObject>
#include <QString>


namespace imudesk::io {

enum class OpenErrorKind { None, NotFound, Busy, Permission, Other };

class SerialTransport : public Transport {
    Q_OBJECT
public:
    explicit SerialTransport(QObject *parent = nullptr);
    ~SerialTransport() override;

    // Opens 8 data bits with the framing set (8N1 by default), no flow control. On failure fills kind and a message that says what to do.
    // Remembers the port's USB identity for locateAgain().
    bool open(const QString &portName, int baud, QString *error, OpenErrorKind *kind);
    bool open(const QString &portName, int baud, QString *error) override { return open(portName, baud, error, nullptr); }
    void setFraming(QSerialPort::Parity parity, QSerialPort::StopBits stopBits) override
    {
        m_parity = parity;
        m_stopBits = stopBits;
    }
    void close() override;
    bool isOpen() const override;
    bool setBaud(int baud) override;
    int baud() const override { return m_baud; }
    QString address() const override { return m_portName; }
    QString portName() const { return m_portName; }
    qint64 write(const QByteArray &bytes) override;
    // Discards bytes waiting in the OS buffers (input and output).
    void clear() override;
    bool bytesWaiting() const override;
    // The same adapter by its USB serial number (ttyUSB0 may come back as ttyUSB1); without
    // one (a pseudo-terminal, an on-board UART) the path the port was first opened at, once
    // it exists again.
    QString locateAgain() const override;
    bool reopen(int baud, QString *error) override;

    static QString describeOpenError(const QString &portName, OpenErrorKind kind, const QString &osText);
    // Maps QSerialPort's open error to a kind. Qt 6.4 on Linux reports a port held by
    // another handle (its lock file, or EBUSY from TIOCEXCL) and a denied open (EACCES)
    // alike as PermissionError, with texts that Qt translates; they are told apart by
    // whether this user may read and write the device at all (`accessible`).
    static OpenErrorKind classifyOpenError(int serialPortError, bool accessible);
    // Whether this process may open the device for reading and writing (access(2)).
    static bool isAccessible(const QString &portName);
    // The device path for a port name ("ttyUSB0" -> "/dev/ttyUSB0"; paths unchanged).
    static QString systemLocation(const QString &portName);

private:
    bool openPort(const QString &portName, int baud, QString *error, OpenErrorKind *kind);
    void rememberDevice(const QString &portName);

    QByteArray takeAvailable();
    void onReadyRead();
    void onError();
    // The port reports a hang-up or an error of its own (Unix: poll); a read error without one is
    // a read that found nothing (onError says when).
    bool hungUp() const;

    QSerialPort *m_port = nullptr;
    QString m_portName;
    int m_baud = 0;
    QSerialPort::Parity m_parity = QSerialPort::NoParity;
    QSerialPort::StopBits m_stopBits = QSerialPort::OneStop;
    // The device first opened (reconnection looks for it again).
    QString m_requestedPort;
    QString m_serialNumber;
    quint16 m_vendorId = 0, m_productId = 0;
    bool m_hasUsbIds = false;
};

} // namespace imudesk::io
