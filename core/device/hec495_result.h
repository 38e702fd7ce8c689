#pragma once
// The outcome of one request to an HEC495, as it crosses from the session's worker thread.
#include "protocol/witlink/reply.h"

#include <QMetaType>
#include <QString>

#include <cstdint>

namespace imudesk::device {

struct Hec495Result {
    enum class Status {
        Ok,        // answered; for status replies: 00 (success)
        Failed,    // answered FF (the device reports failure)
        Invalid,   // answered with a reply the manual does not allow (see message)
        Timeout,   // no reply after every attempt
        NotSent,   // the port is not open, or writing failed
        Cancelled, // the session was closed
    };
    Status status = Status::NotSent;
    uint8_t request = 0;   // command byte sent
    int attempts = 0;      // how many times it was sent (RS-485 retries)
    protocol::witlink::Reply reply;
    QString message;       // what happened, for the user

    bool ok() const { return status == Status::Ok; }
};

const char *statusName(Hec495Result::Status s);

} // namespace imudesk::device

Q_DECLARE_METATYPE(imudesk::device::Hec495Result)
