#include "reading_priority.h"

#include <algorithm>
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
    QString text = QStringLiteral("reading thread: nice %1 -> %2").arg(niceBefore).arg(niceAfter);
    if (niceErrno != 0)
        text += QStringLiteral(" (nice %1 not allowed: %2; CAP_SYS_NICE or an RLIMIT_NICE of %3 allows it)")
                    .arg(kReadingNice)
                    .arg(QString::fromLocal8Bit(std::strerror(niceErrno)))
                    .arg(20 - kReadingNice);
    text += shortSlice ? QStringLiteral(", slice %1 us asked for").arg(kSliceUs)
                       : QStringLiteral(", slice hint refused (%1)").arg(QString::fromLocal8Bit(std::strerror(sliceErrno)));
    return text;
}

ReadingPriority raiseCurrentThreadForReading()
{
    ReadingPriority r;
#ifdef Q_OS_LINUX
    const auto tid = id_t(::syscall(SYS_gettid));
    errno = 0;
    const int before = ::getpriority(PRIO_PROCESS, tid);
    if (before == -1 && errno != 0)
        return r;
    r.niceBefore = r.niceAfter = before;
    if (before > ReadingPriority::kReadingNice) {
        if (::setpriority(PRIO_PROCESS, tid, ReadingPriority::kReadingNice) == 0) {
            r.niceAfter = ReadingPriority::kReadingNice;
        } else {
            r.niceErrno = errno;
            // What RLIMIT_NICE grants, if anything (the lowest nice allowed is 20 - limit).
            rlimit lim{};
            if (::getrlimit(RLIMIT_NICE, &lim) == 0 && lim.rlim_cur != RLIM_INFINITY) {
                const int floor = 20 - int(std::min<rlim_t>(lim.rlim_cur, 40));
                if (floor < before && ::setpriority(PRIO_PROCESS, tid, floor) == 0)
                    r.niceAfter = floor;
            }
        }
    }
    // The slice hint, at the nice value now in force (sched_setattr sets both).
    if (::sched_getscheduler(pid_t(tid)) == SCHED_OTHER) {
        SchedAttr attr;
        attr.policy = SCHED_OTHER;
        attr.nice = r.niceAfter;
        attr.runtime = uint64_t(ReadingPriority::kSliceUs) * 1000u;
        if (::syscall(SYS_sched_setattr, pid_t(tid), &attr, 0u) == 0)
            r.shortSlice = true;
        else
            r.sliceErrno = errno;
    }
#endif
    return r;
}

} // namespace imudesk::io
