#include "charts/plot_canvas.h"

#include "common/paint_helpers.h"

#include <QEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPen>

#include <algorithm>
#include <cmath>

namespace imudesk::ui {

namespace {
constexpr int kCardInset = 2;    // between the widget's edge and the white card
constexpr int kPad = 6;          // inside the card
constexpr int kGap = 4;          // between a label and what it labels
constexpr int kSwatch = 10;      // legend colour square
constexpr int kMaxCachedTexts = 512;
constexpr double kHiddenAlpha = 0.3;
} // namespace

PlotCanvas::PlotCanvas(QWidget *parent) : QWidget(parent)
{
    setAttribute(Qt::WA_OpaquePaintEvent);
    setMouseTracking(true);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

// ---------------------------------------------------------------- content

void PlotCanvas::setTitle(const QString &title)
{
    if (title == m_title)
        return;
    m_title = title;
    relayout();
}

void PlotCanvas::setAxisTitles(const QString &x, const QString &y)
{
    if (x == m_xTitle && y == m_yTitle)
        return;
    m_xTitle = x;
    m_yTitle = y;
    m_yLabelWidth = 0; // another quantity or unit: other labels
    relayout();
}

int PlotCanvas::addLine(const QColor &colour, const QString &name)
{
    m_lines.push_back(Line{colour, name, {}, true});
    relayout();
    return int(m_lines.size()) - 1;
}

void PlotCanvas::setLineName(int line, const QString &name)
{
    if (m_lines[size_t(line)].name == name)
        return;
    m_lines[size_t(line)].name = name;
    relayout();
}

void PlotCanvas::setPoints(int line, const QList<QPointF> &points)
{
    m_lines[size_t(line)].points = points;
    update();
}

QList<QPointF> &PlotCanvas::pointsToFill(int line)
{
    update();
    return m_lines[size_t(line)].points;
}

void PlotCanvas::setLineVisible(int line, bool visible)
{
    Line &l = m_lines[size_t(line)];
    l.visible = visible;
    if (!visible)
        l.points.clear();
    m_staticValid = false; // the legend entry dims
    update();
}

void PlotCanvas::setLineListed(int line, bool listed)
{
    Line &l = m_lines[size_t(line)];
    if (l.listed == listed)
        return;
    l.listed = listed;
    relayout();
}

void PlotCanvas::setLegendVisible(bool visible)
{
    if (visible == m_legendVisible)
        return;
    m_legendVisible = visible;
    relayout();
}

QRectF PlotCanvas::legendEntryRect(int line) const
{
    if (!m_legendVisible || line < 0 || size_t(line) >= m_legendRects.size())
        return {};
    return m_legendRects[size_t(line)];
}

void PlotCanvas::setXRange(double min, double max, double step, int decimals)
{
    m_x = Axis{min, max, step, decimals};
    update();
}

void PlotCanvas::setYRange(double min, double max, double step, int decimals)
{
    if (min == m_y.min && max == m_y.max && step == m_y.step && decimals == m_y.decimals && m_yLabelWidth > 0)
        return;
    m_y = Axis{min, max, step, decimals};
    // A wider value label widens the margin once; narrower ones keep it (no jitter).
    const QFontMetrics fm = fontMetrics();
    int widest = 0;
    for (const QString &label : tickLabels(m_y))
        widest = std::max(widest, fm.horizontalAdvance(label));
    if (widest > m_yLabelWidth) {
        m_yLabelWidth = widest;
        relayout();
    }
    update();
}

void PlotCanvas::setCrosshair(std::optional<double> x)
{
    if (x == m_crosshair)
        return;
    m_crosshair = x;
    update();
}

bool PlotCanvas::isCrosshairDrawn() const
{
    if (!m_crosshair || m_area.isEmpty())
        return false;
    const double px = toPixel(QPointF(*m_crosshair, m_y.min)).x();
    return px >= m_area.left() - 0.5 && px <= m_area.right() + 0.5;
}

// ---------------------------------------------------------------- mapping

QPointF PlotCanvas::toPixel(const QPointF &value) const
{
    const double xSpan = m_x.max - m_x.min, ySpan = m_y.max - m_y.min;
    if (!(xSpan > 0.0) || !(ySpan > 0.0))
        return {};
    return {m_area.left() + (value.x() - m_x.min) / xSpan * m_area.width(),
            m_area.bottom() - (value.y() - m_y.min) / ySpan * m_area.height()};
}

QPointF PlotCanvas::toValue(const QPointF &pixel) const
{
    if (m_area.width() <= 0.0 || m_area.height() <= 0.0)
        return {};
    return {m_x.min + (pixel.x() - m_area.left()) / m_area.width() * (m_x.max - m_x.min),
            m_y.min + (m_area.bottom() - pixel.y()) / m_area.height() * (m_y.max - m_y.min)};
}

// ---------------------------------------------------------------- ticks

QString PlotCanvas::tickText(double value, int decimals)
{
    QString text = QString::number(value, 'f', std::max(0, decimals));
    // "-0.0" reads as a bug.
    if (text.startsWith(QLatin1Char('-')) && text.count(QLatin1Char('0')) + text.count(QLatin1Char('.')) == text.size() - 1)
        text.remove(0, 1);
    return text;
}

template<typename F>
void PlotCanvas::forEachTick(const Axis &axis, F &&f)
{
    if (!(axis.step > 0.0) || !(axis.max > axis.min) || !std::isfinite(axis.min) || !std::isfinite(axis.max))
        return;
    // Ticks on multiples of the step, so that they stay put while the axis scrolls.
    const double first = std::ceil(axis.min / axis.step - 1e-9);
    const double last = std::floor(axis.max / axis.step + 1e-9);
    if (last - first > 200.0) // a step far too small for the range: draw none
        return;
    for (double k = first; k <= last; k += 1.0) {
        double v = k * axis.step;
        if (std::abs(v) < axis.step * 1e-9)
            v = 0.0;
        f(v);
    }
}

QStringList PlotCanvas::tickLabels(const Axis &axis)
{
    QStringList out;
    forEachTick(axis, [&](double v) { out << tickText(v, axis.decimals); });
    return out;
}

const QStaticText &PlotCanvas::staticText(const QString &text)
{
    auto it = m_texts.find(text);
    if (it != m_texts.end())
        return *it;
    if (m_texts.size() >= kMaxCachedTexts) // a long run of scrolling time labels
        m_texts.clear();
    QStaticText st(text);
    st.setTextFormat(Qt::PlainText);
    st.setPerformanceHint(QStaticText::AggressiveCaching);
    st.prepare(QTransform(), font());
    return *m_texts.insert(text, st);
}

// ---------------------------------------------------------------- layout

int PlotCanvas::legendWidth() const
{
    if (!m_legendVisible || m_lines.empty())
        return 0;
    const QFontMetrics fm = fontMetrics();
    int widest = -1;
    for (const Line &l : m_lines)
        if (l.listed)
            widest = std::max(widest, fm.horizontalAdvance(l.name));
    return widest < 0 ? 0 : kSwatch + kGap + widest;
}

QSize PlotCanvas::minimumSizeHint() const
{
    const QFontMetrics fm = fontMetrics();
    return {8 * kPad + 3 * fm.height() + legendWidth() + 120, 4 * fm.height() + 4 * kPad + 60};
}

QSize PlotCanvas::sizeHint() const
{
    return minimumSizeHint() + QSize(200, 120);
}

void PlotCanvas::relayout()
{
    const QFontMetrics fm = fontMetrics();
    const int line = fm.height();
    m_card = rect().adjusted(kCardInset, kCardInset, -kCardInset, -kCardInset);
    const int top = m_card.top() + kPad + (m_title.isEmpty() ? 0 : line + kGap) + line / 2;
    const int left = m_card.left() + kPad + (m_yTitle.isEmpty() ? 0 : line + kGap) + m_yLabelWidth + kGap;
    const int bottom = m_card.bottom() - kPad - (m_xTitle.isEmpty() ? 0 : line + kGap / 2) - line - kGap;
    // Room on the right for the last time label's overhang and for the legend.
    const int legend = legendWidth();
    const int right = m_card.right() - kPad - fm.horizontalAdvance(QStringLiteral("00.0")) / 2
                      - (legend > 0 ? legend + 3 * kPad : 0);
    const QRectF area(QPointF(left, top), QPointF(std::max(left + 1, right), std::max(top + 1, bottom)));

    m_legendRects.assign(m_lines.size(), QRectF());
    if (legend > 0) {
        const double x = m_card.right() - kPad - legend;
        const double entry = std::max(line, kSwatch) + 2;
        const auto listed = std::count_if(m_lines.begin(), m_lines.end(), [](const Line &l) { return l.listed; });
        double y = area.center().y() - entry * double(listed) / 2.0;
        for (size_t i = 0; i < m_lines.size(); ++i)
            if (m_lines[i].listed) {
                m_legendRects[i] = QRectF(x - 2, y, legend + 4, entry);
                y += entry;
            }
    }
    if (area != m_area) {
        m_area = area;
        Q_EMIT plotAreaChanged(m_area);
    }
    m_staticValid = false;
    update();
}

void PlotCanvas::resizeEvent(QResizeEvent *event)
{
    relayout();
    QWidget::resizeEvent(event);
}

void PlotCanvas::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::FontChange || event->type() == QEvent::StyleChange) {
        m_texts.clear();
        m_yLabelWidth = 0;
        setYRange(m_y.min, m_y.max, m_y.step, m_y.decimals);
        relayout();
    } else if (event->type() == QEvent::PaletteChange) {
        m_staticValid = false;
        update();
    }
    QWidget::changeEvent(event);
}

