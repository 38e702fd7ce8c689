#pragma once
// One connected device: its link (any family's, with what it needs, e.g. a simulator), live
// views and counters. The main window shows one workspace per tab. A workspace is a QMainWindow
// of its own so that its docks (values, console, ...) can be rearranged; the arrangement is
// saved and restored by the main window.
//
// Folder ui/workspace/: the application shell. MainWindow with one DeviceWorkspace per tab, the
// connection bar, the port choice, the tool actions, the preferences and their dialog, window
// settings, the size of work-place dialogs, the language switcher, the workspace's docks
// (console, command log, raw bytes, status flags) and the painting helpers shared by
// self-painted widgets. It mirrors core/device: a workspace holds one device::DeviceLink and
// shows the docks its capabilities() call for; the family's UI plug-in (ui/families) adds that
// family's docks, settings panel and tools. Its views read the link's SampleStore and
// RawByteLog on the view clock; the values dock shows models::LatestValuesModel and the
// command log models::CommandLogModel, each in a QTableView (the console's completer uses a
// QStringListModel).
#include "device/device_link.h"
#include "workspace/preferences.h"

#include <QElapsedTimer>
#include <QHash>
#include <QMainWindow>
#include <QPointer>
#include <QTimer>

#include <array>
#include <functional>
#include <memory>
#include <optional>

class QDockWidget;
class QLabel;
class QTableView;

namespace imudesk::verify {
class LiveReference;
}

namespace imudesk::models {
class LatestValuesModel;
class ClockStatsModel;
}

namespace imudesk::ui {

class AttitudeWidget;
class ChartPanel;
class CommandLogWidget;
class ConfigPanel;
class ConsoleWidget;
class RecordingControls;
class RawBytesView;
class StatusFlagsWidget;

class DeviceWorkspace : public QMainWindow {
    Q_OBJECT
public:
    // Arrangements of the docks for a task (View menu). Monitor: charts, values and the 3D
    // attitude; Configure: the settings table and the console; Calibrate: values, a large
    // attitude view and the console; Analyse: charts, values, raw bytes and the command log.
    // The panels below the charts (console, raw bytes, command log, recording) start closed
    // and open on demand; a link that has no use for them (by its capabilities)
    // does not offer them.
    enum class LayoutPreset { Monitor, Configure, Calibrate, Analyse };
    static constexpr int kPresetCount = 4;
    static QString presetName(LayoutPreset preset); // translated, with a mnemonic
    static QString presetKey(LayoutPreset preset);  // "monitor", for settings
    static std::optional<LayoutPreset> presetFromKey(const QString &key);

    static constexpr int kRefreshIntervalMs = 30; // default 33 Hz view clock (<= 60 Hz, >= 30 charts/s)
    static constexpr int kValuesIntervalMs = 100; // the values table and status flags: at most 10 Hz
    static constexpr int kStaleCheckIntervalMs = 1000; // without new samples: the values' ages
    static constexpr size_t kMaxSamplesPerTick = 20000; // a stalled GUI catches up without a burst
    static constexpr int kCommandTimeoutMs = 1000;

    explicit DeviceWorkspace(QWidget *parent = nullptr);
    ~DeviceWorkspace() override;

