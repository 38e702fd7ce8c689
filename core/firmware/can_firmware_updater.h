#pragma once
// Runs a CAN firmware update (CanUpdateFlow over a QtCanFrameLink) in its own worker thread and
// reports it with queued signals shaped like FirmwareUpdater's, so the GUI and the CLI treat both
// links alike. The bus device is created and used in the worker thread; a CanSession on the
// same interface may stay open (CAN is a shared bus), but its own SDO requests to the node would
// disturb the update. cancel() is safe from any thread: the flow sends an SDO abort between
// segments and leaves the module in its bootloader, where the next update finishes the job.
#include "firmware/can_update_flow.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <memory>

QT_BEGIN_NAMESPACE
class QThread;
QT_END_NAMESPACE

namespace imudesk::firmware {

class CanFirmwareUpdater : public QObject {
    Q_OBJECT

public:
    struct Bus {
        QString plugin;        // e.g. "socketcan", "virtualcan", "peakcan"
        QString interfaceName; // e.g. "can0"
        int bitrate = 0;       // bit/s; 0 leaves the interface's setting
    };

    explicit CanFirmwareUpdater(QObject *parent = nullptr);
    ~CanFirmwareUpdater() override;

    // Starts the update; false when one is already running.
    bool start(const Bus &bus, const protocol::ihex::FirmwareImage &image, const CanUpdateFlow::Options &options);
    void cancel();
    bool isRunning() const { return m_thread != nullptr; }
    // The result of the last finished update.
    const CanUpdateFlow::Result &result() const { return m_result; }

Q_SIGNALS:
    void stateChanged(int state, const QString &name);   // CanUpdateFlow::State
    void progressChanged(qulonglong done, qulonglong total, double bytesPerSecond, double secondsLeft);
    void logMessage(const QString &line);
    void finished(bool ok, const QString &message);

private:
    void onWorkerDone();

    struct Shared {
        std::atomic<bool> cancel{false};
        std::shared_ptr<CanUpdateFlow> flow; // set by the worker; read with std::atomic_load
    };
    QThread *m_thread = nullptr;
    std::shared_ptr<Shared> m_shared;
    CanUpdateFlow::Result m_result;
};

} // namespace imudesk::firmware
