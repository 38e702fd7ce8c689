// What SpoolFile does the same on every system: its lifetime and moves. The rest, and the
// platform's state (Impl), are in spool_file_posix.cpp and spool_file_windows.cpp.
#include "format/mat/spool_file.h"

#include <utility>

namespace imudesk::format::mat {

SpoolFile::SpoolFile() : m(newImpl()) {}

SpoolFile::~SpoolFile()
{
    close(false);
    deleteImpl(m);
}

SpoolFile::SpoolFile(SpoolFile &&other) noexcept : m(std::exchange(other.m, newImpl())), m_path(std::move(other.m_path)) {}

SpoolFile &SpoolFile::operator=(SpoolFile &&other) noexcept
{
    if (this != &other) {
        close(false);
        std::swap(m, other.m);
        m_path = std::move(other.m_path);
    }
    return *this;
}

} // namespace imudesk::format::mat
