#include "configuration/mounting_tile.h"

#include "model/mounting.h"

#include <QFontMetrics>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <array>

namespace imudesk::ui {

namespace {
// Oblique projection of a body-frame point (X right, Y forward into the picture, Z up).
QPointF project(double x, double y, double z, QPointF origin, double scale)
{
    return origin + QPointF((x + 0.45 * y) * scale, (-z - 0.3 * y) * scale);
}

void arrow(QPainter &p, QPointF from, QPointF to, const QColor &c, const QString &label)
{
    p.setPen(QPen(c, 2.2));
    p.drawLine(from, to);
    const QLineF l(to, from);
    QLineF a = l;
    a.setLength(7);
    a.setAngle(l.angle() + 25);
    QLineF b = l;
    b.setLength(7);
    b.setAngle(l.angle() - 25);
    p.drawLine(a);
    p.drawLine(b);
    p.drawText(QRectF(to.x() - 8, to.y() - 16, 16, 14), Qt::AlignCenter, label);
}
} // namespace

MountingTile::MountingTile(int code, QWidget *parent) : QWidget(parent), m_code(code)
{
    setCursor(Qt::PointingHandCursor);
    setToolTip(QString::number(code));
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
}

QSize MountingTile::readableSize() const
{
    // The caption's width, and a picture whose axes are about 45 px long at a 13 px font.
    const QFontMetrics fm = fontMetrics();
    const int unit = std::max(10, fm.height());
    return {std::max(fm.horizontalAdvance(QStringLiteral("URFR 000")) + 16, unit * 8),
            unit * 13 / 2 + fm.height() + 4};
}

QSize MountingTile::sizeHint() const
{
    return readableSize() * 1.15;
}

void MountingTile::setChecked(bool checked)
{
    if (m_checked == checked)
        return;
    m_checked = checked;
    update();
}

void MountingTile::mouseReleaseEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton && rect().contains(event->position().toPoint()))
        Q_EMIT clicked(m_code);
}

void MountingTile::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), m_checked ? palette().highlight().color().lighter(170) : palette().base().color());
    p.setPen(QPen(m_checked ? palette().highlight().color() : palette().mid().color(), m_checked ? 2 : 1));
    p.drawRect(rect().adjusted(0, 0, -1, -1));

    // Every mounting's drawing spans x -1.54 .. 1.54 and (up) 1.5 .. (down) 1.0 units of the
    // projection: scaled to the tile above its caption, room for an axis letter above an
    // arrow's end (16 px) and beside it (9 px), so nothing is ever cut.
    const int caption = fontMetrics().height() + 4;
    const double above = 17, below = 4, side = 10;
    const double area = height() - caption - above - below;
    const double s = std::max(1.0, std::min((width() - 2 * side) / 3.08, area / 2.5));
    const QPointF o(width() / 2.0, above + 1.5 * s + std::max(0.0, (area - 2.5 * s) / 2));
    // The body: a flat box 2 x 2.4 x 0.5, its front edge (forward) drawn thicker.
    const double bx = 1.0, by = 1.2, bz = 0.25;
    auto P = [&](double x, double y, double z) { return project(x, y, z, o, s); };
    QPainterPath top;
    top.moveTo(P(-bx, -by, bz));
    top.lineTo(P(bx, -by, bz));
    top.lineTo(P(bx, by, bz));
    top.lineTo(P(-bx, by, bz));
    top.closeSubpath();
    QPainterPath front;
    front.moveTo(P(-bx, -by, bz));
    front.lineTo(P(bx, -by, bz));
    front.lineTo(P(bx, -by, -bz));
    front.lineTo(P(-bx, -by, -bz));
    front.closeSubpath();
    p.setPen(QPen(palette().text().color(), 1));
    p.setBrush(palette().window().color());
    p.drawPath(front);
    p.drawPath(top);
    p.setPen(QPen(palette().text().color(), 2.5));
    p.drawLine(P(-bx, by, bz), P(bx, by, bz)); // the forward edge
    // The module: a small square on top.
    p.setBrush(palette().dark().color());
    p.setPen(Qt::NoPen);
    QPolygonF module;
    for (auto [x, y] : std::array<std::pair<double, double>, 4>{{{-0.3, -0.3}, {0.3, -0.3}, {0.3, 0.3}, {-0.3, 0.3}}})
        module << P(x, y, bz);
    p.drawPolygon(module);

    // IMU axes: column j of userFromSensor is IMU axis j in the body frame.
    const model::Matrix3 r = model::Mounting::userFromSensor(m_code);
    const QColor colours[3] = {QColor(220, 40, 40), QColor(30, 160, 50), QColor(40, 80, 230)};
    const char *names[3] = {"X", "Y", "Z"};
    const QPointF c = P(0, 0, bz);
    for (size_t j = 0; j < 3; ++j) {
        const double L = 1.25;
        const QPointF end = P(r[0][j] * L, r[1][j] * L, bz + r[2][j] * L);
        arrow(p, c, end, colours[j], QLatin1String(names[j]));
    }
    p.setPen(palette().text().color());
    p.drawText(QRectF(0, height() - caption, width(), caption - 1), Qt::AlignCenter,
               QStringLiteral("URFR %1").arg(QString::fromStdString(model::Mounting::codeText(m_code))));
}

} // namespace imudesk::ui
