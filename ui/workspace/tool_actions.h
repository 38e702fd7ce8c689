#pragma once
// The menu entries of the features beyond live monitoring: captures (open for replay,
// import a vendor CSV, export, analyse), Modbus and CAN connections, the configuration
// panel, profiles, the output-rate calculator and the firmware update. Owned by the main
// window, which hands over its menus and asks for an update when the tab or its state
// changes; it reaches the window only through ToolHost (tool_host.h). Every long task runs
// in a non-modal window with its own progress and cancel.
#include "recording/session_recording_window.h"
#include "workspace/tool_host.h"

#include <QCoreApplication>
#include <QObject>
#include <QDialog>
#include <QPointer>

class QAction;
class QMenu;

namespace imudesk::ui {

class DeviceWorkspace;
class SessionRecordingWindow;

class ToolActions : public QObject {
    Q_OBJECT
public:
    ToolActions(ToolHost *host, QObject *parent);

    // Adds the actions to the File and Device menus and builds the Calibrate and Tools menus.
    void addToMenus(QMenu *fileMenu, QMenu *deviceMenu, QMenu *calibrateMenu, QMenu *toolsMenu);
    void retranslate();
    // Enables what the current tab's link and state allow.
    void update(const DeviceWorkspace *ws);

    // The actions themselves (for tests and shortcuts).
    QAction *openCaptureAction() const { return m_openCapture; }
    QAction *importCsvAction() const { return m_importCsv; }
    QAction *exportAction() const { return m_export; }
    QAction *analyzeAction() const { return m_analyze; }
    QAction *modbusAction() const { return m_modbus; }
    QAction *canAction() const { return m_can; }
    QAction *scanBusAction() const { return m_scanBus; }
    QAction *findDevicesAction() const { return m_findDevices; }
    QAction *configurationAction() const { return m_configuration; }
    QAction *profilesAction() const { return m_profiles; }
    QAction *calculatorAction() const { return m_calculator; }
    QAction *firmwareAction() const { return m_firmware; }
    QAction *recordAction() const { return m_record; }
    QAction *recordAllAction() const { return m_recordAll; }
    QAction *twistAlignAction() const { return m_twistAlign; }
    // Device > Record all devices: the window (made on first use).
    SessionRecordingWindow *sessionRecordingWindow() const { return m_sessionWindow; }
    QAction *magCalAction() const { return m_magCal; }
    QAction *gyroCalAction() const { return m_gyroCal; }
    QAction *attitudeResetAction() const { return m_attitudeReset; }
    QAction *verifyModuleAction() const { return m_verifyModule; }
    QAction *compassCalAction() const { return m_compassCal; }
    QAction *calHistoryAction() const { return m_calHistory; }

    // The steps behind the actions, callable without a file dialog (tests, command line).
    // A capture file, or a recorded session (its folder or its session.json): one replay tab per
    // device, on the session's timeline and moving together (record/replay_group.h).
    bool openCapture(const QString &path);
    bool openSession(const QString &folder);
    bool importVendorCsv(const QString &csvPath, const QString &capturePath);
    // The recording made last in this session (any tab), what Export offers first; empty: none.
    QString lastRecording() const { return m_lastRecording; }
    // The session recorded last (Record all devices), what Twist to align offers first.
    QString lastSession() const { return m_lastSession; }

private:
    QAction *make(const char *objectName);
    void chooseCapture();
    void chooseCsv();
    void exportCapture();
    void analyzeCapture();
    void connectModbus();
    void connectCan();
    // Device > Find devices…: the sweep's window (one at a time).
    void findDevices();
    void showConfiguration();
    void openCalculator();
    // Device > Record: starts recording the current tab's device (the panel shows why when it cannot).
    void record();
    void recordAll();
    void openTwistAlign();
    void noteRecording(const QString &path);
    void openCalHistory();

    ToolHost *m_host;
    QAction *m_openCapture = nullptr;
    QAction *m_importCsv = nullptr;
    QAction *m_export = nullptr;
    QAction *m_analyze = nullptr;
    QAction *m_modbus = nullptr;
    QAction *m_can = nullptr;
    QAction *m_scanBus = nullptr;
    QAction *m_findDevices = nullptr;
    QPointer<QDialog> m_findDialog;
    QAction *m_configuration = nullptr;
    QAction *m_profiles = nullptr;
    QAction *m_recordAll = nullptr;
    QAction *m_twistAlign = nullptr;
    QPointer<SessionRecordingWindow> m_sessionWindow;
    QAction *m_calculator = nullptr;
    QAction *m_firmware = nullptr;
    QAction *m_record = nullptr;
    QAction *m_magCal = nullptr;
    QAction *m_gyroCal = nullptr;
    QAction *m_attitudeReset = nullptr;
    QAction *m_verifyModule = nullptr;
    QAction *m_compassCal = nullptr;
    QAction *m_calHistory = nullptr;
    QString m_lastRecording;
    QString m_lastSession;
    QString m_lastRecorded; // the newer of the two above
    QString lastRecordedFolder() const;
    QMenu *m_toolsMenu = nullptr;
    QMenu *m_calibrateMenu = nullptr;
};

} // namespace imudesk::ui
