#include "calib/mag_calibrator.h"

#include "calib/ellipse_fit.h"
#include "calib/ellipsoid_fit.h"
#include "calib/mag_fit_uncertainty.h"
#include "calib/sphere_coverage.h"

#include <Eigen/Eigenvalues>

#include <QLoggingCategory>
#include <QStringList>

#include <array>
#include <cmath>

Q_LOGGING_CATEGORY(lcCalib, "imudesk.core.calib", QtInfoMsg)

namespace imudesk::calib {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int kHeadingSectors = 36;
} // namespace

MagCalibrator::MagCalibrator() = default;

MagCalibrator::MagCalibrator(Options options)
    : m_options(std::move(options))
{
}

double MagCalibrator::eigenRatio(const std::vector<Eigen::Vector3d> &samples)
{
    // Degenerate data reports 1e12 (finite, so that it survives JSON).
    if (samples.size() < 2)
        return 1e12;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto &s : samples)
        mean += s;
    mean /= double(samples.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const auto &s : samples)
        cov.noalias() += (s - mean) * (s - mean).transpose();
    cov /= double(samples.size());
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov, Eigen::EigenvaluesOnly);
    const double lmin = es.eigenvalues()[0], lmax = es.eigenvalues()[2];
    if (!(lmax > 0))
        return 1e12;
    if (!(lmin > 1e-12 * lmax))
        return 1e12;
    return lmax / lmin;
}

double MagCalibrator::roughCoveragePct(const std::vector<Eigen::Vector3d> &samples)
{
    const auto sphere = EllipsoidFit::sphere(samples);
    if (!sphere)
        return 0;
    SphereCoverage cov;
    for (const auto &s : samples)
        cov.add(s - sphere->first);
    return cov.percent();
}

MagCalResult MagCalibrator::calibrate(const std::vector<Eigen::Vector3d> &samplesUt, MagCalMode mode) const
{
    std::vector<Eigen::Vector3d> s;
    s.reserve(samplesUt.size());
    for (const auto &v : samplesUt)
        if (v.allFinite())
            s.push_back(v);
    MagCalResult r;
    r.mode = mode;
    r.samples = int(samplesUt.size());
    r.eigenRatio = eigenRatio(s);
    switch (mode) {
    case MagCalMode::Full3D: r = fullFit(s, r); break;
    case MagCalMode::HardIronOnly: r = hardIronFit(s, r); break;
    case MagCalMode::Planar2D: r = planarFit(s, r); break;
    }
    qCDebug(lcCalib) << "magnetometer fit" << modeName(r.mode) << verdictName(r.verdict) << r.fieldUt << "uT, fit error"
                     << r.fitErrorPct << "%, coverage" << r.coveragePct << "%";
    return r;
}

MagCalResult MagCalibrator::fullFit(const std::vector<Eigen::Vector3d> &s, MagCalResult r) const
{
    r.verdict = MagVerdict::Refused;
    if (int(s.size()) < kMinSamplesFull) {
        r.reason = tr("Only %1 usable samples; a full calibration needs at least %2. Keep turning the module slowly.")
                       .arg(s.size())
                       .arg(kMinSamplesFull);
        r.hardIronOnlyOffered = int(s.size()) >= kMinSamplesHardIron && r.eigenRatio <= m_options.maxEigenRatioHardIron;
        return r;
    }
    if (r.eigenRatio > kPlanarEigenRatio) {
        r.planarOffered = true;
        r.reason = tr("The samples lie in one plane (the module turned about one axis only), so a full 3-D "
                      "calibration cannot be computed. Turn the module about its other axes too, or use the 2-D "
                      "(planar) calibration, which is valid for level operation only.");
        return r;
    }
    // Coverage of the raw directions around the sphere-fit centre: the rotations still missing.
    SphereCoverage raw;
    if (const auto sphere = EllipsoidFit::sphere(s))
        for (const auto &v : s)
            raw.add(v - sphere->first);
    r.coveragePct = raw.percent();
    r.hardIronOnlyOffered = r.eigenRatio <= m_options.maxEigenRatioHardIron;
    if (r.coveragePct < m_options.minCoveragePct) {
        r.reason = tr("Only %1 % of the field directions are covered (at least %2 % are needed before a fit is "
                      "tried). %3.")
                       .arg(r.coveragePct, 0, 'f', 0)
                       .arg(m_options.minCoveragePct, 0, 'f', 0)
                       .arg(raw.missingRotationHint());
        if (r.hardIronOnlyOffered)
            r.reason += QLatin1Char(' ') + tr("A hard-iron-only fit (soft iron kept from before) is possible.");
        return r;
    }
    const auto li = EllipsoidFit::algebraicLi(s);
    if (!li) {
        if (raw.largestGapDeg() > kMissingGapDeg) {
            r.reason = tr("No ellipsoid fits these samples, which cover only part of the sphere. %1, then fit again.")
                           .arg(raw.missingRotationHint());
            if (r.hardIronOnlyOffered)
                r.reason += QLatin1Char(' ') + tr("A hard-iron-only fit (soft iron kept from before) is possible.");
            return r;
        }
        r.hardIronOnlyOffered = false;
        r.verdict = MagVerdict::Fail;
        r.reason = tr("The samples do not describe an ellipsoid (strong interference or a moving magnet nearby). "
                      "Move away from iron and electronics and calibrate again.");
        return r;
    }
    RobustStats st;
    const Ellipsoid e = EllipsoidFit::refine(s, *li, &st);
    r.hardIron = e.center;
    r.softIron = e.softIron();
    r.fieldUt = e.radius();
    SphereCoverage cov;
    for (const auto &v : s)
        cov.add(e.correct(v));
    r.coveragePct = cov.percent();
    const auto u = MagFitUncertainty::resampledEllipsoid(s, e, m_options.inclinationDeg, m_options.replicates);
    r.hardIronSigmaUt = u.hardIronSigmaUt;
    r.softIronSigmaPct = u.softIronSigmaPct;
    r.predictedHeadingErrorDeg = u.headingErrorDeg;
    r.predictedHeadingError95Deg = u.headingError95Deg;
    judge(r, EllipsoidFit::residuals(s, e), true, &raw);
    return r;
}

