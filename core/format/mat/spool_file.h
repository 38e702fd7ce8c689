#pragma once
// The MAT writer's scratch files (mat_file.h): a struct's rows spooled block by block, then
// gathered column by column into a data file that matio reads through a read-only mapping.
// Its lifetime and moves are in spool_file.cpp; the rest is one platform file each:
// spool_file_posix.cpp (pwrite and pread, copy_file_range inside the kernel where the file
// system has it, posix_fallocate, mmap) and spool_file_windows.cpp (QFile's positioned reads
// and writes, resize and map, which use Win32 there).
// Every call that fails returns why, as a sentence; an empty string is success.
#include <QString>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace imudesk::format::mat {

class SpoolFile {
public:
    SpoolFile();
    ~SpoolFile(); // unmaps and closes; the file stays unless close(true) said otherwise
    SpoolFile(const SpoolFile &) = delete;
    SpoolFile &operator=(const SpoolFile &) = delete;
    SpoolFile(SpoolFile &&other) noexcept;
    SpoolFile &operator=(SpoolFile &&other) noexcept;

    // Creates path for reading and writing by this user alone; exclusive: fails when it exists
    // (else it is emptied).
    QString create(const QString &path, bool exclusive);
    bool isOpen() const;
    const QString &path() const { return m_path; }
    // All of size bytes at offset.
    QString writeAt(const void *data, size_t size, uint64_t offset);
    // size bytes of this file from inOffset into out at outOffset (inside the kernel where the
    // system can; else through buffer, which it grows as it needs).
    QString copyTo(uint64_t inOffset, SpoolFile &out, uint64_t outOffset, size_t size, std::vector<char> &buffer);
    // Room for bytes on the disk now, or why not (a file system that cannot say is no failure).
    QString reserve(uint64_t bytes);
    // The first bytes of the file, read-only, read front to back once; null with why in *error.
    const void *map(size_t bytes, QString *error);
    // Lets the system drop the mapped pages read so far (they are read once).
    static void dropPages(const void *map, size_t bytes);
    // Unmaps, closes and, when remove, deletes the file.
    void close(bool remove);

    // Whether a C runtime error number (errno after a failed write by matio's stdio) says the
    // disk is full or failing, so that its text is worth showing.
    static bool saysDiskFull(int errnoValue);

private:
    struct Impl; // the platform's state, defined with its platform file
    static Impl *newImpl();
    static void deleteImpl(Impl *impl);
    Impl *m = nullptr;
    QString m_path;
};

} // namespace imudesk::format::mat
