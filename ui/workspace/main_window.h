#pragma once
// ImuDesk's main window: the connection bar on top and one DeviceWorkspace per
// connected device in tabs (its own session, views, console and counters). Menus act
// on the current workspace. It shows session errors without ever blocking.
#include "device/device_link.h"
#include "links/link_opener.h"
#include "sim/motion_model.h"
#include "workspace/device_workspace.h"
#include "workspace/family_ui.h"
#include "workspace/preferences.h"
#include "workspace/tool_host.h"
#include "workspace/window_settings.h"

#include <QMainWindow>
#include <QList>
#include <QPointer>
#include <QTimer>

#include <functional>

class QAction;
class QDialog;
class QDockWidget;
class QToolButton;
class QMenu;
class QMessageBox;
class QTabWidget;
class QTableView;

namespace imudesk::models {
class LatestValuesModel;
}
namespace imudesk::ui {

class BridgeController;
class ComparisonChart;
class ConnectionBar;
class ConsoleWidget;
class DeviceWorkspace;
class LiveBridgeDialog;
class PreferencesDialog;
class ResultsWindow;
class StationView;
class ToolActions;
class StatusFlagsWidget;

class MainWindow : public QMainWindow, public ToolHost {
    Q_OBJECT
public:
    using ErrorPresenter = std::function<void(const QString &message)>;

    // families: the family UI plug-ins the window shows links with (app/gui/main.cpp registers
    // them); the registry outlives the window.
    explicit MainWindow(const FamilyUiRegistry &families, const WindowSettings &settings = {}, QWidget *parent = nullptr);
    ~MainWindow() override;

    // Applies preferences to every device tab (and to tabs opened later).
    void setPreferences(const Preferences &prefs);
    const Preferences &preferences() const override { return m_prefs; }
    // Opens Edit > Preferences (not modal); accepting it applies and emits preferencesChanged.
    PreferencesDialog *openPreferences();

    // Geometry, dock layout and the last port and baud, for the owner to save.
    WindowSettings windowSettings() const;

    // Connect the current workspace (a new tab is opened when it is busy).
    void connectPort(const QString &port, int baud);
    // A simulated device of the connection bar's list (a family plug-in's), at baud (0: Auto),
    // with a serial number and noise of its own.
    bool connectSimulated(const PortChoice &choice, int baud, QString *error = nullptr);
    void disconnectDevice();
    void setSimulatedMotion(sim::Motion motion) { m_simMotion = motion; }
    sim::Motion simulatedMotion() const override { return m_simMotion; }
    // The current tab when it is idle, else a new one (for a link the user opens).
    DeviceWorkspace *freeWorkspaceForLink() override { return freeWorkspace(); }
    bool openLink(device::LinkRequest request, QString *error) override;
    // Reports a problem to the user (a non-blocking message box, or the error presenter).
    void showError(const QString &message) override { presentError(message); }
    QWidget *dialogParent() override { return this; }
    void arrangeForConfiguration() override { applyLayoutPreset(DeviceWorkspace::LayoutPreset::Configure); }
    ToolActions *tools() const { return m_tools; }

    // Workspaces (tabs).
    DeviceWorkspace *newWorkspace();
    DeviceWorkspace *currentWorkspace() const override;
    std::vector<DeviceWorkspace *> allWorkspaces() const override;
    int workspaceCount() const;
    DeviceWorkspace *workspace(int index) const;
    void closeWorkspace(int index);

    // Replaces the message box that reports session errors (tests collect them instead).
    void setErrorPresenter(ErrorPresenter presenter) { m_errorPresenter = std::move(presenter); }

    // The current workspace's pieces (the main window always has one).
    bool isSimulated() const; // the current tab's device is a simulated one
    ConsoleWidget *console() const;
    QTableView *valuesView() const;
    models::LatestValuesModel *valuesModel() const;
    StatusFlagsWidget *statusFlags() const;
    QString statusText() const;
    bool isRefreshing() const;
    ConnectionBar *connectionBar() const { return m_connectionBar; }
    ComparisonChart *comparisonChart() const { return m_comparison; }
    QDockWidget *comparisonDock() const { return m_comparisonDock; }

    // View > Layout: rearranges the current tab (and the tabs opened later) for a task.
    void applyLayoutPreset(DeviceWorkspace::LayoutPreset preset);
    // View > Reset layout: the current preset's arrangement afresh.
    void resetLayout();
    // Fits the window onto the screen it opens on (a geometry saved on a larger screen);
    // true when it had to change something.
    bool fitToScreen();
    // Shows the window as the settings left it; maximised on its screen when they hold no
    // geometry (a first run, or settings reset), whatever the screen's size (issue 53 point 17d).
    void showAsSaved();

