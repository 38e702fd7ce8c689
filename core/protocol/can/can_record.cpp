#include "can_record.h"

#include <algorithm>

namespace imudesk::protocol::can {

namespace {
constexpr uint8_t kExtended = 0x01, kFd = 0x02, kRemote = 0x04, kError = 0x08;
constexpr uint8_t kKnownFlags = kExtended | kFd | kRemote | kError;
} // namespace

QByteArray toRecord(const CanFrame &f, bool errorFrame)
{
    QByteArray out;
    const uint8_t len = uint8_t(std::min<size_t>(f.len, kMaxCanData));
    out.reserve(CanRecordReader::kHeader + len);
    out.append(char((f.extended ? kExtended : 0) | (f.fd ? kFd : 0) | (f.remote ? kRemote : 0)
                    | (errorFrame ? kError : 0)));
    out.append(char(len));
    for (int i = 0; i < 4; ++i)
        out.append(char((f.id >> (8 * i)) & 0xFF));
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
        if (m_held.size() - at < kHeader + len)
            break;
        const uint32_t id = uint32_t(p[2]) | uint32_t(p[3]) << 8 | uint32_t(p[4]) << 16 | uint32_t(p[5]) << 24;
        CanRecord r;
        r.frame = CanFrame::fromBytes(id, flags & kExtended, p + kHeader, len, flags & kFd);
        r.frame.remote = flags & kRemote;
        r.error = flags & kError;
        out.push_back(r);
        at += kHeader + len;
    }
    m_held.remove(0, at);
}

} // namespace imudesk::protocol::can
