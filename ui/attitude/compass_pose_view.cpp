#include "attitude/compass_pose_view.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace imudesk::ui {

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

// Distance from the centre for a pitch: +90 (nose up) inside, level in the middle, -90 outside.
double ringOf(double pitchDeg, double radius)
{
    const double p = std::clamp(pitchDeg, -90.0, 90.0);
    return radius * (0.62 - 0.32 * p / 90.0);
}

QPointF at(QPointF centre, double headingDeg, double r)
{
    const double a = headingDeg * kDegToRad;
    return {centre.x() + r * std::sin(a), centre.y() - r * std::cos(a)};
}

} // namespace

CompassPoseView::CompassPoseView(QWidget *parent) : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void CompassPoseView::setTracker(const calib::CompassPoseTracker *tracker)
{
    m_tracker = tracker;
    update();
}

void CompassPoseView::setPose(std::optional<Pose> pose)
{
    m_pose = pose;
    update();
}

void CompassPoseView::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPalette pal = palette();
    p.fillRect(rect(), pal.base());

    const double barH = 44;
    const double side = std::max(40.0, std::min<double>(width(), height() - barH));
    const double radius = side / 2 - 18;
    const QPointF c(width() / 2.0, side / 2.0);

    // Rose: rings of the pitch bands and heading ticks.
    p.setPen(QPen(pal.mid().color(), 1));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(c, radius, radius);
    for (double pitch : {60.0, 0.0, -60.0})
        p.drawEllipse(c, ringOf(pitch, radius), ringOf(pitch, radius));
    for (int h = 0; h < 360; h += 30)
        p.drawLine(at(c, h, radius - 6), at(c, h, radius));
    p.setPen(pal.text().color());
    const QString card[4] = {tr("N"), tr("E"), tr("S"), tr("W")};
    for (int i = 0; i < 4; ++i) {
        const QPointF q = at(c, 90.0 * i, radius + 10);
        p.drawText(QRectF(q.x() - 10, q.y() - 9, 20, 18), Qt::AlignCenter, card[i]);
    }

    if (m_tracker && !m_tracker->poseTargets().empty()) {
        const auto &targets = m_tracker->poseTargets();
        const double dot = std::max(7.0, radius * 0.075);
        QFont small = font();
        small.setPointSizeF(std::max(6.0, small.pointSizeF() * 0.75));
        const bool showRoll = m_tracker->method() == calib::CompassCalMethod::Auto12;
        for (size_t i = 0; i < targets.size(); ++i) {
            const auto &t = targets[i];
            const QPointF q = at(c, t.headingDeg, ringOf((t.pitchMinDeg + t.pitchMaxDeg) / 2, radius));
            const bool lit = m_tracker->collected(int(i));
            const bool current = m_tracker->currentTarget() == int(i);
            p.setBrush(lit ? QColor(40, 170, 70) : pal.window().color());
            p.setPen(QPen(current ? QColor(230, 140, 0) : pal.dark().color(), current ? 3 : 1));
            p.drawEllipse(q, dot, dot);
            p.setPen(lit ? Qt::white : pal.text().color());
            p.setFont(small);
            p.drawText(QRectF(q.x() - dot, q.y() - dot, 2 * dot, 2 * dot), Qt::AlignCenter,
                       QString::number(t.number));
            if (showRoll) {
                p.setPen(pal.text().color());
                const double roll = (t.rollMinDeg + t.rollMaxDeg) / 2;
                p.drawText(QRectF(q.x() + dot, q.y() - dot, 4 * dot, 2 * dot), Qt::AlignVCenter | Qt::AlignLeft,
                           tr("R%1").arg(roll, 0, 'f', 0));
            }
        }
        p.setFont(font());
    } else if (m_tracker) {
        // No table: the point count as a ring.
        const double pct = m_tracker->progressPct();
        p.setPen(QPen(QColor(40, 170, 70), 6, Qt::SolidLine, Qt::FlatCap));
        p.drawArc(QRectF(c.x() - radius + 4, c.y() - radius + 4, 2 * radius - 8, 2 * radius - 8), 90 * 16,
                  -int(pct / 100.0 * 360 * 16));
        p.setPen(pal.text().color());
        p.drawText(QRectF(c.x() - radius, c.y() + radius * 0.25, 2 * radius, 24), Qt::AlignCenter,
                   tr("%n point(s)", nullptr, m_tracker->validPoints()));
    }

    // Live pose: needle at the heading, dot at the pitch; roll bar below the rose.
    const QRectF bar(18, side + 8, width() - 36, 12);
    p.setPen(QPen(pal.mid().color(), 1));
    p.setBrush(Qt::NoBrush);
    p.drawRect(bar);
    auto rollX = [&bar](double roll) { return bar.left() + bar.width() * (std::clamp(roll, -90.0, 90.0) + 90) / 180; };
    p.drawLine(QPointF(rollX(0), bar.top()), QPointF(rollX(0), bar.bottom()));
    if (m_tracker && m_tracker->currentTarget() >= 0) {
        const auto &t = m_tracker->poseTargets()[size_t(m_tracker->currentTarget())];
        p.fillRect(QRectF(QPointF(rollX(t.rollMinDeg), bar.top()), QPointF(rollX(t.rollMaxDeg), bar.bottom())),
                   QColor(230, 140, 0, 90));
    }
    if (!m_pose) {
        p.setPen(pal.text().color());
        p.drawText(QRectF(0, bar.bottom() + 2, width(), 20), Qt::AlignCenter, tr("No attitude received yet"));
        return;
    }
    const Pose &pose = *m_pose;
    p.setPen(QPen(QColor(200, 40, 40), 2));
    p.drawLine(c, at(c, pose.heading, radius));
    p.setBrush(QColor(30, 90, 200));
    p.setPen(Qt::NoPen);
    p.drawEllipse(at(c, pose.heading, ringOf(pose.pitch, radius)), 5, 5);
    p.drawRect(QRectF(rollX(pose.roll) - 2, bar.top() - 3, 4, bar.height() + 6));
    p.setPen(pal.text().color());
    p.drawText(QRectF(0, bar.bottom() + 2, width(), 20), Qt::AlignCenter,
               tr("Heading %1°  pitch %2°  roll %3°")
                   .arg(pose.heading, 0, 'f', 1)
                   .arg(pose.pitch, 0, 'f', 1)
                   .arg(pose.roll, 0, 'f', 1));
}

} // namespace imudesk::ui
