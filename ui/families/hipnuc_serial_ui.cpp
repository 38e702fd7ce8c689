#include "families/built_in_families.h"

#include "calibration/attitude_reset_wizard.h"
#include "calibration/gyro_scale_wizard.h"
#include "calibration/verify_module_wizard.h"
#include "calibration/mag_calibration_wizard.h"
#include "configuration/config_panel.h"
#include "configuration/profile_dialog.h"
#include "device/device_session.h"
#include "protocol/hipnuc/ascii_command.h"
#include "workspace/console_widget.h"
#include "ui/firmware/firmware_update_dialog.h"
#include "workspace/device_workspace.h"

namespace imudesk::ui {

bool HipnucSerialUi::accepts(const device::DeviceLink &link) const
{
    return qobject_cast<const device::DeviceSession *>(&link) != nullptr;
}

namespace {

// The simulated module's options (its model and firmware) of a simulated request.
sim::SimOptions simulatorOf(const device::LinkRequest &request)
{
    const auto *options = std::any_cast<sim::SimOptions>(&request.simulator);
    return options ? *options : sim::SimOptions{};
}

} // namespace

QString HipnucSerialUi::target(const device::LinkRequest &request) const
{
    if (!request.simulate)
        return request.address;
    const sim::SimOptions options = simulatorOf(request);
    return tr("Simulated %1 (firmware %2)")
        .arg(QString::fromStdString(options.model), QString::fromStdString(options.firmware));
}

std::vector<SimulatedDevice> HipnucSerialUi::simulatedDevices() const
{
    std::vector<SimulatedDevice> devices;
    for (const char *firmware : {"1.7.1", "1.6.6"}) {
        const PortChoice choice = PortChoice::simulated(QStringLiteral("HI14"), QLatin1String(firmware));
        devices.push_back({choice, tr("Simulated %1 (firmware %2)").arg(choice.model, choice.firmware)});
    }
    return devices;
}

std::optional<device::LinkRequest> HipnucSerialUi::simulatedRequest(const PortChoice &choice,
                                                                    const SimulationSetup &setup) const
{
    // Every simulated HiPNUC module has a firmware version; the model is any the simulator knows.
    if (choice.kind != PortChoice::Kind::Simulated || choice.firmware.isEmpty())
        return std::nullopt;
    sim::SimOptions options;
    options.model = choice.model.toStdString();
    options.firmware = choice.firmware.toStdString();
    options.motion = setup.motion;
    options.seed = setup.seed;
    return device::LinkRequest::simulatedHipnuc(options, setup.baud);
}

std::optional<PortChoice> HipnucSerialUi::simulatedChoice(const device::LinkRequest &request) const
{
    if (!request.simulate || request.kind != device::LinkRequest::Kind::Serial || request.family != QLatin1String("hipnuc"))
        return std::nullopt;
    const sim::SimOptions options = simulatorOf(request);
    return PortChoice::simulated(QString::fromStdString(options.model), QString::fromStdString(options.firmware));
}

namespace {

namespace hp = protocol::hipnuc;

// Sends a command made by the typed builders and shows it in the console and the command log
// like a typed one (its reply follows by id).
void sendShown(DeviceWorkspace &ws, device::DeviceSession &session, const hp::Command &command)
{
    QString error;
    const quint64 id = session.sendCommand(command, DeviceWorkspace::kCommandTimeoutMs, &error);
    if (id == 0) {
        ws.console()->showError(error);
        return;
    }
    ws.showSentCommand(id, QString::fromStdString(command.text));
}

// A calibration wizard, its runs saved under the module's serial number, open until closed.
template <class Wizard>
void showWizard(const DeviceWorkspace &ws, Wizard *wizard)
{
    if (ws.identity())
        wizard->runSaver().setIdentity(*ws.identity());
    wizard->setAttribute(Qt::WA_DeleteOnClose);
    wizard->show();
}

} // namespace

void HipnucSerialUi::decorate(DeviceWorkspace &ws, device::DeviceLink &link, const device::LinkRequest &request) const
{
    auto *session = static_cast<device::DeviceSession *>(&link);
    // Device > Version: LOG VERSION (the identity follows the answer).
    ws.offerTool(DeviceWorkspace::LinkTool::ReadVersion,
                 [&ws, session](QWidget *) { sendShown(ws, *session, hp::commands::logVersion()); });
    // Device > Take one sample: LOG <MSG> ONMARK ONCE (v1.7.1 manual 4.6.8.15: one frame, as a
    // SYNC_IN pulse would give) of the frame type the module sends, HI91 when it sends none.
    ws.offerTool(DeviceWorkspace::LinkTool::TakeSample, [&ws, session](QWidget *) {
        hp::Message m = hp::Message::HI91;
        if (const auto latest = session->store().latest())
            if (hp::Message named; hp::parseMessage(latest->source, named) && hp::commands::logOnMark(named, true).ok())
                m = named;
        sendShown(ws, *session, hp::commands::logOnMark(m, true));
    });
    // Device > Profiles: the module's settings read, saved as a profile, or a profile applied.
    ws.offerTool(DeviceWorkspace::LinkTool::Profiles, [session](QWidget *parent) {
        auto *dialog = new ProfileDialog(*session, parent);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->open();
        dialog->readDevice();
    });
    // Calibrate: the magnetometer (the firmware decides the manual's procedure), the gyro scale
    // and the attitude reset; each wizard saves its run under the module's serial number.
    ws.offerTool(DeviceWorkspace::LinkTool::MagCalibration, [&ws, session](QWidget *parent) {
        if (ws.identity() && ws.identity()->firmware)
            showWizard(ws, new MagCalibrationWizard(*session, *ws.identity()->firmware, parent));
    });
    ws.offerTool(DeviceWorkspace::LinkTool::GyroCalibration,
                 [&ws, session](QWidget *parent) { showWizard(ws, new GyroScaleWizard(*session, parent)); });
    ws.offerTool(DeviceWorkspace::LinkTool::AttitudeReset,
                 [&ws, session](QWidget *parent) { showWizard(ws, new AttitudeResetWizard(*session, parent)); });
    ws.offerTool(DeviceWorkspace::LinkTool::VerifyModule,
                 [&ws, session](QWidget *parent) { showWizard(ws, new VerifyModuleWizard(*session, parent)); });
    // The settings table (the workspace's settings dock, Capability::Settings), which names the
    // port in its advice; the rate as soon as a detection finds it.
    auto *panel = new ConfigPanel(*session);
    panel->setPortName(request.address);
    ws.setConfigPanel(panel);
    QObject::connect(session, &device::DeviceSession::baudDetected, &ws, &DeviceWorkspace::noteBaud);
    // Device > Update firmware: the dialog opens the port itself; the session lends it out (a
    // simulated module keeps running, its bootloader takes the update) and takes it back.
    // After an update the module is looked for at the rate the update found its application at
    // (a rate set but not saved is gone after the restart); after a failed one, at every rate.
    ws.offerTool(DeviceWorkspace::LinkTool::FirmwareUpdate, [&ws, session, requestedBaud = request.baud](QWidget *parent) {
        const int baud = ws.baud() > 0 ? ws.baud() : requestedBaud;
        const auto identity = ws.identity();
        const bool simulated = ws.isSimulated();
        const QString port = ws.releasePort();
        auto *dialog = new FirmwareUpdateDialog(port, baud, identity, parent);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->setDemoImageOffered(simulated);
        // The link closes on its own thread: the update waits until the port is free.
        dialog->setPortFree(!ws.isBusy());
        QObject::connect(&ws, &DeviceWorkspace::stateChanged, dialog, [&ws, dialog] {
            if (!ws.isBusy())
                dialog->setPortFree(true);
        });
        QObject::connect(dialog, &QDialog::finished, &ws, [&ws, session, dialog, port] {
            const auto &r = dialog->result();
            const bool ran = r.finalState != firmware::UpdateFlow::State::Idle;
            const int at = r.ok ? r.afterBaud : 0; // 0: detect
            if (!ran)
                ws.reclaimPort();
            else
                ws.reclaimPort([session, port, at] { session->open(port, at); });
        });
        dialog->open();
    });
}

} // namespace imudesk::ui
