#pragma once
// What a session's engine needs from a byte link, whatever carries the bytes: a serial port
// (SerialTransport) or a simulated device in the same process (sim::SimulatedTransport). A
// transport only moves bytes; it lives in the session's worker thread.
#include <QByteArray>
#include <QObject>
#include <QSerialPort>
#include <QString>

namespace imudesk::io {

class Transport : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;
    ~Transport() override = default;

    // Opens the link at `address` (a port name or path); on failure says why and what to do.
    virtual bool open(const QString &address, int baud, QString *error) = 0;
    virtual void close() = 0;
    virtual bool isOpen() const = 0;
    virtual bool setBaud(int baud) = 0;
    virtual int baud() const = 0;
    // Where the link was opened (the port name as given).
    virtual QString address() const = 0;
    virtual qint64 write(const QByteArray &bytes) = 0;
    // Character framing for the next open (8 data bits; 8N1 unless set): an RS-485 bus may run
    // with parity (Modbus RTU). A link that has no such framing ignores it.
    virtual void setFraming(QSerialPort::Parity parity, QSerialPort::StopBits stopBits)
    {
        Q_UNUSED(parity);
        Q_UNUSED(stopBits);
    }
    // Discards bytes waiting in buffers (both directions).
    virtual void clear() = 0;
    // Whether received bytes wait to be read (in the OS or the port's buffer): the reading
    // thread ran late. A line with bytes waiting is not quiet, whatever a timer says.
    virtual bool bytesWaiting() const { return false; }
    // After the link failed: where the same device can be opened again now (a USB adapter may
    // come back under another name); empty while it is not there.
    virtual QString locateAgain() const { return address(); }
    // Opens the link again where locateAgain() finds the device, at `baud`. False while the
    // device is not there (error empty) or cannot be opened yet (error says why).
    virtual bool reopen(int baud, QString *error) = 0;

Q_SIGNALS:
    void bytesReceived(const QByteArray &bytes);
    // The link failed while open (unplugged cable, I/O error).
    void failed(const QString &message);
    // Something the user should know that does not end the link (a CAN bus error).
    void notice(const QString &message);
};

} // namespace imudesk::io
