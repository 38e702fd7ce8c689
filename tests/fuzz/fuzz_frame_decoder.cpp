// libFuzzer target: HiPNUC FrameDecoder + StreamDemux + payload codecs.
//
// Input layout: byte 0 & 0x0F = k, the next k bytes are chunk sizes (used in turn:
// 0 = an empty feed, 255 = everything that is left, else that many bytes), the rest
// is the byte stream. The stream is fed in those chunks to a FrameDecoder and a
// StreamDemux, and in one piece to a second pair; every violated invariant traps.
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"
#include "protocol/nmea/nmea_parser.h"
#include "protocol/stream/stream_demux.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <variant>
#include <vector>

#define FUZZ_CHECK(cond)                                                                              \
    do {                                                                                              \
        if (!(cond)) {                                                                                \
            std::fprintf(stderr, "fuzz_frame_decoder: invariant failed: %s (line %d)\n", #cond, __LINE__); \
            __builtin_trap();                                                                         \
        }                                                                                             \
    } while (0)

namespace {

using namespace imudesk::protocol;
using namespace imudesk::protocol::hipnuc;

constexpr size_t kMaxPending = FrameDecoder::kHeaderSize + FrameDecoder::kMaxPayload - 1; // 4101

// Records what the decoder reports and rebuilds the stream from it.
class RecordingSink : public FrameDecoder::Sink {
public:
    std::vector<std::vector<uint8_t>> frames;
    std::vector<uint8_t> rebuilt; // skipped bytes and re-built frames, in stream order
    uint64_t frameBytes = 0;
    uint64_t skippedBytes = 0;

    void onFrame(const uint8_t *payload, size_t len) override
    {
        FUZZ_CHECK(payload != nullptr);
        FUZZ_CHECK(len >= 1 && len <= FrameDecoder::kMaxPayload);
        frames.emplace_back(payload, payload + len);
        frameBytes += FrameDecoder::kHeaderSize + len;
        // The frame passed its CRC, so re-building it gives back the original bytes.
        const auto f = buildFrame(payload, len);
        rebuilt.insert(rebuilt.end(), f.begin(), f.end());
    }
    void onSkipped(const uint8_t *bytes, size_t n) override
    {
        skippedBytes += n;
        rebuilt.insert(rebuilt.end(), bytes, bytes + n);
    }
};

void checkCounters(const FrameDecoder &d, const RecordingSink &s, uint64_t fed)
{
    const auto &c = d.counters();
    FUZZ_CHECK(c.bytesIn == fed);
    FUZZ_CHECK(c.frames == s.frames.size());
    FUZZ_CHECK(c.bytesSkipped == s.skippedBytes);
    FUZZ_CHECK(c.bytesSkipped + s.frameBytes + d.pendingBytes() == c.bytesIn);
    FUZZ_CHECK(d.pendingBytes() <= kMaxPending);
    FUZZ_CHECK(std::accumulate(c.perTag.begin(), c.perTag.end(), uint64_t(0)) == c.frames);
}

bool sameCounters(const FrameDecoder::Counters &a, const FrameDecoder::Counters &b)
{
    return a.bytesIn == b.bytesIn && a.frames == b.frames && a.crcErrors == b.crcErrors
        && a.lengthErrors == b.lengthErrors && a.bytesSkipped == b.bytesSkipped && a.perTag == b.perTag;
}

bool sameEvent(const StreamEvent &a, const StreamEvent &b)
{
    return a.kind == b.kind && a.payload == b.payload && a.text == b.text && a.nmeaError == b.nmeaError;
}

// decodePayload, toSample and encode on one frame payload.
void checkPayload(const std::vector<uint8_t> &payload)
{
    const PayloadResult r = decodePayload(payload);
    const std::vector<uint8_t> again = encode(r.packets);
    if (r.ok()) {
        FUZZ_CHECK(!r.packets.empty());
        FUZZ_CHECK(again == payload); // every decoded packet re-encodes to its bytes
    } else {
        FUZZ_CHECK(r.error != PayloadError::Empty); // frames are never empty
        FUZZ_CHECK(r.errorOffset < payload.size());
        FUZZ_CHECK(r.errorTag == payload[r.errorOffset]);
        // The packets decoded before the error are exactly the bytes before it.
        FUZZ_CHECK(again.size() == r.errorOffset);
        FUZZ_CHECK(std::equal(again.begin(), again.end(), payload.begin()));
        FUZZ_CHECK(payloadErrorText(r.error) != nullptr);
    }
    for (const Packet &p : r.packets) {
        const auto sample = toSample(p);
        FUZZ_CHECK(sample.source == packetName(p));
        if (const auto *h = std::get_if<Hi83>(&p)) {
            const auto size = Hi83::payloadSize(h->bitmap, h->legacyTime32);
            FUZZ_CHECK(size.has_value());
            FUZZ_CHECK(*size == encode(*h).size());
        }
    }
    Hi91 h;
    const bool isHi91 = payload.size() == Hi91::kSize && payload[0] == TagHi91;
    FUZZ_CHECK(decodeHi91(payload.data(), payload.size(), h) == isHi91);
    if (isHi91) {
        FUZZ_CHECK(encode(h) == payload);
        FUZZ_CHECK(toSample(h).source == "HI91");
    }
}

void checkEvents(const std::vector<StreamEvent> &events, const StreamDemux &demux,
                 const std::vector<std::vector<uint8_t>> &frames)
{
    size_t nFrames = 0;
    uint64_t nmea = 0, nmeaErr = 0, lines = 0;
    for (const auto &e : events) {
        switch (e.kind) {
        case StreamEvent::Kind::Frame:
            FUZZ_CHECK(nFrames < frames.size());
            FUZZ_CHECK(e.payload == frames[nFrames]);
            ++nFrames;
            break;
        case StreamEvent::Kind::Nmea:
            FUZZ_CHECK(!e.text.empty() && e.text.front() == '$');
            FUZZ_CHECK(nmea::parseSentence(e.text).ok());
            ++nmea;
            break;
        case StreamEvent::Kind::NmeaError: {
            FUZZ_CHECK(!e.text.empty() && e.text.front() == '$');
            const auto r = nmea::parseSentence(e.text);
            FUZZ_CHECK(!r.ok() && r.error == e.nmeaError);
            ++nmeaErr;
            break;
        }
        case StreamEvent::Kind::Line:
            FUZZ_CHECK(!e.text.empty() && e.text.front() != '$');
            ++lines;
            break;
        }
        if (e.kind != StreamEvent::Kind::Frame) {
            FUZZ_CHECK(e.text.size() <= StreamDemux::kMaxLine);
            // A line begins with printable ASCII and holds no control byte (CR dropped, LF ends
            // it); after its first character, bytes from 0x80 up are kept as they came.
            FUZZ_CHECK(uint8_t(e.text.front()) >= 0x20 && uint8_t(e.text.front()) < 0x7F);
            for (char ch : e.text)
                FUZZ_CHECK((uint8_t(ch) >= 0x20 && uint8_t(ch) < 0x7F) || uint8_t(ch) >= 0x80);
        }
    }
    FUZZ_CHECK(nFrames == frames.size());
    FUZZ_CHECK(demux.counters().nmeaSentences == nmea);
    FUZZ_CHECK(demux.counters().nmeaErrors == nmeaErr);
    FUZZ_CHECK(demux.counters().lines == lines);
    FUZZ_CHECK(demux.counters().garbageBytes + demux.counters().lineBytes <= demux.frameCounters().bytesSkipped);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    size_t k = data[0] & 0x0F;
    if (k > size - 1)
        k = size - 1;
    const uint8_t *sizes = data + 1;
    const uint8_t *stream = data + 1 + k;
    const size_t n = size - 1 - k;

    // Chunked feed: decoder and demux see the same chunks.
    FrameDecoder dec;
    RecordingSink sink;
    StreamDemux demux;
    std::vector<StreamEvent> events;
    size_t off = 0, j = 0, zeroRun = 0;
    while (off < n) {
        size_t chunk = n - off;
        if (k > 0) {
            const uint8_t b = sizes[j++ % k];
            if (b == 0 && zeroRun < k) {
                chunk = 0;
                ++zeroRun;
            } else if (b != 0xFF && b != 0) {
                chunk = std::min<size_t>(b, n - off);
            }
            if (chunk)
                zeroRun = 0;
        }
        dec.feed(stream + off, chunk, sink);
        demux.feed(stream + off, chunk, events);
        off += chunk;
        checkCounters(dec, sink, off);
        FUZZ_CHECK(sameCounters(demux.frameCounters(), dec.counters()));
    }
    dec.finish(sink);
    demux.finish(events);
    checkCounters(dec, sink, n);
    FUZZ_CHECK(dec.pendingBytes() == 0);
    FUZZ_CHECK(sink.skippedBytes + sink.frameBytes == n);
    FUZZ_CHECK(sink.rebuilt.size() == n && std::equal(sink.rebuilt.begin(), sink.rebuilt.end(), stream));
    FUZZ_CHECK(sameCounters(demux.frameCounters(), dec.counters()));
    {
        std::array<uint64_t, 256> perTag{};
        for (const auto &f : sink.frames)
            ++perTag[f[0]];
        FUZZ_CHECK(perTag == dec.counters().perTag);
    }

    // One piece: the same frames, counters and events whatever the chunking.
    FrameDecoder whole;
    auto frames = whole.feed(stream, n);
    RecordingSink tail; // finish() may still find frames inside an unfinished candidate
    whole.finish(tail);
    frames.insert(frames.end(), tail.frames.begin(), tail.frames.end());
    FUZZ_CHECK(frames == sink.frames);
    FUZZ_CHECK(sameCounters(whole.counters(), dec.counters()));
    FUZZ_CHECK(whole.pendingBytes() == 0);

    StreamDemux demuxWhole;
    std::vector<StreamEvent> eventsWhole;
    demuxWhole.feed(stream, n, eventsWhole);
    demuxWhole.finish(eventsWhole);
    FUZZ_CHECK(eventsWhole.size() == events.size());
    for (size_t i = 0; i < events.size(); ++i)
        FUZZ_CHECK(sameEvent(events[i], eventsWhole[i]));
    FUZZ_CHECK(demuxWhole.counters().garbageBytes == demux.counters().garbageBytes);
    checkEvents(events, demux, sink.frames);

    // Payloads.
    for (const auto &f : sink.frames)
        checkPayload(f);
    return 0;
}
