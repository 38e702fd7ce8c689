#include "workspace/main_window.h"

#include "ui/results/results_window.h"
#include "ui/station/station_view.h"
#include "bridge/bridge_controller.h"
#include "bridge/live_bridge_dialog.h"
#include "workspace/preferences_dialog.h"
#include "workspace/tool_actions.h"
#include "common/window_helpers.h"

#include "charts/chart_panel.h"
#include "charts/comparison_chart.h"
#include "workspace/help_dialogs.h"
#include "workspace/connection_bar.h"
#include "workspace/console_widget.h"
#include "workspace/device_workspace.h"

#include "links/serial_family.h"

#include <QAction>
#include <QActionGroup>
#include <QScreen>
#include <QDockWidget>
#include <QApplication>
#include <QEvent>
#include <QFileDialog>
#include <QImageWriter>
#include <QKeySequence>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QTabBar>
#include <QTabWidget>
#include <QThread>
#include <QStatusBar>
#include <QToolBar>
#include <QToolButton>

#include <algorithm>
#include <memory>

namespace imudesk::ui {

using device::SessionState;

MainWindow::MainWindow(const FamilyUiRegistry &families, const WindowSettings &settings, QWidget *parent)
    : QMainWindow(parent), m_families(&families)
{
    setObjectName(QStringLiteral("mainWindow"));

    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName(QStringLiteral("workspaceTabs"));
    m_tabs->setDocumentMode(true);
    m_tabs->setTabsClosable(true);
    m_tabs->setMovable(true);
    setCentralWidget(m_tabs);

    // Top: the connection bar, acting on the current workspace.
    m_connectionBar = new ConnectionBar(this);
    m_connectionBar->setSimulatedDevices([this] { return m_families->simulatedDevices(); });
    m_connectionBar->setObjectName(QStringLiteral("connectionBar"));
    auto *toolBar = new QToolBar(this);
    toolBar->setObjectName(QStringLiteral("connectionToolBar"));
    toolBar->setMovable(false);
    toolBar->setFloatable(false);
    toolBar->toggleViewAction()->setVisible(false);
    toolBar->addWidget(m_connectionBar);
    addToolBar(Qt::TopToolBarArea, toolBar);

    // Bottom, hidden at first: the same channel of every connected device on one time axis.
    m_comparison = new ComparisonChart(this);
    m_comparison->setObjectName(QStringLiteral("comparisonChart"));
    m_comparisonDock = new QDockWidget(this);
    m_comparisonDock->setObjectName(QStringLiteral("comparisonDock"));
    m_comparisonDock->setWidget(m_comparison);
    addDockWidget(Qt::BottomDockWidgetArea, m_comparisonDock);
    m_comparisonDock->hide();
    m_comparisonTimer.setInterval(50);
    connect(&m_comparisonTimer, &QTimer::timeout, this, &MainWindow::refreshComparison);
    connect(m_comparisonDock, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible)
            m_comparisonTimer.start();
        else
            m_comparisonTimer.stop();
        if (m_compareAction) {
            const QSignalBlocker blocker(m_compareAction);
            m_compareAction->setChecked(!m_comparisonDock->isHidden());
        }
    });

    createActions();
    createMenus();

    connect(m_connectionBar, &ConnectionBar::connectRequested, this, &MainWindow::connectSelected);
    connect(m_connectionBar, &ConnectionBar::disconnectRequested, this, &MainWindow::disconnectDevice);
    connect(m_connectionBar, &ConnectionBar::findDevicesRequested, this, [this] {
        if (m_tools)
            m_tools->findDevicesAction()->trigger();
    });
    connect(m_tabs, &QTabWidget::currentChanged, this, &MainWindow::onCurrentChanged);
    connect(m_tabs, &QTabWidget::tabCloseRequested, this, &MainWindow::closeWorkspace);

    restoreSettings(settings);
    newWorkspace();
    retranslateUi();
}

MainWindow::~MainWindow()
{
    // A detection still under way closes its port; its result is not wanted any more.
    for (device::LinkOpener *opener : std::as_const(m_openers)) {
        opener->disconnect(this);
        delete opener;
    }
    // Workspaces close their ports (and stop their simulators) as they go.
    m_tabs->disconnect(this);
    m_comparisonTimer.stop();
    m_comparison->setSources({}); // the histories belong to the workspaces
}

