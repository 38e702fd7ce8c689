// Step 5 of the module check (module_check.h): the attitude the module reports while it moves
// between poses, against ImuDesk's reference filter on the module's own calibrated sensors.
#include "check_steps.h"
#include "reference_filter.h"

#include <algorithm>
#include <cmath>

namespace imudesk::verify {

namespace {

constexpr double kRadToDeg = 57.29577951308232;
constexpr double kDegToRad = 0.017453292519943295;
constexpr double kMaxLagS = 0.5;          // the lags searched: -0.1 .. 0.5 s
constexpr double kMinMovingS = 2.0;       // moving time the figures need
constexpr double kMinTurnDeg = 90.0;      // and this much turning

double angleDeg(const Eigen::Quaterniond &a, const Eigen::Quaterniond &b)
{
    return 2.0 * std::acos(std::min(1.0, std::fabs(a.dot(b)))) * kRadToDeg;
}

// The reference attitude at a still pose: up from the calibrated accelerometer, north from the
// magnetometer (then true north by the declination), or, without one, the module's own
// heading with its tilt corrected.
Eigen::Quaterniond poseReference(const Pose &p, const AccFit &acc, const AttitudeCheck &att, const CheckOptions &options)
{
    const Eigen::Vector3d up = (acc.correction * (p.acc - acc.biasG)).normalized();
    if (att.fieldKnown && p.headingUsed) {
        const Eigen::Vector3d m = (p.mag - att.hardIronUt).normalized();
        const Eigen::Vector3d east = m.cross(up).normalized();
        const Eigen::Vector3d north = up.cross(east);
        Eigen::Matrix3d r; // body to magnetic ENU: its rows are east, north and up in the body
        r.row(0) = east.transpose();
        r.row(1) = north.transpose();
        r.row(2) = up.transpose();
        const Eigen::Quaterniond toTrue(Eigen::AngleAxisd(-options.declinationDeg * kDegToRad, Eigen::Vector3d::UnitZ()));
        return (toTrue * Eigen::Quaterniond(r)).normalized();
    }
    const Eigen::Vector3d reportedUp = p.reported * up;
    return (Eigen::Quaterniond::FromTwoVectors(reportedUp, Eigen::Vector3d::UnitZ()) * p.reported).normalized();
}

} // namespace

DynamicCheck checkDynamic(const std::vector<MotionSample> &samples, const std::vector<Pose> &poses, const AccFit &acc,
                          const GyroFit &gyro, const AttitudeCheck &att, const CheckOptions &options)
{
    DynamicCheck out;
    auto refuse = [&out](const QString &why) {
        out.rmsDeg.why = out.maxDeg.why = out.lagMs.why = why;
        return out;
    };
    if (!acc.ok)
        return refuse(CheckReport::tr("needs the accelerometer calibrated from at least 9 still poses"));
    const auto first = std::find_if(poses.begin(), poses.end(), [](const Pose &p) { return p.hasAttitude; });
    if (first == poses.end())
        return refuse(CheckReport::tr("needs a still pose with the module's attitude to start from"));

    ReferenceFilter::Sensors s;
    s.accCorrection = acc.correction;
    s.accBias = acc.biasG;
    s.gravityG = (acc.correction * (first->acc - acc.biasG)).norm(); // the fitted gravity
    s.gyroBias = gyro.biasDps.judged ? gyro.biasDps.value : Eigen::Vector3d::Zero();
    if (gyro.scalePct.judged)
        s.gyroCorrection = gyro.correction;
    std::vector<double> noise;
    for (const Pose &p : poses)
        noise.push_back(p.gyrSigma.norm() / std::sqrt(3.0) * std::sqrt(double(p.samples)));
    std::nth_element(noise.begin(), noise.begin() + std::ptrdiff_t(noise.size() / 2), noise.end());
    s.gyroNoiseDps = std::max(0.005, noise[noise.size() / 2]);
    if (att.fieldKnown) {
        s.useMag = true;
        s.hardIron = att.hardIronUt;
        s.fieldUt = att.fieldUt;
        const double inc = att.inclinationDeg * kDegToRad;
        // Magnetic north and down by the inclination, turned to true north by the declination.
        s.fieldNav = Eigen::AngleAxisd(-options.declinationDeg * kDegToRad, Eigen::Vector3d::UnitZ())
            * Eigen::Vector3d(0, std::cos(inc), -std::sin(inc));
    }
    // The magnetometer is trusted as far as the poses agreed on north: the spread of their heading
    // differences (iron the fit left, a field that is not the same everywhere) is its error.
    double startSigmaDeg = 0.05;
    if (att.fieldKnown) {
        std::vector<double> h;
        for (const Pose &p : poses)
            if (p.headingUsed)
                h.push_back(p.headingErrDeg);
        double mean = 0, var = 0;
        for (double v : h)
            mean += v / double(h.size());
        for (double v : h)
            var += (v - mean) * (v - mean) / double(std::max<size_t>(1, h.size() - 1));
        const double spreadDeg = std::sqrt(var);
        s.magSigmaRad = std::max(s.magSigmaRad, spreadDeg * kDegToRad);
        startSigmaDeg = std::max(startSigmaDeg, spreadDeg);
    }
    ReferenceFilter filter(s);
    filter.start(poseReference(*first, acc, att, options), startSigmaDeg);

    // Run from the first pose on; keep the reference and the report at every sample.
    const auto begin = std::lower_bound(samples.begin(), samples.end(), first->fromS,
                                        [](const MotionSample &m, double t) { return m.tS < t; });
    std::vector<Eigen::Quaterniond> ref, rep;
    std::vector<char> moving;
    std::vector<double> sigma;
    size_t pose = size_t(first - poses.begin());
    double turned = 0;
    for (auto it = begin; it != samples.end(); ++it) {
        filter.update(it->tS, it->acc, it->gyr, it->mag, it->hasMag);
        while (pose < poses.size() && poses[pose].toS < it->tS)
            ++pose;
        const bool still = pose < poses.size() && it->tS >= poses[pose].fromS;
        ref.push_back(filter.attitude());
        rep.push_back(it->hasAttitude ? it->q : Eigen::Quaterniond(0, 0, 0, 0));
        moving.push_back(!still && it->hasAttitude);
        sigma.push_back(filter.attitudeSigmaDeg());
        if (!still && it != begin)
            turned += (it->gyr - s.gyroBias).norm() * (it->tS - (it - 1)->tS);
    }
    const size_t n = ref.size();
    const double dt = n > 1 ? ((begin + std::ptrdiff_t(n) - 1)->tS - begin->tS) / double(n - 1) : 0.0;
    const size_t movingSamples = size_t(std::count(moving.begin(), moving.end(), 1));
    if (dt <= 0 || double(movingSamples) * dt < kMinMovingS || turned < kMinTurnDeg)
        return refuse(CheckReport::tr("the module did not move enough between the poses (%1 s, %2° turned; %3 s and "
                                      "%4° needed)")
                          .arg(double(movingSamples) * dt, 0, 'f', 1)
                          .arg(turned, 0, 'f', 0)
                          .arg(kMinMovingS)
                          .arg(kMinTurnDeg));

    // The error at every moving sample, the report against the reference `shift` samples earlier.
    auto rmsAt = [&](long shift, double *maxOut) {
        double sq = 0, worst = 0;
        size_t count = 0;
        for (size_t i = 0; i < n; ++i) {
            const long j = long(i) - shift;
            if (!moving[i] || j < 0 || j >= long(n))
                continue;
            const double e = angleDeg(rep[i], ref[size_t(j)]);
            sq += e * e;
            worst = std::max(worst, e);
            ++count;
        }
        if (maxOut)
            *maxOut = worst;
        return count ? std::sqrt(sq / double(count)) : INFINITY;
    };
    double worst = 0;
    const double rms = rmsAt(0, &worst);
    double refSigma = 0;
    for (size_t i = 0; i < n; ++i)
        if (moving[i])
            refSigma += sigma[i] * sigma[i];
    refSigma = std::sqrt(refSigma / double(movingSamples));
    out.rmsDeg = Figure{true, rms, refSigma, {}};
    out.maxDeg = Figure{true, worst, refSigma, {}};

    const long lo = -long(std::lround(0.1 / dt)), hi = long(std::lround(kMaxLagS / dt));
    long best = 0;
    double bestRms = rms;
    std::vector<double> curve;
    for (long k = lo; k <= hi; ++k) {
        curve.push_back(rmsAt(k, nullptr));
        if (curve.back() < bestRms) {
            bestRms = curve.back();
            best = k;
        }
    }
    // A parabola through the minimum and its neighbours: the lag between samples.
    double frac = 0;
    const size_t b = size_t(best - lo);
    if (b > 0 && b + 1 < curve.size()) {
        const double y0 = curve[b - 1], y1 = curve[b], y2 = curve[b + 1];
        const double den = y0 - 2 * y1 + y2;
        if (den > 0)
            frac = 0.5 * (y0 - y2) / den;
    }
    if (best == lo || best == hi) {
        out.lagMs.why = CheckReport::tr("the module's attitude follows the reference by more than %1 ms or not at all")
                            .arg(kMaxLagS * 1000);
        return out;
    }
    out.lagMs = Figure{true, (double(best) + frac) * dt * 1000.0, dt * 1000.0 / 2.0, {}};
    return out;
}

} // namespace imudesk::verify
