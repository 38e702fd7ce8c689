#include "trigger_pairing.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

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
    d.commonNs.push_back(commonNs);
    d.aligned.push_back(aligned);
    d.lastDeviceNs = deviceNs;
}

std::map<int, std::optional<int64_t>> TriggerPairing::bases() const
{
    // The pulses' phase on the common time: the circular mean of every aligned frame's.
    const double period = double(m_periodNs);
    double sx = 0, sy = 0;
    for (const auto &[id, d] : m_devices)
        for (size_t i = 0; i < d.local.size(); ++i)
            if (d.aligned[i]) {
                const double a = 2 * std::numbers::pi * double(((d.commonNs[i] % m_periodNs) + m_periodNs) % m_periodNs) / period;
                sx += std::cos(a);
                sy += std::sin(a);
            }
    const double phaseNs = std::atan2(sy, sx) / (2 * std::numbers::pi) * period;
    std::map<int, std::optional<int64_t>> out;
    for (const auto &[id, d] : m_devices) {
        std::vector<int64_t> votes;
        for (size_t i = 0; i < d.local.size(); ++i)
            if (d.aligned[i])
                votes.push_back(std::llround((double(d.commonNs[i]) - phaseNs) / period) - d.local[i]);
        if (votes.empty()) {
            out[id] = std::nullopt;
            continue;
        }
        std::nth_element(votes.begin(), votes.begin() + std::ptrdiff_t(votes.size() / 2), votes.end());
        out[id] = votes[votes.size() / 2];
    }
    return out;
}

std::vector<std::optional<int64_t>> TriggerPairing::indices(int device) const
{
    std::vector<std::optional<int64_t>> out;
    const auto it = m_devices.find(device);
    if (it == m_devices.end())
        return out;
    const std::optional<int64_t> base = bases()[device];
    out.reserve(it->second.local.size());
    for (int64_t l : it->second.local)
        out.push_back(base ? std::optional<int64_t>(l + *base) : std::nullopt);
    return out;
}

TriggerPairing::Summary TriggerPairing::summary() const
{
    Summary s;
    s.devices = int(m_devices.size());
    const auto base = bases();
    std::map<int64_t, int> seen; // pulse index -> devices with a frame of it
    for (const auto &[id, d] : m_devices) {
        s.frames += int64_t(d.local.size());
        const std::optional<int64_t> b = base.at(id);
        if (!b) {
            s.unindexed += int64_t(d.local.size());
            continue;
        }
        int64_t previous = INT64_MIN;
        for (int64_t l : d.local) {
            const int64_t index = l + *b;
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
        if (const std::optional<int64_t> b = base.at(id))
            for (int64_t l : d.local)
                if (seen[l + *b] > 1)
                    ++s.framesPaired;
    return s;
}

} // namespace imudesk::clock
