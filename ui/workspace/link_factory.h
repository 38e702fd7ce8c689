#pragma once
// Opens the links other than the HiPNUC serial session in a device workspace: the HEC495
// compass over serial, Modbus RTU and CAN devices (real or simulated) and replayed
// captures. Each function creates the family's session, attaches it to the workspace with
// the docks that belong to it (register browser, CAN monitor and configuration, compass
// dial and settings, replay controls) and opens it. On failure they return false with a
// message that says what to do, and the workspace is left as it was.
#include "device/can_session_types.h"
#include "device/modbus_types.h"
#include "sim/motion_model.h"

#include <QCoreApplication>
#include <QString>

#include <memory>

namespace imudesk::ui {

class DeviceWorkspace;

class LinkFactory {
    Q_DECLARE_TR_FUNCTIONS(LinkFactory)

public:
    // A HEC495 on a serial port (baud 0: the session finds it) at a module address.
    // keepAlive: what the link needs (its simulator), released when the link closes.
    static bool connectHec495(DeviceWorkspace &ws, const QString &port, int baud, int address, QString *error,
                              std::shared_ptr<void> keepAlive = {});
    // A simulated HEC495 streaming at 50 Hz on a pseudo-terminal.
    static bool connectSimulatedHec495(DeviceWorkspace &ws, sim::Motion motion, QString *error);
    // A Modbus RTU device; `simulate` starts a simulated one of options.kind on a pty first.
    static bool connectModbus(DeviceWorkspace &ws, device::ModbusOptions options, bool simulate, sim::Motion motion,
                              QString *error);
    // A CAN device; `simulate` first puts a simulated device (protocol and family from the
    // options: HEC495 when options.protocol is Hec495) on the same bus.
    static bool connectCan(DeviceWorkspace &ws, const device::CanSessionOptions &options, bool simulate,
                           sim::Motion motion, QString *error);
    // A capture file played through the live views.
    static bool openReplay(DeviceWorkspace &ws, const QString &path, QString *error);
};

} // namespace imudesk::ui
