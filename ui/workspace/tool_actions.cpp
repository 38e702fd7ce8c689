#include "workspace/tool_actions.h"

#include "charts/analysis_window.h"
#include "calibration/calibration_history_dialog.h"
#include "calibration/calibration_run_saver.h"
#include "charts/bandwidth_calculator.h"
#include "bus/bus_connect_dialog.h"
#include "ui/discovery/find_devices_dialog.h"
#include "configuration/config_panel.h"
#include "workspace/device_workspace.h"
#include "recording/export_dialog.h"
#include "recording/recording_controls.h"
#include "recording/session_recording_window.h"
#include "recording/twist_align_dialog.h"
#include "ui/firmware/firmware_update_dialog.h"
#include "workspace/preferences.h"
#include "record/capture_source.h"
#include "record/session_manifest.h"
#include "settings/configuration_controller.h"

#include <QAction>
#include <QDockWidget>
#include <QFileDialog>
#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QStandardPaths>

#include <cmath>

namespace imudesk::ui {

using device::SessionState;

ToolActions::ToolActions(ToolHost *host, QObject *parent) : QObject(parent), m_host(host)
{
    // What the current tab's link family offers (ui/families: a bus scan, its settings profiles,
    // its calibrations, a firmware update), run in that tab.
    using Tool = DeviceWorkspace::LinkTool;
    const auto linkTool = [this](Tool tool) {
        return [this, tool] {
            if (DeviceWorkspace *ws = m_host->currentWorkspace())
                ws->runTool(tool, m_host->dialogParent());
        };
    };
    m_openCapture = make("openCaptureAction");
    m_openCapture->setShortcut(QKeySequence::Open);
    connect(m_openCapture, &QAction::triggered, this, &ToolActions::chooseCapture);
    m_importCsv = make("importCsvAction");
    connect(m_importCsv, &QAction::triggered, this, &ToolActions::chooseCsv);
    m_export = make("exportCaptureAction");
    m_export->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    connect(m_export, &QAction::triggered, this, &ToolActions::exportCapture);
    m_analyze = make("analyzeCaptureAction");
    connect(m_analyze, &QAction::triggered, this, &ToolActions::analyzeCapture);
    m_findDevices = make("findDevicesAction");
    m_findDevices->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
    connect(m_findDevices, &QAction::triggered, this, &ToolActions::findDevices);
    m_modbus = make("connectModbusAction");
    m_modbus->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_M));
    connect(m_modbus, &QAction::triggered, this, &ToolActions::connectModbus);
    m_can = make("connectCanAction");
    m_can->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_N));
    connect(m_can, &QAction::triggered, this, &ToolActions::connectCan);
    m_scanBus = make("scanBusAction");
    connect(m_scanBus, &QAction::triggered, this, linkTool(Tool::ScanBus));
    m_configuration = make("configurationAction");
    m_configuration->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_G));
    connect(m_configuration, &QAction::triggered, this, &ToolActions::showConfiguration);
    m_profiles = make("profilesAction");
    connect(m_profiles, &QAction::triggered, this, linkTool(Tool::Profiles));
    m_calculator = make("calculatorAction");
    connect(m_calculator, &QAction::triggered, this, &ToolActions::openCalculator);
    m_firmware = make("firmwareAction");
    connect(m_firmware, &QAction::triggered, this, linkTool(Tool::FirmwareUpdate));
    m_record = make("recordAction");
    m_record->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    connect(m_record, &QAction::triggered, this, &ToolActions::record);
    m_recordAll = make("recordAllAction");
    m_recordAll->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
    connect(m_recordAll, &QAction::triggered, this, &ToolActions::recordAll);
    m_twistAlign = make("twistAlignAction");
    connect(m_twistAlign, &QAction::triggered, this, &ToolActions::openTwistAlign);
    m_magCal = make("magCalAction");
    connect(m_magCal, &QAction::triggered, this, linkTool(Tool::MagCalibration));
    m_gyroCal = make("gyroCalAction");
    connect(m_gyroCal, &QAction::triggered, this, linkTool(Tool::GyroCalibration));
    m_attitudeReset = make("attitudeResetAction");
    connect(m_attitudeReset, &QAction::triggered, this, linkTool(Tool::AttitudeReset));
    m_verifyModule = make("verifyModuleAction");
    m_verifyModule->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_V));
    connect(m_verifyModule, &QAction::triggered, this, linkTool(Tool::VerifyModule));
    m_compassCal = make("compassCalAction");
    connect(m_compassCal, &QAction::triggered, this, linkTool(Tool::CompassCalibration));
    m_calHistory = make("calibrationHistoryAction");
    m_calHistory->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_H));
    connect(m_calHistory, &QAction::triggered, this, &ToolActions::openCalHistory);
    retranslate();
}

