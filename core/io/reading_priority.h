#pragma once
// Raises the calling thread's scheduling priority for reading a device, as far as the OS lets
// this process, and says what it got. Called by a session's worker thread (and by the pty
// simulator's thread, which stands in for a device that has a CPU of its own).
//
// Why: a serial port's bytes wait in the kernel until the reading thread runs (a real port
// holds 640 KiB, about 7 s at 921600 baud; a pseudo-terminal about 16 KiB, 0.2 s); on a busy
// host a thread at the default priority may wait longer than that, and the kernel drops bytes
// before ImuDesk sees them. Waking late also delays every sample on its way to the views.
//
// What Linux allows (tried for issue 33; bench_gui_live --load N shows what the threads got):
//   * QThread::setPriority does nothing useful here: Qt 6.4 maps its priorities onto
//     sched_get_priority_min..max of the thread's policy, which for SCHED_OTHER is 0..0; only
//     IdlePriority (SCHED_IDLE) has an effect, and it lowers.
//   * A lower nice value for this thread alone (setpriority on the thread id) needs
//     CAP_SYS_NICE or an RLIMIT_NICE that allows it (limits.conf "nice", or systemd's
//     LimitNICE=); an ordinary desktop user has neither, and gets the EACCES this reports.
//     With it, the thread gets kReadingNice (a weight about 9x that of a nice-0 thread).
//   * A short time slice (sched_setattr with SCHED_OTHER and sched_runtime, Linux >= 6.12's
//     EEVDF scheduler) needs no privilege: a waking thread that asks for a short slice gets an
//     earlier deadline and preempts a busy thread sooner. Older kernels accept the call and
//     ignore the slice.
//   * SCHED_FIFO / SCHED_RR are not used: they need CAP_SYS_NICE or RLIMIT_RTPRIO too, and a
//     real-time thread that decodes, records and fills the store could starve the desktop.
// Nice and slice act inside the thread's scheduling group. With autogroup (on by default in
// Debian's and most desktop kernels) each session's processes form one group that gets its
// share against the other groups whatever their nice values, so the raise lifts the reader over
// ImuDesk's own threads and over load in the same session (bench_gui_live --load runs its busy
// threads in the process itself), while load from other sessions is already held to its share
// by the group. Lowering ImuDesk's own other threads would not help against other programs.
#include <QString>

namespace imudesk::io {

struct ReadingPriority {
    static constexpr int kReadingNice = -10;
    static constexpr unsigned kSliceUs = 100; // the shortest slice EEVDF accepts (0.1 ms)

    int niceBefore = 0;
    int niceAfter = 0;
    int niceErrno = 0;       // why the nice value could not be lowered (0: it was, or it was low already)
    bool shortSlice = false; // sched_setattr took the slice hint (on kernels < 6.12 it is ignored)
    int sliceErrno = 0;

    bool raised() const { return niceAfter < niceBefore || shortSlice; }
    // One line for the log: what was asked, what was granted, and how to allow more.
    QString describe() const;
};

// Raises the calling thread (Linux; elsewhere a no-op that reports nothing raised). Safe to
// call again: a thread already raised is left as it is.
ReadingPriority raiseCurrentThreadForReading();

} // namespace imudesk::io
