#include "calibration/mag_sphere_view.h"

#include <Eigen/Geometry>

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <array>
#include <cmath>

namespace imudesk::ui {

namespace {
constexpr double kDeg = 0.017453292519943295;
}

MagSphereView::MagSphereView(QWidget *parent)
    : QWidget(parent)
{
    setMouseTracking(false);
    setToolTip(tr("Magnetometer samples on a sphere: cells turn green as the field directions cover them. Drag to "
                  "turn the view, double-click to reset it."));
}

void MagSphereView::clear()
{
    m_samples.clear();
    m_total = 0;
    m_sum.setZero();
    m_coverage.clear();
    m_showsRun = false;
    m_lastField = 0;
    update();
}

Eigen::Vector3d MagSphereView::corrected(const Eigen::Vector3d &m) const
{
    if (m_calibrated)
        return m_softIron * (m - m_hardIron);
    const Eigen::Vector3d centre = m_samples.empty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(m_sum / double(m_samples.size()));
    return m - centre;
}

void MagSphereView::rebuild()
{
    m_coverage.clear();
    for (const auto &s : m_samples)
        m_coverage.add(corrected(s));
    if (!m_samples.empty())
        m_lastField = m_calibrated ? corrected(m_samples.back()).norm() : m_samples.back().norm();
    update();
}

void MagSphereView::addSample(const Eigen::Vector3d &magUt)
{
    if (!magUt.allFinite())
        return;
    if (m_samples.size() >= kMaxSamples) {
        std::vector<Eigen::Vector3d> kept;
        kept.reserve(kMaxSamples / 2 + 1);
        for (size_t i = 0; i < m_samples.size(); i += 2)
            kept.push_back(m_samples[i]);
        m_samples.swap(kept);
        m_sum.setZero();
        for (const auto &s : m_samples)
            m_sum += s;
    }
    m_samples.push_back(magUt);
    ++m_total;
    m_sum += magUt;
    m_lastField = m_calibrated ? corrected(magUt).norm() : magUt.norm();
    if (m_calibrated) {
        m_coverage.add(corrected(magUt));
        update();
    } else if (m_samples.size() % 16 == 1 || m_samples.size() < 64) {
        rebuild(); // the centre moves while samples come in
    } else {
        m_coverage.add(corrected(magUt));
        update();
    }
}

void MagSphereView::setSamples(const std::vector<Eigen::Vector3d> &magUt)
{
    // Every sample, not the first kMaxSamples: the cells must be those the whole run covered
    // (the painter thins the dots itself).
    m_samples.clear();
    m_samples.reserve(magUt.size());
    m_sum.setZero();
    for (const auto &m : magUt)
        if (m.allFinite()) {
            m_samples.push_back(m);
            m_sum += m;
        }
    m_total = m_samples.size();
    rebuild();
}

void MagSphereView::showRun(const calib::MagCalResult &result)
{
    m_run = result;
    m_showsRun = true;
    update();
}

QString MagSphereView::readoutText() const
{
    if (!m_showsRun)
        return tr("|B| %1 µT   coverage %2 %   %3 samples")
                   .arg(m_lastField, 0, 'f', 1)
                   .arg(m_coverage.percent(), 0, 'f', 0)
                   .arg(m_total)
            + QLatin1Char('\n') + hint();
    // The run's own figures, as its result states them. The coverage is that of the corrected
    // directions: a raw view (no usable correction) centres the samples elsewhere, so it
    // gives only the count.
    if (!m_calibrated)
        return tr("%1 samples, raw (no usable correction)").arg(m_run.samples);
    QString text = tr("%1 samples   coverage %2 %").arg(m_run.samples).arg(m_run.coveragePct, 0, 'f', 0);
    if (std::isfinite(m_run.predictedHeadingErrorDeg))
        text += QLatin1Char('\n')
            + tr("Predicted heading error %1°").arg(m_run.predictedHeadingErrorDeg, 0, 'f', 2);
    return text;
}

void MagSphereView::setCalibration(const Eigen::Vector3d &hardIron, const Eigen::Matrix3d &softIron)
{
    m_calibrated = true;
    m_hardIron = hardIron;
    m_softIron = softIron;
    rebuild();
}

void MagSphereView::clearCalibration()
{
    m_calibrated = false;
    rebuild();
}

void MagSphereView::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), palette().color(QPalette::Base));
    const double size = std::min(width(), height() - 48);
    if (size < 40)
        return;
    const QPointF centre(width() / 2.0, 8 + size / 2.0);
    const double radius = size * 0.42;
    const Eigen::Matrix3d view = (Eigen::AngleAxisd(-m_elevationDeg * kDeg, Eigen::Vector3d::UnitX())
                                  * Eigen::AngleAxisd(-m_azimuthDeg * kDeg, Eigen::Vector3d::UnitZ()))
                                     .toRotationMatrix();
    // Screen: x right, y up (sensor z up before the view turns), depth = -y of the turned frame.
    auto project = [&](const Eigen::Vector3d &v, double *depth) {
        const Eigen::Vector3d r = view * v;
        if (depth)
            *depth = r.y();
        return QPointF(centre.x() + radius * r.x(), centre.y() - radius * r.z());
    };

    const auto &cells = calib::SphereCoverage::cells();
    std::array<int, calib::SphereCoverage::kCells> order{};
    std::array<double, calib::SphereCoverage::kCells> depth{};
    for (int i = 0; i < calib::SphereCoverage::kCells; ++i) {
        order[size_t(i)] = i;
        project(cells[size_t(i)].centre, &depth[size_t(i)]);
    }
    // Far cells first (larger depth is further away).
    std::sort(order.begin(), order.end(), [&](int a, int b) { return depth[size_t(a)] > depth[size_t(b)]; });
    const QColor covered(46, 160, 67), empty(150, 150, 150);
    for (int i : order) {
        const auto &c = cells[size_t(i)];
        QPainterPath path;
        path.moveTo(project(c.corner[0], nullptr));
        path.lineTo(project(c.corner[1], nullptr));
        path.lineTo(project(c.corner[2], nullptr));
        path.closeSubpath();
        const bool front = depth[size_t(i)] < 0;
        QColor fill = m_coverage.covered(i) ? covered : empty;
        fill.setAlpha(front ? (m_coverage.covered(i) ? 170 : 40) : 25);
        p.setBrush(fill);
        QColor edge = palette().color(QPalette::Text);
        edge.setAlpha(front ? 90 : 30);
        p.setPen(QPen(edge, 0.8));
        p.drawPath(path);
    }
    // Samples: direction on the sphere, scaled by |c| relative to the mean radius.
    double meanR = 0;
    for (const auto &s : m_samples)
        meanR += corrected(s).norm();
    meanR = m_samples.empty() ? 1 : meanR / double(m_samples.size());
    p.setPen(Qt::NoPen);
    const size_t step = std::max<size_t>(1, m_samples.size() / 1500);
    for (size_t k = 0; k < m_samples.size(); k += step) {
        const Eigen::Vector3d c = corrected(m_samples[k]) / std::max(meanR, 1e-9);
        double d = 0;
        const QPointF pt = project(c, &d);
        p.setBrush(d < 0 ? QColor(220, 90, 30) : QColor(220, 90, 30, 70));
        p.drawEllipse(pt, 2.2, 2.2);
    }
    // Missing direction marker.
    const Eigen::Vector3d miss = m_coverage.missingDirection();
    if (!miss.isZero()) {
        double d = 0;
        const QPointF pt = project(miss * 1.12, &d);
        p.setPen(QPen(QColor(200, 40, 40), 2));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(pt, 7, 7);
    }
    // Read-outs.
    p.setPen(palette().color(QPalette::Text));
    const QRectF text(6, height() - 44, width() - 12, 42);
    p.drawText(text, Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, readoutText());
}

void MagSphereView::mousePressEvent(QMouseEvent *event)
{
    m_dragFrom = event->position().toPoint();
}

void MagSphereView::mouseMoveEvent(QMouseEvent *event)
{
    if (!(event->buttons() & Qt::LeftButton))
        return;
    const QPoint d = event->position().toPoint() - m_dragFrom;
    m_dragFrom = event->position().toPoint();
    m_azimuthDeg = std::fmod(m_azimuthDeg + d.x() * 0.5, 360.0);
    m_elevationDeg = std::clamp(m_elevationDeg + d.y() * 0.5, -89.0, 89.0);
    update();
}

void MagSphereView::mouseDoubleClickEvent(QMouseEvent *)
{
    m_azimuthDeg = 30;
    m_elevationDeg = 20;
    update();
}

} // namespace imudesk::ui