// ---------------------------------------------------------------- mouse

void PlotCanvas::mousePressEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton && m_legendVisible) {
        for (size_t i = 0; i < m_legendRects.size(); ++i) {
            if (m_legendRects[i].contains(event->position())) {
                Q_EMIT legendClicked(int(i));
                event->accept();
                return;
            }
        }
    }
    QWidget::mousePressEvent(event);
}

void PlotCanvas::mouseMoveEvent(QMouseEvent *event)
{
    bool overLegend = false;
    if (m_legendVisible)
        for (const QRectF &r : m_legendRects)
            overLegend = overLegend || r.contains(event->position());
    if (overLegend)
        setCursor(Qt::PointingHandCursor);
    else
        unsetCursor();
    QWidget::mouseMoveEvent(event);
}

// ---------------------------------------------------------------- painting

void PlotCanvas::paintStatic(QPainter &p)
{
    const QPalette pal = palette();
    p.fillRect(rect(), pal.color(QPalette::Window));
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setPen(QPen(pal.color(QPalette::Midlight), 1.0));
    p.setBrush(pal.color(QPalette::Base));
    p.drawRoundedRect(QRectF(m_card).adjusted(0.5, 0.5, -0.5, -0.5), 4.0, 4.0);
    p.setRenderHint(QPainter::Antialiasing, false);
    p.setBrush(Qt::NoBrush);

    const int line = fontMetrics().height();
    p.setPen(pal.color(QPalette::Text));
    if (!m_title.isEmpty()) {
        const QStaticText &t = staticText(m_title);
        p.drawStaticText(QPointF(m_area.center().x() - t.size().width() / 2.0, m_card.top() + kPad), t);
    }
    if (!m_xTitle.isEmpty()) {
        const QStaticText &t = staticText(m_xTitle);
        p.drawStaticText(QPointF(m_area.center().x() - t.size().width() / 2.0, m_area.bottom() + kGap + line + kGap / 2), t);
    }
    if (!m_yTitle.isEmpty()) {
        const QStaticText &t = staticText(m_yTitle);
        p.save();
        p.translate(m_card.left() + kPad, m_area.center().y() + t.size().width() / 2.0);
        p.rotate(-90.0);
        p.drawStaticText(QPointF(0, 0), t);
        p.restore();
    }
    drawLegend(p);
}

