#pragma once
// Several devices named on the command line (`record PORT,PORT,...`, `bridge PORT,...`), opened
// side by side and connected: a serial port (its family found as probe finds it; PORT:BAUD at
// that rate), modbus:PORT[@ID] (a HiPNUC module's Modbus RTU; modbus-hec495:PORT[@ID] for the
// compass) or can:PLUGIN:INTERFACE[:PROTOCOL] (protocol auto, j1939, canopen or hec495).
#include "links/link_opener.h"
#include "device/session_types.h"
#include "model/device_identity.h"
#include "capture/capture_header.h"

#include <QString>
#include <QStringList>

#include <memory>
#include <vector>

namespace imudesk::cli {

bool linkOf(const QString &spec, int baud, device::LinkRequest *out, QString *error);

struct OpenDevice {
    QString spec;
    std::unique_ptr<device::LinkOpener> opener;
    device::OpenedLink link;
    model::DeviceIdentity identity;
    device::SessionState state = device::SessionState::Closed;
    QString error;
    QString doing; // its last step while it opens ("trying 115200 baud", "Detecting: ...")
    bool ready = false;
};

// What a recording or the bridge says of an opened device: its identity, link and port.
capture::CaptureHeader headerOf(const OpenDevice &d);

// Opens every device of specs (baud: the serial ports' rate, 0 = detect) and waits until each
// is connected (30 s to open, 15 s to connect). ExitOk when all are; else the exit code, the
// reason already printed.
int openDevices(const QStringList &specs, int baud, std::vector<OpenDevice> &devices);

} // namespace imudesk::cli
