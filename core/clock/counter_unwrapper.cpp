#include "counter_unwrapper.h"

#include <algorithm>

namespace imudesk::clock {

CounterUnwrapper::CounterUnwrapper(uint64_t modulus, int64_t tickNs, int64_t maxGapNs)
    : m_modulus(std::max<uint64_t>(modulus, 2)), m_tickNs(std::max<int64_t>(tickNs, 1)),
      m_maxGapTicks(uint64_t(std::max<int64_t>(maxGapNs, 0) / m_tickNs))
{
}

CounterUnwrapper::Result CounterUnwrapper::feed(uint64_t raw)
{
    raw %= m_modulus;
    Result r;
    if (!m_started) {
        m_started = true;
    } else if (raw < m_last) {
        // Across the top: the distance forward through the wrap is short.
        const uint64_t forward = m_modulus - m_last + raw;
        if (forward <= m_maxGapTicks) {
            ++m_wraps;
            ++m_wrapsTotal;
        } else {
            ++m_resets;
            m_wraps = 0;
            r.reset = true;
        }
    }
    m_last = raw;
    r.deviceNs = int64_t((uint64_t(m_wraps) * m_modulus + raw)) * m_tickNs;
    return r;
}

void CounterUnwrapper::clear()
{
    m_started = false;
    m_last = 0;
    m_wraps = 0;
    m_wrapsTotal = 0;
    m_resets = 0;
}

} // namespace imudesk::clock
