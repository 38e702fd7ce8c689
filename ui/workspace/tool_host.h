#pragma once
// What the tool actions (tool_actions.h) need from the window that owns them: the tab in use,
// a tab free for a new link, the preferences, where to report a problem, and the parent of
// their dialogs. MainWindow provides it; ToolActions knows only this, so the two do not call
// into each other's classes.
#include "links/link_opener.h"
#include "sim/motion_model.h"

#include <QString>

#include <vector>

class QWidget;

namespace imudesk::ui {

class DeviceWorkspace;
struct Preferences;

class ToolHost {
public:
    virtual ~ToolHost() = default;
    virtual QWidget *dialogParent() = 0;
    virtual DeviceWorkspace *currentWorkspace() const = 0;
    // Every tab, in order (Record all devices).
    virtual std::vector<DeviceWorkspace *> allWorkspaces() const = 0;
    // The current tab when it is idle, else a new one (for a link the user opens).
    virtual DeviceWorkspace *freeWorkspaceForLink() = 0;
    virtual const Preferences &preferences() const = 0;
    // Reports a problem to the user without blocking.
    virtual void showError(const QString &message) = 0;
    // Device > Configuration: the current tab in the layout made for the settings table (its
    // whole right column), so that the table's rows can be read on a laptop screen too.
    virtual void arrangeForConfiguration() = 0;
    // Opens a link that needs no detection (Modbus, CAN, a capture, a simulated device) in a
    // free tab, with its family's docks; false with why.
    virtual bool openLink(device::LinkRequest request, QString *error) = 0;
    // The motion a simulated device started from the tools follows.
    virtual sim::Motion simulatedMotion() const = 0;
};

} // namespace imudesk::ui
