#pragma once
// Moves bytes to and from a serial port (QSerialPort); nothing else. Lives in the
// session's worker thread.
#include <QObject>
#include <QString>

class QSerialPort;

namespace imudesk::io {

enum class OpenErrorKind { None, NotFound, Busy, Permission, Other };

class SerialTransport : public QObject {
    Q_OBJECT
public:
    explicit SerialTransport(QObject *parent = nullptr);
    ~SerialTransport() override;

    // Opens 8N1, no flow control. On failure fills kind and a message that says what to do.
    bool open(const QString &portName, int baud, QString *error, OpenErrorKind *kind = nullptr);
    void close();
    bool isOpen() const;
    bool setBaud(int baud);
    int baud() const { return m_baud; }
    QString portName() const { return m_portName; }
    qint64 write(const QByteArray &bytes);
    // Discards bytes waiting in the OS buffers (input and output).
    void clear();

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

Q_SIGNALS:
    void bytesReceived(const QByteArray &bytes);
    // The port failed while open (unplugged cable, I/O error).
    void failed(const QString &message);

private:
    QByteArray takeAvailable();
    void onReadyRead();
    void onError();

    QSerialPort *m_port = nullptr;
    QString m_portName;
    int m_baud = 0;
};

} // namespace imudesk::io
