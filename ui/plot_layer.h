#pragma once
// The lines of a live chart, drawn straight onto the chart's plot area.
//
// Qt Charts' QLineSeries rebuilds a QPainterPath and a stroked hover shape for every
// replace(), which at 33 Hz with a few thousand points per chart costs more than the
// drawing itself. This item keeps the decimated points of each line (value
// coordinates), maps them to pixels only when it paints, and draws each unbroken run
// with one drawPolyline() and a 1-pixel cosmetic pen, which the raster engine draws
// without building any path. A point with a NaN x (plot::MinMaxDecimator::breakPoint)
// ends a run, so device-clock gaps show as breaks.
//
// The chart keeps its (empty) QLineSeries for the legend, the axes and mapToValue().
#include <QColor>
#include <QGraphicsItem>
#include <QList>
#include <QPointF>
#include <QRectF>

#include <vector>

namespace imudesk::ui {

class PlotLayer : public QGraphicsItem {
public:
    explicit PlotLayer(QGraphicsItem *parent = nullptr);

    // Adds a line and returns its index.
    int addLine(const QColor &colour);
    void setPoints(int line, const QList<QPointF> &points);
    const QList<QPointF> &points(int line) const { return m_lines[size_t(line)].points; }
    void setLineVisible(int line, bool visible);
    bool isLineVisible(int line) const { return m_lines[size_t(line)].visible; }

    // The plot area in the parent's coordinates and the value range it shows.
    void setPlotArea(const QRectF &area);
    void setRange(double xMin, double xMax, double yMin, double yMax);
    QRectF plotArea() const { return m_area; }

    // Pixel position of a value point (for tests and the crosshair).
    QPointF toPixel(const QPointF &value) const;

    QRectF boundingRect() const override { return m_area; }
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;

private:
    struct Line {
        QColor colour;
        QList<QPointF> points;
        bool visible = true;
    };
    std::vector<Line> m_lines;
    QRectF m_area;
    double m_xMin = 0.0, m_xMax = 1.0, m_yMin = 0.0, m_yMax = 1.0;
    std::vector<QPointF> m_scratch; // pixel coordinates of one run, reused between paints
};

} // namespace imudesk::ui
