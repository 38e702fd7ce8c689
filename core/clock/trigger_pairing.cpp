#include "trigger_pairing.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace imudesk::clock {

TriggerPairing::TriggerPairing(int64_t pulsePeriodNs) : m_periodNs(pulsePeriodNs > 0 ? pulsePeriodNs : 1) {}

void TriggerPairing::add(int device, int64_t deviceNs, int64_t commonNs, bool aligned)
{
    Device &d = m_devices[device];
    int64_t local = 0;
    if (!d.local.empty()) {
        const double steps = double(deviceNs - d.lastDeviceNs) / double(m_periodNs);
        local = d.local.back() + std::max<int64_t>(1, std::llround(steps));
    }
    d.local.push_back(local);
    d.lastDeviceNs = deviceNs;
    if (aligned && !d.base) {
        if (!m_epochNs)
            m_epochNs = commonNs;
        const int64_t index = std::llround(double(commonNs - *m_epochNs) / double(m_periodNs));
        d.base = index - local;
    }
}

std::vector<std::optional<int64_t>> TriggerPairing::indices(int device) const
{
    std::vector<std::optional<int64_t>> out;
    const auto it = m_devices.find(device);
    if (it == m_devices.end())
        return out;
    const Device &d = it->second;
    out.reserve(d.local.size());
    for (int64_t l : d.local)
        out.push_back(d.base ? std::optional<int64_t>(l + *d.base) : std::nullopt);
    return out;
}

TriggerPairing::Summary TriggerPairing::summary() const
{
    Summary s;
    s.devices = int(m_devices.size());
    std::map<int64_t, int> seen; // pulse index -> devices with a frame of it
    for (const auto &[id, d] : m_devices) {
        s.frames += int64_t(d.local.size());
        if (!d.base) {
            s.unindexed += int64_t(d.local.size());
            continue;
        }
        int64_t previous = INT64_MIN;
        for (int64_t l : d.local) {
            const int64_t index = l + *d.base;
            if (index != previous) // a device counts once per pulse
                ++seen[index];
            previous = index;
        }
    }
    s.pulses = int64_t(seen.size());
    for (const auto &[index, n] : seen)
        if (n == s.devices)
            ++s.complete;
    for (const auto &[id, d] : m_devices)
        if (d.base)
            for (int64_t l : d.local)
                if (seen[l + *d.base] > 1)
                    ++s.framesPaired;
    return s;
}

} // namespace imudesk::clock
