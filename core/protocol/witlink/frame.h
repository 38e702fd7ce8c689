#pragma once
// Witlink (HEC495) serial frames, manual "通讯协议" section 1:
//
//   77 LEN ADDR CMD DATA... SUM
//
// LEN counts the bytes from LEN itself to SUM inclusive (4 + data bytes); SUM is the low
// byte of LEN + ADDR + CMD + DATA (carries dropped). Default link 9600 8N1, address 0x00.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace imudesk::protocol::witlink {

inline constexpr uint8_t kSync = 0x77;
inline constexpr size_t kMinLength = 4;  // LEN ADDR CMD SUM, no data
// The longest frame of the manual is the "read all" reply (LEN 0x58, 84 data bytes). The
// decoder refuses anything longer, so a false sync never holds back more than this.
inline constexpr size_t kMaxLength = 0x58;
inline constexpr size_t kMaxData = kMaxLength - kMinLength;

struct Frame {
    uint8_t address = 0;
    uint8_t command = 0;
    std::vector<uint8_t> data;
    friend bool operator==(const Frame &, const Frame &) = default;
};

// Low byte of the sum of n bytes.
uint8_t checksum(const uint8_t *p, size_t n);
// The whole frame (77 ... SUM). Data longer than kMaxData is not encodable: returns {}.
std::vector<uint8_t> encodeFrame(uint8_t address, uint8_t command, const std::vector<uint8_t> &data = {});
inline std::vector<uint8_t> encodeFrame(const Frame &f) { return encodeFrame(f.address, f.command, f.data); }

} // namespace imudesk::protocol::witlink
