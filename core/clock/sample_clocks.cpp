#include "sample_clocks.h"

#include <algorithm>
#include <cmath>

namespace imudesk::clock {

namespace {
// The counter behind a frame type's device time: its unit and how many values it has.
struct CounterSpec {
    int64_t tickNs;
    uint64_t modulus;
};
CounterSpec specOf(const std::string &source)
{
    if (source == "HI81")
        return {1'000'000, 604'800'000}; // GPS time of week, ms
    if (source == "HI83")
        return {1'000, uint64_t(1) << 52}; // system_time_us: 64 bits, kept in a double's mantissa
    return {1'000'000, uint64_t(1) << 32}; // system_time in ms, a u32 (HI91, HI92 and the others)
}
} // namespace

void SampleClocks::stamp(model::Sample &s, int timeBase, int64_t wireNs, int64_t earlierBoundNs)
{
    if (!s.has(model::FieldDeviceTime))
        return;
    if (const auto t = commonTime(s.source, s.deviceTimeMs, s.hostTimeNs, timeBase, wireNs, earlierBoundNs))
        s.commonTimeNs = *t;
}

std::optional<int64_t> SampleClocks::commonTime(const std::string &source, double deviceTimeMs, int64_t hostNs,
                                                int timeBase, int64_t wireNs, int64_t earlierBoundNs)
{
    if (hostNs == 0 || !std::isfinite(deviceTimeMs) || deviceTimeMs < 0)
        return std::nullopt;
    auto it = m_streams.find(source);
    if (it == m_streams.end()) {
        const CounterSpec spec = specOf(source);
        it = m_streams.emplace(source, Clock{CounterUnwrapper(spec.modulus, spec.tickNs), spec.tickNs, ClockModel(),
                                             timeBase, 0})
                 .first;
    }
    Clock &c = it->second;
    const int restartsBefore = c.restarts;
    if (timeBase != c.timeBase) { // another clock behind the same field: start again
        c.timeBase = timeBase;
        c.counter.clear();
        c.model.reset();
        ++c.restarts;
    }
    const auto raw = uint64_t(std::llround(deviceTimeMs * 1e6 / double(c.tickNs)));
    const CounterUnwrapper::Result u = c.counter.feed(raw);
    if (u.reset) {
        c.model.reset();
        ++c.restarts;
    }
    if (c.restarts != restartsBefore)
        c.lastDeviceNs = -1; // a new epoch: nothing to stay in order with
    c.model.add(u.deviceNs, std::min(hostNs - wireNs, earlierBoundNs));
    std::optional<int64_t> t = c.model.toHost(u.deviceNs);
    if (!t)
        return t;
    if (c.lastDeviceNs >= 0 && u.deviceNs > c.lastDeviceNs)
        t = std::max(*t, c.lastCommonNs + (u.deviceNs - c.lastDeviceNs) / 2);
    c.lastDeviceNs = u.deviceNs;
    c.lastCommonNs = *t;
    return t;
}

std::vector<SampleClocks::Stream> SampleClocks::streams() const
{
    std::vector<Stream> out;
    for (const auto &[source, c] : m_streams)
        out.push_back(Stream{source, c.model.fit(), c.model.state(), c.restarts});
    return out;
}

} // namespace imudesk::clock
