#pragma once
// One MCAP file of one live device or of several (issue 37: "a live recording format of one or
// several devices"; issue 54 point 2: recording outside the session engine), written by a thread
// of its own: each device's session hands its samples over through a tap (tap(i), given to
// device::Session::startRecording), which queues them and returns; every 20 ms the writer takes
// what came, encodes it into the file's chunks under the device's name (capture/mcap_recording.h,
// which compresses the chunks on a thread of its own in turn) and closes a chunk twice a second,
// so a recording killed at any moment keeps all but its last second. The sessions never wait for
// it: a device's queue holds kQueueSamples; what arrives while it is full is counted as missed.
#include "device/stream_tap.h"
#include "capture/mcap_recording.h"

#include <QString>

#include <atomic>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace imudesk::record {

class McapRecorder {
public:
    static constexpr size_t kQueueSamples = 30'000; // 30 s of a module at 1 kHz per device
    using Device = capture::McapRecording::Device;  // its header and the label a user set

    McapRecorder() = default;
    ~McapRecorder();
    McapRecorder(const McapRecorder &) = delete;
    McapRecorder &operator=(const McapRecorder &) = delete;

    // Writes the file's start (each device's identity and configuration) and starts the writer.
    bool start(const QString &path, const std::vector<Device> &devices, QString *error);
    // Queues device's samples (any thread; a stopped recorder drops them).
    void append(size_t device, const std::vector<model::Sample> &batch);
    // Writes what is queued, the summary and the footer; the error that stopped the recording, or empty.
    QString stop();
    // Called once, from the writer's thread, when writing fails (a full disk).
    void setFailedHandler(std::function<void(const QString &)> handler) { m_failed = std::move(handler); }

    QString error() const { return m_inbox->errorText(); }
    bool running() const { return m_thread.joinable(); }
    QString path() const { return m_path; }
    // Per device: samples written; and samples missed (all devices).
    std::vector<uint64_t> samples() const;
    uint64_t missed() const { return m_inbox->missed.load(); }
    uint64_t bytesWritten() const { return m_inbox->bytes.load(); }

    // The tap of device i for its session: its samples go to append(i). Its begin() and end()
    // leave the file to this recorder (which the devices share), so a device whose session
    // closes stops being recorded and the others go on. It may outlive the recorder.
    std::shared_ptr<device::StreamTap> tap(size_t device);

private:
    class MemberTap;
    // What the taps share with the writer: a tap may outlive the recorder (its session lets go of
    // it later, in its own thread), so it holds this, not the recorder.
    struct Inbox {
        std::mutex mutex;
        std::condition_variable wake;
        std::vector<std::vector<model::Sample>> queues; // per device, guarded by mutex
        bool stop = true;                               // guarded by mutex
        QString error;                                  // guarded by mutex
        std::vector<std::atomic<uint64_t>> written;     // sized before the writer starts
        std::atomic<uint64_t> missed{0}, bytes{0};
        void append(size_t device, const std::vector<model::Sample> &batch);
        QString errorText();
    };
    void run();
    bool drain();
    void failWith(const QString &message);

    capture::McapRecording m_recording;
    QString m_path;
    std::function<void(const QString &)> m_failed;
    std::shared_ptr<Inbox> m_inbox = std::make_shared<Inbox>();
    std::thread m_thread;
};

// A recording of one device's samples to MCAP, which its session starts (record::startRecording
// with a name ending in .mcap): the file begins with the header the session's engine gives.
class McapTap : public device::StreamTap {
public:
    explicit McapTap(const QString &path) : m_path(path) {}
    bool begin(const capture::CaptureHeader &header, QString *error) override;
    void samples(const std::vector<model::Sample> &batch) override { m_recorder.append(0, batch); }
    Progress progress() const override;
    QString end() override { return m_recorder.stop(); }

private:
    QString m_path;
    McapRecorder m_recorder;
};

} // namespace imudesk::record
