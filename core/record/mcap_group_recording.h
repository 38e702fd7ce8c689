#pragma once
// Several live devices recorded into one MCAP file (issue 37: "a live recording format of one or
// several devices"): each device's channels under its serial number, its identity and
// configuration inside (McapRecording). A writer thread of its own reads every device's sample
// store (device/sample_store.h) every 20 ms, as the views do, and writes what came; its chunk
// closes twice a second, so a recording killed at any moment keeps all but its last second.
// The sessions never wait for it. Samples a store overwrote before the writer read them (it
// holds 100 s at 1 kHz) are counted as missed.
#include "device/sample_store.h"
#include "capture/mcap_recording.h"

#include <QString>

#include <atomic>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace imudesk::record {

class McapGroupRecording {
public:
    struct Member {
        std::shared_ptr<device::SampleStore> store;
        capture::CaptureHeader header;
        std::string label; // a label the user set, or empty (its name: capture::deviceName)
    };

    McapGroupRecording() = default;
    ~McapGroupRecording();
    McapGroupRecording(const McapGroupRecording &) = delete;
    McapGroupRecording &operator=(const McapGroupRecording &) = delete;

    // Writes the file's start and starts the writer; samples that arrive from now on are recorded.
    bool start(const QString &path, std::vector<Member> members, QString *error);
    // Writes what is left, the summary and the footer; the error that stopped the recording, or empty.
    QString stop();
    // The writer's error so far (a full disk stops it), or empty.
    QString error() const;
    bool running() const { return m_thread.joinable(); }
    // Per member: samples written, and samples missed.
    std::vector<uint64_t> samples() const;
    uint64_t missed() const { return m_missed.load(); }
    uint64_t bytesWritten() const { return m_bytes.load(); }

private:
    void run();
    void drain();

    capture::McapRecording m_recording;
    std::vector<Member> m_members;
    std::vector<device::SampleCursor> m_cursors; // one per member
    std::vector<std::atomic<uint64_t>> m_written;
    std::atomic<uint64_t> m_missed{0}, m_bytes{0}; // m_missed: written by the writer thread only
    std::atomic<bool> m_stop{false};
    std::thread m_thread;
    mutable std::mutex m_errorMutex;
    QString m_error;
};

} // namespace imudesk::record