DeviceWorkspace *MainWindow::newWorkspace()
{
    auto *ws = new DeviceWorkspace(m_tabs);
    ws->applyPreset(m_preset);
    ws->restoreLayout(m_workspaceLayout);
    ws->applyPreferences(m_prefs);
    const int index = m_tabs->addTab(ws, ws->title());
    connect(ws, &DeviceWorkspace::titleChanged, this, [this, ws](const QString &title) {
        const int i = m_tabs->indexOf(ws);
        if (i >= 0) {
            m_tabs->setTabText(i, title);
            m_tabs->setTabToolTip(i, title);
        }
        updateComparisonSources();
        if (ws == currentWorkspace()) {
            updateTitle();
            m_connectionBar->setConnectedTarget(ws->target());
        }
    });
    connect(ws, &DeviceWorkspace::stateChanged, this, [this, ws](SessionState state) {
        if (ws != currentWorkspace())
            return;
        m_connectionBar->setSessionState(state);
        updateActions();
        updateTitle();
    });
    connect(ws, &DeviceWorkspace::errorReported, this, &MainWindow::presentError);
    m_tabs->setCurrentIndex(index);
    m_tabs->tabBar()->setVisible(m_tabs->count() > 1);
    updateComparisonSources();
    return ws;
}

DeviceWorkspace *MainWindow::currentWorkspace() const
{
    return qobject_cast<DeviceWorkspace *>(m_tabs->currentWidget());
}

int MainWindow::workspaceCount() const
{
    return m_tabs->count();
}

std::vector<DeviceWorkspace *> MainWindow::allWorkspaces() const
{
    std::vector<DeviceWorkspace *> out;
    for (int i = 0; i < workspaceCount(); ++i)
        out.push_back(workspace(i));
    return out;
}

DeviceWorkspace *MainWindow::workspace(int index) const
{
    return qobject_cast<DeviceWorkspace *>(m_tabs->widget(index));
}

void MainWindow::closeWorkspace(int index)
{
    DeviceWorkspace *ws = workspace(index);
    if (!ws)
        return;
    m_workspaceLayout = ws->saveLayout();
    m_tabs->removeTab(index);
    m_comparison->setSources({}); // before the history goes
    delete ws; // closes its port
    updateComparisonSources();
    if (m_tabs->count() == 0)
        newWorkspace();
    m_tabs->tabBar()->setVisible(m_tabs->count() > 1);
}

DeviceWorkspace *MainWindow::freeWorkspace()
{
    DeviceWorkspace *ws = currentWorkspace();
    return ws && !ws->isBusy() ? ws : newWorkspace();
}

WindowSettings MainWindow::windowSettings() const
{
    WindowSettings s;
    s.geometry = saveGeometry();
    s.windowState = saveState(WindowSettings::kVersion);
    s.workspaceState = currentWorkspace() ? currentWorkspace()->saveLayout() : m_workspaceLayout;
    s.preset = DeviceWorkspace::presetKey(m_preset);
    s.port = m_connectionBar->selectedPort().key();
    s.baud = m_connectionBar->selectedBaud();
    return s;
}

void MainWindow::setPreferences(const Preferences &prefs)
{
    m_prefs = prefs;
    for (int i = 0; i < workspaceCount(); ++i)
        workspace(i)->applyPreferences(prefs);
}

PreferencesDialog *MainWindow::openPreferences()
{
    auto *dialog = new PreferencesDialog(m_prefs, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        const Preferences prefs = dialog->preferences();
        if (prefs == m_prefs)
            return;
        setPreferences(prefs);
        Q_EMIT preferencesChanged(prefs);
    });
    dialog->open();
    return dialog;
}

void MainWindow::restoreSettings(const WindowSettings &settings)
{
    m_geometryRestored = !settings.geometry.isEmpty() && restoreGeometry(settings.geometry);
    if (!m_geometryRestored)
        resize(1280, 860); // the size it returns to from maximised (showAsSaved())
    fitToScreen();
    if (!settings.windowState.isEmpty())
        restoreState(settings.windowState, WindowSettings::kVersion);
    m_workspaceLayout = settings.workspaceState;
    m_preset = DeviceWorkspace::presetFromKey(settings.preset).value_or(DeviceWorkspace::LayoutPreset::Monitor);
    const PortChoice port = PortChoice::fromKey(settings.port);
    if (port.isValid())
        m_connectionBar->selectPort(port);
    m_connectionBar->selectBaud(settings.baud);
}

