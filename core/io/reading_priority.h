#pragma once
// Asks the scheduler to wake the calling thread promptly, for reading a device, and says what
// it got. Called by a session's worker thread (and by the pty simulator's thread, which stands
// in for a device that has a CPU of its own).
//
// Why: a serial port's bytes wait in the kernel until the reading thread runs (a real port
// holds 640 KiB, about 7 s at 921600 baud; a pseudo-terminal about 16 KiB, 0.2 s); on a busy
// host a thread that wakes late delays every sample on its way to the views, and past the
// buffer the kernel drops bytes before ImuDesk sees them.
//
// What Linux offers, and what was measured (issue 33):
//   * A short time slice (sched_setattr with SCHED_OTHER and sched_runtime, Linux >= 6.12's
//     EEVDF scheduler) needs no privilege: a waking thread that asks for a short slice gets an
//     earlier deadline and preempts a busy thread sooner. Older kernels accept the call and
//     ignore the slice. This is what is asked for: bench_gui_live --seconds 60 --load 2 keeps
//     every frame (0 lost before and inside ImuDesk) with it.
//   * A lower nice value (setpriority on the thread id, kReadingNice = -10 before) is not asked
//     for any more. An ordinary desktop user is refused it anyway (it needs CAP_SYS_NICE or an
//     RLIMIT_NICE), and where it was granted (root, as in CI) it backfired: bytes reach a
//     reader through the kernel's tty worker (a nice-0 kworker running flush_to_ldisc, which
//     poll() on the tty waits for), and with nice -10 threads coming and going beside two busy
//     loops that worker sat runnable but unscheduled for up to 25.9 s (Linux 6.18, perf
//     sched_switch), so the raised reader waited longer, not shorter. Slice alone: at most 3.3 s
//     in the same runs, usually well under 0.5 s; neither: under 50 ms.
//   * QThread::setPriority does nothing useful: Qt 6.4 maps its priorities onto
//     sched_get_priority_min..max of the thread's policy, which for SCHED_OTHER is 0..0; only
//     IdlePriority (SCHED_IDLE) has an effect, and it lowers.
//   * SCHED_FIFO / SCHED_RR are not used: they need CAP_SYS_NICE or RLIMIT_RTPRIO, and a
//     real-time thread that decodes, records and fills the store could starve the desktop (and
//     the same tty worker).
#include <QString>

namespace imudesk::io {

struct ReadingPriority {
    static constexpr unsigned kSliceUs = 100; // the shortest slice EEVDF accepts (0.1 ms)

    bool shortSlice = false; // sched_setattr took the slice hint (on kernels < 6.12 it is ignored)
    int sliceErrno = 0;      // why it did not (0: it did, or the thread is not SCHED_OTHER)

    bool raised() const { return shortSlice; }
    // One line for the log: what was asked and what was granted.
    QString describe() const;
};

// Asks for the short slice (Linux; elsewhere a no-op that reports nothing raised). Safe to
// call again. The thread's nice value is left as it is (see above).
ReadingPriority raiseCurrentThreadForReading();

} // namespace imudesk::io
