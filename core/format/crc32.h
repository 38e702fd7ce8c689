#pragma once
// CRC-32 (IEEE 802.3: reflected polynomial 0xEDB88320, initial value and final XOR
// 0xFFFFFFFF), the checksum zlib, PNG and gzip use; check value of "123456789" is
// 0xCBF43926. Slicing-by-8 tables, so checking a capture costs little next to decoding it.
#include <cstddef>
#include <cstdint>

namespace imudesk::format {

// Continues a running CRC: crc32(crc32(0, a), b) == crc32 of a followed by b.
uint32_t crc32(uint32_t crc, const void *data, size_t n);

} // namespace imudesk::format
