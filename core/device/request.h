#pragma once
// One request to a device, and how it ended, in the session engine's terms (session_engine.h).
// The family plug-in fills in what is its own: the bytes to send, what it was (`command`), and
// the typed reply (`RequestResult::reply`, e.g. a hipnuc::AsciiReply or a witlink::Reply).
#include <QByteArray>
#include <QMetaType>
#include <QString>
#include <QVariant>

#include "model/request_outcome.h"

#include <any>
#include <cstdint>
#include <functional>

namespace imudesk::device {

using RequestStatus = model::RequestOutcome; // its name: model::outcomeName

struct RequestResult {
    quint64 id = 0;
    RequestStatus status = RequestStatus::NotSent;
    int attempts = 0;       // times it went on the line
    QString message;        // what happened, for the user (empty on a plain success)
    QVariant reply;         // the family's typed reply
    int64_t sentNs = 0;     // when the last attempt was written (clock::hostNowNs); 0: never
    bool ok() const { return status == RequestStatus::Ok; }
};

struct Request {
    quint64 id = 0;            // 0: the session's own (identification, polling, probes)
    QByteArray wire;           // what goes on the line
    int timeoutMs = 1000;      // per attempt
    int maxAttempts = 1;       // sent again after a timeout, up to this many times in all
    int attempts = 0;
    int64_t sentNs = 0;        // when its last attempt was written (clock::hostNowNs)
    std::any command;          // the family's description (for matching replies and effects)
    // Called in the engine's thread when the request ends, before requestFinished.
    std::function<void(const RequestResult &)> done;
};

} // namespace imudesk::device

Q_DECLARE_METATYPE(imudesk::device::RequestResult)
