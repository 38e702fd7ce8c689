#pragma once
// ROS 2 messages for MCAP files and the live bridge: their definitions as `ros2msg` schema text
// (the message, then each type it uses after a line of '=' and "MSG: package/Type", as ros2 bag
// and Foxglove write them) and their encoding in CDR (XCDR1, little-endian: the 4-byte
// encapsulation header 00 01 00 00, then each field aligned to its own size counted from the end
// of that header; strings as a uint32 length with the terminating NUL, then the bytes; fixed
// arrays without a length, sequences with a uint32 count).
//
// Values the module sends in single precision are written as the double of the single-precision
// SI value (what the tidy CSV holds).
//
//   sensor_msgs/msg/Imu            orientation (the module's quaternion), angular velocity rad/s,
//                                  linear acceleration m/s^2; a part the sample lacks has
//                                  covariance[0] = -1 (ROS: "not available")
//   sensor_msgs/msg/MagneticField  T (the module's uT x 1e-6)
//   sensor_msgs/msg/FluidPressure  Pa
//   sensor_msgs/msg/Temperature    degC
//   sensor_msgs/msg/NavSatFix      deg, deg, m
//   tf2_msgs/msg/TFMessage         the world frame to the module's frame, its attitude
//   geometry_msgs/msg/Vector3Stamped  the Euler angles in deg (x roll, y pitch, z yaw)
#include "model/sample.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace imudesk::format::mcap {

class CdrWriter {
public:
    CdrWriter() { reset(); }
    // Empty again (the encapsulation header only), in its own buffer, keeping its memory.
    void reset()
    {
        m_out = &m_own;
        m_base = 0;
        m_own.assign(kEncapsulation, 4);
    }
    // Encodes at the end of out instead, from its encapsulation header on (an MCAP chunk: the
    // message is written where it stays, not copied there), until reset().
    void into(std::string &out)
    {
        m_out = &out;
        m_base = out.size();
        out.append(kEncapsulation, 4);
    }
    void u8(uint8_t v) { m_out->push_back(char(v)); }
    void i8(int8_t v) { m_out->push_back(char(v)); }
    void u16(uint16_t v) { put(&v, 2); }
    void i32(int32_t v) { put(&v, 4); }
    void u32(uint32_t v) { put(&v, 4); }
    void f64(double v) { put(&v, 8); }
    // n doubles in a row (a vector or a fixed array), aligned once.
    void f64s(const double *v, size_t n)
    {
        align(8);
        m_out->append(reinterpret_cast<const char *>(v), n * 8);
    }
    void str(const std::string &s)
    {
        u32(uint32_t(s.size() + 1));
        m_out->append(s.data(), s.size() + 1); // with its NUL
    }
    // The message encoded so far.
    std::string_view data() const { return std::string_view(*m_out).substr(m_base); }

private:
    static constexpr char kEncapsulation[4] = {0x00, 0x01, 0x00, 0x00};
    void align(size_t n)
    {
        if (const size_t over = (m_out->size() - m_base - 4) % n; over != 0)
            m_out->append(n - over, '\0');
    }
    void put(const void *v, size_t n)
    {
        align(n);
        m_out->append(static_cast<const char *>(v), n); // little-endian host (static_assert in the .cpp)
    }
    std::string m_own;
    std::string *m_out = &m_own;
    size_t m_base = 0;
};

struct Ros2Type {
    const char *name;       // "sensor_msgs/msg/Imu"
    const char *definition; // the ros2msg schema text
};
const Ros2Type &imuType();
const Ros2Type &magneticFieldType();
const Ros2Type &fluidPressureType();
const Ros2Type &temperatureType();
const Ros2Type &navSatFixType();
const Ros2Type &tfMessageType();
const Ros2Type &vector3StampedType();

// A header stamp from ns since the Unix epoch.
struct Stamp {
    int32_t sec = 0;
    uint32_t nanosec = 0;
    static Stamp fromNs(uint64_t ns) { return {int32_t(ns / 1'000'000'000u), uint32_t(ns % 1'000'000'000u)}; }
};

// Each encodes into w where it stands (reset() or into() first) and returns the message.
std::string_view encodeImu(CdrWriter &w, const model::Sample &s, Stamp stamp, const std::string &frameId);
std::string_view encodeMagneticField(CdrWriter &w, const model::Sample &s, Stamp stamp, const std::string &frameId);
std::string_view encodeFluidPressure(CdrWriter &w, const model::Sample &s, Stamp stamp, const std::string &frameId);
std::string_view encodeTemperature(CdrWriter &w, const model::Sample &s, Stamp stamp, const std::string &frameId);
std::string_view encodeNavSatFix(CdrWriter &w, const model::Sample &s, Stamp stamp, const std::string &frameId);
// The Euler angles (deg) as geometry_msgs/msg/Vector3Stamped: x roll, y pitch, z yaw.
std::string_view encodeEuler(CdrWriter &w, const model::Sample &s, Stamp stamp, const std::string &frameId);
// One transform: worldFrame ("enu", "nwu") to frameId, rotated by the sample's quaternion.
std::string_view encodeTf(CdrWriter &w, const model::Sample &s, Stamp stamp, const std::string &worldFrame,
                            const std::string &frameId);

} // namespace imudesk::format::mcap
