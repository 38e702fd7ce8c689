#include "calibration/turn_gauge.h"

#include "common/paint_helpers.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace imudesk::ui {

namespace {
const QColor kTurnedColour(0x1f, 0x77, 0xb4);  // blue, as the charts' Z
const QColor kWindowColour(0x2c, 0xa0, 0x2c);  // green: stop here
const QColor kWarningColour(0xd9, 0x7a, 0x00); // orange: outside the band
// Qt's arcs count 1/16 deg counter-clockwise from 3 o'clock; the gauge runs clockwise from 12.
int qtStart(double clockwiseFromTopDeg)
{
    return int(std::lround((90.0 - clockwiseFromTopDeg) * 16.0));
}
int qtSpan(double clockwiseDeg)
{
    return int(std::lround(-clockwiseDeg * 16.0));
}
} // namespace

TurnGauge::TurnGauge(QWidget *parent) : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void TurnGauge::setTarget(double targetDeg, double toleranceDeg)
{
    m_target = std::max(1.0, targetDeg);
    m_tolerance = std::max(0.0, toleranceDeg);
    update();
}

void TurnGauge::setProgress(double angleDeg, double rateDps)
{
    m_angle = std::abs(angleDeg);
    m_rate = std::abs(rateDps);
    m_started = true;
    update();
}

void TurnGauge::setRateBand(double minDps, double maxDps)
{
    m_minRate = minDps;
    m_maxRate = maxDps;
    update();
}

void TurnGauge::clear()
{
    m_angle = 0.0;
    m_rate = 0.0;
    m_started = false;
    update();
}

double TurnGauge::lapDeg() const
{
    if (m_angle <= 0.0)
        return 0.0;
    const double lap = std::fmod(m_angle, 360.0);
    return lap == 0.0 ? 360.0 : lap;
}

bool TurnGauge::inStopWindow() const
{
    return m_started && std::abs(m_angle - m_target) <= m_tolerance;
}

QString TurnGauge::centreText() const
{
    return tr("%1° of %2°").arg(m_angle, 0, 'f', 0).arg(m_target, 0, 'f', 0);
}

QString TurnGauge::detailText() const
{
    const int laps = int(std::ceil(m_target / 360.0 - 1e-9));
    const int lap = std::min(laps, int(m_angle / 360.0) + 1);
    return tr("lap %1 of %2 · %3 deg/s").arg(lap).arg(laps).arg(m_rate, 0, 'f', 0);
}

void TurnGauge::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPalette pal = palette();
    p.fillRect(rect(), pal.color(QPalette::Window));
    const double side = std::min(width(), height()) - 8.0;
    const double ringWidth = std::max(10.0, side * 0.09);
    const QRectF ring(QPointF(width() / 2.0 - side / 2.0 + ringWidth / 2.0, height() / 2.0 - side / 2.0 + ringWidth / 2.0),
                      QSizeF(side - ringWidth, side - ringWidth));
    const QColor ink = pal.color(QPalette::Text);
    const QColor base = pal.color(QPalette::Base);

    // The empty ring, then the stop window at the target's place on the lap.
    p.setPen(QPen(mixColours(base, ink, 0.12), ringWidth, Qt::SolidLine, Qt::FlatCap));
    p.drawArc(ring, 0, 360 * 16);
    const double targetLap = std::fmod(m_target, 360.0);
    QColor window = kWindowColour;
    window.setAlphaF(0.35);
    p.setPen(QPen(window, ringWidth * 1.4, Qt::SolidLine, Qt::FlatCap));
    p.drawArc(ring, qtStart(targetLap - m_tolerance), qtSpan(2.0 * m_tolerance));

    // What is turned: the laps done show as a full ring under the current lap's arc.
    const QColor turned = inStopWindow() ? kWindowColour : kTurnedColour;
    if (m_angle >= 360.0) {
        p.setPen(QPen(mixColours(base, turned, 0.35), ringWidth, Qt::SolidLine, Qt::FlatCap));
        p.drawArc(ring, 0, 360 * 16);
    }
    if (m_angle > 0.0) {
        p.setPen(QPen(turned, ringWidth, Qt::SolidLine, Qt::FlatCap));
        p.drawArc(ring, qtStart(0.0), qtSpan(lapDeg()));
    }
    // The stop mark: a line across the ring at the target.
    p.save();
    p.translate(ring.center());
    p.rotate(targetLap);
    p.setPen(QPen(kWindowColour.darker(130), 3.0, Qt::SolidLine, Qt::FlatCap));
    p.drawLine(QPointF(0, -ring.height() / 2.0 - ringWidth * 0.8), QPointF(0, -ring.height() / 2.0 + ringWidth * 0.8));
    p.restore();

    // The figures in the middle.
    QFont big = font();
    big.setPointSizeF(big.pointSizeF() * std::clamp(side / 180.0, 1.2, 2.6));
    big.setBold(true);
    p.setFont(big);
    p.setPen(inStopWindow() ? kWindowColour.darker(120) : ink);
    const QRectF inner = ring.adjusted(ringWidth, ringWidth, -ringWidth, -ringWidth);
    const QRectF top(inner.left(), inner.top(), inner.width(), inner.height() * 0.55);
    p.drawText(top, Qt::AlignHCenter | Qt::AlignBottom, centreText());
    QFont small = font();
    small.setPointSizeF(small.pointSizeF() * std::clamp(side / 260.0, 1.0, 1.6));
    p.setFont(small);
    const bool rateOk = !m_started || (m_rate >= m_minRate && m_rate <= m_maxRate);
    p.setPen(rateOk ? ink : kWarningColour);
    const QRectF bottom(inner.left(), inner.top() + inner.height() * 0.58, inner.width(), inner.height() * 0.3);
    p.drawText(bottom, Qt::AlignHCenter | Qt::AlignTop, detailText());
}

} // namespace imudesk::ui
