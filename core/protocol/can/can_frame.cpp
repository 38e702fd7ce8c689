#include "can_frame.h"

#include <QCanBusFrame>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

namespace imudesk::protocol::can {

CanFrame::CanFrame(uint32_t canId, bool ext, std::initializer_list<uint8_t> bytes) : id(canId), extended(ext)
{
    len = uint8_t(std::min(bytes.size(), kMaxCanData));
    fd = len > 8;
    std::copy_n(bytes.begin(), len, data.begin());
}

CanFrame CanFrame::fromBytes(uint32_t canId, bool ext, const uint8_t *bytes, size_t n, bool isFd)
{
    CanFrame f;
    f.id = canId;
    f.extended = ext;
    f.fd = isFd;
    f.len = uint8_t(std::min(n, isFd ? kMaxCanData : size_t(8)));
    if (f.len)
        std::memcpy(f.data.data(), bytes, f.len);
    return f;
}

CanFrame CanFrame::fromHex(uint32_t canId, bool ext, const char *hex)
{
    const QByteArray b = QByteArray::fromHex(QByteArray(hex));
    return fromBytes(canId, ext, reinterpret_cast<const uint8_t *>(b.constData()), size_t(b.size()), b.size() > 8);
}

QByteArray CanFrame::payload() const
{
    return QByteArray(reinterpret_cast<const char *>(data.data()), len);
}

QString CanFrame::idText() const
{
    return QStringLiteral("%1").arg(id, extended ? 8 : 3, 16, QLatin1Char('0')).toUpper();
}

QString CanFrame::dataText() const
{
    return QString::fromLatin1(payload().toHex(' ').toUpper());
}

bool operator==(const CanFrame &a, const CanFrame &b)
{
    return a.id == b.id && a.extended == b.extended && a.fd == b.fd && a.remote == b.remote && a.len == b.len
        && std::equal(a.data.begin(), a.data.begin() + a.len, b.data.begin());
}

QCanBusFrame toQt(const CanFrame &f)
{
    QCanBusFrame q(f.id, f.payload());
    q.setExtendedFrameFormat(f.extended);
    q.setFlexibleDataRateFormat(f.fd);
    if (f.remote)
        q.setFrameType(QCanBusFrame::RemoteRequestFrame);
    return q;
}

CanFrame fromQt(const QCanBusFrame &q)
{
    const QByteArray p = q.payload();
    CanFrame f = CanFrame::fromBytes(q.frameId(), q.hasExtendedFrameFormat(), reinterpret_cast<const uint8_t *>(p.constData()),
                                     size_t(p.size()), q.hasFlexibleDataRateFormat());
    f.remote = q.frameType() == QCanBusFrame::RemoteRequestFrame;
    return f;
}

namespace {
template <typename T> T readLe(const CanFrame &f, size_t at)
{
    T v{};
    if (at + sizeof(T) <= f.len)
        std::memcpy(&v, f.data.data() + at, sizeof(T));
    return v;
}
template <typename T> void writeLe(CanFrame &f, size_t at, T v)
{
    if (at + sizeof(T) > kMaxCanData)
        return;
    std::memcpy(f.data.data() + at, &v, sizeof(T));
    f.len = uint8_t(std::max<size_t>(f.len, at + sizeof(T)));
}
template <typename T> T scaled(double value, double scale)
{
    const double r = std::round(value / scale);
    if (!(r == r))
        return 0;
    return T(std::clamp(r, double(std::numeric_limits<T>::min()), double(std::numeric_limits<T>::max())));
}
} // namespace

uint32_t componentsOf(uint32_t f)
{
    uint32_t c = 0;
    if (f & (1u << 0)) c |= CompAccX | CompAccY | CompAccZ;
    if (f & (1u << 1)) c |= CompGyrX | CompGyrY | CompGyrZ;
    if (f & (1u << 2)) c |= CompMagX | CompMagY | CompMagZ;
    if (f & (1u << 3)) c |= CompRoll | CompPitch | CompYaw;
    if (f & (1u << 4)) c |= CompQuat;
    if (f & (1u << 5)) c |= CompPressure;
    if (f & (1u << 6)) c |= CompTemperature;
    if (f & (1u << 7)) c |= CompDeviceTime;
    if (f & (1u << 8)) c |= CompMainStatus;
    if (f & (1u << 12)) c |= CompInclination;
    return c;
}

uint16_t u16At(const CanFrame &f, size_t at) { return readLe<uint16_t>(f, at); }
int16_t i16At(const CanFrame &f, size_t at) { return readLe<int16_t>(f, at); }
uint32_t u32At(const CanFrame &f, size_t at) { return readLe<uint32_t>(f, at); }
int32_t i32At(const CanFrame &f, size_t at) { return readLe<int32_t>(f, at); }
float f32At(const CanFrame &f, size_t at) { return readLe<float>(f, at); }
void putU16(CanFrame &f, size_t at, uint16_t v) { writeLe(f, at, v); }
void putU32(CanFrame &f, size_t at, uint32_t v) { writeLe(f, at, v); }
void putF32(CanFrame &f, size_t at, float v) { writeLe(f, at, v); }
int16_t toI16(double value, double scale) { return scaled<int16_t>(value, scale); }
int32_t toI32(double value, double scale) { return scaled<int32_t>(value, scale); }

} // namespace imudesk::protocol::can
