#include "ascii_reply.h"

#include <cctype>

namespace imudesk::protocol::hipnuc {
namespace {

std::string_view trim(std::string_view s)
{
    while (!s.empty() && std::isspace(uint8_t(s.front())))
        s.remove_prefix(1);
    while (!s.empty() && std::isspace(uint8_t(s.back())))
        s.remove_suffix(1);
    return s;
}

bool startsWithWord(std::string_view s, std::string_view word)
{
    if (s.size() < word.size())
        return false;
    for (size_t i = 0; i < word.size(); ++i)
        if (std::toupper(uint8_t(s[i])) != word[i])
            return false;
    if (s.size() == word.size())
        return true;
    const char next = s[word.size()];
    return next == ' ' || next == ':' || next == '=' || next == ',' || next == '-' || std::isdigit(uint8_t(next));
}

} // namespace

const char *statusName(AsciiReply::Status s)
{
    switch (s) {
    case AsciiReply::Status::Pending: return "pending";
    case AsciiReply::Status::Ok: return "ok";
    case AsciiReply::Status::Error: return "error";
    case AsciiReply::Status::Timeout: return "timeout";
    case AsciiReply::Status::Cancelled: return "cancelled";
    case AsciiReply::Status::NotSent: return "not sent";
    }
    return "?";
}

LineKind classifyLine(std::string_view raw)
{
    const auto line = trim(raw);
    if (line == "OK")
        return LineKind::Ok;
    if (startsWithWord(line, "ERROR") || startsWithWord(line, "ERR") || startsWithWord(line, "FAIL"))
        return LineKind::Error;
    return LineKind::Info;
}

bool splitKeyValue(std::string_view raw, std::string &key, std::string &value)
{
    const auto line = trim(raw);
    const size_t eq = line.find('=');
    if (eq == std::string_view::npos || eq == 0)
        return false;
    key = std::string(trim(line.substr(0, eq)));
    value = std::string(trim(line.substr(eq + 1)));
    return !key.empty();
}

ReplyCollector::ReplyCollector(std::string command)
{
    m_reply.command = std::move(command);
}

bool ReplyCollector::addLine(std::string_view raw)
{
    if (complete())
        return true;
    const auto line = trim(raw);
    if (line.empty() || line == trim(m_reply.command))
        return false; // blank or the device's echo of the command
    switch (classifyLine(line)) {
    case LineKind::Ok:
        m_reply.status = AsciiReply::Status::Ok;
        return true;
    case LineKind::Error:
        m_reply.status = AsciiReply::Status::Error;
        m_reply.errorLine = std::string(line);
        return true;
    case LineKind::Info: {
        m_reply.lines.emplace_back(line);
        std::string k, v;
        if (splitKeyValue(line, k, v))
            m_reply.values[k] = v;
        return false;
    }
    }
    return false;
}

} // namespace imudesk::protocol::hipnuc
