#include "can_record.h"

#include <algorithm>

namespace imudesk::protocol::can {

namespace {
constexpr uint8_t kExtended = 0x01, kFd = 0x02, kRemote = 0x04, kError = 0x08;
constexpr uint8_t kStamped = 0x10;
constexpr uint8_t kKnownFlags = kExtended | kFd | kRemote | kError | kStamped;
} // namespace

QByteArray toRecord(const CanFrame &f, bool errorFrame, int64_t stampNs)
{
    QByteArray out;
    const uint8_t len = uint8_t(std::min<size_t>(f.len, kMaxCanData));
    out.reserve(CanRecordReader::kHeader + 8 + len);
    out.append(char((f.extended ? kExtended : 0) | (f.fd ? kFd : 0) | (f.remote ? kRemote : 0)
                    | (errorFrame ? kError : 0) | (stampNs != 0 ? kStamped : 0)));
    out.append(char(len));
    for (int i = 0; i < 4; ++i)
        out.append(char((f.id >> (8 * i)) & 0xFF));
    if (stampNs != 0)
        for (int i = 0; i < 8; ++i)
            out.append(char((uint64_t(stampNs) >> (8 * i)) & 0xFF));
    out.append(reinterpret_cast<const char *>(f.data.data()), len);
    return out;
}

void CanRecordReader::feed(const QByteArray &bytes, std::vector<CanRecord> &out)
{
    m_held.append(bytes);
    qsizetype at = 0;
    while (m_held.size() - at >= kHeader) {
        const auto *p = reinterpret_cast<const uint8_t *>(m_held.constData()) + at;
        const uint8_t flags = p[0];
        const uint8_t len = p[1];
        if ((flags & ~kKnownFlags) || len > kMaxCanData) {
            ++m_skipped;
            ++at;
            continue;
        }
        const int stampBytes = (flags & kStamped) ? 8 : 0;
        if (m_held.size() - at < kHeader + stampBytes + len)
            break;
        const uint32_t id = uint32_t(p[2]) | uint32_t(p[3]) << 8 | uint32_t(p[4]) << 16 | uint32_t(p[5]) << 24;
        CanRecord r;
        r.frame = CanFrame::fromBytes(id, flags & kExtended, p + kHeader + stampBytes, len, flags & kFd);
        r.frame.remote = flags & kRemote;
        r.error = flags & kError;
        uint64_t stamp = 0;
        for (int i = 0; i < stampBytes; ++i)
            stamp |= uint64_t(p[kHeader + i]) << (8 * i);
        r.stampNs = int64_t(stamp);
        out.push_back(r);
        at += kHeader + stampBytes + len;
    }
    m_held.remove(0, at);
}

int64_t wireTimeNs(const CanFrame &f, int bitrate)
{
    if (bitrate <= 0)
        return 0;
    // SOF, identifier and control (19 or 39 bits), CRC and its delimiter, ACK, EOF (7): 47 or
    // 67 bits besides the data; stuffing adds up to a fifth of the stuffable ones, a tenth as
    // an average.
    const double bits = (f.extended ? 67.0 : 47.0) + 8.0 * double(f.len);
    return int64_t(bits * 1.1 * 1e9 / double(bitrate));
}

} // namespace imudesk::protocol::can
