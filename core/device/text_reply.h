#pragma once
// A reply to a command typed as text (the console, the command log), whatever the family that
// takes text commands: its outcome, the lines it brought and, when it failed, why. A family
// fills it from its own reply (HiPNUC: protocol::hipnuc::AsciiReply, textReplyOf).
#include "model/request_outcome.h"

#include <QMetaType>
#include <QString>
#include <QStringList>

namespace imudesk::protocol::hipnuc {
struct AsciiReply;
}

namespace imudesk::device {

struct TextReply {
    using Status = model::RequestOutcome; // the device's error line: Refused
    Status status = Status::Pending;
    QString command;  // what it answers, as the device understood it
    QStringList lines; // the lines before the outcome (KEY=VALUE and others)
    QString why;      // the device's error line, or why there was no answer
    bool ok() const { return status == Status::Ok; }
};

// A HiPNUC ASCII reply in these terms (the same outcome).
TextReply textReplyOf(const protocol::hipnuc::AsciiReply &reply);

} // namespace imudesk::device

Q_DECLARE_METATYPE(imudesk::device::TextReply)
