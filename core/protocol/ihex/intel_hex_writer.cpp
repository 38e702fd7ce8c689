#include "intel_hex_writer.h"

#include <algorithm>

namespace imudesk::protocol::ihex {

namespace {

void record(std::string &out, uint8_t type, uint16_t address, const uint8_t *data, size_t n)
{
    static const char *hex = "0123456789ABCDEF";
    uint8_t sum = uint8_t(n) + uint8_t(address >> 8) + uint8_t(address) + type;
    auto put = [&out](uint8_t b) {
        out += hex[b >> 4];
        out += hex[b & 15];
    };
    out += ':';
    put(uint8_t(n));
    put(uint8_t(address >> 8));
    put(uint8_t(address));
    put(type);
    for (size_t i = 0; i < n; ++i) {
        put(data[i]);
        sum = uint8_t(sum + data[i]);
    }
    put(uint8_t(-sum));
    out += "\r\n";
}

} // namespace

std::string IntelHexWriter::write(const FirmwareImage &image, size_t bytesPerRecord)
{
    bytesPerRecord = std::clamp<size_t>(bytesPerRecord, 1, 255);
    std::string out;
    out.reserve(image.data.size() * 2 + image.data.size() / bytesPerRecord * 13 + 64);
    uint64_t upper = ~uint64_t(0);
    size_t i = 0;
    while (i < image.data.size()) {
        const uint64_t at = uint64_t(image.startAddress) + i;
        if ((at >> 16) != upper) {
            upper = at >> 16;
            const uint8_t ext[2] = {uint8_t(upper >> 8), uint8_t(upper)};
            record(out, 0x04, 0, ext, 2);
        }
        const size_t toBoundary = size_t(0x10000 - (at & 0xFFFF));
        const size_t n = std::min({bytesPerRecord, image.data.size() - i, toBoundary});
        record(out, 0x00, uint16_t(at & 0xFFFF), image.data.data() + i, n);
        i += n;
    }
    if (image.entryPoint) {
        const uint32_t e = *image.entryPoint;
        const uint8_t b[4] = {uint8_t(e >> 24), uint8_t(e >> 16), uint8_t(e >> 8), uint8_t(e)};
        record(out, 0x05, 0, b, 4);
    }
    record(out, 0x01, 0, nullptr, 0);
    return out;
}

} // namespace imudesk::protocol::ihex
