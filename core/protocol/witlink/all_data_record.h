#pragma once
// The 84-byte data field of the "read all" reply (manual 2.5, command 0x14, LEN 0x58):
// 21 little-endian fields of 4 bytes, in this order:
//   pitch, roll, heading (deg; pitch +-90, roll and heading +-180)
//   accx, accy, accz (g)
//   magx, magy, magz (relative: the horizontal northward field is 1)
//   gyrox, gyroy, gyroz (deg/s)
//   magroll (magnetic tool face, deg)
//   seven reserved words (the manual lists "res" seven times; 13 + 7 + 1 = 21 fields)
//   time (ms, u32); every other field is an IEEE-754 float.
#include "model/sample.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace imudesk::protocol::witlink {

struct AllDataRecord {
    static constexpr size_t kSize = 84;
    static constexpr size_t kReserved = 7;

    float pitch = 0, roll = 0, heading = 0;
    std::array<float, 3> acc{}, mag{}, gyr{};
    float magRoll = 0;
    std::array<float, kReserved> reserved{};
    uint32_t timeMs = 0;

    // nullopt unless n == kSize.
    static std::optional<AllDataRecord> decode(const uint8_t *p, size_t n);
    std::vector<uint8_t> encode() const;

    // A Sample (source "HEC495"): Euler angles (yaw = the device's heading, clockwise from
    // north), acc in G, gyr in deg/s, device time, the relative magnetic field (magRelative:
    // not in uT, so never in Sample::mag) and the magnetic roll.
    model::Sample toSample(int64_t hostTimeNs = 0) const;

    friend bool operator==(const AllDataRecord &, const AllDataRecord &) = default;
};

} // namespace imudesk::protocol::witlink
