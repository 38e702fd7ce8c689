#pragma once
// The module check's steps 2 to 4 (module_check.h), for module_check.cpp and the tests.
#include "module_check.h"

#include <Eigen/Core>

namespace imudesk::verify {

// Step 2: the multi-position accelerometer fit.
struct AccFit {
    bool ok = false;
    Eigen::Matrix3d correction = Eigen::Matrix3d::Identity(); // C: a_true = C (a - b)
    Eigen::Vector3d biasG = Eigen::Vector3d::Zero();
    Eigen::Matrix<double, 9, 9> covariance = Eigen::Matrix<double, 9, 9>::Zero(); // b, C00 C10 C11 C20 C21 C22
    double rmsResidualG = 0;
    double inflation = 1; // the residuals showed more than the poses' noise: covariance scaled by this
};
AccFit fitAccelerometer(const std::vector<Pose> &poses, double gravityG);
// The fit's nine parameters in the covariance's order, and C from them.
using AccParams = Eigen::Matrix<double, 9, 1>;
AccParams accParams(const AccFit &fit);
Eigen::Matrix3d accCorrectionOf(const AccParams &p);
// Bias (mg), scale error (%), misalignment x-y, x-z, y-z (deg) of a fit, and their 1-sigma.
struct AccFigures {
    Eigen::Vector3d biasMg, scalePct, misalignmentDeg;
    Eigen::Vector3d biasSigma, scaleSigma, misalignmentSigma;
};
AccFigures accFigures(const AccFit &fit);
// The same figures of a sensor model A (measured = A true + b), for the tests' truth.
void accFiguresOf(const Eigen::Matrix3d &a, Eigen::Vector3d &scalePct, Eigen::Vector3d &misalignmentDeg);

// Step 3: the gyro's bias and scale.
struct GyroFit {
    Figure3 biasDps, scalePct;
    Figure misalignmentDeg; // the largest of the three
    Eigen::Vector3d misalignmentAxesDeg = Eigen::Vector3d::Zero(); // x-y, x-z, y-z
    Eigen::Vector3d misalignmentAxesSigmaDeg = Eigen::Vector3d::Zero();
    Eigen::Matrix3d correction = Eigen::Matrix3d::Identity(); // true = correction (measured - bias)
    int turns = 0;
};
GyroFit fitGyro(const std::vector<MotionSample> &samples, const std::vector<Pose> &poses, const AccFit &acc);

// Step 4: the attitude at the poses (fills each pose's errors and setAside).
struct AttitudeCheck {
    Figure roll, pitch, heading;
    Eigen::Vector3d hardIronUt = Eigen::Vector3d::Zero();
    bool hardIronRemoved = false;
    // The field the poses agreed on (when the heading was judged): its magnitude and inclination.
    bool fieldKnown = false;
    double fieldUt = 0, inclinationDeg = 0;
};
AttitudeCheck checkAttitude(std::vector<Pose> &poses, const AccFit &acc, const CheckOptions &options);

// Step 5: the attitude while the module moves, against ImuDesk's reference filter
// (reference_filter.h) started at the first still pose on the calibrated sensors.
struct DynamicCheck {
    Figure rmsDeg, maxDeg, lagMs;
};
DynamicCheck checkDynamic(const std::vector<MotionSample> &samples, const std::vector<Pose> &poses, const AccFit &acc,
                          const GyroFit &gyro, const AttitudeCheck &attitude, const CheckOptions &options);

// Student's t quantile (two-sided level `p`, e.g. 0.6827) for nu degrees of freedom, relative
// to the normal's: what a sigma from n samples' spread is scaled by to hold its coverage.
double smallSampleFactor(int nu);

} // namespace imudesk::verify
