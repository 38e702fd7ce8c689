#include "families/built_in_families.h"

#include "device/device_session.h"
#include "workspace/device_workspace.h"

namespace imudesk::ui {

bool HipnucSerialUi::accepts(const device::DeviceLink &link) const
{
    return qobject_cast<const device::DeviceSession *>(&link) != nullptr;
}

QString HipnucSerialUi::target(const device::LinkRequest &request) const
{
    return request.address;
}

bool HipnucSerialUi::attach(DeviceWorkspace &ws, device::LinkOpener::Opened &opened, const device::LinkRequest &request,
                            QString *error) const
{
    std::unique_ptr<device::DeviceSession> session(static_cast<device::DeviceSession *>(opened.link.release()));
    // The workspace's serial path: settings table, console, auto-reconnect, the port's name.
    // showLink starts the session afterwards.
    if (ws.connectSession(std::move(session), request.address, request.baud, [] {}))
        return true;
    if (error)
        *error = tr("Disconnect first, then connect to the module.");
    return false;
}

} // namespace imudesk::ui
