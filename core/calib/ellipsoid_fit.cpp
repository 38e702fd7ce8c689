#include "calib/ellipsoid_fit.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace imudesk::calib {

namespace {

struct Normaliser {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    double scale = 1;
};

Normaliser normaliser(const std::vector<Eigen::Vector3d> &points)
{
    Normaliser n;
    if (points.empty())
        return n;
    for (const auto &p : points)
        n.mean += p;
    n.mean /= double(points.size());
    double sq = 0;
    for (const auto &p : points)
        sq += (p - n.mean).squaredNorm();
    n.scale = std::sqrt(sq / double(points.size()));
    if (!(n.scale > 0) || !std::isfinite(n.scale))
        n.scale = 1;
    return n;
}

std::vector<Eigen::Vector3d> normalised(const std::vector<Eigen::Vector3d> &points, const Normaliser &n)
{
    std::vector<Eigen::Vector3d> u;
    u.reserve(points.size());
    for (const auto &p : points)
        u.push_back((p - n.mean) / n.scale);
    return u;
}

bool positiveDefinite(const Eigen::Matrix3d &m)
{
    if (!m.allFinite())
        return false;
    Eigen::LLT<Eigen::Matrix3d> llt(m);
    return llt.info() == Eigen::Success;
}

Eigen::Matrix3d sqrtSymmetric(const Eigen::Matrix3d &m)
{
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(m);
    return es.operatorSqrt();
}

double median(std::vector<double> v)
{
    if (v.empty())
        return 0;
    const size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(mid), v.end());
    double m = v[mid];
    if (v.size() % 2 == 0) {
        const double lower = *std::max_element(v.begin(), v.begin() + std::ptrdiff_t(mid));
        m = 0.5 * (m + lower);
    }
    return m;
}

// Huber weight for residual r with threshold delta.
double huber(double r, double delta)
{
    const double a = std::fabs(r);
    return a <= delta ? 1.0 : delta / a;
}

using Vector9d = Eigen::Matrix<double, 9, 1>;
using Matrix9d = Eigen::Matrix<double, 9, 9>;

struct Params9 {
    Eigen::Vector3d c;
    Eigen::Matrix3d w;
};

Params9 apply(const Params9 &p, const Vector9d &d)
{
    Params9 q = p;
    q.c += d.head<3>();
    q.w(0, 0) += d[3];
    q.w(1, 1) += d[4];
    q.w(2, 2) += d[5];
    q.w(0, 1) += d[6];
    q.w(1, 0) += d[6];
    q.w(0, 2) += d[7];
    q.w(2, 0) += d[7];
    q.w(1, 2) += d[8];
    q.w(2, 1) += d[8];
    return q;
}

double residual9(const Params9 &p, const Eigen::Vector3d &u)
{
    return (p.w * (u - p.c)).norm() - 1.0;
}

double weightedCost(const Params9 &p, const std::vector<Eigen::Vector3d> &u, const std::vector<double> &w)
{
    double s = 0;
    for (size_t i = 0; i < u.size(); ++i) {
        const double r = residual9(p, u[i]);
        s += w[i] * r * r;
    }
    return s;
}

} // namespace

double Ellipsoid::radius() const
{
    const double det = w.determinant();
    return det > 0 ? 1.0 / std::cbrt(det) : 0.0;
}

Eigen::Matrix3d Ellipsoid::softIron() const
{
    return w * radius();
}

Eigen::Vector3d Ellipsoid::correct(const Eigen::Vector3d &m) const
{
    return softIron() * (m - center);
}

double EllipsoidFit::robustSigma(std::vector<double> values)
{
    if (values.empty())
        return 0;
    const double med = median(values);
    for (double &v : values)
        v = std::fabs(v - med);
    return 1.4826 * median(std::move(values));
}

std::vector<double> EllipsoidFit::residuals(const std::vector<Eigen::Vector3d> &points, const Ellipsoid &e)
{
    std::vector<double> r;
    r.reserve(points.size());
    const double radius = e.radius();
    const Eigen::Matrix3d s = e.softIron();
    for (const auto &p : points)
        r.push_back((s * (p - e.center)).norm() - radius);
    return r;
}