bool MainWindow::fitToScreen()
{
    const QScreen *screen = this->screen();
    if (!screen)
        return false;
    const QRect avail = screen->availableGeometry();
    if (isMaximized() || isFullScreen())
        return false;
    // The frame (title bar, borders) is not known before the first show: keep a margin for it.
    const QSize room = avail.size() - QSize(16, 48);
    const QSize fitted = size().boundedTo(room);
    bool changed = false;
    if (fitted != size()) {
        resize(fitted);
        changed = true;
    }
    const QRect g = frameGeometry();
    if (!avail.contains(g.topLeft()) || !avail.contains(QRect(g.topLeft(), fitted).bottomRight())) {
        move(avail.topLeft() + QPoint(std::max(0, (room.width() - fitted.width()) / 2),
                                      std::max(0, (room.height() - fitted.height()) / 2)));
        changed = true;
    }
    // A small screen (a 1366x768 laptop): use all of it.
    if (fitted.width() >= room.width() - 8 || fitted.height() >= room.height() - 8)
        setWindowState(windowState() | Qt::WindowMaximized);
    return changed;
}

void MainWindow::showAsSaved()
{
    if (m_geometryRestored)
        show();
    else
        showMaximized();
}

void MainWindow::applyLayoutPreset(DeviceWorkspace::LayoutPreset preset)
{
    m_preset = preset;
    for (int i = 0; i < m_presetActions.size(); ++i)
        m_presetActions[i]->setChecked(i == int(preset));
    if (DeviceWorkspace *ws = currentWorkspace()) {
        ws->applyPreset(preset);
        m_workspaceLayout = ws->saveLayout();
    }
}

void MainWindow::resetLayout()
{
    m_workspaceLayout.clear();
    applyLayoutPreset(m_preset);
}

void MainWindow::connectPort(const QString &port, int baud)
{
    m_connectionBar->selectPort(PortChoice::serial(port));
    m_connectionBar->selectBaud(baud);
    if (baud != 0) {
        // A rate given: the first serial family of the detection order is opened at it (the
        // others are found with Auto, or chosen in the connection bar's list of devices).
        QString error;
        if (!openLink(device::LinkRequest::serial(port, baud, device::serialFamilies().front()->id()), &error))
            presentError(error);
        return;
    }
    // Baud "Auto": the port is opened once; the detection (device::LinkOpener) tells which of
    // device::serialFamilies() is there and finds the rate, then the family's session takes the port.
    QPointer<DeviceWorkspace> ws = freeWorkspace();
    m_connectionBar->setSessionState(SessionState::Detecting);
    m_connectAction->setEnabled(false);
    auto *opener = new device::LinkOpener(this);
    m_openers.push_back(opener);
    const auto done = [this, opener] {
        m_openers.removeOne(opener);
        opener->deleteLater();
    };
    connect(opener, &device::LinkOpener::ready, this, [this, ws, opener, done] {
        connectDetected(ws, opener);
        done();
    });
    connect(opener, &device::LinkOpener::failed, this, [this, ws, done](const QString &message) {
        done();
        if (ws && ws == currentWorkspace())
            m_connectionBar->setSessionState(SessionState::Failed);
        updateActions();
        presentError(message);
    });
    opener->open(withPreferences(device::LinkRequest::serial(port, 0)));
}

void MainWindow::connectDetected(QPointer<DeviceWorkspace> ws, device::LinkOpener *opener)
{
    device::LinkOpener::Opened opened = opener->take();
    if (!ws)
        return; // the link closes with `opened`
    QString error;
    if (!showLink(*ws, *m_families, std::move(opened), opener->request(), &error))
        presentError(error);
    if (ws == currentWorkspace())
        m_connectionBar->setSessionState(ws->state());
    updateActions();
}

bool MainWindow::connectSimulated(const PortChoice &choice, int baud, QString *error)
{
    SimulationSetup setup;
    setup.baud = baud;
    setup.motion = m_simMotion;
    // Each simulated device its own serial number (and noise): two tabs on two simulated HI14
    // are two devices. The demo's module (--demo, --simulate) keeps seed 1.
    setup.seed = m_nextSimulatorSeed++;
    std::optional<device::LinkRequest> request = m_families->simulatedRequest(choice, setup);
    if (!request) {
        if (error)
            *error = tr("No device family simulates \"%1\".").arg(choice.model);
        return false;
    }
    return openLink(std::move(*request), error);
}

