#pragma once
// The one session engine: whatever the device family, it owns the transport, the request
// queue (one request on the line at a time, timeout, retries, cancel), the path of received
// bytes (raw-byte log, a recording's tap, the family's decoder, the bounded sample store), the
// statistics snapshot and, through a Reconnector (reconnector.h), the reconnection after a
// failed link. The family plug-in (family_plugin.h) says what the bytes mean.
//
// Lives in the session's worker thread (Session moves it there); every slot is called queued.
#include "device/family_plugin.h"
#include "device/raw_byte_log.h"
#include "device/reconnector.h"
#include "device/request.h"
#include "device/sample_store.h"
#include "device/session_types.h"
#include "device/stream_tap.h"
#include "io/transport.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <deque>
#include <memory>
#include <optional>
#include <vector>

namespace imudesk::device {

class SessionEngine : public QObject {
    Q_OBJECT
public:
    static constexpr int kStatsPeriodMs = 500;

    // Takes both (as children: they move to the engine's thread with it).
    SessionEngine(FamilyPlugin *family, io::Transport *transport, SampleStore &store, RawByteLog &rawLog,
                  int lineIdleMs);
    ~SessionEngine() override;

    // --- For the family plug-in (engine thread)
    io::Transport &transport() const { return *m_transport; }
    SessionState state() const { return m_state; }
    void setState(SessionState s, const QString &detail = QString());
    // The link could not be brought up: close it, state Failed, errorOccurred(message).
    void fail(const QString &message);
    void reportError(const QString &message) { Q_EMIT errorOccurred(message); }
    void setIdentity(const model::DeviceIdentity &identity);
    const model::DeviceIdentity &identity() const { return m_identity; }
    // The rate the device was last heard at (reconnection reopens there; 0: never).
    void setWorkingBaud(int baud) { m_workingBaud = baud; }
    int workingBaud() const { return m_workingBaud; }
    // Counters start again from zero (after a detection found the rate).
    void restartStatistics();
    void appendSamples(std::vector<model::Sample> &batch);

    // first: ahead of everything queued (a write's read-back directly after the write).
    void submit(Request r, bool first = false);
    // Ends r at once as NotSent with `why` (the family refused to encode it).
    void refuse(Request r, const QString &why);
    const Request *current() const { return m_current ? &*m_current : nullptr; }
    bool idle() const { return !m_current && m_queue.empty(); }
    void finishCurrent(RequestResult result);
    // A held request (holdWriteMs) may go out now.
    void releaseHeldWrite();
    void cancelAll(RequestStatus status, const QString &why);

    // Hands the open transport to another engine (the serial family detection, LinkOpener):
    // the family stops, requests are cancelled, and the transport, no longer this engine's,
    // moves to `thread` without a parent. The engine is closed and cannot open again.
    std::unique_ptr<io::Transport> releaseTransport(QThread *thread);

public Q_SLOTS:
    // A transport that is already open at `address` (handed over by a detection) is taken as
    // it is, tuned to `baud` when one is given; else it is opened.
    void open(const QString &address, int baud);
    void close();
    void setAutoReconnect(bool on);
    // The tap (record/recording.h) gets the bytes and samples from now until stopRecording(),
    // close() or its own failure; header: entries beside the engine's (identity, link, baud).
    void startRecording(const QString &path, std::shared_ptr<imudesk::device::StreamTap> tap,
                        const imudesk::capture::CaptureHeader &header);
    void stopRecording();
    void publishStats();

Q_SIGNALS:
    void stateChanged(imudesk::device::SessionState state, const QString &detail);
    void identityChanged(const imudesk::model::DeviceIdentity &identity);
    void statsUpdated(const imudesk::device::SessionStats &stats);
    void errorOccurred(const QString &message);
    // A condition of the stream worth a note that stays in view while it lasts (bytes that form
    // no frame); an empty message withdraws it (frames again, or the port closed).
    void streamWarning(const QString &message);
    void requestFinished(const imudesk::device::RequestResult &result);
    void reconnected();
    void recordingStarted(const QString &path);
    void recordingStopped(const QString &reason); // empty: stopped as asked
    void recordingProgress(quint64 bytesWritten, quint64 frames);

private:
    void onBytes(const QByteArray &bytes);
    void onLineIdle();
    void onTransportFailed(const QString &message);
    // After the family stopped, what else runs on the link stops (reconnection, the idle timer,
    // the requests, the recording); close() and releaseTransport() then part with the transport.
    void stopActivity(const QString &why);
    void startNext();
    void sendCurrent();
    void writeCurrent();
    void onReplyTimeout();
    void end(Request &r, RequestResult result);
    void onReopened();
    void finishRecording(const QString &reason);
    // The tap stopped by itself (any thread): ended here, unless another recording took its place.
    void onTapStopped(const StreamTap *tap, const QString &reason);
    void watchForGarbage(const SessionStats &now, qint64 nowMs);
    void withdrawGarbageWarning();

    FamilyPlugin *m_family;
    io::Transport *m_transport;
    SampleStore &m_store;
    RawByteLog &m_rawLog;
    SessionState m_state = SessionState::Closed;
    model::DeviceIdentity m_identity;
    int m_workingBaud = 0;

    std::deque<Request> m_queue;
    std::optional<Request> m_current;
    QTimer m_replyTimer{this}; // children, so that moveToThread moves them
    QTimer m_holdTimer{this};  // runs while the request on hand waits for a gap (holdWriteMs)
    QTimer m_idleTimer{this};  // releases bytes held behind an unfinished frame when the line goes quiet

    QTimer m_statsTimer{this};
    QElapsedTimer m_statsClock;
    SessionStats m_lastStats;
    qint64 m_lastStatsMs = 0;
    qint64 m_garbageSinceMs = -1; // bytes that form nothing: since when, and whether the user was told
    bool m_garbageReported = false;

    Reconnector m_reconnector;

    std::shared_ptr<StreamTap> m_tap; // the recording, while one runs
};

} // namespace imudesk::device
