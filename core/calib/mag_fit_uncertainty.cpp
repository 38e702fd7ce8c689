#include "calib/mag_fit_uncertainty.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace imudesk::calib {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();

// The parameters, in one order for every fit: hard iron b (uT), then the entries of the
// symmetric W (1/uT): xx, yy, zz, xy, xz, yz. A fit that holds some of them uses a basis
// P (9 x k) of the directions it can move in.
constexpr int kParams = 9;
using Vector9d = Eigen::Matrix<double, kParams, 1>;
using Matrix9d = Eigen::Matrix<double, kParams, kParams>;
using Basis = Eigen::Matrix<double, kParams, Eigen::Dynamic>;

Eigen::Matrix3d basisMatrix(int k)
{
    static constexpr int kRow[6] = {0, 1, 2, 0, 0, 1};
    static constexpr int kCol[6] = {0, 1, 2, 1, 2, 2};
    Eigen::Matrix3d e = Eigen::Matrix3d::Zero();
    e(kRow[k], kCol[k]) = 1;
    e(kCol[k], kRow[k]) = 1;
    return e;
}

// The gradient of r = |W (m - b)| - 1 with respect to the nine parameters.
Vector9d gradient3(const Eigen::Vector3d &m, const Eigen::Vector3d &b, const Eigen::Matrix3d &w, double *residual)
{
    Vector9d j = Vector9d::Zero();
    const Eigen::Vector3d d = m - b;
    const Eigen::Vector3d y = w * d;
    const double n = y.norm();
    *residual = n - 1.0;
    if (!(n > 0))
        return j;
    j.head<3>() = -(w * y) / n;
    for (int k = 0; k < 6; ++k)
        j[3 + k] = y.dot(basisMatrix(k) * d) / n;
    return j;
}

// s^2 (J^T J)^-1 in the directions of P, mapped back onto the nine parameters. The
// inliers are the residuals within 5 robust sigmas (the fits' own outlier rule); s^2 is
// the sum of their squares over the degrees of freedom. False when the geometry leaves a
// direction undetermined.
bool covariance(const std::vector<Vector9d> &rows, const std::vector<double> &residuals, const Basis &p, Matrix9d &out)
{
    const int k = int(p.cols());
    const double sigma = EllipsoidFit::robustSigma(residuals);
    const double limit = sigma > 0 ? 5.0 * sigma : kInf;
    Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(k, k);
    double sumSq = 0;
    int n = 0;
    for (size_t i = 0; i < rows.size(); ++i) {
        if (!(std::fabs(residuals[i]) <= limit))
            continue;
        const Eigen::VectorXd j = p.transpose() * rows[i];
        normal.noalias() += j * j.transpose();
        sumSq += residuals[i] * residuals[i];
        ++n;
    }
    if (n <= k || !normal.allFinite())
        return false;
    const double s2 = sumSq / double(n - k);
    // Equilibrate the columns (centre in uT, W in 1/uT differ by |B|^2) before inverting.
    Eigen::VectorXd scale(k);
    for (int i = 0; i < k; ++i) {
        if (!(normal(i, i) > 0))
            return false;
        scale[i] = 1.0 / std::sqrt(normal(i, i));
    }
    const Eigen::MatrixXd eq = scale.asDiagonal() * normal * scale.asDiagonal();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(eq);
    if (es.info() != Eigen::Success)
        return false;
    const Eigen::VectorXd lambda = es.eigenvalues();
    if (!(lambda[0] > 1e-12 * lambda[k - 1]))
        return false;
    const Eigen::MatrixXd inv = es.eigenvectors() * lambda.cwiseInverse().asDiagonal() * es.eigenvectors().transpose();
    const Eigen::MatrixXd covK = s2 * scale.asDiagonal() * inv * scale.asDiagonal();
    out = p * covK * p.transpose();
    return out.allFinite();
}

// splitmix64 with Box-Muller: the same draws on every platform.
class Normal {
public:
    Normal() = default;
    explicit Normal(uint64_t seed) : m_state(seed) {}
    double next()
    {
        if (m_haveSpare) {
            m_haveSpare = false;
            return m_spare;
        }
        const double r = std::sqrt(-2.0 * std::log(unit()));
        const double a = 2.0 * kPi * unit();
        m_spare = r * std::sin(a);
        m_haveSpare = true;
        return r * std::cos(a);
    }

private:
    double unit()
    {
        uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        z ^= z >> 31;
        return (double(z >> 11) + 0.5) * 0x1.0p-53;
    }
    uint64_t m_state = 0x5DEECE66Dull;
    double m_spare = 0;
    bool m_haveSpare = false;
};

