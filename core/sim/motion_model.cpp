#include "motion_model.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <utility>

namespace imudesk::sim {
namespace {

constexpr double kDeg = 0.017453292519943295;

Eigen::Quaterniond axisAngle(double deg, const Eigen::Vector3d &axis)
{
    return Eigen::Quaterniond(Eigen::AngleAxisd(deg * kDeg, axis));
}

// splitmix64: a seed-to-number mapping that does not depend on the standard library.
uint64_t mix(uint64_t x)
{
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

// Angle (deg) and rate (deg/s) tau seconds into one turntable leg.
std::pair<double, double> turntableLeg(double tau)
{
    const double w = MotionModel::kTurntableRateDps, tr = MotionModel::kTurntableRampS;
    const double total = MotionModel::kTurntableLegDeg, len = MotionModel::turntableLegS();
    if (tau <= 0)
        return {0.0, 0.0};
    if (tau < tr)
        return {w * tau * tau / (2 * tr), w * tau / tr};
    if (tau < len - tr)
        return {w * tr / 2 + w * (tau - tr), w};
    if (tau < len) {
        const double left = len - tau;
        return {total - w * left * left / (2 * tr), w * left / tr};
    }
    return {total, 0.0};
}

// The yaw (deg) and its rate (deg/s) of Motion::Twists t seconds in: each twist turns by
// peak * width / 2, alternately one way and the other (three one way, two back in a cycle).
std::pair<double, double> twists(double t)
{
    static constexpr double kStartS[MotionModel::kTwistsPerCycle] = {2.0, 5.3, 9.1, 11.4, 15.8};
    static constexpr double kSign[MotionModel::kTwistsPerCycle] = {1, -1, 1, -1, 1};
    const double p = MotionModel::kTwistPeakDps, w = MotionModel::kTwistWidthS;
    const double perTwist = p * w / 2;
    const double cycle = std::floor(t / MotionModel::kTwistCycleS);
    const double tau = t - cycle * MotionModel::kTwistCycleS;
    double yaw = cycle * perTwist; // 3 - 2 twists' worth per cycle
    double rate = 0;
    for (int i = 0; i < MotionModel::kTwistsPerCycle; ++i) {
        const double u = tau - kStartS[i];
        if (u <= 0)
            continue;
        const double pi2 = 2 * 3.141592653589793;
        if (u >= w) {
            yaw += kSign[i] * perTwist;
            continue;
        }
        yaw += kSign[i] * p / 2 * (u - w / pi2 * std::sin(pi2 * u / w));
        rate = kSign[i] * p / 2 * (1 - std::cos(pi2 * u / w));
    }
    return {yaw, rate};
}

double unitFromSeed(uint64_t seed, uint64_t salt)
{
    return double(mix(seed ^ (salt * 0xD1B54A32D192ED03ull)) >> 11) * (1.0 / 9007199254740992.0);
}

} // namespace

const char *motionName(Motion m)
{
    switch (m) {
    case Motion::Static: return "static";
    case Motion::Spin: return "spin";
    case Motion::Tumble: return "tumble";
    case Motion::Turntable: return "turntable";
    case Motion::Twists: return "twists";
    }
    return "?";
}

bool parseMotion(std::string_view text, Motion &out)
{
    std::string t;
    for (char c : text)
        t.push_back(char(std::tolower(uint8_t(c))));
    for (Motion m : {Motion::Static, Motion::Spin, Motion::Tumble, Motion::Turntable, Motion::Twists})
        if (t == motionName(m)) {
            out = m;
            return true;
        }
    return false;
}

namespace {
model::Quat toModel(const Eigen::Quaterniond &q)
{
    return model::Quat{q.w(), q.x(), q.y(), q.z()};
}
Eigen::Quaterniond toEigen(const model::Quat &q)
{
    return Eigen::Quaterniond(q.w, q.x, q.y, q.z);
}
} // namespace

Eigen::Quaterniond canonical(const Eigen::Quaterniond &q)
{
    return toEigen(model::canonical(toModel(q)));
}

EulerAngles eulerEnu312(const Eigen::Quaterniond &q)
{
    return model::eulerEnu312(toModel(q));
}

Eigen::Quaterniond quatFromEnu312(const EulerAngles &e)
{
    return toEigen(model::quatFromEnu312(e));
}

MotionModel::MotionModel() : MotionModel(Options{}) {}

MotionModel::MotionModel(Options options) : m_options(options)
{
    m_headingDeg = 360.0 * unitFromSeed(options.seed, 1);
    m_phaseDeg = 360.0 * unitFromSeed(options.seed, 2);
}

MotionState MotionModel::at(double t) const
{
    MotionState s;
    switch (m_options.motion) {
    case Motion::Static:
        s.q = quatFromEnu312({kStaticRollDeg, kStaticPitchDeg, kStaticYawDeg});
        s.rateDps.setZero();
        s.moving = false;
        break;
    case Motion::Spin:
        s.q = canonical(axisAngle(m_headingDeg + kSpinRateDps * t, Eigen::Vector3d::UnitZ()));
        s.rateDps = Eigen::Vector3d(0, 0, kSpinRateDps);
        s.moving = true;
        break;
    case Motion::Tumble: {
        const double a = m_headingDeg + kTumbleRateZDps * t;
        const double b = kTumbleRateXDps * t;
        const double c = m_phaseDeg + kTumbleRateYDps * t;
        const Eigen::Quaterniond qa = axisAngle(a, Eigen::Vector3d::UnitZ());
        const Eigen::Quaterniond qb = axisAngle(b, Eigen::Vector3d::UnitX());
        const Eigen::Quaterniond qc = axisAngle(c, Eigen::Vector3d::UnitY());
        s.q = canonical(qa * qb * qc);
        // R = Ra Rb Rc: w_body = Rc^T Rb^T (0,0,a') + Rc^T (b',0,0) + (0,c',0).
        const Eigen::Matrix3d rbT = qb.toRotationMatrix().transpose();
        const Eigen::Matrix3d rcT = qc.toRotationMatrix().transpose();
        s.rateDps = rcT * rbT * Eigen::Vector3d(0, 0, kTumbleRateZDps) + rcT * Eigen::Vector3d(kTumbleRateXDps, 0, 0)
            + Eigen::Vector3d(0, kTumbleRateYDps, 0);
        s.moving = true;
        break;
    }
    case Motion::Turntable: {
        const double still = kTurntableStillS, leg = turntableLegS();
        const auto [cwDeg, cwRate] = turntableLeg(t - still);
        const auto [ccwDeg, ccwRate] = turntableLeg(t - (2 * still + leg));
        s.q = canonical(axisAngle(m_headingDeg - cwDeg + ccwDeg, Eigen::Vector3d::UnitZ()));
        s.rateDps = Eigen::Vector3d(0, 0, ccwRate - cwRate);
        s.moving = s.rateDps.z() != 0;
        break;
    }
    case Motion::Twists: {
        const auto [yaw, rate] = twists(t);
        s.q = canonical(axisAngle(yaw, Eigen::Vector3d::UnitZ())
                        * quatFromEnu312({kStaticRollDeg, kStaticPitchDeg, kStaticYawDeg}));
        s.rateDps = s.q.conjugate() * Eigen::Vector3d(0, 0, rate);
        s.moving = rate != 0;
        break;
    }
    }
    return s;
}

} // namespace imudesk::sim
