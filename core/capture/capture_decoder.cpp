#include "capture_decoder.h"

namespace imudesk::capture {

CaptureDecoder::CaptureDecoder() : m_stream(decode::decoderFor(std::string())) {}
CaptureDecoder::CaptureDecoder(CaptureDecoder &&) noexcept = default;
CaptureDecoder &CaptureDecoder::operator=(CaptureDecoder &&) noexcept = default;
CaptureDecoder::~CaptureDecoder() = default;

bool CaptureDecoder::configure(const CaptureHeader &header)
{
    m_timedIdle = header.value(CaptureHeader::kIdleMarkers) != "1";
    m_haveLast = false;
    const std::string kind = header.family();
    m_stream = decode::decoderFor(kind);
    if (!m_stream) {
        m_error = decode::unsupportedWhy(kind);
        return false;
    }
    m_error.clear();
    m_stream->setNmeaSamples(m_nmeaSamples);
    m_stream->configure(header.values);
    m_stream->setBaud(header.baud()); // a frame's time on the wire
    return true;
}

void CaptureDecoder::setNmeaSamples(bool on)
{
    m_nmeaSamples = on;
    if (m_stream)
        m_stream->setNmeaSamples(on);
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
        if (m_stream)
            m_stream->sent(chunk.monotonicNs); // a request: the next answer's bracket opens here
        break;
    default:
        break; // a kind this version does not know
    }
}

void CaptureDecoder::lineIdle(int64_t hostNs, Sink &sink)
{
    if (m_stream)
        m_stream->lineIdle(hostNs, sink);
}

void CaptureDecoder::feed(const uint8_t *data, size_t n, int64_t hostNs, Sink &sink)
{
    if (!m_stream)
        return;
    if (m_timedIdle && m_haveLast && hostNs - m_lastNs >= kLineIdleNs)
        m_stream->lineIdle(m_lastNs + kLineIdleNs, sink);
    m_lastNs = hostNs;
    m_haveLast = true;
    m_stream->feed(data, n, hostNs, sink);
}

void CaptureDecoder::finish(Sink &sink)
{
    if (m_stream)
        m_stream->finish(m_lastNs, sink);
}

void CaptureDecoder::reset()
{
    m_haveLast = false;
    if (m_stream)
        m_stream->reset();
}

void CaptureDecoder::resetCounters()
{
    if (m_stream)
        m_stream->resetCounters();
}

decode::Counters CaptureDecoder::counters() const
{
    return m_stream ? m_stream->counters() : decode::Counters{};
}

} // namespace imudesk::capture
