#include "attitude.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace imudesk::model {

namespace {

Eigen::Quaterniond toEigen(const Quat &q)
{
    return Eigen::Quaterniond(q.w, q.x, q.y, q.z);
}

Quat fromEigen(const Eigen::Quaterniond &q)
{
    return Quat{q.w(), q.x(), q.y(), q.z()};
}

// Turns -0.0 into 0.0 so that printed angles never read "-0".
double noNegativeZero(double v)
{
    return v == 0 ? 0.0 : v;
}

double asinClamped(double s)
{
    return std::asin(std::clamp(s, -1.0, 1.0));
}

// |sin(pitch)| above this is treated as gimbal lock (pitch within about 0.0001 deg of
// +-90): both atan2 arguments of the appendix formulas vanish there and their ratio is
// rounding noise, so roll is set to 0 and yaw taken from the axis that stays horizontal.
constexpr double kGimbalLockSin = 1.0 - 1e-12;

// The axis swap between the ENU/RFU and the NED/FRD frames: (a,b,c) -> (b,a,-c), a
// 180 deg rotation about (1,1,0)/sqrt2. It is its own inverse.
Eigen::Quaterniond frameSwap()
{
    constexpr double h = 0.70710678118654752440;
    return Eigen::Quaterniond(0.0, h, h, 0.0);
}

} // namespace

double quatNorm(const Quat &q)
{
    return std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
}

bool isUsableQuat(const Quat &q)
{
    if (!std::isfinite(q.w) || !std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z))
        return false;
    const double n = quatNorm(q);
    return std::isfinite(n) && n > 1e-9;
}

Quat normalized(const Quat &q)
{
    if (!isUsableQuat(q))
        return Quat{};
    const double n = quatNorm(q);
    return Quat{q.w / n, q.x / n, q.y / n, q.z / n};
}

Quat canonical(const Quat &q)
{
    Quat n = normalized(q);
    if (n.w < 0)
        n = Quat{-n.w, -n.x, -n.y, -n.z};
    return Quat{noNegativeZero(n.w), noNegativeZero(n.x), noNegativeZero(n.y), noNegativeZero(n.z)};
}

Quat multiply(const Quat &a, const Quat &b)
{
    return fromEigen(toEigen(a) * toEigen(b));
}

Quat conjugate(const Quat &q)
{
    return Quat{q.w, -q.x, -q.y, -q.z};
}

double angleBetweenDeg(const Quat &a, const Quat &b)
{
    const Eigen::Quaterniond d = toEigen(normalized(a)).conjugate() * toEigen(normalized(b));
    // atan2 keeps precision for tiny angles where acos(|w|) would not.
    return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w())) * kRadToDeg;
}

Vec3 rotate(const Quat &q, const Vec3 &v)
{
    const Eigen::Vector3d r = toEigen(normalized(q)) * Eigen::Vector3d(v.x, v.y, v.z);
    return Vec3{r.x(), r.y(), r.z()};
}

Matrix3 rotationMatrix(const Quat &qIn)
{
    const Quat q = normalized(qIn);
    const double q0 = q.w, q1 = q.x, q2 = q.y, q3 = q.z;
    // The manual's C_b2n, written out as in appendix 1 (10.35).
    Matrix3 c;
    c[0] = {q0 * q0 + q1 * q1 - q2 * q2 - q3 * q3, 2 * (q1 * q2 - q0 * q3), 2 * (q1 * q3 + q0 * q2)};
    c[1] = {2 * (q1 * q2 + q0 * q3), q0 * q0 - q1 * q1 + q2 * q2 - q3 * q3, 2 * (q2 * q3 - q0 * q1)};
    c[2] = {2 * (q1 * q3 - q0 * q2), 2 * (q2 * q3 + q0 * q1), q0 * q0 - q1 * q1 - q2 * q2 + q3 * q3};
    return c;
}

Euler eulerEnu312(const Quat &qIn)
{
    const Quat q = normalized(qIn);
    const double q0 = q.w, q1 = q.x, q2 = q.y, q3 = q.z;
    Euler e;
    const double sinPitch = 2 * (q0 * q1 + q2 * q3);
    e.pitch = asinClamped(sinPitch) * kRadToDeg;
    if (std::abs(sinPitch) > kGimbalLockSin) {
        // C = Rz(yaw) * Rx(+-90): body x (right) stays horizontal, at bearing yaw from east.
        e.roll = 0;
        e.yaw = std::atan2(2 * (q1 * q2 + q0 * q3), q0 * q0 + q1 * q1 - q2 * q2 - q3 * q3) * kRadToDeg;
    } else {
        e.roll = -std::atan2(2 * (q1 * q3 - q0 * q2), q0 * q0 - q1 * q1 - q2 * q2 + q3 * q3) * kRadToDeg;
        e.yaw = -std::atan2(2 * (q1 * q2 - q0 * q3), q0 * q0 - q1 * q1 + q2 * q2 - q3 * q3) * kRadToDeg;
    }
    e.roll = noNegativeZero(e.roll);
    e.pitch = noNegativeZero(e.pitch);
    e.yaw = noNegativeZero(e.yaw);
    return e;
}

