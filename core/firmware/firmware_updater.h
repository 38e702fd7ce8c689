#pragma once
// Runs a serial firmware update (UpdateFlow over a SerialByteLink) in its own worker thread
// and reports it with UpdateRunner's queued signals; the GUI and the CLI use this. The port
// must not be open elsewhere (close the DeviceSession first). cancel() is safe from any thread:
// the flow stops between packets and leaves the module in its bootloader, where the next update
// finishes the job.
#include "core/firmware/update_flow.h"
#include "core/firmware/update_runner.h"

namespace imudesk::firmware {

class FirmwareUpdater : public UpdateRunner {
    Q_OBJECT

public:
    explicit FirmwareUpdater(QObject *parent = nullptr);

    // Starts the update; false when one is already running.
    bool start(const QString &portName, const protocol::ihex::FirmwareImage &image, const UpdateFlow::Options &options);
    // The result of the last finished update (stateChanged() carries UpdateFlow::State).
    const UpdateFlow::Result &result() const { return m_result; }

private:
    UpdateFlow::Result m_result;
};

} // namespace imudesk::firmware
