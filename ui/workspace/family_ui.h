#pragma once
// What a device family adds to a workspace, on the UI side: the counterpart of the core's
// device::FamilyPlugin. A workspace shows any device::DeviceLink with the views every link has
// (values, charts, attitude, status) and the docks its capabilities call for; a family's UI
// plug-in adds what only that family has: its docks (a compass dial, a register browser, a
// CAN monitor, replay controls), the tools it offers in the menus (a bus scan, the compass's
// calibration, an update over the bus) and the workspace's title for the link.
//
// This interface is the shell's (ui/workspace), which names no family; the plug-ins live in
// ui/families. The built-in ones are registered once, in app/gui/main.cpp
// (families/built_in_families.h: registerBuiltInFamilies), and the window is given the registry;
// it finds the plug-in for a link with FamilyUiRegistry::forLink. A new device family is a core
// plug-in, one class of this interface and one registration line.
#include "device/device_link.h"
#include "links/link_opener.h"
#include "sim/motion_model.h"
#include "workspace/port_choice.h"

#include <QString>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace imudesk::ui {

class DeviceWorkspace;

// How the window starts a simulated device: at the connection bar's baud (0: Auto), moving as
// the window's motion, with a seed of its own (serial number and noise) for each device.
struct SimulationSetup {
    int baud = 0;
    sim::Motion motion = sim::Motion::Static;
    uint64_t seed = 1;
};

class FamilyUi {
public:
    virtual ~FamilyUi() = default;
    // Whether `link` is this family's (its session type).
    virtual bool accepts(const device::DeviceLink &link) const = 0;
    // What the workspace calls the link ("HEC495 on /dev/ttyUSB0", "Simulated HEC495").
    virtual QString target(const device::LinkRequest &request) const = 0;
    // Makes ws show the opened link, not started yet (default: DeviceWorkspace::attachLink
    // under target(), with what it needs and how it starts). False (with why) while ws is busy.
    virtual bool attach(DeviceWorkspace &ws, device::LinkOpener::Opened &opened, const device::LinkRequest &request,
                        QString *error) const;
    // Adds the family's docks and tools to ws, which shows `link` already.
    virtual void decorate(DeviceWorkspace &ws, device::DeviceLink &link, const device::LinkRequest &request) const = 0;

    // The simulated devices the family lists in the connection bar (default: none).
    virtual std::vector<SimulatedDevice> simulatedDevices() const { return {}; }
    // The request that opens a simulated device of this family's (those it lists, or another
    // model it simulates, e.g. a choice saved earlier); nullopt when the choice is not its.
    virtual std::optional<device::LinkRequest> simulatedRequest(const PortChoice &choice,
                                                                const SimulationSetup &setup) const
    {
        (void)choice;
        (void)setup;
        return std::nullopt;
    }
    // The connection bar's entry for a simulated request of this family's; nullopt when not its.
    virtual std::optional<PortChoice> simulatedChoice(const device::LinkRequest &request) const
    {
        (void)request;
        return std::nullopt;
    }
};

class FamilyUiRegistry {
public:
    void add(std::unique_ptr<FamilyUi> family) { m_families.push_back(std::move(family)); }
    // The plug-in for a link; null when none registered takes it (the workspace then shows the
    // views every link has).
    const FamilyUi *forLink(const device::DeviceLink &link) const;
    bool empty() const { return m_families.empty(); }
    // Every family's simulated devices, in registration order.
    std::vector<SimulatedDevice> simulatedDevices() const;
    // The first family's request for a simulated choice; nullopt when no family simulates it.
    std::optional<device::LinkRequest> simulatedRequest(const PortChoice &choice, const SimulationSetup &setup) const;
    // The connection bar's entry for a simulated request; nullopt when no family claims it.
    std::optional<PortChoice> simulatedChoice(const device::LinkRequest &request) const;

private:
    std::vector<std::unique_ptr<FamilyUi>> m_families;
};


// Shows an opened link in ws: attaches it under the family's name for it, lets the family's
// plug-in add its docks and tools, then starts the link. False (with why) while ws is busy.
bool showLink(DeviceWorkspace &ws, const FamilyUiRegistry &families, device::LinkOpener::Opened opened,
              const device::LinkRequest &request, QString *error);
// Opens a request that needs no detection (device::LinkOpener::openNow) and shows it in ws.
bool openLinkIn(DeviceWorkspace &ws, const FamilyUiRegistry &families, device::LinkRequest request, QString *error);

} // namespace imudesk::ui
