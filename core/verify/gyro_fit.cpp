// Step 3 of the module check (module_check.h): the gyro's bias from the still poses and its
// scale from the turns between them.
#include "check_steps.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace imudesk::verify {

namespace {

constexpr double kDegToRad = 0.017453292519943295;
constexpr double kMaxTurnS = 30;       // longer between two poses: the bias's error grows too large
constexpr double kMaxScaleSigmaPct = 0.3; // a scale known worse than this is not judged

// One turn between two poses: the rate samples (bias removed) and the calibrated gravity
// direction at each end.
struct Turn {
    std::vector<double> dt;               // between consecutive samples
    std::vector<Eigen::Vector3d> rate;    // deg/s, bias removed, at the samples
    Eigen::Vector3d upFrom, upTo;
};

// The rotation of the body over a turn (q_to = q_from * result) with the rate divided by
// (1 + scale): trapezoidal rates, the exact rotation of each step.
Eigen::Quaterniond integrate(const Turn &t, const Eigen::Vector3d &scale)
{
    Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
    const Eigen::Vector3d inv = (Eigen::Vector3d::Ones() + scale).cwiseInverse();
    for (size_t i = 0; i + 1 < t.rate.size(); ++i) {
        const Eigen::Vector3d w = 0.5 * (t.rate[i] + t.rate[i + 1]).cwiseProduct(inv) * kDegToRad;
        const double angle = w.norm() * t.dt[i];
        if (angle > 0)
            q = q * Eigen::Quaterniond(Eigen::AngleAxisd(angle, w.normalized()));
    }
    return q.normalized();
}

// Residuals of every turn: the first pose's gravity carried to the second minus the second's.
Eigen::VectorXd residuals(const std::vector<Turn> &turns, const Eigen::Vector3d &scale)
{
    Eigen::VectorXd r(3 * turns.size());
    for (size_t k = 0; k < turns.size(); ++k) {
        const Eigen::Quaterniond q = integrate(turns[k], scale);
        r.segment<3>(3 * Eigen::Index(k)) = q.conjugate() * turns[k].upFrom - turns[k].upTo;
    }
    return r;
}

size_t indexAt(const std::vector<MotionSample> &s, double t)
{
    return size_t(std::lower_bound(s.begin(), s.end(), t, [](const MotionSample &m, double v) { return m.tS < v; })
                  - s.begin());
}

} // namespace

GyroFit fitGyro(const std::vector<MotionSample> &samples, const std::vector<Pose> &poses, const AccFit &acc)
{
    GyroFit fit;
    if (poses.empty()) {
        fit.biasDps.why = fit.scalePct.why = CheckReport::tr("no still pose");
        return fit;
    }
    // The bias: the still intervals' means weighted by their length; its sigma the larger of
    // the intervals' noise and their spread (a bias that wanders).
    double total = 0;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero(), noise = Eigen::Vector3d::Zero();
    for (const Pose &p : poses) {
        const double w = p.toS - p.fromS;
        total += w;
        mean += w * p.gyr;
        noise += (w * p.gyrSigma).cwiseAbs2();
    }
    mean /= total;
    noise = noise.cwiseSqrt() / total;
    Eigen::Vector3d spread = Eigen::Vector3d::Zero();
    if (poses.size() >= 3) {
        for (const Pose &p : poses)
            spread += (p.gyr - mean).cwiseAbs2();
        spread = (spread / double(poses.size() - 1) / double(poses.size())).cwiseSqrt()
            * smallSampleFactor(int(poses.size()) - 1);
    }
    fit.biasDps.judged = true;
    fit.biasDps.value = mean;
    fit.biasDps.sigma = noise.cwiseMax(spread);

    if (!acc.ok) {
        fit.scalePct.why = CheckReport::tr("needs the accelerometer calibrated from at least 9 still poses");
        return fit;
    }
    std::vector<Turn> turns;
    auto up = [&acc](const Pose &p) { return (acc.correction * (p.acc - acc.biasG)).normalized().eval(); };
    for (size_t k = 0; k + 1 < poses.size(); ++k) {
        const Pose &a = poses[k], &b = poses[k + 1];
        if (b.fromS - a.toS > kMaxTurnS)
            continue;
        const size_t from = indexAt(samples, a.toS), to = indexAt(samples, b.fromS);
        if (to <= from + 1 || to >= samples.size())
            continue;
        Turn t;
        t.upFrom = up(a);
        t.upTo = up(b);
        for (size_t i = from; i <= to; ++i) {
            t.rate.push_back(samples[i].gyr - mean);
            if (i > from)
                t.dt.push_back(samples[i].tS - samples[i - 1].tS);
        }
        // A turn too small to show a scale error (under 20°) carries nothing.
        if (std::acos(std::clamp(t.upFrom.dot(t.upTo), -1.0, 1.0)) < 20 * kDegToRad)
            continue;
        turns.push_back(std::move(t));
    }
    fit.turns = int(turns.size());
    if (turns.size() < 3) {
        fit.scalePct.why = CheckReport::tr("needs at least 3 turns of more than 20° between still poses (found %1)")
                               .arg(turns.size());
        return fit;
    }
    Eigen::Vector3d scale = Eigen::Vector3d::Zero();
    Eigen::MatrixXd j(3 * turns.size(), 3);
    Eigen::VectorXd r;
    for (int iteration = 0; iteration < 8; ++iteration) {
        r = residuals(turns, scale);
        for (int c = 0; c < 3; ++c) {
            Eigen::Vector3d h = Eigen::Vector3d::Zero();
            h[c] = 1e-5;
            j.col(c) = (residuals(turns, scale + h) - residuals(turns, scale - h)) / 2e-5;
        }
        const Eigen::Vector3d step = (j.transpose() * j).ldlt().solve(-j.transpose() * r);
        if (!step.allFinite())
            break;
        scale += step;
        if (step.norm() < 1e-9)
            break;
    }
    r = residuals(turns, scale);
    // Each residual is the difference of two unit vectors: two of its three components count.
    const int dof = 2 * int(turns.size()) - 3;
    const double s2 = r.squaredNorm() / dof;
    const Eigen::Matrix3d cov = (j.transpose() * j).inverse() * s2;
    const Eigen::Vector3d sigma = cov.diagonal().cwiseMax(0).cwiseSqrt() * 100.0 * smallSampleFactor(dof);
    fit.scalePct.value = scale * 100.0;
    fit.scalePct.sigma = sigma;
    static const char *const kAxis[3] = {"X", "Y", "Z"};
    QStringList weak;
    for (int c = 0; c < 3; ++c)
        if (!(sigma[c] <= kMaxScaleSigmaPct))
            weak << QString::fromLatin1(kAxis[c]);
    if (!weak.isEmpty()) {
        fit.scalePct.why = CheckReport::tr("the turns between poses did not turn the module about its %1 axis enough: "
                                           "turn it about each axis while that axis is level")
                               .arg(weak.join(QStringLiteral(", ")));
        return fit;
    }
    fit.scalePct.judged = true;
    return fit;
}

} // namespace imudesk::verify
