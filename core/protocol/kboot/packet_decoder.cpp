#include "packet_decoder.h"

#include "protocol/hipnuc/crc16.h"

#include <algorithm>
#include <cstring>

namespace imudesk::protocol::kboot {

void PacketDecoder::feed(const uint8_t *data, size_t n, std::vector<Packet> &out)
{
    while (n > 0) {
        // Keep the buffer bounded: append at most one maximal packet's worth at a time.
        const size_t room = kFramedHeaderSize + m_maxPayload;
        const size_t take = std::min(n, room > m_buf.size() ? room - m_buf.size() : size_t(1));
        m_buf.insert(m_buf.end(), data, data + take);
        data += take;
        n -= take;
        while (!m_buf.empty() && step(out)) {
        }
    }
}

void PacketDecoder::reset()
{
    m_counters.bytesSkipped += m_buf.size();
    m_buf.clear();
}

void PacketDecoder::skip(size_t n)
{
    n = std::min(n, m_buf.size());
    // Jump to the next start byte in one go.
    const auto next = std::find(m_buf.begin() + long(n), m_buf.end(), kStartByte);
    const size_t drop = size_t(next - m_buf.begin());
    m_counters.bytesSkipped += drop;
    m_buf.erase(m_buf.begin(), next);
}

bool PacketDecoder::step(std::vector<Packet> &out)
{
    if (m_buf[0] != kStartByte) {
        skip(0);
        return !m_buf.empty();
    }
    if (m_buf.size() < 2)
        return false;
    if (!isKnownType(m_buf[1])) {
        skip(1);
        return !m_buf.empty();
    }
    const auto type = PacketType(m_buf[1]);
    Packet p;
    p.type = type;
    size_t used = 2;
    switch (type) {
    case PacketType::Ack:
    case PacketType::Nak:
    case PacketType::AckAbort:
    case PacketType::Ping: break;
    case PacketType::PingResponse: {
        if (m_buf.size() < 10)
            return false;
        const uint16_t crc = hipnuc::crc16(m_buf.data(), 8);
        if ((uint16_t(m_buf[8]) | uint16_t(m_buf[9]) << 8) != crc) {
            ++m_counters.crcErrors;
            skip(1);
            return !m_buf.empty();
        }
        p.ping = PingResponse{m_buf[2], m_buf[3], m_buf[4], m_buf[5], uint16_t(m_buf[6] | m_buf[7] << 8)};
        used = 10;
        break;
    }
    case PacketType::Command:
    case PacketType::Data: {
        if (m_buf.size() < kFramedHeaderSize)
            return false;
        const size_t len = size_t(m_buf[2]) | size_t(m_buf[3]) << 8;
        if (len > m_maxPayload || (type == PacketType::Command && len < 4)) {
            ++m_counters.lengthErrors;
            skip(1);
            return !m_buf.empty();
        }
        if (m_buf.size() < kFramedHeaderSize + len)
            return false;
        const uint16_t crc = hipnuc::frameCrc(m_buf.data(), m_buf.data() + kFramedHeaderSize, len);
        if ((uint16_t(m_buf[4]) | uint16_t(m_buf[5]) << 8) != crc) {
            ++m_counters.crcErrors;
            skip(1);
            return !m_buf.empty();
        }
        p.payload.assign(m_buf.begin() + long(kFramedHeaderSize), m_buf.begin() + long(kFramedHeaderSize + len));
        used = kFramedHeaderSize + len;
        break;
    }
    }
    m_buf.erase(m_buf.begin(), m_buf.begin() + long(used));
    ++m_counters.packets;
    out.push_back(std::move(p));
    return !m_buf.empty();
}

} // namespace imudesk::protocol::kboot
