#include "ui/results/trend_view.h"

#include "ui/results/results_format.h"
#include "ui/common/elided_label.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDateTimeAxis>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLegendMarker>
#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace imudesk::ui {

using results::Outcome;
using Point = results::ResultsStore::Point;

TrendView::TrendView(QWidget *parent) : QWidget(parent)
{
    m_measurementTitle = new QLabel(this);
    m_measurement = new QComboBox(this);
    m_measurement->setObjectName(QStringLiteral("trendMeasurement"));
    // A long name does not widen the window: the combo box shows what fits, the tooltip all.
    m_measurement->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_measurement->setMinimumContentsLength(24);
    m_measurementTitle->setBuddy(m_measurement);
    connect(m_measurement, &QComboBox::activated, this, [this] {
        m_measurement->setToolTip(m_measurement->currentData(Qt::ToolTipRole).toString());
        Q_EMIT measurementChosen(measurement());
    });
    auto *top = new QHBoxLayout;
    top->addWidget(m_measurementTitle);
    top->addWidget(m_measurement);
    top->addStretch(1);

    m_chart = new QChart;
    m_chart->legend()->setAlignment(Qt::AlignBottom);
    m_chart->setMargins(QMargins(4, 4, 4, 4));
    m_x = new QDateTimeAxis;
    m_x->setFormat(QStringLiteral("MM-dd HH:mm"));
    m_x->setTickCount(6);
    m_y = new QValueAxis;
    m_y->setLabelFormat(QStringLiteral("%.4g"));
    m_chart->addAxis(m_x, Qt::AlignBottom);
    m_chart->addAxis(m_y, Qt::AlignLeft);
    const auto scatter = [this](const QColor &colour) {
        auto *s = new QScatterSeries;
        s->setColor(colour);
        s->setBorderColor(colour);
        s->setMarkerSize(7);
        return s;
    };
    m_pass = scatter(ResultsFormat::outcomeColour(Outcome::Pass));
    m_fail = scatter(ResultsFormat::outcomeColour(Outcome::Fail));
    const auto line = [](const QColor &colour, Qt::PenStyle style) {
        auto *s = new QLineSeries;
        QPen pen(colour, 1.5, style);
        s->setPen(pen);
        return s;
    };
    m_low = line(QColor(0xc6, 0x28, 0x28), Qt::SolidLine);
    m_high = line(QColor(0xc6, 0x28, 0x28), Qt::SolidLine);
    m_marginalLow = line(QColor(0xef, 0x9a, 0x00), Qt::DashLine);
    m_marginalHigh = line(QColor(0xef, 0x9a, 0x00), Qt::DashLine);
    for (auto *s : std::initializer_list<QXYSeries *>{m_low, m_high, m_marginalLow, m_marginalHigh, m_pass, m_fail}) {
        m_chart->addSeries(s);
        s->attachAxis(m_x);
        s->attachAxis(m_y);
    }
    // One legend entry for both limit lines and one for the band.
    for (auto *s : std::initializer_list<QXYSeries *>{m_high, m_marginalHigh})
        for (QLegendMarker *marker : m_chart->legend()->markers(s))
            marker->setVisible(false);
    m_view = new QChartView(m_chart, this);
    m_view->setObjectName(QStringLiteral("trendChart"));
    m_view->setRenderHint(QPainter::Antialiasing);
    m_view->setMinimumHeight(160);

    m_messageLabel = new QLabel(this);
    m_messageLabel->setObjectName(QStringLiteral("trendMessage"));
    m_messageLabel->setWordWrap(true);
    m_stats = new ElidedLabel(1, this);
    m_stats->setObjectName(QStringLiteral("trendStats"));

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_messageLabel);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_stats);
    retranslateUi();
    showMessage(QString());
}

void TrendView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange && m_chart)
        retranslateUi();
    QWidget::changeEvent(event);
}

void TrendView::retranslateUi()
{
    m_measurementTitle->setText(tr("Measurement:"));
    m_measurement->setToolTip(m_measurement->currentData(Qt::ToolTipRole).toString());
    m_pass->setName(tr("Pass"));
    m_fail->setName(tr("Fail"));
    m_low->setName(tr("Limits"));
    m_high->setName(tr("Limits"));
    m_marginalLow->setName(tr("Marginal band"));
    m_marginalHigh->setName(tr("Marginal band"));
    m_x->setTitleText(tr("Module started"));
    updateStats();
}

QString TrendView::measurement() const
{
    return m_measurement->currentData().toString();
}

void TrendView::setMeasurements(const QStringList &names)
{
    const QString kept = measurement();
    m_measurement->clear();
    for (const QString &name : names)
        ResultsFormat::addComboItem(m_measurement, name, name);
    const int at = m_measurement->findData(kept);
    m_measurement->setCurrentIndex(at >= 0 ? at : 0);
    m_measurement->setToolTip(m_measurement->currentData(Qt::ToolTipRole).toString());
    m_measurement->setEnabled(!names.isEmpty());
}

QString TrendView::cpkText(double cpk)
{
    return std::isfinite(cpk) ? QString::number(cpk, 'f', 2) : QStringLiteral("–");
}

void TrendView::showMessage(const QString &text)
{
    m_message = text;
    m_haveSeries = false;
    m_points.clear();
    m_capability = {};
    for (QXYSeries *s : std::initializer_list<QXYSeries *>{m_pass, m_fail, m_low, m_high, m_marginalLow, m_marginalHigh})
        s->clear();
    m_chart->setTitle(QString());
    m_messageLabel->setText(text);
    m_messageLabel->setVisible(!text.isEmpty());
    updateStats();
}

