#pragma once
// Packed BCD values of the Witlink protocol (manual 2.1, 2.4, 2.6).
//
// Angle, 3 bytes "SX XX YY": S = sign nibble (0 positive, 1 negative), then three integer
// digits, YY two decimals: 10 26 80 = -26.80 deg, 00 33 65 = 33.65, 03 13 71 = 313.71.
// Declination, 2 bytes "SX XY": sign nibble, two integer digits, one decimal:
// 02 08 = +20.8 deg, 10 32 = -3.2 deg.
#include <array>
#include <cstdint>
#include <optional>

namespace imudesk::protocol::witlink {

inline constexpr double kMaxAngle = 999.99;
inline constexpr double kMaxDeclination = 99.9;

// nullopt when a digit nibble is above 9 or the sign nibble is neither 0 nor 1.
std::optional<double> decodeAngle(const uint8_t *p);
std::optional<double> decodeDeclination(const uint8_t *p);
// Rounded to the format's resolution; nullopt when |value| exceeds the format or is not finite.
std::optional<std::array<uint8_t, 3>> encodeAngle(double deg);
std::optional<std::array<uint8_t, 2>> encodeDeclination(double deg);

} // namespace imudesk::protocol::witlink
