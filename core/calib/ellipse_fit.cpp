#include "calib/ellipse_fit.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <cmath>

namespace imudesk::calib {

double Ellipse::radius() const
{
    const double det = w.determinant();
    return det > 0 ? 1.0 / std::sqrt(det) : 0.0;
}

Eigen::Matrix2d Ellipse::softIron() const
{
    return w * radius();
}

Eigen::Vector2d Ellipse::correct(const Eigen::Vector2d &m) const
{
    return softIron() * (m - center);
}

std::optional<Ellipse> EllipseFit::fit(const std::vector<Eigen::Vector2d> &points)
{
    if (points.size() < size_t(kMinPoints))
        return std::nullopt;
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (const auto &p : points)
        mean += p;
    mean /= double(points.size());
    double sq = 0;
    for (const auto &p : points)
        sq += (p - mean).squaredNorm();
    const double scale = std::sqrt(sq / double(points.size()));
    if (!(scale > 0) || !std::isfinite(scale))
        return std::nullopt;

    Eigen::Matrix3d s1 = Eigen::Matrix3d::Zero(), s2 = Eigen::Matrix3d::Zero(), s3 = Eigen::Matrix3d::Zero();
    for (const auto &p : points) {
        const Eigen::Vector2d u = (p - mean) / scale;
        const Eigen::Vector3d d1(u.x() * u.x(), u.x() * u.y(), u.y() * u.y());
        const Eigen::Vector3d d2(u.x(), u.y(), 1.0);
        s1.noalias() += d1 * d1.transpose();
        s2.noalias() += d1 * d2.transpose();
        s3.noalias() += d2 * d2.transpose();
    }
    Eigen::FullPivLU<Eigen::Matrix3d> s3lu(s3);
    if (!s3lu.isInvertible())
        return std::nullopt;
    const Eigen::Matrix3d t = -s3lu.inverse() * s2.transpose();
    const Eigen::Matrix3d m = s1 + s2 * t;
    Eigen::Matrix3d reduced;
    reduced.row(0) = m.row(2) / 2.0;
    reduced.row(1) = -m.row(1);
    reduced.row(2) = m.row(0) / 2.0;
    Eigen::EigenSolver<Eigen::Matrix3d> es(reduced);
    if (es.info() != Eigen::Success)
        return std::nullopt;
    int best = -1;
    double bestCond = 0;
    for (int i = 0; i < 3; ++i) {
        const Eigen::Vector3d v = es.eigenvectors().col(i).real();
        const double cond = 4 * v[0] * v[2] - v[1] * v[1];
        if (cond > bestCond) {
            bestCond = cond;
            best = i;
        }
    }
    if (best < 0)
        return std::nullopt;
    const Eigen::Vector3d a1 = es.eigenvectors().col(best).real();
    const Eigen::Vector3d a2 = t * a1;
    Eigen::Matrix2d q;
    q << a1[0], a1[1] / 2, a1[1] / 2, a1[2];
    Eigen::Vector2d lin(a2[0], a2[1]);
    double f = a2[2];
    if (q.trace() < 0) {
        q = -q;
        lin = -lin;
        f = -f;
    }
    // (u - c)^T Q (u - c) = k with c = -Q^-1 lin / 2.
    const Eigen::Matrix2d qinv = q.inverse();
    const Eigen::Vector2d c = -0.5 * qinv * lin;
    const double k = c.dot(q * c) - f;
    if (!(k > 0) || !std::isfinite(k) || !(q.determinant() > 0))
        return std::nullopt;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> sq2(q / k);
    Ellipse out;
    out.w = sq2.operatorSqrt() / scale;
    out.center = mean + scale * c;
    if (!out.w.allFinite() || !out.center.allFinite())
        return std::nullopt;
    return out;
}

} // namespace imudesk::calib
