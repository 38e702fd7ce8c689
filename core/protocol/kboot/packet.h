#pragma once
// KBOOT (NXP MCUBoot) UART packets as the HiPNUC bootloader speaks them
// (hipnuc-protocol-notes.md 3.1):
//   ping            5A A6
//   ping response   5A A7 bugfix minor major 'P' optLo optHi crcLo crcHi   (CRC over the first 8 bytes)
//   ACK/NAK/abort   5A A1 / 5A A2 / 5A A3                                   (no CRC)
//   command         5A A4 lenLo lenHi crcLo crcHi payload                   (CRC over 4 header bytes + payload)
//   data            5A A5 lenLo lenHi crcLo crcHi payload
// CRC-16/XMODEM, as HiPNUC frames (protocol/hipnuc/crc16.h).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace imudesk::protocol::kboot {

inline constexpr uint8_t kStartByte = 0x5A;
inline constexpr size_t kFramedHeaderSize = 6;
// Largest payload a framed packet may carry here: bounds the decoder's buffer. KBOOT's own
// limit is the MaxPacketSize property (32..4096 on NXP parts); the length field is 16 bits.
inline constexpr size_t kMaxPayload = 8192;

enum class PacketType : uint8_t {
    Ack = 0xA1,
    Nak = 0xA2,
    AckAbort = 0xA3,
    Command = 0xA4,
    Data = 0xA5,
    Ping = 0xA6,
    PingResponse = 0xA7,
};

struct PingResponse {
    uint8_t bugfix = 0, minor = 0, major = 0, name = 'P';
    uint16_t options = 0;
    friend bool operator==(const PingResponse &, const PingResponse &) = default;
};

struct Packet {
    PacketType type = PacketType::Ack;
    std::vector<uint8_t> payload;   // Command and Data
    PingResponse ping;              // PingResponse
    friend bool operator==(const Packet &, const Packet &) = default;
};

bool isKnownType(uint8_t b);
bool isFramed(PacketType t);        // Command or Data

std::vector<uint8_t> encodePing();
std::vector<uint8_t> encodePingResponse(const PingResponse &r);
std::vector<uint8_t> encodeControl(PacketType t); // Ack, Nak, AckAbort
std::vector<uint8_t> encodeFramed(PacketType t, const uint8_t *payload, size_t n);
inline std::vector<uint8_t> encodeFramed(PacketType t, const std::vector<uint8_t> &payload)
{
    return encodeFramed(t, payload.data(), payload.size());
}
std::vector<uint8_t> encode(const Packet &p);

} // namespace imudesk::protocol::kboot
