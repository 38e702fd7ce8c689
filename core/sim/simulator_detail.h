#pragma once
// Helpers shared by the HipnucSimulator translation units (text parsing, numbers,
// frames and dates). Internal to core/sim.
#include "hipnuc_simulator.h"

#include "model/main_status.h"
#include "protocol/hipnuc/ascii_command.h"

#include <QLoggingCategory>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace imudesk::sim::detail {


Q_DECLARE_LOGGING_CATEGORY(lcSim)

using protocol::hipnuc::Hi81;
using protocol::hipnuc::Hi83;
using protocol::hipnuc::Hi91;
using protocol::hipnuc::Hi92;
using protocol::hipnuc::Message;
using model::MainStatus;
using model::ManualEdition;

constexpr double kDeg = 0.017453292519943295;
constexpr int64_t kNever = std::numeric_limits<int64_t>::max();

constexpr Message kMessages171[] = {Message::HI91, Message::HI81, Message::HI83, Message::GGA, Message::RMC, Message::SXT};
constexpr Message kMessages166[] = {Message::HI91, Message::HI92};

inline uint64_t mix(uint64_t x)
{
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

inline std::string upper(std::string s)
{
    for (char &c : s)
        c = char(std::toupper(uint8_t(c)));
    return s;
}

inline std::vector<std::string> tokenize(const std::string &line)
{
    std::vector<std::string> out;
    std::string cur;
    for (char c : line) {
        if (c == ' ' || c == '\t' || c == '\r') {
            if (!cur.empty())
                out.push_back(upper(std::move(cur)));
            cur.clear();
        } else {
            cur.push_back(c);
        }
    }
    if (!cur.empty())
        out.push_back(upper(std::move(cur)));
    return out;
}

inline bool parseInt(std::string_view s, int &out)
{
    if (s.empty())
        return false;
    if (s.front() == '+')
        s.remove_prefix(1);
    const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
    return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

inline bool parseDouble(std::string_view s, double &out)
{
    if (s.empty())
        return false;
    if (s.front() == '+')
        s.remove_prefix(1);
    const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
    return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(out);
}

// "0x1F", "0X1F" or decimal.
inline bool parseU32(std::string_view s, uint32_t &out)
{
    int base = 10;
    if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
        s.remove_prefix(2);
        base = 16;
    }
    if (s.empty())
        return false;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), out, base);
    return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

// "COM1".."COM9" -> n; -1 when the word is not a port word ("COMCONFIG").
inline int comNumber(const std::string &w)
{
    if (w.size() < 4 || w.compare(0, 3, "COM") != 0)
        return -1;
    for (size_t i = 3; i < w.size(); ++i)
        if (w[i] < '0' || w[i] > '9')
            return -1;
    int n = 0;
    return parseInt(std::string_view(w).substr(3), n) ? n : -1;
}

// "PMUX2" -> 2, "IO5" -> 5; -1 when the prefix differs, 0 when the number is bad.
inline int suffixNumber(const std::string &w, std::string_view prefix)
{
    if (w.compare(0, prefix.size(), prefix) != 0)
        return -1;
    int n = 0;
    return parseInt(std::string_view(w).substr(prefix.size()), n) ? n : 0;
}

using protocol::hipnuc::commands::formatNumber;

inline int16_t clamp16(double v)
{
    return int16_t(std::clamp(std::lround(v), -32768L, 32767L));
}

inline int32_t round32(double v)
{
    return int32_t(std::clamp<long long>(std::llround(v), std::numeric_limits<int32_t>::min(),
                                         std::numeric_limits<int32_t>::max()));
}

inline Eigen::Matrix3d toEigen(const model::Matrix3 &m)
{
    Eigen::Matrix3d r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r(i, j) = m[size_t(i)][size_t(j)];
    return r;
}

inline Eigen::Quaterniond qAxis(double deg, const Eigen::Vector3d &axis)
{
    return Eigen::Quaterniond(Eigen::AngleAxisd(deg * kDeg, axis));
}

// ENU -> NWU: N = ENU y, W = -ENU x, U = ENU z.
inline Eigen::Quaterniond enuToNwu()
{
    Eigen::Matrix3d t;
    t << 0, 1, 0, -1, 0, 0, 0, 0, 1;
    return Eigen::Quaterniond(t);
}

// Days since 1970-01-01 -> civil date (Howard Hinnant's algorithm).
inline void civilFromDays(int64_t z, int &y, int &m, int &d)
{
    z += 719468;
    const int64_t era = (z >= 0 ? z : z - 146096) / 146097;
    const int64_t doe = z - era * 146097;
    const int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    const int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    const int64_t mp = (5 * doy + 2) / 153;
    d = int(doy - (153 * mp + 2) / 5 + 1);
    m = int(mp < 10 ? mp + 3 : mp - 9);
    y = int(yoe + era * 400 + (m <= 2 ? 1 : 0));
}

inline HipnucSimulator::MessageSetting onTime(int ms)
{
    HipnucSimulator::MessageSetting s;
    s.mode = HipnucSimulator::MessageSetting::Mode::OnTime;
    s.periodMs = ms;
    return s;
}

} // namespace imudesk::sim::detail
