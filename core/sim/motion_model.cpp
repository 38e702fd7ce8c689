#include "motion_model.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
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
    case Motion::Poses: return "poses";
    case Motion::Bearings: return "bearings";
    }
    return "?";
}

bool parseMotion(std::string_view text, Motion &out)
{
    std::string t;
    for (char c : text)
        t.push_back(char(std::tolower(uint8_t(c))));
    for (Motion m : {Motion::Static, Motion::Spin, Motion::Tumble, Motion::Turntable, Motion::Twists, Motion::Poses, Motion::Bearings})
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
    if (options.motion != Motion::Poses)
        return;
    // The body axis that points up in each pose: the six faces, then six between them.
    static const double kUp[kPoseCount][3] = {{0, 0, 1},  {1, 0, 0},  {0, 1, 0},   {0, 0, -1},  {-1, 0, 0}, {0, -1, 0},
                                              {1, 1, 0},  {-1, 0, 1}, {0, 1, -1},  {1, -1, 1},  {-1, -1, -1}, {1, 0, -1}};
    uint64_t salt = 100;
    auto u = [&](double lo, double hi) { return lo + (hi - lo) * unitFromSeed(options.seed, salt++); };
    auto poseAt = [&](int i) {
        const Eigen::Vector3d up = Eigen::Vector3d(kUp[i][0], kUp[i][1], kUp[i][2]).normalized();
        // Body to nav: the axis `up` onto the vertical, then the hand's tilt and heading.
        const Eigen::Quaterniond base = Eigen::Quaterniond::FromTwoVectors(up, Eigen::Vector3d::UnitZ());
        const Eigen::Quaterniond tilt = axisAngle(u(-10, 10), Eigen::Vector3d::UnitX()) * axisAngle(u(-10, 10), Eigen::Vector3d::UnitY());
        return canonical(axisAngle(u(0, 360), Eigen::Vector3d::UnitZ()) * tilt * base);
    };
    double t = 0;
    Eigen::Quaterniond previous = poseAt(0);
    m_poses.push_back(PoseMove{0, 0, u(kPoseHoldMinS, kPoseHoldMaxS), previous, previous});
    t = m_poses.back().holdS;
    for (int i = 1; i < kPoseCount; ++i) {
        for (int pass = 0; pass < (i == kBriefPoseAfter ? 2 : 1); ++pass) {
            const bool brief = pass == 1;
            PoseMove m;
            m.brief = brief;
            m.startS = t;
            m.moveS = u(kPoseMoveMinS, kPoseMoveMaxS);
            m.holdS = brief ? kBriefPoseHoldS : u(kPoseHoldMinS, kPoseHoldMaxS);
            m.from = previous;
            // The brief pose: part of the way to a pose of its own (the hand pauses, then goes on).
            m.to = brief ? canonical(previous * axisAngle(u(30, 60), Eigen::Vector3d(u(-1, 1), u(-1, 1), 1).normalized()))
                         : poseAt(i);
            const Eigen::AngleAxisd d(m.from.conjugate() * m.to);
            m.angleDeg = d.angle() * (180.0 / 3.141592653589793);
            m.axis = d.angle() > 1e-9 ? d.axis() : Eigen::Vector3d::UnitX();
            m.wobbleAxis = m.axis.unitOrthogonal();
            m.wobbleDeg = u(-25, 25);
            m.wobbleCycles = u(0, 1) < 0.5 ? 1 : 2;
            m.jerk = u(0.05, 0.25);
            m_poses.push_back(m);
            previous = m.to;
            t += m.moveS + m.holdS;
        }
    }
    m_poses.back().holdS = std::numeric_limits<double>::infinity();
}

std::vector<MotionModel::PoseHold> MotionModel::poseHolds() const
{
    std::vector<PoseHold> out;
    for (const PoseMove &m : m_poses)
        out.push_back(PoseHold{m.startS + m.moveS, m.startS + m.moveS + m.holdS, m.to, m.brief});
    return out;
}

double MotionModel::posesEndS() const
{
    return m_poses.empty() ? 0.0 : m_poses.back().startS + m_poses.back().moveS;
}

namespace {
// sin^2(pi u) sin(2 pi n u): zero with its slope at u = 0 and u = 1; and its derivative.
double bump(double x, int n)
{
    const double pi = 3.141592653589793;
    const double s = std::sin(pi * x);
    return s * s * std::sin(2 * pi * n * x);
}
double bumpRate(double x, int n)
{
    const double pi = 3.141592653589793;
    const double s = std::sin(pi * x);
    return pi * std::sin(2 * pi * x) * std::sin(2 * pi * n * x) + 2 * pi * n * s * s * std::cos(2 * pi * n * x);
}
} // namespace

MotionState MotionModel::poseState(double t) const
{
    MotionState s;
    auto it = std::upper_bound(m_poses.begin(), m_poses.end(), t,
                               [](double v, const PoseMove &m) { return v < m.startS; });
    const PoseMove &m = it == m_poses.begin() ? m_poses.front() : *(it - 1);
    const double x = m.moveS > 0 ? (t - m.startS) / m.moveS : 1.0;
    if (x >= 1.0 || x <= 0.0) {
        s.q = x <= 0.0 ? m.from : m.to;
        s.rateDps.setZero();
        s.moving = false;
        return s;
    }
    // q = from * turn(f(x) angle about axis) * wobble(g(x) about wobbleAxis); the rate in the
    // body: R_wobble^T * f' angle axis + g' wobbleAxis (per second: / moveS).
    const double pi = 3.141592653589793;
    const double f = x - std::sin(2 * pi * x) / (2 * pi) + m.jerk * bump(x, 2);
    const double fRate = 1 - std::cos(2 * pi * x) + m.jerk * bumpRate(x, 2);
    const double g = m.wobbleDeg * bump(x, m.wobbleCycles);
    const double gRate = m.wobbleDeg * bumpRate(x, m.wobbleCycles);
    const Eigen::Quaterniond wobble = axisAngle(g, m.wobbleAxis);
    s.q = canonical(m.from * axisAngle(f * m.angleDeg, m.axis) * wobble);
    s.rateDps = (wobble.conjugate() * (m.axis * (fRate * m.angleDeg)) + m.wobbleAxis * gRate) / m.moveS;
    s.moving = true;
    return s;
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
    case Motion::Poses:
        s = poseState(t);
        break;
    case Motion::Bearings: {
        // Heading (clockwise) 45° further at each turn; the yaw is its negative.
        const double step = 360.0 / kBearingCount, cycle = kBearingHoldS + kBearingTurnS;
        const int k = std::min(int(t / cycle), kBearingCount);
        const double u = k < kBearingCount ? (t - k * cycle - kBearingHoldS) / kBearingTurnS : -1.0;
        double heading = k * step, rate = 0;
        if (u > 0) {
            const double pi2 = 2 * 3.141592653589793;
            heading += step * (u - std::sin(pi2 * u) / pi2);
            rate = step / kBearingTurnS * (1 - std::cos(pi2 * u));
        }
        s.q = canonical(axisAngle(-heading, Eigen::Vector3d::UnitZ()));
        s.rateDps = Eigen::Vector3d(0, 0, -rate);
        s.moving = rate != 0;
        break;
    }
    }
    return s;
}

} // namespace imudesk::sim
