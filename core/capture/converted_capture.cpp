#include "converted_capture.h"

#include "capture/capture_format.h"

#include <QFileInfo>

namespace imudesk::capture {

bool ConvertedCapture::open(const QString &path, const QString &sourcePath, const char *linkKind, const char *family,
                            const capture::CaptureHeader &header, QString *error)
{
    m_file.setFileName(path);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        if (error)
            *error = tr("Cannot write %1: %2").arg(path, m_file.errorString());
        return false;
    }
    capture::CaptureHeader h = header;
    h.set(capture::CaptureHeader::kLinkKind, linkKind);
    h.set(capture::CaptureHeader::kFamily, family);
    h.set(capture::CaptureHeader::kPort, QFileInfo(sourcePath).fileName().toStdString());
    h.set(capture::CaptureHeader::kApplication, "imudesk");
    m_buf = capture::encodeFileHeader(h);
    m_failed = false;
    return true;
}

void ConvertedCapture::append(int64_t monotonicNs, const uint8_t *data, size_t n, capture::ChunkKind kind)
{
    capture::appendChunk(m_buf, kind, monotonicNs, 0, data, n);
    if (m_buf.size() >= (1u << 20))
        flush();
}

void ConvertedCapture::flush()
{
    if (!m_buf.empty() && m_file.write(reinterpret_cast<const char *>(m_buf.data()), qint64(m_buf.size()))
                              != qint64(m_buf.size()))
        m_failed = true;
    m_buf.clear();
}

bool ConvertedCapture::finish(QString *error)
{
    flush();
    const QString why = m_file.errorString();
    m_file.close();
    if (!m_failed)
        return true;
    QFile::remove(m_file.fileName());
    if (error)
        *error = tr("Writing %1 failed: %2. Check the free disk space.").arg(m_file.fileName(), why);
    return false;
}

void ConvertedCapture::discard()
{
    m_buf.clear();
    m_file.close();
    QFile::remove(m_file.fileName());
}

} // namespace imudesk::capture
