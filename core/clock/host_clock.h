#pragma once
// The host clock every session stamps its samples and raw bytes with: steady_clock, in ns.
// SampleStore ages its values against it and the views align devices on it, so every family
// and transport takes its times from here (or from the time the engine hands it).
#include <chrono>
#include <cstdint>

namespace imudesk::clock {

inline int64_t hostNowNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

} // namespace imudesk::clock

// The sessions and families of core/device call it unqualified, as their own.
namespace imudesk::device {
using clock::hostNowNs;
} // namespace imudesk::device