device::LinkRequest MainWindow::withPreferences(device::LinkRequest request) const
{
    // A real serial device that is unplugged is waited for as the preferences say (a simulated
    // one never is: its pseudo-terminal's number is reused).
    if (request.kind == device::LinkRequest::Kind::Serial && !request.simulate)
        request.autoReconnect = m_prefs.autoReconnect;
    return request;
}

bool MainWindow::openLink(device::LinkRequest request, QString *error)
{
    // A simulated serial device shows in the connection bar as the entry that opens it again.
    if (request.simulate && request.kind == device::LinkRequest::Kind::Serial)
        if (const std::optional<PortChoice> choice = m_families->simulatedChoice(request)) {
            m_connectionBar->selectPort(*choice);
            m_connectionBar->selectBaud(request.baud);
        }
    return openLinkIn(*freeWorkspace(), *m_families, withPreferences(std::move(request)), error);
}

void MainWindow::disconnectDevice()
{
    if (DeviceWorkspace *ws = currentWorkspace())
        ws->disconnectDevice();
}

void MainWindow::connectSelected()
{
    const PortChoice choice = m_connectionBar->selectedPort();
    const int baud = m_connectionBar->selectedBaud();
    switch (choice.kind) {
    case PortChoice::Kind::Serial: connectPort(choice.port, baud); break;
    case PortChoice::Kind::Simulated: {
        QString error;
        if (!connectSimulated(choice, baud, &error))
            presentError(error);
        break;
    }
    case PortChoice::Kind::None: presentError(tr("Choose a port first.")); break;
    }
}

bool MainWindow::isSimulated() const
{
    return currentWorkspace()->isSimulated();
}

ConsoleWidget *MainWindow::console() const
{
    return currentWorkspace()->console();
}

QTableView *MainWindow::valuesView() const
{
    return currentWorkspace()->valuesView();
}

models::LatestValuesModel *MainWindow::valuesModel() const
{
    return currentWorkspace()->valuesModel();
}

StatusFlagsWidget *MainWindow::statusFlags() const
{
    return currentWorkspace()->statusFlags();
}

QString MainWindow::statusText() const
{
    return currentWorkspace()->statusText();
}

bool MainWindow::isRefreshing() const
{
    return currentWorkspace()->isRefreshing();
}

bool MainWindow::saveScreenshot(const QString &path, QString *error)
{
    return WindowHelpers::saveScreenshot(this, path, error);
}

StationView *MainWindow::station() const
{
    return m_station;
}

LiveBridgeDialog *MainWindow::openLiveBridge()
{
    if (!m_bridgeDialog) {
        m_bridgeDialog = new LiveBridgeDialog(m_bridge, this);
        m_bridgeDialog->setAttribute(Qt::WA_DeleteOnClose);
    }
    m_bridgeDialog->show();
    m_bridgeDialog->raise();
    m_bridgeDialog->activateWindow();
    return m_bridgeDialog;
}

ResultsWindow *MainWindow::openResults()
{
    if (!m_results) {
        m_results = new ResultsWindow(this);
        m_results->setAttribute(Qt::WA_DeleteOnClose);
        // The station window's settings as they are now, else as saved.
        m_results->openLocation(m_station ? m_station->settings().resultsDatabase() : ResultsWindow::stationDatabase());
    }
    m_results->show();
    m_results->raise();
    m_results->activateWindow();
    return m_results;
}

StationView *MainWindow::openStation()
{
    if (!m_station) {
        auto *view = new StationView(this);
        view->setAttribute(Qt::WA_DeleteOnClose);
        connect(view, &StationView::openWorkspaceRequested, this, [this](const QString &port, int baud) {
            // The module's workspace in a free tab (or a new one), and this window in front.
            connectPort(port, baud);
            if (isMinimized())
                showNormal();
            show();
            raise();
            activateWindow();
        });
        m_station = view;
    }
    m_station->show();
    m_station->raise();
    m_station->activateWindow();
    return m_station;
}

void MainWindow::presentError(const QString &message)
{
    if (m_errorPresenter) {
        m_errorPresenter(message);
        return;
    }
    WindowHelpers::showError(this, m_errorBox, tr("ImuDesk"), message);
}

void MainWindow::showAbout()
{
    QMessageBox::about(this, tr("About ImuDesk"),
                       tr("<h3>ImuDesk %1</h3><p>A bench tool for IMU, AHRS and compass modules on serial, RS-485 "
                          "Modbus and CAN links: live values and charts, settings, calibration, firmware "
                          "updates, recordings and simulated devices.</p><p>Built with Qt %2.</p>")
                           .arg(QCoreApplication::applicationVersion(), QString::fromLatin1(qVersion())));
}

