#pragma once
// The clock of a simulated device and the USB adapter between it and the host (issue 36
// point 6), so that what ImuDesk makes of device times and arrival times can be measured
// against the truth.
//
// True time is the host's (the simulation's) clock. A device's oscillator is off by an offset
// and a drift, and may step once (a counter set anew): its own time runs as
//     device(t) = t * (1 + driftPpm * 1e-6) + offset  (+ step from stepAt on)
// and everything it schedules (its output periods, its system_time counter) is on that time,
// while the motion it measures happens in true time.
//
// A USB serial adapter does not pass bytes on as they arrive: an FTDI chip holds them until
// its latency timer runs out (16 ms by default) or a USB packet is full, and the host's USB
// stack and reading thread add their own jitter. AdapterLatency models the timer (the bytes
// received since the last expiry are released together), an optional packet size, a fixed
// delay (a hub, the driver) and a random jitter per release.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

namespace imudesk::sim {

struct ClockError {
    double offsetUs = 0;  // device time at true time 0
    double driftPpm = 0;  // + : the device's clock runs fast
    double stepAtS = -1;  // true time of a step of the device's clock; < 0: none
    double stepUs = 0;    // the step, >= 0: the device's time jumps forward (a step back is not modelled)

    bool isIdeal() const { return offsetUs == 0 && driftPpm == 0 && (stepAtS < 0 || stepUs == 0); }
    double rate() const { return 1.0 + driftPpm * 1e-6; }
    // The device's time (µs) at true time trueUs, and back.
    int64_t deviceUs(int64_t trueUs) const;
    int64_t trueUs(int64_t deviceUs) const;
    friend bool operator==(const ClockError &, const ClockError &) = default;
};

struct AdapterLatency {
    double latencyTimerMs = 0; // 0: bytes pass at once (a UART on the host's own board)
    size_t packetBytes = 0;    // > 0: a full packet of this many bytes goes at once
    double fixedUs = 0;        // added to every release
    double jitterUs = 0;       // uniform 0..jitterUs added to every release
    double phaseUs = 0;        // where the adapter's timer stands at true time 0
    uint64_t seed = 1;

    bool isIdeal() const { return latencyTimerMs == 0 && packetBytes == 0 && fixedUs == 0 && jitterUs == 0; }
    friend bool operator==(const AdapterLatency &, const AdapterLatency &) = default;
};

// Bytes into the adapter at their true time, out at the time the host receives them.
class AdapterBatcher {
public:
    explicit AdapterBatcher(AdapterLatency latency = {});
    // Bytes that reached the adapter at trueUs (times never go back).
    void push(const uint8_t *data, size_t n, int64_t trueUs);
    // The bytes the host has received by trueUs, in order, each run with its release time.
    struct Release {
        int64_t hostUs = 0;
        std::vector<uint8_t> bytes;
    };
    std::vector<Release> take(int64_t trueUs);
    size_t held() const { return m_held.size(); }
    const AdapterLatency &latency() const { return m_l; }

private:
    int64_t timerExpiryAfter(int64_t trueUs) const;
    double nextJitter();
    void release(int64_t atUs, size_t count);

    AdapterLatency m_l;
    std::deque<uint8_t> m_held;
    int64_t m_heldSinceUs = -1;
    std::deque<Release> m_released;
    uint64_t m_rng;
};

} // namespace imudesk::sim
