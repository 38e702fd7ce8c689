#pragma once
// CRC-16/XMODEM (poly 0x1021, init 0, no reflection, no final XOR), as used by
// HiPNUC frames and KBOOT packets. check("123456789") == 0x31C3.
#include <cstddef>
#include <cstdint>

namespace imudesk::protocol::hipnuc {

// Fast path: slicing-by-8 tables.
uint16_t crc16Update(uint16_t crc, const uint8_t *data, size_t len);
inline uint16_t crc16(const uint8_t *data, size_t len) { return crc16Update(0, data, len); }

// The bit-by-bit form printed in the manual (section 5.10); reference and baseline.
uint16_t crc16UpdateBitwise(uint16_t crc, const uint8_t *data, size_t len);

// CRC of a HiPNUC/KBOOT frame: the 4 header bytes then the payload (CRC field skipped).
uint16_t frameCrc(const uint8_t *header4, const uint8_t *payload, size_t payloadLen);

} // namespace imudesk::protocol::hipnuc
