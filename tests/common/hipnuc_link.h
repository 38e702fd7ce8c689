#pragma once
// The HiPNUC serial session a workspace shows, for the tests that connected one (the window
// itself never asks: a family's session is its UI plug-in's business, ui/families).
#include "device/device_session.h"
#include "workspace/device_workspace.h"

namespace imudesk::test {

// Null when the workspace shows another family's link (or none).
inline device::DeviceSession *hipnucOf(ui::DeviceWorkspace &ws)
{
    return qobject_cast<device::DeviceSession *>(&ws.link());
}

} // namespace imudesk::test