std::optional<std::pair<Eigen::Vector3d, double>> EllipsoidFit::sphere(const std::vector<Eigen::Vector3d> &points)
{
    if (points.size() < 4)
        return std::nullopt;
    const Normaliser n = normaliser(points);
    Eigen::Matrix4d ata = Eigen::Matrix4d::Zero();
    Eigen::Vector4d atb = Eigen::Vector4d::Zero();
    for (const auto &p : points) {
        const Eigen::Vector3d u = (p - n.mean) / n.scale;
        const Eigen::Vector4d row(2 * u.x(), 2 * u.y(), 2 * u.z(), 1.0);
        ata.noalias() += row * row.transpose();
        atb.noalias() += row * u.squaredNorm();
    }
    Eigen::LDLT<Eigen::Matrix4d> ldlt(ata);
    if (ldlt.info() != Eigen::Success)
        return std::nullopt;
    const Eigen::Vector4d x = ldlt.solve(atb);
    const Eigen::Vector3d c = x.head<3>();
    const double r2 = x[3] + c.squaredNorm();
    if (!x.allFinite() || !(r2 > 0))
        return std::nullopt;
    return std::make_pair(Eigen::Vector3d(n.mean + n.scale * c), n.scale * std::sqrt(r2));
}

std::optional<Ellipsoid> EllipsoidFit::algebraicLi(const std::vector<Eigen::Vector3d> &points)
{
    if (points.size() < size_t(kMinPoints))
        return std::nullopt;
    const Normaliser n = normaliser(points);
    using Vector10d = Eigen::Matrix<double, 10, 1>;
    using Matrix10d = Eigen::Matrix<double, 10, 10>;
    Matrix10d s = Matrix10d::Zero();
    for (const auto &p : points) {
        const Eigen::Vector3d u = (p - n.mean) / n.scale;
        Vector10d d;
        d << u.x() * u.x(), u.y() * u.y(), u.z() * u.z(), 2 * u.y() * u.z(), 2 * u.x() * u.z(), 2 * u.x() * u.y(),
            2 * u.x(), 2 * u.y(), 2 * u.z(), 1.0;
        s.noalias() += d * d.transpose();
    }
    const Eigen::Matrix<double, 6, 6> s11 = s.topLeftCorner<6, 6>();
    const Eigen::Matrix<double, 6, 4> s12 = s.topRightCorner<6, 4>();
    const Eigen::Matrix4d s22 = s.bottomRightCorner<4, 4>();
    Eigen::FullPivLU<Eigen::Matrix4d> s22lu(s22);
    if (!s22lu.isInvertible())
        return std::nullopt;
    const Eigen::Matrix4d s22inv = s22lu.inverse();
    const Eigen::Matrix<double, 6, 6> reduced = s11 - s12 * s22inv * s12.transpose();

    // Constraint k = 4: kJ - I^2 = 1 (Li & Griffiths 2004, eq. 9).
    Eigen::Matrix<double, 6, 6> c = Eigen::Matrix<double, 6, 6>::Zero();
    c.topLeftCorner<3, 3>() << -1, 1, 1, 1, -1, 1, 1, 1, -1;
    c.bottomRightCorner<3, 3>() = -4.0 * Eigen::Matrix3d::Identity();
    const Eigen::Matrix<double, 6, 6> e = c.inverse() * reduced;
    Eigen::EigenSolver<Eigen::Matrix<double, 6, 6>> es(e);
    if (es.info() != Eigen::Success)
        return std::nullopt;

    std::array<int, 6> order{0, 1, 2, 3, 4, 5};
    const auto values = es.eigenvalues();
    std::sort(order.begin(), order.end(), [&](int a, int b) { return values[a].real() > values[b].real(); });
    // The solution belongs to the only positive eigenvalue; with exact data it is 0 within
    // rounding, so try them from the largest down and keep the first that is an ellipsoid.
    for (int idx : order) {
        Eigen::Matrix<double, 6, 1> v1 = es.eigenvectors().col(idx).real();
        Eigen::Vector4d v2 = -s22inv * s12.transpose() * v1;
        Eigen::Matrix3d m;
        m << v1[0], v1[5], v1[4], v1[5], v1[1], v1[3], v1[4], v1[3], v1[2];
        Eigen::Vector3d lin(v2[0], v2[1], v2[2]);
        double d = v2[3];
        if (m.trace() < 0) {
            m = -m;
            lin = -lin;
            d = -d;
        }
        if (!positiveDefinite(m))
            continue;
        const Eigen::Matrix3d minv = m.inverse();
        const Eigen::Vector3d centre = -minv * lin;
        const double k = lin.dot(minv * lin) - d;
        if (!(k > 0) || !std::isfinite(k))
            continue;
        Ellipsoid out;
        out.w = sqrtSymmetric(m / k) / n.scale;
        out.center = n.mean + n.scale * centre;
        if (!out.w.allFinite() || !out.center.allFinite())
            continue;
        return out;
    }
    return std::nullopt;
}

