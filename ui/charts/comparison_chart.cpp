#include "charts/comparison_chart.h"

#include "charts/chart_settings.h"
#include "charts/chart_view.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLegend>
#include <QLineSeries>
#include <QPainter>
#include <QPen>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <array>
#include <cmath>

namespace imudesk::ui {

using plot::Channel;
using plot::TimeAxis;

namespace {

// Source colours, in order (a colour-blind-friendly set).
constexpr std::array<QRgb, 8> kSourceColours = {0x1f77b4, 0xd62728, 0x2ca02c, 0xff7f0e,
                                                0x9467bd, 0x8c564b, 0xe377c2, 0x17becf};

QString labelFormat(double step)
{
    return QStringLiteral("%.%1f").arg(plot::AxisScaling::decimalsFor(step));
}

} // namespace

ComparisonChart::ComparisonChart(QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("comparisonChart"));

    m_chart = new QChart;
    m_chart->setAnimationOptions(QChart::NoAnimation);
    m_chart->setMargins(QMargins(4, 4, 4, 4));
    m_chart->legend()->setAlignment(Qt::AlignTop);
    m_axisX = new QValueAxis(m_chart);
    m_axisY = new QValueAxis(m_chart);
    for (QValueAxis *axis : {m_axisX, m_axisY}) {
        axis->setTickType(QValueAxis::TicksDynamic);
        axis->setTickAnchor(0.0);
    }
    m_chart->addAxis(m_axisX, Qt::AlignBottom);
    m_chart->addAxis(m_axisY, Qt::AlignLeft);
    m_chartView = new QChartView(m_chart, this);
    m_chartView->setObjectName(QStringLiteral("comparisonChartArea"));
    m_chartView->setMinimumHeight(kMinimumChartHeight);

    m_channelLabel = new QLabel(this);
    m_channelCombo = new QComboBox(this);
    m_channelCombo->setObjectName(QStringLiteral("channelCombo"));
    m_channelLabel->setBuddy(m_channelCombo);
    for (int c = 0; c < plot::kChannelCount; ++c)
        m_channelCombo->addItem(QString(), c);
    m_channelCombo->setCurrentIndex(m_channelCombo->findData(int(m_channel)));
    connect(m_channelCombo, &QComboBox::currentIndexChanged, this,
            [this](int) { setChannel(Channel(m_channelCombo->currentData().toInt())); });

    m_windowCombo = ChartView::makeWindowChooser(this, m_window, m_windowLabel,
                                                 [this](double seconds) { setWindowSeconds(seconds); });

    m_pauseButton = new QToolButton(this);
    m_pauseButton->setObjectName(QStringLiteral("pauseButton"));
    m_pauseButton->setCheckable(true);
    connect(m_pauseButton, &QToolButton::toggled, this, &ComparisonChart::setPaused);

    m_saveButton = new QPushButton(this);
    m_saveButton->setObjectName(QStringLiteral("savePngButton"));
    connect(m_saveButton, &QPushButton::clicked, this, &ComparisonChart::saveAsPngInteractive);

    auto *controls = new QHBoxLayout;
    controls->addWidget(m_channelLabel);
    controls->addWidget(m_channelCombo);
    controls->addSpacing(12);
    controls->addWidget(m_windowLabel);
    controls->addWidget(m_windowCombo);
    controls->addWidget(m_pauseButton);
    controls->addStretch(1);
    controls->addWidget(m_saveButton);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addLayout(controls);
    layout->addWidget(m_chartView, 1);

    retranslateUi();
    m_axisX->setRange(0.0, m_window);
}

ComparisonChart::~ComparisonChart() = default;

void ComparisonChart::retranslateUi()
{
    // No title of its own: the dock's or window's title says "Compare devices", and the
    // height goes to the plot.
    m_channelLabel->setText(tr("&Channel:"));
    m_channelCombo->setToolTip(tr("The quantity compared across the devices"));
    for (int i = 0; i < m_channelCombo->count(); ++i) {
        const Channel c = Channel(m_channelCombo->itemData(i).toInt());
        const QString u = ChartView::unit(ChartView::kindOf(c));
        m_channelCombo->setItemText(i, u.isEmpty() ? ChartView::channelName(c)
                                                   : tr("%1 (%2)", "quantity (unit)").arg(ChartView::channelName(c), u));
    }
    m_windowLabel->setText(tr("&Window:"));
    m_windowCombo->setToolTip(tr("Time span shown"));
    ChartView::fillWindowCombo(m_windowCombo, m_window);
    m_saveButton->setText(tr("Save as PNG…"));
    m_saveButton->setToolTip(tr("Save this chart as a PNG image"));
    updatePauseButton();
    updateAxisTitles();
}

