#pragma once
// How accurate a magnetometer fit is, estimated from the data it was fitted to:
//   * hardIronSigmaUt: the RMS of the hard-iron error |b^ - b| (uT),
//   * softIronSigmaPct: the RMS of the soft-iron shape error ||S^ S^-1 / cbrt(det) - I||_F (%),
//   * headingErrorDeg: the predicted heading error of a level module in the measured field:
//     the largest heading error while the module turns once (yaw 0..355 in 5-degree steps,
//     tilt compensated with the true attitude), as the kHeadingQuantile quantile over the
//     fit's possible errors: the error the calibration stays within two times in three.
//     The field's inclination is an input (the world magnetic model's; kDefaultInclinationDeg
//     when unknown); |B| cancels.
// Two ways to the fit's possible errors:
//   * resampledEllipsoid (the full 3-D fit): a parametric bootstrap. The inlier samples are
//     moved onto the fitted ellipsoid, given new noise of the residuals' spread and fitted
//     again the same way; the replicates' departures from the fit stand for the fit's
//     departure from the truth. On part of the sphere this sees what the linear term does
//     not: noise pushes the centre away from the covered side (a bias that more samples do
//     not remove), and on a small cap or a narrow band the fit can run away.
//   * the covariance (hard-iron-only, 2-D, and ofEllipsoid as the cheap baseline):
//     cov = s^2 (J^T J)^-1 at the solution over the inliers, s^2 their residual variance;
//     errors drawn from it (kDraws, fixed seed) give the heading quantile.
// What no fit of magnitudes can see (a rotation between the magnetometer and the body, a
// field that changes while the module turns) is not part of the prediction. Deterministic:
// every draw uses a fixed seed.
#include "calib/ellipse_fit.h"
#include "calib/ellipsoid_fit.h"

#include <Eigen/Core>

#include <limits>
#include <vector>

namespace imudesk::calib {

class MagFitUncertainty {
public:
    static constexpr double kDefaultInclinationDeg = 60.0; // mid latitudes (calibration-notes.md §3)
    static constexpr double kHeadingQuantile = 0.68;
    static constexpr double kHeadingQuantile95 = 0.95; // the bound the error stays within 19 times in 20
    static constexpr int kHeadingStepDeg = 5;
    static constexpr int kDraws = 400;
    static constexpr int kReplicates = 32;

    struct Figures {
        double hardIronSigmaUt = std::numeric_limits<double>::quiet_NaN();
        double softIronSigmaPct = std::numeric_limits<double>::quiet_NaN(); // NaN: soft iron not fitted
        double headingErrorDeg = std::numeric_limits<double>::quiet_NaN();   // kHeadingQuantile (68 %)
        double headingError95Deg = std::numeric_limits<double>::quiet_NaN(); // kHeadingQuantile95
        // The parameters could not be determined at all (singular geometry): every figure is +inf.
        bool singular = false;
    };

    // Full 3-D fit (Li, then Huber-LM) by resampling: `replicates` refits (none: the
    // covariance). A replicate without a fit counts as an unbounded heading error.
    static Figures resampledEllipsoid(const std::vector<Eigen::Vector3d> &points, const Ellipsoid &e,
                                      double inclinationDeg = kDefaultInclinationDeg, int replicates = kReplicates);
    // Full 3-D fit, linear covariance only (cheap; optimistic on partial coverage).
    static Figures ofEllipsoid(const std::vector<Eigen::Vector3d> &points, const Ellipsoid &e,
                               double inclinationDeg = kDefaultInclinationDeg);
    // Hard-iron-only fit (soft iron held); the field strength free or held.
    static Figures ofHardIronFit(const std::vector<Eigen::Vector3d> &points, const Ellipsoid &e, bool radiusFree,
                                 double inclinationDeg = kDefaultInclinationDeg);
    // 2-D fit of (mx, my): the heading of a level module from the horizontal components.
    static Figures ofEllipse(const std::vector<Eigen::Vector2d> &points, const Ellipse &e);
};

} // namespace imudesk::calib
