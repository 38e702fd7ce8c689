#include "families/built_in_families.h"

#include "configuration/config_panel.h"
#include "device/device_session.h"
#include "ui/firmware/firmware_update_dialog.h"
#include "workspace/device_workspace.h"

namespace imudesk::ui {

bool HipnucSerialUi::accepts(const device::DeviceLink &link) const
{
    return qobject_cast<const device::DeviceSession *>(&link) != nullptr;
}

QString HipnucSerialUi::target(const device::LinkRequest &request) const
{
    if (!request.simulate)
        return request.address;
    return tr("Simulated %1 (firmware %2)")
        .arg(QString::fromStdString(request.hipnucSimulator.model), QString::fromStdString(request.hipnucSimulator.firmware));
}

void HipnucSerialUi::decorate(DeviceWorkspace &ws, device::DeviceLink &, const device::LinkRequest &request) const
{
    // The settings table (the workspace's, Capability::Settings) names the port in its advice.
    if (ConfigPanel *panel = ws.configPanel())
        panel->setPortName(request.address);
    // Device > Update firmware: the dialog opens the port itself; the session lends it out (a
    // simulated module keeps running, its bootloader takes the update) and takes it back.
    ws.offerTool(DeviceWorkspace::LinkTool::FirmwareUpdate, [&ws, requestedBaud = request.baud](QWidget *parent) {
        const int baud = ws.baud() > 0 ? ws.baud() : requestedBaud;
        const auto identity = ws.identity();
        const bool simulated = ws.isSimulated();
        const QString port = ws.releasePort();
        auto *dialog = new FirmwareUpdateDialog(port, baud, identity, parent);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->setDemoImageOffered(simulated);
        QObject::connect(dialog, &QDialog::finished, &ws, [&ws] { ws.reclaimPort(); });
        dialog->open();
    });
}

} // namespace imudesk::ui
