#include "capture_format.h"

#include "format/crc32.h"

#include <cstring>

namespace imudesk::capture {

namespace {

template<typename T>
void put(std::vector<uint8_t> &out, T v)
{
    uint8_t b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T)); // little-endian host (see format/crc32.cpp)
    out.insert(out.end(), b, b + sizeof(T));
}

} // namespace

std::vector<uint8_t> encodeFileHeader(const CaptureHeader &header)
{
    const std::vector<uint8_t> body = header.encodeBody();
    std::vector<uint8_t> out(kMagic, kMagic + sizeof kMagic);
    put<uint16_t>(out, kVersion);
    put<uint16_t>(out, 0);
    put<uint32_t>(out, uint32_t(body.size()));
    out.insert(out.end(), body.begin(), body.end());
    put<uint32_t>(out, format::crc32(0, out.data(), out.size()));
    return out;
}

void appendChunk(std::vector<uint8_t> &out, ChunkKind kind, int64_t monotonicNs, int64_t wallUs, const uint8_t *data,
                 size_t n)
{
    const size_t start = out.size();
    put<uint32_t>(out, kChunkMagic);
    put<uint16_t>(out, kind);
    put<uint16_t>(out, 0);
    put<uint32_t>(out, uint32_t(n));
    put<int64_t>(out, monotonicNs);
    put<int64_t>(out, wallUs);
    out.insert(out.end(), data, data + n);
    put<uint32_t>(out, format::crc32(0, out.data() + start, out.size() - start));
}

} // namespace imudesk::capture
