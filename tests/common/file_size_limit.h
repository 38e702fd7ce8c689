#pragma once
// A "disk" of a given size for this process while the object lives: RLIMIT_FSIZE makes a
// write() past it fail with EFBIG (SIGXFSZ ignored meanwhile), as a full disk fails a write.
// The limit and the signal's handler are put back when it goes.
#include <csignal>

#include <sys/resource.h>

namespace imudesk::test {

class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes)
    {
        m_set = getrlimit(RLIMIT_FSIZE, &m_before) == 0;
        m_oldHandler = std::signal(SIGXFSZ, SIG_IGN);
        rlimit limited = m_before;
        limited.rlim_cur = bytes;
        m_set = m_set && setrlimit(RLIMIT_FSIZE, &limited) == 0;
    }
    ~FileSizeLimit() { lift(); }
    FileSizeLimit(const FileSizeLimit &) = delete;
    FileSizeLimit &operator=(const FileSizeLimit &) = delete;

    // False when the limit could not be set (the test cannot check what it meant to).
    bool ok() const { return m_set; }
    // Back to the limit before (before the object goes, to check what follows without it).
    void lift()
    {
        if (m_lifted)
            return;
        m_lifted = true;
        setrlimit(RLIMIT_FSIZE, &m_before);
        std::signal(SIGXFSZ, m_oldHandler);
    }

private:
    rlimit m_before{};
    void (*m_oldHandler)(int) = SIG_DFL;
    bool m_set = false;
    bool m_lifted = false;
};

} // namespace imudesk::test
