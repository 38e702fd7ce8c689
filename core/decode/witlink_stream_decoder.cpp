#include "witlink_stream_decoder.h"

#include "protocol/nmea/nmea_parser.h"

namespace imudesk::decode {

namespace wl = protocol::witlink;
using protocol::StreamEvent;

void WitlinkStreamDecoder::configure(const std::map<std::string, std::string> &)
{
    m_frames.reset();
    m_text.reset();
    m_sentNs = 0;
}

void WitlinkStreamDecoder::feed(const uint8_t *data, size_t n, int64_t hostNs, Sink &sink)
{
    handle(hostNs, sink, false, data, n);
}

void WitlinkStreamDecoder::lineIdle(int64_t hostNs, Sink &sink)
{
    if (m_frames.pendingBytes() > 0)
        handle(hostNs, sink, true, nullptr, 0);
}

void WitlinkStreamDecoder::finish(int64_t hostNs, Sink &sink)
{
    handle(hostNs, sink, true, nullptr, 0);
    m_textEvents.clear();
    m_text.finish(m_textEvents);
    for (const StreamEvent &e : m_textEvents)
        if (e.kind == StreamEvent::Kind::Nmea)
            nmea(e.text, hostNs, sink);
}

void WitlinkStreamDecoder::handle(int64_t hostNs, Sink &sink, bool idle, const uint8_t *data, size_t n)
{
    m_decoded.clear();
    if (idle)
        m_frames.flushIdle(m_decoded);
    else
        m_frames.feed(data, n, m_decoded);
    // The bytes of no frame: the NMEA output's text (and noise), through the demultiplexer.
    if (std::string text = m_frames.takeSkipped(); !text.empty()) {
        m_textEvents.clear();
        m_text.feed(reinterpret_cast<const uint8_t *>(text.data()), text.size(), m_textEvents);
        for (const StreamEvent &e : m_textEvents) {
            if (e.kind == StreamEvent::Kind::Nmea) {
                if (const auto parsed = protocol::nmea::parseSentence(e.text); parsed.sentence)
                    ++m_byType["NMEA " + parsed.sentence->type];
                nmea(e.text, hostNs, sink);
            } else if (e.kind == StreamEvent::Kind::Line) {
                sink.onText(TextKind::Line, e.text, hostNs);
            }
        }
    }
    for (const wl::Frame &f : m_decoded) {
        const wl::Reply r = wl::decodeReply(f);
        FrameVerdict v;
        if (m_hook) {
            v = m_hook->frame(f, r);
            if (v.skip)
                continue;
        } else if (m_sentNs > 0 && m_sentNs <= hostNs) {
            v.answers = true; // the answer to the request recorded before it
            v.sentNs = m_sentNs;
        }
        const bool data = r.ok() && (r.kind == wl::Reply::Kind::AllData || r.kind == wl::Reply::Kind::Angles);
        if (data) {
            const char *type = r.kind == wl::Reply::Kind::AllData ? "HEC495 record" : "HEC495 angles";
            ++m_byType[type];
            model::Sample s = *wl::sampleOf(r, hostNs);
            // Asked for: the module measured between the question and its answer. Sent on its
            // own (continuous output) it has no bracket and keeps its arrival alone.
            if (v.answers && v.sentNs > 0) {
                const clock::BracketTime b = clock::bracketTime(v.sentNs, hostNs);
                s.commonTimeNs = b.hostNs;
                s.commonUncertaintyNs = b.uncertaintyNs;
                m_brackets.add(b);
            }
            if (!m_hook && v.answers)
                m_sentNs = 0;
            Record rec;
            rec.family = kFamily;
            rec.type = type;
            rec.unitBytes = f.data.size() + 5;
            rec.native = &r;
            sink.onSample(s, rec);
        } else {
            if (!m_hook)
                m_sentNs = 0; // another answer closed the request
            if (!r.ok()) {
                ++m_payloadErrors;
                sink.onPayloadError(PayloadError{wl::Reply::errorText(r.error).toStdString(), f.command, 0}, hostNs);
            }
        }
    }
}

void WitlinkStreamDecoder::restart()
{
    m_frames.reset();
    m_text.reset();
}

void WitlinkStreamDecoder::reset()
{
    restart();
    m_sentNs = 0;
}

void WitlinkStreamDecoder::resetCounters()
{
    m_frames = wl::FrameDecoder{};
    m_text.resetCounters();
    m_byType.clear();
    m_payloadErrors = 0;
}

Counters WitlinkStreamDecoder::counters() const
{
    const auto &f = m_frames.counters();
    Counters c;
    c.bytesIn = f.bytesIn;
    c.frames = f.frames;
    c.crcErrors = f.checksumErrors;
    c.lengthErrors = f.lengthErrors;
    c.bytesSkipped = f.bytesSkipped;
    c.payloadErrors = m_payloadErrors;
    c.framesByType = m_byType;
    c.nmeaSentences = m_text.counters().nmeaSentences;
    c.nmeaErrors = m_text.counters().nmeaErrors;
    return c;
}

} // namespace imudesk::decode
