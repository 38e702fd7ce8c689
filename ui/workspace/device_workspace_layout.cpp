// DeviceWorkspace's layout: where the docks go (the presets, a link's own docks), how big they
// are (the values table sized from its texts and rows, the attitude the rest), and the repair
// of a layout restored from another screen. The rest of the class is in device_workspace.cpp.
#include "attitude/attitude_widget.h"
#include "charts/chart_panel.h"
#include "configuration/config_panel.h"
#include "workspace/device_workspace.h"
#include "itemmodels/latest_values_model.h"

#include <QDockWidget>
#include <QEvent>
#include <QGuiApplication>
#include <QHeaderView>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QStatusBar>
#include <QStyle>
#include <QTableView>
#include <QTimer>

#include <algorithm>

namespace imudesk::ui {

void DeviceWorkspace::addLinkDock(QDockWidget *dock, LinkDockPlace place)
{
    dock->setParent(this);
    m_linkDocks << dock;
    m_linkDockPlaces.insert(dock, place);
    if (place == LinkDockPlace::BehindValues) // in front, it wants the values' room (fitDocks)
        connect(dock, &QDockWidget::visibilityChanged, this, [this] {
            if (m_shownOnce && followsWindow() && !m_refitQueued) {
                m_refitQueued = true;
                QTimer::singleShot(0, this, [this] {
                    m_refitQueued = false;
                    fitDocks();
                });
            }
        });
    placeLinkDock(dock);
    if (m_shownOnce)
        fitDocks();
}

void DeviceWorkspace::placeLinkDock(QDockWidget *dock)
{
    dock->setFloating(false);
    switch (m_linkDockPlaces.value(dock)) {
    case LinkDockPlace::OverAttitude:
        addDockWidget(Qt::RightDockWidgetArea, dock);
        tabifyDockWidget(m_attitudeDock, dock);
        dock->show();
        dock->raise();
        break;
    case LinkDockPlace::BehindValues:
        addDockWidget(Qt::RightDockWidgetArea, dock);
        tabifyDockWidget(m_valuesDock, dock);
        dock->show();
        m_valuesDock->raise();
        break;
    case LinkDockPlace::Below:
        addDockWidget(Qt::BottomDockWidgetArea, dock);
        dock->show();
        break;
    }
}

void DeviceWorkspace::placeDetailsDock()
{
    m_detailsDock->setFloating(false);
    addDockWidget(Qt::RightDockWidgetArea, m_detailsDock);
    tabifyDockWidget(m_valuesDock, m_detailsDock);
    m_detailsDock->setVisible(m_detailsOffered && m_preset != LayoutPreset::Calibrate);
    m_valuesDock->raise();
}

void DeviceWorkspace::resizeValueColumns()
{
    using Model = models::LatestValuesModel;
    // From the model's texts, not from the rows on screen: a row that appears later (a field
    // only some frames carry) fits as well.
    const QFontMetrics fm = m_valuesView->fontMetrics();
    const QFontMetrics headerFm = m_valuesView->horizontalHeader()->fontMetrics();
    constexpr int kCellPadding = 14; // the style's text margins and the grid line
    const auto textWidth = [&](int column) {
        int w = headerFm.horizontalAdvance(m_valuesModel->headerData(column, Qt::Horizontal).toString()) + 2 * kCellPadding;
        for (int r = 0; r < Model::RowCount; ++r)
            w = std::max(w, fm.horizontalAdvance(m_valuesModel->index(r, column).data().toString()) + kCellPadding);
        return w;
    };
    m_valuesView->setColumnWidth(Model::QuantityColumn, textWidth(Model::QuantityColumn));
    // Room for the longest number; the MAIN_STATUS text elides (the flags are in the status bar too).
    // A value that stopped arriving carries its age (LatestValuesModel::staleText).
    const int valueWidth = std::max(fm.horizontalAdvance(QStringLiteral("-100676.0703125")),
                                    fm.horizontalAdvance(Model::staleText(QStringLiteral("-1000.000"), 99)))
        + kCellPadding;
    m_valuesView->setColumnWidth(Model::ValueColumn, valueWidth);
    const int unitWidth = textWidth(Model::UnitColumn);
    m_valuesView->setColumnWidth(Model::UnitColumn, unitWidth);
    // The last column stretches with the dock: remember what the columns need, not what they got.
    m_valuesColumnsWidth = m_valuesView->columnWidth(Model::QuantityColumn) + valueWidth + unitWidth;
    m_valuesView->setMinimumWidth(valuesTableWidth());
}

void DeviceWorkspace::resizeDetailColumns()
{
    // Each column as wide as its widest text so far (never narrower: numbers that change do
    // not make the columns jump), the view no narrower than its columns: the right column
    // widens for them, no text is cut.
    using Model = models::LatestValuesModel;
    const QFontMetrics fm = m_detailsView->fontMetrics();
    constexpr int kCellPadding = 14;
    bool changed = false;
    for (int c = 0; c < Model::ColumnCount; ++c) {
        int w = m_detailsView->horizontalHeader()->fontMetrics().horizontalAdvance(
                    m_valuesModel->headerData(c, Qt::Horizontal).toString())
            + 2 * kCellPadding;
        for (int r = 0; r < Model::RowCount; ++r)
            if (!m_detailsView->isRowHidden(r))
                w = std::max(w, fm.horizontalAdvance(m_valuesModel->index(r, c).data().toString()) + kCellPadding);
        if (w > m_detailsColumns[size_t(c)]) {
            m_detailsColumns[size_t(c)] = w;
            m_detailsView->setColumnWidth(c, w);
            changed = true;
        }
    }
    if (changed)
        m_detailsView->setMinimumWidth(
            2 * m_detailsView->frameWidth()
            + m_detailsView->style()->pixelMetric(QStyle::PM_ScrollBarExtent, nullptr, m_detailsView->verticalScrollBar())
            + m_detailsColumns[0] + m_detailsColumns[1] + m_detailsColumns[2]);
}

int DeviceWorkspace::valuesTableWidth() const
{
    // The vertical scroll bar's width from the style: its size hint is not settled before the
    // view is first shown.
    return 2 * m_valuesView->frameWidth()
        + m_valuesView->style()->pixelMetric(QStyle::PM_ScrollBarExtent, nullptr, m_valuesView->verticalScrollBar())
        + m_valuesColumnsWidth;
}

int DeviceWorkspace::valuesTableHeight() const
{
    int rows = 0;
    for (int r = 0; r < m_valuesModel->rowCount(); ++r)
        rows += m_valuesView->isRowHidden(r) ? 0 : 1;
    const int rowsHeight = rows * m_valuesView->verticalHeader()->defaultSectionSize();
    // The tab bar of docks tabbed with the values is the main window's, not the dock's.
    bool tabbed = false;
    for (const QDockWidget *other : tabifiedDockWidgets(m_valuesDock))
        tabbed = tabbed || !other->isHidden();
    const int tabBar = tabbed ? m_valuesDock->fontMetrics().height() + 14 : 0;
    constexpr int kSlack = 20; // the separator, the layout's spacing and rounding
    // Laid out: what the dock spends besides the rows (title bar, header, frame), as measured.
    // Before that: an estimate of it.
    if (m_valuesDock->isVisible() && m_valuesView->viewport()->height() > 0)
        return m_valuesDock->height() - m_valuesView->viewport()->height() + rowsHeight + tabBar + kSlack;
    const int title = m_valuesDock->style()->pixelMetric(QStyle::PM_TitleBarHeight, nullptr, m_valuesDock);
    return title + m_valuesView->horizontalHeader()->sizeHint().height() + rowsHeight + 2 * m_valuesView->frameWidth()
        + tabBar + kSlack;
}

QString DeviceWorkspace::presetName(LayoutPreset preset)
{
    switch (preset) {
    case LayoutPreset::Monitor: return tr("&Monitor");
    case LayoutPreset::Configure: return tr("C&onfigure");
    case LayoutPreset::Calibrate: return tr("C&alibrate");
    case LayoutPreset::Analyse: return tr("A&nalyse");
    }
    return QString();
}

QString DeviceWorkspace::presetKey(LayoutPreset preset)
{
    static const char *const keys[] = {"monitor", "configure", "calibrate", "analyse"};
    return QString::fromLatin1(keys[int(preset)]);
}

std::optional<DeviceWorkspace::LayoutPreset> DeviceWorkspace::presetFromKey(const QString &key)
{
    for (int i = 0; i < kPresetCount; ++i)
        if (presetKey(LayoutPreset(i)) == key)
            return LayoutPreset(i);
    return std::nullopt;
}

QList<QPair<QDockWidget *, device::DeviceLink::Capability>> DeviceWorkspace::capabilityDocks() const
{
    using C = device::DeviceLink::Capability;
    return {{m_configDock, C::Settings},
            {m_consoleDock, C::TextCommands},
            {m_commandLogDock, C::TextCommands},
            {m_rawDock, C::RawBytes},
            {m_recordingDock, C::Recording}};
}

bool DeviceWorkspace::offersDock(const QDockWidget *dock) const
{
    for (const auto &[d, capability] : capabilityDocks())
        if (d == dock)
            return capabilities().testFlag(capability);
    return true;
}

void DeviceWorkspace::openDock(QDockWidget *dock)
{
    if (!dock || !offersDock(dock))
        return;
    dock->show();
    dock->raise();
}

void DeviceWorkspace::applyPreset(LayoutPreset preset)
{
    m_preset = preset;
    const auto offers = [this](const QDockWidget *dock) { return offersDock(dock); };
    // Every built-in dock back home, docked: values above the attitude on the right (the
    // settings behind the values), the serial panels as tabs below the charts.
    for (QDockWidget *dock : {m_valuesDock, m_attitudeDock, m_configDock}) {
        dock->setFloating(false);
        addDockWidget(Qt::RightDockWidgetArea, dock);
    }
    splitDockWidget(m_valuesDock, m_attitudeDock, Qt::Vertical);
    tabifyDockWidget(m_valuesDock, m_configDock);
    placeDetailsDock();
    const QList<QDockWidget *> bottom{m_consoleDock, m_rawDock, m_commandLogDock, m_recordingDock, m_syncDock};
    for (QDockWidget *dock : bottom) {
        dock->setFloating(false);
        addDockWidget(Qt::BottomDockWidgetArea, dock);
    }
    for (int i = 1; i < bottom.size(); ++i)
        tabifyDockWidget(bottom[i - 1], bottom[i]);

    // Calibrate gives the whole right column to the 3D attitude (the wizards show their own
    // figures); Configure gives it to the settings table.
    m_valuesDock->setVisible(preset != LayoutPreset::Calibrate);
    m_attitudeDock->setVisible(preset == LayoutPreset::Monitor || preset == LayoutPreset::Calibrate);
    m_configDock->setVisible(offers(m_configDock) && preset == LayoutPreset::Configure);
    // Configure gives the height to the charts (the settings table shows each reply; an ERR
    // opens the console); Calibrate keeps the console for the wizards' commands.
    m_consoleDock->setVisible(offers(m_consoleDock) && preset == LayoutPreset::Calibrate);
    m_rawDock->setVisible(offers(m_rawDock) && preset == LayoutPreset::Analyse);
    m_commandLogDock->setVisible(offers(m_commandLogDock) && preset == LayoutPreset::Analyse);
    m_recordingDock->setVisible(false);
    m_syncDock->setVisible(preset == LayoutPreset::Analyse);
    if (preset == LayoutPreset::Configure)
        m_configDock->raise();
    else
        m_valuesDock->raise();
    if (preset == LayoutPreset::Analyse)
        m_rawDock->raise();
    else
        m_consoleDock->raise();
    // The attached link's docks back in their places; Configure brings its settings forward.
    for (QDockWidget *dock : std::as_const(m_linkDocks)) {
        placeLinkDock(dock);
        if (preset == LayoutPreset::Configure && m_linkDockPlaces.value(dock) == LinkDockPlace::BehindValues)
            dock->raise();
    }
    if (m_shownOnce)
        fitDocks();
}

void DeviceWorkspace::fitDocks()
{
    const int w = width(), h = height() - statusBar()->sizeHint().height();
    if (w < 200 || h < 200)
        return;
    // Right column: the table in full, and at least a quarter of a large window so that the
    // attitude view gets room (the settings table wants more in Configure).
    // Configure: the settings table is what the user came for, the charts keep half the width.
    const double most = m_preset == LayoutPreset::Configure ? 0.5 : 0.45;
    int right = std::max({valuesTableWidth(), m_detailsOffered ? m_detailsView->minimumWidth() : 0, int(w * 0.24)});
    if (m_preset == LayoutPreset::Configure)
        right = std::max(right, int(w * most));
    right = std::min(right, std::max({valuesTableWidth(), m_detailsOffered ? m_detailsView->minimumWidth() : 0,
                                      int(w * most)}));
    resizeDocks({m_valuesDock}, {right}, Qt::Horizontal);
    // The panels below the charts (console, raw bytes): a quarter of the height; a link's own
    // monitor (the CAN frames) is part of what the user came for: a third, room for its rows.
    for (QDockWidget *dock : findChildren<QDockWidget *>(QString(), Qt::FindDirectChildrenOnly)) {
        if (!dock->isHidden() && !dock->isFloating() && dockWidgetArea(dock) == Qt::BottomDockWidgetArea) {
            const bool monitor = m_linkDocks.contains(dock);
            const int share = int(h * (monitor ? 0.33 : 0.24)), least = dock->minimumSizeHint().height();
            const int wanted = monitor ? share : std::clamp(dock->sizeHint().height(), std::min(least, share), share);
            resizeDocks({dock}, {wanted}, Qt::Vertical);
            break;
        }
    }
    if (!m_attitudeDock->isHidden() && !m_valuesDock->isHidden() && !m_attitudeDock->isFloating()
        && !m_valuesDock->isFloating()) {
        // The values need every row in view, the attitude takes the rest: at least 165 px (a
        // quarter of a short window; 300 px on a large one). When the rows need more than that leaves (a module that
        // sends INS or GNSS fields, on a laptop screen), the 3D view becomes a tab beside the
        // values, and comes back below them when there is room again.
        // On a large window the 3D view keeps a real size (300 px with its title), else a quarter.
        const int attitudeLeast = h >= 900 ? 300 : std::min(165, h / 4);
        const bool tabbed = tabifiedDockWidgets(m_valuesDock).contains(m_attitudeDock);
        // What is in front in the values' place: the values, or a link's panel behind them (the
        // CAN configuration), whose rows want their height as much.
        int needed = valuesTableHeight();
        for (QDockWidget *dock : std::as_const(m_linkDocks)) {
            const auto *area = qobject_cast<const QScrollArea *>(dock->widget());
            if (m_linkDockPlaces.value(dock) == LinkDockPlace::BehindValues && dock->isVisible() && !dock->isFloating()
                && area && area->widget())
                needed = std::max(needed, area->widget()->minimumSizeHint().height() + 2 * area->frameWidth()
                                              + dock->height() - area->height() + m_valuesDock->fontMetrics().height() + 14
                                              + 20); // the separator, spacing and rounding, as valuesTableHeight()
        }
        if (!tabbed && needed > h - attitudeLeast) {
            tabifyDockWidget(m_valuesDock, m_attitudeDock);
            m_valuesDock->raise();
        } else if (tabbed && needed + attitudeLeast + m_valuesDock->fontMetrics().height() + 14 <= h) {
            splitDockWidget(m_valuesDock, m_attitudeDock, Qt::Vertical);
        }
        if (!tabifiedDockWidgets(m_valuesDock).contains(m_attitudeDock)) {
            const int values = std::clamp(needed, int(h * 0.3), h - attitudeLeast);
            resizeDocks({m_valuesDock, m_attitudeDock}, {values, std::max(1, h - values)}, Qt::Vertical);
        }
    }
}

QStringList DeviceWorkspace::repairLayout()
{
    QStringList repaired;
    // A floating dock that is off every screen: dock it again.
    for (QDockWidget *dock : findChildren<QDockWidget *>(QString(), Qt::FindDirectChildrenOnly)) {
        if (!dock->isFloating() || dock->isHidden())
            continue;
        const QScreen *screen = QGuiApplication::screenAt(dock->geometry().center());
        if (!screen || !screen->availableGeometry().contains(dock->geometry())) {
            dock->setFloating(false);
            repaired << tr("%1 was floating off the screen").arg(dock->windowTitle());
        }
    }
    for (const auto &[dock, capability] : capabilityDocks())
        if (!offersDock(dock) && !dock->isHidden()) {
            dock->hide();
            repaired << tr("%1 is not used by this link").arg(dock->windowTitle());
        }
    // Squeezed areas: the charts below a third of the width, the attitude view below 120 px.
    const bool chartsSqueezed = m_charts->width() < width() / 3;
    const bool attitudeSqueezed = !m_attitudeDock->isHidden() && !m_attitudeDock->isFloating()
        && std::min(m_attitude->width(), m_attitude->height()) < 120;
    const bool valuesSqueezed = !m_valuesDock->isHidden() && !m_valuesDock->isFloating()
        && m_valuesView->viewport()->height() < m_valuesView->verticalHeader()->length() / 2;
    if (chartsSqueezed || attitudeSqueezed || valuesSqueezed) {
        repaired << (chartsSqueezed     ? tr("the charts were squeezed")
                         : attitudeSqueezed ? tr("the 3D attitude view was squeezed")
                                            : tr("the values table was squeezed"));
        // The preset's proportions, following the window from now on.
        m_layoutRestored = false;
        applyPreset(m_preset);
        return repaired;
    }
    // The values table narrower than its columns (its minimum width normally prevents it).
    if (!m_valuesDock->isHidden() && m_valuesView->width() < valuesTableWidth()) {
        resizeDocks({m_valuesDock}, {valuesTableWidth()}, Qt::Horizontal);
        repaired << tr("the values table was too narrow for its columns");
    }
    return repaired;
}

void DeviceWorkspace::resizeEvent(QResizeEvent *event)
{
    QMainWindow::resizeEvent(event);
    // The first show may come before the window is maximised or fitted to the screen.
    if (followsWindow())
        fitDocks();
}

bool DeviceWorkspace::event(QEvent *event)
{
    // A press that reaches the main window itself lands on a dock separator (its children
    // take every other press): from then on the user's sizes are kept.
    if (event->type() == QEvent::MouseButtonPress)
        m_userSized = true;
    return QMainWindow::event(event);
}

} // namespace imudesk::ui
