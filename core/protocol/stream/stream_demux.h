#pragma once
// Splits one serial byte stream into HiPNUC binary frames, NMEA sentences and
// ASCII reply lines (they share the UART). Binary frames take precedence: only
// bytes that belong to no CRC-valid frame are considered as text. A line begins with
// printable ASCII and holds no control bytes but CR; bytes from 0x80 up after its
// first are kept as they came (they are not necessarily UTF-8).
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/nmea/nmea_parser.h"

#include <cstdint>
#include <string>
#include <vector>

namespace imudesk::protocol {

struct StreamEvent {
    enum class Kind { Frame, Nmea, NmeaError, Line };
    Kind kind = Kind::Frame;
    std::vector<uint8_t> payload;        // Frame: the frame's payload
    std::string text;                    // Nmea/NmeaError/Line: the line without CR/LF
    nmea::NmeaError nmeaError = nmea::NmeaError::None;
};

class StreamDemux {
public:
    static constexpr size_t kMaxLine = 512;

    struct Counters {
        uint64_t nmeaSentences = 0;
        uint64_t nmeaErrors = 0;
        uint64_t lines = 0;
        uint64_t garbageBytes = 0; // skipped bytes that were not part of any line or sentence
        // Bytes of the lines and sentences handed out (replies, NMEA), their CR and LF included:
        // the frame decoder counts them as skipped, but they are not damage.
        uint64_t lineBytes = 0;
        uint64_t quarantinedLines = 0; // lines dropped because they may have been frame bytes
    };

    void feed(const uint8_t *data, size_t n, std::vector<StreamEvent> &out);
    std::vector<StreamEvent> feed(const uint8_t *data, size_t n)
    {
        std::vector<StreamEvent> out;
        feed(data, n, out);
        return out;
    }
    // End of stream: flushes an unterminated line and the decoder's tail.
    void finish(std::vector<StreamEvent> &out);
    // The line went quiet: an unfinished binary candidate will not complete (a UART sends
    // a frame without pauses), so frames and text held behind it are released.
    void flushPending(std::vector<StreamEvent> &out);
    size_t pendingBytes() const { return m_decoder.pendingBytes(); }
    // Forgets partial frames and lines (after a baud change or reconnect) and quarantines text.
    void reset();

    // Text quarantine: at the start of a stream and after a damaged frame, bytes that look like
    // text may be the tail of a frame, so lines are dropped until a boundary is certain again:
    // a CRC-valid frame, a valid NMEA sentence, or endQuarantine() (the owner knows the line was
    // quiet, or it just sent a command whose reply follows).
    bool quarantined() const { return m_quarantined; }
    void endQuarantine() { m_quarantined = false; }

    const hipnuc::FrameDecoder::Counters &frameCounters() const { return m_decoder.counters(); }
    const Counters &counters() const { return m_counters; }
    void resetCounters();

private:
    class Router;
    void textBytes(const uint8_t *p, size_t n, std::vector<StreamEvent> &out);
    // terminator: the LF that ended the line (1), or none at the end of the stream (0).
    void endLine(std::vector<StreamEvent> &out, size_t terminator);
    void dropPartialLine();
    void dropQuarantinedLine();

    hipnuc::FrameDecoder m_decoder;
    std::string m_line;
    size_t m_lineCr = 0; // CRs received within m_line (ignored, but part of its bytes)
    bool m_lineOverflow = false;
    bool m_quarantined = true;
    Counters m_counters;
};

} // namespace imudesk::protocol
