#include "stream_demux.h"

namespace imudesk::protocol {

class StreamDemux::Router : public hipnuc::FrameDecoder::Sink {
public:
    Router(StreamDemux &d, std::vector<StreamEvent> &out) : m_d(d), m_out(out) {}
    void onFrame(const uint8_t *payload, size_t len) override
    {
        m_d.dropPartialLine(); // a frame boundary ends any text: a half line is a frame's tail
        m_d.m_quarantined = false;
        StreamEvent e;
        e.kind = StreamEvent::Kind::Frame;
        e.payload.assign(payload, payload + len);
        m_out.push_back(std::move(e));
    }
    void onSkipped(const uint8_t *bytes, size_t n) override { m_d.textBytes(bytes, n, m_out); }
    void onDamage() override
    {
        m_d.dropPartialLine();
        m_d.m_quarantined = true; // what follows may be the rest of the damaged frame
    }

private:
    StreamDemux &m_d;
    std::vector<StreamEvent> &m_out;
};

void StreamDemux::feed(const uint8_t *data, size_t n, std::vector<StreamEvent> &out)
{
    Router r(*this, out);
    m_decoder.feed(data, n, r);
}

void StreamDemux::finish(std::vector<StreamEvent> &out)
{
    Router r(*this, out);
    m_decoder.finish(r);
    if (!m_line.empty())
        endLine(out, 0);
}

void StreamDemux::flushPending(std::vector<StreamEvent> &out)
{
    Router r(*this, out);
    m_decoder.finish(r);
}

void StreamDemux::reset()
{
    m_decoder.reset();
    m_line.clear();
    m_lineCr = 0;
    m_lineOverflow = false;
    m_quarantined = true;
}

void StreamDemux::resetCounters()
{
    m_decoder.resetCounters();
    m_counters = Counters{};
}

void StreamDemux::dropQuarantinedLine()
{
    ++m_counters.quarantinedLines;
    dropPartialLine();
}

void StreamDemux::dropPartialLine()
{
    m_counters.garbageBytes += m_line.size();
    m_line.clear();
    m_lineCr = 0;
    m_lineOverflow = false;
}

void StreamDemux::textBytes(const uint8_t *p, size_t n, std::vector<StreamEvent> &out)
{
    for (size_t i = 0; i < n; ++i) {
        const uint8_t c = p[i];
        if (c == '\n') {
            endLine(out, 1);
        } else if (c == '\r') {
            // ignored: lines end at LF; a CR alone never ends a reply
            ++m_lineCr;
        } else if (c == '$' && !m_line.empty()) {
            // A new sentence start aborts a partial one (NMEA) or unterminated junk.
            dropPartialLine();
            m_line.push_back('$');
        } else if ((c >= 0x20 && c < 0x7F) || (c >= 0x80 && !m_line.empty())) {
            // A line starts with printable ASCII (a reply's key, "$"); after that, bytes from
            // 0x80 up are its own (a serial read from erased flash, UTF-8 text), kept as sent.
            if (m_line.size() < kMaxLine)
                m_line.push_back(char(c));
            else
                m_lineOverflow = true;
        } else {
            // Not text: it and whatever was collected belong to binary garbage.
            ++m_counters.garbageBytes;
            dropPartialLine();
        }
    }
}

void StreamDemux::endLine(std::vector<StreamEvent> &out, size_t terminator)
{
    const size_t crs = m_lineCr;
    m_lineCr = 0;
    if (m_lineOverflow) {
        dropPartialLine();
        return;
    }
    if (m_line.empty())
        return;
    StreamEvent e;
    if (m_line.front() == '$') {
        const auto r = nmea::parseSentence(m_line);
        if (r.ok()) {
            e.kind = StreamEvent::Kind::Nmea;
            ++m_counters.nmeaSentences;
            m_quarantined = false;
        } else if (m_quarantined) {
            dropQuarantinedLine();
            return;
        } else {
            e.kind = StreamEvent::Kind::NmeaError;
            e.nmeaError = r.error;
            ++m_counters.nmeaErrors;
        }
    } else if (m_quarantined) {
        dropQuarantinedLine();
        return;
    } else {
        e.kind = StreamEvent::Kind::Line;
        ++m_counters.lines;
    }
    m_counters.lineBytes += m_line.size() + crs + terminator;
    e.text = std::move(m_line);
    m_line.clear();
    out.push_back(std::move(e));
}

} // namespace imudesk::protocol