QAction *ToolActions::make(const char *objectName)
{
    auto *a = new QAction(m_host->dialogParent());
    a->setObjectName(QString::fromLatin1(objectName));
    return a;
}

void ToolActions::addToMenus(QMenu *fileMenu, QMenu *deviceMenu, QMenu *calibrateMenu, QMenu *toolsMenu)
{
    QAction *firstFileEntry = fileMenu->actions().value(2); // after "new tab", "close tab"
    fileMenu->insertActions(firstFileEntry, {m_openCapture, m_importCsv, m_export});
    fileMenu->insertSeparator(firstFileEntry);
    deviceMenu->addSeparator();
    deviceMenu->addActions({m_findDevices, m_modbus, m_can, m_scanBus});
    deviceMenu->addSeparator();
    deviceMenu->addActions({m_configuration, m_profiles, m_record, m_recordAll, m_firmware});
    m_calibrateMenu = calibrateMenu;
    calibrateMenu->addActions({m_magCal, m_gyroCal, m_attitudeReset});
    calibrateMenu->addSeparator();
    calibrateMenu->addAction(m_verifyModule);
    calibrateMenu->addSeparator();
    calibrateMenu->addAction(m_compassCal);
    calibrateMenu->addSeparator();
    calibrateMenu->addAction(m_calHistory);
    m_toolsMenu = toolsMenu;
    toolsMenu->addActions({m_analyze, m_twistAlign, m_calculator});
}

void ToolActions::retranslate()
{
    m_openCapture->setText(tr("&Open capture…"));
    m_openCapture->setStatusTip(tr("Play a recorded capture through the charts and views, as a live device (in a tab of its own "
                                        "when this one is connected); a recorded session's session.json opens every device, aligned"));
    m_importCsv->setText(tr("&Import vendor CSV…"));
    m_importCsv->setStatusTip(tr("Turn a CSV written by the vendor's PC tool into a capture and play it"));
    m_export->setText(tr("&Export capture…"));
    m_export->setStatusTip(tr("Write a capture as vendor CSV, tidy CSV or JSON Lines"));
    m_analyze->setText(tr("&Analyze capture…"));
    m_analyze->setStatusTip(tr("Statistics, output rate and jitter, lost frames and Allan deviation of a capture"));
    m_findDevices->setText(tr("&Find devices…"));
    m_findDevices->setStatusTip(tr("One sweep of every serial port and CAN bus: what is connected, at what rate and "
                                   "address, and two devices at one address"));
    m_modbus->setText(tr("Connect over &Modbus RTU…"));
    m_modbus->setStatusTip(tr("Poll a module or compass on an RS-485 bus"));
    m_can->setText(tr("Connect over C&AN…"));
    m_can->setStatusTip(tr("Listen to and configure a device on a CAN bus (J1939 or CANopen)"));
    m_scanBus->setText(tr("&Scan the bus…"));
    m_scanBus->setStatusTip(tr("Find the node IDs that answer on the bus"));
    m_configuration->setText(tr("Con&figuration"));
    m_configuration->setStatusTip(tr("Every setting of the connected module: read, edit, apply, save"));
    m_profiles->setText(tr("&Profiles…"));
    m_profiles->setStatusTip(tr("Save the configuration to a file, compare a file with the device, apply it to several"));
    m_calculator->setText(tr("Output-rate &calculator…"));
    m_calculator->setStatusTip(tr("Bytes per second of the chosen outputs against the link's capacity"));
    m_firmware->setText(tr("&Update firmware…"));
    m_firmware->setStatusTip(tr("Write a new firmware image to the module over its serial port or its CAN bus, and verify it"));
    m_record->setText(tr("&Record"));
    m_record->setStatusTip(tr("Record this device to a capture file; the recording panel shows the progress and Stop"));
    m_recordAll->setText(tr("Record &all devices…"));
    m_recordAll->setStatusTip(tr("Record every connected tab into one session folder, the devices on one time base"));
    m_twistAlign->setText(tr("T&wist to align…"));
    m_twistAlign->setStatusTip(tr("Align the devices of a recorded session from sharp turns of the fixture they share"));
    m_magCal->setText(tr("&Magnetometer…"));
    m_magCal->setStatusTip(tr("Calibrate the magnetometer: turn the module while the sphere fills, then judge the fit"));
    m_gyroCal->setText(tr("&Gyro scale factor…"));
    m_gyroCal->setStatusTip(tr("Turn the module a known angle about Z to correct the gyro's scale (CONFIG USRCAL)"));
    m_attitudeReset->setText(tr("&Attitude reset / level…"));
    m_attitudeReset->setStatusTip(tr("Zero the heading or level the module (ATT RST), after checking that it is still"));
    m_verifyModule->setText(tr("&Verify module…"));
    m_verifyModule->setStatusTip(tr("Is the module right? Turn it through still poses: its accelerometer, gyro and attitude "
                                    "judged, each figure with its bounds"));
    m_compassCal->setText(tr("&Compass calibration…"));
    m_compassCal->setStatusTip(tr("The compass's own calibration methods, with the target poses to turn it to"));
    m_calHistory->setText(tr("Calibration &history…"));
    m_calHistory->setStatusTip(tr("Every finished calibration run per device: metrics, samples, PDF report"));
    if (m_toolsMenu)
        m_toolsMenu->setTitle(tr("&Tools"));
    if (m_calibrateMenu)
        m_calibrateMenu->setTitle(tr("&Calibrate"));
}

