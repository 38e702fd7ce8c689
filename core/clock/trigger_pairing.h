#pragma once
// Hardware trigger mode (issue 36 point 5): modules that share a SYNC_IN edge (v1.7.1 manual
// 2.2.1, LOG <MSG> ONMARK 1) send one frame per rising edge, and CANopen modules one TPDO per
// SYNC. TriggerPairing gives every such frame the index of the pulse that made it, the same on
// every device, so that the frames of one pulse are paired whatever their arrival order.
//
// Within a device the index follows its own counter: consecutive frames are as many pulses
// apart as their device times are periods apart (a frame lost on the way leaves a gap, it does
// not shift what follows). Across devices the counts are tied by the common time (core/clock) of
// the frames that came while the device's clock model was aligned: the common times of one
// pulse agree to well under a millisecond, a pulse period is several, so the nearest period is
// the pulse. Robustly: the pulses' phase on the common time is the circular mean over every
// aligned frame, and each device's base is the median over its aligned frames, so a frame whose
// time was off (the model's first seconds, a delayed read) does not shift a device's count.
// Frames that came before the model was aligned are indexed from the same base.
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace imudesk::clock {

class TriggerPairing {
public:
    // pulsePeriodNs: the time between two edges (the host's SYNC period, the pulse source's).
    explicit TriggerPairing(int64_t pulsePeriodNs);

    // A triggered frame of a device: its device time (ns, unwrapped: CounterUnwrapper), its
    // common time and whether the device's clock model is aligned.
    void add(int device, int64_t deviceNs, int64_t commonNs, bool aligned);

    // The pulse index of each frame of a device, in the order they were added; nullopt while
    // the device's clock model has not been aligned yet.
    std::vector<std::optional<int64_t>> indices(int device) const;

    struct Summary {
        int devices = 0;
        int64_t pulses = 0;       // distinct indices seen
        int64_t complete = 0;     // indices every device has a frame for
        int64_t frames = 0;       // frames added
        int64_t framesPaired = 0; // frames whose index another device has too
        int64_t unindexed = 0;    // frames of devices never aligned
    };
    Summary summary() const;
    int64_t pulsePeriodNs() const { return m_periodNs; }

private:
    struct Device {
        std::vector<int64_t> local;   // index within the device, from its counter
        std::vector<int64_t> commonNs; // each frame's common time
        std::vector<bool> aligned;
        int64_t lastDeviceNs = 0;
    };
    // local index + base = pulse index, per device (nullopt: never aligned); worked out on demand.
    std::map<int, std::optional<int64_t>> bases() const;
    int64_t m_periodNs;
    std::map<int, Device> m_devices;
};

} // namespace imudesk::clock
