#pragma once
// Value types that cross between a CanSession and its worker thread.
#include "device/request.h"
#include "protocol/can/can_decoder.h"
#include "protocol/can/can_frame.h"

#include <QList>
#include <QMetaType>
#include <QString>

#include <cstdint>

namespace imudesk::device {

struct CanSessionOptions {
    QString plugin = QStringLiteral("virtualcan");
    QString interfaceName = QStringLiteral("can0");
    int bitrate = 0;      // 0: leave the plugin's setting
    int dataBitrate = 0;  // CAN FD data phase; 0: none
    bool canFd = false;
    protocol::can::CanProtocol protocol = protocol::can::CanProtocol::Auto;
    int node = -1;        // node / source address to follow; -1: the first one that sends data
    int hec495Mode = -1;  // HEC495 PDO mode, -1 = guess per frame
    // HiPNUC CANopen node-ID object: 0x209C (firmware 1.7.x) or 0x20A0 (1.6.6); see
    // canopen::hipnuc::nodeIdObject(major, minor, patch).
    uint16_t hipnucNodeIdObject = 0x209C;
    bool hec495Extended = false; // HEC495 extended-frame variant (0x18FA....)
    uint8_t hostAddress = 0x55; // J1939 source address of the host (vendor tools' 0x55; 0..253)
    int requestTimeoutMs = 1000;
};

struct CanFrameEvent {
    protocol::can::CanFrame frame;
    qint64 hostTimeNs = 0;
    bool transmitted = false; // sent by this session
};
using CanFrameEvents = QList<CanFrameEvent>;

struct CanNodeInfo {
    protocol::can::CanProtocol protocol = protocol::can::CanProtocol::Auto;
    int node = -1;
    QString seenAs; // "data", "heartbeat", "boot-up", "SDO scan", "configuration reply"
};

// One node's answer to a J1939 request to the broadcast address 255.
struct CanNodeAnswer {
    int node = -1;
    bool ok = false;     // status 0
    quint32 value = 0;
    int status = 0;      // the reply's STATUS byte
};

struct CanRequestResult {
    quint64 id = 0;
    bool ok = false;
    quint32 value = 0;  // value read back or echoed
    QString message;    // what happened (error text when !ok)
    RequestStatus status = RequestStatus::NotSent; // how it ended (Ok when ok)
    QList<CanNodeAnswer> answers; // a J1939 broadcast request: every node's answer, by node
    QList<quint32> values;        // every reply's value in step order (a setting of several registers)
};

} // namespace imudesk::device

Q_DECLARE_METATYPE(imudesk::device::CanFrameEvents)
Q_DECLARE_METATYPE(imudesk::device::CanNodeInfo)
Q_DECLARE_METATYPE(imudesk::device::CanRequestResult)
Q_DECLARE_METATYPE(imudesk::device::CanSessionOptions)
