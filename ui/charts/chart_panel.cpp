#include "charts/chart_panel.h"

#include "charts/chart_view.h"

#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QEvent>
#include <QFileInfo>
#include <QGridLayout>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QPainter>
#include <QPixmap>
#include <QPushButton>
#include <QScreen>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>
#include <QToolButton>
#include <QToolTip>
#include <QVBoxLayout>

#include <algorithm>
#include <bit>

namespace imudesk::ui {

using plot::TimeAxis;

namespace {
// Sets a toolbar toggle without its toggled signal (the caller is what it would call).
void checkQuietly(QAction *action, bool on)
{
    const QSignalBlocker blocker(action);
    action->setChecked(on);
}

// Narrower than this, the charts go in one column.
constexpr int kMinimumChartWidth = 380;
constexpr int kNarrowChartWidth = 300;       // still readable: axis labels, a short legend
constexpr int kComfortableChartHeight = 200; // a column of charts lower than this goes to two columns
} // namespace

ChartPanel::ChartPanel(QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("chartPanel"));

    // One toolbar for all charts.
    m_toolBar = new QToolBar(this);
    m_toolBar->setObjectName(QStringLiteral("chartToolBar"));
    m_toolBar->setIconSize(QSize(16, 16));
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);

    m_area = new QWidget(this);
    m_area->setObjectName(QStringLiteral("chartArea"));
    m_grid = new QGridLayout(m_area);
    m_grid->setContentsMargins(0, 0, 0, 0);
    m_grid->setSpacing(4);

    auto *chartsMenu = new QMenu(this);
    chartsMenu->setObjectName(QStringLiteral("chartsMenu"));
    for (int k = 0; k < kChartKindCount; ++k) {
        const auto kind = ChartKind(k);
        auto *chart = new ChartView(kind, m_area);
        chart->setHistory(&m_history);
        chart->setTimeAxis(m_timeAxis);
        chart->hide();
        connect(chart, &ChartView::settingsChanged, this, &ChartPanel::settingsChanged);
        // The crosshair of one chart moves every other chart's to the same time.
        connect(chart, &ChartView::crosshairMoved, this, [this, chart](double x) {
            for (ChartView *other : m_charts)
                if (other != chart && !other->isHidden())
                    other->showCrosshairAt(x);
        });
        connect(chart, &ChartView::crosshairLeft, this, [this, chart] {
            for (ChartView *other : m_charts)
                if (other != chart)
                    other->hideCrosshair();
        });
        m_charts[size_t(k)] = chart;
        auto *action = chartsMenu->addAction(QString());
        action->setObjectName(QStringLiteral("chartAction_%1").arg(QLatin1String(ChartSettings::chartKey(kind))));
        action->setCheckable(true);
        action->setChecked(isChartChosen(kind));
        connect(action, &QAction::toggled, this, [this, kind](bool on) { setChartChosen(kind, on); });
        m_chartActions[size_t(k)] = action;
    }
    m_chartsButton = new QToolButton(this);
    m_chartsButton->setObjectName(QStringLiteral("chartsButton"));
    m_chartsButton->setMenu(chartsMenu);
    m_chartsButton->setPopupMode(QToolButton::InstantPopup);
    m_toolBar->addWidget(m_chartsButton);
    m_toolBar->addSeparator();

    m_windowCombo = ChartView::makeWindowChooser(this, m_window, m_windowLabel,
                                                 [this](double seconds) { setWindowSeconds(seconds); });
    m_toolBar->addWidget(m_windowLabel);
    m_toolBar->addWidget(m_windowCombo);

    m_pauseAction = m_toolBar->addAction(QString());
    m_pauseAction->setObjectName(QStringLiteral("pauseAction"));
    m_pauseAction->setCheckable(true);
    m_pauseAction->setShortcut(QKeySequence(Qt::Key_Pause));
    connect(m_pauseAction, &QAction::toggled, this, &ChartPanel::setPaused);
    m_toolBar->addSeparator();

    m_timeAxisLabel = new QLabel(this);
    m_timeAxisCombo = new QComboBox(this);
    m_timeAxisCombo->setObjectName(QStringLiteral("timeAxisCombo"));
    m_timeAxisLabel->setBuddy(m_timeAxisCombo);
    m_timeAxisCombo->addItem(QString(), int(TimeAxis::Device));
    m_timeAxisCombo->addItem(QString(), int(TimeAxis::Host));
    connect(m_timeAxisCombo, &QComboBox::currentIndexChanged, this,
            [this](int) { setTimeAxis(TimeAxis(m_timeAxisCombo->currentData().toInt())); });
    m_toolBar->addWidget(m_timeAxisLabel);
    m_toolBar->addWidget(m_timeAxisCombo);
    m_toolBar->addSeparator();

    m_cursorAction = m_toolBar->addAction(QString());
    m_cursorAction->setObjectName(QStringLiteral("cursorAction"));
    m_cursorAction->setCheckable(true);
    connect(m_cursorAction, &QAction::toggled, this, &ChartPanel::setCursorEnabled);
    m_saveAllAction = m_toolBar->addAction(style()->standardIcon(QStyle::SP_DialogSaveButton), QString());
    m_saveAllAction->setObjectName(QStringLiteral("saveAllPngAction"));
    connect(m_saveAllAction, &QAction::triggered, this, [this] {
        ChartView::savePngInteractive(this, QStringLiteral("charts"), [this](const QString &path, QString *error) {
            return saveAllPngAndSay(path, error);
        });
    });

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 0, 2, 2);
    layout->setSpacing(2);
    layout->addWidget(m_toolBar);
    layout->addWidget(m_area, 1);
    retranslateUi();
    updateChartVisibility(true);
}

