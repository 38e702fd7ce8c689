#include "sim_clock.h"

#include <algorithm>
#include <cmath>

namespace imudesk::sim {

int64_t ClockError::deviceUs(int64_t trueUs) const
{
    double d = double(trueUs) * rate() + offsetUs;
    if (stepAtS >= 0 && double(trueUs) >= stepAtS * 1e6)
        d += stepUs;
    return int64_t(std::llround(d));
}

int64_t ClockError::trueUs(int64_t deviceUs) const
{
    double d = double(deviceUs) - offsetUs;
    if (stepAtS >= 0) {
        // The device's time at the step, after it: a device time past it is on the stepped side.
        const double stepped = stepAtS * 1e6 * rate() + stepUs;
        if (d >= stepped)
            d -= stepUs;
    }
    return int64_t(std::llround(d / rate()));
}

AdapterBatcher::AdapterBatcher(AdapterLatency latency) : m_l(latency), m_rng(latency.seed * 0x9E3779B97F4A7C15ull + 1) {}

int64_t AdapterBatcher::timerExpiryAfter(int64_t trueUs) const
{
    const double period = m_l.latencyTimerMs * 1000;
    if (period <= 0)
        return trueUs;
    const double k = std::floor((double(trueUs) - m_l.phaseUs) / period) + 1;
    return int64_t(std::llround(m_l.phaseUs + k * period));
}

double AdapterBatcher::nextJitter()
{
    if (m_l.jitterUs <= 0)
        return 0;
    m_rng ^= m_rng >> 12;
    m_rng ^= m_rng << 25;
    m_rng ^= m_rng >> 27;
    const double u = double((m_rng * 0x2545F4914F6CDD1Dull) >> 11) * (1.0 / 9007199254740992.0);
    return u * m_l.jitterUs;
}

void AdapterBatcher::release(int64_t atUs, size_t count)
{
    Release r;
    r.hostUs = atUs + int64_t(std::llround(m_l.fixedUs + nextJitter()));
    // The host reads the adapter's packets in the order they were sent.
    if (!m_released.empty())
        r.hostUs = std::max(r.hostUs, m_released.back().hostUs);
    r.bytes.assign(m_held.begin(), m_held.begin() + std::ptrdiff_t(count));
    m_held.erase(m_held.begin(), m_held.begin() + std::ptrdiff_t(count));
    m_released.push_back(std::move(r));
}

void AdapterBatcher::push(const uint8_t *data, size_t n, int64_t trueUs)
{
    // What the timer released before these bytes came.
    if (!m_held.empty() && m_l.latencyTimerMs > 0) {
        const int64_t expiry = timerExpiryAfter(m_heldSinceUs);
        if (expiry <= trueUs)
            release(expiry, m_held.size());
    }
    for (size_t i = 0; i < n; ++i) {
        if (m_held.empty())
            m_heldSinceUs = trueUs;
        m_held.push_back(data[i]);
        if (m_l.packetBytes > 0 && m_held.size() >= m_l.packetBytes)
            release(trueUs, m_l.packetBytes);
    }
    if (m_l.latencyTimerMs <= 0 && !m_held.empty())
        release(trueUs, m_held.size());
}

std::vector<AdapterBatcher::Release> AdapterBatcher::take(int64_t trueUs)
{
    if (!m_held.empty() && m_l.latencyTimerMs > 0) {
        const int64_t expiry = timerExpiryAfter(m_heldSinceUs);
        if (expiry <= trueUs)
            release(expiry, m_held.size());
    }
    std::vector<Release> out;
    while (!m_released.empty() && m_released.front().hostUs <= trueUs) {
        out.push_back(std::move(m_released.front()));
        m_released.pop_front();
    }
    return out;
}

} // namespace imudesk::sim
