// libFuzzer target: KBOOT packet decoder and command payloads, host and device side.
//
// The input is a byte stream from the line. The decoder must find the same packets whether
// it gets the stream whole, byte by byte or in chunks whose sizes come from the input; it
// never holds more than one maximal packet; every packet it returns re-encodes to bytes that
// decode to the same packet. A command payload that decodes re-encodes to itself. The same
// stream fed to the simulated bootloader must not crash it or change its flash size, and it
// never writes into the bootloader area.
#include "protocol/kboot/command.h"
#include "protocol/kboot/packet.h"
#include "protocol/kboot/packet_decoder.h"
#include "sim/kboot_bootloader.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <vector>

#define FUZZ_CHECK(cond)                                                                         \
    do {                                                                                         \
        if (!(cond)) {                                                                           \
            std::fprintf(stderr, "fuzz_kboot: invariant failed: %s (line %d)\n", #cond, __LINE__); \
            __builtin_trap();                                                                    \
        }                                                                                        \
    } while (0)

using namespace imudesk::protocol::kboot;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    constexpr size_t kMax = 600;
    PacketDecoder whole(kMax);
    const auto ref = whole.feed(data, size);
    FUZZ_CHECK(whole.pendingBytes() < kFramedHeaderSize + kMax);

    PacketDecoder bytewise(kMax);
    std::vector<Packet> one;
    for (size_t i = 0; i < size; ++i)
        bytewise.feed(data + i, 1, one);
    FUZZ_CHECK(one == ref);

    PacketDecoder chunked(kMax);
    std::vector<Packet> chunks;
    size_t at = 0, k = 0;
    while (at < size) {
        const size_t n = std::min<size_t>(size - at, size_t(data[k++ % size]) % 97 + 1);
        chunked.feed(data + at, n, chunks);
        at += n;
    }
    FUZZ_CHECK(chunks == ref);
    FUZZ_CHECK(whole.counters().packets == ref.size());

    for (const Packet &p : ref) {
        PacketDecoder d(kMax);
        const auto again = d.feed(encode(p));
        FUZZ_CHECK(again.size() == 1 && again[0] == p);
        if (p.type == PacketType::Command) {
            const auto c = Command::decode(p.payload);
            if (c)
                FUZZ_CHECK(c->encode() == p.payload);
        }
    }

    imudesk::sim::KbootBootloader::Options o;
    o.flashSize = 64 * 1024;
    o.appStart = 0x2000;
    o.sectorSize = 1024;
    imudesk::sim::KbootBootloader bl(o);
    const std::vector<uint8_t> bootArea(bl.flash().begin(), bl.flash().begin() + o.appStart);
    bl.start(921600, 0);
    bl.receive(data, size, 0);
    int64_t t = 0;
    for (int i = 0; i < 100000 && bl.nextEventUs() != INT64_MAX; ++i) {
        t = std::max(t, bl.nextEventUs());
        const auto req = bl.runUntil(t);
        bl.takeOutput();
        if (req != imudesk::sim::KbootBootloader::Request::None)
            bl.start(921600, t);
    }
    FUZZ_CHECK(bl.flash().size() == o.flashSize);
    FUZZ_CHECK(std::equal(bootArea.begin(), bootArea.end(), bl.flash().begin()));
    return 0;
}
