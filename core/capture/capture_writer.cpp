#include "capture_writer.h"

#include "capture/capture_format.h"
#include "io/file_sync.h"

#include <QFile>
#include <QFileInfo>
#include <QLoggingCategory>

#include <algorithm>
#include <chrono>

Q_LOGGING_CATEGORY(lcRecord, "imudesk.core.record")

namespace imudesk::capture {

namespace {

std::unique_ptr<QIODevice> openFile(const QString &path, QString *error)
{
    auto file = std::make_unique<QFile>(path);
    if (!file->open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Unbuffered)) {
        if (error)
            *error = file->errorString();
        return nullptr;
    }
    return file;
}

} // namespace

CaptureWriter::CaptureWriter() : m_factory(openFile) {}

CaptureWriter::~CaptureWriter()
{
    stop();
}

QString CaptureWriter::partPath(const QString &path, int part)
{
    if (part == 0)
        return path;
    const QFileInfo info(path);
    const QString suffix = info.completeSuffix();
    const QString number = QStringLiteral("-%1").arg(part, 3, 10, QLatin1Char('0'));
    const QString dir = info.path() == QLatin1String(".") && !path.startsWith(QLatin1String("./"))
        ? QString()
        : info.path() + QLatin1Char('/');
    return dir + info.baseName() + number + (suffix.isEmpty() ? QString() : QLatin1Char('.') + suffix);
}

bool CaptureWriter::start(const QString &path, const CaptureHeader &header, const Options &options, QString *error)
{
    stop();
    m_basePath = path;
    m_header = header;
    m_options = options;
    m_options.flushIntervalMs = std::clamp(m_options.flushIntervalMs, 10, 1000);
    {
        std::lock_guard lock(m_mutex);
        m_status = Status{};
        m_queue.clear();
        m_queuedBytes = 0;
        m_stopRequested = false;
    }
    QString why;
    if (!openPart(0, &why)) {
        if (error)
            *error = why;
        std::lock_guard lock(m_mutex);
        m_status.failed = true;
        m_status.error = why;
        return false;
    }
    {
        std::lock_guard lock(m_mutex);
        m_status.running = true;
    }
    m_thread = std::thread([this] { run(); });
    return true;
}

bool CaptureWriter::openPart(int part, QString *error)
{
    if (m_device) {
        sync();
        m_device->close();
        m_device.reset();
    }
    const QString path = partPath(m_basePath, part);
    QString why;
    m_device = m_factory(path, &why);
    if (!m_device) {
        *error = tr("Cannot create the capture file %1: %2. Choose a folder you can write to.").arg(path, why);
        return false;
    }
    m_part = part;
    m_partBytes = 0;
    m_partGoodBytes = 0;
    m_partHasChunks = false;
    CaptureHeader h = m_header;
    h.set(CaptureHeader::kPart, std::to_string(part));
    const auto bytes = capture::encodeFileHeader(h);
    {
        std::lock_guard lock(m_mutex);
        m_status.paths << path;
    }
    if (!writeAll(bytes.data(), bytes.size())) {
        *error = tr("Cannot write the capture file %1: %2. Check the free disk space.").arg(path, m_device->errorString());
        return false;
    }
    m_partGoodBytes = m_partBytes;
    return true;
}

bool CaptureWriter::append(const char *data, size_t n, int64_t monotonicNs, int64_t wallUs)
{
    if (n == 0)
        return true;
    std::lock_guard lock(m_mutex);
    if (!m_status.running || m_stopRequested) {
        m_status.bytesDropped += n;
        return false;
    }
    m_status.bytesReceived += n;
    // Chunks are bounded by the format; a larger read is split (never happens with a UART).
    for (size_t off = 0; off < n; off += capture::kMaxChunkPayload) {
        const size_t len = std::min<size_t>(n - off, capture::kMaxChunkPayload);
        m_queue.push_back(Pending{capture::ChunkReceived, monotonicNs, wallUs, QByteArray(data + off, qsizetype(len))});
        m_queuedBytes += len;
    }
    if (m_queuedBytes > m_options.maxQueueBytes) {
        // The writer is stuck: it reports and stops; what is queued is still written.
        m_stopRequested = true;
        if (m_status.error.isEmpty())
            m_status.error = tr("Recording stopped: the disk cannot keep up (more than %1 MB waiting to be written). "
                                "Record to a faster disk.")
                                 .arg(m_options.maxQueueBytes >> 20);
    }
    m_wake.notify_one();
    return true;
}

bool CaptureWriter::appendLineIdle(int64_t monotonicNs, int64_t wallUs)
{
    std::lock_guard lock(m_mutex);
    if (!m_status.running || m_stopRequested)
        return false;
    m_queue.push_back(Pending{capture::ChunkLineIdle, monotonicNs, wallUs, QByteArray(1, '\0')});
    m_queuedBytes += 1;
    m_wake.notify_one();
    return true;
}

