#include "reading_priority.h"

#include <cerrno>
#include <cstring>

#ifdef Q_OS_LINUX
#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cstdint>
#endif

namespace imudesk::io {

#ifdef Q_OS_LINUX
namespace {

// struct sched_attr, first version (48 bytes); glibc before 2.41 has no wrapper for
// sched_setattr, and <linux/sched/types.h> clashes with newer glibc headers.
struct SchedAttr {
    uint32_t size = sizeof(SchedAttr);
    uint32_t policy = 0;
    uint64_t flags = 0;
    int32_t nice = 0;
    uint32_t priority = 0;
    uint64_t runtime = 0; // SCHED_OTHER on Linux >= 6.12: the slice asked for (ns)
    uint64_t deadline = 0;
    uint64_t period = 0;
};
static_assert(sizeof(SchedAttr) == 48);

} // namespace
#endif

QString ReadingPriority::describe() const
{
    return shortSlice ? QStringLiteral("reading thread: slice %1 us asked for").arg(kSliceUs)
                      : QStringLiteral("reading thread: slice hint refused (%1)")
                            .arg(sliceErrno ? QString::fromLocal8Bit(std::strerror(sliceErrno))
                                            : QStringLiteral("not SCHED_OTHER"));
}

ReadingPriority raiseCurrentThreadForReading()
{
    ReadingPriority r;
#ifdef Q_OS_LINUX
    const auto tid = pid_t(::syscall(SYS_gettid));
    if (::sched_getscheduler(tid) != SCHED_OTHER)
        return r;
    // sched_setattr sets the nice value too: pass the one in force, so that it stays.
    errno = 0;
    const int nice = ::getpriority(PRIO_PROCESS, id_t(tid));
    if (nice == -1 && errno != 0) {
        r.sliceErrno = errno;
        return r;
    }
    SchedAttr attr;
    attr.policy = SCHED_OTHER;
    attr.nice = nice;
    attr.runtime = uint64_t(ReadingPriority::kSliceUs) * 1000u;
    if (::syscall(SYS_sched_setattr, tid, &attr, 0u) == 0)
        r.shortSlice = true;
    else
        r.sliceErrno = errno;
#endif
    return r;
}

} // namespace imudesk::io
