#include "sim/line_devices.h"

#include <algorithm>

namespace imudesk::sim {

NoiseLine::NoiseLine(int baud, int bytesPerSecond, uint64_t seed) : m_baud(baud), m_rate(bytesPerSecond), m_random(seed) {}

void NoiseLine::advanceTo(int64_t nowUs)
{
    if (m_lastUs < 0 || nowUs <= m_lastUs) {
        m_lastUs = std::max(m_lastUs, nowUs);
        return;
    }
    m_owed += double(nowUs - m_lastUs) * 1e-6 * m_rate;
    m_lastUs = nowUs;
    while (m_owed >= 1.0) {
        m_owed -= 1.0;
        // High bytes only, none of them a frame's start: 0x80..0xFF without 0xA5.
        uint8_t b = uint8_t(0x80 | (m_random() & 0x7F));
        if (b == 0xA5)
            b = 0xA6;
        m_out.push_back(b);
    }
}

std::vector<SerialSegment> NoiseLine::takeOutputSegments()
{
    if (m_out.empty())
        return {};
    SerialSegment s;
    s.baud = m_baud;
    s.bytes.swap(m_out);
    s.chunk = ++m_chunk;
    s.chunkStart = s.chunkEnd = true;
    s.data = true;
    return {s};
}

} // namespace imudesk::sim
