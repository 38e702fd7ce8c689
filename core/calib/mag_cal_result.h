#pragma once
// The outcome of one magnetometer calibration fit, with the metrics and the verdict the
// wizard and the CLI show (calibration-notes.md §3 "Wizard metrics to display").
#include <Eigen/Core>

#include <QCoreApplication>
#include <QJsonObject>
#include <QString>

#include <limits>

namespace imudesk::calib {

enum class MagCalMode { Full3D, HardIronOnly, Planar2D };
enum class MagVerdict { Pass, Warn, Fail, Refused };

const char *modeName(MagCalMode m);       // "full", "hard_iron_only", "planar"
const char *verdictName(MagVerdict v);    // "pass", "warn", "fail", "refused"
bool parseMode(const QString &text, MagCalMode &out);
bool parseVerdict(const QString &text, MagVerdict &out);

struct MagCalResult {
    Q_DECLARE_TR_FUNCTIONS(MagCalResult)

public:
    MagCalMode mode = MagCalMode::Full3D;
    MagVerdict verdict = MagVerdict::Refused;
    QString reason;                        // translated; why (the first problem first)
    bool hardIronOnlyOffered = false;      // refused: the hard-iron-only fit would be allowed
    bool planarOffered = false;            // refused: the data is planar, the 2-D fit fits it

    Eigen::Vector3d hardIron = Eigen::Vector3d::Zero();      // uT
    Eigen::Matrix3d softIron = Eigen::Matrix3d::Identity();  // symmetric, det 1: c = S (m - b)
    double fieldUt = 0;          // fitted |B| (2-D: horizontal field)
    double fitErrorPct = 0;      // 100 * RMS(|c| - R) / R over the inliers
    double residualRmsUt = 0;    // RMS(|c| - R) over the inliers, uT
    double coveragePct = 0;      // geodesic cells covered (2-D: 10-degree heading sectors)
    double eigenRatio = 0;       // lambda_max / lambda_min of the raw-sample covariance
    int samples = 0;             // samples given
    int outliers = 0;            // samples the robust fit set aside
    bool zOffsetKnown = true;    // 2-D: false when no vertical reference was given
    // The accuracy the data can give (MagFitUncertainty), NaN when unknown: not fitted, or a
    // result written before these were computed. JSON null.
    double hardIronSigmaUt = std::numeric_limits<double>::quiet_NaN();     // RMS of |b^ - b|, uT
    double softIronSigmaPct = std::numeric_limits<double>::quiet_NaN();    // RMS soft-iron shape error, %
    // The heading error of a level module the fit stays within in 68 % of cases, and in 95 %.
    double predictedHeadingErrorDeg = std::numeric_limits<double>::quiet_NaN();   // level module, deg (68 %)
    double predictedHeadingError95Deg = std::numeric_limits<double>::quiet_NaN(); // level module, deg (95 %)

    bool usable() const { return verdict == MagVerdict::Pass || verdict == MagVerdict::Warn; }
    Eigen::Vector3d correct(const Eigen::Vector3d &m) const { return softIron * (m - hardIron); }
    static QString verdictText(MagVerdict v);   // translated word
    QJsonObject toJson() const;                  // the CLI's --json keys, plus the extra metrics
    static bool fromJson(const QJsonObject &o, MagCalResult &out);
};

} // namespace imudesk::calib