void TrendView::showSeries(const QString &measurement, std::vector<Point> points,
                           const results::ResultsStore::Capability &capability)
{
    m_message.clear();
    m_messageLabel->clear();
    m_messageLabel->hide();
    m_haveSeries = true;
    m_points = std::move(points);
    m_capability = capability;
    QList<QPointF> pass, fail, low, high, marginalLow, marginalHigh;
    for (const Point &p : m_points) {
        const double t = double(p.time.toMSecsSinceEpoch());
        (p.outcome == Outcome::Fail ? fail : pass) << QPointF(t, p.value);
        if (p.low)
            low << QPointF(t, *p.low);
        if (p.high)
            high << QPointF(t, *p.high);
        if (p.marginalLow)
            marginalLow << QPointF(t, *p.marginalLow);
        if (p.marginalHigh)
            marginalHigh << QPointF(t, *p.marginalHigh);
    }
    m_pass->replace(pass);
    m_fail->replace(fail);
    m_chart->setTitle(ResultsFormat::shortText(measurement).toHtmlEscaped());
    m_view->setToolTip(ResultsFormat::toolTip(measurement));
    fitAxes();
    // The limits run across the whole time axis: modules tested within a minute of each other
    // would otherwise draw them as a dot.
    const double left = double(m_x->min().toMSecsSinceEpoch()), right = double(m_x->max().toMSecsSinceEpoch());
    for (QList<QPointF> *line : {&low, &high, &marginalLow, &marginalHigh})
        if (!line->isEmpty()) {
            line->prepend(QPointF(left, line->first().y()));
            line->append(QPointF(right, line->last().y()));
        }
    m_low->replace(low);
    m_high->replace(high);
    m_marginalLow->replace(marginalLow);
    m_marginalHigh->replace(marginalHigh);
    updateStats();
}

void TrendView::fitAxes()
{
    if (m_points.empty())
        return;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    const auto take = [&lo, &hi](double v) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    };
    for (const Point &p : m_points) {
        take(p.value);
        for (const auto &limit : {p.low, p.high, p.marginalLow, p.marginalHigh})
            if (limit)
                take(*limit);
    }
    const double pad = hi > lo ? (hi - lo) * 0.08 : std::max(std::abs(hi) * 0.1, 1e-9);
    // Round ticks at multiples of a 1, 2 or 5 step, counted from 0 (Qt Charts sizes the axis for
    // its end labels and cuts longer ones between; a sum of steps would show 0 as -1.4e-17).
    // Values that are all positive (a noise, an error) keep the axis at or above 0.
    const double bottom = lo >= 0 ? std::max(0.0, lo - pad) : lo - pad;
    const double top = hi + pad;
    const double raw = (top - bottom) / 5;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    const double step = magnitude * (raw / magnitude <= 1 ? 1 : raw / magnitude <= 2 ? 2 : raw / magnitude <= 5 ? 5 : 10);
    m_y->setTickType(QValueAxis::TicksDynamic);
    m_y->setTickAnchor(0);
    m_y->setTickInterval(step);
    m_y->setRange(std::floor(bottom / step) * step, std::ceil(top / step) * step);
    QDateTime first = m_points.front().time, last = m_points.back().time;
    if (first.secsTo(last) < 60) { // one module, or a few within a minute: a window around them
        first = first.addSecs(-1800);
        last = last.addSecs(1800);
    }
    const qint64 span = first.msecsTo(last);
    m_x->setRange(first.addMSecs(-span / 40), last.addMSecs(span / 40));
    m_x->setFormat(span > 2LL * 24 * 3600 * 1000 ? QStringLiteral("yyyy-MM-dd") : QStringLiteral("MM-dd HH:mm"));
}

int TrendView::pointCount() const
{
    return int(m_pass->count() + m_fail->count());
}

int TrendView::failureCount() const
{
    return int(m_fail->count());
}

QString TrendView::statsText() const
{
    return m_stats->fullText();
}

void TrendView::updateStats()
{
    m_view->setVisible(m_haveSeries);
    m_stats->setVisible(m_haveSeries);
    if (!m_haveSeries) {
        m_stats->setFullText(QString());
        return;
    }
    const auto &c = m_capability;
    if (c.n == 0) {
        m_stats->setFullText(tr("No values of this measurement in the time chosen."));
        m_stats->setExtraToolTip(QString());
        return;
    }
    m_stats->setFullText(tr("n = %1 · mean = %2 · σ = %3 · Cpk = %4")
                             .arg(c.n)
                             .arg(ResultsFormat::number(c.mean), ResultsFormat::number(c.sigma), cpkText(c.cpk)));
    QString limits = ResultsFormat::range(c.lsl, c.usl);
    m_stats->setExtraToolTip(
        tr("Cpk, the process capability index: how far the mean lies from the nearer limit, in units of three "
           "standard deviations: min(USL − mean, mean − LSL) / 3σ, against the latest module's limits (%1). 1.33 or "
           "more is commonly asked for; below 1, some modules will fail. \"–\": no limit, or no spread (fewer than "
           "two values, or all equal).")
            .arg(limits.isEmpty() ? tr("none") : limits));
}

} // namespace imudesk::ui