Quat quatFromEnu312(const Euler &e)
{
    const double hp = 0.5 * e.pitch * kDegToRad, hr = 0.5 * e.roll * kDegToRad, hy = 0.5 * e.yaw * kDegToRad;
    const double cp = std::cos(hp), sp = std::sin(hp);
    const double cr = std::cos(hr), sr = std::sin(hr);
    const double cy = std::cos(hy), sy = std::sin(hy);
    // Appendix 1 (10.36), q = qz(yaw) * qx(pitch) * qy(roll).
    return canonical(Quat{cp * cr * cy - sp * sr * sy, cr * cy * sp - cp * sr * sy, cp * cy * sr + cr * sp * sy,
                          cp * cr * sy + sp * sr * cy});
}

Euler eulerNed321(const Quat &qIn)
{
    const Quat q = normalized(qIn);
    const double q0 = q.w, q1 = q.x, q2 = q.y, q3 = q.z;
    Euler e;
    const double sinPitch = 2 * (q0 * q2 - q1 * q3);
    e.pitch = asinClamped(sinPitch) * kRadToDeg;
    if (std::abs(sinPitch) > kGimbalLockSin) {
        // C = Rz(yaw) * Ry(+-90): body y (right) stays horizontal, at yaw + 90 from north.
        e.roll = 0;
        e.yaw = std::atan2(-2 * (q1 * q2 - q0 * q3), q0 * q0 - q1 * q1 + q2 * q2 - q3 * q3) * kRadToDeg;
    } else {
        e.roll = std::atan2(2 * (q0 * q1 + q2 * q3), 1 - 2 * (q1 * q1 + q2 * q2)) * kRadToDeg;
        e.yaw = std::atan2(2 * (q0 * q3 + q1 * q2), 1 - 2 * (q2 * q2 + q3 * q3)) * kRadToDeg;
    }
    e.roll = noNegativeZero(e.roll);
    e.pitch = noNegativeZero(e.pitch);
    e.yaw = noNegativeZero(e.yaw);
    return e;
}

Quat quatFromNed321(const Euler &e)
{
    const double hr = 0.5 * e.roll * kDegToRad, hp = 0.5 * e.pitch * kDegToRad, hy = 0.5 * e.yaw * kDegToRad;
    const double cr = std::cos(hr), sr = std::sin(hr);
    const double cp = std::cos(hp), sp = std::sin(hp);
    const double cy = std::cos(hy), sy = std::sin(hy);
    // Appendix 1 (10.37), q = qz(yaw) * qy(pitch) * qx(roll).
    return canonical(Quat{cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
                          cr * cp * sy - sr * sp * cy});
}

Quat enuToNed(const Quat &qEnu)
{
    const Eigen::Quaterniond m = frameSwap();
    return canonical(fromEigen(m * toEigen(normalized(qEnu)) * m.conjugate()));
}

// The navigation frame turned about up by `rad` (counter-clockwise seen from above).
static Quat navigationTurned(const Quat &q, double rad)
{
    const Eigen::Quaterniond r(Eigen::AngleAxisd(rad, Eigen::Vector3d::UnitZ()));
    return canonical(fromEigen(r * toEigen(normalized(q))));
}

Quat nwuToEnu(const Quat &qNwu)
{
    return navigationTurned(qNwu, std::numbers::pi / 2); // R_enu<-nwu: NWU x, north, is ENU y
}

Quat enuToNwu(const Quat &qEnu)
{
    return navigationTurned(qEnu, -std::numbers::pi / 2);
}

Quat nedToEnu(const Quat &qNed)
{
    // The swap is an involution, so the inverse is the same conjugation.
    const Eigen::Quaterniond m = frameSwap();
    return canonical(fromEigen(m * toEigen(normalized(qNed)) * m.conjugate()));
}

double headingDeg(const Quat &qEnu)
{
    // -yaw_enu is atan2(C[0][1], C[1][1]): the bearing atan2(east, north) of the forward
    // axis (body y). Going through eulerEnu312() keeps the gimbal-lock rule in one place.
    return wrap360(-eulerEnu312(qEnu).yaw);
}

void setCompassHeading(Sample &s, double headingCwDeg, bool trueNorth)
{
    s.headingDeg = wrap360(headingCwDeg);
    s.headingTrue = trueNorth;
    s.yaw = wrap180(-headingCwDeg);
    s.fields |= FieldHeading;
}

double wrap180(double deg)
{
    if (!std::isfinite(deg))
        return deg;
    double r = std::fmod(deg + 180.0, 360.0);
    if (r < 0)
        r += 360.0;
    if (r >= 360.0)
        r -= 360.0;
    return noNegativeZero(r - 180.0);
}

double wrap360(double deg)
{
    if (!std::isfinite(deg))
        return deg;
    double r = std::fmod(deg, 360.0);
    if (r < 0)
        r += 360.0;
    if (r >= 360.0)
        r -= 360.0;
    return noNegativeZero(r);
}

} // namespace imudesk::model
