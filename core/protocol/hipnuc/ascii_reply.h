#pragma once
// Replies to ASCII commands: zero or more info lines (often KEY=VALUE), then `OK`,
// or a line starting with ERR/ERROR/FAIL. Unknown commands get no reply at all;
// the session turns that into a timeout.
#include "model/request_outcome.h"

#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace imudesk::protocol::hipnuc {

struct AsciiReply {
    using Status = model::RequestOutcome; // an ERR line: Refused
    Status status = Status::Pending;
    std::string command;                       // the command this answers
    std::vector<std::string> lines;            // info lines before OK/ERR (echo removed)
    std::map<std::string, std::string> values; // KEY=VALUE lines
    std::string errorLine;                     // the ERR line, or why it failed
    bool ok() const { return status == Status::Ok; }
};

enum class LineKind { Ok, Error, Info };
LineKind classifyLine(std::string_view line);

// Collects the lines of one reply.
class ReplyCollector {
public:
    explicit ReplyCollector(std::string command);
    // Returns true when the reply is complete.
    bool addLine(std::string_view line);
    bool complete() const { return m_reply.status != AsciiReply::Status::Pending; }
    const AsciiReply &reply() const { return m_reply; }
    AsciiReply take() { return std::move(m_reply); }

private:
    AsciiReply m_reply;
};

// Every KEY=VALUE pair of a line, read tolerantly (the manual prints no format for the replies
// of the LOG queries but URFR=<CODE>): keys in upper case with blanks as '_' ("att mode" ->
// "ATT_MODE"); several pairs on one line ("BAUD=115200; LOG=ENABLE", "A=1 B=2"); blanks around
// the separator; "Key: value" when the line has no '='. A value keeps its commas and blanks
// ("URFR=1,0,0,...", "HI91=ONTIME 0.01"). Empty when the line holds no pair.
std::vector<std::pair<std::string, std::string>> keyValuePairs(std::string_view line);

} // namespace imudesk::protocol::hipnuc
