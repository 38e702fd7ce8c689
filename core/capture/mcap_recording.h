#pragma once
// One device's samples into an MCAP file (format/mcap): what File > Export's MCAP and a live
// MCAP recording share. start() writes the header, the device's identity as metadata ("device",
// and "time": what the times mean) and its configuration snapshot as the attachment
// configuration.json; append() writes samples as they come (SampleChannels); tick(), called
// twice a second, closes the chunk, so a recording killed at any moment keeps all but its last
// second; stop() writes the summary.
//
// Times: the samples' host-clock times plus epochOffsetNs (the Unix epoch). Plain class, used in
// one thread.
#include "format/mcap/mcap_writer.h"
#include "format/mcap/sample_channels.h"
#include "capture/capture_header.h"

#include <QElapsedTimer>
#include <QString>

#include <memory>
#include <vector>

namespace imudesk::capture {

class McapRecording {
public:
    McapRecording();
    ~McapRecording();
    // header: the device (identity, link, configuration snapshot) as a capture would have it.
    bool start(const QString &path, const CaptureHeader &header, int64_t epochOffsetNs, QString *error);
    // Several devices in one file (a live recording of several): each one's channels under its
    // name (channelsOf), its identity as the metadata "device <name>", its configuration as
    // the attachment "<name>/configuration.json". append(index, ...) writes the index-th's.
    struct Device {
        CaptureHeader header;
        std::string label; // a label the user set, or empty (its name: capture::deviceName)
    };
    bool start(const QString &path, const std::vector<Device> &devices, int64_t epochOffsetNs, QString *error);
    bool append(size_t device, const model::Sample &s);
    bool append(const model::Sample &s) { return append(0, s); }
    bool append(const std::vector<model::Sample> &batch);
    void tick();
    // The summary and the footer; the error that stopped it, or empty.
    QString stop();
    // Closes the file as it stands (tests: what a crash leaves).
    void abandon();

    bool isOpen() const { return m_writer && m_writer->isOpen(); }
    uint64_t samples() const { return m_samples; }
    uint64_t bytesWritten() const { return m_writer ? m_writer->bytesWritten() : 0; }
    const QString &path() const { return m_path; }
    QString error() const { return m_writer ? m_writer->error() : QString(); }

    // The writer's options of every MCAP file ImuDesk writes (its library named).
    static format::mcap::McapWriter::Options writerOptions();
    // "imudesk-cli record ... -o run.mcap", Record to a name ending in .mcap.
    static bool isMcapPath(const QString &path);
    // What the file says of a device: product, serial, firmware, link, ... from a capture's header.
    static format::mcap::McapWriter::StringMap deviceMetadata(const CaptureHeader &header);
    // The "time" metadata record: what log_time, publish_time and sequence are.
    static format::mcap::McapWriter::StringMap timeMetadata();
    // The configuration snapshot as JSON (empty when the header has none).
    static std::string configurationJson(const CaptureHeader &header);
    // The device's channels under name, or when empty under its own (capture::deviceName).
    static format::mcap::SampleChannels::Device channelsOf(const CaptureHeader &header, const std::string &name = {});

private:
    std::unique_ptr<format::mcap::McapWriter> m_writer;
    std::vector<std::unique_ptr<format::mcap::SampleChannels>> m_channels;
    int64_t m_epochOffsetNs = 0;
    uint64_t m_samples = 0;
    QElapsedTimer m_sinceFlush;
    QString m_path;
};

} // namespace imudesk::capture
