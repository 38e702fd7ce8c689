#pragma once
// The production station window (issue 22): a test plan, the serial ports of a tray of modules
// and a report folder on top; Start runs the plan on every checked port at once (a
// StationRunner: one engine session per module in its own thread), and a grid of tiles shows
// each module's serial number, product, step under way, progress and verdict, with the
// failing step and its values for a module that failed. Clicking a tile opens that module's
// workspace in the main window (openWorkspaceRequested), at once for a module that is not
// under test, else when its test has ended; a finished tile's Report button opens the module's
// PDF report, and "Open run folder" the folder of the run (through the desktop's viewers, or
// an opener a test puts in their place).
//
// "Simulated tray…" starts simulated HI14 modules on pseudo-terminals (the demo: 8 modules,
// one with a noisy gyro, one mounted wrongly, one with firmware 1.6.6); the window owns them
// and stops them when it closes. Tests can have the same tray run in this process instead
// (setSimulatedTrayInProcess). The station's state (plan, settings, tray, run, summary line)
// is a station::StationSession of core's (core/station/station_session.h); this window shows
// it and gives it the checked ports. Nothing here blocks: the runner works in its sessions'
// threads, the tiles and the summary follow a StationModel that reads it on a 5 Hz clock,
// and problems (a plan that does not load, a folder that cannot be written, a report that
// failed) are shown in a message that does not wait for an answer.
#include "core/station/station_session.h"

#include <QCoreApplication>
#include <QHash>
#include <QPointer>
#include <QSet>
#include <QWidget>

#include <functional>
#include <memory>
#include <vector>

class QLabel;
class QLineEdit;
class QListWidget;
class QMessageBox;
class QPushButton;
class QScrollArea;
class QSettings;
class QUrl;


namespace imudesk::ui {

class ElidedLabel;
class LineDatabaseStatus;
class PlanEditorDialog;
class StationModel;
class StationTile;
class TileGridLayout;


class StationView : public QWidget {
    Q_OBJECT

public:
    using ErrorPresenter = std::function<void(const QString &message)>;
    // Opens a file or folder in the desktop's application for it; false when none could.
    using UrlOpener = std::function<bool(const QUrl &url)>;

    static constexpr int kDemoTraySize = station::StationSession::kDemoTraySize;
    static constexpr int kMaxTraySize = station::StationSession::kMaxTraySize;
    static constexpr int kSimulatedBaud = station::StationSession::kSimulatedBaud;
    static constexpr int kPortReleaseMs = station::StationSession::kPortReleaseMs;

    explicit StationView(QWidget *parent = nullptr);
    ~StationView() override;

    // The plan: from a file (false, and the reason shown, when it does not load), or given.
    bool openPlan(const QString &path);
    void setPlan(const station::TestPlan &plan, const QString &path);
    const station::TestPlan &plan() const { return m_session->plan(); }
    bool hasPlan() const { return m_session->hasPlan(); }
    // StationSession::demoPlan(): what --station-demo runs when no plan is given.
    static station::TestPlan demoPlan() { return station::StationSession::demoPlan(); }
    // Opens the plan in the editor (non-modal); a saved plan becomes the station's plan.
    PlanEditorDialog *editPlan();

    // Ports: the serial ports found (Refresh) and the simulated ones, each with a check box.
    void refreshPorts();
    QStringList checkedPorts() const;
    void setPortChecked(const QString &port, bool checked);
    // Starts the session's simulated tray (StationSession::startSimulatedTray) and checks only
    // its ports.
    bool startSimulatedTray(int count, bool withFaults, QString *error = nullptr);
    void stopSimulatedTray() { m_session->stopSimulatedTray(); }
    QStringList simulatedPorts() const { return m_session->simulatedPorts(); }
    // Where the next startSimulatedTray runs its modules (StationSession): on pseudo-terminals,
    // or in process (for tests: no pseudo-terminal and no simulator thread, so a loaded host
    // cannot lose bytes between module and session; a workspace cannot open such a port).
    void setSimulatedTrayInProcess(bool inProcess, double timeScale = 1.0)
    {
        m_session->setSimulatedTrayInProcess(inProcess, timeScale);
    }
    bool simulatedTrayInProcess() const { return m_session->simulatedTrayInProcess(); }

