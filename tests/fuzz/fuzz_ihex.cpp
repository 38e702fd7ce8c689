// libFuzzer target: Intel HEX loader (and the .bin path).
//
// Whatever the input, parsing must not crash and must stay within its limits. When it
// loads, the image is non-empty, within the span limit, and writing it back as Intel HEX
// and loading that again gives the same start address, bytes and entry point. An error
// always has a message, and a line number within the input's line count.
#include "protocol/ihex/intel_hex_loader.h"
#include "protocol/ihex/intel_hex_writer.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string_view>

#define FUZZ_CHECK(cond)                                                                        \
    do {                                                                                        \
        if (!(cond)) {                                                                          \
            std::fprintf(stderr, "fuzz_ihex: invariant failed: %s (line %d)\n", #cond, __LINE__); \
            __builtin_trap();                                                                   \
        }                                                                                       \
    } while (0)

using namespace imudesk::protocol::ihex;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const std::string_view text(reinterpret_cast<const char *>(data), size);
    IntelHexLoader::Limits limits;
    limits.maxImageBytes = 1u << 20; // keep each run small
    const auto r = IntelHexLoader::parseHex(text, limits);
    const long lines = long(std::count(text.begin(), text.end(), '\n')) + 1;
    if (!r.ok()) {
        FUZZ_CHECK(!r.error.isEmpty());
        FUZZ_CHECK(r.line >= 0 && r.line <= lines);
    } else {
        const FirmwareImage &img = *r.image;
        FUZZ_CHECK(!img.data.empty());
        FUZZ_CHECK(img.data.size() <= limits.maxImageBytes);
        FUZZ_CHECK(img.endAddress() <= (uint64_t(1) << 32));
        const auto again = IntelHexLoader::parseHex(IntelHexWriter::write(img), limits);
        FUZZ_CHECK(again.ok());
        FUZZ_CHECK(again.image->startAddress == img.startAddress);
        FUZZ_CHECK(again.image->data == img.data);
        FUZZ_CHECK(again.image->entryPoint == img.entryPoint);
    }
    // The same bytes as a .bin at an address taken from the input.
    uint32_t start = 0;
    for (size_t i = 0; i < std::min<size_t>(4, size); ++i)
        start = start << 8 | data[i];
    const auto b = IntelHexLoader::fromBinary(text, start, limits);
    if (b.ok()) {
        FUZZ_CHECK(b.image->data.size() == size);
        FUZZ_CHECK(b.image->endAddress() <= (uint64_t(1) << 32));
    } else {
        FUZZ_CHECK(size == 0 || size > limits.maxImageBytes || uint64_t(start) + size > (uint64_t(1) << 32));
    }
    return 0;
}
