#pragma once
// True motion of a simulated IMU: attitude (body -> navigation, ENU) and body rate as
// functions of time. Deterministic: the same options give the same trajectory.
//
// Frames: the navigation frame is ENU (x east, y north, z up). The body frame is the
// sensor frame of the module (x right, y forward, z up when the module lies flat in
// its default mounting). q rotates body vectors into the navigation frame:
// v_nav = R(q) * v_body.
//
// Euler angles follow the manuals' appendix 1, ENU 3-1-2 (Z first, then X, then Y):
//   R = Rz(yaw) * Rx(pitch) * Ry(roll)
//   pitch = asin(2(q0q1 + q2q3))
//   roll  = -atan2(2(q1q3 - q0q2), q0^2 - q1^2 - q2^2 + q3^2)
//   yaw   = -atan2(2(q1q2 - q0q3), q0^2 - q1^2 + q2^2 - q3^2)
// yaw is counter-clockwise positive, -180..180; pitch -90..90; roll -180..180.
#include "model/attitude.h"

#include <Eigen/Geometry>

#include <cstdint>
#include <string_view>
#include <vector>

namespace imudesk::sim {

enum class Motion {
    Static, // a fixed, slightly tilted attitude
    Spin,   // level, 30 deg/s about body Z (yaw), as on a turntable
    Tumble, // slow rotation whose axis precesses: every attitude within about a minute
    // Level turntable for the gyro scale-factor run: still for kTurntableStillS, two turns
    // (720 deg) clockwise, still, two turns counter-clockwise, still from then on. Each
    // leg ramps to kTurntableRateDps in 1 s, turns evenly and ramps down in 1 s.
    Turntable,
    // A fixture at rest that is turned sharply now and then (issue 36, twist to align): at the
    // static attitude, with kTwistsPerCycle yaw twists in every kTwistCycleS at irregular times,
    // each a raised-cosine rate pulse of kTwistPeakDps and kTwistWidthS. The same for every
    // seed: modules on one fixture feel one motion.
    Twists,
    // A module turned by hand through still poses (issue 55, verify): kPoseCount orientations
    // (each face up and down, six between them), each at a heading and a tilt of the hand's
    // choosing (from the seed), held still kPoseHoldMinS..kPoseHoldMaxS, the moves between them
    // jerky (an uneven rate and a wobble about a second axis) and kPoseMoveMinS..kPoseMoveMaxS
    // long; after the kBriefPoseAfter-th pose one more is held only kBriefPoseHoldS, too briefly
    // to count. The last pose is held from then on. MotionModel::poseHolds() gives the truth.
    Poses,
    // A compass turned on a level compass rose to its 8 marked bearings (0, 45, ... 315°
    // clockwise from north), held still kBearingHoldS at each, each turn kBearingTurnS (a raised
    // cosine), then back to 0° and held there (issue 55: a compass's heading against known bearings).
    Bearings,
};
const char *motionName(Motion m);
// "static", "spin", "tumble" (case-insensitive).
bool parseMotion(std::string_view text, Motion &out);

using EulerAngles = model::Euler; // deg

// Eigen forms of the attitude maths in core/model/attitude.h (appendix 1, ENU 3-1-2).
EulerAngles eulerEnu312(const Eigen::Quaterniond &q);
// The inverse: q = qz(yaw) * qx(pitch) * qy(roll), returned with w >= 0.
Eigen::Quaterniond quatFromEnu312(const EulerAngles &e);
// Sign convention used on the wire: w >= 0, normalised.
Eigen::Quaterniond canonical(const Eigen::Quaterniond &q);

struct MotionState {
    Eigen::Quaterniond q = Eigen::Quaterniond::Identity(); // body -> nav (ENU)
    Eigen::Vector3d rateDps = Eigen::Vector3d::Zero();     // angular rate, body frame, deg/s
    bool moving = false;                                   // false only for Motion::Static
};

class MotionModel {
public:
    struct Options {
        uint64_t seed = 1;              // picks the initial heading of Spin and the phases of Tumble
        Motion motion = Motion::Static;
    };

    static constexpr double kSpinRateDps = 30.0;
    // Tumble: R(t) = Rz(h0 + a t) * Rx(b t) * Ry(c0 + c t); |rate| stays below 56 deg/s and the
    // field direction in the body frame covers 50 of 72 direction cells within about 52 s.
    static constexpr double kTumbleRateZDps = 22.0;
    static constexpr double kTumbleRateXDps = 17.0;
    static constexpr double kTumbleRateYDps = 31.0;
    static constexpr double kTurntableStillS = 3.0;
    static constexpr double kTurntableRateDps = 45.0;
    static constexpr double kTurntableLegDeg = 720.0;
    static constexpr double kTurntableRampS = 1.0;
    // Duration of one leg: ramps plus the even part.
    static constexpr double turntableLegS()
    {
        return 2 * kTurntableRampS + (kTurntableLegDeg - kTurntableRateDps * kTurntableRampS) / kTurntableRateDps;
    }
    static constexpr double kTwistCycleS = 20.0;
    static constexpr int kTwistsPerCycle = 5;
    static constexpr double kTwistPeakDps = 300.0;
    static constexpr double kTwistWidthS = 0.25;
    // Static attitude (deg).
    static constexpr double kStaticRollDeg = 1.5;
    static constexpr double kStaticPitchDeg = -2.5;
    static constexpr double kStaticYawDeg = 35.0;
    static constexpr int kBearingCount = 8;
    static constexpr double kBearingHoldS = 3.5, kBearingTurnS = 1.5;
    static constexpr int kPoseCount = 12;
    static constexpr double kPoseHoldMinS = 2.5, kPoseHoldMaxS = 5.0;
    static constexpr double kPoseMoveMinS = 0.8, kPoseMoveMaxS = 2.0;
    static constexpr int kBriefPoseAfter = 5;
    static constexpr double kBriefPoseHoldS = 0.6;

    // Motion::Poses: where the module rests, and when (s).
    struct PoseHold {
        double fromS = 0, toS = 0; // toS infinite for the last
        Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
        bool brief = false;        // the one held too briefly
    };
    std::vector<PoseHold> poseHolds() const;
    // The time the last pose is reached (s); 0 for other motions.
    double posesEndS() const;

    MotionModel();
    explicit MotionModel(Options options);

    const Options &options() const { return m_options; }
    Motion motion() const { return m_options.motion; }

    // True state at t seconds after the start of the simulation.
    MotionState at(double tSeconds) const;

private:
    Options m_options;
    double m_headingDeg = 0; // initial heading of Spin/Tumble
    double m_phaseDeg = 0;   // initial Y angle of Tumble
    struct PoseMove {
        double startS = 0, moveS = 1, holdS = 1; // the move from the previous pose, then the hold
        Eigen::Quaterniond from, to;
        Eigen::Vector3d axis = Eigen::Vector3d::UnitX();   // of the turn, in the body at `from`
        double angleDeg = 0;
        Eigen::Vector3d wobbleAxis = Eigen::Vector3d::UnitY();
        double wobbleDeg = 0, jerk = 0;
        int wobbleCycles = 1;
        bool brief = false;
    };
    std::vector<PoseMove> m_poses; // Motion::Poses: the first starts at 0 with no move
    MotionState poseState(double t) const;
};

} // namespace imudesk::sim
