#pragma once
// One connected device, whatever its family: the public side of the session engine. The
// engine (session_engine.h), its transport and the family plug-in run in a private QThread;
// every call here is queued to them, and results come back as signals carrying value types,
// in the owner's thread. Samples go to the bounded store (DeviceLink::store()).
//
// A family's typed front-end (DeviceSession for HiPNUC serial, Hec495Session for the HEC495)
// derives from this: it builds typed requests with the family's codec and translates the
// family's own signals; queueing, timeouts, statistics, recording and reconnection are here.
#include "device/device_link.h"
#include "device/family_plugin.h"
#include "device/raw_byte_log.h"
#include "device/request.h"
#include "device/stream_tap.h"
#include "io/transport.h"

#include <QThread>
#include <QTimer>

#include <atomic>
#include <memory>

namespace imudesk::device {

class SessionEngine;

class Session : public DeviceLink {
    Q_OBJECT
public:
    // The transport defaults to a serial port (io::SerialTransport). The engine runs in a thread
    // of its own named threadName, or in sharedThread when given (CAN: io::canThread()).
    Session(std::unique_ptr<FamilyPlugin> family, std::unique_ptr<io::Transport> transport,
            const QString &threadName, int lineIdleMs, QObject *parent = nullptr, QThread *sharedThread = nullptr);
    ~Session() override;

    void close() override;
    QString linkKind() const override { return m_linkKind; }
    // A byte link: its raw bytes can be shown.
    Capabilities capabilities() const override { return Capability::RawBytes; }

    // When the link fails while open (unplugged), wait for the same device to come back (the
    // same USB serial number, else the same path; polled every 500 ms), reopen it at the last
    // working baud, identify it again and carry on: state Reconnecting while waiting, then
    // Connected and reconnected(). Samples and counters are kept. close() stops the waiting.
    // On by default; families that do not reconnect report Disconnected and stay there.
    void setAutoReconnect(bool on);
    bool autoReconnect() const { return m_autoReconnect.load(); }

    // Hands what the link reads to a recording (record/recording.h: record::startRecording makes
    // the one a file name asks for, a capture of every byte received or an MCAP file of the
    // samples) until stopRecording(), close() or a write error: recordingStarted(path), then
    // recordingProgress every 500 ms and recordingStopped(reason) (empty reason: as asked).
    // header adds entries (e.g. config.* from LOG COMCONFIG) to the identity, port and baud.
    void startRecording(const QString &path, std::shared_ptr<StreamTap> tap, const capture::CaptureHeader &header = {});
    void stopRecording();

    // Raw bytes of the link, both directions (bounded).
    RawByteLog &rawLog() { return m_rawLog; }

    // Takes the open transport away from this session (closed afterwards, for good) and moves
    // it to the calling thread: a detection hands the port it opened to the family's session,
    // which opens nothing again (LinkOpener). Waits for the engine's thread.
    std::unique_ptr<io::Transport> releaseTransport();

Q_SIGNALS:
    // A request with an id ended; result.reply holds the family's typed reply.
    void requestEnded(const imudesk::device::RequestResult &result);
    // The device came back after the link failed and the session reopened it.
    void reconnected();
    void recordingStarted(const QString &path);
    void recordingStopped(const QString &reason);
    void recordingProgress(quint64 bytesWritten, quint64 frames);

protected:
    void openLink(const QString &address, int baud);
    // Queues a request; its id (set here) comes back in requestEnded.
    quint64 submit(Request request);
    // An id of the session's one id space, for a family front-end's request that is not one
    // engine request (a Modbus verified write, a CAN job): its end is announced with
    // requestEnded too, under this id.
    quint64 takeRequestId() { return m_nextId++; }
    // Announces the end of a front-end's own request (a Modbus register reply, a CAN job result:
    // id, status, ok, message) with requestEnded, its typed result as the reply.
    template <class Result>
    void announceEnded(const Result &r)
    {
        Q_EMIT requestEnded(RequestResult{r.id, r.status, 0, r.ok ? QString() : r.message, QVariant::fromValue(r)});
    }
    // A request refused before it reached the engine: requestEnded(NotSent, why, reply)
    // from the event loop, after the caller has the id.
    quint64 refuse(const QVariant &reply, const QString &why);
    // Runs f(family) in the engine's thread, queued.
    template <class Family, class F>
    void inFamily(F f)
    {
        auto *family = static_cast<Family *>(m_family);
        QMetaObject::invokeMethod(family, [family, f = std::move(f)]() mutable { f(*family); }, Qt::QueuedConnection);
    }
    // For connecting the family's own signals (it lives in the engine's thread).
    FamilyPlugin *family() const { return m_family; }

private:
    QThread m_thread;
    QThread *m_sharedThread = nullptr;
    RawByteLog m_rawLog;
    SessionEngine *m_engine = nullptr;
    FamilyPlugin *m_family = nullptr;
    QString m_linkKind;
    std::atomic<quint64> m_nextId{1};
    std::atomic<bool> m_autoReconnect{true};
};

} // namespace imudesk::device
