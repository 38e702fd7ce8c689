#include "families/built_in_families.h"

#include "bus/can_config_panel.h"
#include "bus/can_monitor_widget.h"
#include "device/can_session.h"
#include "ui/firmware/firmware_update_dialog.h"
#include "workspace/device_workspace.h"

#include <QScrollArea>

namespace imudesk::ui {

bool CanUi::accepts(const device::DeviceLink &link) const
{
    return qobject_cast<const device::CanSession *>(&link) != nullptr;
}

QString CanUi::target(const device::LinkRequest &request) const
{
    return tr("CAN %1:%2").arg(request.can.plugin, request.can.interfaceName);
}

void CanUi::decorate(DeviceWorkspace &ws, device::DeviceLink &link, const device::LinkRequest &request) const
{
    auto *session = static_cast<device::CanSession *>(&link);
    auto *monitor = new CanMonitorWidget;
    monitor->setObjectName(QStringLiteral("canMonitor"));
    QObject::connect(session, &device::CanSession::framesSeen, monitor, &CanMonitorWidget::addEvents);
    QObject::connect(monitor, &CanMonitorWidget::sendFrameRequested, session, &device::CanSession::sendFrame);
    ws.addLinkDock(familyDock(monitor, QStringLiteral("canMonitorDock"), tr("CAN frames")),
                   DeviceWorkspace::LinkDockPlace::Below);
    auto *panel = new CanConfigPanel;
    panel->setObjectName(QStringLiteral("canConfigPanel"));
    panel->setSession(session);
    QObject::connect(session, &QObject::destroyed, panel, [panel] { panel->setSession(nullptr); });
    // The form is taller than the values it sits behind: on a short screen (1366x768 in
    // Chinese) it scrolls, rather than making the window taller than the screen.
    auto *scroll = new QScrollArea;
    scroll->setObjectName(QStringLiteral("canConfigScroll"));
    scroll->setWidget(panel);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setMinimumWidth(panel->minimumSizeHint().width());
    ws.addLinkDock(familyDock(scroll, QStringLiteral("canConfigDock"), tr("CAN configuration")),
                   DeviceWorkspace::LinkDockPlace::BehindValues);
    if (request.can.protocol == protocol::can::CanProtocol::CanOpen) {
        // A HiPNUC module on CANopen updates over the bus: the session stays on it, the dialog
        // talks to the node with its own CAN device (SDO to 0x1F51), and the session sees the
        // module leave and come back.
        ws.offerTool(DeviceWorkspace::LinkTool::FirmwareUpdate, [&ws, session](QWidget *parent) {
            auto *dialog = new FirmwareUpdateDialog(QString(), 0, ws.identity(), parent);
            dialog->setAttribute(Qt::WA_DeleteOnClose);
            dialog->setLink(FirmwareUpdateDialog::Link::Can);
            const auto &o = session->options();
            dialog->setCanBus(o.plugin, o.interfaceName, o.bitrate, session->targetNode() > 0 ? session->targetNode() : 8);
            dialog->open();
        });
    }
}

} // namespace imudesk::ui
