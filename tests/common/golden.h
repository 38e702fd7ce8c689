#pragma once
// Golden vectors from the manuals, shared by the tests.
#include <QByteArray>

#include <cstdint>
#include <vector>

namespace golden {

// v1.7.1 manual 5.11 / v1.6.6 manual 3.5: one HI91 frame, 82 bytes, CRC 0xBB14.
inline QByteArray hi91Frame()
{
    return QByteArray::fromHex("5AA54C0014BB91081523" "09A2C447" "08151C00"
                               "CCE861BE9A35563E65EA723F" "31D07CBD75DDC5BB6BD724BC"
                               "8988FC400100 6A41AB2A70C2" "96D45041ED0343 4141F4F4C2"
                               "CCCAF8BE736A19BEF0001C3D8D375C3F");
}

// v1.7.1 manual 2.2.2.3: the RMC time message.
inline constexpr const char *kRmc = "$GPRMC,235952.00,A,3112.5000,N,12127.5000,E,0.0,0.0,141125,0.0,E,A*3B";

inline std::vector<uint8_t> bytes(const QByteArray &b)
{
    return std::vector<uint8_t>(b.begin(), b.end());
}

} // namespace golden