void MainWindow::onCurrentChanged()
{
    DeviceWorkspace *ws = currentWorkspace();
    if (!ws)
        return;
    m_connectionBar->setSessionState(ws->state());
    m_connectionBar->setConnectedTarget(ws->target());
    rebuildViewMenu();
    updateActions();
    updateTitle();
}

void MainWindow::updateTitle()
{
    const QString base = tr("ImuDesk – IMU bench tool");
    const DeviceWorkspace *ws = currentWorkspace();
    if (ws && ws->isBusy() && ws->identity() && !ws->identity()->productName.empty())
        setWindowTitle(tr("%1 – %2").arg(QString::fromStdString(ws->identity()->productName), base));
    else
        setWindowTitle(base);
}

void MainWindow::updateActions()
{
    const DeviceWorkspace *ws = currentWorkspace();
    const bool busy = ws && ws->isBusy();
    m_connectAction->setEnabled(!busy);
    m_disconnectAction->setEnabled(busy);
    const bool connected = ws && ws->state() == SessionState::Connected;
    m_versionAction->setEnabled(connected && ws->offersTool(DeviceWorkspace::LinkTool::ReadVersion));
    m_takeSampleAction->setEnabled(connected && ws->offersTool(DeviceWorkspace::LinkTool::TakeSample));
    m_tools->update(ws);
}

void MainWindow::rebuildViewMenu()
{
    m_viewMenu->clear();
    m_viewMenu->addActions(m_presetActions);
    m_viewMenu->addAction(m_resetLayoutAction);
    m_viewMenu->addSeparator();
    if (DeviceWorkspace *ws = currentWorkspace())
        m_viewMenu->addActions(ws->dockActions());
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(m_compareAction);
}

void MainWindow::showComparison(bool show)
{
    if (show) {
        placeComparison(); // before it is shown: a dock shown first would grow the window at once
        m_comparisonDock->show();
        m_comparisonDock->raise();
    } else {
        m_comparisonDock->hide();
    }
}

void MainWindow::placeComparison()
{
    // Docked below the tabs when the window can give it its height; on a short screen (a
    // 1366x768 laptop, where a tab's charts, values and 3D view already take every row) the
    // window would grow past the screen's bottom (878 px on 768): there the comparison opens
    // as a window of its own over the lower part of the screen, and the main window stays.
    const QScreen *screen = this->screen();
    if (!screen || m_comparisonDock->isFloating() || !m_comparisonDock->isHidden())
        return;
    const QRect avail = screen->availableGeometry();
    const bool maximized = isMaximized() || isFullScreen();
    const int frame = maximized ? 0 : frameGeometry().height() - geometry().height();
    // What the window needs with the dock: its bars as they are, the tab at the height it asks
    // for (its charts, values and 3D view in full: below it the tab's own docks resize
    // themselves and the window grows, 798 px on a 768-px screen, measured) and the dock at
    // the height it asks for, with the separator.
    const int bars = height() - centralWidget()->height();
    const int needed = bars + std::max(centralWidget()->sizeHint().height(), centralWidget()->minimumSizeHint().height())
        + std::max(m_comparisonDock->sizeHint().height(), m_comparisonDock->minimumSizeHint().height()) + 10 + frame;
    if (needed <= avail.height())
        return;
    const int h = std::max(m_comparisonDock->minimumSizeHint().height(), avail.height() * 2 / 5);
    m_comparisonDock->setFloating(true);
    // Above the status bar, where the counters stay readable.
    m_comparisonDock->setGeometry(avail.left() + avail.width() / 8, avail.bottom() - h - 44, avail.width() * 3 / 4, h);
}

void MainWindow::refreshComparison()
{
    // A tab in front feeds its history on its own view clock; the others stop theirs while
    // hidden, so the comparison feeds them: every connected device is drawn live.
    for (int i = 0; i < m_tabs->count(); ++i)
        if (DeviceWorkspace *ws = workspace(i); ws && ws != currentWorkspace())
            ws->pullSamples();
    m_comparison->refresh();
}

