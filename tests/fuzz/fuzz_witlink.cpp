// libFuzzer target: the Witlink (HEC495) streaming decoder, typed replies and packed BCD.
//
// The first input byte picks the chunk size (1..64) the rest is fed in. Whatever the bytes:
// nothing crashes; the counters add up; at most one unfinished candidate is held; every
// frame found re-encodes to bytes that occur in the input; the same stream fed whole gives
// the same frames; a decoded reply describes itself; BCD values re-encode to their bytes.
#include "protocol/witlink/bcd.h"
#include "protocol/witlink/frame_decoder.h"
#include "protocol/witlink/reply.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <vector>

#define FUZZ_CHECK(cond)                                                                            \
    do {                                                                                            \
        if (!(cond)) {                                                                              \
            std::fprintf(stderr, "fuzz_witlink: invariant failed: %s (line %d)\n", #cond, __LINE__); \
            __builtin_trap();                                                                       \
        }                                                                                           \
    } while (0)

using namespace imudesk::protocol::witlink;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    const size_t chunk = size_t(data[0] % 64) + 1;
    const uint8_t *p = data + 1;
    const size_t n = size - 1;

    FrameDecoder chunked;
    std::vector<Frame> frames;
    for (size_t i = 0; i < n; i += chunk) {
        const size_t k = std::min(chunk, n - i);
        chunked.feed(p + i, k, frames);
        FUZZ_CHECK(chunked.pendingBytes() <= kMaxLength + 1 + k);
    }
    const auto &c = chunked.counters();
    FUZZ_CHECK(c.bytesIn == n);
    FUZZ_CHECK(c.frames == frames.size());

    std::vector<Frame> whole = FrameDecoder().feed(p, n);
    FUZZ_CHECK(whole == frames);

    std::vector<Frame> flushed = frames;
    chunked.flushIdle(flushed);
    FUZZ_CHECK(flushed.size() >= frames.size());

    for (const auto &f : flushed) {
        FUZZ_CHECK(f.data.size() <= kMaxData);
        const std::vector<uint8_t> bytes = encodeFrame(f);
        FUZZ_CHECK(bytes.size() == f.data.size() + kMinLength + 1);
        FUZZ_CHECK(std::search(p, p + n, bytes.begin(), bytes.end()) != p + n);
        const Reply r = decodeReply(f);
        FUZZ_CHECK(!r.describe().isEmpty());
        FUZZ_CHECK(r.ok() == (r.error == Reply::Error::None));
        if (r.ok() && r.kind == Reply::Kind::AllData)
            FUZZ_CHECK(r.record.encode() == f.data);
    }

    // Packed BCD: what decodes re-encodes to the same bytes (negative zero aside).
    if (n >= 3) {
        if (const auto v = decodeAngle(p); v && *v != 0.0) {
            const auto e = encodeAngle(*v);
            FUZZ_CHECK(e && std::equal(e->begin(), e->end(), p));
        }
        if (const auto v = decodeDeclination(p); v && *v != 0.0) {
            const auto e = encodeDeclination(*v);
            FUZZ_CHECK(e && std::equal(e->begin(), e->end(), p));
        }
    }
    return 0;
}