// FNV-1a over the samples' bits.
uint64_t seedOf(const std::vector<Eigen::Vector3d> &points)
{
    uint64_t h = 0xCBF29CE484222325ull;
    for (const auto &p : points)
        for (int i = 0; i < 3; ++i) {
            uint64_t bits;
            const double v = p[i];
            std::memcpy(&bits, &v, sizeof bits);
            for (int b = 0; b < 8; ++b) {
                h ^= (bits >> (8 * b)) & 0xFF;
                h *= 0x100000001B3ull;
            }
        }
    return h;
}

MagFitUncertainty::Figures singularFigures()
{
    MagFitUncertainty::Figures f;
    f.hardIronSigmaUt = f.softIronSigmaPct = f.headingErrorDeg = f.headingError95Deg = kInf;
    f.singular = true;
    return f;
}

// The q quantile of v (+inf when v is empty).
// The bound a further draw stays below with probability q, from n draws: the k-th smallest of n
// draws is exceeded by the next one with probability 1 - k/(n + 1), so the bound sits at rank
// q (n + 1), interpolated between neighbours (Weibull's plotting position). Taking rank q n
// instead made every bound a little short: with the 32 refits, the "68 %" bound held 67 % of the
// time and the "95 %" bound 94 % (the bench's coverage sweep shows the difference).
double quantile(std::vector<double> v, double q)
{
    if (v.empty())
        return kInf;
    std::sort(v.begin(), v.end());
    const double rank = std::clamp(q * double(v.size() + 1), 1.0, double(v.size())); // 1-based
    const size_t below = size_t(rank) - 1;
    const double frac = rank - std::floor(rank);
    if (below + 1 >= v.size() || frac == 0)
        return v[below];
    return v[below] + frac * (v[below + 1] - v[below]); // +inf when the next draw failed
}

// The figures from the parameter covariance. dims 3: a 3-D fit, the field inclined by
// `inclination` (rad); dims 2: a 2-D fit, the corrected vector is the horizontal field.
MagFitUncertainty::Figures figuresOf(const Matrix9d &cov, const Eigen::Matrix3d &w, double inclination, int dims,
                                     bool softIronFitted)
{
    MagFitUncertainty::Figures f;
    const Eigen::Matrix3d covB = cov.topLeftCorner<3, 3>();
    f.hardIronSigmaUt = std::sqrt(std::max(0.0, covB.trace()));
    const Eigen::Matrix3d wInv = w.inverse();

    if (softIronFitted) {
        // S = W / cbrt(det W): to first order the shape error S^ S^-1 - I is
        // dW W^-1 - tr(W^-1 dW) / dims * I, over the fitted block.
        Eigen::Matrix<double, 9, 6> jf = Eigen::Matrix<double, 9, 6>::Zero();
        for (int k = 0; k < 6; ++k) {
            const Eigen::Matrix3d e = basisMatrix(k);
            Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
            m.topLeftCorner(dims, dims) = (e * wInv).topLeftCorner(dims, dims);
            const double tr = (wInv * e).topLeftCorner(dims, dims).trace() / dims;
            m.topLeftCorner(dims, dims) -= tr * Eigen::MatrixXd::Identity(dims, dims);
            jf.col(k) = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(m.data());
        }
        const Eigen::Matrix<double, 6, 6> covW = cov.bottomRightCorner<6, 6>();
        f.softIronSigmaPct = 100.0 * std::sqrt(std::max(0.0, (jf * covW * jf.transpose()).trace()));
    }

    // Heading error of a level module at each heading, linear in the parameter errors:
    // the corrected unit vector u = W (m - b) moves by dW W^-1 u - W db; its component
    // across the horizontal field, over the horizontal field, is the heading error (rad).
    const double cosI = std::cos(inclination), sinI = std::sin(inclination);
    const Eigen::Vector3d fieldNav(0.0, cosI, -sinI); // towards north and down
    constexpr int kHeadings = 360 / MagFitUncertainty::kHeadingStepDeg;
    Eigen::Matrix<double, kHeadings, kParams> g;
    for (int h = 0; h < kHeadings; ++h) {
        const double yaw = h * MagFitUncertainty::kHeadingStepDeg * kPi / 180.0;
        const Eigen::Matrix3d r = Eigen::Matrix3d(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
        const Eigen::Vector3d u = r.transpose() * fieldNav;
        const Eigen::RowVector3d across = r.row(0) / cosI; // east, with the field towards north
        g.block<1, 3>(h, 0) = -across * w;
        for (int k = 0; k < 6; ++k)
            g(h, 3 + k) = across * (basisMatrix(k) * (wInv * u));
    }
    // Draws of the parameter errors from the covariance: L L^T = cov.
    Eigen::SelfAdjointEigenSolver<Matrix9d> ec(cov);
    const Matrix9d l = ec.eigenvectors() * ec.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
    const Eigen::Matrix<double, kHeadings, kParams> gl = g * l;
    Normal normal;
    std::vector<double> worst(MagFitUncertainty::kDraws);
    for (double &x : worst) {
        Vector9d z;
        for (int i = 0; i < kParams; ++i)
            z[i] = normal.next();
        x = (gl * z).cwiseAbs().maxCoeff();
    }
    f.headingErrorDeg = quantile(worst, MagFitUncertainty::kHeadingQuantile) * 180.0 / kPi;
    f.headingError95Deg = quantile(worst, MagFitUncertainty::kHeadingQuantile95) * 180.0 / kPi;
    return f;
}

// Largest heading error over one level turn of a fit `fit` against the model `truth` (the
// corrected frame of `truth` taken as the body frame), radians.
double levelTurnError(const Ellipsoid &truth, const Ellipsoid &fit, double inclination)
{
    const Eigen::Vector3d fieldNav(0.0, std::cos(inclination), -std::sin(inclination));
    const Eigen::Matrix3d truthInv = truth.w.inverse();
    double worst = 0;
    for (int deg = 0; deg < 360; deg += MagFitUncertainty::kHeadingStepDeg) {
        const Eigen::Matrix3d r = Eigen::Matrix3d(Eigen::AngleAxisd(deg * kPi / 180.0, Eigen::Vector3d::UnitZ()));
        const Eigen::Vector3d raw = truth.center + truthInv * (r.transpose() * fieldNav);
        const Eigen::Vector3d nav = r * (fit.w * (raw - fit.center));
        const double e = std::fabs(std::atan2(nav.x(), nav.y())); // the field points north: heading 0
        if (!std::isfinite(e))
            return kInf;
        worst = std::max(worst, e);
    }
    return worst;
}

} // namespace

