#include "frame_decoder.h"

#include <algorithm>
#include <cstring>

namespace imudesk::protocol::witlink {

void FrameDecoder::feed(const uint8_t *data, size_t n, std::vector<Frame> &out)
{
    m_counters.bytesIn += n;
    // Bounded: the buffer holds at most one unfinished candidate plus this chunk, and the
    // chunk is consumed below before the next one arrives.
    m_buf.insert(m_buf.end(), data, data + n);
    process(out, false);
}

std::vector<Frame> FrameDecoder::feed(const uint8_t *data, size_t n)
{
    std::vector<Frame> out;
    feed(data, n, out);
    return out;
}

void FrameDecoder::flushIdle(std::vector<Frame> &out)
{
    if (m_buf.empty())
        return;
    process(out, true);
}

void FrameDecoder::reset()
{
    m_buf.clear();
}

std::string FrameDecoder::takeSkipped()
{
    std::string s;
    s.swap(m_skipped);
    return s;
}

void FrameDecoder::skip(size_t from, size_t n)
{
    m_counters.bytesSkipped += n;
    m_skipped.append(reinterpret_cast<const char *>(m_buf.data() + from), n);
    if (m_skipped.size() > kMaxSkippedKept)
        m_skipped.erase(0, m_skipped.size() - kMaxSkippedKept);
}

void FrameDecoder::process(std::vector<Frame> &out, bool idle)
{
    // Works on an offset and erases once at the end: a chunk full of false syncs costs O(n).
    bool dropHead = idle;
    size_t pos = 0;
    const size_t size = m_buf.size();
    while (pos < size) {
        const auto sync = std::find(m_buf.begin() + std::ptrdiff_t(pos), m_buf.end(), kSync);
        const size_t at = size_t(sync - m_buf.begin());
        if (at != pos)
            skip(pos, at - pos);
        pos = at;
        if (pos >= size)
            break;
        const size_t avail = size - pos;
        if (avail >= 2) {
            const size_t len = m_buf[pos + 1];
            if (len < kMinLength || len > kMaxLength) {
                ++m_counters.lengthErrors;
                skip(pos, 1);
                ++pos;
                continue;
            }
            if (avail >= len + 1) {
                const uint8_t *f0 = m_buf.data() + pos;
                if (checksum(f0 + 1, len - 1) != f0[len]) {
                    ++m_counters.checksumErrors;
                    skip(pos, 1);
                    ++pos;
                    continue;
                }
                Frame f;
                f.address = f0[2];
                f.command = f0[3];
                f.data.assign(f0 + 4, f0 + len);
                out.push_back(std::move(f));
                ++m_counters.frames;
                pos += len + 1;
                continue;
            }
        }
        if (!dropHead)
            break; // an unfinished candidate: wait for more bytes
        // Idle with an unfinished candidate: it will never complete.
        dropHead = false;
        skip(pos, 1);
        ++pos;
    }
    m_buf.erase(m_buf.begin(), m_buf.begin() + std::ptrdiff_t(pos));
}

} // namespace imudesk::protocol::witlink