void ComparisonChart::updateAxisTitles()
{
    m_axisX->setTitleText(ChartView::timeAxisTitle(TimeAxis::Host));
    const QString u = ChartView::unit(ChartView::kindOf(m_channel));
    m_axisY->setTitleText(u.isEmpty() ? ChartView::channelName(m_channel)
                                      : tr("%1 (%2)", "quantity (unit)").arg(ChartView::channelName(m_channel), u));
}

void ComparisonChart::updatePauseButton()
{
    const QSignalBlocker blocker(m_pauseButton);
    m_pauseButton->setChecked(m_paused);
    m_pauseButton->setText(m_paused ? tr("Resume") : tr("Pause"));
    m_pauseButton->setToolTip(m_paused ? tr("Follow the newest data again")
                                       : tr("Freeze this chart; the data keeps being recorded"));
}

void ComparisonChart::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void ComparisonChart::showEvent(QShowEvent *event)
{
    m_dirty = true;
    QWidget::showEvent(event);
}

void ComparisonChart::resizeEvent(QResizeEvent *event)
{
    m_dirty = true;
    QWidget::resizeEvent(event);
}

void ComparisonChart::setSources(std::vector<Source> sources)
{
    m_sources = std::move(sources);
    rebuildSeries();
    m_haveYRange = false;
    m_dirty = true;
}

void ComparisonChart::rebuildSeries()
{
    for (QLineSeries *s : m_series) {
        m_chart->removeSeries(s);
        delete s;
    }
    m_series.clear();
    m_points.assign(m_sources.size(), {});
    m_offsets.assign(m_sources.size(), 0.0);
    m_drawnRevisions.assign(m_sources.size(), ~uint64_t(0));
    for (size_t i = 0; i < m_sources.size(); ++i) {
        auto *series = new QLineSeries(m_chart);
        series->setName(m_sources[i].first);
        QPen pen{QColor(kSourceColours[i % kSourceColours.size()])};
        pen.setWidthF(1.0);
        series->setPen(pen);
        m_chart->addSeries(series);
        series->attachAxis(m_axisX);
        series->attachAxis(m_axisY);
        m_series.push_back(series);
    }
}

QLineSeries *ComparisonChart::series(int index) const
{
    return index >= 0 && size_t(index) < m_series.size() ? m_series[size_t(index)] : nullptr;
}

void ComparisonChart::setChannel(Channel channel)
{
    if (channel == m_channel)
        return;
    m_channel = channel;
    {
        const QSignalBlocker blocker(m_channelCombo);
        m_channelCombo->setCurrentIndex(m_channelCombo->findData(int(channel)));
    }
    updateAxisTitles();
    m_haveYRange = false;
    m_dirty = true;
    Q_EMIT channelChanged(channel);
}

void ComparisonChart::setWindowSeconds(double seconds)
{
    if (!ChartSettings::isWindowChoice(seconds) || seconds == m_window)
        return;
    m_window = seconds;
    {
        const QSignalBlocker blocker(m_windowCombo);
        m_windowCombo->setCurrentIndex(m_windowCombo->findData(seconds));
    }
    if (m_paused)
        m_frozen.t0 = m_frozen.t1 - m_window;
    m_haveYRange = false;
    m_dirty = true;
}

void ComparisonChart::setPaused(bool paused)
{
    if (paused != m_paused) {
        m_paused = paused;
        if (paused)
            m_frozen = m_drawn.valid ? m_drawn : liveWindow();
        m_dirty = true;
    }
    updatePauseButton();
}

double ComparisonChart::sourceOffset(int index) const
{
    return index >= 0 && size_t(index) < m_offsets.size() ? m_offsets[size_t(index)] : 0.0;
}

