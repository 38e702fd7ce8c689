#include "raw_byte_log.h"

namespace imudesk::device {

RawByteLog::RawByteLog(size_t maxBytes) : m_maxBytes(maxBytes ? maxBytes : 1) {}

void RawByteLog::append(Direction direction, const QByteArray &bytes, int64_t hostTimeNs)
{
    if (bytes.isEmpty())
        return;
    std::lock_guard lock(m_mutex);
    Chunk c;
    c.seq = m_nextSeq++;
    c.hostTimeNs = hostTimeNs;
    c.direction = direction;
    // A chunk larger than the whole log keeps only its newest bytes. A chunk whose allocation
    // is much larger than its bytes (a read buffer's spare capacity) is copied to its size, so
    // the log holds about maxBytes of memory, not maxBytes of chunks.
    if (size_t(bytes.size()) > m_maxBytes)
        c.bytes = QByteArray(bytes.constData() + bytes.size() - qsizetype(m_maxBytes), qsizetype(m_maxBytes));
    else if (bytes.capacity() > bytes.size() + kSpareCapacity)
        c.bytes = QByteArray(bytes.constData(), bytes.size());
    else
        c.bytes = bytes;
    m_bytes += size_t(c.bytes.size());
    m_chunks.push_back(std::move(c));
    while (m_bytes > m_maxBytes && !m_chunks.empty()) {
        m_bytes -= size_t(m_chunks.front().bytes.size());
        m_chunks.pop_front();
    }
}

void RawByteLog::clear()
{
    std::lock_guard lock(m_mutex);
    m_chunks.clear();
    m_bytes = 0;
}

std::vector<RawByteLog::Chunk> RawByteLog::since(uint64_t fromSeq) const
{
    std::lock_guard lock(m_mutex);
    std::vector<Chunk> out;
    for (auto it = m_chunks.rbegin(); it != m_chunks.rend() && it->seq >= fromSeq; ++it)
        out.push_back(*it);
    return {out.rbegin(), out.rend()};
}

uint64_t RawByteLog::nextSeq() const
{
    std::lock_guard lock(m_mutex);
    return m_nextSeq;
}

size_t RawByteLog::bytesHeld() const
{
    std::lock_guard lock(m_mutex);
    return m_bytes;
}

} // namespace imudesk::device