Ellipsoid EllipsoidFit::refine(const std::vector<Eigen::Vector3d> &points, const Ellipsoid &start, RobustStats *stats)
{
    RobustStats st;
    if (points.size() < size_t(kMinPoints)) {
        if (stats)
            *stats = st;
        return start;
    }
    const Normaliser n = normaliser(points);
    const std::vector<Eigen::Vector3d> u = normalised(points, n);
    Params9 p{(start.center - n.mean) / n.scale, start.w * n.scale};
    std::vector<double> weights(u.size(), 1.0);
    std::vector<double> r(u.size());
    double lambda = 1e-3;
    constexpr int kOuter = 12;
    constexpr double kMinDelta = 1e-7;

    for (int outer = 0; outer < kOuter; ++outer) {
        for (size_t i = 0; i < u.size(); ++i)
            r[i] = residual9(p, u[i]);
        st.sigma = robustSigma(r);
        st.delta = std::max(3.0 * st.sigma, kMinDelta);
        for (size_t i = 0; i < u.size(); ++i)
            weights[i] = huber(r[i], st.delta);
        const Params9 before = p;
        double cost = weightedCost(p, u, weights);
        for (int it = 0; it < 20 && st.iterations < kMaxLmIterations * kOuter; ++it) {
            ++st.iterations;
            Matrix9d jtj = Matrix9d::Zero();
            Vector9d jtr = Vector9d::Zero();
            for (size_t i = 0; i < u.size(); ++i) {
                const Eigen::Vector3d d = u[i] - p.c;
                const Eigen::Vector3d y = p.w * d;
                const double norm = y.norm();
                if (!(norm > 0))
                    continue;
                const Eigen::Vector3d dc = -(p.w * y) / norm;
                Vector9d j;
                j << dc, y[0] * d[0] / norm, y[1] * d[1] / norm, y[2] * d[2] / norm, (y[0] * d[1] + y[1] * d[0]) / norm,
                    (y[0] * d[2] + y[2] * d[0]) / norm, (y[1] * d[2] + y[2] * d[1]) / norm;
                const double ri = norm - 1.0;
                jtj.noalias() += weights[i] * j * j.transpose();
                jtr.noalias() += weights[i] * ri * j;
            }
            bool improved = false;
            for (int attempt = 0; attempt < 10; ++attempt) {
                Matrix9d a = jtj;
                for (int k = 0; k < 9; ++k)
                    a(k, k) += lambda * std::max(jtj(k, k), 1e-12);
                const Vector9d step = a.ldlt().solve(-jtr);
                if (!step.allFinite()) {
                    lambda *= 10;
                    continue;
                }
                const Params9 q = apply(p, step);
                const double c2 = positiveDefinite(q.w) ? weightedCost(q, u, weights) : cost * 2 + 1;
                if (c2 < cost) {
                    const double rel = step.norm();
                    p = q;
                    const double drop = cost - c2;
                    cost = c2;
                    lambda = std::max(lambda / 10, 1e-12);
                    improved = true;
                    if (rel < 1e-12 || drop <= 1e-15 * cost)
                        it = 1000; // converged for these weights
                    break;
                }
                lambda *= 10;
            }
            if (!improved)
                break;
        }
        const double change = (p.c - before.c).norm() + (p.w - before.w).norm();
        if (change < 1e-10) {
            st.converged = true;
            break;
        }
    }
    for (size_t i = 0; i < u.size(); ++i)
        r[i] = residual9(p, u[i]);
    st.sigma = robustSigma(r);
    st.outliers = int(std::count_if(r.begin(), r.end(), [&](double x) {
        return std::fabs(x) > std::max(5.0 * st.sigma, st.delta);
    }));
    if (stats)
        *stats = st;
    Ellipsoid out;
    out.center = n.mean + n.scale * p.c;
    out.w = p.w / n.scale;
    // Keep W exactly symmetric.
    out.w = 0.5 * (out.w + out.w.transpose()).eval();
    return out;
}

