#include "frame_decoder.h"

#include "crc16.h"

#include <cstring>

namespace imudesk::protocol::hipnuc {

namespace {
constexpr uint8_t kSync1 = 0x5A;
constexpr uint8_t kSync2 = 0xA5;

class CollectingSink : public FrameDecoder::Sink {
public:
    std::vector<std::vector<uint8_t>> frames;
    void onFrame(const uint8_t *payload, size_t len) override { frames.emplace_back(payload, payload + len); }
};
} // namespace

void FrameDecoder::feed(const uint8_t *data, size_t n, Sink &sink)
{
    m_counters.bytesIn += n;
    if (m_buf.empty()) {
        const size_t used = process(data, n, sink);
        m_buf.assign(data + used, data + n);
        return;
    }
    m_buf.insert(m_buf.end(), data, data + n);
    const size_t used = process(m_buf.data(), m_buf.size(), sink);
    m_buf.erase(m_buf.begin(), m_buf.begin() + ptrdiff_t(used));
}

std::vector<std::vector<uint8_t>> FrameDecoder::feed(const uint8_t *data, size_t n)
{
    CollectingSink sink;
    feed(data, n, sink);
    return std::move(sink.frames);
}

size_t FrameDecoder::process(const uint8_t *p, size_t n, Sink &sink, bool final)
{
    size_t i = 0;
    size_t skipStart = 0; // [skipStart, i) belongs to no frame
    while (i < n) {
        if (p[i] != kSync1) {
            const void *hit = std::memchr(p + i, kSync1, n - i);
            if (!hit) {
                i = n;
                break;
            }
            i = size_t(static_cast<const uint8_t *>(hit) - p);
        }
        if (i + 1 >= n) {
            if (final) { ++i; continue; }
            break; // wait for the second sync byte
        }
        if (p[i + 1] != kSync2) {
            ++i;
            continue;
        }
        if (i + kHeaderSize > n) {
            if (final) { ++i; continue; }
            break; // wait for the header
        }
        const size_t len = size_t(p[i + 2]) | (size_t(p[i + 3]) << 8);
        if (len == 0 || len > kMaxPayload) {
            ++m_counters.lengthErrors;
            reportDamage(p, skipStart, i, sink);
            ++i;
            continue;
        }
        if (i + kHeaderSize + len > n) {
            // At the end of the stream an unfinished candidate can never complete:
            // abandon it and look for frames inside it.
            if (final) { ++i; continue; }
            break; // wait for the payload
        }
        const uint16_t expected = uint16_t(p[i + 4] | (p[i + 5] << 8));
        if (frameCrc(p + i, p + i + kHeaderSize, len) != expected) {
            ++m_counters.crcErrors;
            reportDamage(p, skipStart, i, sink);
            ++i;
            continue;
        }
        if (i > skipStart) {
            m_counters.bytesSkipped += i - skipStart;
            sink.onSkipped(p + skipStart, i - skipStart);
        }
        const uint8_t *payload = p + i + kHeaderSize;
        ++m_counters.frames;
        ++m_counters.perTag[payload[0]];
        sink.onFrame(payload, len);
        i += kHeaderSize + len;
        skipStart = i;
    }
    if (i > skipStart) {
        m_counters.bytesSkipped += i - skipStart;
        sink.onSkipped(p + skipStart, i - skipStart);
    }
    return i;
}

void FrameDecoder::reportDamage(const uint8_t *p, size_t &skipStart, size_t i, Sink &sink)
{
    if (i > skipStart) {
        m_counters.bytesSkipped += i - skipStart;
        sink.onSkipped(p + skipStart, i - skipStart);
        skipStart = i;
    }
    sink.onDamage();
}

void FrameDecoder::finish(Sink &sink)
{
    if (m_buf.empty())
        return;
    process(m_buf.data(), m_buf.size(), sink, true);
    m_buf.clear();
}

void FrameDecoder::reset()
{
    m_buf.clear();
}

std::vector<uint8_t> buildFrame(const uint8_t *payload, size_t len)
{
    std::vector<uint8_t> f(FrameDecoder::kHeaderSize + len);
    f[0] = kSync1;
    f[1] = kSync2;
    f[2] = uint8_t(len & 0xFF);
    f[3] = uint8_t(len >> 8);
    if (len)
        std::memcpy(f.data() + FrameDecoder::kHeaderSize, payload, len);
    const uint16_t crc = frameCrc(f.data(), payload, len);
    f[4] = uint8_t(crc & 0xFF);
    f[5] = uint8_t(crc >> 8);
    return f;
}

} // namespace imudesk::protocol::hipnuc
