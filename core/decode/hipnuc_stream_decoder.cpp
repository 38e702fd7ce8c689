#include "hipnuc_stream_decoder.h"

#include "model/main_status.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"

#include <cstdio>
#include <iterator>
#include <variant>

namespace imudesk::decode {

namespace hp = protocol::hipnuc;
using protocol::StreamEvent;

namespace {

// The packet's name and tag, by its alternative in hp::Packet (Hi91, Hi92, Hi81, Hi83).
struct PacketKind {
    const char *type;
    int tag;
};
constexpr PacketKind kPacketKinds[] = {{"HI91", hp::TagHi91}, {"HI92", hp::TagHi92}, {"HI81", hp::TagHi81}, {"HI83", hp::TagHi83}};
static_assert(std::variant_size_v<hp::Packet> == std::size(kPacketKinds));

} // namespace

int HipnucStreamDecoder::tagOf(const std::string &source)
{
    for (const PacketKind &k : kPacketKinds)
        if (source == k.type)
            return k.tag;
    return 0;
}

void HipnucStreamDecoder::configure(const std::map<std::string, std::string> &)
{
    m_demux.reset();
    m_clocks.clear();
}

void HipnucStreamDecoder::feed(const uint8_t *data, size_t n, int64_t hostNs, Sink &sink)
{
    m_events.clear();
    m_demux.feed(data, n, m_events);
    dispatch(hostNs, sink);
    // A frame this read ended inside: its bytes so far bound its sampling instant.
    m_clocks.endRead(m_demux.pendingBytes(), hostNs);
}

void HipnucStreamDecoder::lineIdle(int64_t hostNs, Sink &sink)
{
    if (m_demux.pendingBytes() == 0)
        return; // nothing held: the session's idle timer runs only while bytes are
    m_events.clear();
    m_demux.flushPending(m_events);
    m_demux.endQuarantine(); // the line went quiet: the next byte starts something new
    m_clocks.lineIdle();
    dispatch(hostNs, sink);
}

void HipnucStreamDecoder::finish(int64_t hostNs, Sink &sink)
{
    m_events.clear();
    m_demux.finish(m_events);
    dispatch(hostNs, sink);
}

void HipnucStreamDecoder::restart()
{
    m_demux.reset();
    m_clocks.lineIdle(); // what the last read held is gone
}

void HipnucStreamDecoder::reset()
{
    m_demux.reset();
    const int baud = m_clocks.baud();
    m_clocks.clear(); // the counters jump where a seek lands
    m_clocks.setBaud(baud);
}

void HipnucStreamDecoder::resetCounters()
{
    m_demux.resetCounters();
    m_payloadErrors = 0;
}

Counters HipnucStreamDecoder::counters() const
{
    Counters c;
    const auto &fc = m_demux.frameCounters();
    const auto &dc = m_demux.counters();
    c.bytesIn = fc.bytesIn;
    c.frames = fc.frames;
    c.crcErrors = fc.crcErrors;
    c.lengthErrors = fc.lengthErrors;
    // Bytes that were neither a frame nor a reply or NMEA line (a command's OK is not damage).
    c.bytesSkipped = fc.bytesSkipped > dc.lineBytes ? fc.bytesSkipped - dc.lineBytes : 0;
    c.nmeaSentences = dc.nmeaSentences;
    c.nmeaErrors = dc.nmeaErrors;
    c.payloadErrors = m_payloadErrors;
    for (int tag = 0; tag < 256; ++tag) {
        if (!fc.perTag[size_t(tag)])
            continue;
        char name[8];
        std::snprintf(name, sizeof name, "HI%02X", tag);
        c.framesByType[name] = fc.perTag[size_t(tag)];
    }
    if (dc.nmeaSentences)
        c.framesByType["NMEA"] = dc.nmeaSentences;
    return c;
}

void HipnucStreamDecoder::dispatch(int64_t hostNs, Sink &sink)
{
    for (const StreamEvent &e : m_events) {
        switch (e.kind) {
        case StreamEvent::Kind::Frame: {
            const size_t frameBytes = e.payload.size() + hp::FrameDecoder::kHeaderSize;
            m_clocks.beginFrame(frameBytes, hostNs);
            const auto res = hp::forEachPacket(e.payload, [&](const hp::Packet &p) {
                model::Sample s = hp::toSample(p);
                s.hostTimeNs = hostNs;
                if (s.has(model::FieldDeviceTime))
                    m_clocks.stamp(s, model::MainStatus::timeBase(s.has(model::FieldMainStatus), s.mainStatus));
                Record r;
                r.family = kFamily;
                r.type = kPacketKinds[p.index()].type;
                r.tag = kPacketKinds[p.index()].tag;
                r.unitBytes = frameBytes;
                r.native = &p;
                sink.onSample(s, r);
            });
            if (!res.ok()) {
                ++m_payloadErrors;
                sink.onPayloadError(PayloadError{hp::payloadErrorText(res.error), res.errorTag, res.errorOffset}, hostNs);
            }
            break;
        }
        case StreamEvent::Kind::Nmea:
            nmea(e.text, hostNs, sink);
            break;
        case StreamEvent::Kind::Line:
            sink.onText(TextKind::Line, e.text, hostNs);
            break;
        case StreamEvent::Kind::NmeaError:
            break;
        }
    }
    m_events.clear();
}

} // namespace imudesk::decode