int ComparisonChart::plotWidthPx() const
{
    const int w = int(m_chart->plotArea().width());
    return w >= 1 ? w : std::max(1, m_chartView->width() - 80);
}

void ComparisonChart::computeOffsets()
{
    // Host clocks are one monotonic clock: align every source on the earliest first sample.
    bool any = false;
    int64_t origin = 0;
    for (const auto &[label, history] : m_sources) {
        if (!history || history->empty())
            continue;
        origin = any ? std::min(origin, history->hostOriginNs()) : history->hostOriginNs();
        any = true;
    }
    for (size_t i = 0; i < m_sources.size(); ++i) {
        const plot::ChannelHistory *history = m_sources[i].second;
        m_offsets[i] = history && !history->empty() ? double(history->hostOriginNs() - origin) / 1e9 : 0.0;
    }
}

ComparisonChart::Window ComparisonChart::liveWindow() const
{
    Window w;
    w.valid = true;
    bool any = false;
    for (size_t i = 0; i < m_sources.size(); ++i) {
        const plot::ChannelHistory *history = m_sources[i].second;
        if (!history || history->empty())
            continue;
        const double newest = history->newestTime(TimeAxis::Host) + m_offsets[i];
        w.t1 = any ? std::max(w.t1, newest) : newest;
        any = true;
    }
    if (!any)
        w.t1 = m_window;
    w.t0 = w.t1 - m_window;
    return w;
}

bool ComparisonChart::refresh()
{
    if (!isVisible() || visibleRegion().isEmpty())
        return false;
    bool newData = false;
    for (size_t i = 0; i < m_sources.size(); ++i)
        if (m_sources[i].second && m_sources[i].second->revision() != m_drawnRevisions[i])
            newData = true;
    if (!m_dirty && (!newData || m_paused))
        return false;
    const std::vector<double> previousOffsets = m_offsets;
    computeOffsets();
    const Window w = m_paused ? m_frozen : liveWindow();
    const int width = plotWidthPx();
    if (!m_dirty && m_drawn.valid && m_offsets == previousOffsets &&
        std::abs(w.t1 - m_drawn.t1) < (w.t1 - w.t0) / width)
        return false; // less than a pixel column of news

    double lo = 0.0, hi = 0.0;
    bool any = false;
    for (size_t i = 0; i < m_sources.size(); ++i) {
        const plot::ChannelHistory *history = m_sources[i].second;
        QList<QPointF> &points = m_points[i];
        if (!history) {
            points.clear();
            m_series[i]->replace(points);
            continue;
        }
        const double off = m_offsets[i];
        const auto r = m_decimator.decimate(*history, m_channel, TimeAxis::Host, w.t0 - off, w.t1 - off, width,
                                            points, -off);
        m_series[i]->replace(points);
        m_drawnRevisions[i] = history->revision();
        if (r.rows > 0) {
            lo = any ? std::min(lo, r.yMin) : r.yMin;
            hi = any ? std::max(hi, r.yMax) : r.yMax;
            any = true;
        }
    }
    const double step = plot::AxisScaling::timeTickInterval(w.t1 - w.t0);
    m_axisX->setTickInterval(step);
    m_axisX->setLabelFormat(labelFormat(step));
    m_axisX->setRange(w.t0, w.t1);
    if (any) {
        m_yRange = plot::AxisScaling::autoRange(m_yRange, m_haveYRange, lo, hi, 1e-3);
        m_haveYRange = true;
        const double yStep = plot::AxisScaling::niceStep(m_yRange.span(), 5);
        m_axisY->setTickInterval(yStep);
        m_axisY->setLabelFormat(labelFormat(yStep));
        m_axisY->setRange(m_yRange.min, m_yRange.max);
    }
    m_drawn = w;
    m_drawnWidth = width;
    m_dirty = false;
    ++m_redraws;
    return true;
}

bool ComparisonChart::savePng(const QString &path, QString *error) const
{
    return ChartView::saveWidgetPng(m_chartView, path, error);
}

void ComparisonChart::saveAsPngInteractive()
{
    ChartView::savePngInteractive(this, QStringLiteral("comparison"),
                                  [this](const QString &path, QString *error) { return savePng(path, error); });
}

} // namespace imudesk::ui
