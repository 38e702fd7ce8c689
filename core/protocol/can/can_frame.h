#pragma once
// One CAN frame as the codecs see it: identifier, format flags and up to 64 data bytes
// (classic CAN uses 0..8, CAN FD up to 64). A plain value type; conversions to and from
// Qt's QCanBusFrame live here too so transports and codecs share one shape.
#include <QByteArray>
#include <QMetaType>
#include <QString>

#include <array>
#include <cstdint>
#include <initializer_list>

class QCanBusFrame;

namespace imudesk::protocol::can {

inline constexpr size_t kMaxCanData = 64;

// Which scalar quantities a decoded frame carried: CAN devices split a sample over several
// frames (J1939 roll/pitch and heading, HEC495 acc axes over two PDOs), so merging needs more
// than Sample::fields.
enum Component : uint32_t {
    CompAccX = 1u << 0, CompAccY = 1u << 1, CompAccZ = 1u << 2,
    CompGyrX = 1u << 3, CompGyrY = 1u << 4, CompGyrZ = 1u << 5,
    CompMagX = 1u << 6, CompMagY = 1u << 7, CompMagZ = 1u << 8,
    CompRoll = 1u << 9, CompPitch = 1u << 10, CompYaw = 1u << 11,
    CompQuat = 1u << 12, CompPressure = 1u << 13, CompTemperature = 1u << 14,
    CompInclination = 1u << 15, CompDeviceTime = 1u << 16, CompMainStatus = 1u << 17,
    CompUtcTime = 1u << 18, // Sample::utcTimeOfDayS (J1939 FF2F)
};
// The components implied by Sample::fields (every axis of each group present).
uint32_t componentsOf(uint32_t sampleFields);

struct CanFrame {
    uint32_t id = 0;
    bool extended = false; // 29-bit identifier
    bool fd = false;       // CAN FD frame
    bool remote = false;   // remote transmission request
    uint8_t len = 0;
    std::array<uint8_t, kMaxCanData> data{};

    CanFrame() = default;
    CanFrame(uint32_t canId, bool ext, std::initializer_list<uint8_t> bytes);
    // Copies at most 64 bytes; a classic frame (fd == false) keeps at most 8.
    static CanFrame fromBytes(uint32_t canId, bool ext, const uint8_t *bytes, size_t n, bool fd = false);
    static CanFrame fromHex(uint32_t canId, bool ext, const char *hex);

    uint8_t at(size_t i) const { return i < len ? data[i] : 0; }
    QByteArray payload() const;
    // "0CFF3408" or "188"
    QString idText() const;
    // "4A 00 1F 00 C8 03"
    QString dataText() const;

    friend bool operator==(const CanFrame &a, const CanFrame &b);
};

QCanBusFrame toQt(const CanFrame &f);
CanFrame fromQt(const QCanBusFrame &f);

// Reads little-endian integers from a frame (0 beyond len).
uint16_t u16At(const CanFrame &f, size_t at);
int16_t i16At(const CanFrame &f, size_t at);
uint32_t u32At(const CanFrame &f, size_t at);
int32_t i32At(const CanFrame &f, size_t at);
float f32At(const CanFrame &f, size_t at);
void putU16(CanFrame &f, size_t at, uint16_t v);
void putU32(CanFrame &f, size_t at, uint32_t v);
void putF32(CanFrame &f, size_t at, float v);
// round(value / scale) clamped to the type's range.
int16_t toI16(double value, double scale);
int32_t toI32(double value, double scale);

} // namespace imudesk::protocol::can

Q_DECLARE_METATYPE(imudesk::protocol::can::CanFrame)
