#pragma once
// Counts frames lost on a link from gaps in the device's own timestamps (HI91
// system_time, HI83 system_time_us, ...), per frame type. Plain C++, no Qt.
//
// How it works, per frame type:
//   * Learning: the nominal period is learned from the last kLearnDeltas intervals:
//     a trimmed mean for a first guess, then the slot count over the window whose grid
//     fits the stamps best, and the least-squares slope over it (ms rounding averages
//     out); snapped to whole ms, as ONTIME periods are. A window that is not regular
//     (ONMARK, bursts) is not learned from; it slides on. The grid is anchored at the
//     window's median phase and follows the stamps' mean phase slowly.
//   * Counting: every frame is placed on the period's grid; the deficit is
//     slots elapsed - frames received since the grid was anchored, so jitter never
//     accumulates (a late stamp followed by an early one adds nothing). A loss is
//     committed once both the minimum and the median of the deficit over the
//     confirmation window have risen (12 frames; 64 when the stamp jitter is comparable
//     to the period, as at 1 kHz with ms stamps: there the deficit flickers between two
//     values, and either may be the rare one). The count only grows.
//   * Rate changes: when most recent frames fall off the grid (a new period that is not
//     a multiple), or most recent intervals are whole multiples of the period and the
//     deficit ramps instead of stepping (output slowed down), or frames come faster
//     than the grid allows (output sped up), the period is learned again and the
//     deficit not yet committed is dropped: a rate change is not a loss.
//   * Assumes each stamp is within about kJitterMs of its slot (ms rounding, the frame
//     lagging the tick); much noisier stamps at periods of a few ms can be misread.
//   * A backwards jump (more than the jitter) is a device reset: counted as a reset,
//     never as a loss, and the period is learned again. (The 32-bit ms counter wrapping
//     after 49.7 days looks the same.)
//   * resetTiming(): the owner knows output was reconfigured (LOG DISABLE/ENABLE, a new
//     ONTIME, REBOOT, a baud change, a reconnection): the gap across it is not counted.
//   * setExpectedPeriod(): the configured period, for a link too slow to carry it: the
//     frames that do arrive no longer show the period (at 115200 baud a 1 kHz HI91
//     stream arrives every 7-8 ms), so it cannot be learned. While a type has an
//     expected period, slower output counts as loss; faster output drops the hint.
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace imudesk::device {

class FrameGapCounter {
public:
    static constexpr int kLearnDeltas = 16;      // intervals needed to learn a period
    static constexpr double kJitterMs = 1.0;     // a stamp may sit this far from its slot (ms rounding, latency)
    static constexpr int kConfirmFrames = 12;    // frames a deficit must hold before it counts
    static constexpr int kConfirmFramesJittery = 64;
    static constexpr int kRateWindow = 8;        // frames that reveal a rate change

    // Feeds one frame's device timestamp in ms. Returns the frames newly counted as lost.
    // timeBase names the clock the stamps count on (HiPNUC: 1 while MAIN_STATUS has
    // UTC_UNSYNC, the time since power-on; 0 once PPS aligned it to the UTC day, v1.7.1
    // manual 2.2.2): when it changes, the jump between the two clocks is not a loss.
    uint64_t add(const std::string &type, double deviceTimeMs, int timeBase = 0);

    // Forgets the period and grid of every type (or one type); counts and expected
    // periods are kept. A loss that held for the last few frames is counted first.
    void resetTiming();
    void resetTiming(const std::string &type);
    // The period the device was configured to (ms); 0 clears it. Takes effect at once
    // (the grid is anchored at the next frame).
    void setExpectedPeriod(const std::string &type, double periodMs);
    // Forgets everything, counts included.
    void clear();

    uint64_t lost() const { return m_lost; }
    uint64_t lost(const std::string &type) const;
    const std::map<std::string, uint64_t> &lostByType() const { return m_lostByType; }
    // Backwards jumps of the device time (resets).
    uint64_t resets() const { return m_resets; }
    // Times a type's output rate changed and its period was learned again.
    uint64_t rateChanges(const std::string &type) const;
    // The period in use for a type (ms), once learned or expected.
    std::optional<double> period(const std::string &type) const;

private:
    struct Step {
        int64_t deficit = 0;
        int64_t slots = 0;     // slots this frame advanced the grid by
        bool offGrid = false;  // farther from its slot than the jitter allows
    };
    struct Track {
        bool havePrev = false;
        double prev = 0;
        int timeBase = 0;
        double expected = 0;          // hint, 0 = none
        // learning
        std::vector<double> learnTimes;
        // counting
        bool locked = false;
        bool snapped = false;         // period is exact (whole ms): never refined
        double period = 0;
        double origin = 0;            // grid time of slot 0
        int64_t slots = 0;            // slot of the last frame
        int64_t frames = 0;           // frames after the origin frame
        int confirm = kConfirmFrames; // confirmation window
        bool calibrating = false;     // jittery: the first window sets the references
        int64_t minRef = 0;           // minimum and median of the deficit, losses accounted for
        int64_t medRef = 0;
        std::deque<Step> history;     // newest last, at most kConfirmFramesJittery
        uint64_t lost = 0;
        uint64_t rateChanges = 0;
    };

    static void begin(Track &k, double t);
    static uint64_t tryLock(Track &k);
    static void lock(Track &k, double period, double origin, bool jittery);
    static uint64_t step(Track &k, double t);
    static uint64_t commitPending(Track &k);
    uint64_t account(const std::string &type, Track &k, uint64_t n);

    std::map<std::string, Track> m_tracks;
    std::map<std::string, uint64_t> m_lostByType;
    uint64_t m_lost = 0;
    uint64_t m_resets = 0;
};

} // namespace imudesk::device