    // Where run folders are made (one per Start: "<plan>-<date>-<time>").
    QString reportFolder() const;
    void setReportFolder(const QString &dir);
    // Whether the report folder and the plan opened are remembered for the next time (off for
    // automation: a --screenshot run or a test leaves the user's settings alone).
    void setRemembering(bool on) { m_session->setRemembering(on); }
    const station::StationSettings &settings() const { return m_session->settings(); }
    // The line database button: its dialog (window-modal); OK stores URL and artifact folder.
    void editLineDatabase();

    // Runs the plan on the checked ports; false (and the reason shown) when it cannot.
    bool start();
    void cancel() { m_session->cancel(); }
    // Runs the modules that failed again, into the same run folder (their next attempt).
    void rerunFailed() { m_session->rerunFailed(); }
    bool running() const { return m_session->running(); }
    const station::StationRunner *runner() const { return m_session->runner(); }
    station::StationSession *session() const { return m_session; }
    StationModel *model() const { return m_model; }

    // "n passed · n failed · n running · n waiting", and which workspaces wait for their test.
    QString summaryText() const;
    int tileCount() const { return int(m_tiles.size()); }
    QWidget *tile(int index) const;
    int tileColumns() const;
    // Opens the module's workspace now, or when its test has ended (what a click on its tile does).
    void openModule(int index) { m_session->openModule(index); }
    // Opens the module's PDF report (its tile's Report button); false, and the reason shown,
    // while it has none yet.
    bool openReport(int index);
    // Opens the folder of the current (or last) run; false, and the reason shown, without one.
    bool openRunFolder();
    // Replaces QDesktopServices::openUrl (tests record the URLs instead).
    void setUrlOpener(UrlOpener opener) { m_urlOpener = std::move(opener); }

    // Replaces the non-modal message box (tests collect the messages instead).
    void setErrorPresenter(ErrorPresenter presenter) { m_errorPresenter = std::move(presenter); }
    // Saves the window as a PNG; false with a reason when it cannot be written.
    bool saveScreenshot(const QString &path, QString *error = nullptr);

Q_SIGNALS:
    // The user asked for this module's workspace (a click on its tile) and its port is free.
    void openWorkspaceRequested(const QString &port, int baud);

protected:
    void closeEvent(QCloseEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void showError(const QString &message);
    void choosePlan();
    void newFromExample();
    void chooseReportFolder();
    void openTrayDialog();
    void addPortItem(const QString &port, const QString &text, const QString &toolTip, bool checked);
    void rebuildTiles();
    void updateTiles(int first, int last);
    void updateSummary();
    void updateActions();
    void updatePlanLabel();
    void showNewReportErrors();
    bool openUrl(const QString &localPath);

    station::StationSession *m_session = nullptr;
    StationModel *m_model = nullptr;

    QLabel *m_planTitle = nullptr;
    ElidedLabel *m_planName = nullptr; // the plan's name and steps (elided; the whole plan in its tooltip)
    QPushButton *m_openPlan = nullptr;
    QPushButton *m_editPlan = nullptr;
    QPushButton *m_examplePlan = nullptr;
    QLabel *m_portsTitle = nullptr;
    QListWidget *m_ports = nullptr;
    QPushButton *m_refreshPorts = nullptr;
    QPushButton *m_tray = nullptr;
    QLabel *m_folderTitle = nullptr;
    QLineEdit *m_folder = nullptr;
    QPushButton *m_chooseFolder = nullptr;
    QPushButton *m_lineDatabase = nullptr;
    LineDatabaseStatus *m_upload = nullptr; // the summary line's words for the run's uploader
    QPushButton *m_start = nullptr;
    QPushButton *m_cancel = nullptr;
    QPushButton *m_rerun = nullptr;
    QPushButton *m_openFolder = nullptr;
    ElidedLabel *m_summary = nullptr;
    QLabel *m_placeholder = nullptr;
    QScrollArea *m_scroll = nullptr;
    QWidget *m_tileArea = nullptr;
    TileGridLayout *m_grid = nullptr;
    std::vector<StationTile *> m_tiles;
    QPointer<PlanEditorDialog> m_editor;

    ErrorPresenter m_errorPresenter;
    UrlOpener m_urlOpener;
    QPointer<QMessageBox> m_errorBox;
};

} // namespace imudesk::ui
