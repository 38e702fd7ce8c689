#pragma once
// Streaming decoder for HiPNUC binary frames: 5A A5 LEN(u16 LE) CRC(u16 LE) PAYLOAD[LEN].
//
// Bytes may arrive in any chunking. A candidate sync whose length is outside
// 1..kMaxPayload or whose CRC fails is abandoned and the search resumes one byte
// after that sync, so a real frame that started inside a damaged or false frame
// is still found. LEN is 1-4096 (v1.7.1 manual 5.7; the vendor's SDK stops at 506, and
// the largest payload the manual defines, HI83 with every bit, is 348 bytes). Memory is
// bounded: at most one unfinished frame (< 4102 bytes) is kept between calls.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace imudesk::protocol::hipnuc {

class FrameDecoder {
public:
    static constexpr size_t kHeaderSize = 6;
    static constexpr size_t kMaxPayload = 4096;

    struct Counters {
        uint64_t bytesIn = 0;
        uint64_t frames = 0;
        uint64_t crcErrors = 0;
        uint64_t lengthErrors = 0;
        uint64_t bytesSkipped = 0;           // bytes that belong to no valid frame
        std::array<uint64_t, 256> perTag{};  // frames by the first payload byte (0x91, 0x81, ...)
    };

    // Receives decoded frames and the bytes that belong to no frame, in stream order.
    class Sink {
    public:
        virtual ~Sink() = default;
        // payload points into the decoder's or the caller's buffer; valid during the call.
        virtual void onFrame(const uint8_t *payload, size_t len) = 0;
        virtual void onSkipped(const uint8_t * /*bytes*/, size_t /*n*/) {}
        // A candidate frame failed its length or CRC check here (every byte before it was
        // already reported); what follows may be the rest of a damaged frame.
        virtual void onDamage() {}
    };

    void feed(const uint8_t *data, size_t n, Sink &sink);
    // Convenience: returns the payloads of the complete frames.
    std::vector<std::vector<uint8_t>> feed(const uint8_t *data, size_t n);

    // End of stream: frames inside the unfinished tail are still decoded; the rest is
    // reported as skipped.
    void finish(Sink &sink);
    // Drops the unfinished tail without reporting it (e.g. after a baud change).
    void reset();

    size_t pendingBytes() const { return m_buf.size(); }
    const Counters &counters() const { return m_counters; }
    void resetCounters() { m_counters = Counters{}; }

private:
    size_t process(const uint8_t *p, size_t n, Sink &sink, bool final = false);
    void reportDamage(const uint8_t *p, size_t &skipStart, size_t i, Sink &sink);

    std::vector<uint8_t> m_buf;
    Counters m_counters;
};

// Builds a complete frame around a payload (header, length and CRC).
std::vector<uint8_t> buildFrame(const uint8_t *payload, size_t len);
inline std::vector<uint8_t> buildFrame(const std::vector<uint8_t> &payload)
{
    return buildFrame(payload.data(), payload.size());
}

} // namespace imudesk::protocol::hipnuc
