#pragma once
// Fast, locale-independent number text for CSV and JSON exports: the shortest text that
// reads back to the same float or double (std::to_chars), so an export re-imports to the
// exact values. Non-finite values are written as an empty field.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>

namespace imudesk::record::csv {

inline void appendNumber(std::string &out, float v)
{
    if (!std::isfinite(v))
        return;
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, r.ptr);
}

inline void appendNumber(std::string &out, double v)
{
    if (!std::isfinite(v))
        return;
    char buf[40];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, r.ptr);
}

inline void appendInt(std::string &out, int64_t v)
{
    char buf[24];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, r.ptr);
}

} // namespace imudesk::record::csv
