#pragma once
// Is the module right? (issue 55) Its accelerometer, gyro and attitude judged from a recording
// of the module turned by hand through still poses, with no equipment but a table.
//
//  1. Still intervals (still_poses.cpp): windows whose gyro and accelerometer spread and mean
//     rate stay below the stillness limits, at least minHoldS long; their means, and the
//     uncertainty of each mean from batch means (correlated noise and tremor included).
//  2. The accelerometer (acc_fit.cpp): gravity has one magnitude in every pose, the bench's
//     (local_gravity.h) in the module's G. From at least minPoses distinct poses a Gauss-Newton
//     fit of  a_true = C (a_measured - b), C lower triangular (9 parameters: the frame's
//     rotation is not observable from gravity alone), gives the bias b and, from A = C^-1 (the
//     measured per true), each axis's scale (|row| - 1) and the misalignment of each pair of
//     sensitive axes (90° less the angle between their rows). Uncertainties: the fit's
//     covariance with the poses' own noise, inflated when the residuals show more than noise.
//  3. The gyro (gyro_fit.cpp): its bias from the still intervals; its scale per axis from the
//     turns between consecutive poses, the rate integrated with candidate scales until the
//     rotation carries the first pose's gravity (calibrated) onto the next one's.
//  4. The attitude at each pose (pose_attitude.cpp): roll and pitch against the calibrated
//     gravity direction, heading (clockwise from north, plus the declination) against the
//     tilt-compensated magnetometer, ImuDesk removing a hard iron it can fit from the poses; a
//     pose whose field magnitude or inclination disagrees with the others is set aside and
//     said so, and so is a pose near pitch ±90° (roll and heading have no meaning there).
//  5. A verdict (module_check.cpp) per figure and in all: pass when the figure's 95 % bound
//     lies inside the pass limit, fail when it lies beyond the fail limit, warn between; a
//     figure the data cannot back is not judged, with what to do.
// Plain C++ and Eigen with QtCore's strings (translated reasons); no GUI.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <array>
#include <vector>

namespace imudesk::verify {

// One sample of the module: its own time, raw sensors and the attitude it reports.
struct MotionSample {
    double tS = 0;
    Eigen::Vector3d acc = Eigen::Vector3d::Zero(); // G (the module's 9.8 m/s²)
    Eigen::Vector3d gyr = Eigen::Vector3d::Zero(); // deg/s
    Eigen::Vector3d mag = Eigen::Vector3d::Zero(); // uT
    Eigen::Quaterniond q = Eigen::Quaterniond::Identity(); // body to ENU, as reported
    bool hasMag = false;
    bool hasAttitude = false;
};

enum class Verdict { Pass, Warn, Fail, CannotJudge };
const char *verdictName(Verdict v); // "pass", "warn", "fail", "cannot judge"
QString verdictText(Verdict v);     // the same, translated

// One figure: its value and 1-sigma, or why it cannot be judged.
struct Figure {
    bool judged = false;
    double value = 0;
    double sigma = 0;
    QString why; // when not judged: what is missing and what to do
    double bound95() const { return 1.959964 * sigma; }
};
struct Figure3 {
    bool judged = false;
    Eigen::Vector3d value = Eigen::Vector3d::Zero();
    Eigen::Vector3d sigma = Eigen::Vector3d::Zero();
    QString why;
};

struct Limit {
    double pass = 0; // |figure| with its 95 % bound at most this: pass
    double fail = 0; // |figure| less its 95 % bound above this: fail
};
struct Limits {
    Limit accBiasMg{10, 25};
    Limit accScalePct{0.5, 0.8};
    Limit accMisalignmentDeg{0.5, 1.0};
    Limit gyroBiasDps{0.5, 1.0};
    Limit gyroScalePct{0.5, 1.0};
    Limit gyroMisalignmentDeg{0.5, 1.0};
    Limit tiltDeg{0.3, 1.0};
    Limit headingDeg{1.0, 2.5};
    Limit dynamicRmsDeg{1.0, 3.0};  // the attitude while moving against the reference filter
    Limit lagMs{20, 100};
    // By name ("acc_bias_mg", ...) for a user's --limit NAME=PASS/FAIL; nullptr for another.
    Limit *byName(const QString &name);
    static QStringList names();
};

struct CheckOptions {
    double gravityMs2 = 0;      // the bench's gravity; 0: not known (standard gravity assumed)
    double declinationDeg = 0;  // added to the magnetic heading (east positive)
    double minHoldS = 1.5;      // a still interval at least this long is a pose
    double stillWindowS = 0.5;  // the stillness window
    double maxGyroStdDps = 0.3; // stillness limits, as calib::StillnessDetector's
    double maxAccStdG = 0.005;
    double maxGyroMeanDps = 2.0;
    double samePoseDeg = 10;    // still intervals whose gravity directions are this close: one pose
    int minPoses = 9;           // distinct poses the accelerometer fit needs
    double maxPitchDeg = 70;    // poses steeper than this: no roll or heading
    double magMagnitudeTolerancePct = 3; // a pose's |B| this far from the others' median: set aside
    double magInclinationToleranceDeg = 2;
    Limits limits;
};

// A still interval, with what the module said and what ImuDesk derives there.
struct Pose {
    double fromS = 0, toS = 0;
    int samples = 0;
    Eigen::Vector3d acc = Eigen::Vector3d::Zero(), accSigma = Eigen::Vector3d::Zero(); // G, sigma of the mean
    Eigen::Vector3d gyr = Eigen::Vector3d::Zero(), gyrSigma = Eigen::Vector3d::Zero(); // deg/s
    Eigen::Vector3d mag = Eigen::Vector3d::Zero();                                    // uT
    Eigen::Quaterniond reported = Eigen::Quaterniond::Identity();
    bool hasMag = false, hasAttitude = false;
    int distinct = -1;          // which distinct pose (gravity direction) it is
    // From the checks (NaN where not made):
    double rollErrDeg = 0, pitchErrDeg = 0, headingErrDeg = 0;
    bool tiltUsed = false, headingUsed = false;
    QString setAside;           // why its heading was not used
};

struct CheckReport {
    Q_DECLARE_TR_FUNCTIONS(CheckReport)

public:
    std::vector<Pose> poses;     // still intervals, in time order
    int distinctPoses = 0;
    double durationS = 0;
    size_t samples = 0;
    double gravityG = 1;         // the magnitude fitted to, in the module's G
    bool gravityGiven = false;