void PlotCanvas::paintEvent(QPaintEvent *)
{
    // What changes only with the layout, the titles, the legend or the palette is drawn
    // once into a pixmap (rotated text and the rounded card are the costly parts); each
    // refresh copies it and draws the grid, the tick labels and the lines over it.
    const qreal dpr = devicePixelRatioF();
    if (m_static.isNull() || m_static.size() != size() * dpr || m_static.devicePixelRatio() != dpr) {
        m_static = QPixmap(size() * dpr);
        m_static.setDevicePixelRatio(dpr);
        m_staticValid = false;
    }
    if (!m_staticValid) {
        QPainter sp(&m_static);
        sp.setFont(font());
        paintStatic(sp);
        m_staticValid = true;
    }
    QPainter p(this);
    p.drawPixmap(0, 0, m_static);

    // Grid and axis lines in opaque colours (see mixColours).
    const QColor text = palette().color(QPalette::Text);
    const QColor base = palette().color(QPalette::Base);
    const QPen gridPen(mixColours(base, text, 0.12), 0);
    const QPen axisPen(mixColours(base, text, 0.45), 0);

    // Grid and tick labels.
    const double labelTop = m_area.bottom() + kGap;
    forEachTick(m_x, [&](double v) {
        const double x = std::round(toPixel(QPointF(v, m_y.min)).x());
        p.setPen(gridPen);
        p.drawLine(QPointF(x, m_area.top()), QPointF(x, m_area.bottom()));
        p.setPen(text);
        const QStaticText &t = staticText(tickText(v, m_x.decimals));
        p.drawStaticText(QPointF(x - t.size().width() / 2.0, labelTop), t);
    });
    forEachTick(m_y, [&](double v) {
        const double y = std::round(toPixel(QPointF(m_x.min, v)).y());
        p.setPen(gridPen);
        p.drawLine(QPointF(m_area.left(), y), QPointF(m_area.right(), y));
        p.setPen(text);
        const QStaticText &t = staticText(tickText(v, m_y.decimals));
        p.drawStaticText(QPointF(m_area.left() - kGap - t.size().width(), y - t.size().height() / 2.0), t);
    });
    p.setPen(axisPen);
    p.drawLine(m_area.bottomLeft(), m_area.bottomRight());
    p.drawLine(m_area.bottomLeft(), m_area.topLeft());

    drawLines(p);

    if (isCrosshairDrawn()) {
        QPen pen(QColor(0x60, 0x60, 0x60));
        pen.setStyle(Qt::DashLine);
        pen.setCosmetic(true);
        p.setPen(pen);
        const double x = std::round(toPixel(QPointF(*m_crosshair, m_y.min)).x());
        p.drawLine(QPointF(x, m_area.top()), QPointF(x, m_area.bottom()));
    }
}

