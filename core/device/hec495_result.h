#pragma once
// The outcome of one request to an HEC495, as it crosses from the session's worker thread.
#include "device/request.h"
#include "protocol/witlink/reply.h"

#include <QMetaType>
#include <QString>

#include <cstdint>

namespace imudesk::device {

struct Hec495Result {
    // Every request's one shape of outcome (device/request.h). For the HEC495: Ok, answered (a
    // status reply 00, success); Refused, answered FF (the device reports failure); Invalid, a
    // reply the manual does not allow there (see message); Timeout, NotSent, Cancelled.
    using Status = RequestStatus;
    Status status = Status::NotSent;
    uint8_t request = 0;   // command byte sent
    int attempts = 0;      // how many times it was sent (RS-485 retries)
    protocol::witlink::Reply reply;
    QString message;       // what happened, for the user

    bool ok() const { return status == Status::Ok; }
};

} // namespace imudesk::device

Q_DECLARE_METATYPE(imudesk::device::Hec495Result)
