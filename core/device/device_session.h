#pragma once
// One connected HiPNUC serial device. The public object lives in the caller's
// thread; its worker (transport, stream demux, command queue) runs in a private
// QThread. All calls are queued to the worker; results come back as signals
// carrying value types. Samples go to a bounded SampleStore.
#include "device/device_link.h"
#include "protocol/hipnuc/ascii_command.h"
#include "device/raw_byte_log.h"
#include "record/capture_writer.h"

#include <QList>
#include <QString>
#include <QThread>

#include <atomic>
#include <memory>
#include <vector>

namespace imudesk::device {

class SessionWorker;

class DeviceSession : public DeviceLink {
    Q_OBJECT
public:
    // Rates tried by auto-detection, in order.
    static const std::vector<int> &detectionBauds();

    explicit DeviceSession(QObject *parent = nullptr);
    ~DeviceSession() override;

    // baud 0 = auto-detect (listen first, then LOG VERSION at each rate).
    void open(const QString &portName, int baud = 0);
    void close() override;
    QString linkKind() const override { return QStringLiteral("HiPNUC serial"); }
    // Queues an ASCII command; the reply arrives in commandFinished(id, reply).
    // Unknown commands get no reply and finish as a timeout.
    quint64 sendCommand(const QString &text, int timeoutMs = 1000);
    // The same for a command made by the typed builders (protocol::hipnuc::commands): one
    // whose arguments were refused is not sent; 0, and `error` gets why.
    quint64 sendCommand(const protocol::hipnuc::Command &command, int timeoutMs = 1000, QString *error = nullptr);
    // Changes the host side of the link (after SERIALCONFIG).
    void setHostBaud(int baud);
    // When the port fails while open (unplugged), wait for the same device to come back
    // (the same USB serial number, else the same path; polled every 500 ms), reopen it
    // at the last working baud, read its identity again and carry on: state Reconnecting
    // while waiting, then Connected and reconnected(). Samples and counters are kept.
    // close() stops the waiting. On by default.
    void setAutoReconnect(bool on);
    bool autoReconnect() const { return m_autoReconnect.load(); }

    // Safe baud change: sends SERIALCONFIG <baud>, follows to the new rate and confirms with
    // LOG VERSION; if the device does not answer there, returns to the old rate, and failing
    // that runs auto-detection. Ends with baudChangeFinished.
    void changeBaud(int baud);
    // After REBOOT or FRESET: waits settleMs, then confirms with LOG VERSION at each rate
    // in turn, then at the current one, failing that auto-detects. Ends with
    // linkRecovered.
    void recoverLink(const QList<int> &bauds, int settleMs);
    // Records every byte received, as received, to a capture file (README, "Capture file
    // format") until stopRecording(), close() or a write error: recordingStarted(path), then
    // recordingProgress every 500 ms and recordingStopped(reason) (empty reason: as asked).
    // header adds entries (e.g. config.* from LOG COMCONFIG) to the identity, port and baud.
    void startRecording(const QString &path, const record::CaptureHeader &header = {},
                        const record::CaptureWriter::Options &options = {});
    void stopRecording();

    // Raw bytes of the link, both directions (bounded).
    RawByteLog &rawLog() { return m_rawLog; }

Q_SIGNALS:
    void baudDetected(int baud);
    // The LOG VERSION query sent after opening at a fixed baud has finished (answered or not).
    void identityQueryFinished(bool answered);
    void commandFinished(quint64 id, const imudesk::protocol::hipnuc::AsciiReply &reply);
    void nmeaReceived(const QString &sentence);
    void textReceived(const QString &line); // ASCII lines that answer no command
    // The device came back after the port failed and the session reopened it.
    void reconnected();
    // changeBaud finished: changed = the device answers at the requested rate; baud = the
    // rate it answers at now (0: it answers nowhere).
    void baudChangeFinished(bool changed, int baud, const QString &detail);
    // recoverLink finished.
    void linkRecovered(bool reachable, int baud, const QString &detail);
    void recordingStarted(const QString &path);
    void recordingStopped(const QString &reason);
    void recordingProgress(quint64 bytesWritten, quint64 frames);

private:
    QThread m_thread;
    RawByteLog m_rawLog;
    SessionWorker *m_worker = nullptr;
    std::atomic<quint64> m_nextId{1};
    std::atomic<bool> m_autoReconnect{true};
};

} // namespace imudesk::device