void PlotCanvas::drawLines(QPainter &p)
{
    const double xSpan = m_x.max - m_x.min, ySpan = m_y.max - m_y.min;
    if (!(xSpan > 0.0) || !(ySpan > 0.0) || m_area.isEmpty())
        return;
    const double sx = m_area.width() / xSpan, sy = m_area.height() / ySpan;
    const double left = m_area.left(), bottom = m_area.bottom();
    // Values far outside the range (a fixed scale) are clamped so that the raster engine
    // never sees coordinates it would overflow on; the clip hides them anyway.
    const double yLow = m_area.top() - m_area.height(), yHigh = bottom + m_area.height();
    p.save();
    p.setClipRect(m_area.adjusted(0, -1, 1, 0));
    for (const Line &line : m_lines) {
        if (!line.visible || line.points.isEmpty())
            continue;
        QPen pen(line.colour);
        pen.setWidth(0); // cosmetic 1 px: the raster engine's fast line path
        p.setPen(pen);
        const auto flush = [&] {
            if (m_scratch.size() == 1)
                p.drawPoint(m_scratch.front());
            else if (m_scratch.size() > 1)
                p.drawPolyline(m_scratch.data(), int(m_scratch.size()));
            m_scratch.clear();
        };
        m_scratch.clear();
        m_scratch.reserve(size_t(line.points.size()));
        for (const QPointF &pt : line.points) {
            if (std::isnan(pt.x()) || std::isnan(pt.y())) {
                flush();
                continue;
            }
            const double y = std::clamp(bottom - (pt.y() - m_y.min) * sy, yLow, yHigh);
            m_scratch.emplace_back(left + (pt.x() - m_x.min) * sx, y);
        }
        flush();
    }
    p.restore();
}

void PlotCanvas::drawLegend(QPainter &p)
{
    if (!m_legendVisible)
        return;
    const QColor text = palette().color(QPalette::Text);
    for (size_t i = 0; i < m_lines.size() && i < m_legendRects.size(); ++i) {
        const Line &l = m_lines[i];
        const QRectF r = m_legendRects[i];
        if (!l.listed || r.isEmpty())
            continue;
        QColor swatch = l.colour, label = text;
        if (!l.visible) {
            swatch.setAlphaF(kHiddenAlpha);
            label.setAlphaF(kHiddenAlpha + 0.1);
        }
        const double cy = r.center().y();
        p.fillRect(QRectF(r.left() + 2, cy - kSwatch / 2.0, kSwatch, kSwatch), swatch);
        p.setPen(label);
        const QStaticText &t = staticText(l.name);
        p.drawStaticText(QPointF(r.left() + 2 + kSwatch + kGap, cy - t.size().height() / 2.0), t);
    }
}

} // namespace imudesk::ui
