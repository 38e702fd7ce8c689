#include "packet.h"

#include "protocol/hipnuc/crc16.h"

namespace imudesk::protocol::kboot {

bool isKnownType(uint8_t b)
{
    return b >= 0xA1 && b <= 0xA7;
}

bool isFramed(PacketType t)
{
    return t == PacketType::Command || t == PacketType::Data;
}

std::vector<uint8_t> encodePing()
{
    return {kStartByte, uint8_t(PacketType::Ping)};
}

std::vector<uint8_t> encodePingResponse(const PingResponse &r)
{
    std::vector<uint8_t> b{kStartByte, uint8_t(PacketType::PingResponse), r.bugfix, r.minor, r.major, r.name,
                           uint8_t(r.options & 0xFF), uint8_t(r.options >> 8)};
    const uint16_t crc = hipnuc::crc16(b.data(), b.size());
    b.push_back(uint8_t(crc & 0xFF));
    b.push_back(uint8_t(crc >> 8));
    return b;
}

std::vector<uint8_t> encodeControl(PacketType t)
{
    return {kStartByte, uint8_t(t)};
}

std::vector<uint8_t> encodeFramed(PacketType t, const uint8_t *payload, size_t n)
{
    std::vector<uint8_t> b;
    b.reserve(kFramedHeaderSize + n);
    b.insert(b.end(), {kStartByte, uint8_t(t), uint8_t(n & 0xFF), uint8_t(n >> 8), 0, 0});
    const uint16_t crc = hipnuc::frameCrc(b.data(), payload, n);
    b[4] = uint8_t(crc & 0xFF);
    b[5] = uint8_t(crc >> 8);
    b.insert(b.end(), payload, payload + n);
    return b;
}

std::vector<uint8_t> encode(const Packet &p)
{
    switch (p.type) {
    case PacketType::Ping: return encodePing();
    case PacketType::PingResponse: return encodePingResponse(p.ping);
    case PacketType::Command:
    case PacketType::Data: return encodeFramed(p.type, p.payload);
    case PacketType::Ack:
    case PacketType::Nak:
    case PacketType::AckAbort: break;
    }
    return encodeControl(p.type);
}

} // namespace imudesk::protocol::kboot