ChartPanel::~ChartPanel() = default;

void ChartPanel::retranslateUi()
{
    m_chartsButton->setText(tr("Charts"));
    m_chartsButton->setToolTip(tr("Choose the charts to show; they share the area"));
    for (int k = 0; k < kChartKindCount; ++k)
        m_chartActions[size_t(k)]->setText(ChartView::title(ChartKind(k)));
    m_windowLabel->setText(tr("&Window:"));
    m_windowCombo->setToolTip(tr("Time span shown by every chart"));
    ChartView::fillWindowCombo(m_windowCombo, m_window);
    m_pauseAction->setText(m_paused ? tr("Run") : tr("Pause"));
    m_pauseAction->setToolTip(m_paused ? tr("Follow the newest data again (Pause key)")
                                       : tr("Freeze every chart; the data keeps being recorded (Pause key)"));
    m_timeAxisLabel->setText(tr("&Time axis:"));
    m_timeAxisCombo->setItemText(0, tr("Device clock"));
    m_timeAxisCombo->setItemText(1, tr("Common time"));
    m_timeAxisCombo->setToolTip(
        tr("Device clock: the module's own timestamps, where lost samples show as gaps. "
           "Common time: when each sample was taken, on this computer's clock (from the device's own "
           "clock where it has one, else when it arrived): every device on one time base."));
    m_cursorAction->setText(tr("Cursor"));
    m_cursorAction->setToolTip(tr("A crosshair that follows the mouse and reads out every chart at the same time"));
    m_saveAllAction->setText(tr("Save all as PNG…"));
    m_saveAllAction->setToolTip(tr("Save the charts shown as one PNG image"));
}

void ChartPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void ChartPanel::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    layoutCharts();
}

void ChartPanel::appendSamples(const std::vector<model::Sample> &batch)
{
    m_history.append(batch);
}

void ChartPanel::clear()
{
    m_history.clear();
    m_switchClickedAt = -1.0;
}

void ChartPanel::offerOutputSwitch(uint32_t charts, std::function<QString()> label, std::function<void()> action)
{
    m_offerCharts = charts;
    m_offerLabel = std::move(label);
    m_offerAction = std::move(action);
    for (ChartView *chart : m_charts)
        chart->clearNote(); // offered again on the next refresh
    updateChartVisibility(true);
}

QString ChartPanel::missingText(ChartKind kind)
{
    switch (kind) {
    case ChartKind::Accelerometer: return tr("This device's output carries no acceleration at its current setting.");
    case ChartKind::Gyroscope: return tr("This device's output carries no angular rate at its current setting.");
    case ChartKind::Magnetometer: return tr("This device's output carries no magnetic field at its current setting.");
    case ChartKind::Euler: return tr("This device's output carries no Euler angles at its current setting.");
    case ChartKind::Quaternion: return tr("This device's output carries no quaternion at its current setting.");
    case ChartKind::Pressure: return tr("This device's output carries no pressure at its current setting.");
    case ChartKind::Temperature: return tr("This device's output carries no temperature at its current setting.");
    case ChartKind::MagneticRelative:
        return tr("This device's output carries no relative magnetic field at its current setting.");
    }
    return {};
}