void MainWindow::updateComparisonSources()
{
    // One legend name per device: tabs with the same title (two simulated HI14) are told
    // apart by their serial number, or by their tab's number while none is known.
    std::vector<QString> titles;
    for (int i = 0; i < m_tabs->count(); ++i)
        titles.push_back(workspace(i) ? workspace(i)->title() : QString());
    std::vector<ComparisonChart::Source> sources;
    for (int i = 0; i < m_tabs->count(); ++i) {
        DeviceWorkspace *ws = workspace(i);
        if (!ws)
            continue;
        QString label = titles[size_t(i)];
        if (std::count(titles.begin(), titles.end(), label) > 1) {
            const auto &id = ws->identity();
            label = id && !id->serial.empty()
                        ? tr("%1, serial %2").arg(label, QString::fromStdString(id->serial))
                        : tr("%1 (tab %2)").arg(label).arg(i + 1);
        }
        sources.emplace_back(label, &ws->chartPanel()->history());
    }
    m_comparison->setSources(std::move(sources));
}

void MainWindow::createActions()
{
    auto *presetGroup = new QActionGroup(this);
    for (int i = 0; i < DeviceWorkspace::kPresetCount; ++i) {
        auto *action = new QAction(this);
        action->setObjectName(QStringLiteral("layoutPreset_%1").arg(DeviceWorkspace::presetKey(DeviceWorkspace::LayoutPreset(i))));
        action->setCheckable(true);
        action->setShortcut(QKeySequence(Qt::ALT | Qt::SHIFT | Qt::Key(Qt::Key_1 + i)));
        presetGroup->addAction(action);
        connect(action, &QAction::triggered, this, [this, i] { applyLayoutPreset(DeviceWorkspace::LayoutPreset(i)); });
        m_presetActions << action;
    }
    m_resetLayoutAction = new QAction(this);
    m_resetLayoutAction->setObjectName(QStringLiteral("resetLayoutAction"));
    connect(m_resetLayoutAction, &QAction::triggered, this, &MainWindow::resetLayout);

    m_newTabAction = new QAction(this);
    m_newTabAction->setObjectName(QStringLiteral("newTabAction"));
    m_newTabAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_T));
    connect(m_newTabAction, &QAction::triggered, this, [this] { newWorkspace(); });

    m_closeTabAction = new QAction(this);
    m_closeTabAction->setObjectName(QStringLiteral("closeTabAction"));
    m_closeTabAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_W));
    connect(m_closeTabAction, &QAction::triggered, this, [this] { closeWorkspace(m_tabs->currentIndex()); });

    m_screenshotAction = new QAction(this);
    m_screenshotAction->setObjectName(QStringLiteral("screenshotAction"));
    m_screenshotAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
    connect(m_screenshotAction, &QAction::triggered, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save screenshot"), QStringLiteral("imudesk.png"),
                                                          tr("PNG images (*.png)"));
        QString error;
        if (!path.isEmpty() && !saveScreenshot(path, &error))
            presentError(error);
    });

    m_quitAction = new QAction(this);
    m_quitAction->setObjectName(QStringLiteral("quitAction"));
    m_quitAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Q));
    m_quitAction->setMenuRole(QAction::QuitRole);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);

    m_connectAction = new QAction(this);
    m_connectAction->setObjectName(QStringLiteral("connectAction"));
    m_connectAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_K));
    connect(m_connectAction, &QAction::triggered, this, &MainWindow::connectSelected);

    m_disconnectAction = new QAction(this);
    m_disconnectAction->setObjectName(QStringLiteral("disconnectAction"));
    m_disconnectAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    connect(m_disconnectAction, &QAction::triggered, this, &MainWindow::disconnectDevice);

    m_versionAction = new QAction(this);
    m_versionAction->setObjectName(QStringLiteral("versionAction"));
    connect(m_versionAction, &QAction::triggered, this, [this] {
        // The family's "who are you", shown in the console with its answer.
        if (DeviceWorkspace *ws = currentWorkspace())
            ws->runTool(DeviceWorkspace::LinkTool::ReadVersion, this);
    });

    m_takeSampleAction = new QAction(this);
    m_takeSampleAction->setObjectName(QStringLiteral("takeSampleAction"));
    m_takeSampleAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_T));
    connect(m_takeSampleAction, &QAction::triggered, this, [this] {
        // One frame on request, shown in the console.
        if (DeviceWorkspace *ws = currentWorkspace())
            ws->runTool(DeviceWorkspace::LinkTool::TakeSample, this);
    });

    m_preferencesAction = new QAction(this);
    m_preferencesAction->setObjectName(QStringLiteral("preferencesAction"));
    m_preferencesAction->setMenuRole(QAction::PreferencesRole);
    m_preferencesAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Comma));
    connect(m_preferencesAction, &QAction::triggered, this, &MainWindow::openPreferences);

    m_stationAction = new QAction(this);
    m_stationAction->setObjectName(QStringLiteral("stationAction"));
    m_stationAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
    connect(m_stationAction, &QAction::triggered, this, [this] { openStation(); });

    // Tools > Live bridge; while it runs, the window's status bar says where and how it goes
    // (a click on it opens the bridge's window).
    m_bridge = new BridgeController(
        [this] {
            std::vector<BridgedLink> shown;
            for (DeviceWorkspace *ws : allWorkspaces())
                shown.push_back(BridgedLink{&ws->link(), ws->identity()});
            return shown;
        },
        this);
    m_bridgeAction = new QAction(this);
    m_bridgeAction->setObjectName(QStringLiteral("liveBridgeAction"));
    m_bridgeAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_B));
    connect(m_bridgeAction, &QAction::triggered, this, [this] { openLiveBridge(); });
    // Tools > Results. (Ctrl+Shift+H is Calibration history's: D for database.)
    m_resultsAction = new QAction(this);
    m_resultsAction->setObjectName(QStringLiteral("resultsAction"));
    m_resultsAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_D));
    connect(m_resultsAction, &QAction::triggered, this, [this] { openResults(); });
    m_bridgeStatus = new QToolButton(this);
    m_bridgeStatus->setObjectName(QStringLiteral("bridgeStatusButton"));
    m_bridgeStatus->setAutoRaise(true);
    connect(m_bridgeStatus, &QToolButton::clicked, this, [this] { openLiveBridge(); });
    statusBar()->addPermanentWidget(m_bridgeStatus);
    statusBar()->setSizeGripEnabled(false);
    statusBar()->hide();
    connect(m_bridge, &BridgeController::statusChanged, this, [this](const QString &text) {
        m_bridgeStatus->setText(text);
        statusBar()->setVisible(!text.isEmpty());
    });

    m_aboutAction = new QAction(this);
    m_aboutAction->setObjectName(QStringLiteral("aboutAction"));
    m_aboutAction->setMenuRole(QAction::AboutRole);
    connect(m_aboutAction, &QAction::triggered, this, &MainWindow::showAbout);

    m_compareAction = new QAction(this);
    m_compareAction->setObjectName(QStringLiteral("compareDevicesAction"));
    m_compareAction->setCheckable(true);
    m_compareAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C));
    connect(m_compareAction, &QAction::triggered, this, &MainWindow::showComparison);

    m_userGuideAction = new QAction(this);
    m_userGuideAction->setObjectName(QStringLiteral("userGuideAction"));
    m_userGuideAction->setShortcut(QKeySequence::HelpContents);
    connect(m_userGuideAction, &QAction::triggered, this, [this] { openHelp(new UserGuideDialog(this)); });

    m_shortcutsAction = new QAction(this);
    m_shortcutsAction->setObjectName(QStringLiteral("shortcutsAction"));
    m_shortcutsAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Slash));
    connect(m_shortcutsAction, &QAction::triggered, this,
            [this] { openHelp(new ShortcutsDialog(findChildren<QAction *>(), this)); });
}

