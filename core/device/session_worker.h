#pragma once
// The worker half of DeviceSession: owns the transport, the stream demux and the
// one-at-a-time command queue. Runs in the session's thread; never touched directly
// by other threads.
#include "device/frame_gap_counter.h"
#include "device/raw_byte_log.h"
#include "device/sample_store.h"
#include "device/session_types.h"
#include "io/serial_transport.h"
#include "protocol/stream/stream_demux.h"
#include "record/capture_writer.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace imudesk::device {

class SessionWorker : public QObject {
    Q_OBJECT
public:
    SessionWorker(SampleStore &store, RawByteLog &rawLog, QObject *parent = nullptr);
    ~SessionWorker() override;

public Q_SLOTS:
    void open(const QString &portName, int baud);
    void close();
    void sendCommand(quint64 id, const QString &text, int timeoutMs);
    void setHostBaud(int baud);
    // On by default: after the port fails, wait for the same device and reopen it.
    void setAutoReconnect(bool on);
    // Safe baud change (session_worker_baud.cpp): SERIALCONFIG, then follow to the new rate and
    // confirm with LOG VERSION; failing that, back to the old rate; failing that, auto-detect.
    void changeBaud(int baud);
    // After REBOOT or FRESET: wait settleMs, then confirm with LOG VERSION at each rate in
    // turn, then at the current one, failing that auto-detect.
    void recoverLink(const QList<int> &bauds, int settleMs);
    // Recording: every byte received goes to a capture file until stopRecording(), close()
    // or a write error. header adds to what the worker knows (identity, port, baud).
    void startRecording(const QString &path, const imudesk::record::CaptureHeader &header,
                        const imudesk::record::CaptureWriter::Options &options);
    void stopRecording();

Q_SIGNALS:
    void stateChanged(imudesk::device::SessionState state, const QString &detail);
    void baudDetected(int baud);
    void identityChanged(const imudesk::model::DeviceIdentity &identity);
    // The LOG VERSION query sent after opening at a fixed baud has finished (answered or not).
    void identityQueryFinished(bool answered);
    void commandFinished(quint64 id, const imudesk::protocol::hipnuc::AsciiReply &reply);
    void statsUpdated(const imudesk::device::SessionStats &stats);
    void nmeaReceived(const QString &sentence);
    void textReceived(const QString &line);
    void errorOccurred(const QString &message);
    void reconnected();
    // changeBaud finished: changed = the device answers at the requested rate; baud = where it answers (0: nowhere).
    void baudChangeFinished(bool changed, int baud, const QString &detail);
    // recoverLink finished: the device answers at baud (0 and reachable false: nowhere).
    void linkRecovered(bool reachable, int baud, const QString &detail);
    void recordingStarted(const QString &path);
    void recordingStopped(const QString &reason); // empty: stopped as asked
    void recordingProgress(quint64 bytesWritten, quint64 frames);

private:
    using Reply = protocol::hipnuc::AsciiReply;
    struct Pending {
        quint64 id = 0; // 0 = internal
        QString text;
        int timeoutMs = 1000;
        std::function<void(const Reply &)> done;
    };

    void setState(SessionState s, const QString &detail = QString());
    void onBytes(const QByteArray &bytes);
    void handleEvents();
    void onLineIdle();
    void onTransportFailed(const QString &message);
    void enqueue(Pending p);
    void startNext();
    void finishCurrent(Reply reply);
    void onCommandTimeout();
    void cancelAll(Reply::Status status, const QString &why);
    void publishStats();

    // Frames lost: the gap counter's timing follows what the commands do to the output.
    void noteCommandSent(const QString &text);
    void noteCommandDone(const QString &text, const Reply &reply);
    SessionStats counterSnapshot() const;

    // Reconnection after the port failed.
    void rememberDevice(const QString &portName);
    QString locateDevice() const;
    void startWaiting();
    void tryReconnect();
    void listenThenQueryIdentity();
    void noteIdentity(const model::DeviceIdentity &id);

    // Auto-detection
    void detectAt(size_t index);
    void detectQuery(bool retry);
    void detectFinished(int baud, const std::optional<model::DeviceIdentity> &id);
    void queryIdentity(int attempt);

    // Link recovery (session_worker_baud.cpp)
    using LinkDone = std::function<void(bool reachable, int baud)>;
    void probeBauds(std::vector<int> bauds, size_t index, int attempt, LinkDone done);
    void detectForRecovery(LinkDone done);

    SampleStore &m_store;
    RawByteLog &m_rawLog;
    io::SerialTransport *m_transport = nullptr;
    protocol::StreamDemux m_demux;
    std::vector<protocol::StreamEvent> m_events;
    std::vector<model::Sample> m_batch;

    std::deque<Pending> m_queue;
    std::optional<Pending> m_current;
    std::optional<protocol::hipnuc::ReplyCollector> m_collector;
    QTimer m_commandTimer{this}; // timers are parented so that moveToThread moves them
    QTimer m_idleTimer{this}; // releases bytes held behind an unfinished frame when the line goes quiet

    bool m_detecting = false;
    size_t m_detectIndex = 0;
    uint64_t m_framesAtDetectStart = 0;
    QTimer m_detectTimer{this};
    QString m_portName;

    QTimer m_statsTimer{this};
    QElapsedTimer m_statsClock;
    SessionStats m_lastStats;
    qint64 m_lastStatsMs = 0;
    // Bytes that form nothing (the device changed its baud rate under us): since when, and
    // whether the user was told for this episode.
    qint64 m_garbageSinceMs = -1;
    bool m_garbageReported = false;
    void watchForGarbage(const SessionStats &now, qint64 nowMs);
    uint64_t m_payloadErrors = 0;
    SessionState m_state = SessionState::Closed;

    FrameGapCounter m_gaps;
    std::map<std::string, size_t> m_frameBytes; // last frame size per type (link load of a rate)

    bool m_autoReconnect = true;
    QTimer m_reconnectTimer{this};
    QString m_requestedPort;    // what open() was given: the path to watch
    QString m_serialNumber;     // USB serial number of the port at open time, if any
    quint16 m_vendorId = 0, m_productId = 0;
    bool m_hasUsbIds = false;
    int m_workingBaud = 0;      // last baud the device was heard at (0: never)
    QString m_lastReconnectError;
    uint64_t m_reconnects = 0;
    std::string m_deviceSerial;   // from LOG VERSION: tells whether the same module came back
    bool m_checkSameDevice = false;
    LinkDone m_afterDetect;       // a recovery that fell back to auto-detection

    void finishRecording(const QString &reason);
    std::unique_ptr<record::CaptureWriter> m_recorder;
    model::DeviceIdentity m_identity;
    uint64_t m_framesAtRecordStart = 0;
};

} // namespace imudesk::device
