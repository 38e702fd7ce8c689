#include "capture_decoder.h"

namespace imudesk::record {

namespace hp = protocol::hipnuc;
using protocol::StreamEvent;

void CaptureDecoder::feed(const uint8_t *data, size_t n, int64_t hostNs, Sink &sink)
{
    if (m_haveLast && hostNs - m_lastNs >= kLineIdleNs && m_demux.pendingBytes() > 0) {
        m_events.clear();
        m_demux.flushPending(m_events);
        m_demux.endQuarantine();
        dispatch(m_lastNs + kLineIdleNs, sink);
    }
    m_lastNs = hostNs;
    m_haveLast = true;
    m_events.clear();
    m_demux.feed(data, n, m_events);
    dispatch(hostNs, sink);
}

void CaptureDecoder::finish(Sink &sink)
{
    m_events.clear();
    m_demux.finish(m_events);
    dispatch(m_lastNs, sink);
}

void CaptureDecoder::reset()
{
    m_demux.reset();
    m_haveLast = false;
}

void CaptureDecoder::resetCounters()
{
    m_demux.resetCounters();
    m_payloadErrors = 0;
}

void CaptureDecoder::dispatch(int64_t hostNs, Sink &sink)
{
    for (const StreamEvent &e : m_events) {
        switch (e.kind) {
        case StreamEvent::Kind::Frame: {
            hp::Hi91 h;
            if (hp::decodeHi91(e.payload.data(), e.payload.size(), h)) {
                sink.onPacket(hp::Packet(h), hostNs);
                break;
            }
            const auto res = hp::decodePayload(e.payload);
            for (const auto &p : res.packets)
                sink.onPacket(p, hostNs);
            if (!res.ok())
                ++m_payloadErrors;
            break;
        }
        case StreamEvent::Kind::Nmea:
            sink.onNmea(e.text, hostNs);
            break;
        case StreamEvent::Kind::Line:
            sink.onLine(e.text, hostNs);
            break;
        case StreamEvent::Kind::NmeaError:
            break;
        }
    }
    m_events.clear();
}

} // namespace imudesk::record