void ToolActions::update(const DeviceWorkspace *ws)
{
    const bool busy = ws && ws->isBusy();
    using C = device::DeviceLink::Capability;
    const auto caps = ws ? ws->capabilities() : device::DeviceLink::Capabilities{};
    const bool settings = caps.testFlag(C::Settings);
    const bool connected = ws && ws->state() == SessionState::Connected;
    m_modbus->setEnabled(!busy);
    m_can->setEnabled(!busy);
    // A capture opens in a tab of its own when this one is connected (MainWindow::freeWorkspace).
    m_openCapture->setEnabled(true);
    m_importCsv->setEnabled(true);
    using Tool = DeviceWorkspace::LinkTool;
    m_scanBus->setEnabled(connected && ws->offersTool(Tool::ScanBus));
    m_configuration->setEnabled(settings);
    m_profiles->setEnabled(connected && ws->offersTool(Tool::Profiles));
    m_record->setEnabled(caps.testFlag(C::Recording));
    // Every tab that was current may record: Export offers the last recording of any of them.
    if (ws && ws->recordingControls())
        connect(ws->recordingControls(), &RecordingControls::recordingStopped, this, &ToolActions::noteRecording,
                Qt::UniqueConnection);
    const bool hasMag = ws && ws->identity() && ws->identity()->hasMagnetometer() && ws->identity()->firmware;
    m_magCal->setEnabled(connected && hasMag && ws->offersTool(Tool::MagCalibration));
    m_gyroCal->setEnabled(connected && ws->offersTool(Tool::GyroCalibration));
    m_attitudeReset->setEnabled(connected && ws->offersTool(Tool::AttitudeReset));
    m_verifyModule->setEnabled(connected && ws->offersTool(Tool::VerifyModule));
    m_compassCal->setEnabled(connected && ws->offersTool(Tool::CompassCalibration));
    // The update opens the port or the bus itself; the link's family offers it (a HiPNUC module
    // on its serial port or on a CANopen bus).
    m_firmware->setEnabled(connected && ws->offersTool(Tool::FirmwareUpdate));
}

bool ToolActions::openCapture(const QString &path)
{
    const QFileInfo info(path);
    if (record::SessionManifest::isSessionFolder(path))
        return openSession(path);
    if (info.fileName() == QLatin1String(record::SessionManifest::kFileName))
        return openSession(info.absolutePath());
    QString error;
    if (!m_host->openLink(device::LinkRequest::capture(path), &error)) {
        m_host->showError(error);
        return false;
    }
    return true;
}

