// Step 4 of the module check (module_check.h): the attitude the module reports at each still
// pose against the calibrated accelerometer and the tilt-compensated magnetometer.
#include "check_steps.h"

#include "model/attitude.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace imudesk::verify {

namespace {

constexpr double kRadToDeg = 57.29577951308232;
constexpr double kDegToRad = 0.017453292519943295;

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The mean of per-pose errors and the sigma of that mean (from their spread, scaled for few
// poses), never below `floor`.
Figure meanFigure(const std::vector<double> &errors, double floor)
{
    Figure f;
    const size_t n = errors.size();
    double mean = 0;
    for (double e : errors)
        mean += e;
    mean /= double(n);
    double var = 0;
    for (double e : errors)
        var += (e - mean) * (e - mean);
    const double spread = n > 1 ? std::sqrt(var / double(n - 1) / double(n)) * smallSampleFactor(int(n) - 1) : 0.0;
    f.judged = true;
    f.value = mean;
    f.sigma = std::max(spread, floor);
    return f;
}

// Hard iron as the centre of the sphere the poses' fields lie on (linear least squares):
// |m|^2 = 2 m.c + (r^2 - |c|^2).
bool sphereCentre(const std::vector<Eigen::Vector3d> &m, Eigen::Vector3d &centre)
{
    Eigen::MatrixXd a(m.size(), 4);
    Eigen::VectorXd y(m.size());
    for (size_t i = 0; i < m.size(); ++i) {
        a.row(Eigen::Index(i)) << 2 * m[i].transpose(), 1.0;
        y[Eigen::Index(i)] = m[i].squaredNorm();
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
    if (qr.rank() < 4)
        return false;
    const Eigen::Vector4d x = qr.solve(y);
    centre = x.head<3>();
    return centre.allFinite();
}

double spreadPct(const std::vector<Eigen::Vector3d> &m, const Eigen::Vector3d &centre)
{
    double mean = 0, sq = 0;
    for (const auto &v : m)
        mean += (v - centre).norm();
    mean /= double(m.size());
    for (const auto &v : m)
        sq += std::pow((v - centre).norm() - mean, 2);
    return 100.0 * std::sqrt(sq / double(m.size())) / mean;
}

} // namespace

double smallSampleFactor(int nu)
{
    if (nu <= 0)
        return std::numeric_limits<double>::infinity();
    // Cornish-Fisher expansion of Student's t about the normal's 84th percentile (z = 0.9945):
    // the 1-sigma coverage of a spread from nu degrees of freedom.
    const double z = 0.9945;
    const double t = z + (z * z * z + z) / (4.0 * nu) + (5 * std::pow(z, 5) + 16 * z * z * z + 3 * z) / (96.0 * nu * nu);
    return t / z;
}

AttitudeCheck checkAttitude(std::vector<Pose> &poses, const AccFit &acc, const CheckOptions &options)
{
    AttitudeCheck out;
    for (Pose &p : poses) {
        p.tiltUsed = p.headingUsed = false;
        p.rollErrDeg = p.pitchErrDeg = p.headingErrDeg = std::numeric_limits<double>::quiet_NaN();
    }
    if (!acc.ok) {
        out.roll.why = out.pitch.why = out.heading.why =
            CheckReport::tr("needs the accelerometer calibrated from at least 9 still poses: an uncalibrated one "
                            "is no reference for the tilt");
        return out;
    }
    // Roll and pitch against gravity (ENU 3-1-2: up in the body is (-sin r cos p, sin p, cos r cos p)).
    std::vector<double> rollErr, pitchErr;
    std::vector<Eigen::Vector3d> up(poses.size());
    std::vector<double> refRoll(poses.size()), refPitch(poses.size());
    int steep = 0;
    for (size_t i = 0; i < poses.size(); ++i) {
        Pose &p = poses[i];
        up[i] = (acc.correction * (p.acc - acc.biasG)).normalized();
        refPitch[i] = std::asin(std::clamp(up[i].y(), -1.0, 1.0)) * kRadToDeg;
        refRoll[i] = std::atan2(-up[i].x(), up[i].z()) * kRadToDeg;
        if (!p.hasAttitude)
            continue;
        if (std::fabs(refPitch[i]) > options.maxPitchDeg) {
            ++steep;
            p.setAside = CheckReport::tr("pitch %1°: roll and heading have no meaning near ±90°").arg(refPitch[i], 0, 'f', 1);
            continue;
        }
        const model::Euler e =
            model::eulerEnu312(model::Quat{p.reported.w(), p.reported.x(), p.reported.y(), p.reported.z()});
        p.rollErrDeg = model::wrap180(e.roll - refRoll[i]);
        p.pitchErrDeg = e.pitch - refPitch[i];
        p.tiltUsed = true;
        rollErr.push_back(p.rollErrDeg);
        pitchErr.push_back(p.pitchErrDeg);
    }
    // The reference's own error: the accelerometer fit's, the same at every pose (so the poses'
    // spread does not show it), carried through the mean roll and pitch of the poses used.
    const AccParams params = accParams(acc);
    auto meanTilt = [&](const AccParams &q) {
        const Eigen::Matrix3d c = accCorrectionOf(q);
        Eigen::Vector2d sum = Eigen::Vector2d::Zero();
        for (const Pose &p : poses)
            if (p.tiltUsed) {
                const Eigen::Vector3d u = (c * (p.acc - q.head<3>())).normalized();
                sum += Eigen::Vector2d(std::atan2(-u.x(), u.z()), std::asin(std::clamp(u.y(), -1.0, 1.0)));
            }
        return Eigen::Vector2d(sum * kRadToDeg / double(std::max<size_t>(1, rollErr.size())));
    };
    Eigen::Matrix<double, 2, 9> jac;
    for (int k = 0; k < 9; ++k) {
        AccParams plus = params, minus = params;
        plus[k] += 1e-6;
        minus[k] -= 1e-6;
        jac.col(k) = (meanTilt(plus) - meanTilt(minus)) / 2e-6;
    }
    const Eigen::Vector2d refSigma = (jac * acc.covariance * jac.transpose()).diagonal().cwiseMax(0).cwiseSqrt();
    if (rollErr.size() < 3) {
        out.roll.why = out.pitch.why =
            CheckReport::tr("needs at least 3 still poses with the module's attitude and a pitch within ±%1° (found %2)")
                .arg(options.maxPitchDeg)
                .arg(rollErr.size());
    } else {
        out.roll = meanFigure(rollErr, 0.0);
        out.pitch = meanFigure(pitchErr, 0.0);
        // The poses' spread holds the reference's noise at each pose as well as the module's:
        // the larger of the two, not their sum, or that noise would count twice.
        out.roll.sigma = std::max(out.roll.sigma, refSigma[0]);
        out.pitch.sigma = std::max(out.pitch.sigma, refSigma[1]);
    }

    // Heading against the tilt-compensated magnetometer.
    std::vector<size_t> withMag;
    std::vector<Eigen::Vector3d> fields;
    for (size_t i = 0; i < poses.size(); ++i)
        if (poses[i].hasMag && poses[i].tiltUsed) {
            withMag.push_back(i);
            fields.push_back(poses[i].mag);
        }
    if (withMag.size() < 3) {
        out.heading.why = CheckReport::tr("needs at least 3 still poses with a magnetometer, the module's attitude and a "
                                          "pitch within ±%1° (found %2)")
                              .arg(options.maxPitchDeg)
                              .arg(withMag.size());
        return out;
    }
    // A hard iron the poses show (their fields on a sphere off the origin) is removed when that
    // makes the magnitudes agree.
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> allFields;
    for (const Pose &p : poses)
        if (p.hasMag)
            allFields.push_back(p.mag);
    // A disturbed pose would pull the centre: the worst is left out while it stands out.
    while (allFields.size() >= 6 && sphereCentre(allFields, centre)) {
        std::vector<double> radius;
        for (const auto &v : allFields)
            radius.push_back((v - centre).norm());
        const double med = median(radius);
        size_t worst = 0;
        for (size_t k = 1; k < radius.size(); ++k)
            if (std::fabs(radius[k] - med) > std::fabs(radius[worst] - med))
                worst = k;
        if (100.0 * std::fabs(radius[worst] - med) / med <= options.magMagnitudeTolerancePct) {
            const double before = spreadPct(allFields, Eigen::Vector3d::Zero());
            const double after = spreadPct(allFields, centre);
            if (centre.norm() > 0.1 && after < 0.5 * before) {
                out.hardIronUt = centre;
                out.hardIronRemoved = true;
            }
            break;
        }
        allFields.erase(allFields.begin() + std::ptrdiff_t(worst));
    }
    std::vector<double> magnitude, inclination;
    for (size_t k = 0; k < withMag.size(); ++k) {
        const Eigen::Vector3d m = fields[k] - out.hardIronUt;
        magnitude.push_back(m.norm());
        inclination.push_back(std::asin(std::clamp(-m.normalized().dot(up[withMag[k]]), -1.0, 1.0)) * kRadToDeg);
    }
    const double medMagnitude = median(magnitude), medInclination = median(inclination);
    std::vector<double> headingErr;
    for (size_t k = 0; k < withMag.size(); ++k) {
        Pose &p = poses[withMag[k]];
        const double dm = 100.0 * (magnitude[k] - medMagnitude) / medMagnitude;
        const double di = inclination[k] - medInclination;
        if (std::fabs(dm) > options.magMagnitudeTolerancePct) {
            p.setAside = CheckReport::tr("field %1 µT, %2 % from the other poses': a magnetic disturbance here")
                             .arg(magnitude[k], 0, 'f', 1)
                             .arg(dm, 0, 'f', 1);
            continue;
        }
        if (std::fabs(di) > options.magInclinationToleranceDeg) {
            p.setAside = CheckReport::tr("field inclination %1°, %2° from the other poses': a magnetic disturbance here")
                             .arg(inclination[k], 0, 'f', 1)
                             .arg(di, 0, 'f', 1);
            continue;
        }
        const size_t i = withMag[k];
        const double r = refRoll[i] * kDegToRad, pt = refPitch[i] * kDegToRad;
        const Eigen::Matrix3d tilt =
            (Eigen::AngleAxisd(pt, Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(r, Eigen::Vector3d::UnitY())).toRotationMatrix();
        const Eigen::Vector3d level = tilt * (fields[k] - out.hardIronUt);
        const double yawRef = std::atan2(level.x(), level.y()) * kRadToDeg; // counter-clockwise from magnetic north
        const double headingRef = -yawRef + options.declinationDeg;        // clockwise from north
        const model::Euler e =
            model::eulerEnu312(model::Quat{p.reported.w(), p.reported.x(), p.reported.y(), p.reported.z()});
        p.headingErrDeg = model::wrap180(-e.yaw - headingRef);
        p.headingUsed = true;
        headingErr.push_back(p.headingErrDeg);
    }
    if (headingErr.size() < 3) {
        out.heading.why = CheckReport::tr("the magnetic field disagreed between the poses (%1 of %2 set aside): "
                                          "calibrate the magnetometer, move away from steel and motors, and record again")
                              .arg(withMag.size() - headingErr.size())
                              .arg(withMag.size());
        return out;
    }
    out.heading = meanFigure(headingErr, 0.0);
    out.fieldKnown = true;
    out.fieldUt = medMagnitude;
    out.inclinationDeg = medInclination;
    return out;
}

} // namespace imudesk::verify
