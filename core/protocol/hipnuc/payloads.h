#pragma once
// HiPNUC payload sub-packets: HI91 (float IMU, 76 B), HI92 (integer IMU, 48 B,
// v1.6.6 manual 3.3.2), HI81 (fixed-point INS, 104 B), HI83 (bitmap-selected,
// variable). Values are stored as they are on the wire (already scaled floats for
// HI91/HI83, raw integers for HI92/HI81) so that encode(decode(x)) == x byte for
// byte; toSample() converts to ImuDesk units (see core/model/sample.h).
#include "model/sample.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace imudesk::protocol::hipnuc {

enum Tag : uint8_t { TagHi91 = 0x91, TagHi92 = 0x92, TagHi81 = 0x81, TagHi83 = 0x83 };

struct Hi91 {
    static constexpr size_t kSize = 76;
    uint16_t mainStatus = 0;
    int8_t temperature = 0;      // degC
    float pressure = 0;          // Pa
    uint32_t systemTime = 0;     // ms
    std::array<float, 3> acc{};  // G
    std::array<float, 3> gyr{};  // deg/s
    std::array<float, 3> mag{};  // uT
    float roll = 0, pitch = 0, yaw = 0; // deg
    std::array<float, 4> quat{1, 0, 0, 0}; // w x y z
    friend bool operator==(const Hi91 &, const Hi91 &) = default;
};

struct Hi92 {
    static constexpr size_t kSize = 48;
    uint16_t status = 0;          // reserved in v1.6.6
    int8_t temperature = 0;       // degC
    uint16_t reserved = 0;
    int16_t pressure = 0;         // Pa - 100000
    int16_t heave = 0;            // x 0.01 m
    std::array<int16_t, 3> gyr{}; // x 0.001 rad/s
    std::array<int16_t, 3> acc{}; // x 0.0048828 m/s^2
    std::array<int16_t, 3> mag{}; // x 0.030517 uT
    int32_t roll = 0, pitch = 0, yaw = 0; // x 0.001 deg
    std::array<int16_t, 4> quat{10000, 0, 0, 0}; // x 0.0001
    friend bool operator==(const Hi92 &, const Hi92 &) = default;
};

struct Hi81 {
    static constexpr size_t kSize = 104;
    uint16_t mainStatus = 0;
    uint8_t insStatus = 0;
    uint16_t gpsWeek = 0;
    uint32_t gpsTowMs = 0;
    uint16_t reserved = 0;
    std::array<int16_t, 3> gyr{};  // x 0.001 rad/s
    std::array<int16_t, 3> acc{};  // x 0.0048828 m/s^2
    std::array<int16_t, 3> mag{};  // x 0.030517 uT
    int16_t pressure = 0;          // Pa - 100000 (firmware-dependent)
    int16_t odSpeed = 0;           // x 0.01 m/s
    int8_t temperature = 0;        // degC
    uint8_t utcYear = 0, utcMonth = 0, utcDay = 0, utcHour = 0, utcMinute = 0;
    uint16_t utcMs = 0;            // second*1000 + ms
    int16_t roll = 0, pitch = 0;   // x 0.01 deg
    uint16_t yaw = 0;              // x 0.01 deg, heading 0..360 clockwise
    std::array<int16_t, 4> quat{10000, 0, 0, 0}; // x 0.0001
    int32_t lon = 0, lat = 0;      // x 1e-7 deg
    int32_t msl = 0;               // x 0.001 m
    uint8_t pdop = 0, hdop = 0, solqPos = 0, nvPos = 0, solqHeading = 0, nvHeading = 0, diffAge = 0;
    int16_t undulation = 0;        // x 0.01 m
    uint8_t antStatus = 0;
    std::array<int16_t, 3> velEnu{}; // x 0.01 m/s
    std::array<int16_t, 3> accEnu{}; // x 0.0048828 m/s^2
    std::array<uint8_t, 14> tail{};  // reserved on current firmware
    friend bool operator==(const Hi81 &, const Hi81 &) = default;
};

