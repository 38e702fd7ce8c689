#include "plot_layer.h"

#include <QPainter>
#include <QPen>

#include <algorithm>
#include <cmath>

namespace imudesk::ui {

PlotLayer::PlotLayer(QGraphicsItem *parent) : QGraphicsItem(parent)
{
    setFlag(QGraphicsItem::ItemClipsToShape, false);
    setAcceptedMouseButtons(Qt::NoButton);
    setAcceptHoverEvents(false);
}

int PlotLayer::addLine(const QColor &colour)
{
    m_lines.push_back(Line{colour, {}, true});
    update();
    return int(m_lines.size()) - 1;
}

void PlotLayer::setPoints(int line, const QList<QPointF> &points)
{
    m_lines[size_t(line)].points = points;
    update();
}

void PlotLayer::setLineVisible(int line, bool visible)
{
    Line &l = m_lines[size_t(line)];
    l.visible = visible;
    if (!visible)
        l.points.clear();
    update();
}

void PlotLayer::setPlotArea(const QRectF &area)
{
    if (area == m_area)
        return;
    prepareGeometryChange();
    m_area = area;
    update();
}

void PlotLayer::setRange(double xMin, double xMax, double yMin, double yMax)
{
    m_xMin = xMin;
    m_xMax = xMax;
    m_yMin = yMin;
    m_yMax = yMax;
    update();
}

QPointF PlotLayer::toPixel(const QPointF &value) const
{
    const double xSpan = m_xMax - m_xMin, ySpan = m_yMax - m_yMin;
    if (!(xSpan > 0.0) || !(ySpan > 0.0))
        return {};
    return {m_area.left() + (value.x() - m_xMin) / xSpan * m_area.width(),
            m_area.bottom() - (value.y() - m_yMin) / ySpan * m_area.height()};
}

void PlotLayer::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    const double xSpan = m_xMax - m_xMin, ySpan = m_yMax - m_yMin;
    if (!(xSpan > 0.0) || !(ySpan > 0.0) || m_area.isEmpty())
        return;
    const double sx = m_area.width() / xSpan, sy = m_area.height() / ySpan;
    const double left = m_area.left(), bottom = m_area.bottom();
    // Values far outside the range (a fixed scale) are clamped so that the raster engine
    // never sees coordinates it would overflow on; the clip hides them anyway.
    const double yLow = m_area.top() - m_area.height(), yHigh = bottom + m_area.height();
    painter->save();
    painter->setClipRect(m_area);
    painter->setRenderHint(QPainter::Antialiasing, false);
    for (const Line &line : m_lines) {
        if (!line.visible || line.points.isEmpty())
            continue;
        QPen pen(line.colour);
        pen.setWidth(0); // cosmetic 1 px: the raster engine's fast line path
        painter->setPen(pen);
        const auto flush = [&] {
            if (m_scratch.size() == 1)
                painter->drawPoint(m_scratch.front());
            else if (m_scratch.size() > 1)
                painter->drawPolyline(m_scratch.data(), int(m_scratch.size()));
            m_scratch.clear();
        };
        m_scratch.clear();
        m_scratch.reserve(size_t(line.points.size()));
        for (const QPointF &p : line.points) {
            if (std::isnan(p.x()) || std::isnan(p.y())) {
                flush();
                continue;
            }
            const double y = std::clamp(bottom - (p.y() - m_yMin) * sy, yLow, yHigh);
            m_scratch.emplace_back(left + (p.x() - m_xMin) * sx, y);
        }
        flush();
    }
    painter->restore();
}

} // namespace imudesk::ui
