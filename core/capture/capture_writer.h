#pragma once
// Background writer of capture files (capture/capture_format.h). append() is cheap and
// thread-safe (the session's worker calls it for every read from the port): it queues
// the bytes with their time stamps; the writer's own thread encodes and writes them,
// and makes them durable (fdatasync) at least every flushIntervalMs.
//
// The queue is bounded (maxQueueBytes). When the disk fails (full, removed, a file size
// limit) or cannot keep up, recording stops by itself: the file is cut back to the end
// of its last complete chunk, so everything written before stays readable, and the
// stopped handler receives a message that says what happened and what to do.
//
// Optional split: a new file (same header, capture.part incremented, name "-001" etc.
// before the suffix) once a file exceeds splitBytes or spans splitSeconds.
#include "capture/capture_format.h"
#include "capture/capture_header.h"

#include <QCoreApplication>
#include <QIODevice>
#include <QString>
#include <QStringList>

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

namespace imudesk::capture {

class CaptureWriter {
    Q_DECLARE_TR_FUNCTIONS(CaptureWriter)

public:
    struct Options {
        int64_t splitBytes = 0;      // 0: never split by size
        int64_t splitSeconds = 0;    // 0: never split by time
        size_t maxQueueBytes = 64u << 20;
        int flushIntervalMs = 500;   // durable at least this often (<= 1000)
    };
    struct Status {
        bool running = false;
        bool failed = false;
        QString error;               // why recording stopped by itself
        uint64_t bytesReceived = 0;  // payload bytes given to append()
        uint64_t bytesWritten = 0;   // file bytes written, headers included, all parts
        uint64_t chunks = 0;         // chunks written
        uint64_t bytesDropped = 0;   // payload bytes refused after a failure
        QStringList paths;           // files written, in order
    };
    // Opens a file for writing (tests replace it to simulate a failing disk).
    using DeviceFactory = std::function<std::unique_ptr<QIODevice>(const QString &path, QString *error)>;
    using StoppedHandler = std::function<void(const QString &reason)>;

    CaptureWriter();
    ~CaptureWriter();
    CaptureWriter(const CaptureWriter &) = delete;
    CaptureWriter &operator=(const CaptureWriter &) = delete;

    void setDeviceFactory(DeviceFactory factory) { m_factory = std::move(factory); }
    // Called once, from the writer's thread, when recording stops by itself (error).
    void setStoppedHandler(StoppedHandler handler) { m_stoppedHandler = std::move(handler); }

    // Creates the first file, writes its header and starts the thread.
    bool start(const QString &path, const CaptureHeader &header, const Options &options, QString *error);
    // Queues bytes received at the given host times. False once recording has stopped.
    bool append(const char *data, size_t n, int64_t monotonicNs, int64_t wallUs);
    // Marks where the session found the line idle (capture::ChunkLineIdle).
    bool appendLineIdle(int64_t monotonicNs, int64_t wallUs);
    // Bytes the host wrote to the device (capture::ChunkSent): a polled device's request, whose
    // time and its answer's bracket the sampling instant in a replay as they did live.
    bool appendSent(const char *data, size_t n, int64_t monotonicNs, int64_t wallUs);
    // Writes what is queued, closes the file and joins the thread. Returns the error, if any.
    QString stop();
    Status status() const;

    // The file name of part n of a split recording ("run.imucap" -> "run-001.imucap").
    static QString partPath(const QString &path, int part);

private:
    struct Pending {
        capture::ChunkKind kind;
        int64_t monotonicNs;
        int64_t wallUs;
        QByteArray bytes;
    };
    void run();
    bool openPart(int part, QString *error);
    bool writeAll(const uint8_t *data, size_t n);
    void fail(const QString &message);
    void sync();

    DeviceFactory m_factory;
    StoppedHandler m_stoppedHandler;
    Options m_options;
    CaptureHeader m_header;
    QString m_basePath;

    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    std::deque<Pending> m_queue;
    size_t m_queuedBytes = 0;
    bool m_stopRequested = false;
    Status m_status;
    std::thread m_thread;

    // Writer thread only.
    std::unique_ptr<QIODevice> m_device;
    int m_part = 0;
    int64_t m_partBytes = 0;        // bytes in the current part
    int64_t m_partGoodBytes = 0;    // ... ending with a complete chunk
    int64_t m_partStartNs = 0;
    bool m_partHasChunks = false;
};

} // namespace imudesk::capture
