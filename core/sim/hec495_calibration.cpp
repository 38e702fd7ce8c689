#include "hec495_calibration.h"

#include <Eigen/Dense>

#include <cmath>
#include <numbers>

namespace imudesk::sim {

namespace {

constexpr int kBands = 8;
constexpr int kSectors = 12;

double headingDiff(double a, double b)
{
    double d = std::fmod(a - b, 360.0);
    if (d > 180)
        d -= 360;
    if (d < -180)
        d += 360;
    return std::fabs(d);
}

int slotCount(Hec495Calibration::Method m)
{
    using M = Hec495Calibration::Method;
    switch (m) {
    case M::Auto12:
    case M::SmallTilt12:
    case M::Planar:
        return 12;
    case M::AllOrientation:
        return kBands * kSectors;
    case M::Manual:
        return 0;
    }
    return 0;
}

} // namespace

void Hec495Calibration::start(Method m)
{
    m_method = m;
    m_points.clear();
    m_taken.assign(size_t(slotCount(m)), false);
}

void Hec495Calibration::stop()
{
    m_method.reset();
    m_points.clear();
    m_taken.clear();
}

int Hec495Calibration::minimumPoints(Method m)
{
    switch (m) {
    case Method::Manual:
    case Method::AllOrientation:
        return 12;
    case Method::Auto12:
    case Method::SmallTilt12:
        return 6;
    case Method::Planar:
        return 4;
    }
    return 12;
}

int Hec495Calibration::tableSlot(Method m, const Pose &p)
{
    if (m != Method::Auto12 && m != Method::SmallTilt12)
        return -1;
    // Tables 1 and 4: slot i has heading 0, 90, 180, 270, 30, 120, 210, 300, 60, 150, 240, 330;
    // pitch level (1-4), up (5-8), down (9-12); roll alternates +/- (table 1) or is level (table 4).
    static constexpr std::array<double, 12> kHeading{0, 90, 180, 270, 30, 120, 210, 300, 60, 150, 240, 330};
    for (int i = 0; i < 12; ++i) {
        if (headingDiff(p.heading, kHeading[size_t(i)]) > kHeadingToleranceDeg)
            continue;
        const bool pitchOk = i < 4 ? std::fabs(p.pitch) <= 5.0 : (i < 8 ? p.pitch > 45.0 : p.pitch < -45.0);
        if (!pitchOk)
            continue;
        bool rollOk;
        if (m == Method::SmallTilt12)
            rollOk = std::fabs(p.roll) <= 5.0;
        else
            rollOk = (i % 2 == 0) ? (p.roll >= 30.0 && p.roll <= 40.0) : (p.roll <= -30.0 && p.roll >= -40.0);
        if (rollOk)
            return i;
    }
    return -1;
}

int Hec495Calibration::slotFor(const Pose &p, const Eigen::Vector3d &rawMag) const
{
    switch (*m_method) {
    case Method::Auto12:
    case Method::SmallTilt12:
        return tableSlot(*m_method, p);
    case Method::Planar:
        if (std::fabs(p.pitch) > kPlanarTiltDeg || std::fabs(p.roll) > kPlanarTiltDeg)
            return -1;
        return int(std::floor(std::fmod(p.heading + 360.0, 360.0) / 30.0)) % 12;
    case Method::AllOrientation: {
        const double n = rawMag.norm();
        if (n <= 0)
            return -1;
        const Eigen::Vector3d u = rawMag / n;
        const int band = std::min(kBands - 1, int((u.z() + 1.0) / 2.0 * kBands));
        const double az = std::atan2(u.y(), u.x()) * 180.0 / std::numbers::pi + 180.0;
        const int sector = std::min(kSectors - 1, int(az / (360.0 / kSectors)));
        return band * kSectors + sector;
    }
    case Method::Manual:
        return -1;
    }
    return -1;
}

bool Hec495Calibration::offer(const Pose &pose, const Eigen::Vector3d &rawMag)
{
    if (!m_method || *m_method == Method::Manual)
        return false;
    const int slot = slotFor(pose, rawMag);
    if (slot < 0 || size_t(slot) >= m_taken.size() || m_taken[size_t(slot)])
        return false;
    m_taken[size_t(slot)] = true;
    m_points.push_back(rawMag);
    return true;
}

bool Hec495Calibration::collect(const Eigen::Vector3d &rawMag)
{
    if (!m_method || int(m_points.size()) >= kMaxPoints)
        return false;
    m_points.push_back(rawMag);
    return true;
}

std::optional<Hec495Calibration::Result> Hec495Calibration::finish()
{
    if (!m_method)
        return std::nullopt;
    const Method m = *m_method;
    const std::vector<Eigen::Vector3d> pts = m_points;
    stop();
    const int n = int(pts.size());
    if (n < minimumPoints(m))
        return std::nullopt;
    const bool planar = m == Method::Planar;
    const int unknowns = planar ? 3 : 4;
    Eigen::MatrixXd a(n, unknowns);
    Eigen::VectorXd b(n);
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d &p = pts[size_t(i)];
        if (planar) {
            a.row(i) << 2 * p.x(), 2 * p.y(), 1.0;
            b(i) = p.x() * p.x() + p.y() * p.y();
        } else {
            a.row(i) << 2 * p.x(), 2 * p.y(), 2 * p.z(), 1.0;
            b(i) = p.squaredNorm();
        }
    }
    const auto qr = a.colPivHouseholderQr();
    if (qr.rank() < unknowns)
        return std::nullopt;
    const Eigen::VectorXd x = qr.solve(b);
    Result r;
    r.hardIron = planar ? Eigen::Vector3d(x(0), x(1), 0) : Eigen::Vector3d(x(0), x(1), x(2));
    const double k = x(unknowns - 1);
    const double r2 = k + (planar ? r.hardIron.head<2>().squaredNorm() : r.hardIron.squaredNorm());
    if (!(r2 > 0))
        return std::nullopt;
    r.radius = std::sqrt(r2);
    double sum = 0;
    for (const auto &p : pts) {
        const Eigen::Vector3d d = p - r.hardIron;
        const double len = planar ? d.head<2>().norm() : d.norm();
        sum += (len - r.radius) * (len - r.radius);
    }
    r.fitError = float(100.0 * std::sqrt(sum / n) / r.radius);
    r.points = n;
    return r;
}

} // namespace imudesk::sim