MagFitUncertainty::Figures MagFitUncertainty::resampledEllipsoid(const std::vector<Eigen::Vector3d> &points,
                                                                 const Ellipsoid &e, double inclinationDeg, int replicates)
{
    if (replicates < 1)
        return ofEllipsoid(points, e, inclinationDeg);
    const double inclination = inclinationDeg * kPi / 180.0;
    const Eigen::Matrix3d wInv = e.w.inverse();
    // Residuals in uT along the gradient of |W (m - b)| (the Sampson distance): for noise of
    // sigma per axis their spread is sigma whatever the shape.
    std::vector<double> res;
    std::vector<Eigen::Vector3d> onSurface;
    res.reserve(points.size());
    onSurface.reserve(points.size());
    for (const auto &m : points) {
        const Eigen::Vector3d y = e.w * (m - e.center);
        const double n = y.norm();
        const double grad = (e.w * y).norm() / std::max(n, 1e-300);
        if (!(n > 0) || !(grad > 0) || !std::isfinite(n))
            continue;
        res.push_back((n - 1.0) / grad);
        onSurface.push_back(e.center + wInv * (y / n));
    }
    const double robust = EllipsoidFit::robustSigma(res);
    const double limit = robust > 0 ? 5.0 * robust : kInf;
    std::vector<Eigen::Vector3d> clean;
    double sumSq = 0;
    for (size_t i = 0; i < res.size(); ++i)
        if (std::fabs(res[i]) <= limit) {
            clean.push_back(onSurface[i]);
            sumSq += res[i] * res[i];
        }
    if (int(clean.size()) <= kParams + 1)
        return singularFigures();
    // The fit took 9 degrees of freedom (10 with the radius) out of the residuals.
    const double sigma = std::sqrt(sumSq / double(clean.size() - kParams - 1));

    // The draws are seeded by the samples: the same data give the same figures, and other data
    // other draws. (One fixed sequence for every data set made the replicates' errors of every
    // fit of one geometry err together: the 68 % bound then held 53 % of the time on one
    // coverage and 75 % on another.)
    Normal normal(seedOf(points));
    std::vector<double> headings, hiSq, siSq;
    std::vector<Eigen::Vector3d> noisy(clean.size());
    const Eigen::Matrix3d shape = e.softIron();
    for (int k = 0; k < replicates; ++k) {
        for (size_t i = 0; i < clean.size(); ++i)
            noisy[i] = clean[i] + sigma * Eigen::Vector3d(normal.next(), normal.next(), normal.next());
        const auto li = EllipsoidFit::algebraicLi(noisy);
        if (!li) {
            headings.push_back(kInf);
            hiSq.push_back(kInf);
            siSq.push_back(kInf);
            continue;
        }
        const Ellipsoid fit = EllipsoidFit::refine(noisy, *li);
        const Eigen::Vector3d db = fit.center - e.center;
        hiSq.push_back(db.squaredNorm());
        const Eigen::Matrix3d m = fit.softIron() * shape.inverse();
        const double det = m.determinant();
        siSq.push_back(det > 0 ? (m / std::cbrt(det) - Eigen::Matrix3d::Identity()).squaredNorm() : kInf);
        headings.push_back(levelTurnError(e, fit, inclination));
    }
    auto rmsOf = [](const std::vector<double> &v) {
        double s = 0;
        for (double x : v)
            s += x;
        return v.empty() ? kInf : std::sqrt(s / double(v.size()));
    };
    Figures f;
    f.hardIronSigmaUt = rmsOf(hiSq);
    f.softIronSigmaPct = 100.0 * rmsOf(siSq);
    f.headingErrorDeg = quantile(headings, kHeadingQuantile) * 180.0 / kPi;
    f.headingError95Deg = quantile(headings, kHeadingQuantile95) * 180.0 / kPi;
    return f;
}

