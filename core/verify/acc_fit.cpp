// Step 2 of the module check (module_check.h): the accelerometer from still poses.
#include "check_steps.h"

#include <Eigen/Dense>

#include <cmath>

namespace imudesk::verify {

namespace {

constexpr double kRadToDeg = 57.29577951308232;

using Params = AccParams;

Eigen::Matrix3d correctionOf(const Params &p)
{
    return accCorrectionOf(p);
}

// The 95 % quantile of chi-square with nu degrees of freedom (Wilson and Hilferty).
double chiSquare95(int nu)
{
    const double k = 2.0 / (9.0 * nu);
    const double c = 1.0 - k + 1.6449 * std::sqrt(k);
    return nu * c * c * c;
}

// Bias (mg), scale (%) and misalignment (deg) of the parameters, nine figures.
Eigen::Matrix<double, 9, 1> figuresOf(const Params &p)
{
    const Eigen::Matrix3d a = correctionOf(p).inverse();
    Eigen::Vector3d scale, mis;
    accFiguresOf(a, scale, mis);
    Eigen::Matrix<double, 9, 1> f;
    f << p.head<3>() * 1000.0, scale, mis;
    return f;
}

} // namespace

Eigen::Matrix3d accCorrectionOf(const AccParams &p)
{
    Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
    c(0, 0) = p[3];
    c(1, 0) = p[4];
    c(1, 1) = p[5];
    c(2, 0) = p[6];
    c(2, 1) = p[7];
    c(2, 2) = p[8];
    return c;
}

AccParams accParams(const AccFit &fit)
{
    const Eigen::Matrix3d &c = fit.correction;
    AccParams p;
    p << fit.biasG, c(0, 0), c(1, 0), c(1, 1), c(2, 0), c(2, 1), c(2, 2);
    return p;
}

void accFiguresOf(const Eigen::Matrix3d &a, Eigen::Vector3d &scalePct, Eigen::Vector3d &misalignmentDeg)
{
    for (int i = 0; i < 3; ++i)
        scalePct[i] = (a.row(i).norm() - 1.0) * 100.0;
    const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d u = a.row(pairs[k][0]).normalized(), v = a.row(pairs[k][1]).normalized();
        // 90° less the angle between the two sensitive axes: asin of their cosine.
        misalignmentDeg[k] = std::asin(std::clamp(u.dot(v), -1.0, 1.0)) * kRadToDeg;
    }
}

AccFit fitAccelerometer(const std::vector<Pose> &poses, double gravityG)
{
    AccFit fit;
    const int n = int(poses.size());
    if (n < 9)
        return fit;
    Params p = Params::Zero();
    // Start: no bias, every axis scaled so that the mean magnitude is gravity's.
    double meanNorm = 0;
    for (const Pose &pose : poses)
        meanNorm += pose.acc.norm();
    meanNorm /= n;
    p[3] = p[5] = p[8] = gravityG / meanNorm;

    Eigen::MatrixXd j(n, 9);
    Eigen::VectorXd r(n);
    auto evaluate = [&](const Params &q) {
        const Eigen::Matrix3d c = correctionOf(q);
        const Eigen::Vector3d b = q.head<3>();
        for (int i = 0; i < n; ++i) {
            const Eigen::Vector3d d = poses[size_t(i)].acc - b;
            const Eigen::Vector3d v = c * d;
            const double norm = v.norm();
            const Eigen::Vector3d u = v / norm;
            // The pose's noise along the measured direction (G).
            const double sigma = std::max(1e-7, u.cwiseProduct(poses[size_t(i)].accSigma).norm());
            r[i] = (norm - gravityG) / sigma;
            const Eigen::RowVector3d db = -(u.transpose() * c) / sigma;
            j.row(i) << db, u[0] * d[0] / sigma, u[1] * d[0] / sigma, u[1] * d[1] / sigma, u[2] * d[0] / sigma,
                u[2] * d[1] / sigma, u[2] * d[2] / sigma;
        }
    };
    for (int iteration = 0; iteration < 30; ++iteration) {
        evaluate(p);
        const Eigen::Matrix<double, 9, 9> h = j.transpose() * j;
        const Params step = h.ldlt().solve(-j.transpose() * r);
        if (!step.allFinite())
            return fit;
        p += step;
        if (step.norm() < 1e-12)
            break;
    }
    evaluate(p);
    const Eigen::Matrix<double, 9, 9> h = j.transpose() * j;
    Eigen::FullPivLU<Eigen::Matrix<double, 9, 9>> lu(h);
    if (lu.rank() < 9 || !p.allFinite())
        return fit; // the poses do not pin every parameter (too few directions)
    const double chi2 = r.squaredNorm();
    const int dof = n - 9;
    fit.inflation = dof > 0 && chi2 > chiSquare95(dof) ? chi2 / dof : 1.0;
    fit.covariance = lu.inverse() * fit.inflation;
    fit.correction = correctionOf(p);
    fit.biasG = p.head<3>();
    double sq = 0;
    for (const Pose &pose : poses) {
        const double e = (fit.correction * (pose.acc - fit.biasG)).norm() - gravityG;
        sq += e * e;
    }
    fit.rmsResidualG = std::sqrt(sq / n);
    fit.ok = true;
    return fit;
}

AccFigures accFigures(const AccFit &fit)
{
    const Params p = accParams(fit);
    const Eigen::Matrix<double, 9, 1> f0 = figuresOf(p);
    Eigen::Matrix<double, 9, 9> jac;
    for (int k = 0; k < 9; ++k) {
        const double h = 1e-7;
        Params plus = p, minus = p;
        plus[k] += h;
        minus[k] -= h;
        jac.col(k) = (figuresOf(plus) - figuresOf(minus)) / (2 * h);
    }
    const Eigen::Matrix<double, 9, 1> sigma = (jac * fit.covariance * jac.transpose()).diagonal().cwiseMax(0).cwiseSqrt();
    AccFigures out;
    out.biasMg = f0.segment<3>(0);
    out.scalePct = f0.segment<3>(3);
    out.misalignmentDeg = f0.segment<3>(6);
    out.biasSigma = sigma.segment<3>(0);
    out.scaleSigma = sigma.segment<3>(3);
    out.misalignmentSigma = sigma.segment<3>(6);
    return out;
}

} // namespace imudesk::verify
