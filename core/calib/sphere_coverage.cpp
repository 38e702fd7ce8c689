#include "calib/sphere_coverage.h"

#include <Eigen/Geometry>

#include <algorithm>

#include <cmath>

namespace imudesk::calib {

namespace {

std::array<SphereCoverage::Cell, SphereCoverage::kCells> buildCells()
{
    const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<Eigen::Vector3d> v;
    for (int s1 : {-1, 1})
        for (int s2 : {-1, 1}) {
            v.emplace_back(0, s1, s2 * phi);
            v.emplace_back(s1, s2 * phi, 0);
            v.emplace_back(s2 * phi, 0, s1);
        }
    // Faces: the vertex triples with all three edges of length 2.
    std::vector<std::array<Eigen::Vector3d, 3>> faces;
    auto edge = [](const Eigen::Vector3d &a, const Eigen::Vector3d &b) { return std::fabs((a - b).norm() - 2.0) < 1e-9; };
    for (size_t i = 0; i < v.size(); ++i)
        for (size_t j = i + 1; j < v.size(); ++j)
            for (size_t k = j + 1; k < v.size(); ++k)
                if (edge(v[i], v[j]) && edge(v[j], v[k]) && edge(v[i], v[k]))
                    faces.push_back({v[i].normalized(), v[j].normalized(), v[k].normalized()});
    std::array<SphereCoverage::Cell, SphereCoverage::kCells> cells;
    size_t n = 0;
    for (const auto &f : faces) {
        const Eigen::Vector3d ab = (f[0] + f[1]).normalized();
        const Eigen::Vector3d bc = (f[1] + f[2]).normalized();
        const Eigen::Vector3d ca = (f[2] + f[0]).normalized();
        const std::array<std::array<Eigen::Vector3d, 3>, 4> parts{{{f[0], ab, ca}, {ab, f[1], bc}, {ca, bc, f[2]}, {ab, bc, ca}}};
        for (const auto &p : parts) {
            if (n >= cells.size())
                break;
            cells[n].corner = p;
            cells[n].centre = (p[0] + p[1] + p[2]).normalized();
            ++n;
        }
    }
    return cells;
}

} // namespace

const std::array<SphereCoverage::Cell, SphereCoverage::kCells> &SphereCoverage::cells()
{
    static const std::array<Cell, kCells> c = buildCells();
    return c;
}

int SphereCoverage::cellOf(const Eigen::Vector3d &d)
{
    const double n = d.norm();
    if (!(n > 0) || !std::isfinite(n))
        return -1;
    const Eigen::Vector3d u = d / n;
    int best = 0;
    double bestDot = -2;
    const auto &c = cells();
    for (int i = 0; i < kCells; ++i) {
        const double dot = c[size_t(i)].centre.dot(u);
        if (dot > bestDot) {
            bestDot = dot;
            best = i;
        }
    }
    return best;
}

void SphereCoverage::clear()
{
    m_counts.fill(0);
    m_covered = 0;
}

bool SphereCoverage::add(const Eigen::Vector3d &direction)
{
    const int c = cellOf(direction);
    if (c < 0)
        return false;
    if (m_counts[size_t(c)]++ == 0) {
        ++m_covered;
        return true;
    }
    return false;
}

void SphereCoverage::addAll(const std::vector<Eigen::Vector3d> &directions)
{
    for (const auto &d : directions)
        add(d);
}

Eigen::Vector3d SphereCoverage::missingDirection() const
{
    if (m_covered == 0 || m_covered == kCells)
        return Eigen::Vector3d::Zero();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int i = 0; i < kCells; ++i)
        if (m_counts[size_t(i)] == 0)
            sum += cells()[size_t(i)].centre;
    if (sum.norm() < 1e-9) {
        // Empty cells spread evenly (e.g. a band): point at the first one.
        for (int i = 0; i < kCells; ++i)
            if (m_counts[size_t(i)] == 0)
                return cells()[size_t(i)].centre;
    }
    return sum.normalized();
}

double SphereCoverage::largestGapDeg() const
{
    if (m_covered == 0)
        return 180.0;
    double worstCos = 1.0; // the cosine from the empty cell furthest from coverage to its nearest covered cell
    for (int i = 0; i < kCells; ++i) {
        if (m_counts[size_t(i)] > 0)
            continue;
        double nearest = -1.0;
        for (int j = 0; j < kCells; ++j)
            if (m_counts[size_t(j)] > 0)
                nearest = std::max(nearest, cells()[size_t(i)].centre.dot(cells()[size_t(j)].centre));
        worstCos = std::min(worstCos, nearest);
    }
    return std::acos(std::clamp(worstCos, -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
}

QString SphereCoverage::missingRotationHint() const
{
    if (m_covered == kCells)
        return {};
    if (m_covered == 0)
        return tr("Turn the module slowly about each of its axes: no direction is covered yet");
    const Eigen::Vector3d d = missingDirection();
    int axis = 0;
    d.cwiseAbs().maxCoeff(&axis);
    const QString names[3] = {QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")};
    const QString sign = d[axis] >= 0 ? QStringLiteral("+") : QStringLiteral("-");
    return tr("Turn the module so that its %1%2 axis points along the magnetic field (towards north and, in the "
              "northern hemisphere, down)")
        .arg(sign, names[axis]);
}

} // namespace imudesk::calib
