#pragma once
// Bounded log of the raw bytes a link carried in both directions (for the console's
// hex/ASCII view). Written by the session's worker, read by views on their clock.
#include <QByteArray>

#include <cstdint>
#include <deque>
#include <mutex>
#include <vector>

namespace imudesk::device {

class RawByteLog {
public:
    enum class Direction : uint8_t { Rx, Tx };
    struct Chunk {
        uint64_t seq = 0;
        int64_t hostTimeNs = 0;
        Direction direction = Direction::Rx;
        QByteArray bytes;
    };

    // Spare capacity a held chunk may keep beyond its bytes before it is copied to size.
    static constexpr qsizetype kSpareCapacity = 64;

    explicit RawByteLog(size_t maxBytes = 256 * 1024);

    void append(Direction direction, const QByteArray &bytes, int64_t hostTimeNs);
    void clear();
    // Chunks with seq >= fromSeq still held (oldest first).
    std::vector<Chunk> since(uint64_t fromSeq) const;
    uint64_t nextSeq() const;
    size_t bytesHeld() const;
    size_t maxBytes() const { return m_maxBytes; }

private:
    const size_t m_maxBytes;
    mutable std::mutex m_mutex;
    std::deque<Chunk> m_chunks;
    size_t m_bytes = 0;
    uint64_t m_nextSeq = 0;
};

} // namespace imudesk::device
