#pragma once
// The worker half of ReplaySession: reads a capture, paces its chunks on the host
// clock (or as fast as possible), decodes them with CaptureDecoder and fills the
// sample store. Runs in the replay's thread; never touched directly by other threads.
#include "device/frame_gap_counter.h"
#include "device/sample_store.h"
#include "device/session_types.h"
#include "capture/capture_decoder.h"
#include "capture/capture_reader.h"
#include "record/capture_source.h"
#include "record/replay_group.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <vector>

namespace imudesk::record {

class ReplayWorker : public QObject, private capture::CaptureDecoder::Sink {
    Q_OBJECT
public:
    explicit ReplayWorker(device::SampleStore &store, QObject *parent = nullptr);
    ~ReplayWorker() override;

public Q_SLOTS:
    void open(const QString &path, const imudesk::record::ReplayTimeline &timeline = {});
    void close();
    void play();
    void pause();
    void setSpeed(double factor); // 0: as fast as possible
    void seek(double seconds);
    void setLoop(bool on);

Q_SIGNALS:
    void stateChanged(imudesk::device::SessionState state, const QString &detail);
    void identityChanged(const imudesk::model::DeviceIdentity &identity);
    void opened(double durationS, const imudesk::capture::CaptureHeader &header);
    void positionChanged(double seconds);
    void playingChanged(bool playing);
    void finished();
    void statsUpdated(const imudesk::device::SessionStats &stats);
    void nmeaReceived(const QString &sentence);
    void errorOccurred(const QString &message);

private:
    struct IndexEntry {
        qint64 offset;
        int64_t relNs; // chunk time since the first chunk
    };
    void onSample(const model::Sample &sample, const decode::Record &record) override;
    void onText(decode::TextKind kind, const std::string &text, int64_t hostNs) override;
    void tick();
    void seekTo(int64_t relNs);
    void anchor();
    void flushBatch();
    void publishStats();
    void reportPosition(bool force);
    void setPlaying(bool on);

    device::SampleStore &m_store;
    CaptureSource m_source; // owns a converted vendor CSV or raw dump while it plays
    capture::CaptureReader m_reader;
    capture::CaptureDecoder m_decoder;
    device::FrameGapCounter m_gaps;
    std::vector<model::Sample> m_batch;
    std::vector<IndexEntry> m_index;
    void applyOffset(model::Sample &s) const;

    ReplayTimeline m_timeline;
    int64_t m_firstNs = 0; // the timeline's 0 on the capture's clock
    int64_t m_durationNs = 0;
    int64_t m_posNs = 0;
    int64_t m_anchorNs = 0;      // capture time at the anchor
    QElapsedTimer m_wall;        // host time since the anchor
    double m_speed = 1.0;
    bool m_playing = false;
    bool m_drained = false; // the capture's end was reached and what the decoder held released
    bool m_loop = false;
    bool m_open = false;
    int m_baud = 0;
    QTimer m_timer{this};
    QTimer m_statsTimer{this};
    QElapsedTimer m_statsClock;
    qint64 m_lastStatsMs = 0;
    device::SessionStats m_lastStats;
    qint64 m_lastPositionMs = -1000;
    QElapsedTimer m_positionClock;
};

} // namespace imudesk::record