struct Hi83 {
    // Bits with a known size (v1.7.1 manual 5.9.12: 0-19 and 25-31); 20-24 are reserved
    // there, without a size, and a frame that sets them is refused.
    static constexpr uint32_t kSupportedMask = 0xFE0FFFFFu;
    static constexpr uint32_t kDefaultMap = 0x000000FFu;
    uint16_t mainStatus = 0;
    uint8_t insStatus = 0;
    uint32_t bitmap = 0;
    std::array<float, 3> accB{};      // bit 0, m/s^2
    std::array<float, 3> gyrB{};      // bit 1, rad/s
    std::array<float, 3> magB{};      // bit 2, uT
    std::array<float, 3> rpy{};       // bit 3, deg
    std::array<float, 4> quat{1, 0, 0, 0}; // bit 4
    uint64_t systemTimeUs = 0;        // bit 5 (8 bytes; legacy 4-byte ms form, see legacyTime32)
    bool legacyTime32 = false;        //   early 1.7.1 builds: u32 ms
    std::array<uint8_t, 8> utc{};     // bit 6: yy mm dd hh mi ms(u16) reserved
    float pressure = 0;               // bit 7, Pa
    float temperature = 0;            // bit 8, degC
    std::array<float, 3> inclination{}; // bit 9, deg
    std::array<float, 3> hss{};       // bit 10, m
    std::array<float, 3> hssFreq{};   // bit 11, Hz
    std::array<float, 3> velEnu{};    // bit 12, m/s
    std::array<float, 3> accEnu{};    // bit 13, m/s^2
    std::array<double, 3> insLonLatMsl{}; // bit 14
    std::array<uint8_t, 4> gnssQualityNv{}; // bit 15
    float odSpeed = 0;                // bit 16
    float undulation = 0;             // bit 17
    float diffAge = 0;                // bit 18
    std::array<uint8_t, 4> nodeInfo{}; // bit 19
    std::array<uint32_t, 16> eventCounter{}; // bit 25: gravity, mag, gnss_pos, gnss_vel, dual_heading, nhc, zupt, zaru, zihr, od, reserved
    std::array<float, 3> kfAccBias{}; // bit 26, m/s^2
    std::array<float, 3> kfGyrBias{}; // bit 27, rad/s
    std::array<float, 3> gnssStd{};   // bit 28: position std norm, velocity std norm, reserved
    std::array<float, 3> gnssHeadingInfo{}; // bit 29: baseline m, pitch deg, heading deg
    std::array<double, 3> gnssLonLatMsl{}; // bit 30
    std::array<float, 3> gnssVel{};   // bit 31
    friend bool operator==(const Hi83 &, const Hi83 &) = default;

    // Size in bytes of one bitmap field; 0 for an unsupported bit.
    static size_t fieldSize(int bit);
    // Payload size implied by a bitmap, or std::nullopt if it has unsupported bits.
    static std::optional<size_t> payloadSize(uint32_t bitmap, bool legacyTime32 = false);
};

using Packet = std::variant<Hi91, Hi92, Hi81, Hi83>;

enum class PayloadError {
    None,
    Empty,
    UnknownTag,       // a tag no manual defines
    Truncated,        // a sub-packet runs past the payload
    UnsupportedBits,  // HI83 bitmap with a field of unknown size (never guessed)
    SizeMismatch,     // HI83 length does not match its bitmap
};

struct PayloadResult {
    std::vector<Packet> packets;   // the sub-packets decoded before any error
    PayloadError error = PayloadError::None;
    size_t errorOffset = 0;
    uint8_t errorTag = 0;
    bool ok() const { return error == PayloadError::None; }
};

// Walks every sub-packet of a frame payload (several tags may share a frame).
PayloadResult decodePayload(const uint8_t *data, size_t len);
inline PayloadResult decodePayload(const std::vector<uint8_t> &p) { return decodePayload(p.data(), p.size()); }
const char *payloadErrorText(PayloadError e);

// Fast path for the common one-HI91 frame: false when the payload is not exactly one HI91.
bool decodeHi91(const uint8_t *data, size_t len, Hi91 &out);

// A frame's payload, packet by packet: the fast path for a frame of exactly one HI91, else
// decodePayload(). `each` gets every packet decoded; the result tells what could not be
// decoded (its packet list is left empty: they went to `each`). The one place that turns a
// payload into packets, for the live session, the replay and the CLI alike.
template<typename F>
PayloadResult forEachPacket(const std::vector<uint8_t> &payload, F &&each)
{
    Hi91 h;
    if (decodeHi91(payload.data(), payload.size(), h)) {
        each(Packet(h));
        return {};
    }
    PayloadResult result = decodePayload(payload);
    for (const Packet &p : result.packets)
        each(p);
    result.packets.clear();
    return result;
}

std::vector<uint8_t> encode(const Hi91 &p);
std::vector<uint8_t> encode(const Hi92 &p);
std::vector<uint8_t> encode(const Hi81 &p);
std::vector<uint8_t> encode(const Hi83 &p);
std::vector<uint8_t> encode(const Packet &p);
// Concatenates sub-packets into one payload.
std::vector<uint8_t> encode(const std::vector<Packet> &packets);

std::string packetName(const Packet &p); // "HI91", ...
// The device time a packet carries, as toSample gives it (without building the sample): HI91's
// system_time, HI81's GPS time of week, HI83's system_time_us (when its bitmap has it).
struct PacketClock {
    const char *source = "";
    bool has = false;
    double deviceTimeMs = 0;
    bool hasStatus = false;
    uint16_t mainStatus = 0;
};
PacketClock packetClock(const Packet &p);
model::Sample toSample(const Packet &p);
model::Sample toSample(const Hi91 &p);

} // namespace imudesk::protocol::hipnuc
