#include "ros2_messages.h"

#include <bit>
#include <cmath>

namespace imudesk::format::mcap {

static_assert(std::endian::native == std::endian::little, "CdrWriter copies little-endian values as they are");

namespace {

#define IMUDESK_SEP "\n================================================================================\n"

constexpr const char *kHeaderDeps = IMUDESK_SEP "MSG: std_msgs/Header\n"
                                                "builtin_interfaces/Time stamp\n"
                                                "string frame_id\n" IMUDESK_SEP "MSG: builtin_interfaces/Time\n"
                                                "int32 sec\n"
                                                "uint32 nanosec\n";
constexpr const char *kVector3 = IMUDESK_SEP "MSG: geometry_msgs/Vector3\n"
                                             "float64 x\n"
                                             "float64 y\n"
                                             "float64 z\n";
constexpr const char *kQuaternion = IMUDESK_SEP "MSG: geometry_msgs/Quaternion\n"
                                                "float64 x 0\n"
                                                "float64 y 0\n"
                                                "float64 z 0\n"
                                                "float64 w 1\n";

std::string join(std::initializer_list<const char *> parts)
{
    std::string s;
    for (const char *p : parts)
        s += p;
    return s;
}

// A value the module sent in single precision, scaled to SI: kept at that precision (the tidy CSV's
// value exactly), which also leaves the double's low bits zero for the chunk's compression.
double single(double v) { return double(float(v)); }

void header(CdrWriter &w, Stamp stamp, const std::string &frameId)
{
    w.i32(stamp.sec);
    w.u32(stamp.nanosec);
    w.str(frameId);
}

void vector3(CdrWriter &w, double x, double y, double z)
{
    const double v[3] = {x, y, z};
    w.f64s(v, 3);
}

// A covariance nobody measured: all zero ("unknown"), or -1 first ("this part is not available").
void covariance(CdrWriter &w, bool available)
{
    static constexpr double kUnknown[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    static constexpr double kNotAvailable[9] = {-1, 0, 0, 0, 0, 0, 0, 0, 0};
    w.f64s(available ? kUnknown : kNotAvailable, 9);
}

} // namespace

const Ros2Type &imuType()
{
    static const std::string def = join({"std_msgs/Header header\n"
                                         "geometry_msgs/Quaternion orientation\n"
                                         "float64[9] orientation_covariance\n"
                                         "geometry_msgs/Vector3 angular_velocity\n"
                                         "float64[9] angular_velocity_covariance\n"
                                         "geometry_msgs/Vector3 linear_acceleration\n"
                                         "float64[9] linear_acceleration_covariance\n",
                                         kHeaderDeps, kQuaternion, kVector3});
    static const Ros2Type t{"sensor_msgs/msg/Imu", def.c_str()};
    return t;
}

const Ros2Type &magneticFieldType()
{
    static const std::string def = join({"std_msgs/Header header\n"
                                         "geometry_msgs/Vector3 magnetic_field\n"
                                         "float64[9] magnetic_field_covariance\n",
                                         kHeaderDeps, kVector3});
    static const Ros2Type t{"sensor_msgs/msg/MagneticField", def.c_str()};
    return t;
}

const Ros2Type &fluidPressureType()
{
    static const std::string def = join({"std_msgs/Header header\n"
                                         "float64 fluid_pressure\n"
                                         "float64 variance\n",
                                         kHeaderDeps});
    static const Ros2Type t{"sensor_msgs/msg/FluidPressure", def.c_str()};
    return t;
}

const Ros2Type &temperatureType()
{
    static const std::string def = join({"std_msgs/Header header\n"
                                         "float64 temperature\n"
                                         "float64 variance\n",
                                         kHeaderDeps});
    static const Ros2Type t{"sensor_msgs/msg/Temperature", def.c_str()};
    return t;
}

const Ros2Type &navSatFixType()
{
    static const std::string def = join({"std_msgs/Header header\n"
                                         "sensor_msgs/NavSatStatus status\n"
                                         "float64 latitude\n"
                                         "float64 longitude\n"
                                         "float64 altitude\n"
                                         "float64[9] position_covariance\n"
                                         "uint8 COVARIANCE_TYPE_UNKNOWN=0\n"
                                         "uint8 COVARIANCE_TYPE_APPROXIMATED=1\n"
                                         "uint8 COVARIANCE_TYPE_DIAGONAL_KNOWN=2\n"
                                         "uint8 COVARIANCE_TYPE_KNOWN=3\n"
                                         "uint8 position_covariance_type\n",
                                         kHeaderDeps,
                                         IMUDESK_SEP "MSG: sensor_msgs/NavSatStatus\n"
                                                     "int8 STATUS_NO_FIX=-1\n"
                                                     "int8 STATUS_FIX=0\n"
                                                     "int8 STATUS_SBAS_FIX=1\n"
                                                     "int8 STATUS_GBAS_FIX=2\n"
                                                     "int8 status\n"
                                                     "uint16 SERVICE_GPS=1\n"
                                                     "uint16 SERVICE_GLONASS=2\n"
                                                     "uint16 SERVICE_COMPASS=4\n"
                                                     "uint16 SERVICE_GALILEO=8\n"
                                                     "uint16 service\n"});
    static const Ros2Type t{"sensor_msgs/msg/NavSatFix", def.c_str()};
    return t;
}

const Ros2Type &tfMessageType()
{
    static const std::string def = join({"geometry_msgs/TransformStamped[] transforms\n",
                                         IMUDESK_SEP "MSG: geometry_msgs/TransformStamped\n"
                                                     "std_msgs/Header header\n"
                                                     "string child_frame_id\n"
                                                     "geometry_msgs/Transform transform\n",
                                         kHeaderDeps,
                                         IMUDESK_SEP "MSG: geometry_msgs/Transform\n"
                                                     "geometry_msgs/Vector3 translation\n"
                                                     "geometry_msgs/Quaternion rotation\n",
                                         kVector3, kQuaternion});
    static const Ros2Type t{"tf2_msgs/msg/TFMessage", def.c_str()};
    return t;
}

const Ros2Type &vector3StampedType()
{
    static const std::string def = join({"std_msgs/Header header\n"
                                         "geometry_msgs/Vector3 vector\n",
                                         kHeaderDeps, kVector3});
    static const Ros2Type t{"geometry_msgs/msg/Vector3Stamped", def.c_str()};
    return t;
}

std::string_view encodeEuler(CdrWriter &w, const model::Sample &s, Stamp stamp, const std::string &frameId)
{
    header(w, stamp, frameId);
    vector3(w, single(s.roll), single(s.pitch), single(s.yaw));
    return w.data();
}

std::string_view encodeImu(CdrWriter &w, const model::Sample &s, Stamp stamp, const std::string &frameId)
{
    using namespace model;
    header(w, stamp, frameId);
    const bool q = s.has(FieldQuat), g = s.has(FieldGyr), a = s.has(FieldAcc);
    if (q) {
        const double quat[4] = {s.quat.x, s.quat.y, s.quat.z, s.quat.w};
        w.f64s(quat, 4);
    } else {
        vector3(w, 0, 0, 0);
        w.f64(1);
    }
    covariance(w, q);
    if (g)
        vector3(w, single(s.gyr.x * kDegToRad), single(s.gyr.y * kDegToRad), single(s.gyr.z * kDegToRad));
    else
        vector3(w, 0, 0, 0);
    covariance(w, g);
    if (a)
        vector3(w, single(s.acc.x * kGravity), single(s.acc.y * kGravity), single(s.acc.z * kGravity));
    else
        vector3(w, 0, 0, 0);
    covariance(w, a);
    return w.data();
}

std::string_view encodeMagneticField(CdrWriter &w, const model::Sample &s, Stamp stamp, const std::string &frameId)
{
    header(w, stamp, frameId);
    vector3(w, single(s.mag.x * 1e-6), single(s.mag.y * 1e-6), single(s.mag.z * 1e-6));
    covariance(w, true);
    return w.data();
}

std::string_view encodeFluidPressure(CdrWriter &w, const model::Sample &s, Stamp stamp, const std::string &frameId)
{
    header(w, stamp, frameId);
    w.f64(s.pressurePa);
    w.f64(0);
    return w.data();
}

std::string_view encodeTemperature(CdrWriter &w, const model::Sample &s, Stamp stamp, const std::string &frameId)
{
    header(w, stamp, frameId);
    w.f64(s.temperatureC);
    w.f64(0);
    return w.data();
}

std::string_view encodeNavSatFix(CdrWriter &w, const model::Sample &s, Stamp stamp, const std::string &frameId)
{
    header(w, stamp, frameId);
    // NavSatStatus: a fix where the sample says so (or has no quality to say), GPS.
    w.i8(s.gnssQuality == 0 ? int8_t(-1) : int8_t(0));
    w.u16(1);
    w.f64(s.latitudeDeg);
    w.f64(s.longitudeDeg);
    w.f64(std::isfinite(s.altitudeM) ? s.altitudeM : std::nan(""));
    for (int i = 0; i < 9; ++i)
        w.f64(0);
    w.u8(0);
    return w.data();
}

std::string_view encodeTf(CdrWriter &w, const model::Sample &s, Stamp stamp, const std::string &worldFrame,
                            const std::string &frameId)
{
    w.u32(1); // one transform
    header(w, stamp, worldFrame);
    w.str(frameId);
    vector3(w, 0, 0, 0);
    w.f64(s.quat.x);
    w.f64(s.quat.y);
    w.f64(s.quat.z);
    w.f64(s.quat.w);
    return w.data();
}

} // namespace imudesk::format::mcap
