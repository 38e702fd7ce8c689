#include "attitude/heading_dial.h"

#include <QEvent>
#include <QPainter>
#include <QPainterPath>
#include <QtMath>

#include <cmath>

namespace imudesk::ui {

namespace {

// Read-outs change in their last shown digit: 0.1 deg heading, 0.01 deg tilt.
bool differs(double a, double b, double resolution)
{
    return std::lround(a / resolution) != std::lround(b / resolution);
}

} // namespace

HeadingDial::HeadingDial(QWidget *parent) : QWidget(parent)
{
    setAttribute(Qt::WA_OpaquePaintEvent);
    setAccessibleName(tr("Heading dial"));
}

void HeadingDial::setAttitude(double headingDeg, double pitchDeg, double rollDeg)
{
    if (!std::isfinite(headingDeg) || !std::isfinite(pitchDeg) || !std::isfinite(rollDeg))
        return;
    double h = std::fmod(headingDeg, 360.0);
    if (h < 0)
        h += 360.0;
    const bool changed = !m_hasData || differs(h, m_heading, 0.1) || differs(pitchDeg, m_pitch, 0.01)
        || differs(rollDeg, m_roll, 0.01);
    m_heading = h;
    m_pitch = pitchDeg;
    m_roll = rollDeg;
    m_hasData = true;
    if (changed)
        update();
}

void HeadingDial::clear()
{
    if (!m_hasData)
        return;
    m_hasData = false;
    update();
}

QString HeadingDial::headingText() const
{
    return m_hasData ? tr("%1°").arg(m_heading, 0, 'f', 1) : tr("no data");
}

QString HeadingDial::tiltText() const
{
    return m_hasData ? tr("pitch %1°  roll %2°").arg(m_pitch, 0, 'f', 2).arg(m_roll, 0, 'f', 2) : QString();
}

void HeadingDial::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange || event->type() == QEvent::PaletteChange)
        update();
    QWidget::changeEvent(event);
}

void HeadingDial::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), palette().window());

    const QFontMetrics fm(font());
    const int textHeight = 2 * fm.height() + 8;
    const double side = std::max(20.0, std::min(double(width()), double(height() - textHeight)) - 8.0);
    const QPointF c(width() / 2.0, 4.0 + side / 2.0);
    const double r = side / 2.0;

    // Card
    const QColor ink = m_hasData ? palette().color(QPalette::WindowText) : palette().color(QPalette::Disabled, QPalette::WindowText);
    p.setPen(QPen(ink, 2));
    p.setBrush(palette().base());
    p.drawEllipse(c, r, r);
    for (int deg = 0; deg < 360; deg += 10) {
        const double a = qDegreesToRadians(double(deg));
        const QPointF dir(std::sin(a), -std::cos(a)); // clockwise from north (up)
        const double inner = deg % 30 == 0 ? r * 0.86 : r * 0.92;
        p.setPen(QPen(ink, deg % 90 == 0 ? 2.5 : 1));
        p.drawLine(c + dir * inner, c + dir * r * 0.98);
    }
    const QString cardinals[4] = {tr("N"), tr("E"), tr("S"), tr("W")};
    QFont bold = font();
    bold.setBold(true);
    p.setFont(bold);
    for (int i = 0; i < 12; ++i) {
        const double a = qDegreesToRadians(i * 30.0);
        const QPointF at = c + QPointF(std::sin(a), -std::cos(a)) * r * 0.72;
        const QString label = i % 3 == 0 ? cardinals[i / 3] : QString::number(i * 30);
        p.setPen(i == 0 && m_hasData ? QColor::fromRgb(kNeedleColor) : ink);
        const QRectF box(at.x() - 20, at.y() - fm.height() / 2.0, 40, fm.height());
        p.drawText(box, Qt::AlignCenter, label);
        if (i == 0)
            p.setFont(font());
    }
    p.setFont(font());

    // Needle: red half towards the heading, grey tail.
    if (m_hasData) {
        p.save();
        p.translate(c);
        p.rotate(m_heading); // QPainter rotates clockwise on screen
        const double len = r * 0.62, w = std::max(3.0, r * 0.07);
        QPainterPath head;
        head.moveTo(0, -len);
        head.lineTo(w, 0);
        head.lineTo(-w, 0);
        head.closeSubpath();
        QPainterPath tail;
        tail.moveTo(0, len * 0.6);
        tail.lineTo(w, 0);
        tail.lineTo(-w, 0);
        tail.closeSubpath();
        p.setPen(Qt::NoPen);
        p.setBrush(QColor::fromRgb(kNeedleColor));
        p.drawPath(head);
        p.setBrush(palette().color(QPalette::Mid));
        p.drawPath(tail);
        p.setBrush(ink);
        p.drawEllipse(QPointF(0, 0), w * 0.6, w * 0.6);
        p.restore();
    }

    // Read-outs
    p.setPen(ink);
    QRectF text(0, c.y() + r + 4, width(), fm.height());
    p.setFont(bold);
    p.drawText(text, Qt::AlignCenter, headingText());
    p.setFont(font());
    text.translate(0, fm.height() + 2);
    p.drawText(text, Qt::AlignCenter, tiltText());
}

} // namespace imudesk::ui