namespace {

// Each sample's residual from the ellipsoid and its gradient in the nine parameters.
void linearise(const std::vector<Eigen::Vector3d> &points, const Ellipsoid &e,
               std::vector<Vector9d> &rows, std::vector<double> &res)
{
    rows.reserve(points.size());
    res.reserve(points.size());
    for (const auto &m : points) {
        double r = 0;
        rows.push_back(gradient3(m, e.center, e.w, &r));
        res.push_back(r);
    }
}

} // namespace

MagFitUncertainty::Figures MagFitUncertainty::ofEllipsoid(const std::vector<Eigen::Vector3d> &points, const Ellipsoid &e,
                                                          double inclinationDeg)
{
    std::vector<Vector9d> rows;
    std::vector<double> res;
    linearise(points, e, rows, res);
    Matrix9d cov;
    if (!covariance(rows, res, Basis::Identity(kParams, kParams), cov))
        return singularFigures();
    return figuresOf(cov, e.w, inclinationDeg * kPi / 180.0, 3, true);
}

MagFitUncertainty::Figures MagFitUncertainty::ofHardIronFit(const std::vector<Eigen::Vector3d> &points,
                                                            const Ellipsoid &e, bool radiusFree, double inclinationDeg)
{
    std::vector<Vector9d> rows;
    std::vector<double> res;
    linearise(points, e, rows, res);
    // The hard iron moves freely; W only by a common scale (the field strength) when free.
    Basis p = Basis::Zero(kParams, radiusFree ? 4 : 3);
    p.topLeftCorner<3, 3>().setIdentity();
    if (radiusFree)
        p.block<6, 1>(3, 3) << e.w(0, 0), e.w(1, 1), e.w(2, 2), e.w(0, 1), e.w(0, 2), e.w(1, 2);
    Matrix9d cov;
    if (!covariance(rows, res, p, cov))
        return singularFigures();
    return figuresOf(cov, e.w, inclinationDeg * kPi / 180.0, 3, false);
}

MagFitUncertainty::Figures MagFitUncertainty::ofEllipse(const std::vector<Eigen::Vector2d> &points, const Ellipse &e)
{
    // The 2-D fit as the x/y block of the 3-D parameters: b_x, b_y, W_xx, W_yy, W_xy.
    Eigen::Matrix3d w = Eigen::Matrix3d::Identity();
    w.topLeftCorner<2, 2>() = e.w;
    std::vector<Vector9d> rows;
    std::vector<double> res;
    rows.reserve(points.size());
    res.reserve(points.size());
    for (const auto &p : points) {
        double r = 0;
        rows.push_back(gradient3(Eigen::Vector3d(p.x(), p.y(), 0.0), Eigen::Vector3d(e.center.x(), e.center.y(), 0.0), w, &r));
        res.push_back(r);
    }
    Basis p = Basis::Zero(kParams, 5);
    const int used[5] = {0, 1, 3, 4, 6};
    for (int i = 0; i < 5; ++i)
        p(used[i], i) = 1;
    Matrix9d cov;
    if (!covariance(rows, res, p, cov))
        return singularFigures();
    return figuresOf(cov, w, 0.0, 2, true);
}

} // namespace imudesk::calib