void MainWindow::openHelp(QDialog *dialog)
{
    // One of each at a time, not modal: the guide stays open beside the window.
    for (QDialog *open : findChildren<QDialog *>(dialog->objectName(), Qt::FindDirectChildrenOnly))
        if (open != dialog)
            open->close();
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
    dialog->raise();
}

void MainWindow::createMenus()
{
    m_fileMenu = menuBar()->addMenu(QString());
    m_fileMenu->addAction(m_newTabAction);
    m_fileMenu->addAction(m_closeTabAction);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_screenshotAction);
    m_fileMenu->addAction(m_preferencesAction);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_quitAction);
    m_deviceMenu = menuBar()->addMenu(QString());
    m_deviceMenu->addAction(m_connectAction);
    m_deviceMenu->addAction(m_disconnectAction);
    m_deviceMenu->addSeparator();
    m_deviceMenu->addAction(m_versionAction);
    m_deviceMenu->addAction(m_takeSampleAction);
    m_viewMenu = menuBar()->addMenu(QString());
    m_calibrateMenu = menuBar()->addMenu(QString());
    m_toolsMenu = menuBar()->addMenu(QString());
    m_tools = new ToolActions(this, this);
    m_tools->addToMenus(m_fileMenu, m_deviceMenu, m_calibrateMenu, m_toolsMenu);
    m_toolsMenu->addSeparator();
    m_toolsMenu->addAction(m_stationAction);
    m_toolsMenu->addAction(m_bridgeAction);
    m_toolsMenu->addAction(m_resultsAction);
    m_helpMenu = menuBar()->addMenu(QString());
    m_helpMenu->addAction(m_userGuideAction);
    m_helpMenu->addAction(m_shortcutsAction);
    m_helpMenu->addSeparator();
    m_helpMenu->addAction(m_aboutAction);
}

