#include "hipnuc_serial_device.h"

namespace imudesk::sim {

std::vector<SerialSegment> HipnucSerialDevice::takeOutputSegments()
{
    auto in = m_sim.takeOutputSegments();
    std::vector<SerialSegment> out;
    out.reserve(in.size());
    for (auto &s : in)
        out.push_back(SerialSegment{s.baud, std::move(s.bytes), s.chunk, s.chunkStart, s.chunkEnd, s.data});
    return out;
}

} // namespace imudesk::sim
