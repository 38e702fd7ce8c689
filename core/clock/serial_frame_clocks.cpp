#include "serial_frame_clocks.h"

namespace imudesk::clock {

void SerialFrameClocks::clear()
{
    m_clocks.clear();
    m_cutBytes = 0;
    m_frameBoundNs = INT64_MAX;
}

void SerialFrameClocks::beginFrame(size_t frameBytes, int64_t hostNs)
{
    m_frameWireNs = wireNs(frameBytes);
    // Only the first frame a read completes can be the one the last read ended inside.
    const bool cutFits = m_cutBytes > 0 && m_cutBytes < frameBytes && m_baud > 0
        && hostNs - m_cutHostNs <= wireNs(frameBytes - m_cutBytes) + kMaxCutAgeNs;
    m_frameBoundNs = cutFits ? m_cutHostNs - wireNs(m_cutBytes) : INT64_MAX;
    m_cutBytes = 0;
}

void SerialFrameClocks::stamp(model::Sample &s, int timeBase)
{
    m_clocks.stamp(s, timeBase, m_frameWireNs, m_frameBoundNs);
}

int64_t SerialFrameClocks::commonTime(const char *source, double deviceTimeMs, int64_t hostNs, int timeBase)
{
    m_source.assign(source);
    return m_clocks.commonTime(m_source, deviceTimeMs, hostNs, timeBase, m_frameWireNs, m_frameBoundNs).value_or(0);
}

void SerialFrameClocks::endRead(size_t pendingBytes, int64_t hostNs)
{
    m_cutBytes = pendingBytes;
    m_cutHostNs = hostNs;
}

} // namespace imudesk::clock
