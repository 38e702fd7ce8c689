#include "capture_reader.h"

#include "format/crc32.h"

#include <QFile>

#include <cstring>

namespace imudesk::capture {

namespace {

constexpr size_t kReadBlock = 1u << 20;

template<typename T>
T get(const uint8_t *p)
{
    T v;
    std::memcpy(&v, p, sizeof(T));
    return v;
}

} // namespace

CaptureReader::CaptureReader() = default;
CaptureReader::~CaptureReader() = default;

bool CaptureReader::looksLikeCapture(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return false;
    const QByteArray magic = f.read(sizeof capture::kMagic);
    return magic == QByteArray(capture::kMagic, sizeof capture::kMagic);
}

bool CaptureReader::open(const QString &path, QString *error)
{
    close();
    auto file = std::make_unique<QFile>(path);
    if (!file->open(QIODevice::ReadOnly)) {
        if (error)
            *error = tr("Cannot open %1: %2").arg(path, file->errorString());
        return false;
    }
    m_owned = std::move(file);
    m_device = m_owned.get();
    if (!readHeader(error)) {
        if (error)
            *error = tr("%1: %2").arg(path, *error);
        return false;
    }
    return true;
}

bool CaptureReader::open(QIODevice *device, QString *error)
{
    close();
    m_device = device;
    return readHeader(error);
}

void CaptureReader::close()
{
    m_owned.reset();
    m_device = nullptr;
    m_header = CaptureHeader{};
    m_buf.clear();
    m_pos = m_len = 0;
    m_bufOffset = 0;
    m_dataStart = 0;
    m_eof = m_final = m_resync = false;
    m_damaged = 0;
    m_message.clear();
}

qint64 CaptureReader::size() const
{
    return m_device ? m_device->size() : 0;
}

bool CaptureReader::fill(size_t need)
{
    if (m_len - m_pos >= need)
        return true;
    if (m_pos > 0) { // keep only the unread bytes
        std::memmove(m_buf.data(), m_buf.data() + m_pos, m_len - m_pos);
        m_bufOffset += qint64(m_pos);
        m_len -= m_pos;
        m_pos = 0;
    }
    while (m_len < need && !m_eof) {
        const size_t want = std::max(need - m_len, kReadBlock);
        if (m_buf.size() < m_len + want)
            m_buf.resize(m_len + want);
        const qint64 n = m_device->read(reinterpret_cast<char *>(m_buf.data() + m_len), qint64(want));
        if (n <= 0) {
            m_eof = true;
            break;
        }
        m_len += size_t(n);
    }
    return m_len >= need;
}

bool CaptureReader::readHeader(QString *error)
{
    auto bad = [&](const QString &why) {
        if (error)
            *error = why;
        m_device = nullptr;
        m_owned.reset();
        return false;
    };
    if (!fill(capture::kFileHeaderFixed) || std::memcmp(m_buf.data(), capture::kMagic, sizeof capture::kMagic) != 0)
        return bad(tr("not an ImuDesk capture file (it does not start with IMUDCAP1); raw byte dumps are read by "
                      "'imudesk-cli decode'"));
    const uint16_t version = get<uint16_t>(m_buf.data() + 8);
    if (version != capture::kVersion)
        return bad(tr("capture format version %1 is newer than this ImuDesk reads (%2); update ImuDesk")
                       .arg(version)
                       .arg(capture::kVersion));
    const uint32_t bodyLen = get<uint32_t>(m_buf.data() + 12);
    if (bodyLen > CaptureHeader::kMaxBodyBytes)
        return bad(tr("the capture header claims %1 bytes (at most %2): the file is damaged")
                       .arg(bodyLen)
                       .arg(CaptureHeader::kMaxBodyBytes));
    const size_t total = capture::kFileHeaderFixed + bodyLen + 4;
    if (!fill(total))
        return bad(tr("the file ends inside the capture header: nothing was recorded"));
    if (format::crc32(0, m_buf.data(), total - 4) != get<uint32_t>(m_buf.data() + total - 4))
        return bad(tr("the capture header's CRC does not match: the file is damaged"));
    QString why;
    if (!CaptureHeader::decodeBody(m_buf.data() + capture::kFileHeaderFixed, bodyLen, m_header, &why))
        return bad(why);
    m_pos = total;
    m_dataStart = qint64(total);
    return true;
}

bool CaptureReader::seek(qint64 offset)
{
    if (!m_device || offset < m_dataStart)
        return false;
    if (offset >= m_bufOffset && offset <= m_bufOffset + qint64(m_len)) {
        m_pos = size_t(offset - m_bufOffset);
    } else {
        if (!m_device->seek(offset))
            return false;
        m_bufOffset = offset;
        m_pos = m_len = 0;
        m_eof = false;
    }
    m_final = m_resync = false;
    m_message.clear();
    return true;
}

CaptureReader::Result CaptureReader::next(Chunk &chunk)
{
    if (!m_device)
        return Result::Error;
    if (m_final)
        return m_finalResult;
    for (;;) {
        if (m_resync) {
            // Find the next chunk magic after the damaged one.
            bool found = false;
            while (!found) {
                if (!fill(4))
                    break;
                const uint8_t *p = m_buf.data() + m_pos;
                const uint8_t *end = m_buf.data() + m_len - 3;
                const uint8_t *hit = p;
                while (hit < end && get<uint32_t>(hit) != capture::kChunkMagic)
                    ++hit;
                m_pos += size_t(hit - p);
                found = hit < end;
            }
            m_resync = false;
        }
        if (!fill(1)) {
            m_final = true;
            m_finalResult = Result::End;
            m_message.clear();
            return Result::End;
        }
        if (!fill(capture::kChunkHeaderSize)) {
            m_final = true;
            m_finalResult = Result::Truncated;
            m_message = tr("the file ends inside a chunk at offset %1 (recording was interrupted); everything before "
                           "it was read")
                            .arg(position());
            return Result::Truncated;
        }
        const uint8_t *h = m_buf.data() + m_pos;
        const uint32_t len = get<uint32_t>(h + 8);
        const qint64 at = position();
        if (get<uint32_t>(h) != capture::kChunkMagic || len == 0 || len > capture::kMaxChunkPayload) {
            ++m_damaged;
            m_message = tr("damaged chunk at offset %1 (bad framing); skipped").arg(at);
            ++m_pos;
            m_resync = true;
            return Result::Damaged;
        }
        const size_t total = capture::kChunkHeaderSize + len + capture::kChunkTrailerSize;
        if (!fill(total)) {
            // The file ends before the claimed length: an interrupted last chunk, unless a
            // chunk follows (then the length itself is damaged).
            bool later = false;
            for (size_t i = m_pos + 1; i + 4 <= m_len && !later; ++i)
                later = get<uint32_t>(m_buf.data() + i) == capture::kChunkMagic;
            if (later) {
                ++m_damaged;
                m_message = tr("damaged chunk at offset %1 (bad length); skipped").arg(at);
                ++m_pos;
                m_resync = true;
                return Result::Damaged;
            }
            m_final = true;
            m_finalResult = Result::Truncated;
            m_message = tr("the file ends inside a chunk at offset %1 (recording was interrupted); everything before "
                           "it was read")
                            .arg(at);
            return Result::Truncated;
        }
        h = m_buf.data() + m_pos;
        if (format::crc32(0, h, total - 4) != get<uint32_t>(h + total - 4)) {
            ++m_damaged;
            m_message = tr("damaged chunk at offset %1 (CRC mismatch); skipped").arg(at);
            ++m_pos;
            m_resync = true;
            return Result::Damaged;
        }
        chunk.kind = capture::ChunkKind(get<uint16_t>(h + 4));
        chunk.monotonicNs = get<int64_t>(h + 12);
        chunk.wallUs = get<int64_t>(h + 20);
        chunk.data = h + capture::kChunkHeaderSize;
        chunk.size = len;
        chunk.offset = at;
        m_pos += total;
        return Result::Chunk;
    }
}

} // namespace imudesk::capture
