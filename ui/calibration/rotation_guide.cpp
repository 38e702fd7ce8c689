#include "calibration/rotation_guide.h"

#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>

#include <array>
#include <cmath>

namespace imudesk::ui {

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Vec {
    double x, y, z;
};

// Isometric view with Z up: +X to the lower right, +Y to the lower left (the 3D attitude view's
// viewer stands on the +X +Y side, looking down a little).
QPointF project(const Vec &v, const QPointF &centre, double scale)
{
    const double c = std::cos(kPi / 6), s = std::sin(kPi / 6);
    return centre + QPointF((v.x - v.y) * c * scale, ((v.x + v.y) * s - v.z) * scale);
}

QColor axisColour(int axis)
{
    static const std::array<QColor, 3> colours = {QColor(0xd6, 0x27, 0x28), QColor(0x2c, 0xa0, 0x2c),
                                                  QColor(0x1f, 0x77, 0xb4)};
    return colours[size_t(axis)];
}

// A point on a circle of radius r about `axis`, at angle t.
Vec onCircle(int axis, double r, double t)
{
    const double a = r * std::cos(t), b = r * std::sin(t);
    switch (axis) {
    case 0: return {0, a, b};
    case 1: return {b, 0, a};
    default: return {a, b, 0};
    }
}

void drawModule(QPainter &p, const QPointF &centre, double scale, const QPalette &palette)
{
    const double a = 1.0, b = 0.7, h = 0.18; // half sizes: a flat board
    auto pt = [&](double x, double y, double z) { return project({x, y, z}, centre, scale); };
    const QColor body = palette.color(QPalette::Mid);
    p.setPen(QPen(palette.color(QPalette::Shadow), 1));
    p.setBrush(body.darker(115));
    p.drawPolygon(QPolygonF({pt(a, -b, h), pt(a, b, h), pt(a, b, -h), pt(a, -b, -h)})); // +X side
    p.setBrush(body.darker(130));
    p.drawPolygon(QPolygonF({pt(-a, b, h), pt(a, b, h), pt(a, b, -h), pt(-a, b, -h)})); // +Y side
    p.setBrush(body.lighter(115));
    p.drawPolygon(QPolygonF({pt(-a, -b, h), pt(a, -b, h), pt(a, b, h), pt(-a, b, h)})); // top
}

void drawAxes(QPainter &p, const QPointF &centre, double scale, int highlighted)
{
    static const char *names[3] = {"X", "Y", "Z"};
    const std::array<Vec, 3> tips = {Vec{1.55, 0, 0}, Vec{0, 1.25, 0}, Vec{0, 0, 1.05}};
    for (int axis = 0; axis < 3; ++axis) {
        const QPointF o = project({0, 0, 0.18}, centre, scale);
        const QPointF tip = project({tips[size_t(axis)].x, tips[size_t(axis)].y, tips[size_t(axis)].z + 0.18}, centre,
                                    scale);
        QPen pen(axisColour(axis), axis == highlighted ? 3 : 1.5);
        pen.setCapStyle(Qt::RoundCap);
        p.setPen(pen);
        p.drawLine(o, tip);
        QFont f = p.font();
        f.setBold(axis == highlighted);
        p.setFont(f);
        p.drawText(QRectF(tip.x() - 12, tip.y() - 18, 24, 16), Qt::AlignCenter, QLatin1String(names[axis]));
    }
}

// The turn about `axis`: most of a circle with an arrowhead at its end.
void drawTurn(QPainter &p, const QPointF &centre, double scale, int axis)
{
    const double r = axis == 2 ? 1.35 : 1.05;
    const double from = 0.25, to = 2 * kPi - 0.45;
    QPainterPath path;
    const int steps = 64;
    for (int i = 0; i <= steps; ++i) {
        const Vec v = onCircle(axis, r, from + (to - from) * i / steps);
        const QPointF q = project(v, centre, scale);
        if (i == 0)
            path.moveTo(q);
        else
            path.lineTo(q);
    }
    QPen pen(axisColour(axis), 2.5);
    pen.setCapStyle(Qt::RoundCap);
    p.setPen(pen);
    p.setBrush(Qt::NoBrush);
    p.drawPath(path);
    // The arrowhead along the circle's direction at its end.
    const QPointF end = project(onCircle(axis, r, to), centre, scale);
    const QPointF before = project(onCircle(axis, r, to - 0.12), centre, scale);
    QPointF d = end - before;
    const double len = std::hypot(d.x(), d.y());
    if (len <= 0)
        return;
    d /= len;
    const QPointF n(-d.y(), d.x());
    const double s = std::max(6.0, scale * 0.16);
    p.setBrush(axisColour(axis));
    p.setPen(Qt::NoPen);
    p.drawPolygon(QPolygonF({end + d * s, end - d * s * 0.6 + n * s * 0.7, end - d * s * 0.6 - n * s * 0.7}));
}

} // namespace

RotationGuide::RotationGuide(QWidget *parent) : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    setToolTip(tr("Turn the module at least one full turn about each of its axes, slowly (20-100 deg/s), in any order"));
}

QStringList RotationGuide::captions() const
{
    return {tr("About X: roll it over"), tr("About Y: tip it end over end"), tr("About Z: turn it flat, like a compass")};
}

int RotationGuide::heightForWidth(int width) const
{
    return std::max(minimumSizeHint().height(), std::min(320, width * 3 / 8));
}

void RotationGuide::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QStringList texts = captions();
    const QFontMetricsF fm(font());
    const double captionHeight = fm.lineSpacing() * 2.4;
    const double panelWidth = width() / 3.0;
    const double drawHeight = std::max(40.0, height() - captionHeight);
    // The figure spans about 3.4 units across and 2.6 down.
    const double scale = std::min(panelWidth / 3.6, drawHeight / 2.9);
    for (int axis = 0; axis < 3; ++axis) {
        const QPointF centre(panelWidth * (axis + 0.5), drawHeight * 0.52);
        drawModule(p, centre, scale, palette());
        drawAxes(p, centre, scale, axis);
        drawTurn(p, centre, scale, axis);
        p.setPen(palette().color(QPalette::WindowText));
        QFont f = font();
        f.setBold(false);
        p.setFont(f);
        p.drawText(QRectF(panelWidth * axis + 4, drawHeight, panelWidth - 8, captionHeight),
                   Qt::AlignHCenter | Qt::AlignTop | Qt::TextWordWrap, texts[axis]);
    }
}

} // namespace imudesk::ui
