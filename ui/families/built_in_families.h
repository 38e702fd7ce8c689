#pragma once
// The family UI plug-ins ImuDesk ships (family_ui.h), one file each. registerBuiltInFamilies
// adds them; nothing else names these classes.
#include "workspace/family_ui.h"

#include <QCoreApplication>

class QDockWidget;
class QWidget;

namespace imudesk::ui {

// A HiPNUC module on a serial port (or a simulated one on a pseudo-terminal): the workspace's
// settings table, console and command log serve it (its capabilities); the plug-in adds the
// firmware update over the port.
class HipnucSerialUi : public FamilyUi {
    Q_DECLARE_TR_FUNCTIONS(HipnucSerialUi)
public:
    bool accepts(const device::DeviceLink &link) const override;
    QString target(const device::LinkRequest &request) const override;
    void decorate(DeviceWorkspace &ws, device::DeviceLink &link, const device::LinkRequest &request) const override;    std::vector<SimulatedDevice> simulatedDevices() const override;
    std::optional<device::LinkRequest> simulatedRequest(const PortChoice &choice,
                                                        const SimulationSetup &setup) const override;
    std::optional<PortChoice> simulatedChoice(const device::LinkRequest &request) const override;
};

// The Witlink HEC495 on a serial port: the compass dial, its settings and its calibration.
class Hec495SerialUi : public FamilyUi {
    Q_DECLARE_TR_FUNCTIONS(Hec495SerialUi)
public:
    bool accepts(const device::DeviceLink &link) const override;
    QString target(const device::LinkRequest &request) const override;
    void decorate(DeviceWorkspace &ws, device::DeviceLink &link, const device::LinkRequest &request) const override;    std::vector<SimulatedDevice> simulatedDevices() const override;
    std::optional<device::LinkRequest> simulatedRequest(const PortChoice &choice,
                                                        const SimulationSetup &setup) const override;
    std::optional<PortChoice> simulatedChoice(const device::LinkRequest &request) const override;
};

// A Modbus RTU device: the register browser and the bus scan.
class ModbusUi : public FamilyUi {
    Q_DECLARE_TR_FUNCTIONS(ModbusUi)
public:
    bool accepts(const device::DeviceLink &link) const override;
    QString target(const device::LinkRequest &request) const override;
    void decorate(DeviceWorkspace &ws, device::DeviceLink &link, const device::LinkRequest &request) const override;
};

// A CAN device: the frame monitor, the configuration panel and (CANopen) the update over the bus.
class CanUi : public FamilyUi {
    Q_DECLARE_TR_FUNCTIONS(CanUi)
public:
    bool accepts(const device::DeviceLink &link) const override;
    QString target(const device::LinkRequest &request) const override;
    void decorate(DeviceWorkspace &ws, device::DeviceLink &link, const device::LinkRequest &request) const override;
};

// A capture file played through the live views: the replay controls.
class ReplayUi : public FamilyUi {
    Q_DECLARE_TR_FUNCTIONS(ReplayUi)
public:
    bool accepts(const device::DeviceLink &link) const override;
    QString target(const device::LinkRequest &request) const override;
    void decorate(DeviceWorkspace &ws, device::DeviceLink &link, const device::LinkRequest &request) const override;
};

// A dock around a family's widget.
// The families ImuDesk ships: HiPNUC serial, HEC495 serial, Modbus RTU, CAN and replayed captures.
void registerBuiltInFamilies(FamilyUiRegistry &registry);

// A family's dock: content under title, named for the window's saved layout.
QDockWidget *familyDock(QWidget *content, const QString &objectName, const QString &title);

} // namespace imudesk::ui