bool ToolActions::openSession(const QString &folder)
{
    record::SessionManifest manifest;
    QString error;
    if (!record::SessionManifest::load(folder, &manifest, &error)) {
        m_host->showError(error);
        return false;
    }
    // One timeline for all: the session's start on the recording host's clock, which every
    // capture's chunks carry; each device with its twist-to-align offset.
    auto group = std::make_shared<record::ReplayGroup>();
    const QDir dir(folder);
    QStringList problems;
    int opened = 0;
    for (const auto &d : manifest.devices) {
        const QString path = dir.filePath(d.file);
        if (d.file.isEmpty() || !QFileInfo::exists(path)) {
            problems << tr("%1: its capture %2 is missing.").arg(d.name, d.file);
            continue;
        }
        if (d.linkKind.contains(QLatin1String("Modbus"), Qt::CaseInsensitive)) {
            problems << tr("%1 (%2): Modbus captures cannot be replayed yet; export the session to see its data.")
                            .arg(d.name, d.linkKind);
            continue;
        }
        device::LinkRequest r = device::LinkRequest::capture(path);
        r.replay.originNs = manifest.startedHostNs;
        r.replay.endNs = manifest.stoppedHostNs;
        r.replay.offsetNs = int64_t(std::llround(d.offsetNs));
        r.replayGroup = group;
        if (!m_host->openLink(std::move(r), &error)) {
            problems << tr("%1: %2").arg(d.name, error);
            continue;
        }
        ++opened;
    }
    if (!problems.isEmpty())
        m_host->showError((opened > 0 ? tr("The session opened without some of its devices:")
                                      : tr("No device of the session could be replayed:"))
                          + QLatin1Char('\n') + problems.join(QLatin1Char('\n')));
    return opened > 0;
}

bool ToolActions::importVendorCsv(const QString &csvPath, const QString &capturePath)
{
    const auto r = record::CaptureSource::convert(csvPath, capturePath);
    if (!r.ok) {
        m_host->showError(tr("%1 could not be imported: %2").arg(QFileInfo(csvPath).fileName(), r.error));
        return false;
    }
    return openCapture(capturePath);
}

void ToolActions::chooseCapture()
{
    // Any file: a capture, a vendor CSV or a raw byte dump is recognised by its content.
    // A recorded session opens by its session.json (Device > Record all devices writes one).
    const QString path = QFileDialog::getOpenFileName(m_host->dialogParent(), tr("Open capture"), lastRecordedFolder(),
                                                      tr("Captures, sessions, vendor CSV and raw dumps (*.imucap session.json *.csv *.bin *.raw *.log *.dat *.txt);;All files (*)"));
    if (!path.isEmpty())
        openCapture(path);
}

void ToolActions::chooseCsv()
{
    const QString csv = QFileDialog::getOpenFileName(m_host->dialogParent(), tr("Import vendor CSV"), QString(),
                                                     tr("CSV files (*.csv);;All files (*)"));
    if (csv.isEmpty())
        return;
    const QFileInfo info(csv);
    const QString capture = QFileDialog::getSaveFileName(
        m_host->dialogParent(), tr("Save the imported capture as"), info.dir().filePath(info.completeBaseName() + QStringLiteral(".imucap")),
        tr("Captures (*.imucap)"));
    if (!capture.isEmpty())
        importVendorCsv(csv, capture);
}

void ToolActions::exportCapture()
{
    // The recording just made is what is usually exported: the dialog opens with it, a single
    // device's capture or the session Record all devices wrote, whichever came last (its
    // Choose… picks another); without one, the file is asked for first.
    QString path = QFileInfo::exists(m_lastRecorded) ? m_lastRecorded : QString();
    if (path.isEmpty())
        path = QFileDialog::getOpenFileName(m_host->dialogParent(), tr("Export capture"), lastRecordedFolder(),
                                            tr("Captures, sessions, vendor CSV and raw dumps (*.imucap session.json *.csv *.bin *.raw *.log *.dat *.txt);;All files (*)"));
    if (path.isEmpty())
        return;
    auto *dialog = new ExportDialog(path, m_host->dialogParent());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
}

void ToolActions::analyzeCapture()
{
    const QString path = QFileDialog::getOpenFileName(m_host->dialogParent(), tr("Analyze capture"), m_host->preferences().effectiveRecordingFolder(),
                                                      tr("Captures, vendor CSV and raw dumps (*.imucap *.csv *.bin *.raw *.log *.dat *.txt);;All files (*)"));
    if (path.isEmpty())
        return;
    auto *window = new AnalysisWindow(m_host->dialogParent());
    window->setWindowFlag(Qt::Window);
    window->setAttribute(Qt::WA_DeleteOnClose);
    window->show();
    window->analyzeFile(path);
}

void ToolActions::connectModbus()
{
    auto *dialog = new ModbusConnectDialog(m_host->dialogParent());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        QString error;
        device::LinkRequest request = device::LinkRequest::modbusDevice(dialog->options());
        request.simulate = dialog->simulate();
        request.motion = m_host->simulatedMotion();
        if (!m_host->openLink(request, &error))
            m_host->showError(error);
    });
    dialog->open();
}

