#pragma once
// Value types of a Modbus RTU session (core/device/modbus_session.h) that cross threads.
#include "device/request.h"
#include "model/device_identity.h"
#include "protocol/modbus/register_map.h"

#include <QList>
#include <QMetaType>
#include <QSerialPort>
#include <QString>

namespace imudesk::device {

struct ModbusOptions {
    QString port;
    protocol::modbus::DeviceKind kind = protocol::modbus::DeviceKind::Hipnuc;
    int nodeId = 0;   // 0: the device's default (80 HiPNUC, 1 HEC495)
    int baud = 0;     // 0: the device's default (115200 HiPNUC, 9600 HEC495)
    QSerialPort::Parity parity = QSerialPort::NoParity;
    QSerialPort::StopBits stopBits = QSerialPort::OneStop;
    double pollHz = 10;       // 0: no polling; bounded by ModbusSession::maxPollRate()
    bool shipMotion = false;  // HiPNUC: poll 0x34..0x51 (heave) instead of 0x34..0x4B
    bool identify = true;     // read the identity at connect; false: open the port only (scan)
    int timeoutMs = 300;      // per request
    int retries = 1;          // requests sent again after a timeout

    int effectiveNodeId() const;
    int effectiveBaud() const;
};

struct ModbusScanOptions {
    int firstId = 1;
    int lastId = 247;
    QList<int> bauds;     // empty: the session's baud only
    int timeoutMs = 0;    // per probe; 0: from the baud (a few frame times)
    // Instead of every id at every baud: these probes in this order (a sweep asks the likely
    // addresses first). A probe's timeoutMs 0: from the baud.
    struct Probe {
        int baud = 0;
        int id = 0;
        int timeoutMs = 0;
    };
    QList<Probe> plan;
    // A bus runs at one rate: once a device answered at a baud, probes at other bauds are skipped.
    bool oneRate = false;
};

struct ModbusScanHit {
    int nodeId = 0;
    int baud = 0;
    bool exception = false;             // answered with a Modbus exception (present, but refused the probe)
    bool identified = false;            // HiPNUC identity block read
    QList<quint16> probeValues;         // the probe's two registers (HiPNUC: UART1_BAUD code and MD_ID; HEC495: pitch)
    int damaged = 0;                    // replies to this id whose CRC failed (two devices answering at once garble each other)
    model::DeviceIdentity identity;
    QString summary;                    // "HI14R3N-485-000 V1.71 SN 0123..." or the HEC495 angles
};

struct ModbusRegisterReply {
    quint64 id = 0;
    bool ok = false;
    int start = 0;
    QList<quint16> values;
    QString message;       // what went wrong and what to do, when !ok
    int exceptionCode = 0; // Modbus exception code, 0 = none
    RequestStatus status = RequestStatus::NotSent; // how it ended (Ok when ok)
};

} // namespace imudesk::device

Q_DECLARE_METATYPE(imudesk::device::ModbusOptions)
Q_DECLARE_METATYPE(imudesk::device::ModbusScanOptions)
Q_DECLARE_METATYPE(imudesk::device::ModbusScanHit)
Q_DECLARE_METATYPE(imudesk::device::ModbusRegisterReply)