    // Saves the window as a PNG; false with a reason when it cannot be written.
    bool saveScreenshot(const QString &path, QString *error = nullptr);

    // Tools > Production station: opens the station window, or raises the one already open.
    // A module's workspace it asks for opens here, in a free tab or a new one.
    StationView *openStation();
    StationView *station() const;
    // Tools > Live bridge: opens its window, or raises the one open. The bridge runs on when
    // the window closes; the status bar shows it while it runs.
    LiveBridgeDialog *openLiveBridge();
    BridgeController *liveBridge() const { return m_bridge; }
    // Tools > Results: opens the results window on the station's database (the line database
    // when one is set), or raises the one open.
    ResultsWindow *openResults();

Q_SIGNALS:
    // The user accepted new preferences (the owner stores them).
    void preferencesChanged(const imudesk::ui::Preferences &prefs);

protected:
    void changeEvent(QEvent *event) override;

private:
    QList<device::LinkOpener *> m_openers; // family detections under way (connectPort with baud Auto)

    void createActions();
    void createMenus();
    void retranslateUi();
    void restoreSettings(const WindowSettings &settings);

    DeviceWorkspace *freeWorkspace(); // the current one if idle, else a new tab
    // The request with what the preferences decide for it (auto-reconnect).
    device::LinkRequest withPreferences(device::LinkRequest request) const;
    // After a family detection: shows the family's session, on the port the detection opened,
    // in ws (if it is still there).
    void connectDetected(QPointer<DeviceWorkspace> ws, device::LinkOpener *opener);
    void connectSelected();
    void presentError(const QString &message);
    void showAbout();
    void openHelp(QDialog *dialog);
    void onCurrentChanged();
    void updateTitle();
    void updateActions();
    void rebuildViewMenu();
    void updateComparisonSources();
    void refreshComparison();
    void placeComparison();
    void showComparison(bool show);

    QTabWidget *m_tabs = nullptr;
    ConnectionBar *m_connectionBar = nullptr;
    QByteArray m_workspaceLayout; // applied to every new workspace
    bool m_geometryRestored = false; // the settings' geometry was restored (showAsSaved())
    ComparisonChart *m_comparison = nullptr;
    QDockWidget *m_comparisonDock = nullptr;
    QTimer m_comparisonTimer; // the comparison's view clock, only while it is shown

    QMenu *m_fileMenu = nullptr;
    QMenu *m_deviceMenu = nullptr;
    QMenu *m_viewMenu = nullptr;
    QMenu *m_helpMenu = nullptr;
    QMenu *m_toolsMenu = nullptr;
    QMenu *m_calibrateMenu = nullptr;
    ToolActions *m_tools = nullptr;
    QAction *m_newTabAction = nullptr;
    QAction *m_closeTabAction = nullptr;
    QAction *m_screenshotAction = nullptr;
    QAction *m_quitAction = nullptr;
    QAction *m_connectAction = nullptr;
    QAction *m_disconnectAction = nullptr;
    QAction *m_versionAction = nullptr;
    QAction *m_takeSampleAction = nullptr; // LOG <MSG> ONMARK ONCE
    QAction *m_aboutAction = nullptr;
    QAction *m_userGuideAction = nullptr;
    QAction *m_compareAction = nullptr;
    QAction *m_shortcutsAction = nullptr;
    QAction *m_preferencesAction = nullptr;
    QList<QAction *> m_presetActions;
    QAction *m_resetLayoutAction = nullptr;
    QAction *m_stationAction = nullptr;
    QPointer<StationView> m_station;
    QAction *m_bridgeAction = nullptr;
    BridgeController *m_bridge = nullptr;
    QPointer<LiveBridgeDialog> m_bridgeDialog;
    QAction *m_resultsAction = nullptr;
    QPointer<ResultsWindow> m_results;
    QToolButton *m_bridgeStatus = nullptr;
    DeviceWorkspace::LayoutPreset m_preset = DeviceWorkspace::LayoutPreset::Monitor;
    Preferences m_prefs;
    const FamilyUiRegistry *m_families;

    sim::Motion m_simMotion = sim::Motion::Static;
    uint64_t m_nextSimulatorSeed = 2;
    ErrorPresenter m_errorPresenter;
    QPointer<QMessageBox> m_errorBox;
};

} // namespace imudesk::ui
