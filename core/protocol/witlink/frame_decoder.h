#pragma once
// Streaming decoder for Witlink frames (frame.h). Bytes may arrive in any chunking.
//
// The decoder looks for 0x77, then checks LEN (kMinLength..kMaxLength) and the checksum.
// When either fails the candidate is abandoned and the search resumes one byte after that
// 0x77, so a real frame that started inside a damaged or false one is still found. At most
// one unfinished candidate (< kMaxLength + 1 bytes) is kept between calls. Bytes that
// belong to no valid frame are counted as skipped and kept, bounded, for the caller (an
// HEC495 set to NMEA 0183 output sends text between, or instead of, frames).
#include "frame.h"

#include <cstdint>
#include <string>
#include <vector>

namespace imudesk::protocol::witlink {

class FrameDecoder {
public:
    static constexpr size_t kMaxSkippedKept = 4096;

    struct Counters {
        uint64_t bytesIn = 0;
        uint64_t frames = 0;
        uint64_t checksumErrors = 0;
        uint64_t lengthErrors = 0;
        uint64_t bytesSkipped = 0;
        friend bool operator==(const Counters &, const Counters &) = default;
    };

    // Appends the frames completed by these bytes to out.
    void feed(const uint8_t *data, size_t n, std::vector<Frame> &out);
    std::vector<Frame> feed(const uint8_t *data, size_t n);
    std::vector<Frame> feed(const std::vector<uint8_t> &bytes) { return feed(bytes.data(), bytes.size()); }

    // The line went quiet: an unfinished candidate will not complete (a device sends a frame
    // without pauses). Its 0x77 is skipped and the bytes after it are searched again; frames
    // found there are appended to out.
    void flushIdle(std::vector<Frame> &out);
    // Drops the unfinished tail without counting it (e.g. after a baud change).
    void reset();

    size_t pendingBytes() const { return m_buf.size(); }
    const Counters &counters() const { return m_counters; }
    // Skipped bytes since the last call (at most kMaxSkippedKept; older ones are dropped).
    std::string takeSkipped();

private:
    void process(std::vector<Frame> &out, bool idle);
    void skip(size_t from, size_t n);

    std::vector<uint8_t> m_buf;
    std::string m_skipped;
    Counters m_counters;
};

} // namespace imudesk::protocol::witlink
