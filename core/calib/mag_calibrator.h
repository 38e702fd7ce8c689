#pragma once
// The magnetometer calibration as the wizard and `imudesk-cli magcal` run it
// (calibration-notes.md §0, §2, §3): gates on the raw data first, then the fit, then the
// accuracy the data can give, then the checks on the parameters and the residuals. Never
// trusts the fit error or the coverage percentage alone.
//
//  Full3D:       refused when there are too few samples, the data is planar
//                (eigenvalue ratio > kPlanarEigenRatio) or almost nothing is covered
//                (< minCoveragePct of the geodesic cells). Otherwise Li & Griffiths,
//                refined by Huber-LM, and its accuracy by resampling (MagFitUncertainty):
//                hard iron and soft iron sigma and the predicted heading error of a level
//                module. Refused when that error exceeds kRefuseHeadingErrorDeg, with the
//                missing rotations; the refusal offers the hard-iron-only fit (when the
//                eigenvalue ratio <= maxEigenRatioHardIron) and the 2-D fit (planar data).
//  HardIronOnly: the soft iron of an earlier calibration is kept (identity by default),
//                |B| held at referenceFieldUt when given. Accuracy from the covariance.
//  Planar2D:     ellipse fit on (mx, my); b_z = mean(mz) - levelVerticalUt when given.
//                Accuracy from the covariance.
// Verdict: Fail when the fit error > 5 %, the soft-iron eigenvalues leave 0.67..1.5 or
// |B| leaves 10..100 uT (with full coverage; on part of the sphere such a fit is refused
// for its accuracy); Refused (Full3D) when the predicted heading error > 1 deg; Warn when
// it is > 0.5 deg, the fit error > 3.5 %, coverage < 70 % (hard-iron-only and 2-D fits),
// |B| outside the manual's 20..60 uT, |b| > 1.5 |B|, > 5 % outliers or |B| off the
// reference by > 15 %.
// Deterministic: the same samples give bit-identical results.
#include "calib/mag_cal_result.h"
#include "calib/mag_fit_uncertainty.h"

#include <QCoreApplication>

#include <limits>
#include <vector>

namespace imudesk::calib {

class SphereCoverage;

class MagCalibrator {
    Q_DECLARE_TR_FUNCTIONS(MagCalibrator)

public:
    static constexpr int kMinSamplesFull = 30;
    static constexpr int kMinSamplesHardIron = 10;
    static constexpr int kMinSamplesPlanar = 12;
    static constexpr double kPlanarEigenRatio = 50.0;
    static constexpr double kFailFitErrorPct = 5.0;
    static constexpr double kWarnFitErrorPct = 3.5;
    static constexpr double kWarnCoveragePct = 70.0;
    static constexpr double kFieldMinUt = 20.0, kFieldMaxUt = 60.0;        // manual chapter 9.31
    static constexpr double kGrossFieldMinUt = 10.0, kGrossFieldMaxUt = 100.0;
    static constexpr double kSoftIronMin = 0.67, kSoftIronMax = 1.5;
    static constexpr double kRefuseHeadingErrorDeg = 1.0; // predicted, level module
    static constexpr double kWarnHeadingErrorDeg = 0.5;
    static constexpr double kMissingGapDeg = 45.0; // a hole this wide means rotations are missing

    struct Options {
        // Below this no full fit is tried (25 % cap: 24-43 %, bench_magcal); above it the
        // predicted accuracy decides.
        double minCoveragePct = 20.0;
        double maxEigenRatioHardIron = 15.0;
        double referenceFieldUt = 0;                       // WMM |B|; 0 = unknown
        // WMM inclination, for the predicted heading error (the horizontal field it divides by).
        double inclinationDeg = MagFitUncertainty::kDefaultInclinationDeg;
        int replicates = MagFitUncertainty::kReplicates;   // resampled fits for the full fit's accuracy
        double levelVerticalUt = std::numeric_limits<double>::quiet_NaN(); // body z at level, 2-D mode
        Eigen::Matrix3d previousSoftIron = Eigen::Matrix3d::Identity();
    };

    MagCalibrator();
    explicit MagCalibrator(Options options);
    const Options &options() const { return m_options; }

    MagCalResult calibrate(const std::vector<Eigen::Vector3d> &samplesUt, MagCalMode mode = MagCalMode::Full3D) const;

    // Raw-data metrics, also shown live by the wizard.
    static double eigenRatio(const std::vector<Eigen::Vector3d> &samples);
    // Coverage of the directions around the sphere-fit centre (before any fit), %.
    static double roughCoveragePct(const std::vector<Eigen::Vector3d> &samples);

private:
    MagCalResult fullFit(const std::vector<Eigen::Vector3d> &s, MagCalResult r) const;
    MagCalResult hardIronFit(const std::vector<Eigen::Vector3d> &s, MagCalResult r) const;
    MagCalResult planarFit(const std::vector<Eigen::Vector3d> &s, MagCalResult r) const;
    void judge(MagCalResult &r, const std::vector<double> &residualsUt, bool checkSoftIron,
               const SphereCoverage *rawCoverage = nullptr) const;

    Options m_options;
};

} // namespace imudesk::calib
