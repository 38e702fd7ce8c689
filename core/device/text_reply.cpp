#include "text_reply.h"

#include "protocol/hipnuc/ascii_reply.h"

namespace imudesk::device {

TextReply textReplyOf(const protocol::hipnuc::AsciiReply &reply)
{
    TextReply t;
    t.status = reply.status;
    t.command = QString::fromStdString(reply.command);
    for (const auto &line : reply.lines)
        t.lines << QString::fromStdString(line);
    t.why = QString::fromStdString(reply.errorLine);
    return t;
}

} // namespace imudesk::device
