#pragma once
// A capture's bytes decoded as the live session decoded them: the decoder of the family the
// capture's header names (decode::decoderFor, the same class the family's live plug-in
// feeds), driven by the capture's chunks. Received chunks are fed with their arrival time;
// a request recorded (a sent chunk) opens the bracket of its answer; with idle markers
// recorded, the markers release held bytes exactly where the live session did, and without
// them a pause of kLineIdleNs between chunks does, as the session's idle timer does. So a
// replay decodes what the live session decoded. Replay, export, analysis and `imudesk-cli
// decode` all decode through it. A capture of a family ImuDesk has no decoder for is refused
// by name (error()), never decoded as another. Plain value class; holds no family code.
#include "capture/capture_header.h"
#include "capture/capture_reader.h"
#include "decode/stream_decoder.h"

#include <QString>

#include <cstdint>
#include <memory>

namespace imudesk::capture {

class CaptureDecoder {
public:
    static constexpr int64_t kLineIdleNs = 30'000'000; // the session's kLineIdleMs

    using Sink = decode::Sink;

    CaptureDecoder();
    CaptureDecoder(CaptureDecoder &&) noexcept;
    CaptureDecoder &operator=(CaptureDecoder &&) noexcept;
    ~CaptureDecoder();

    // Follows the capture's header: its family's decoder, configured as the header says (until
    // then, and for a header naming no family: HiPNUC serial's, as captures before link kinds).
    // False (error() says why) when ImuDesk has no decoder for the family it names.
    bool configure(const CaptureHeader &header);
    const QString &error() const { return m_error; }
    // The family decoded ("HiPNUC serial"); empty when refused.
    std::string family() const { return m_stream ? m_stream->family() : std::string(); }
    // NMEA sentences' samples too (decode::StreamDecoder::setNmeaSamples).
    void setNmeaSamples(bool on);

    // One chunk of a capture, whatever its kind.
    void feedChunk(const CaptureReader::Chunk &chunk, Sink &sink);
    // Bytes that arrived at hostNs (host monotonic clock).
    void feed(const uint8_t *data, size_t n, int64_t hostNs, Sink &sink);
    // The line went idle at hostNs: release what an unfinished unit holds.
    void lineIdle(int64_t hostNs, Sink &sink);
    // End of the capture: releases whatever is held.
    void finish(Sink &sink);
    // Forgets partial units and the clocks (after a seek); counters are kept.
    void reset();
    void resetCounters();

    // The stream's statistics: the live session's for the same bytes.
    decode::Counters counters() const;

private:
    std::unique_ptr<decode::StreamDecoder> m_stream;
    QString m_error;
    bool m_nmeaSamples = false;
    int64_t m_lastNs = 0;
    bool m_haveLast = false;
    bool m_timedIdle = true; // no markers recorded: infer idle lines from pauses between chunks
};

} // namespace imudesk::capture