void ChartPanel::updateNotes()
{
    const double newest = m_history.empty() ? 0.0 : m_history.newestTime(TimeAxis::Host);
    const bool switchEnabled = m_switchClickedAt < 0.0 || newest - m_switchClickedAt > kSwitchWaitS;
    for (ChartView *chart : m_charts) {
        if (m_history.empty() || chart->isHidden()) {
            if (chart->hasNote())
                chart->clearNote();
            continue;
        }
        // Host time 0 is the first row: a quantity that never came counts from there.
        double seen = 0.0;
        for (plot::Channel c : ChartView::channelsOf(chart->kind()))
            seen = std::max(seen, m_history.channelSeenHost(c));
        if (newest - seen <= kMissingAfterS) {
            if (chart->hasNote())
                chart->clearNote();
            continue;
        }
        const bool offered = ((m_offerCharts >> int(chart->kind())) & 1u) && m_offerAction;
        const QString text = missingText(chart->kind());
        const QString label = offered && m_offerLabel ? m_offerLabel() : QString();
        if (chart->hasNote() && chart->noteText() == text && chart->noteButton()->text() == label
            && (!offered || chart->noteButton()->isEnabled() == switchEnabled))
            continue;
        if (!offered) {
            chart->setNote(text);
            continue;
        }
        chart->setNote(text, label,
                       [this] {
                           m_switchClickedAt = m_history.empty() ? 0.0 : m_history.newestTime(TimeAxis::Host);
                           for (ChartView *other : m_charts)
                               other->noteButton()->setEnabled(false);
                           m_offerAction();
                       },
                       switchEnabled);
    }
}

void ChartPanel::updateChartVisibility(bool force)
{
    // Before any data every chosen chart shows; after, only those with something to show (or
    // that the device's output can be switched to fill: they say so on the chart).
    uint32_t offered = 0;
    for (int k = 0; k < kChartKindCount; ++k)
        if ((m_offerCharts >> k) & 1u)
            offered |= ChartView::channelMask(ChartKind(k));
    // (A compass's relative field, which only the HEC495 sends, waits for its data.)
    const uint32_t beforeData = ~ChartView::channelMask(ChartKind::MagneticRelative);
    const uint32_t present = m_history.empty() ? beforeData : m_history.presentChannels() | offered;
    if (present == m_shownPresence && !force)
        return;
    m_shownPresence = present;
    layoutCharts();
}

void ChartPanel::layoutCharts()
{
    uint32_t shown = 0;
    std::vector<ChartView *> charts;
    for (ChartView *chart : m_charts)
        if (isChartChosen(chart->kind()) && (m_shownPresence & ChartView::channelMask(chart->kind()))) {
            shown |= 1u << int(chart->kind());
            charts.push_back(chart);
        }
    const int n = int(charts.size());
    const int w = m_area->width();
    const bool wide = w > 1.6 * std::max(1, m_area->height());
    // Two columns when there is room, or when one column of n charts would not fit the height
    // (a narrow central area, as in the Configure layout) and two narrower ones do.
    // The height counted is what the area has in a window that fits its screen: a column too
    // tall for the screen would make the window grow past it.
    int h = std::max(1, m_area->height());
    if (const QScreen *screen = this->screen())
        h = std::min(h, screen->availableGeometry().height() - (window()->height() - m_area->height()));
    const bool tooTallForOne = n >= 3 && n * kComfortableChartHeight > h && w >= 2 * kNarrowChartWidth;
    const int columns = n >= 2 && ((w >= 2 * kMinimumChartWidth && (n >= 3 || wide)) || tooTallForOne) ? 2 : 1;
    if (shown == m_shownCharts && columns == m_columns)
        return;
    m_shownCharts = shown;
    m_columns = columns;
    for (ChartView *chart : m_charts)
        m_grid->removeWidget(chart);
    for (int r = 0; r < m_grid->rowCount(); ++r)
        m_grid->setRowStretch(r, 0);
    for (int c = 0; c < m_grid->columnCount(); ++c)
        m_grid->setColumnStretch(c, 0);
    for (int i = 0; i < n; ++i) {
        // An odd last chart spans both columns.
        const int row = i / columns, column = i % columns;
        const int span = (i == n - 1 && column == 0 && columns == 2) ? 2 : 1;
        m_grid->addWidget(charts[size_t(i)], row, column, 1, span);
        m_grid->setRowStretch(row, 1);
    }
    for (int c = 0; c < columns; ++c)
        m_grid->setColumnStretch(c, 1);
    for (ChartView *chart : m_charts)
        chart->setVisible((shown >> int(chart->kind())) & 1u);
}

