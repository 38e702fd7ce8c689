#pragma once
// Streaming KBOOT packet decoder: feed() any chunking of the byte stream, get the complete
// packets back. Bytes before a start byte, unknown packet types and packets with a bad CRC
// or an impossible length are skipped and counted; after a bad candidate the search resumes
// one byte after its start byte, so a real packet that began inside it is still found.
// At most one unfinished packet (< kFramedHeaderSize + maxPayload bytes) is kept.
#include "protocol/kboot/packet.h"

#include <cstdint>
#include <vector>

namespace imudesk::protocol::kboot {

class PacketDecoder {
public:
    struct Counters {
        uint64_t packets = 0;
        uint64_t crcErrors = 0;
        uint64_t lengthErrors = 0;
        uint64_t bytesSkipped = 0;
    };

    explicit PacketDecoder(size_t maxPayload = kMaxPayload) : m_maxPayload(maxPayload) {}

    void feed(const uint8_t *data, size_t n, std::vector<Packet> &out);
    std::vector<Packet> feed(const uint8_t *data, size_t n)
    {
        std::vector<Packet> out;
        feed(data, n, out);
        return out;
    }
    std::vector<Packet> feed(const std::vector<uint8_t> &b) { return feed(b.data(), b.size()); }
    // Forgets an unfinished packet (counted as skipped).
    void reset();
    size_t pendingBytes() const { return m_buf.size(); }
    const Counters &counters() const { return m_counters; }

private:
    // Tries to take one packet at the front of m_buf. Returns false when more bytes are needed.
    bool step(std::vector<Packet> &out);
    void skip(size_t n);

    size_t m_maxPayload;
    std::vector<uint8_t> m_buf;
    Counters m_counters;
};

} // namespace imudesk::protocol::kboot