std::optional<Ellipsoid> EllipsoidFit::hardIronOnly(const std::vector<Eigen::Vector3d> &points,
                                                    const Eigen::Matrix3d &softIron, double fixedRadius,
                                                    RobustStats *stats)
{
    if (points.size() < 4 || !positiveDefinite(softIron))
        return std::nullopt;
    const double det = softIron.determinant();
    const Eigen::Matrix3d s = softIron / std::cbrt(det);
    std::vector<Eigen::Vector3d> y;
    y.reserve(points.size());
    for (const auto &p : points)
        y.push_back(s * p);
    const auto seed = sphere(y);
    if (!seed)
        return std::nullopt;
    Eigen::Vector3d c = seed->first; // centre in the corrected space
    double radius = fixedRadius > 0 ? fixedRadius : seed->second;
    const bool freeRadius = !(fixedRadius > 0);
    const int np = freeRadius ? 4 : 3;
    RobustStats st;
    std::vector<double> r(y.size()), w(y.size(), 1.0);
    auto costOf = [&](const Eigen::Vector3d &cc, double rr) {
        double sum = 0;
        for (size_t i = 0; i < y.size(); ++i) {
            const double e = (y[i] - cc).norm() - rr;
            sum += w[i] * e * e;
        }
        return sum;
    };
    double lambda = 1e-3;
    for (int outer = 0; outer < 12; ++outer) {
        for (size_t i = 0; i < y.size(); ++i)
            r[i] = (y[i] - c).norm() - radius;
        st.sigma = robustSigma(r);
        st.delta = std::max(3.0 * st.sigma, 1e-7 * std::max(radius, 1e-9));
        for (size_t i = 0; i < y.size(); ++i)
            w[i] = huber(r[i], st.delta);
        const Eigen::Vector3d before = c;
        const double radiusBefore = radius;
        double cost = costOf(c, radius);
        for (int it = 0; it < 20; ++it) {
            ++st.iterations;
            Eigen::Matrix4d jtj = Eigen::Matrix4d::Zero();
            Eigen::Vector4d jtr = Eigen::Vector4d::Zero();
            for (size_t i = 0; i < y.size(); ++i) {
                const Eigen::Vector3d d = y[i] - c;
                const double norm = d.norm();
                if (!(norm > 0))
                    continue;
                Eigen::Vector4d j;
                j << -d / norm, -1.0;
                if (!freeRadius)
                    j[3] = 0;
                const double e = norm - radius;
                jtj.noalias() += w[i] * j * j.transpose();
                jtr.noalias() += w[i] * e * j;
            }
            if (!freeRadius)
                jtj(3, 3) = 1;
            bool improved = false;
            for (int attempt = 0; attempt < 10; ++attempt) {
                Eigen::Matrix4d a = jtj;
                for (int k = 0; k < np; ++k)
                    a(k, k) += lambda * std::max(jtj(k, k), 1e-12);
                const Eigen::Vector4d step = a.ldlt().solve(-jtr);
                const Eigen::Vector3d c2 = c + step.head<3>();
                const double r2 = freeRadius ? radius + step[3] : radius;
                const double cost2 = step.allFinite() && r2 > 0 ? costOf(c2, r2) : cost * 2 + 1;
                if (cost2 < cost) {
                    const double drop = cost - cost2;
                    c = c2;
                    radius = r2;
                    cost = cost2;
                    lambda = std::max(lambda / 10, 1e-12);
                    improved = true;
                    if (drop <= 1e-15 * cost || step.norm() < 1e-12 * radius)
                        it = 1000;
                    break;
                }
                lambda *= 10;
            }
            if (!improved)
                break;
        }
        if ((c - before).norm() + std::fabs(radius - radiusBefore) < 1e-10 * radius) {
            st.converged = true;
            break;
        }
    }
    for (size_t i = 0; i < y.size(); ++i)
        r[i] = (y[i] - c).norm() - radius;
    st.sigma = robustSigma(r);
    st.outliers = int(std::count_if(r.begin(), r.end(), [&](double x) {
        return std::fabs(x) > std::max(5.0 * st.sigma, st.delta);
    }));
    if (stats)
        *stats = st;
    Ellipsoid out;
    out.center = s.inverse() * c;
    out.w = s / radius;
    return out;
}

} // namespace imudesk::calib
