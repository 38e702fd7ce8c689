#pragma once
// The drawing surface of a live chart: title, axes with ticks, grid and labels, the lines,
// a legend that switches lines on and off, and the crosshair, all painted by this widget
// with QPainter.
//
// Why not Qt Charts: a QChart lays itself out again on every change of an axis range and
// re-creates the axis labels as rich-text items, so a chart whose time axis scrolls at
// 33 Hz spent most of its time in text layout (four charts at 1 kHz: 28 % of a core on
// the GUI thread, of which 19 % the charts). Here a range change only moves the ticks;
// labels are laid out once per distinct text (QStaticText, cached); the plot area is laid
// out again only when the size, the font, a title or the widest value label changes.
//
// The lines hold decimated points in value coordinates (plot::MinMaxDecimator's output);
// they are mapped to pixels when painted and drawn as 1-pixel cosmetic polylines, which the
// raster engine draws without building a path. A point with a NaN x or y ends a run, so
// gaps show as breaks. Values far outside the range are clamped before drawing.
#include <QColor>
#include <QHash>
#include <QList>
#include <QPixmap>
#include <QPointF>
#include <QRectF>
#include <QStaticText>
#include <QString>
#include <QWidget>

#include <optional>
#include <vector>

namespace imudesk::ui {

class PlotCanvas : public QWidget {
    Q_OBJECT
public:
    explicit PlotCanvas(QWidget *parent = nullptr);

    void setTitle(const QString &title);
    QString title() const { return m_title; }
    void setAxisTitles(const QString &x, const QString &y);
    QString xTitle() const { return m_xTitle; }
    QString yTitle() const { return m_yTitle; }

    // Lines: added once, addressed by the returned index.
    int addLine(const QColor &colour, const QString &name = QString());
    int lineCount() const { return int(m_lines.size()); }
    void setLineName(int line, const QString &name);
    void setPoints(int line, const QList<QPointF> &points);
    // The line's own list, for a caller that fills it in place (ChartView decimates into it);
    // the canvas repaints on the next paint cycle.
    QList<QPointF> &pointsToFill(int line);
    const QList<QPointF> &points(int line) const { return m_lines[size_t(line)].points; }
    // A hidden line keeps its legend entry, dimmed, so that a click brings it back.
    void setLineVisible(int line, bool visible);
    bool isLineVisible(int line) const { return m_lines[size_t(line)].visible; }
    // An unlisted line has no legend entry (a quantity the device has not sent, such as an
    // HEC495's magnetic roll beside a module's Euler angles); lines are listed by default.
    void setLineListed(int line, bool listed);
    bool isLineListed(int line) const { return m_lines[size_t(line)].listed; }
    void setLegendVisible(bool visible);
    bool isLegendVisible() const { return m_legendVisible; }
    // Where a line's legend entry is (widget coordinates); empty without a legend.
    QRectF legendEntryRect(int line) const;

    // The ranges shown, the distance between grid lines (ticks sit on multiples of it) and
    // the decimals of the tick labels. A step of 0 means no ticks.
    void setXRange(double min, double max, double step, int decimals);
    void setYRange(double min, double max, double step, int decimals);
    double xMin() const { return m_x.min; }
    double xMax() const { return m_x.max; }
    double yMin() const { return m_y.min; }
    double yMax() const { return m_y.max; }
    // The tick labels as drawn (for tests and for the reserved label width).
    QStringList xTickLabels() const { return tickLabels(m_x); }
    QStringList yTickLabels() const { return tickLabels(m_y); }

    // The plot area in widget coordinates, and the mapping between values and pixels.
    QRectF plotArea() const { return m_area; }
    QPointF toPixel(const QPointF &value) const;
    QPointF toValue(const QPointF &pixel) const;

    // A dashed vertical line at x (in value coordinates) while set; none outside the range.
    void setCrosshair(std::optional<double> x);
    bool isCrosshairDrawn() const;

    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;

Q_SIGNALS:
    // The user clicked a line's legend entry.
    void legendClicked(int line);
    // The plot area moved or changed size (a resize, a font, a wider value label).
    void plotAreaChanged(const QRectF &area);

protected:
    void paintEvent(QPaintEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void changeEvent(QEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;

private:
    struct Line {
        QColor colour;
        QString name;
        QList<QPointF> points;
        bool visible = true;
        bool listed = true;
    };
    struct Axis {
        double min = 0.0;
        double max = 1.0;
        double step = 0.0;
        int decimals = 0;
    };

    static QStringList tickLabels(const Axis &axis);
    static QString tickText(double value, int decimals);
    template<typename F>
    static void forEachTick(const Axis &axis, F &&f);
    const QStaticText &staticText(const QString &text);
    int legendWidth() const;
    void relayout();
    void paintStatic(QPainter &painter);
    void drawLines(QPainter &painter);
    void drawLegend(QPainter &painter);

    QString m_title;
    QString m_xTitle;
    QString m_yTitle;
    std::vector<Line> m_lines;
    bool m_legendVisible = true;
    Axis m_x;
    Axis m_y;
    int m_yLabelWidth = 0; // widest value label so far: the plot area does not jitter
    std::optional<double> m_crosshair;

    QRectF m_area;
    QRect m_card;
    std::vector<QRectF> m_legendRects;
    QHash<QString, QStaticText> m_texts;
    std::vector<QPointF> m_scratch;
    QPixmap m_static;
    bool m_staticValid = false;
};

} // namespace imudesk::ui