void MainWindow::retranslateUi()
{
    m_fileMenu->setTitle(tr("&File"));
    m_deviceMenu->setTitle(tr("&Device"));
    m_viewMenu->setTitle(tr("&View"));
    m_helpMenu->setTitle(tr("&Help"));
    m_newTabAction->setText(tr("&New connection tab"));
    m_newTabAction->setStatusTip(tr("Open a tab for another device; each tab has its own connection and views"));
    m_closeTabAction->setText(tr("&Close tab"));
    m_screenshotAction->setText(tr("Save &screenshot…"));
    m_quitAction->setText(tr("&Quit"));
    m_connectAction->setText(tr("&Connect"));
    m_connectAction->setStatusTip(tr("Connect to the port chosen in the connection bar"));
    m_disconnectAction->setText(tr("&Disconnect"));
    m_versionAction->setText(tr("Send LOG &VERSION"));
    m_versionAction->setStatusTip(tr("Ask the device for its product name, firmware and serial number"));
    m_takeSampleAction->setText(tr("&Take one sample"));
    m_takeSampleAction->setStatusTip(tr("Send LOG … ONMARK ONCE: the module outputs one frame of the type it sends, "
                                        "as a pulse on SYNC_IN would trigger"));
    m_takeSampleAction->setToolTip(m_takeSampleAction->statusTip());
    m_aboutAction->setText(tr("&About ImuDesk"));
    m_compareAction->setText(tr("Compare &devices"));
    m_compareAction->setStatusTip(tr("One channel of every connected device on one time axis, live whichever tab "
                                     "is in front"));
    m_userGuideAction->setText(tr("&User guide"));
    m_userGuideAction->setStatusTip(tr("How to connect, chart, configure, calibrate, update, record and test a tray"));
    m_shortcutsAction->setText(tr("&Keyboard shortcuts"));
    m_shortcutsAction->setStatusTip(tr("Every key combination of this window, with what it does"));
    m_preferencesAction->setText(tr("&Preferences…"));
    for (int i = 0; i < m_presetActions.size(); ++i) {
        const auto preset = DeviceWorkspace::LayoutPreset(i);
        m_presetActions[i]->setText(tr("Layout: %1").arg(DeviceWorkspace::presetName(preset)));
        m_presetActions[i]->setChecked(preset == m_preset);
    }
    m_presetActions[0]->setStatusTip(tr("Charts, the values table and the 3D attitude"));
    m_presetActions[1]->setStatusTip(tr("The device's settings beside the charts"));
    m_presetActions[2]->setStatusTip(tr("A large 3D attitude view and the console"));
    m_presetActions[3]->setStatusTip(tr("Charts, the values, the raw bytes and the command log"));
    m_stationAction->setText(tr("&Production station…"));
    m_stationAction->setStatusTip(tr("Test a tray of modules at once against a test plan: a verdict and a report "
                                     "per serial number"));
    m_bridgeAction->setText(tr("&Live bridge…"));
    m_bridgeAction->setStatusTip(tr("Send the connected devices' samples live to Foxglove, Lichtblick and PlotJuggler"));
    m_bridgeStatus->setToolTip(tr("The live bridge is running: click to open its window"));
    m_resultsAction->setText(tr("&Results…"));
    m_resultsAction->setStatusTip(tr("Every module the station tested: search by serial number, each attempt's "
                                     "measurements, the yield and a measurement's trend with Cpk"));
    m_resetLayoutAction->setText(tr("&Reset layout"));
    m_resetLayoutAction->setStatusTip(tr("Put every panel of this tab back where the chosen layout has it"));
    m_tools->retranslate();
    if (auto *bar = findChild<QToolBar *>(QStringLiteral("connectionToolBar")))
        bar->setWindowTitle(tr("Connection"));
    m_comparisonDock->setWindowTitle(tr("Compare devices"));
    updateTitle();
}

void MainWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange && m_fileMenu)
        retranslateUi();
    QMainWindow::changeEvent(event);
}

} // namespace imudesk::ui
