#pragma once
// A device's free-running counter (HI91 system_time in ms, a u32; HI83 system_time_us) made
// into a monotonic device time in ns. A value below the last one is a wrap when the last one
// was near the counter's top and the new one near its bottom (within maxGap of each other
// across the wrap); any other step back is a reset of the counter (the module restarted),
// which starts a new epoch: the caller's clock model starts again there.
#include <cstdint>

namespace imudesk::clock {

class CounterUnwrapper {
public:
    // modulus: the number of counter values (2^32 for a u32); tickNs: one count in ns;
    // maxGapNs: the longest silence a wrap may hide (a longer one cannot be told from a reset).
    CounterUnwrapper(uint64_t modulus, int64_t tickNs, int64_t maxGapNs = 60'000'000'000);

    struct Result {
        int64_t deviceNs = 0; // since the counter's zero in this epoch
        bool reset = false;   // this value started a new epoch
    };
    Result feed(uint64_t raw);

    int wraps() const { return m_wrapsTotal; }
    int resets() const { return m_resets; } // also the epoch: 0 until the first reset
    void clear();

private:
    uint64_t m_modulus;
    int64_t m_tickNs;
    uint64_t m_maxGapTicks;
    bool m_started = false;
    uint64_t m_last = 0;
    int64_t m_wraps = 0; // in this epoch
    int m_wrapsTotal = 0;
    int m_resets = 0;
};

} // namespace imudesk::clock