    // Shows a link (device::LinkOpener made it, a family's UI plug-in attaches it, ui/families)
    // in this workspace's live views in place of the current one. `keepAlive` holds what the
    // link needs (e.g. its simulator) and is released when the link closes or fails; `start`
    // opens the link (startLink(), and again after releasePort()); `address` is what it opens
    // (a port, a bus, a file). False while busy.
    bool attachLink(std::unique_ptr<device::DeviceLink> link, const QString &target,
                    std::shared_ptr<void> keepAlive = {}, std::function<void()> start = {},
                    const QString &address = {});
    // Opens the attached link.
    void startLink();
    // The link the views show (device::NoLink in a new workspace).
    device::DeviceLink &link() { return *m_link; }
    const device::DeviceLink &link() const { return *m_link; }
    device::DeviceLink::Capabilities capabilities() const { return m_link->capabilities(); }
    // Where a link's dock goes: as a tab in front of the 3D attitude (a view that replaces it,
    // the compass dial), as a tab behind the values (settings, registers: the values stay in
    // front), or below the charts (monitors and transport controls).
    enum class LinkDockPlace { OverAttitude, BehindValues, Below };
    // What the attached link's family offers in the Tools and Calibrate menus beyond the
    // capabilities (a bus scan, the compass's own calibration, a firmware update over the port
    // or the bus). Offered by the family's UI plug-in (ui/families); withdrawn with the link.
    // ReadVersion: ask the device who it is (Device > Version); TakeSample: one frame on request;
    // Profiles: save and apply the device's settings; the calibrations of the Calibrate menu.
    enum class LinkTool {
        ScanBus,
        CompassCalibration,
        FirmwareUpdate,
        ReadVersion,
        TakeSample,
        Profiles,
        MagCalibration,
        GyroCalibration,
        AttitudeReset,
        VerifyModule,
    };
    using ToolRunner = std::function<void(QWidget *dialogParent)>;
    void offerTool(LinkTool tool, ToolRunner run);
    bool offersTool(LinkTool tool) const { return m_linkTools.contains(int(tool)); }
    // Opens the tool's dialog or wizard; false when the link offers no such tool.
    bool runTool(LinkTool tool, QWidget *dialogParent);
    // A dock that belongs to the attached link (register browser, CAN monitor, replay
    // controls, ...): shown while the link is attached, deleted with it.
    void addLinkDock(QDockWidget *dock, LinkDockPlace place);
    QList<QDockWidget *> linkDocks() const { return m_linkDocks; }
    // The settings of a link with Capability::Settings (null for other links), and the
    // recording controls.
    ConfigPanel *configPanel() const { return m_configPanel; }
    // The attached link's settings panel (its family's plug-in makes it); deleted with the link.
    void setConfigPanel(ConfigPanel *panel);
    // The rate the link runs at, as soon as a detection found it (the statistics bring it too).
    void noteBaud(int baud);
    QDockWidget *configDock() const { return m_configDock; }
    RecordingControls *recordingControls() const { return m_recording; }
    QDockWidget *recordingDock() const { return m_recordingDock; }
    void disconnectDevice();
    bool isBusy() const;
    // Units, attitude frame, refresh rate, chart history and auto-reconnect.
    void applyPreferences(const Preferences &prefs);

    // Sends a command as typed in the console (shown there with its reply).
    void sendConsoleCommand(const QString &text);
    // A command a family's tool sent (typed, by its builders) under the link's request id:
    // shown in the console and the command log like a typed one, its reply following by id.
    void showSentCommand(quint64 id, const QString &text);

    // The link's far end is a simulated device (what it needs is kept alive with it).
    bool isSimulated() const { return m_linkKeepAlive != nullptr; }
    // What the link needs (its simulator), for whoever made the link and knows its type.
    const std::shared_ptr<void> &linkKeepAlive() const { return m_linkKeepAlive; }
    // Frees the link's port for another user (the firmware update), keeping a simulated module
    // running behind it; returns the port. reclaimPort() opens the link on it again.
    QString releasePort();
    // `open`: how to open the link again this once (e.g. at the rate a firmware update found
    // the module at); empty: as it was opened first.
    void reclaimPort(const std::function<void()> &open = {});
    // What the link opens ("/dev/ttyUSB0", the simulator's pseudo-terminal).
    QString address() const { return m_address; }
    device::SessionState state() const { return m_state; }
    // What the user connected to ("/dev/ttyUSB0", "Simulated HI14 (firmware 1.7.1)").
    QString target() const { return m_target; }
    const std::optional<model::DeviceIdentity> &identity() const { return m_identity; }
    int baud() const { return m_baud; }
    // A short name for the tab: product and port, or "New connection".
    QString title() const;

