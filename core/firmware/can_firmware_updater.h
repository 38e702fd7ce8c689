#pragma once
// Runs a CAN firmware update (CanUpdateFlow over a QtCanFrameLink) in its own worker thread and
// reports it with UpdateRunner's queued signals, like FirmwareUpdater, so the GUI and the CLI
// treat both links alike. The bus device is created and used in the worker thread; a CanSession on the
// same interface may stay open (CAN is a shared bus), but its own SDO requests to the node would
// disturb the update. cancel() is safe from any thread: the flow sends an SDO abort between
// segments and leaves the module in its bootloader, where the next update finishes the job.
#include "core/firmware/can_update_flow.h"
#include "core/firmware/update_runner.h"

#include <QString>

namespace imudesk::firmware {

class CanFirmwareUpdater : public UpdateRunner {
    Q_OBJECT

public:
    struct Bus {
        QString plugin;        // e.g. "socketcan", "virtualcan", "peakcan"
        QString interfaceName; // e.g. "can0"
        int bitrate = 0;       // bit/s; 0 leaves the interface's setting
    };

    explicit CanFirmwareUpdater(QObject *parent = nullptr);

    // Starts the update; false when one is already running.
    bool start(const Bus &bus, const protocol::ihex::FirmwareImage &image, const CanUpdateFlow::Options &options);
    // The result of the last finished update (stateChanged() carries CanUpdateFlow::State).
    const CanUpdateFlow::Result &result() const { return m_result; }

private:
    CanUpdateFlow::Result m_result;
};

} // namespace imudesk::firmware
