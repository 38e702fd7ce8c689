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
#include <memory>
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

// The HI83 fields (v1.7.1 manual 5.9.12) that no other frame carries. A sample holds them
// behind a shared pointer, so a sample without them stays small and copies without a heap
// allocation. `bits` says which of them the frame carried (the data_bitmap bit numbers).
struct Hi83Extra {
    uint32_t bits = 0;
    std::array<uint16_t, 3> utcDate{};      // bit 6: year (2000 + yy), month, day; the time of day is Sample::utcTimeOfDayS
    std::array<float, 3> hssFreqHz{};       // bit 11: heave, surge, sway
    std::array<float, 3> accEnu{};          // bit 13, m/s^2
    uint8_t solqPos = 0, nvPos = 0, solqHeading = 0, nvHeading = 0; // bit 15
    float odSpeedMs = 0;                    // bit 16
    float undulationM = 0;                  // bit 17
    float diffAgeS = 0;                     // bit 18
    uint8_t nodeId = 0;                     // bit 19
    std::array<uint32_t, 16> eventCounter{}; // bit 25: gravity, mag, gnss_pos, gnss_vel, dual_heading, nhc, zupt, zaru, zihr, od, reserved...
    std::array<float, 3> kfAccBias{};       // bit 26, m/s^2
    std::array<float, 3> kfGyrBias{};       // bit 27, rad/s
    std::array<float, 3> gnssStd{};         // bit 28: position std norm, velocity std norm, reserved
    std::array<float, 3> dualHeading{};     // bit 29: baseline m, pitch deg, heading deg
    std::array<double, 3> gnssLonLatMsl{};  // bit 30: deg, deg, m
    std::array<float, 3> gnssVelEnu{};      // bit 31, m/s
    bool has(int bit) const { return (bits >> bit) & 1u; }
    friend bool operator==(const Hi83Extra &, const Hi83Extra &) = default;
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
    FieldHeading = 1u << 15,      // a heading reported on its own (NMEA HDT, HDM)
    FieldHi83Extra = 1u << 16,    // Sample::hi83: HI83 fields beyond the ones above
    FieldMagRelative = 1u << 17,  // a compass's relative magnetic field (HEC495: no unit)
    FieldMagRoll = 1u << 18,      // magnetic tool face (HEC495 read-all record)
};

struct Sample {
    std::string source;      // "HI91", "HI92", "HI81", "HI83", ...
    uint32_t fields = 0;     // SampleField bits
    int64_t hostTimeNs = 0;  // arrival on the host clock (clock::hostNowNs)
    // The sampling instant on the host clock, from the device's own time through its clock
    // model (core/clock); 0 where the sample has no device time or no model yet.
    int64_t commonTimeNs = 0;
    // For a polled device without a counter (HEC495, Modbus), the common time is the middle of
    // its request's send and its answer's arrival (clock::bracketTime), and this is half that
    // interval: the sampling instant lies within commonTimeNs +- this. 0: from a clock model.
    int64_t commonUncertaintyNs = 0;
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
    double headingDeg = 0;      // FieldHeading, 0..360 clockwise from north
    bool headingTrue = true;    //   from true north (NMEA HDT) or magnetic north (HDM)
    // FieldMagRelative: the HEC495's magnetic field on serial (2.5) and CAN alike, no unit: the
    // horizontal northward field is 1. Not in uT, so never in `mag` (or its charts).
    Vec3 magRelative;
    double magRollDeg = 0;      // FieldMagRoll: magnetic tool face, deg (meaningful near pitch +-90)
    std::shared_ptr<const Hi83Extra> hi83; // FieldHi83Extra

    bool has(SampleField f) const { return (fields & f) != 0; }
};

// Copies every field group that src carries into dst (dst keeps the others) and takes src's
// source and host time: "the latest value of each quantity" when a link interleaves frames
// that carry different fields (HEC495 angles between full records, NMEA between HI91 frames).
void mergeFields(Sample &dst, const Sample &src);

} // namespace imudesk::model
