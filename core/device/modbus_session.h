#pragma once
// One device on an RS-485 bus, spoken to in Modbus RTU (HiPNUC v1.7.1 chapter 6 / v1.6.6
// chapter 4, HEC495 "Modbus 通讯协议"): the typed front-end of a Session (session.h) whose
// family plug-in is ModbusFamily (modbus_family.h, which frames the requests and has the link
// rules). All calls are queued; results come back as signals carrying value types.
//
// open(): the port at the node's baud and parity, then the identity (HiPNUC 0x70..0x83;
// HEC495: one read of the angles), then polling of the sensor block (HiPNUC 0x34..0x4B, or
// 0x34..0x51 with ship motion; HEC495 0x0004..0x0009) at the chosen rate, bounded by
// maxPollRate(). Each poll is one Sample in store() (source "MODBUS" or "HEC495";
// deviceTimeMs = host ms since open, the registers carry no device time).
// Writes are checked against the register map first, then verified by reading back where the
// register is readable. Writing MD_ID makes the session follow the new ID; writing UART1_BAUD
// makes it switch its own baud once the reply arrived. CTRL reset/factory pause polling briefly.
// Counters (statsUpdated): frames = replies, crcErrors = replies dropped for a bad CRC,
// payloadErrors = Modbus exceptions, framesLost = polls that got no reply.
#include "device/modbus_types.h"
#include "device/session.h"

#include <QSerialPort>

#include <atomic>

namespace imudesk::device {

class ModbusSession : public Session {
    Q_OBJECT
public:
    // transport: a serial port when null.
    explicit ModbusSession(QObject *parent = nullptr, std::unique_ptr<io::Transport> transport = nullptr);
    ~ModbusSession() override;

    void open(const ModbusOptions &options);
    void close() override;
    QString linkKind() const override;

    // Requested poll rate (Hz); the session uses min(hz, maxPollRate()). 0 stops polling.
    void setPollRate(double hz);
    // Raw read of 1..125 holding registers; the answer arrives in registersRead(reply) with this id.
    quint64 readRegisters(int start, int count);
    // Write one register; writeFinished(reply) says whether it took (and read back).
    quint64 writeRegister(int address, int value, bool verify = true);
    // Probe node IDs (and bauds); scanFound for each device that answers, then scanFinished.
    // Polling pauses during a scan and resumes after it.
    void scan(const ModbusScanOptions &options);
    void cancelScan();

    // The highest poll rate the line carries: one request (8 bytes), one reply (5 + 2n bytes)
    // and two 3.5-character gaps per poll at 10 bits per byte (11 with parity), with 20 % left
    // for the device's turnaround.
    static double maxPollRate(int baud, int registers, QSerialPort::Parity parity = QSerialPort::NoParity);
    // "ILLEGAL DATA ADDRESS (02): register 0x0010 does not exist ..."
    static QString describeException(int code, const QString &where);

Q_SIGNALS:
    void registersRead(const imudesk::device::ModbusRegisterReply &reply);
    void writeFinished(const imudesk::device::ModbusRegisterReply &reply);
    void nodeIdChanged(int nodeId);
    void baudChanged(int baud);
    void pollRateChanged(double hz);
    void scanProgress(int done, int total);
    void scanFound(const imudesk::device::ModbusScanHit &hit);
    void scanFinished(const QList<imudesk::device::ModbusScanHit> &hits, bool cancelled);

private:
    std::atomic<int> m_kind{0};
};

} // namespace imudesk::device
