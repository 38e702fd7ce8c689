#pragma once
// The clocks of one device's sample streams: each frame type with a device time (HI91's
// system_time in ms, HI81's GPS time of week, HI83's µs counter, ...) gets its counter made
// monotonic and its own ClockModel, and every such sample is stamped with its common time
// (Sample::commonTimeNs). A time base that changes (the module's clock aligned to UTC by a PPS
// input) or a counter reset starts that stream's model again.
// A stream's common time never steps back: when its line moves down (a sample that waited
// less than every one before), later samples advance at half their device pace until they
// meet the line again, so a live view or a file gets its samples in order.
#include "clock/clock_model.h"
#include "clock/counter_unwrapper.h"
#include "model/sample.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace imudesk::clock {

class SampleClocks {
public:
    // timeBase: what the device time counts (0 since power-up, 1 UTC time of day, as
    // model::MainStatus::timeBase says); a change restarts the stream's model.
    // What bounds the sampling instant from above (the model's input, clock_model.h): the
    // sample's arrival less wireNs, the frame's own time on the wire (its bytes x 10 / baud);
    // and earlierBoundNs when part of the frame came with an earlier read: that read's time less
    // the time its bytes of the frame took (a USB adapter that releases its buffer when its
    // timer runs out cuts frames anywhere, and the cut tells where the frame stood on the wire
    // then, which the complete frame's arrival does not).
    void stamp(model::Sample &s, int timeBase = 0, int64_t wireNs = 0, int64_t earlierBoundNs = INT64_MAX);
    // The same for a device time and arrival alone: the common time, nullopt without one.
    std::optional<int64_t> commonTime(const std::string &source, double deviceTimeMs, int64_t hostNs, int timeBase = 0,
                                      int64_t wireNs = 0, int64_t earlierBoundNs = INT64_MAX);

    struct Stream {
        std::string source;
        ClockFit fit;
        ClockModel::State state = ClockModel::State::FreeRunning;
        int resets = 0; // counter resets and time-base changes seen
    };
    std::vector<Stream> streams() const;
    void clear() { m_streams.clear(); }

private:
    struct Clock {
        CounterUnwrapper counter;
        int64_t tickNs = 1'000'000;
        ClockModel model;
        int timeBase = 0;
        int restarts = 0;
        int64_t lastDeviceNs = -1; // the last sample's device time and common time given
        int64_t lastCommonNs = 0;
    };
    std::map<std::string, Clock> m_streams;
};

} // namespace imudesk::clock
