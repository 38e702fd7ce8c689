#include "calib/mag_environment_judge.h"

#include "calib/sphere_coverage.h"

#include <algorithm>
#include <cmath>

namespace imudesk::calib {

namespace {
constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
constexpr size_t kMaxStillEntries = 20000; // a long still stretch at 1 kHz: bounded all the same

double percentile(std::vector<double> &v, double p)
{
    const size_t k = std::min(v.size() - 1, size_t(std::lround(p * double(v.size() - 1))));
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
    return v[k];
}
} // namespace

MagEnvironmentJudge::MagEnvironmentJudge() = default;

MagEnvironmentJudge::MagEnvironmentJudge(Options options)
    : m_options(options)
{
}

void MagEnvironmentJudge::reset()
{
    *this = MagEnvironmentJudge(m_options);
}

void MagEnvironmentJudge::add(double timeMs, const Eigen::Vector3d &rawUt, const std::optional<Eigen::Vector3d> &gyroDps)
{
    if (!rawUt.allFinite() || !std::isfinite(timeMs))
        return;
    const double b = rawUt.norm();
    ++m_count;
    m_rawSum += b;
    m_lastRaw = b;
    trackStillness(timeMs, b, gyroDps);
    // A module held still would fill the fit with one point: a sample joins when it points
    // somewhere new.
    const bool apart = m_points.empty()
        || rawUt.normalized().dot(m_points.back().normalized()) < std::cos(m_options.minSeparationDeg * kDegToRad);
    if (!apart || b <= 0)
        return;
    if (m_points.size() >= kMaxSamples)
        m_points.erase(m_points.begin()); // the oldest orientation gives way
    m_points.push_back(rawUt);
    if (++m_keptSinceFit >= 10) // a fit per ten new orientations: a few a second while turning
        fit();
}

void MagEnvironmentJudge::trackStillness(double timeMs, double fieldUt, const std::optional<Eigen::Vector3d> &gyroDps)
{
    m_stillNow = gyroDps && gyroDps->allFinite() && gyroDps->norm() < m_options.stillGyroDps;
    if (!m_stillNow) {
        m_still.clear();
        return;
    }
    m_still.emplace_back(timeMs, fieldUt);
    if (m_still.size() > kMaxStillEntries)
        m_still.pop_front();
    const double first = m_still.front().first;
    if (timeMs - first < m_options.stillMinMs)
        return;
    // The mean |B| over the first and the newest averageMs of the stretch: noise averages out,
    // a change of the surroundings does not.
    double headSum = 0, tailSum = 0;
    int head = 0, tail = 0;
    for (const auto &[t, v] : m_still) {
        if (t - first <= m_options.averageMs) {
            headSum += v;
            ++head;
        }
        if (timeMs - t <= m_options.averageMs) {
            tailSum += v;
            ++tail;
        }
    }
    if (head > 0 && tail > 0)
        m_stillChangeMax = std::max(m_stillChangeMax, std::abs(tailSum / tail - headSum / head));
}

void MagEnvironmentJudge::fit()
{
    m_keptSinceFit = 0;
    // Coverage around the centre found so far (the mean of the points before any fit).
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    if (m_fit) {
        centre = m_fit->center;
    } else {
        for (const auto &p : m_points)
            centre += p;
        centre /= double(m_points.size());
    }
    SphereCoverage coverage;
    for (const auto &p : m_points)
        coverage.add(p - centre);
    m_covered = coverage.coveredCells();
    if (coverage.coveredCells() < m_options.minCellsForFit || int(m_points.size()) < EllipsoidFit::kMinPoints) {
        m_fit.reset();
        return;
    }
    std::optional<Ellipsoid> e;
    bool ellipsoid = false;
    if (coverage.coveredCells() >= m_options.minCellsForEllipsoid) {
        e = EllipsoidFit::algebraicLi(m_points);
        ellipsoid = e && std::isfinite(e->radius()) && e->radius() > 0;
    }
    if (!ellipsoid) {
        const auto s = EllipsoidFit::sphere(m_points);
        if (!s || !(s->second > 0)) {
            m_fit.reset();
            return;
        }
        e = Ellipsoid{s->first, Eigen::Matrix3d::Identity() / s->second};
    }
    m_fit = e;
    m_fitIsEllipsoid = ellipsoid;
    std::vector<double> fields;
    fields.reserve(m_points.size());
    for (const auto &p : m_points)
        fields.push_back(m_fit->correct(p).norm());
    m_spread = percentile(fields, 0.95) - percentile(fields, 0.05);
}

std::optional<double> MagEnvironmentJudge::fittedFieldUt() const
{
    return m_fit ? std::optional<double>(m_fit->radius()) : std::nullopt;
}

std::optional<double> MagEnvironmentJudge::moduleIronUt() const
{
    return m_fit ? std::optional<double>(m_fit->center.norm()) : std::nullopt;
}

std::optional<double> MagEnvironmentJudge::spreadUt() const
{
    return m_fit ? std::optional<double>(m_spread) : std::nullopt;
}

MagEnvironmentJudge::Status MagEnvironmentJudge::status() const
{
    if (m_stillChangeMax > m_options.maxStillChangeUt)
        return Status::FieldChanging;
    // A sphere fit on a few orientations is a first estimate (on 10 cells of a tumbling module
    // it read 59 µT for 50): only the ellipsoid, on a quarter of the sphere or more, is judged.
    if (!m_fit || !m_fitIsEllipsoid)
        return Status::TurnMore;
    const double field = m_fit->radius();
    if (field < m_options.minFieldUt || field > m_options.maxFieldUt)
        return Status::FieldOutOfRange;
    if (m_spread > m_options.maxSpreadUt)
        return Status::SpatialInterference;
    return Status::Ok;
}

QString MagEnvironmentJudge::advice() const
{
    const auto uT = [](double v) { return QString::number(v, 'f', 1); };
    switch (status()) {
    case Status::FieldChanging:
        return tr("|B| changed by %1 µT while the module was still: something near it moves or switches (a magnet, "
                  "a motor, a current). Remove it or choose another place.")
            .arg(uT(m_stillChangeMax));
    case Status::TurnMore:
        if (!m_fit)
            return tr("Turn the module slowly to many orientations at the calibration spot: the field has pointed "
                      "into %1 % of the sphere so far. The raw |B| (%2 µT now) includes the module's own iron, which "
                      "the calibration removes, so it is not judged by itself.")
                .arg(coveragePercent(), 0, 'f', 0)
                .arg(uT(m_lastRaw));
        return tr("So far the field here is about %1 µT once the module's own iron (%2 µT) is taken out. Keep "
                  "turning (%3 % of the sphere) for the full check.")
            .arg(uT(m_fit->radius()), uT(m_fit->center.norm()))
            .arg(coveragePercent(), 0, 'f', 0);
    case Status::Ok:
        return tr("The field here is %1 µT once the module's own iron (%2 µT) is taken out: within the Earth's "
                  "%3..%4 µT, and the same in every orientation within %5 µT. You can calibrate here.")
            .arg(uT(m_fit->radius()), uT(m_fit->center.norm()))
            .arg(m_options.minFieldUt, 0, 'f', 0)
            .arg(m_options.maxFieldUt, 0, 'f', 0)
            .arg(uT(m_spread));
    case Status::FieldOutOfRange:
        return tr("The field here is %1 µT once the module's own iron (%2 µT) is taken out, outside the Earth's "
                  "%3..%4 µT: a magnetic object or a steel structure is near. Move away from it, or choose another "
                  "place.")
            .arg(uT(m_fit->radius()), uT(m_fit->center.norm()))
            .arg(m_options.minFieldUt, 0, 'f', 0)
            .arg(m_options.maxFieldUt, 0, 'f', 0);
    case Status::SpatialInterference:
        return tr("Once the module's own iron is taken out, the field still differs by %1 µT between orientations "
                  "(more than %2 µT): it is not uniform here. Choose another place (outdoors, away from buildings "
                  "and vehicles), or use 6-axis mode.")
            .arg(uT(m_spread))
            .arg(m_options.maxSpreadUt, 0, 'f', 0);
    }
    return {};
}

} // namespace imudesk::calib
