#include "families/built_in_families.h"

#include "bus/modbus_scan_dialog.h"
#include "bus/register_browser.h"
#include "device/modbus_session.h"
#include "workspace/device_workspace.h"

namespace imudesk::ui {

bool ModbusUi::accepts(const device::DeviceLink &link) const
{
    return qobject_cast<const device::ModbusSession *>(&link) != nullptr;
}

QString ModbusUi::target(const device::LinkRequest &request) const
{
    const QString device = !request.simulate ? request.modbus.port
                           : request.modbus.kind == protocol::modbus::DeviceKind::Hec495
                               ? tr("Simulated HEC495 (Modbus)")
                               : tr("Simulated HI14 (Modbus)");
    return tr("%1, Modbus node %2").arg(device).arg(request.modbus.effectiveNodeId());
}

void ModbusUi::decorate(DeviceWorkspace &ws, device::DeviceLink &link, const device::LinkRequest &) const
{
    auto *session = static_cast<device::ModbusSession *>(&link);
    ws.addLinkDock(new RegisterBrowser(session), DeviceWorkspace::LinkDockPlace::BehindValues);
    ws.offerTool(DeviceWorkspace::LinkTool::ScanBus, [session](QWidget *parent) {
        auto *dialog = new ModbusScanDialog(session, parent);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->open();
    });
}

} // namespace imudesk::ui