MagCalResult MagCalibrator::hardIronFit(const std::vector<Eigen::Vector3d> &s, MagCalResult r) const
{
    r.verdict = MagVerdict::Refused;
    if (int(s.size()) < kMinSamplesHardIron) {
        r.reason = tr("Only %1 usable samples; the hard-iron fit needs at least %2.").arg(s.size()).arg(kMinSamplesHardIron);
        return r;
    }
    if (r.eigenRatio > m_options.maxEigenRatioHardIron) {
        r.planarOffered = r.eigenRatio > kPlanarEigenRatio;
        r.reason = tr("The samples are too close to a plane (eigenvalue ratio %1, at most %2) even for a hard-iron fit. "
                      "Tilt the module more while turning it.")
                       .arg(r.eigenRatio, 0, 'f', 1)
                       .arg(m_options.maxEigenRatioHardIron, 0, 'f', 0);
        return r;
    }
    RobustStats st;
    const auto e = EllipsoidFit::hardIronOnly(s, m_options.previousSoftIron, m_options.referenceFieldUt, &st);
    if (!e) {
        r.verdict = MagVerdict::Fail;
        r.reason = tr("The hard-iron fit found no solution: check that the samples come from the magnetometer in µT.");
        return r;
    }
    r.hardIron = e->center;
    r.softIron = e->softIron();
    r.fieldUt = e->radius();
    SphereCoverage cov;
    for (const auto &v : s)
        cov.add(e->correct(v));
    r.coveragePct = cov.percent();
    const auto u = MagFitUncertainty::ofHardIronFit(s, *e, !(m_options.referenceFieldUt > 0), m_options.inclinationDeg);
    r.hardIronSigmaUt = u.hardIronSigmaUt;
    r.predictedHeadingErrorDeg = u.headingErrorDeg; // the soft iron is held: its sigma stays unknown
    r.predictedHeadingError95Deg = u.headingError95Deg;
    judge(r, EllipsoidFit::residuals(s, *e), false);
    return r;
}

MagCalResult MagCalibrator::planarFit(const std::vector<Eigen::Vector3d> &s, MagCalResult r) const
{
    r.verdict = MagVerdict::Refused;
    if (int(s.size()) < kMinSamplesPlanar) {
        r.reason = tr("Only %1 usable samples; the 2-D fit needs at least %2. Turn the module a full circle.")
                       .arg(s.size())
                       .arg(kMinSamplesPlanar);
        return r;
    }
    std::vector<Eigen::Vector2d> xy;
    xy.reserve(s.size());
    double meanZ = 0;
    for (const auto &v : s) {
        xy.emplace_back(v.x(), v.y());
        meanZ += v.z();
    }
    meanZ /= double(s.size());
    const auto e = EllipseFit::fit(xy);
    if (!e) {
        r.verdict = MagVerdict::Fail;
        r.reason = tr("The horizontal samples do not describe an ellipse: turn the module one full, even circle.");
        return r;
    }
    r.zOffsetKnown = std::isfinite(m_options.levelVerticalUt);
    r.hardIron = Eigen::Vector3d(e->center.x(), e->center.y(), r.zOffsetKnown ? meanZ - m_options.levelVerticalUt : 0.0);
    r.softIron = Eigen::Matrix3d::Identity();
    r.softIron.topLeftCorner<2, 2>() = e->softIron();
    r.fieldUt = e->radius();
    std::array<bool, kHeadingSectors> sectors{};
    std::vector<double> res;
    res.reserve(xy.size());
    for (const auto &p : xy) {
        const Eigen::Vector2d c = e->correct(p);
        res.push_back(c.norm() - r.fieldUt);
        double a = std::atan2(c.y(), c.x()) + kPi;
        int k = int(a / (2 * kPi) * kHeadingSectors);
        sectors[size_t(std::clamp(k, 0, kHeadingSectors - 1))] = true;
    }
    r.coveragePct = 100.0 * double(std::count(sectors.begin(), sectors.end(), true)) / kHeadingSectors;
    const auto u = MagFitUncertainty::ofEllipse(xy, *e);
    r.hardIronSigmaUt = u.hardIronSigmaUt;
    r.softIronSigmaPct = u.softIronSigmaPct;
    r.predictedHeadingErrorDeg = u.headingErrorDeg;
    r.predictedHeadingError95Deg = u.headingError95Deg;
    judge(r, res, true);
    return r;
}

