#include "bcd.h"

#include <cmath>

namespace imudesk::protocol::witlink {

namespace {

// Nibbles of n bytes, high first; nullopt unless the first is a sign (0/1) and the rest digits.
template <size_t N>
std::optional<std::array<int, 2 * N>> nibbles(const uint8_t *p)
{
    std::array<int, 2 * N> d{};
    for (size_t i = 0; i < N; ++i) {
        d[2 * i] = p[i] >> 4;
        d[2 * i + 1] = p[i] & 0x0F;
    }
    if (d[0] > 1)
        return std::nullopt;
    for (size_t i = 1; i < d.size(); ++i)
        if (d[i] > 9)
            return std::nullopt;
    return d;
}

// |deg| in units of the resolution (1/scale), or -1 when out of range.
long long scaled(double deg, double scale, double max)
{
    if (!std::isfinite(deg))
        return -1;
    const long long v = std::llround(std::fabs(deg) * scale);
    if (v > std::llround(max * scale))
        return -1;
    return v;
}

} // namespace

std::optional<double> decodeAngle(const uint8_t *p)
{
    const auto d = nibbles<3>(p);
    if (!d)
        return std::nullopt;
    const int v = (*d)[1] * 10000 + (*d)[2] * 1000 + (*d)[3] * 100 + (*d)[4] * 10 + (*d)[5];
    const double deg = v / 100.0;
    return (*d)[0] ? -deg : deg;
}

std::optional<double> decodeDeclination(const uint8_t *p)
{
    const auto d = nibbles<2>(p);
    if (!d)
        return std::nullopt;
    const int v = (*d)[1] * 100 + (*d)[2] * 10 + (*d)[3];
    const double deg = v / 10.0;
    return (*d)[0] ? -deg : deg;
}

std::optional<std::array<uint8_t, 3>> encodeAngle(double deg)
{
    const long long v = scaled(deg, 100.0, kMaxAngle);
    if (v < 0)
        return std::nullopt;
    const int s = (deg < 0 && v != 0) ? 1 : 0;
    const int d[5] = {int(v / 10000 % 10), int(v / 1000 % 10), int(v / 100 % 10), int(v / 10 % 10), int(v % 10)};
    return std::array<uint8_t, 3>{uint8_t(s << 4 | d[0]), uint8_t(d[1] << 4 | d[2]), uint8_t(d[3] << 4 | d[4])};
}

std::optional<std::array<uint8_t, 2>> encodeDeclination(double deg)
{
    const long long v = scaled(deg, 10.0, kMaxDeclination);
    if (v < 0)
        return std::nullopt;
    const int s = (deg < 0 && v != 0) ? 1 : 0;
    const int d[3] = {int(v / 100 % 10), int(v / 10 % 10), int(v % 10)};
    return std::array<uint8_t, 2>{uint8_t(s << 4 | d[0]), uint8_t(d[1] << 4 | d[2])};
}

} // namespace imudesk::protocol::witlink
