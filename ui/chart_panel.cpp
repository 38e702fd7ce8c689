#include "chart_panel.h"

#include <algorithm>

#include "chart_view.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

namespace imudesk::ui {

using plot::TimeAxis;

ChartPanel::ChartPanel(QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("chartPanel"));

    m_timeAxisLabel = new QLabel(this);
    m_timeAxisCombo = new QComboBox(this);
    m_timeAxisCombo->setObjectName(QStringLiteral("timeAxisCombo"));
    m_timeAxisLabel->setBuddy(m_timeAxisCombo);
    m_timeAxisCombo->addItem(QString(), int(TimeAxis::Device));
    m_timeAxisCombo->addItem(QString(), int(TimeAxis::Host));
    connect(m_timeAxisCombo, &QComboBox::currentIndexChanged, this,
            [this](int) { setTimeAxis(TimeAxis(m_timeAxisCombo->currentData().toInt())); });
    auto *top = new QHBoxLayout;
    top->addWidget(m_timeAxisLabel);
    top->addWidget(m_timeAxisCombo);
    top->addStretch(1);

    auto *content = new QWidget;
    content->setObjectName(QStringLiteral("chartPanelContent"));
    auto *column = new QVBoxLayout(content);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(6);
    for (int k = 0; k < kChartKindCount; ++k) {
        auto *chart = new ChartView(ChartKind(k), content);
        chart->setHistory(&m_history);
        chart->setTimeAxis(m_timeAxis);
        connect(chart, &ChartView::settingsChanged, this, &ChartPanel::settingsChanged);
        column->addWidget(chart);
        m_charts[size_t(k)] = chart;
    }
    column->addStretch(1);
    m_scroll = new QScrollArea(this);
    m_scroll->setObjectName(QStringLiteral("chartScrollArea"));
    m_scroll->setWidgetResizable(true);
    m_scroll->setFrameShape(QFrame::NoFrame);
    m_scroll->setWidget(content);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(top);
    layout->addWidget(m_scroll, 1);
    retranslateUi();
}

ChartPanel::~ChartPanel() = default;

void ChartPanel::retranslateUi()
{
    m_timeAxisLabel->setText(tr("&Time axis:"));
    m_timeAxisCombo->setItemText(0, tr("Device clock"));
    m_timeAxisCombo->setItemText(1, tr("Host arrival time"));
    m_timeAxisCombo->setToolTip(
        tr("Device clock: the module's own timestamps, where lost samples show as gaps. "
           "Host arrival time: when the samples reached this computer."));
}

void ChartPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void ChartPanel::appendSamples(const std::vector<model::Sample> &batch)
{
    m_history.append(batch);
}

void ChartPanel::clear()
{
    m_history.clear();
}

void ChartPanel::updateChartVisibility()
{
    // Before any data every chart shows; after, only those with something to show.
    const uint32_t present = m_history.empty() ? ~0u : m_history.presentChannels();
    if (present == m_shownPresence)
        return;
    m_shownPresence = present;
    for (ChartView *chart : m_charts)
        chart->setHidden((present & ChartView::channelMask(chart->kind())) == 0);
}

void ChartPanel::refresh()
{
    updateChartVisibility();
    for (ChartView *chart : m_charts)
        if (chart->refresh())
            ++m_refreshCount;
}

void ChartPanel::setUnits(const model::DisplayUnits &units)
{
    for (ChartView *chart : m_charts)
        chart->setUnits(units);
}

void ChartPanel::setHistoryMinutes(int minutes)
{
    const double seconds = std::clamp(minutes, 1, 10) * 60.0;
    m_history.setLimits(seconds, size_t(seconds * 1000.0));
}

void ChartPanel::setTimeAxis(TimeAxis axis)
{
    if (axis == m_timeAxis)
        return;
    m_timeAxis = axis;
    {
        const QSignalBlocker blocker(m_timeAxisCombo);
        m_timeAxisCombo->setCurrentIndex(m_timeAxisCombo->findData(int(axis)));
    }
    for (ChartView *chart : m_charts)
        chart->setTimeAxis(axis);
    Q_EMIT settingsChanged();
}

ChartSettings ChartPanel::settings() const
{
    ChartSettings s;
    s.timeAxis = m_timeAxis;
    for (const ChartView *chart : m_charts) {
        s.windowSeconds[size_t(chart->kind())] = chart->windowSeconds();
        for (plot::Channel c : ChartView::channelsOf(chart->kind()))
            if (!chart->isChannelVisible(c))
                s.hiddenChannels |= plot::channelBit(c);
    }
    return s;
}

void ChartPanel::setSettings(const ChartSettings &settings)
{
    const QSignalBlocker blocker(this); // the owner set them: no settingsChanged
    setTimeAxis(settings.timeAxis);
    for (ChartView *chart : m_charts) {
        chart->setWindowSeconds(settings.window(chart->kind()));
        for (plot::Channel c : ChartView::channelsOf(chart->kind()))
            chart->setChannelVisible(c, !settings.isHidden(c));
    }
}

} // namespace imudesk::ui
