#pragma once
// ImuDesk's main window: connection bar on top, the live values table in the middle,
// the ASCII console as a dock, session state, identity, link counters and MAIN_STATUS
// flags in the status bar. It owns the DeviceSession and, for the simulated entries,
// the in-process PtySimulator the session connects to over its pseudo-terminal.
#include "device/device_session.h"
#include "sim/hipnuc_simulator.h"
#include "window_settings.h"

#include <QMainWindow>
#include <QPointer>
#include <QTimer>

#include <functional>
#include <memory>
#include <optional>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QMessageBox;
class QTableView;

namespace imudesk::models {
class LatestValuesModel;
}
namespace imudesk::sim {
class PtySimulator;
}

namespace imudesk::ui {

class ConnectionBar;
class ConsoleWidget;
class StatusFlagsWidget;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    static constexpr int kRefreshIntervalMs = 33; // 30 Hz view clock
    static constexpr int kCommandTimeoutMs = 1000;

    using ErrorPresenter = std::function<void(const QString &message)>;

    explicit MainWindow(const WindowSettings &settings = {}, QWidget *parent = nullptr);
    ~MainWindow() override;

    // Geometry, dock layout and the last port and baud, for the owner to save.
    WindowSettings windowSettings() const;

    // Opens a serial port (baud 0 = auto-detect).
    void connectPort(const QString &port, int baud);
    // Starts a simulated device on a pseudo-terminal and connects to it like to hardware
    // (baud 0 = auto-detect). The --simulate option and the simulated port entries use this.
    bool connectSimulated(const sim::SimOptions &options, int baud, QString *error = nullptr);
    void disconnectDevice();
    // Motion of the simulated devices offered in the port list.
    void setSimulatedMotion(sim::Motion motion) { m_simMotion = motion; }

    // Replaces the message box that reports session errors (tests collect them instead).
    void setErrorPresenter(ErrorPresenter presenter) { m_errorPresenter = std::move(presenter); }

    device::DeviceSession &session() { return m_session; }
    sim::PtySimulator *simulator() const { return m_simulator.get(); }
    ConnectionBar *connectionBar() const { return m_connectionBar; }
    ConsoleWidget *console() const { return m_console; }
    QTableView *valuesView() const { return m_valuesView; }
    models::LatestValuesModel *valuesModel() const { return m_valuesModel; }
    StatusFlagsWidget *statusFlags() const { return m_flags; }
    // The texts of the status bar's labels, joined by " | ".
    QString statusText() const;
    bool isRefreshing() const { return m_refreshTimer.isActive(); }

protected:
    void changeEvent(QEvent *event) override;
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;

private:
    void createActions();
    void createMenus();
    void createStatusBar();
    void retranslateUi();
    void restoreSettings(const WindowSettings &settings);
    void resizeValueColumns();

    void connectSelected();
    void sendConsoleCommand(const QString &text);
    void refreshViews();
    void stopSimulator();
    void presentError(const QString &message);
    void showAbout();

    void onStateChanged(device::SessionState state, const QString &detail);
    void onIdentityChanged(const model::DeviceIdentity &identity);
    void onStatsUpdated(const device::SessionStats &stats);
    void onBaudDetected(int baud);
    void onCommandFinished(quint64 id, const protocol::hipnuc::AsciiReply &reply);
    void onErrorOccurred(const QString &message);

    void updateStateLabel();
    void updateIdentityLabel();
    void updateStatsLabel();
    void updateTitle();
    void updateActions();

    // Declared before the session: the session (and its port) goes first on destruction.
    std::unique_ptr<sim::PtySimulator> m_simulator;
    device::DeviceSession m_session;

    models::LatestValuesModel *m_valuesModel = nullptr;
    QTableView *m_valuesView = nullptr;
    ConnectionBar *m_connectionBar = nullptr;
    ConsoleWidget *m_console = nullptr;
    QDockWidget *m_consoleDock = nullptr;
    StatusFlagsWidget *m_flags = nullptr;
    QLabel *m_stateLabel = nullptr;
    QLabel *m_identityLabel = nullptr;
    QLabel *m_statsLabel = nullptr;

    QMenu *m_fileMenu = nullptr;
    QMenu *m_deviceMenu = nullptr;
    QMenu *m_viewMenu = nullptr;
    QMenu *m_helpMenu = nullptr;
    QAction *m_quitAction = nullptr;
    QAction *m_connectAction = nullptr;
    QAction *m_disconnectAction = nullptr;
    QAction *m_versionAction = nullptr;
    QAction *m_aboutAction = nullptr;

    QTimer m_refreshTimer;
    quint64 m_shownTotal = ~quint64(0);

    device::SessionState m_state = device::SessionState::Closed;
    QString m_stateDetail;
    QString m_target; // what we connect to, as shown to the user
    std::optional<model::DeviceIdentity> m_identity;
    std::optional<device::SessionStats> m_stats;
    int m_baud = 0;
    sim::Motion m_simMotion = sim::Motion::Static;

    ErrorPresenter m_errorPresenter;
    QPointer<QMessageBox> m_errorBox;
};

} // namespace imudesk::ui
