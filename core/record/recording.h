#pragma once
// The recordings a session hands its stream to (issue 54 point 2): the session's engine offers
// what it reads through a device::StreamTap, and the tap is one of these, chosen by the file's
// name. Each writes on a thread of its own, never the one that reads the port:
//  - CaptureTap: every byte received, as received, with its host time (docs/FILE_FORMATS.md,
//    "Capture file format"; capture/capture_writer.h queues and writes);
//  - McapTap (record/mcap_recorder.h): the decoded samples of one device to MCAP; several
//    devices into one MCAP file are McapRecorder's taps.
#include "device/session.h"
#include "device/stream_tap.h"
#include "capture/capture_decoder.h"
#include "capture/capture_writer.h"

#include <QString>

#include <memory>

namespace imudesk::record {

class CaptureTap : public device::StreamTap {
public:
    explicit CaptureTap(const QString &path, const capture::CaptureWriter::Options &options = {});
    bool begin(const capture::CaptureHeader &header, QString *error) override;
    void received(const QByteArray &bytes, int64_t hostNs, int64_t utcUs) override;
    void sent(const QByteArray &bytes, int64_t hostNs, int64_t utcUs) override;
    void lineIdle(int64_t hostNs, int64_t utcUs) override;
    // frames: those whole in the file, decoded as an export or a replay will decode it (a frame
    // whose first bytes arrived before the recording started is not in the file, so the
    // session's own frame counter would count one more than the file holds).
    Progress progress() const override;
    QString end() override;

private:
    struct NoSink : capture::CaptureDecoder::Sink {
        void onSample(const model::Sample &, const decode::Record &) override {}
    };
    QString m_path;
    capture::CaptureWriter::Options m_options;
    capture::CaptureWriter m_writer;
    capture::CaptureDecoder m_decoder; // the engine's thread, as the tap's calls
    NoSink m_noSink;
};

// The recording a file name asks for: MCAP for a name ending in .mcap, else a capture.
std::shared_ptr<device::StreamTap> recordingFor(const QString &path, const capture::CaptureWriter::Options &options = {});
// session.startRecording(path, recordingFor(path, options), header).
void startRecording(device::Session &session, const QString &path, const capture::CaptureHeader &header = {},
                    const capture::CaptureWriter::Options &options = {});

} // namespace imudesk::record
