#include "ascii_reply.h"

#include <algorithm>
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

LineKind classifyLine(std::string_view raw)
{
    const auto line = trim(raw);
    if (line == "OK")
        return LineKind::Ok;
    if (startsWithWord(line, "ERROR") || startsWithWord(line, "ERR") || startsWithWord(line, "FAIL"))
        return LineKind::Error;
    return LineKind::Info;
}

namespace {

std::string normalisedKey(std::string_view key)
{
    std::string out;
    bool blank = false;
    for (char c : key) {
        if (std::isspace(uint8_t(c))) {
            blank = !out.empty();
            continue;
        }
        if (blank)
            out.push_back('_');
        blank = false;
        out.push_back(char(std::toupper(uint8_t(c))));
    }
    return out;
}

bool keyChar(char c)
{
    return std::isalnum(uint8_t(c)) || c == '_' || c == '.' || c == '-';
}

} // namespace

std::vector<std::pair<std::string, std::string>> keyValuePairs(std::string_view raw)
{
    std::vector<std::pair<std::string, std::string>> out;
    const auto line = trim(raw);
    // '=' separates keys from values; in a line without one, ':'.
    const char sep = line.find('=') != std::string_view::npos ? '=' : ':';
    if (sep == ':' && std::count(line.begin(), line.end(), ':') == 1) {
        // "Key: value", the key perhaps of several words ("Att mode: 1").
        const size_t colon = line.find(':');
        if (colon == 0)
            return out;
        const std::string key = normalisedKey(line.substr(0, colon));
        const auto value = trim(line.substr(colon + 1));
        if (!key.empty() && std::isalpha(uint8_t(key.front())))
            out.emplace_back(key, std::string(value));
        return out;
    }
    // The starts of the pairs: a key (a letter, then letters, digits, '_', '.' or '-') at the start
    // or after a blank, ';' or ',', then blanks and '='.
    struct Start {
        size_t key, eq;
    };
    std::vector<Start> starts;
    for (size_t i = 0; i < line.size(); ++i) {
        if (!std::isalpha(uint8_t(line[i])) || (i > 0 && !std::isspace(uint8_t(line[i - 1])) && line[i - 1] != ';'
                                                 && line[i - 1] != ','))
            continue;
        size_t j = i;
        while (j < line.size() && keyChar(line[j]))
            ++j;
        size_t eq = j;
        while (eq < line.size() && std::isspace(uint8_t(line[eq])))
            ++eq;
        if (eq < line.size() && line[eq] == sep) {
            starts.push_back({i, eq});
            i = eq;
        }
    }
    if (starts.empty() || starts.front().key != 0)
        return out; // text before the first key: not a line of pairs
    for (size_t k = 0; k < starts.size(); ++k) {
        const size_t end = k + 1 < starts.size() ? starts[k + 1].key : line.size();
        std::string_view value = trim(line.substr(starts[k].eq + 1, end - starts[k].eq - 1));
        if (k + 1 < starts.size())
            while (!value.empty() && (value.back() == ';' || value.back() == ','))
                value = trim(value.substr(0, value.size() - 1));
        out.emplace_back(normalisedKey(line.substr(starts[k].key, starts[k].eq - starts[k].key)), std::string(value));
    }
    return out;
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
        m_reply.status = AsciiReply::Status::Refused;
        m_reply.errorLine = std::string(line);
        return true;
    case LineKind::Info: {
        m_reply.lines.emplace_back(line);
        for (auto &[k, v] : keyValuePairs(line))
            m_reply.values[std::move(k)] = std::move(v);
        return false;
    }
    }
    return false;
}

} // namespace imudesk::protocol::hipnuc
