#pragma once
// A firmware image: contiguous bytes at a start address (gaps already filled with 0xFF),
// as loaded from an Intel HEX or a raw .bin file.
#include <cstdint>
#include <optional>
#include <vector>

namespace imudesk::protocol::ihex {

struct FirmwareImage {
    uint32_t startAddress = 0;
    std::vector<uint8_t> data;
    std::optional<uint32_t> entryPoint;   // type 05 (EIP) or type 03 (CS << 4 + IP)

    uint32_t size() const { return uint32_t(data.size()); }
    // One past the last byte (64-bit: an image may end exactly at 4 GiB).
    uint64_t endAddress() const { return uint64_t(startAddress) + data.size(); }
    bool empty() const { return data.empty(); }
    // CRC-32 (IEEE 802.3, as zlib/PNG) over the data: shown to the user and logged.
    uint32_t crc32() const;
};

// CRC-32 (poly 0x04C11DB7 reflected, init/xorout 0xFFFFFFFF). check("123456789") == 0xCBF43926.
uint32_t crc32(const uint8_t *data, size_t n, uint32_t crc = 0);

} // namespace imudesk::protocol::ihex
