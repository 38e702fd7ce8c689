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
constexpr double kMaxMisalignmentSigmaDeg = 0.3; // nor a misalignment known worse than this

// One turn between two poses: the rate samples (bias removed) and the calibrated gravity
// direction at each end.
struct Turn {
    std::vector<double> dt;               // between consecutive samples
    std::vector<Eigen::Vector3d> rate;    // deg/s, bias removed, at the samples
    Eigen::Vector3d upFrom, upTo;
};

// The rotation of the body over a turn (q_to = q_from * result) with the true rate taken as
// `correction` times the measured one (bias removed): trapezoidal rates, the exact rotation of
// each step.
Eigen::Quaterniond integrate(const Turn &t, const Eigen::Matrix3d &correction)
{
    Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
    for (size_t i = 0; i + 1 < t.rate.size(); ++i) {
        const Eigen::Vector3d w = correction * (0.5 * (t.rate[i] + t.rate[i + 1])) * kDegToRad;
        const double angle = w.norm() * t.dt[i];
        if (angle > 0)
            q = q * Eigen::Quaterniond(Eigen::AngleAxisd(angle, w.normalized()));
    }
    return q.normalized();
}

// The gyro's model: measured = G true + bias, G = diag(1 + scale) (I + N), N strictly lower
// triangular (the accelerometer's form); the parameters: three scales, then (with
// misalignment) N(1,0), N(2,0), N(2,1).
Eigen::Matrix3d gyroMatrixOf(const Eigen::VectorXd &p)
{
    Eigen::Matrix3d n = Eigen::Matrix3d::Identity();
    if (p.size() == 6) {
        n(1, 0) = p[3];
        n(2, 0) = p[4];
        n(2, 1) = p[5];
    }
    return (Eigen::Vector3d::Ones() + p.head<3>()).asDiagonal() * n;
}

// Residuals of every turn: the first pose's gravity carried to the second minus the second's.
Eigen::VectorXd residuals(const std::vector<Turn> &turns, const Eigen::VectorXd &p)
{
    const Eigen::Matrix3d correction = gyroMatrixOf(p).inverse();
    Eigen::VectorXd r(3 * turns.size());
    for (size_t k = 0; k < turns.size(); ++k) {
        const Eigen::Quaterniond q = integrate(turns[k], correction);
        r.segment<3>(3 * Eigen::Index(k)) = q.conjugate() * turns[k].upFrom - turns[k].upTo;
    }
    return r;
}

struct GyroSolution {
    Eigen::VectorXd p;
    Eigen::MatrixXd covariance;
    bool ok = false;
};

// Gauss-Newton over `count` parameters (3: scales; 6: with misalignment).
GyroSolution solve(const std::vector<Turn> &turns, int count)
{
    GyroSolution out;
    out.p = Eigen::VectorXd::Zero(count);
    Eigen::MatrixXd j(3 * turns.size(), count);
    Eigen::VectorXd r;
    for (int iteration = 0; iteration < 8; ++iteration) {
        r = residuals(turns, out.p);
        for (int c = 0; c < count; ++c) {
            Eigen::VectorXd h = Eigen::VectorXd::Zero(count);
            h[c] = 1e-5;
            j.col(c) = (residuals(turns, out.p + h) - residuals(turns, out.p - h)) / 2e-5;
        }
        const Eigen::VectorXd step = (j.transpose() * j).ldlt().solve(-j.transpose() * r);
        if (!step.allFinite())
            return out;
        out.p += step;
        if (step.norm() < 1e-9)
            break;
    }
    r = residuals(turns, out.p);
    // Each residual is the difference of two unit vectors: two of its three components count.
    const int dof = 2 * int(turns.size()) - count;
    if (dof <= 0)
        return out;
    const double factor = smallSampleFactor(dof);
    out.covariance = (j.transpose() * j).inverse() * (r.squaredNorm() / dof) * factor * factor;
    out.ok = out.covariance.allFinite();
    return out;
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
    // Scales alone, then with the axes' misalignment where the turns pin it.
    const GyroSolution scales = solve(turns, 3);
    if (!scales.ok) {
        fit.scalePct.why = CheckReport::tr("the turns between poses do not pin the gyro's scale: turn it about each axis "
                                           "while that axis is level");
        return fit;
    }
    GyroSolution full = turns.size() >= 6 ? solve(turns, 6) : GyroSolution{};
    Eigen::Vector3d misSigma = Eigen::Vector3d::Constant(INFINITY);
    if (full.ok) {
        // The figures of the full model and their sigmas (numeric propagation).
        auto figures = [](const Eigen::VectorXd &p) {
            Eigen::Vector3d scalePct, misDeg;
            accFiguresOf(gyroMatrixOf(p), scalePct, misDeg);
            Eigen::Matrix<double, 6, 1> f;
            f << scalePct, misDeg;
            return f;
        };
        Eigen::Matrix<double, 6, 6> jac;
        for (int k = 0; k < 6; ++k) {
            Eigen::VectorXd plus = full.p, minus = full.p;
            plus[k] += 1e-7;
            minus[k] -= 1e-7;
            jac.col(k) = (figures(plus) - figures(minus)) / 2e-7;
        }
        const Eigen::Matrix<double, 6, 1> f = figures(full.p);
        const Eigen::Matrix<double, 6, 1> sigma = (jac * full.covariance * jac.transpose()).diagonal().cwiseMax(0).cwiseSqrt();
        misSigma = sigma.tail<3>();
        if ((misSigma.array() <= kMaxMisalignmentSigmaDeg).all()) {
            fit.misalignmentAxesDeg = f.tail<3>();
            fit.misalignmentAxesSigmaDeg = misSigma;
            Eigen::Index worst = 0;
            fit.misalignmentAxesDeg.cwiseAbs().maxCoeff(&worst);
            fit.misalignmentDeg = Figure{true, fit.misalignmentAxesDeg[worst], misSigma[worst], {}};
            fit.correction = gyroMatrixOf(full.p).inverse();
            fit.scalePct.value = f.head<3>();
            fit.scalePct.sigma = sigma.head<3>();
        }
    }
    if (!fit.misalignmentDeg.judged) {
        fit.misalignmentDeg.why = CheckReport::tr("the turns between poses do not pin the gyro's axes (at least 6 turns "
                                                  "of more than 20°, about every axis, are needed; found %1)")
                                      .arg(turns.size());
        fit.correction = gyroMatrixOf(scales.p).inverse();
        fit.scalePct.value = scales.p * 100.0;
        fit.scalePct.sigma = scales.covariance.diagonal().cwiseMax(0).cwiseSqrt() * 100.0;
    }
    const Eigen::Vector3d &sigma = fit.scalePct.sigma;
    static const char *const kAxis[3] = {"X", "Y", "Z"};
    QStringList weak;
    for (int c = 0; c < 3; ++c)
        if (!(sigma[c] <= kMaxScaleSigmaPct))
            weak << QString::fromLatin1(kAxis[c]);
    if (!weak.isEmpty()) {
        fit.scalePct.why = CheckReport::tr("the turns between poses did not turn the module about its %1 axis enough: "
                                           "turn it about each axis while that axis is level")
                               .arg(weak.join(QStringLiteral(", ")));
        fit.misalignmentDeg = Figure{false, 0, 0, fit.scalePct.why};
        fit.correction = Eigen::Matrix3d::Identity();
        return fit;
    }
    fit.scalePct.judged = true;
    return fit;
}

} // namespace imudesk::verify
