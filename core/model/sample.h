#pragma once
// One measurement, whatever device family or frame type produced it.
//
// Units (the HiPNUC manual's units, used across ImuDesk):
//   acc          G (1 G = 9.8 m/s^2, the vendor's constant; see kGravity)
//   gyr          deg/s
//   mag          uT
//   roll/pitch/yaw  deg, in the device's Euler convention (ENU-312 by default)
//   quat         w, x, y, z (body to navigation)
//   pressure     Pa
//   temperature  degC
//   deviceTimeMs device timestamp in ms (HI91 system_time; HI83 system_time_us / 1000)
//   hostTimeNs   monotonic host clock when the bytes arrived (0 when decoded offline)
#include <array>
#include <cstdint>
#include <string>

namespace imudesk::model {

inline constexpr double kGravity = 9.8;          // vendor firmware divides m/s^2 by 9.8
inline constexpr double kRadToDeg = 57.29577951308232;
inline constexpr double kDegToRad = 0.017453292519943295;

struct Vec3 {
    double x = 0, y = 0, z = 0;
    friend bool operator==(const Vec3 &, const Vec3 &) = default;
};

struct Quat {
    double w = 1, x = 0, y = 0, z = 0;
    friend bool operator==(const Quat &, const Quat &) = default;
};

// Which members of a Sample hold data.
enum SampleField : uint32_t {
    FieldAcc = 1u << 0,
    FieldGyr = 1u << 1,
    FieldMag = 1u << 2,
    FieldEuler = 1u << 3,
    FieldQuat = 1u << 4,
    FieldPressure = 1u << 5,
    FieldTemperature = 1u << 6,
    FieldDeviceTime = 1u << 7,
    FieldMainStatus = 1u << 8,
    FieldPosition = 1u << 9,      // lat/lon/alt
    FieldVelocity = 1u << 10,     // ENU velocity
    FieldHeave = 1u << 11,        // heave/surge/sway
    FieldInclination = 1u << 12,  // inclinometer x/y
    FieldInsStatus = 1u << 13,
    FieldGnss = 1u << 14,         // GNSS fix quality, satellites, UTC time of day (NMEA)
};

struct Sample {
    std::string source;      // "HI91", "HI92", "HI81", "HI83", ...
    uint32_t fields = 0;     // SampleField bits
    int64_t hostTimeNs = 0;
    uint16_t mainStatus = 0;
    uint8_t insStatus = 0;
    double deviceTimeMs = 0;
    Vec3 acc, gyr, mag;
    double roll = 0, pitch = 0, yaw = 0;
    Quat quat;
    double pressurePa = 0;
    double temperatureC = 0;
    double latitudeDeg = 0, longitudeDeg = 0, altitudeM = 0; // altitude NaN: not reported
    Vec3 velEnu;            // m/s
    Vec3 heaveSurgeSway;    // m
    double inclinationX = 0, inclinationY = 0; // deg
    int gnssQuality = -1;       // GGA style: 0 none, 1 single, 2 DGNSS, 4 RTK fixed, 5 RTK float; -1 not reported
    int gnssSatellites = -1;    // -1: not reported
    double utcTimeOfDayS = -1;  // seconds since UTC midnight; -1: not reported

    bool has(SampleField f) const { return (fields & f) != 0; }
};

// Copies every field group that src carries into dst (dst keeps the others) and takes src's
// source and host time: "the latest value of each quantity" when a link interleaves frames
// that carry different fields (HEC495 angles between full records, NMEA between HI91 frames).
void mergeFields(Sample &dst, const Sample &src);

} // namespace imudesk::model
