#include "frame.h"

namespace imudesk::protocol::witlink {

uint8_t checksum(const uint8_t *p, size_t n)
{
    unsigned sum = 0;
    for (size_t i = 0; i < n; ++i)
        sum += p[i];
    return uint8_t(sum & 0xFFu);
}

std::vector<uint8_t> encodeFrame(uint8_t address, uint8_t command, const std::vector<uint8_t> &data)
{
    if (data.size() > kMaxData)
        return {};
    std::vector<uint8_t> out;
    out.reserve(data.size() + kMinLength + 1);
    out.push_back(kSync);
    out.push_back(uint8_t(kMinLength + data.size()));
    out.push_back(address);
    out.push_back(command);
    out.insert(out.end(), data.begin(), data.end());
    out.push_back(checksum(out.data() + 1, out.size() - 1));
    return out;
}

} // namespace imudesk::protocol::witlink
