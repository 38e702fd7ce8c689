#pragma once
// Fast, locale-independent number text for CSV and JSON exports: the shortest text that
// reads back to the same float or double (std::to_chars), so an export re-imports to the
// exact values. Non-finite values are written as an empty field.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>

namespace imudesk::format::csv {

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

// Fixed-point text with `decimals` digits after the point (0..9), e.g. times in s to the µs.
inline void appendFixed(std::string &out, double v, int decimals)
{
    if (!std::isfinite(v))
        return;
    static constexpr int64_t kScale[] = {1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000, 1000000000};
    const int64_t scale = kScale[decimals];
    const double scaled = std::round(v * double(scale));
    if (std::abs(scaled) > 9e18) {
        appendNumber(out, v);
        return;
    }
    int64_t q = int64_t(scaled);
    if (q < 0) {
        out += '-';
        q = -q;
    }
    appendInt(out, q / scale);
    if (decimals == 0)
        return;
    char frac[10];
    int64_t r = q % scale;
    for (int i = decimals - 1; i >= 0; --i) {
        frac[i] = char('0' + r % 10);
        r /= 10;
    }
    out += '.';
    out.append(frac, size_t(decimals));
}

} // namespace imudesk::format::csv