void ChartPanel::refresh()
{
    updateChartVisibility();
    updateNotes();
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
    if (m_paused) // the frozen range is on the other axis
        setPaused(false);
    for (ChartView *chart : m_charts)
        chart->setTimeAxis(axis);
    Q_EMIT settingsChanged();
}

void ChartPanel::setWindowSeconds(double seconds)
{
    if (!ChartSettings::isWindowChoice(seconds))
        return;
    const bool changed = seconds != m_window;
    m_window = seconds;
    {
        const QSignalBlocker blocker(m_windowCombo);
        m_windowCombo->setCurrentIndex(m_windowCombo->findData(seconds));
    }
    {
        const QSignalBlocker blocker(this); // one settingsChanged, not one per chart
        for (ChartView *chart : m_charts)
            chart->setWindowSeconds(seconds);
    }
    if (changed)
        Q_EMIT settingsChanged();
}

void ChartPanel::setPaused(bool paused)
{
    m_paused = paused;
    checkQuietly(m_pauseAction, paused);
    for (ChartView *chart : m_charts)
        chart->setPaused(paused);
    retranslateUi();
}

void ChartPanel::setCursorEnabled(bool on)
{
    m_cursorEnabled = on;
    checkQuietly(m_cursorAction, on);
    for (ChartView *chart : m_charts)
        chart->setCursorEnabled(on);
}

void ChartPanel::setChartChosen(ChartKind kind, bool chosen)
{
    if (chosen == isChartChosen(kind))
        return;
    if (chosen)
        m_hiddenCharts &= ~(1u << int(kind));
    else
        m_hiddenCharts |= 1u << int(kind);
    checkQuietly(m_chartActions[size_t(kind)], chosen);
    layoutCharts();
    Q_EMIT settingsChanged();
}

bool ChartPanel::saveAllPng(const QString &path, QString *error) const
{
    return ChartView::saveWidgetPng(m_area, path, error);
}

bool ChartPanel::saveAllPngAndSay(const QString &path, QString *error)
{
    if (!saveAllPng(path, error))
        return false;
    tellSaved(path);
    return true;
}

void ChartPanel::tellSaved(const QString &path)
{
    // Where it went, without a box to click away: the window's status bar (the panel may sit
    // in a workspace that is itself a main window: the top-level window's bar is the one seen).
    const QFileInfo file(path);
    const QString message = tr("%n chart(s) saved as one PNG in %1 (%2)", nullptr, std::popcount(m_shownCharts))
                                .arg(QDir::toNativeSeparators(file.absolutePath()), file.fileName());
    if (auto *main = qobject_cast<QMainWindow *>(window()))
        main->statusBar()->showMessage(message, kSavedMessageMs);
    else
        QToolTip::showText(m_toolBar->mapToGlobal(QPoint(0, m_toolBar->height())), message, m_toolBar, {},
                           kSavedMessageMs);
    Q_EMIT pngSaved(path, message);
}

ChartSettings ChartPanel::settings() const
{
    ChartSettings s;
    s.timeAxis = m_timeAxis;
    s.hiddenCharts = m_hiddenCharts;
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
    // One window for all charts: the first chosen chart's.
    double window = ChartSettings::kDefaultWindowSeconds;
    for (int k = kChartKindCount - 1; k >= 0; --k)
        if (!settings.isChartHidden(ChartKind(k)))
            window = settings.window(ChartKind(k));
    setWindowSeconds(window);
    for (int k = 0; k < kChartKindCount; ++k)
        setChartChosen(ChartKind(k), !settings.isChartHidden(ChartKind(k)));
    for (ChartView *chart : m_charts)
        for (plot::Channel c : ChartView::channelsOf(chart->kind()))
            chart->setChannelVisible(c, !settings.isHidden(c));
}

} // namespace imudesk::ui
