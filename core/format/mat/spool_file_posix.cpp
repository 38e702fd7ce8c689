#include "format/mat/spool_file.h"

#include <QFile>

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace imudesk::format::mat {

namespace {

QString why(int errnoValue) { return QString::fromLocal8Bit(std::strerror(errnoValue)); }

// 0, or the errno of the failed pwrite().
int pwriteAll(int fd, const void *data, size_t size, uint64_t offset)
{
    auto p = static_cast<const char *>(data);
    while (size > 0) {
        const ssize_t n = ::pwrite(fd, p, size, off_t(offset));
        if (n < 0) {
            if (errno == EINTR)
                continue;
            return errno;
        }
        if (n == 0)
            return EIO;
        p += n;
        size -= size_t(n);
        offset += uint64_t(n);
    }
    return 0;
}

} // namespace

struct SpoolFile::Impl {
    int fd = -1;
    void *map = nullptr;
    size_t mapBytes = 0;
    bool copyRangeWorks = true; // false once copy_file_range is found unsupported
};

SpoolFile::Impl *SpoolFile::newImpl() { return new Impl; }

void SpoolFile::deleteImpl(Impl *impl) { delete impl; }

QString SpoolFile::create(const QString &path, bool exclusive)
{
    close(false);
    m_path = path;
    const int flags = O_RDWR | O_CREAT | O_CLOEXEC | (exclusive ? O_EXCL : O_TRUNC);
    m->fd = ::open(QFile::encodeName(path).constData(), flags, 0600);
    return m->fd < 0 ? why(errno) : QString();
}

bool SpoolFile::isOpen() const { return m->fd >= 0; }

QString SpoolFile::writeAt(const void *data, size_t size, uint64_t offset)
{
    const int e = pwriteAll(m->fd, data, size, offset);
    return e ? why(e) : QString();
}

QString SpoolFile::copyTo(uint64_t inOffset, SpoolFile &out, uint64_t outOffset, size_t size, std::vector<char> &buffer)
{
    while (size > 0 && m->copyRangeWorks) {
        off_t from = off_t(inOffset), to = off_t(outOffset);
        const ssize_t n = ::copy_file_range(m->fd, &from, out.m->fd, &to, size, 0);
        if (n > 0) {
            inOffset += uint64_t(n);
            outOffset += uint64_t(n);
            size -= size_t(n);
        } else if (n == 0) {
            return why(EIO); // the spool ends early
        } else if (errno == ENOSYS || errno == EXDEV || errno == EOPNOTSUPP || errno == EINVAL) {
            m->copyRangeWorks = false; // not here: read and write
        } else if (errno != EINTR) {
            return why(errno);
        }
    }
    buffer.resize(std::max<size_t>(buffer.size(), 1 << 16));
    while (size > 0) {
        const ssize_t n = ::pread(m->fd, buffer.data(), std::min(size, buffer.size()), off_t(inOffset));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return why(n < 0 ? errno : EIO);
        if (const int e = pwriteAll(out.m->fd, buffer.data(), size_t(n), outOffset))
            return why(e);
        inOffset += uint64_t(n);
        outOffset += uint64_t(n);
        size -= size_t(n);
    }
    return {};
}

QString SpoolFile::reserve(uint64_t bytes)
{
    const int e = ::posix_fallocate(m->fd, 0, off_t(bytes));
    return e == 0 || e == EOPNOTSUPP || e == EINVAL ? QString() : why(e);
}

const void *SpoolFile::map(size_t bytes, QString *error)
{
    void *map = ::mmap(nullptr, bytes, PROT_READ, MAP_SHARED, m->fd, 0);
    if (map == MAP_FAILED) {
        if (error)
            *error = why(errno);
        return nullptr;
    }
    m->map = map;
    m->mapBytes = bytes;
    ::madvise(map, bytes, MADV_SEQUENTIAL); // read once, front to back
    return map;
}

void SpoolFile::dropPages(const void *map, size_t bytes)
{
    ::madvise(const_cast<void *>(map), bytes, MADV_DONTNEED);
}

void SpoolFile::close(bool remove)
{
    if (m->map)
        ::munmap(m->map, m->mapBytes);
    m->map = nullptr;
    m->mapBytes = 0;
    if (m->fd >= 0) {
        ::close(m->fd);
        m->fd = -1;
        if (remove)
            ::unlink(QFile::encodeName(m_path).constData());
    }
}

bool SpoolFile::saysDiskFull(int errnoValue)
{
    return errnoValue == ENOSPC || errnoValue == EDQUOT || errnoValue == EFBIG || errnoValue == EIO;
}

} // namespace imudesk::format::mat
