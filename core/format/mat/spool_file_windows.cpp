#include "format/mat/spool_file.h"

#include <QFile>

#include <algorithm>
#include <cerrno>

namespace imudesk::format::mat {

// QFile's positioned reads and writes, resize and map: Win32's CreateFile, SetFilePointerEx,
// SetEndOfFile and CreateFileMapping underneath. Windows has no copy inside the kernel between
// two open files: the rows go through the buffer.
struct SpoolFile::Impl {
    QFile file;
    uchar *map = nullptr;
};

namespace {

QString writeAll(QFile &file, const void *data, size_t size, uint64_t offset)
{
    if (!file.seek(qint64(offset)))
        return file.errorString();
    auto p = static_cast<const char *>(data);
    while (size > 0) {
        const qint64 n = file.write(p, qint64(size));
        if (n <= 0)
            return file.errorString();
        p += n;
        size -= size_t(n);
    }
    return {};
}

} // namespace

SpoolFile::Impl *SpoolFile::newImpl() { return new Impl; }

void SpoolFile::deleteImpl(Impl *impl) { delete impl; }

QString SpoolFile::create(const QString &path, bool exclusive)
{
    close(false);
    m_path = path;
    m->file.setFileName(path);
    const QIODevice::OpenMode mode = QIODevice::ReadWrite | (exclusive ? QIODevice::NewOnly : QIODevice::Truncate);
    if (!m->file.open(mode))
        return m->file.errorString();
    m->file.setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner);
    return {};
}

bool SpoolFile::isOpen() const { return m->file.isOpen(); }

QString SpoolFile::writeAt(const void *data, size_t size, uint64_t offset)
{
    return writeAll(m->file, data, size, offset);
}

QString SpoolFile::copyTo(uint64_t inOffset, SpoolFile &out, uint64_t outOffset, size_t size, std::vector<char> &buffer)
{
    buffer.resize(std::max<size_t>(buffer.size(), 1 << 16));
    while (size > 0) {
        if (!m->file.seek(qint64(inOffset)))
            return m->file.errorString();
        const qint64 n = m->file.read(buffer.data(), qint64(std::min(size, buffer.size())));
        if (n < 0)
            return m->file.errorString();
        if (n == 0)
            return QStringLiteral("the spool ends early");
        if (QString e = writeAll(out.m->file, buffer.data(), size_t(n), outOffset); !e.isEmpty())
            return e;
        inOffset += uint64_t(n);
        outOffset += uint64_t(n);
        size -= size_t(n);
    }
    return {};
}

QString SpoolFile::reserve(uint64_t bytes)
{
    return m->file.resize(qint64(bytes)) ? QString() : m->file.errorString();
}

const void *SpoolFile::map(size_t bytes, QString *error)
{
    m->file.flush();
    m->map = m->file.map(0, qint64(bytes));
    if (!m->map && error)
        *error = m->file.errorString();
    return m->map;
}

void SpoolFile::dropPages(const void *, size_t)
{
    // Windows trims a process's working set itself under memory pressure; nothing to ask.
}

void SpoolFile::close(bool remove)
{
    if (m->map)
        m->file.unmap(m->map);
    m->map = nullptr;
    if (m->file.isOpen()) {
        m->file.close();
        if (remove)
            m->file.remove();
    }
}

bool SpoolFile::saysDiskFull(int errnoValue)
{
    return errnoValue == ENOSPC || errnoValue == EFBIG || errnoValue == EIO;
}

} // namespace imudesk::format::mat
