#include "capture_decoder.h"

#include "model/main_status.h"
#include "protocol/witlink/reply.h"

namespace imudesk::capture {

namespace hp = protocol::hipnuc;
using protocol::StreamEvent;

void CaptureDecoder::configure(const CaptureHeader &header)
{
    m_timedIdle = header.value(CaptureHeader::kIdleMarkers) != "1";
    m_witlink = header.value(CaptureHeader::kLinkKind) == "HEC495 serial";
    m_can = header.value(CaptureHeader::kLinkKind) == "CAN";
    const auto number = [&header](const char *key) {
        bool ok = false;
        const int v = QString::fromStdString(header.value(key)).toInt(&ok);
        return ok ? v : -1;
    };
    m_canDecoder = protocol::can::CanDecoder(
        protocol::can::parseProtocol(QString::fromStdString(header.value(CaptureHeader::kCanProtocol)))
            .value_or(protocol::can::CanProtocol::Auto));
    m_canDecoder.setHec495Mode(number(CaptureHeader::kCanHec495Mode));
    m_canNode = number(CaptureHeader::kCanNode);
    m_canMerged = model::Sample{};
    m_clocks.clear();
    m_clocks.setBaud(header.baud());
}

void CaptureDecoder::feedWitlink(const uint8_t *data, size_t n, int64_t hostNs, Sink &sink, bool idle)
{
    m_witlinkFrames.clear();
    if (idle)
        m_witlinkDecoder.flushIdle(m_witlinkFrames);
    else
        m_witlinkDecoder.feed(data, n, m_witlinkFrames);
    // The bytes of no frame: the NMEA output's text (and noise), through the demultiplexer.
    const std::string text = m_witlinkDecoder.takeSkipped();
    if (!text.empty()) {
        m_events.clear();
        m_demux.feed(reinterpret_cast<const uint8_t *>(text.data()), text.size(), m_events);
        dispatch(hostNs, sink);
    }
    for (const auto &f : m_witlinkFrames) {
        const auto reply = protocol::witlink::decodeReply(f);
        if (auto s = protocol::witlink::sampleOf(reply, hostNs)) {
            ++m_witlinkByType[reply.kind == protocol::witlink::Reply::Kind::AllData ? "HEC495 record" : "HEC495 angles"];
            // The answer to the request recorded before it (as Hec495Family brackets it live);
            // output the module sends on its own has its arrival alone.
            if (m_lastSentNs > 0 && m_lastSentNs <= hostNs) {
                const clock::BracketTime b = clock::bracketTime(m_lastSentNs, hostNs);
                s->commonTimeNs = b.hostNs;
                s->commonUncertaintyNs = b.uncertaintyNs;
                m_lastSentNs = 0;
            }
            sink.onSample(*s, hostNs);
        } else {
            m_lastSentNs = 0; // another answer closed the request (live: it answered the current one)
            if (!reply.ok())
                ++m_payloadErrors;
        }
    }
}

void CaptureDecoder::feedCan(const uint8_t *data, size_t n, int64_t hostNs, Sink &sink)
{
    using namespace protocol::can;
    m_canRecords.clear();
    m_canReader.feed(QByteArray::fromRawData(reinterpret_cast<const char *>(data), qsizetype(n)), m_canRecords);
    for (const CanRecord &r : m_canRecords) {
        if (r.error)
            continue;
        const DecodedFrame d = m_canDecoder.decode(r.frame);
        ++m_canByType[frameKindName(d.kind)];
        if (!d.sample)
            continue;
        // The node CanFamily followed: the one the header names, else the first that sent data.
        if (m_canNode < 0 && d.node >= 0)
            m_canNode = d.node;
        if (d.node >= 0 && d.node != m_canNode)
            continue;
        mergeComponents(m_canMerged, *d.sample, d.components);
        model::Sample s = m_canMerged;
        s.hostTimeNs = hostNs;
        if (r.stampNs > 0)
            s.commonTimeNs = r.stampNs - wireTimeNs(r.frame, m_clocks.baud());
        sink.onSample(s, hostNs);
    }
}

void CaptureDecoder::feedChunk(const CaptureReader::Chunk &chunk, Sink &sink)
{
    switch (chunk.kind) {
    case capture::ChunkReceived:
        feed(chunk.data, chunk.size, chunk.monotonicNs, sink);
        break;
    case capture::ChunkLineIdle:
        lineIdle(chunk.monotonicNs, sink);
        break;
    case capture::ChunkSent:
        m_lastSentNs = chunk.monotonicNs; // a request: the next answer's bracket opens here
        break;
    default:
        break; // a kind this version does not know
    }
}

void CaptureDecoder::lineIdle(int64_t hostNs, Sink &sink)
{
    if (m_witlink) {
        if (m_witlinkDecoder.pendingBytes() > 0)
            feedWitlink(nullptr, 0, hostNs, sink, true);
        return;
    }
    if (m_demux.pendingBytes() == 0)
        return; // as the session: its idle timer runs only while bytes are held
    m_events.clear();
    m_demux.flushPending(m_events);
    m_demux.endQuarantine();
    m_clocks.lineIdle();
    dispatch(hostNs, sink);
}

void CaptureDecoder::feed(const uint8_t *data, size_t n, int64_t hostNs, Sink &sink)
{
    if (m_timedIdle && m_haveLast && hostNs - m_lastNs >= kLineIdleNs)
        lineIdle(m_lastNs + kLineIdleNs, sink);
    m_lastNs = hostNs;
    m_haveLast = true;
    if (m_can) {
        feedCan(data, n, hostNs, sink);
        return;
    }
    if (m_witlink) {
        feedWitlink(data, n, hostNs, sink, false);
        return;
    }
    m_events.clear();
    m_demux.feed(data, n, m_events);
    dispatch(hostNs, sink);
    m_clocks.endRead(m_demux.pendingBytes(), hostNs);
}

void CaptureDecoder::finish(Sink &sink)
{
    if (m_witlink)
        feedWitlink(nullptr, 0, m_lastNs, sink, true);
    m_events.clear();
    m_demux.finish(m_events);
    dispatch(m_lastNs, sink);
}

void CaptureDecoder::reset()
{
    m_demux.reset();
    m_witlinkDecoder.reset();
    m_canReader.reset();
    m_canMerged = model::Sample{};
    m_haveLast = false;
    m_lastSentNs = 0;
    const int baud = m_clocks.baud();
    m_clocks.clear(); // the counters jump where a seek lands
    m_clocks.setBaud(baud);
}

void CaptureDecoder::resetCounters()
{
    m_demux.resetCounters();
    m_witlinkDecoder = protocol::witlink::FrameDecoder{};
    m_witlinkByType.clear();
    m_canDecoder.resetCounters();
    m_canByType.clear();
    m_payloadErrors = 0;
}

void CaptureDecoder::dispatch(int64_t hostNs, Sink &sink)
{
    for (const StreamEvent &e : m_events) {
        switch (e.kind) {
        case StreamEvent::Kind::Frame: {
            m_clocks.beginFrame(e.payload.size() + hp::FrameDecoder::kHeaderSize, hostNs);
            const auto res = hp::forEachPacket(e.payload, [&](const hp::Packet &p) {
                const hp::PacketClock c = hp::packetClock(p);
                m_packetCommonNs = c.has ? m_clocks.commonTime(c.source, c.deviceTimeMs, hostNs,
                                                               model::MainStatus::timeBase(c.hasStatus, c.mainStatus))
                                         : 0;
                sink.onPacket(p, hostNs);
            });
            m_packetCommonNs = 0;
            if (!res.ok()) {
                ++m_payloadErrors;
                sink.onPayloadError(res, hostNs);
            }
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

} // namespace imudesk::capture
