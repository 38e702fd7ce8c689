// libFuzzer target: capture file reader (capture/capture_reader.h) and the decoder path a
// replay feeds its chunks through.
//
// Whatever the bytes, reading must not crash and must end. A header that opens re-encodes
// to a body that decodes to the same map. Every chunk returned lies inside the input, in
// increasing offsets, and re-encoding it with appendChunk gives back exactly the bytes at
// its offset (so its CRC held). Damaged chunks are counted; the last result is End or
// Truncated.
#include "capture/capture_decoder.h"
#include "capture/capture_format.h"
#include "capture/capture_reader.h"

#include <QBuffer>
#include <QByteArray>

#include <cstdint>
#include <cstdio>
#include <cstring>

#define FUZZ_CHECK(cond)                                                                           \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            std::fprintf(stderr, "fuzz_capture: invariant failed: %s (line %d)\n", #cond, __LINE__); \
            __builtin_trap();                                                                      \
        }                                                                                          \
    } while (0)

using namespace imudesk::capture;
using namespace imudesk;

namespace {
struct CountingSink : CaptureDecoder::Sink {
    uint64_t packets = 0;
    void onSample(const imudesk::model::Sample &, const imudesk::decode::Record &) override { ++packets; }
};
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    QBuffer buf(&bytes);
    buf.open(QIODevice::ReadOnly);
    CaptureReader reader;
    QString error;
    if (!reader.open(&buf, &error)) {
        FUZZ_CHECK(!error.isEmpty());
        return 0;
    }
    // The header round-trips.
    const std::vector<uint8_t> body = reader.header().encodeBody();
    CaptureHeader again;
    FUZZ_CHECK(CaptureHeader::decodeBody(body.data(), body.size(), again, &error));
    FUZZ_CHECK(again == reader.header());
    FUZZ_CHECK(reader.dataStart() <= qint64(size));

    CaptureDecoder decoder;
    decoder.configure(reader.header());
    CountingSink sink;
    CaptureReader::Chunk c;
    CaptureReader::Result r;
    qint64 lastEnd = reader.dataStart();
    uint64_t damaged = 0;
    std::vector<uint8_t> encoded;
    for (size_t steps = 0;; ++steps) {
        FUZZ_CHECK(steps <= size + 1); // every call consumes at least one byte
        r = reader.next(c);
        if (r == CaptureReader::Result::Damaged) {
            ++damaged;
            continue;
        }
        if (r != CaptureReader::Result::Chunk)
            break;
        FUZZ_CHECK(c.offset >= lastEnd);
        FUZZ_CHECK(c.size >= 1 && c.size <= capture::kMaxChunkPayload);
        const qint64 end = c.offset + qint64(c.size + capture::kChunkOverhead);
        FUZZ_CHECK(end <= qint64(size));
        encoded.clear();
        capture::appendChunk(encoded, c.kind, c.monotonicNs, c.wallUs, c.data, c.size);
        FUZZ_CHECK(std::memcmp(encoded.data(), data + c.offset, encoded.size()) == 0);
        lastEnd = end;
        decoder.feedChunk(c, sink);
    }
    decoder.finish(sink);
    FUZZ_CHECK(r == CaptureReader::Result::End || r == CaptureReader::Result::Truncated);
    FUZZ_CHECK(reader.damagedChunks() == damaged);
    FUZZ_CHECK(reader.next(c) == r); // final results stay final
    return 0;
}
