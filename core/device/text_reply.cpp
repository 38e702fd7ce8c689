#include "text_reply.h"

#include "protocol/hipnuc/ascii_reply.h"

namespace imudesk::device {

TextReply textReplyOf(const protocol::hipnuc::AsciiReply &reply)
{
    using A = protocol::hipnuc::AsciiReply::Status;
    TextReply t;
    switch (reply.status) {
    case A::Pending: t.status = TextReply::Status::Pending; break;
    case A::Ok: t.status = TextReply::Status::Ok; break;
    case A::Error: t.status = TextReply::Status::Error; break;
    case A::Timeout: t.status = TextReply::Status::Timeout; break;
    case A::Cancelled: t.status = TextReply::Status::Cancelled; break;
    case A::NotSent: t.status = TextReply::Status::NotSent; break;
    }
    t.command = QString::fromStdString(reply.command);
    for (const auto &line : reply.lines)
        t.lines << QString::fromStdString(line);
    t.why = QString::fromStdString(reply.errorLine);
    return t;
}

} // namespace imudesk::device