    Figure3 accBiasMg, accScalePct;
    Figure accMisalignmentDeg;            // the largest of the three
    Eigen::Vector3d accMisalignmentAxesDeg = Eigen::Vector3d::Zero(); // x-y, x-z, y-z
    Eigen::Vector3d accMisalignmentAxesSigmaDeg = Eigen::Vector3d::Zero();
    Eigen::Matrix3d accCorrection = Eigen::Matrix3d::Identity(); // C: a_true = C (a - b)
    Eigen::Vector3d accBiasG = Eigen::Vector3d::Zero();
    double accResidualMg = 0;             // RMS of |C (a - b)| - g over the poses
    Figure3 gyroBiasDps, gyroScalePct;
    Figure gyroMisalignmentDeg;           // the largest of the three
    Eigen::Vector3d gyroMisalignmentAxesDeg = Eigen::Vector3d::Zero(); // x-y, x-z, y-z
    Eigen::Vector3d gyroMisalignmentAxesSigmaDeg = Eigen::Vector3d::Zero();
    int gyroTurns = 0;                    // turns between poses the gyro scale used
    Figure rollErrDeg, pitchErrDeg, headingErrDeg; // reported minus true
    Eigen::Vector3d hardIronUt = Eigen::Vector3d::Zero(); // what ImuDesk removed (zero: none)
    bool hardIronRemoved = false;
    Figure dynamicRmsDeg, dynamicMaxDeg, dynamicLagMs;

    Verdict verdict = Verdict::CannotJudge;
    QStringList reasons;                  // every figure's judgement in words, worst first
    // Each figure's own verdict by its limit's name ("acc_bias_mg", ... Limits::names()).
    std::vector<std::pair<QString, Verdict>> figureVerdicts;
    Verdict figureVerdict(const QString &limitName) const;
};

// The whole check on a recording (samples in time order).
CheckReport checkModule(const std::vector<MotionSample> &samples, const CheckOptions &options = {});

// The steps, for the tests and the wizard's live tally.
std::vector<Pose> findStillPoses(const std::vector<MotionSample> &samples, const CheckOptions &options);
// Numbers the distinct gravity directions among poses (Pose::distinct); returns their count.
int groupPoses(std::vector<Pose> &poses, double samePoseDeg);

} // namespace imudesk::verify