void MagCalibrator::judge(MagCalResult &r, const std::vector<double> &residualsUt, bool checkSoftIron,
                          const SphereCoverage *rawCoverage) const
{
    const double sigma = EllipsoidFit::robustSigma(residualsUt);
    const double limit = std::max(5.0 * sigma, 1e-9 * std::max(r.fieldUt, 1.0));
    double sq = 0;
    int inliers = 0;
    for (double x : residualsUt)
        if (std::fabs(x) <= limit) {
            sq += x * x;
            ++inliers;
        }
    r.outliers = int(residualsUt.size()) - inliers;
    r.residualRmsUt = inliers > 0 ? std::sqrt(sq / inliers) : 0;
    r.fitErrorPct = r.fieldUt > 0 ? 100.0 * r.residualRmsUt / r.fieldUt : 100.0;

    QStringList fails, warns;
    const bool planar = r.mode == MagCalMode::Planar2D;
    if (r.fitErrorPct > kFailFitErrorPct)
        fails << tr("fit error %1 % is above %2 %").arg(r.fitErrorPct, 0, 'f', 2).arg(kFailFitErrorPct, 0, 'f', 1);
    if (checkSoftIron) {
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(0.5 * (r.softIron + r.softIron.transpose()), Eigen::EigenvaluesOnly);
        const double lo = es.eigenvalues()[0], hi = es.eigenvalues()[2];
        if (lo < kSoftIronMin || hi > kSoftIronMax)
            fails << tr("soft-iron scale %1..%2 is outside %3..%4 (a magnet or iron part very close to the module)")
                         .arg(lo, 0, 'f', 2)
                         .arg(hi, 0, 'f', 2)
                         .arg(kSoftIronMin, 0, 'f', 2)
                         .arg(kSoftIronMax, 0, 'f', 2);
    }
    if (!planar && (r.fieldUt < kGrossFieldMinUt || r.fieldUt > kGrossFieldMaxUt))
        fails << tr("field strength %1 µT is not the earth's field (%2..%3 µT)")
                     .arg(r.fieldUt, 0, 'f', 1)
                     .arg(kGrossFieldMinUt, 0, 'f', 0)
                     .arg(kGrossFieldMaxUt, 0, 'f', 0);
    if (r.fitErrorPct > kWarnFitErrorPct && r.fitErrorPct <= kFailFitErrorPct)
        warns << tr("fit error %1 % is above %2 %").arg(r.fitErrorPct, 0, 'f', 2).arg(kWarnFitErrorPct, 0, 'f', 1);
    const bool full = r.mode == MagCalMode::Full3D;
    const double predicted = r.predictedHeadingErrorDeg;
    if (std::isfinite(predicted) && predicted > kWarnHeadingErrorDeg)
        warns << tr("the predicted heading error of a level module, %1 deg, is above %2 deg (hard iron +-%3 µT)")
                     .arg(predicted, 0, 'f', 2)
                     .arg(kWarnHeadingErrorDeg, 0, 'f', 1)
                     .arg(r.hardIronSigmaUt, 0, 'f', 2);
    // The 68 % bound within the limit, but the 95 % bound more than twice it: one fit in twenty
    // of such data would be off by more than that.
    else if (const double p95 = r.predictedHeadingError95Deg; std::isfinite(p95) && p95 > 2 * kWarnHeadingErrorDeg)
        warns << tr("the heading error of a level module stays below %1 deg only 19 times in 20 (over %2 deg)")
                     .arg(p95, 0, 'f', 2)
                     .arg(2 * kWarnHeadingErrorDeg, 0, 'f', 1);
    // A full fit's accuracy says what its coverage is worth; the other fits keep the coverage warning.
    if (!full && r.coveragePct < kWarnCoveragePct)
        warns << tr("only %1 % of the directions are covered").arg(r.coveragePct, 0, 'f', 0);
    if (!planar && r.fieldUt >= kGrossFieldMinUt && r.fieldUt <= kGrossFieldMaxUt
        && (r.fieldUt < kFieldMinUt || r.fieldUt > kFieldMaxUt))
        warns << tr("field strength %1 µT is outside the normal %2..%3 µT: move away from magnetic objects")
                     .arg(r.fieldUt, 0, 'f', 1)
                     .arg(kFieldMinUt, 0, 'f', 0)
                     .arg(kFieldMaxUt, 0, 'f', 0);
    if (!planar && r.hardIron.norm() > 1.5 * r.fieldUt)
        warns << tr("hard iron %1 µT is large (over 1.5 times the field): the sensor may saturate")
                     .arg(r.hardIron.norm(), 0, 'f', 1);
    if (r.outliers * 20 > int(residualsUt.size()))
        warns << tr("%1 of %2 samples were disturbed and set aside").arg(r.outliers).arg(residualsUt.size());
    if (!planar && m_options.referenceFieldUt > 0 && r.mode == MagCalMode::Full3D
        && std::fabs(r.fieldUt / m_options.referenceFieldUt - 1.0) > 0.15)
        warns << tr("field strength %1 µT differs from the expected %2 µT by more than 15 %")
                     .arg(r.fieldUt, 0, 'f', 1)
                     .arg(m_options.referenceFieldUt, 0, 'f', 1);
    if (planar && !r.zOffsetKnown)
        warns << tr("2-D calibration: valid for level operation only; the vertical offset is unknown");
    else if (planar)
        warns << tr("2-D calibration: valid for level operation only");

    const bool tooInaccurate = full && !(predicted <= kRefuseHeadingErrorDeg); // NaN and inf too
    const double gap = rawCoverage ? rawCoverage->largestGapDeg() : 0.0;
    const bool missing = gap > kMissingGapDeg;
    if (!fails.isEmpty() && !(tooInaccurate && missing)) {
        r.hardIronOnlyOffered = false;
        r.verdict = MagVerdict::Fail;
        r.reason = tr("Calibration failed: %1.").arg((fails + warns).join(QStringLiteral("; ")));
    } else if (tooInaccurate) {
        // On part of the sphere a fit can run away and break the parameter checks too: the
        // missing rotations are the cause, so the reason names them and not the symptoms.
        r.verdict = MagVerdict::Refused;
        r.reason = std::isfinite(predicted)
            ? tr("The data cannot give an accurate calibration: the predicted heading error of a level module is %1 "
                 "deg, at most %2 deg is accepted (hard iron +-%3 µT, soft iron +-%4 %).")
                  .arg(predicted, 0, 'f', 1)
                  .arg(kRefuseHeadingErrorDeg, 0, 'f', 1)
                  .arg(r.hardIronSigmaUt, 0, 'f', 2)
                  .arg(r.softIronSigmaPct, 0, 'f', 1)
            : tr("The data cannot give an accurate calibration: the fit's parameters are not determined by these "
                 "samples.");
        if (missing)
            r.reason += QLatin1Char(' ')
                + tr("Part of the sphere is missing (a gap of %1 deg). %2, then fit again.")
                      .arg(gap, 0, 'f', 0)
                      .arg(rawCoverage->missingRotationHint());
        else
            r.reason += QLatin1Char(' ')
                + tr("The directions are covered, but there are too few samples or they scatter too much (%1 µT RMS "
                     "about the fit): collect more, turning slowly and evenly, away from iron and electronics.")
                      .arg(r.residualRmsUt, 0, 'f', 2);
        if (r.hardIronOnlyOffered)
            r.reason += QLatin1Char(' ') + tr("A hard-iron-only fit (soft iron kept from before) is possible.");
    } else if (!warns.isEmpty()) {
        r.hardIronOnlyOffered = false;
        r.verdict = MagVerdict::Warn;
        r.reason = tr("Usable with care: %1.").arg(warns.join(QStringLiteral("; ")));
    } else {
        r.hardIronOnlyOffered = false;
        r.verdict = MagVerdict::Pass;
        r.reason = std::isfinite(predicted)
            ? tr("Good calibration: predicted heading error %1 deg (level module), fit error %2 %, %3 % of the "
                 "directions covered.")
                  .arg(predicted, 0, 'f', 2)
                  .arg(r.fitErrorPct, 0, 'f', 2)
                  .arg(r.coveragePct, 0, 'f', 0)
            : tr("Good calibration: fit error %1 %, %2 % of the directions covered.")
                  .arg(r.fitErrorPct, 0, 'f', 2)
                  .arg(r.coveragePct, 0, 'f', 0);
    }
}

} // namespace imudesk::calib
