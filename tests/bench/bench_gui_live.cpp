// The live-monitoring benchmark: the simulator on a pseudo-terminal at 921600 baud
// sends HI91 at 1000 Hz (close to the link's ~1124 frames/s) while the whole GUI runs
// offscreen with charts, attitude view and values table visible. Prints frames sent,
// decoded and lost, chart refreshes per second, GUI-thread busy time (% of one core)
// and peak resident memory, each against its target, measured in this run.
//
// usage: bench_gui_live [--seconds N] (default 60). Exit code 1 only when frames were lost.
#include "chart_panel.h"
#include "device_workspace.h"
#include "main_window.h"
#include "sim/pty_simulator.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QTimer>

#include <sys/resource.h>

#include <cstdio>
#include <ctime>
#include <optional>

using namespace imudesk;

namespace {

double threadCpuSeconds()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + double(ts.tv_nsec) / 1e9;
}

double peakRssMiB()
{
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    return double(ru.ru_maxrss) / 1024.0; // kB on Linux
}

// Runs the event loop for `ms` (blocking in the event dispatcher, not polling, so the
// GUI thread's CPU time is what the application spends).
void spin(int ms)
{
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

bool command(device::DeviceSession &s, const QString &text)
{
    std::optional<protocol::hipnuc::AsciiReply> reply;
    const quint64 id = s.sendCommand(text, 2000);
    auto c = QObject::connect(&s, &device::DeviceSession::commandFinished,
                              [&](quint64 done, const protocol::hipnuc::AsciiReply &r) {
                                  if (done == id)
                                      reply = r;
                              });
    QEventLoop loop;
    QTimer::singleShot(5000, &loop, &QEventLoop::quit);
    auto q = QObject::connect(&s, &device::DeviceSession::commandFinished, &loop, [&](quint64 done) {
        if (done == id)
            loop.quit();
    });
    if (!reply)
        loop.exec();
    QObject::disconnect(c);
    QObject::disconnect(q);
    return reply && reply->ok();
}

} // namespace

int main(int argc, char **argv)
{
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    int seconds = 60;
    for (int i = 1; i + 1 < argc; ++i)
        if (QByteArray(argv[i]) == "--seconds")
            seconds = std::max(5, QByteArray(argv[i + 1]).toInt());

    ui::MainWindow window;
    window.resize(1280, 860);
    window.show();
    sim::SimOptions options; // HI14, firmware 1.7.1
    options.baud = 921600;
    options.motion = sim::Motion::Tumble;
    QString error;
    if (!window.connectSimulated(options, 921600, &error)) {
        std::fprintf(stderr, "bench_gui_live: %s\n", qPrintable(error));
        return 1;
    }
    ui::DeviceWorkspace *ws = window.currentWorkspace();
    for (int waited = 0; ws->state() != device::SessionState::Connected && waited < 10000; waited += 50)
        spin(50);
    if (ws->state() != device::SessionState::Connected) {
        std::fprintf(stderr, "bench_gui_live: could not connect to the simulator\n");
        return 1;
    }
    device::DeviceSession &session = ws->session();
    sim::PtySimulator *simulator = ws->simulator();

    // Quiet line, then a clean baseline.
    if (!command(session, QStringLiteral("LOG HI91 ONTIME 0"))) {
        std::fprintf(stderr, "bench_gui_live: LOG HI91 ONTIME 0 was not acknowledged\n");
        return 1;
    }
    spin(300);
    uint64_t queued0 = 0, uartDrops0 = 0;
    simulator->withDevice([&](sim::HipnucSimulator &d) {
        queued0 = d.framesQueued();
        uartDrops0 = d.droppedFrames();
    });
    const uint64_t decoded0 = session.store().totalAppended();
    const uint64_t ptyDrops0 = simulator->stats().chunksDropped;
    const int refresh0 = ws->chartPanel()->refreshCount();

    if (!command(session, QStringLiteral("LOG HI91 ONTIME 0.001"))) {
        std::fprintf(stderr, "bench_gui_live: LOG HI91 ONTIME 0.001 was not acknowledged\n");
        return 1;
    }
    const double cpu0 = threadCpuSeconds();
    QElapsedTimer wall;
    wall.start();
    spin(seconds * 1000);
    const double wallS = double(wall.nsecsElapsed()) / 1e9;
    const double cpuS = threadCpuSeconds() - cpu0;
    const int refreshes = ws->chartPanel()->refreshCount() - refresh0;

    command(session, QStringLiteral("LOG HI91 ONTIME 0"));
    spin(500); // let the last frames arrive
    uint64_t queued1 = 0, uartDrops1 = 0;
    simulator->withDevice([&](sim::HipnucSimulator &d) {
        queued1 = d.framesQueued();
        uartDrops1 = d.droppedFrames();
    });
    const uint64_t sent = queued1 - queued0;
    const uint64_t decoded = session.store().totalAppended() - decoded0;
    const uint64_t lost = sent > decoded ? sent - decoded : 0;
    const uint64_t uartDrops = uartDrops1 - uartDrops0;
    const uint64_t ptyDrops = simulator->stats().chunksDropped - ptyDrops0;
    const double refreshRate = refreshes / wallS;
    const double busy = 100.0 * cpuS / wallS;
    const double rss = peakRssMiB();

    const bool okLost = lost == 0 && uartDrops == 0 && ptyDrops == 0;
    const bool okRefresh = refreshRate >= 30.0;
    const bool okBusy = busy < 30.0;
    std::printf("bench_gui_live: HI91 at 1000 Hz, 921600 baud, %d s, GUI offscreen (charts, attitude, table)\n",
                seconds);
    std::printf("  %-34s %12llu\n", "frames sent by the module", (unsigned long long)sent);
    std::printf("  %-34s %12llu\n", "frames decoded", (unsigned long long)decoded);
    std::printf("  %-34s %12llu   target 0  %s\n", "frames lost", (unsigned long long)lost, okLost ? "ok" : "MISSED");
    std::printf("  %-34s %12llu / %llu\n", "  dropped by UART model / by pty", (unsigned long long)uartDrops,
                (unsigned long long)ptyDrops);
    std::printf("  %-34s %12.1f   target >= 30  %s\n", "chart refreshes per second", refreshRate,
                okRefresh ? "ok" : "MISSED");
    std::printf("  %-34s %11.1f%%   target < 30 %%  %s\n", "GUI thread busy (one core)", busy,
                okBusy ? "ok" : "MISSED");
    std::printf("  %-34s %10.1f MiB\n", "peak resident memory", rss);
    std::printf("  %-34s %12.1f Hz\n", "decoded rate", decoded / wallS);
    std::printf("targets: %s\n", okLost && okRefresh && okBusy ? "all met" : "NOT all met (see MISSED above)");
    window.close();
    // A lost frame is a correctness failure; the speed targets are reported, not enforced
    // (a benchmark, not a timed test).
    return okLost ? 0 : 1;
}
