#pragma once
// The worker half of Hec495Session: owns the serial transport and the Witlink decoder and
// sends one request at a time. Runs in the session's thread; never touched directly by
// other threads.
//
// Link rules (manual "通讯协议"):
//   * Each request waits kReplyTimeoutMs for its reply and is sent up to kAttempts times:
//     an RS-485 module that is streaming may not hear a command (2.14). While the module
//     streams, a request is written right after an auto-output frame has arrived (the line
//     is quiet until the next one), or after kGapWaitMs without one.
//   * A reply answers the pending request when its command byte is one the request allows
//     (commands::expectedReplies) and it comes from the module's address (2.16's reply to
//     "set address" carries FF). The host's own request heard back (an RS-485 echo) is ignored.
//   * After "set baud" succeeds the host follows to the new rate (the reply comes at the
//     old one, 2.13); after "set address" the new address is used; after "factory reset"
//     9600 and address 0.
//   * Opening: listen kListenMs; data frames mean the module streams (auto-output).
//     Otherwise ask "read all"; a module in its 3 s quiet window after power-on (2.14) still
//     answers commands, so identification retries until kIdentifyWindowMs has passed.
//   * In question/answer mode the session polls "read all" at the polling rate while no
//     other request is pending; auto-output frames (84 angles, 14 record) become samples.
#include "device/hec495_result.h"
#include "device/raw_byte_log.h"
#include "device/sample_store.h"
#include "device/session_types.h"
#include "io/serial_transport.h"
#include "protocol/witlink/frame_decoder.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace imudesk::device {

class Hec495Worker : public QObject {
    Q_OBJECT
public:
    static constexpr int kReplyTimeoutMs = 300;
    static constexpr int kAttempts = 3;
    static constexpr int kListenMs = 200;
    static constexpr int kIdentifyWindowMs = 3500;
    static constexpr int kStatsPeriodMs = 500;
    static constexpr int kLineIdleMs = 30;
    static constexpr int kGapWaitMs = 250;

    Hec495Worker(SampleStore &store, RawByteLog &rawLog, QObject *parent = nullptr);
    ~Hec495Worker() override;

    static const std::vector<int> &detectionBauds();

public Q_SLOTS:
    void open(const QString &portName, int baud, int address);
    void close();
    void request(quint64 id, uint8_t command, const QByteArray &data, int timeoutMs);
    void setPollingRate(int hz);

Q_SIGNALS:
    void stateChanged(imudesk::device::SessionState state, const QString &detail);
    void identityChanged(const imudesk::model::DeviceIdentity &identity);
    void baudChanged(int baud);
    void addressChanged(int address);
    void streamingChanged(bool streaming);
    void commandFinished(quint64 id, const imudesk::device::Hec495Result &result);
    void calibrationPoint(int points);
    void statsUpdated(const imudesk::device::SessionStats &stats);
    void errorOccurred(const QString &message);

private:
    struct Pending {
        quint64 id = 0; // 0: internal (identification, polling)
        uint8_t command = 0;
        std::vector<uint8_t> data;
        int timeoutMs = kReplyTimeoutMs;
        int attempts = 0;
        int maxAttempts = kAttempts;
        std::vector<uint8_t> wire;
        std::function<void(const Hec495Result &)> done;
    };

    void setState(SessionState s, const QString &detail = QString());
    void onBytes(const QByteArray &bytes);
    void onLineIdle();
    void handleFrames(const std::vector<protocol::witlink::Frame> &frames);
    bool answersCurrent(const protocol::witlink::Frame &f) const;
    void applyEffects(const Pending &p, const Hec495Result &r);
    void enqueue(Pending p);
    void startNext();
    void sendCurrent();
    void writeCurrent();
    void finishCurrent(Hec495Result r);
    void onTimeout();
    void cancelAll(Hec495Result::Status status, const QString &why);
    void onTransportFailed(const QString &message);
    void publishStats();
    void poll();
    void setStreaming(bool on);

    // Opening
    void identifyAt(size_t baudIndex);
    void identified(int baud, const protocol::witlink::Reply *reply);
    void identifyFailed();

    SampleStore &m_store;
    RawByteLog &m_rawLog;
    io::SerialTransport *m_transport = nullptr;
    protocol::witlink::FrameDecoder m_decoder;
    std::vector<model::Sample> m_batch;

    std::deque<Pending> m_queue;
    std::optional<Pending> m_current;
    QTimer m_replyTimer{this};
    QTimer m_idleTimer{this};
    QTimer m_pollTimer{this};
    QTimer m_statsTimer{this};
    QTimer m_identifyTimer{this};
    QTimer m_gapTimer{this};
    bool m_waitingForGap = false;

    SessionState m_state = SessionState::Closed;
    QString m_portName;
    int m_address = 0;
    int m_pollHz = 10;
    bool m_streaming = false;
    bool m_identifying = false;
    std::vector<int> m_identifyBauds;
    QElapsedTimer m_lastStreamFrame; // since the last auto-output frame
    bool m_identityKnown = false;

    QElapsedTimer m_statsClock;
    qint64 m_lastStatsMs = 0;
    SessionStats m_lastStats;
    std::map<std::string, uint64_t> m_framesByType;
    std::map<std::string, size_t> m_frameBytes;
    uint64_t m_payloadErrors = 0;
};

} // namespace imudesk::device
