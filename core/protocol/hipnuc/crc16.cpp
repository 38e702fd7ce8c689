#include "crc16.h"

#include <array>

namespace imudesk::protocol::hipnuc {
namespace {

using Tables = std::array<std::array<uint16_t, 256>, 8>;

constexpr Tables makeTables()
{
    Tables t{};
    for (unsigned b = 0; b < 256; ++b) {
        uint16_t crc = uint16_t(b << 8);
        for (int i = 0; i < 8; ++i)
            crc = (crc & 0x8000) ? uint16_t((crc << 1) ^ 0x1021) : uint16_t(crc << 1);
        t[0][b] = crc;
    }
    // t[k][b]: the CRC contribution of byte b followed by k zero bytes.
    for (int k = 1; k < 8; ++k)
        for (unsigned b = 0; b < 256; ++b) {
            const uint16_t prev = t[k - 1][b];
            t[k][b] = uint16_t((prev << 8) ^ t[0][prev >> 8]);
        }
    return t;
}

constexpr Tables kTables = makeTables();

} // namespace

uint16_t crc16Update(uint16_t crc, const uint8_t *p, size_t len)
{
    const auto &t = kTables;
    while (len >= 8) {
        const uint8_t x0 = uint8_t(p[0] ^ (crc >> 8));
        const uint8_t x1 = uint8_t(p[1] ^ (crc & 0xFF));
        crc = uint16_t(t[7][x0] ^ t[6][x1] ^ t[5][p[2]] ^ t[4][p[3]] ^ t[3][p[4]] ^ t[2][p[5]]
                       ^ t[1][p[6]] ^ t[0][p[7]]);
        p += 8;
        len -= 8;
    }
    while (len--)
        crc = uint16_t((crc << 8) ^ t[0][((crc >> 8) ^ *p++) & 0xFF]);
    return crc;
}

uint16_t crc16UpdateBitwise(uint16_t correctCrc, const uint8_t *src, size_t len)
{
    uint32_t crc = correctCrc;
    for (size_t j = 0; j < len; ++j) {
        crc ^= uint32_t(src[j]) << 8;
        for (int i = 0; i < 8; ++i) {
            uint32_t temp = crc << 1;
            if (crc & 0x8000)
                temp ^= 0x1021;
            crc = temp;
        }
    }
    return uint16_t(crc);
}

uint16_t frameCrc(const uint8_t *header4, const uint8_t *payload, size_t payloadLen)
{
    return crc16Update(crc16Update(0, header4, 4), payload, payloadLen);
}

} // namespace imudesk::protocol::hipnuc
