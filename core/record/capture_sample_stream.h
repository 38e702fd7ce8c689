#pragma once
// One capture read a sample at a time, each with its arrival and its common time (the clock
// model the live session used, rebuilt from the capture's chunks: CaptureDecoder) plus an
// offset (a session's twist-to-align result): what a session's export and alignment read.
#include "capture/capture_decoder.h"
#include "capture/capture_reader.h"

#include <QString>

#include <cstdint>
#include <deque>

namespace imudesk::record {

class CaptureSampleStream : public capture::CaptureDecoder::Sink {
public:
    QString name;
    int64_t offsetNs = 0;  // added to every common time
    uint64_t samples = 0;  // taken so far

    bool open(const QString &path, QString *error);
    model::WorldFrame worldFrame() const { return m_reader.header().identity().worldFrame; }
    const capture::CaptureHeader &header() const { return m_reader.header(); }
    // The next sample (nullptr at the end of the capture).
    const model::Sample *peek();
    model::Sample take();
    // Where the sample sits on the session's time: its common time (offset included), its
    // arrival plus the offset where it has no common time.
    int64_t key(const model::Sample &s) const { return s.commonTimeNs != 0 ? s.commonTimeNs : s.hostTimeNs + offsetNs; }

    void onSample(const model::Sample &sample, const decode::Record &record) override;

private:
    void push(model::Sample s);

    capture::CaptureReader m_reader;
    capture::CaptureDecoder m_decoder;
    std::deque<model::Sample> m_queue;
    bool m_ended = false;
};

} // namespace imudesk::record
