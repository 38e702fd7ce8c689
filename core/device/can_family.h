#pragma once
// A device on a CAN bus (HiPNUC J1939, HiPNUC CANopen, HEC495 CAN) as a session-engine family
// (family_plugin.h). The transport (io::CanTransport) hands frames over as records
// (protocol/can/can_record.h); this plug-in decodes them (protocol::can::CanDecoder), merges
// what a device splits over several frames into one sample per data frame of the node it
// follows, finds nodes (data, heartbeat, boot-up, the SDO scan), and runs configuration jobs.
//
// A job (can_job.h) is a sequence of steps; each step is one engine request: a frame to send
// and what confirms it (a J1939 configuration reply, an SDO reply, an HEC495 write reply,
// traffic from a node, or a pause). A failed or timed-out step ends the job; the next step
// goes out ahead of anything queued after the job. SYNC, NMT, raw frames and scan probes go
// out directly, beside the queue, as on a bus anyone may talk on.
#include "device/can_job.h"
#include "device/can_session_types.h"
#include "device/family_plugin.h"
#include "decode/can_stream_decoder.h"
#include "protocol/can/can_record.h"

#include <QSet>
#include <QTimer>

#include <deque>
#include <map>
#include <optional>
#include <vector>

namespace imudesk::device {

class CanFamily : public FamilyPlugin, private decode::Sink, private decode::CanStreamDecoder::FrameHook {
    Q_OBJECT
public:
    static constexpr int kMaxQueuedJobs = 64;
    static constexpr int kScanSpacingMs = 5;
    static constexpr int kScanTailMs = 300;

    CanFamily();

    // Engine thread. Before the engine opens the link.
    void configure(const CanSessionOptions &options);
    void submitJob(const CanJob &job);
    void sendFrame(const protocol::can::CanFrame &f);
    void setSyncPeriod(int ms);
    void scan(int from, int to);
    void cancelScan();

    QString linkKind() const override { return QStringLiteral("CAN"); }
    void describeCapture(capture::CaptureHeader &h) const override;
    int firstBaud(int requestedBaud) const override { return requestedBaud; }
    void opened(int requestedBaud) override;
    void stopping() override;
    void restartStream() override { m_decoder.restart(); }
    void resetCounters() override;
    void feed(const QByteArray &bytes, int64_t nowNs) override;
    bool midUnit() const override { return false; } // records arrive whole
    void lineIdle(int64_t) override {}
    void fillCounters(SessionStats &s) const override;
    QString prepare(Request &r) override;
    void writing(const Request &r) override;
    void unanswered(const Request &r, RequestResult &result) override;

Q_SIGNALS:
    void framesSeen(const imudesk::device::CanFrameEvents &events);
    void nodeDiscovered(const imudesk::device::CanNodeInfo &info);
    void protocolDetected(int protocol);
    void targetNodeChanged(int node);
    void jobFinished(const imudesk::device::CanRequestResult &result);
    void scanProgress(int done, int total);
    void scanFinished(const QList<int> &nodes, bool cancelled);

private:
    // What a step's request carries (Request::command).
    struct Step {
        quint64 job = 0;
        CanJobStep step;
    };
    bool matchStep(const protocol::can::CanFrame &f, const protocol::can::DecodedFrame &d);
    bool write(const protocol::can::CanFrame &f); // beside the queue (SYNC, NMT, raw frames, scan probes)
    void startJob();
    void submitStep(bool first);
    void stepEnded(const RequestResult &r);
    void finishJob(bool ok, const QString &message, RequestStatus status = RequestStatus::NotSent);
    void noteNode(protocol::can::CanProtocol p, int node, const QString &how);
    void scanTick();
    CanSessionOptions m_options;
    // The stream: records, frames, the followed node's merged samples and the counters (also a
    // replay's: decode/can_stream_decoder.h). The family sees each frame first (frame()).
    decode::CanStreamDecoder m_decoder;
    CanFrameEvents m_frameEvents; // this read's frames, for the monitor
    void onSample(const model::Sample &sample, const decode::Record &record) override;
    bool frame(const protocol::can::CanFrame &f, const protocol::can::DecodedFrame &d, int64_t hostNs) override;
    void nodeFollowed(int node) override;
    void follow(int node);
    protocol::can::CanProtocol m_lastDetected = protocol::can::CanProtocol::Auto;
    std::vector<model::Sample> m_batch;

    std::deque<CanJob> m_jobs;
    std::optional<CanJob> m_job;
    size_t m_step = 0;
    uint32_t m_lastValue = 0;
    QList<CanNodeAnswer> m_answers; // the job's broadcast answers
    QList<quint32> m_values;        // the job's replies' values, in step order

    QTimer m_syncTimer{this};
    QTimer m_scanTimer{this};
    int m_scanNext = 0, m_scanTo = 0, m_scanFrom = 0;
    bool m_scanning = false;
    qint64 m_scanTailUntil = 0;
    QList<int> m_scanFound;
    QSet<QString> m_seenNodes;
    // The node a data frame counts for (its own; the target's for the HEC495 extended variant).
    int dataSource(const protocol::can::DecodedFrame &d) const;
    QSet<int> m_dataNodes; // nodes heard sending data frames (output off can be confirmed)

};

} // namespace imudesk::device