    ConsoleWidget *console() const { return m_console; }
    ChartPanel *chartPanel() const { return m_charts; }
    AttitudeWidget *attitudeWidget() const { return m_attitude; }
    RawBytesView *rawBytesView() const { return m_rawView; }
    CommandLogWidget *commandLog() const { return m_commandLog; }
    QTableView *valuesView() const { return m_valuesView; }
    QTableView *detailsView() const { return m_detailsView; }
    QDockWidget *detailsDock() const { return m_detailsDock; }
    models::LatestValuesModel *valuesModel() const { return m_valuesModel; }
    StatusFlagsWidget *statusFlags() const { return m_flags; }
    // The texts of the status bar's labels, joined by " | ".
    QString statusText() const;
    bool isRefreshing() const { return m_refreshTimer.isActive(); }
    // The dock toggles for the View menu.
    QList<QAction *> dockActions() const;

    QByteArray saveLayout() const;
    bool restoreLayout(const QByteArray &state);
    // Rearranges the docks for a task and sizes them for this workspace's size.
    void applyPreset(LayoutPreset preset);
    LayoutPreset preset() const { return m_preset; }
    // Checks the arrangement against the workspace's size and content (a dock narrower than
    // its table, an attitude view or chart area squeezed to a sliver, a floating dock off
    // screen) and repairs it; returns what it repaired (empty when nothing was wrong).
    // Runs by itself on the first show after restoreLayout().
    QStringList repairLayout();
    // The width the values table needs to show every column in full.
    // The height the values dock needs for every row it shows, without a scroll bar.
    int valuesTableHeight() const;
    int valuesTableWidth() const;
    // Docks, for the View menu, the presets and tests.
    QDockWidget *valuesDock() const { return m_valuesDock; }
    QDockWidget *attitudeDock() const { return m_attitudeDock; }
    QDockWidget *consoleDock() const { return m_consoleDock; }
    QDockWidget *rawBytesDock() const { return m_rawDock; }
    QDockWidget *commandLogDock() const { return m_commandLogDock; }
    // The clocks of the link (issue 36): how each stream's samples get their common time.
    QDockWidget *syncDock() const { return m_syncDock; }
    const models::ClockStatsModel *clockModel() const { return m_clockModel; }
    // Whether the current link has a use for `dock` (by its capabilities).
    bool offersDock(const QDockWidget *dock) const;
    // Shows a dock the link offers and brings it to the front.
    void openDock(QDockWidget *dock);

    void refreshViews();
    // Moves the samples that arrived since the last call into the charts' history, without
    // drawing: the view clock calls it on screen, and the comparison's clock for a tab that is
    // not in front, so that every connected device is compared live.
    void pullSamples();

Q_SIGNALS:
    void stateChanged(imudesk::device::SessionState state);
    void titleChanged(const QString &title);
    // A session error for the user (already logged in the console); the main window shows it.
    void errorReported(const QString &message);
    // The workspace's view clock (Preferences: refresh rate, <= 60 Hz; not while minimised or
    // hidden): a link's docks and dials redraw on it instead of keeping a clock of their own.
    void viewTick();

protected:
    void changeEvent(QEvent *event) override;
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    bool event(QEvent *event) override;

private:
    void createStatusBar();
    void fitDocks();
    // The docks that need a capability, with it.
    QList<QPair<QDockWidget *, device::DeviceLink::Capability>> capabilityDocks() const;
    void retranslateUi();
    void resizeValueColumns();
    void placeDetailsDock(); // tabbed behind the values, visible once offered (not in Calibrate)
    void resizeDetailColumns();
    // Makes `link` the one shown: the old link's docks and panels go, then the old link; the
    // views start afresh and the docks follow the new link's capabilities.
    void bindLink(std::unique_ptr<device::DeviceLink> link, std::shared_ptr<void> keepAlive);
    // Closes and frees the link, and first what refers to it.
    void dropLink();
    void resetViews();

