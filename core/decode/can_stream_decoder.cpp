#include "can_stream_decoder.h"

#include <QString>

namespace imudesk::decode {

using namespace protocol::can;

namespace {

int numberOf(const std::map<std::string, std::string> &header, const char *key)
{
    const auto it = header.find(key);
    if (it == header.end())
        return -1;
    bool ok = false;
    const int v = QString::fromStdString(it->second).toInt(&ok);
    return ok ? v : -1;
}

} // namespace

void CanStreamDecoder::configure(const std::map<std::string, std::string> &header)
{
    const auto p = header.find("can.protocol");
    m_decoder = CanDecoder(parseProtocol(QString::fromStdString(p == header.end() ? std::string() : p->second))
                               .value_or(CanProtocol::Auto));
    m_decoder.setHec495Mode(numberOf(header, "can.hec495_mode"));
    m_node = numberOf(header, "can.node");
    m_merged = model::Sample{};
    m_reader.reset();
}

void CanStreamDecoder::setNode(int node)
{
    m_node = node;
    m_merged = model::Sample{};
}

void CanStreamDecoder::feed(const uint8_t *data, size_t n, int64_t hostNs, Sink &sink)
{
    m_records.clear();
    m_reader.feed(QByteArray::fromRawData(reinterpret_cast<const char *>(data), qsizetype(n)), m_records);
    for (const CanRecord &r : m_records) {
        if (r.error) {
            ++m_errorFrames;
            continue;
        }
        ++m_frames;
        m_bytesIn += r.frame.len;
        const DecodedFrame d = m_decoder.decode(r.frame);
        ++m_byType[frameKindName(d.kind)];
        if (m_hook && m_hook->frame(r.frame, d, hostNs))
            continue;
        if (!d.sample)
            continue;
        if (m_node < 0 && d.node >= 0) {
            m_node = d.node;
            if (m_hook)
                m_hook->nodeFollowed(m_node);
        }
        if (d.node >= 0 && d.node != m_node)
            continue;
        mergeComponents(m_merged, *d.sample, d.components);
        model::Sample s = m_merged;
        s.hostTimeNs = hostNs;
        // The sample was sent when the frame's bits began: its receive stamp less its time on
        // the bus (issue 36: what a CAN device without a counter has for a common time).
        if (r.stampNs > 0) {
            s.commonTimeNs = r.stampNs - wireTimeNs(r.frame, m_bitrate);
            ++m_stamped;
        } else {
            ++m_unstamped;
        }
        Record rec;
        rec.family = kFamily;
        rec.type = frameKindName(d.kind);
        rec.unitBytes = CanRecordReader::kHeader + r.frame.len;
        rec.native = &d;
        sink.onSample(s, rec);
    }
}

void CanStreamDecoder::reset()
{
    m_reader.reset();
    m_merged = model::Sample{};
}

void CanStreamDecoder::resetCounters()
{
    m_decoder.resetCounters();
    m_byType.clear();
    m_frames = m_bytesIn = m_errorFrames = 0;
    m_stamped = m_unstamped = 0;
}

Counters CanStreamDecoder::counters() const
{
    Counters c;
    c.frames = m_frames;
    c.bytesIn = m_bytesIn;
    c.framesByType = m_byType;
    c.payloadErrors = m_errorFrames; // error frames the interface reported
    c.bytesSkipped = m_decoder.counters().unknownFrames + m_reader.bytesSkipped();
    c.lengthErrors = m_decoder.counters().malformed;
    return c;
}

} // namespace imudesk::decode
