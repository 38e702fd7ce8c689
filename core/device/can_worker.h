#pragma once
// The worker side of a CanSession, living in the process-wide CAN thread: owns the
// QCanBusDevice, the decoder and the job queue (one job at a time, one step outstanding),
// merges decoded data into samples for the store, discovers nodes and runs the SDO scan.
#include "can_job.h"
#include "can_session_types.h"
#include "device/sample_store.h"
#include "device/session_types.h"

#include <QElapsedTimer>
#include <QObject>
#include <QSet>
#include <QTimer>

#include <deque>
#include <map>
#include <memory>

QT_BEGIN_NAMESPACE
class QCanBusDevice;
class QThread;
QT_END_NAMESPACE

namespace imudesk::device {

// The thread every CAN session's worker lives in (started on first use, stopped when the
// application object is destroyed). One thread keeps the virtualcan plugin's TCP server alive.
QThread *canThread();

class CanWorker : public QObject {
    Q_OBJECT
public:
    static constexpr int kMaxQueuedJobs = 64;
    static constexpr int kScanSpacingMs = 5;
    static constexpr int kScanTailMs = 300;

    explicit CanWorker(SampleStore *store);
    ~CanWorker() override;

    void open(const CanSessionOptions &options);
    void close();
    void submit(const CanJob &job);
    void sendFrame(const protocol::can::CanFrame &f);
    void setSyncPeriod(int ms);
    void scan(int from, int to);
    void cancelScan();

Q_SIGNALS:
    void stateChanged(imudesk::device::SessionState state, const QString &detail);
    void statsUpdated(const imudesk::device::SessionStats &stats);
    void framesSeen(const imudesk::device::CanFrameEvents &events);
    void nodeDiscovered(const imudesk::device::CanNodeInfo &info);
    void protocolDetected(int protocol);
    void targetNodeChanged(int node);
    void jobFinished(const imudesk::device::CanRequestResult &result);
    void scanProgress(int done, int total);
    void scanFinished(const QList<int> &nodes, bool cancelled);
    void errorOccurred(const QString &message);

private:
    void onFramesReceived();
    void onErrorOccurred(int error);
    void handleFrame(const protocol::can::CanFrame &f, qint64 now, std::vector<model::Sample> &batch);
    bool write(const protocol::can::CanFrame &f, CanFrameEvents *events = nullptr);
    void startNextJob();
    void startStep();
    void stepDone(bool ok, uint32_t value, const QString &message);
    void finishJob(bool ok, const QString &message);
    bool matchStep(const protocol::can::CanFrame &f, const protocol::can::DecodedFrame &d);
    void noteNode(protocol::can::CanProtocol p, int node, const QString &how);
    void scanTick();
    void emitStats();
    qint64 nowNs() const;

    SampleStore *m_store;
    CanSessionOptions m_options;
    std::unique_ptr<QCanBusDevice> m_bus;
    protocol::can::CanDecoder m_decoder;
    protocol::can::CanProtocol m_lastDetected = protocol::can::CanProtocol::Auto;
    int m_target = -1;
    model::Sample m_merged;
    std::deque<CanJob> m_jobs;
    std::optional<CanJob> m_job;
    size_t m_step = 0;
    uint32_t m_lastValue = 0;
    QTimer m_stepTimer{this}; // children, so they move to the CAN thread with the worker
    QTimer m_syncTimer{this};
    QTimer m_statsTimer{this};
    QTimer m_scanTimer{this};
    int m_scanNext = 0, m_scanTo = 0, m_scanFrom = 0;
    bool m_scanning = false;
    qint64 m_scanTailUntil = 0;
    QList<int> m_scanFound;
    QSet<QString> m_seenNodes;
    QElapsedTimer m_clock;
    SessionStats m_stats;
    std::map<std::string, uint64_t> m_rateBase;
    qint64 m_rateBaseNs = 0;
};

} // namespace imudesk::device