void ToolActions::findDevices()
{
    if (m_findDialog) {
        m_findDialog->raise();
        m_findDialog->activateWindow();
        return;
    }
    auto *dialog = new FindDevicesDialog(
        [this](device::LinkRequest request, QString *error) {
            request.motion = m_host->simulatedMotion();
            return m_host->openLink(std::move(request), error);
        },
        m_host->dialogParent());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    m_findDialog = dialog;
    dialog->show();
}

void ToolActions::connectCan()
{
    auto *dialog = new CanConnectDialog(m_host->dialogParent());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        QString error;
        device::LinkRequest request = device::LinkRequest::canBus(dialog->options());
        request.simulate = dialog->simulate();
        request.motion = m_host->simulatedMotion();
        if (!m_host->openLink(request, &error))
            m_host->showError(error);
    });
    dialog->open();
}

void ToolActions::showConfiguration()
{
    if (DeviceWorkspace *ws = m_host->currentWorkspace()) {
        // Behind the values in the Monitor layout the panel had two rows of its table at
        // 1366x768: the Configure layout gives it the right column.
        if (ws->preset() != DeviceWorkspace::LayoutPreset::Configure || ws->configDock()->isFloating())
            m_host->arrangeForConfiguration();
        ws->configDock()->show();
        ws->configDock()->raise();
    }
}

void ToolActions::record()
{
    DeviceWorkspace *ws = m_host->currentWorkspace();
    if (!ws)
        return;
    ws->recordingDock()->show();
    ws->recordingDock()->raise();
    RecordingControls *controls = ws->recordingControls();
    connect(controls, &RecordingControls::recordingStopped, this, &ToolActions::noteRecording, Qt::UniqueConnection);
    // A second Ctrl+R while recording leaves it running (Stop is in the panel).
    if (!controls->isRecording())
        controls->startRecording();
}

void ToolActions::recordAll()
{
    if (!m_sessionWindow) {
        ToolHost *host = m_host;
        auto devices = [host] {
            std::vector<SessionRecordingWindow::Device> out;
            for (DeviceWorkspace *ws : host->allWorkspaces()) {
                if (!ws || ws->state() != SessionState::Connected
                    || !ws->capabilities().testFlag(device::DeviceLink::Capability::Recording))
                    continue;
                auto *session = qobject_cast<device::Session *>(&ws->link());
                if (!session)
                    continue;
                out.push_back({session, ws->title(), ws->target(), ws->identity().value_or(model::DeviceIdentity{})});
            }
            return out;
        };
        QString folder = m_host->preferences().recordingFolder;
        if (folder.isEmpty())
            folder = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
        m_sessionWindow = new SessionRecordingWindow(devices, folder, m_host->dialogParent());
        m_sessionWindow->setAttribute(Qt::WA_DeleteOnClose);
        connect(m_sessionWindow, &SessionRecordingWindow::recordingFinished, this,
                [this](const QString &folder, bool) {
                    m_lastSession = folder;
                    m_lastRecorded = folder;
                });
    }
    m_sessionWindow->show();
    m_sessionWindow->raise();
    m_sessionWindow->activateWindow();
}

void ToolActions::openTwistAlign()
{
    auto *dialog = new TwistAlignDialog(m_lastSession, m_host->dialogParent());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
}

void ToolActions::noteRecording(const QString &path)
{
    m_lastRecording = path;
    m_lastRecorded = path;
}

// Where the file dialogs for a recording start: the session just recorded (its session.json in
// view), else the folder of the capture just recorded, else the recording folder.
QString ToolActions::lastRecordedFolder() const
{
    const QFileInfo last(m_lastRecorded);
    if (!m_lastRecorded.isEmpty() && last.exists())
        return last.isDir() ? last.absoluteFilePath() : last.absolutePath();
    return m_host->preferences().effectiveRecordingFolder();
}

void ToolActions::openCalculator()
{
    auto *calculator = new BandwidthCalculator(m_host->dialogParent());
    calculator->setWindowFlag(Qt::Window);
    calculator->setAttribute(Qt::WA_DeleteOnClose);
    if (DeviceWorkspace *ws = m_host->currentWorkspace(); ws && ws->configPanel())
        calculator->setConfiguration(ws->configPanel()->controller().configuration());
    calculator->show();
}

void ToolActions::openCalHistory()
{
    auto *dialog = new CalibrationHistoryDialog(calib::CalibrationHistory::defaultRoot(), m_host->dialogParent());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    const DeviceWorkspace *ws = m_host->currentWorkspace();
    if (ws && ws->identity())
        dialog->selectDevice(CalibrationRunSaver::serialOf(*ws->identity()));
    dialog->show();
}

} // namespace imudesk::ui