    void onStateChanged(device::SessionState state, const QString &detail);
    void onIdentityChanged(const model::DeviceIdentity &identity);
    void onStatsUpdated(const device::SessionStats &stats);
    void onTextReplied(quint64 id, const device::TextReply &reply);
    void onErrorOccurred(const QString &message);
    void onStreamWarning(const QString &message);

    void updateStateLabel();
    void updateIdentityLabel();
    void updateStatsLabel();

    // What the link needs (declared before it: the link goes first).
    std::shared_ptr<void> m_linkKeepAlive;
    QHash<int, ToolRunner> m_linkTools; // LinkTool -> what opens it, for the attached link
    std::unique_ptr<device::DeviceLink> m_link;

    models::LatestValuesModel *m_valuesModel = nullptr;
    QTableView *m_valuesView = nullptr;
    QTableView *m_detailsView = nullptr;  // the HI83 detail rows of the same model
    QDockWidget *m_detailsDock = nullptr; // behind the values, once a frame carried a detail
    bool m_detailsOffered = false;
    bool m_refitQueued = false; // a link panel behind the values came to the front: fitDocks soon
    std::array<int, 3> m_detailsColumns{}; // widest text so far per column (resizeDetailColumns)
    QDockWidget *m_valuesDock = nullptr;
    ChartPanel *m_charts = nullptr;
    AttitudeWidget *m_attitude = nullptr;
    // ImuDesk's reference attitude, while the attitude view shows it (its context menu).
    std::unique_ptr<verify::LiveReference> m_reference;
    QElapsedTimer m_referenceClock; // the difference chart's time
    void showReference(bool shown);
    QDockWidget *m_attitudeDock = nullptr;
    LayoutPreset m_preset = LayoutPreset::Monitor;
    bool m_layoutRestored = false;
    bool m_shownOnce = false;
    // The user dragged a separator: the preset's proportions no longer follow the window size.
    bool m_userSized = false;
    QElapsedTimer m_valuesClock; // when the values table was last refreshed
    bool m_portLent = false; // the port is lent out (firmware update): what the link needs stays
    std::function<void()> m_start; // opens the attached link
    QString m_address;
    int m_valuesColumnsWidth = 0; // what the values table's columns need, without the stretch
    uint64_t m_chartSeq = 0; // next sample of the store the charts have not seen
    ConsoleWidget *m_console = nullptr;
    QDockWidget *m_consoleDock = nullptr;
    RawBytesView *m_rawView = nullptr;
    QDockWidget *m_rawDock = nullptr;
    CommandLogWidget *m_commandLog = nullptr;
    QDockWidget *m_commandLogDock = nullptr;
    StatusFlagsWidget *m_flags = nullptr;
    ConfigPanel *m_configPanel = nullptr;
    QDockWidget *m_configDock = nullptr;
    RecordingControls *m_recording = nullptr;
    QDockWidget *m_recordingDock = nullptr;
    models::ClockStatsModel *m_clockModel = nullptr;
    QTableView *m_syncView = nullptr;
    QDockWidget *m_syncDock = nullptr;
    QList<QDockWidget *> m_linkDocks;
    QHash<QDockWidget *, LinkDockPlace> m_linkDockPlaces;
    void placeLinkDock(QDockWidget *dock);
    // The preset's proportions follow the window's size: shown, not restored from the user's
    // settings, and no separator dragged by the user since.
    bool followsWindow() const { return m_shownOnce && !m_userSized && !m_layoutRestored; }
    QLabel *m_stateLabel = nullptr;
    QLabel *m_identityLabel = nullptr;
    QLabel *m_statsLabel = nullptr;
    QLabel *m_streamWarningLabel = nullptr; // shown while the link's stream warning lasts
    QString m_statsPlainText; // the stats label's text without the highlight

    QTimer m_refreshTimer;
    quint64 m_shownTotal = ~quint64(0);

    device::SessionState m_state = device::SessionState::Closed;
    QString m_stateDetail;
    QString m_target;
    std::optional<model::DeviceIdentity> m_identity;
    std::optional<device::SessionStats> m_stats;
    int m_baud = 0;
};

} // namespace imudesk::ui
