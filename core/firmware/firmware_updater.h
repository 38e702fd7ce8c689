#pragma once
// Runs a serial firmware update (UpdateFlow over a SerialByteLink) in its own worker thread
// and reports it with queued signals; the GUI and the CLI use this. The port must not be
// open elsewhere (close the DeviceSession first). cancel() is safe from any thread: the flow
// stops between packets and leaves the module in its bootloader, where the next update
// finishes the job.
#include "firmware/update_flow.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <memory>

QT_BEGIN_NAMESPACE
class QThread;
QT_END_NAMESPACE

namespace imudesk::firmware {

class FirmwareUpdater : public QObject {
    Q_OBJECT

public:
    explicit FirmwareUpdater(QObject *parent = nullptr);
    ~FirmwareUpdater() override;

    // Starts the update; false when one is already running.
    bool start(const QString &portName, const protocol::ihex::FirmwareImage &image, const UpdateFlow::Options &options);
    void cancel();
    bool isRunning() const { return m_thread != nullptr; }
    // The result of the last finished update.
    const UpdateFlow::Result &result() const { return m_result; }

Q_SIGNALS:
    void stateChanged(int state, const QString &name);   // UpdateFlow::State
    void progressChanged(qulonglong done, qulonglong total, double bytesPerSecond, double secondsLeft);
    void logMessage(const QString &line);
    void finished(bool ok, const QString &message);

private:
    void onWorkerDone();

    struct Shared {
        std::atomic<bool> cancel{false};
        std::shared_ptr<UpdateFlow> flow; // set by the worker; read with std::atomic_load
    };
    QThread *m_thread = nullptr;
    std::shared_ptr<Shared> m_shared;
    UpdateFlow::Result m_result;
};

} // namespace imudesk::firmware