bool CaptureWriter::appendSent(const char *data, size_t n, int64_t monotonicNs, int64_t wallUs)
{
    if (n == 0 || n > capture::kMaxChunkPayload)
        return n == 0;
    std::lock_guard lock(m_mutex);
    if (!m_status.running || m_stopRequested)
        return false;
    m_queue.push_back(Pending{capture::ChunkSent, monotonicNs, wallUs, QByteArray(data, qsizetype(n))});
    m_queuedBytes += n;
    m_wake.notify_one();
    return true;
}

bool CaptureWriter::writeAll(const uint8_t *data, size_t n)
{
    size_t done = 0;
    while (done < n) {
        const qint64 w = m_device->write(reinterpret_cast<const char *>(data + done), qint64(n - done));
        if (w <= 0)
            return false;
        done += size_t(w);
        m_partBytes += w;
        std::lock_guard lock(m_mutex);
        m_status.bytesWritten += uint64_t(w);
    }
    return true;
}

void CaptureWriter::sync()
{
    if (auto *file = qobject_cast<QFileDevice *>(m_device.get()))
        io::syncFileData(*file);
}

void CaptureWriter::fail(const QString &message)
{
    qCWarning(lcRecord) << message;
    // Cut a partly written chunk off, so the file ends with a complete one.
    if (auto *file = qobject_cast<QFileDevice *>(m_device.get()); file && m_partBytes > m_partGoodBytes)
        file->resize(m_partGoodBytes);
    if (m_device)
        m_device->close();
    m_device.reset();
    std::lock_guard lock(m_mutex);
    m_status.failed = true;
    m_status.running = false;
    m_status.error = message;
    m_queue.clear();
    m_queuedBytes = 0;
}

void CaptureWriter::run()
{
    using Clock = std::chrono::steady_clock;
    const auto interval = std::chrono::milliseconds(m_options.flushIntervalMs);
    auto lastSync = Clock::now();
    std::deque<Pending> batch;
    std::vector<uint8_t> encoded;
    for (;;) {
        bool stopping = false;
        QString overflow;
        {
            std::unique_lock lock(m_mutex);
            m_wake.wait_for(lock, interval, [this] { return !m_queue.empty() || m_stopRequested; });
            batch.swap(m_queue);
            m_queuedBytes = 0;
            stopping = m_stopRequested;
            if (stopping && m_status.running)
                overflow = m_status.error; // set by append() when the queue overflowed
        }
        QString error;
        for (const Pending &p : batch) {
            if (!error.isEmpty())
                break;
            const size_t chunkBytes = p.bytes.size() + capture::kChunkOverhead;
            if (m_partHasChunks
                && ((m_options.splitBytes > 0 && m_partBytes + int64_t(chunkBytes) > m_options.splitBytes)
                    || (m_options.splitSeconds > 0 && p.monotonicNs - m_partStartNs >= m_options.splitSeconds * 1000000000))) {
                if (!openPart(m_part + 1, &error))
                    break;
            }
            if (!m_partHasChunks) {
                m_partHasChunks = true;
                m_partStartNs = p.monotonicNs;
            }
            encoded.clear();
            capture::appendChunk(encoded, p.kind, p.monotonicNs, p.wallUs,
                                 reinterpret_cast<const uint8_t *>(p.bytes.constData()), size_t(p.bytes.size()));
            if (!writeAll(encoded.data(), encoded.size())) {
                error = tr("Recording stopped: writing %1 failed (%2). Everything up to that point is in the file; "
                           "free some disk space and record again.")
                            .arg(partPath(m_basePath, m_part), m_device->errorString());
                break;
            }
            m_partGoodBytes = m_partBytes;
            std::lock_guard lock(m_mutex);
            ++m_status.chunks;
        }
        batch.clear();
        if (!error.isEmpty()) {
            fail(error);
            if (m_stoppedHandler)
                m_stoppedHandler(error);
            return;
        }
        if (stopping || Clock::now() - lastSync >= interval) {
            sync();
            lastSync = Clock::now();
        }
        if (stopping) {
            if (m_device)
                m_device->close();
            m_device.reset();
            {
                std::lock_guard lock(m_mutex);
                m_status.running = false;
                if (!overflow.isEmpty())
                    m_status.failed = true;
            }
            if (!overflow.isEmpty() && m_stoppedHandler)
                m_stoppedHandler(overflow);
            return;
        }
    }
}

QString CaptureWriter::stop()
{
    {
        std::lock_guard lock(m_mutex);
        m_stopRequested = true;
    }
    m_wake.notify_one();
    if (m_thread.joinable())
        m_thread.join();
    if (m_device) { // start() failed after opening
        m_device->close();
        m_device.reset();
    }
    std::lock_guard lock(m_mutex);
    m_status.running = false;
    return m_status.error;
}

CaptureWriter::Status CaptureWriter::status() const
{
    std::lock_guard lock(m_mutex);
    return m_status;
}

} // namespace imudesk::capture
