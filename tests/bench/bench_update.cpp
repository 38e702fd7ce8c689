// bench_update: serial firmware update throughput over a pseudo-terminal.
//
// For each baud rate (115200 and 921600) a simulated module (PtySimulator, its own thread,
// real time, UART timing of 10 bits per byte in both directions) is updated with a
// 256 KiB image through the real serial path (SerialByteLink/QSerialPort + UpdateFlow):
// REBOOT BL, ping, properties, erase, write, read-back verify, reset, LOG VERSION.
// Printed per baud: the data phase's throughput as a fraction of the link's raw capacity
// (baud/10 bytes per second); with --full also the read-back's and the whole update's.
// Without --full the flow is stopped when verification begins (the written flash is compared
// in-process instead of reading it back over the line), which keeps the run near 30 s.
//
//   bench_update [--quick] [--full] [--kib N] [--baud B]
//
// --quick uses 64 KiB. Exit status: 0 when every update succeeded and the write phase at
// 115200 reached 85 % of baud/10; 1 otherwise; 2 on bad arguments.
#include "core/firmware/serial_byte_link.h"
#include "core/firmware/update_flow.h"
#include "sim/kboot_bootloader.h"
#include "sim/pty_simulator.h"

#include <QCoreApplication>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

using namespace imudesk;

namespace {

constexpr double kTarget = 0.85;

struct Figures {
    bool ok = false;
    double write = 0, verify = 0, whole = 0; // fractions of baud/10
    double writeSeconds = 0, totalSeconds = 0;
    QString message;
};

Figures runOnce(int baud, size_t bytes, bool full)
{
    Figures f;
    sim::SimOptions o;
    o.baud = baud;
    sim::PtySimulator simulator(o);
    QString error;
    if (!simulator.start(&error)) {
        f.message = error;
        return f;
    }
    protocol::ihex::FirmwareImage img;
    img.startAddress = 0x8000;
    img.data = sim::KbootBootloader::makeApplication("1.7.2", bytes, uint64_t(baud));
    firmware::SerialByteLink link(simulator.devicePath());
    firmware::UpdateFlow::Options opt;
    opt.baud = baud;
    int64_t verifyStart = 0, verifyEnd = 0;
    firmware::UpdateFlow *flowPtr = nullptr;
    firmware::UpdateFlow::Observer obs;
    obs.stateChanged = [&](firmware::UpdateFlow::State s) {
        if (s == firmware::UpdateFlow::State::Verifying)
            verifyStart = link.nowUs();
        if (s == firmware::UpdateFlow::State::Verifying && !full)
            flowPtr->cancel();
        if (s == firmware::UpdateFlow::State::Resetting)
            verifyEnd = link.nowUs();
    };
    firmware::UpdateFlow flow(link, opt, obs);
    flowPtr = &flow;
    const auto r = flow.run(img);
    link.close();
    bool same = false;
    simulator.withDevice([&](sim::HipnucSimulator &d) {
        const auto &fl = d.bootloader().flash();
        same = std::equal(img.data.begin(), img.data.end(), fl.begin() + img.startAddress);
    });
    simulator.stop();
    const double capacity = baud / 10.0;
    const bool stoppedAtVerify = !full && r.finalState == firmware::UpdateFlow::State::Cancelled
        && r.failedIn == firmware::UpdateFlow::State::Verifying;
    f.ok = (r.ok || stoppedAtVerify) && same;
    f.message = r.message;
    f.writeSeconds = r.writeSeconds;
    f.totalSeconds = r.totalSeconds;
    if (r.writeSeconds > 0)
        f.write = double(bytes) / r.writeSeconds / capacity;
    if (verifyEnd > verifyStart)
        f.verify = double(bytes) / (double(verifyEnd - verifyStart) / 1e6) / capacity;
    if (r.ok && r.totalSeconds > 0)
        f.whole = double(bytes) / r.totalSeconds / capacity;
    return f;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    size_t kib = 256;
    bool full = false;
    std::vector<int> bauds{115200, 921600};
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--quick")) {
            kib = 64;
        } else if (!std::strcmp(argv[i], "--full")) {
            full = true;
        } else if (!std::strcmp(argv[i], "--kib") && i + 1 < argc) {
            kib = size_t(std::strtoul(argv[++i], nullptr, 10));
        } else if (!std::strcmp(argv[i], "--baud") && i + 1 < argc) {
            bauds = {int(std::strtol(argv[++i], nullptr, 10))};
        } else {
            std::fprintf(stderr, "usage: bench_update [--quick] [--full] [--kib N] [--baud B]\n");
            return 2;
        }
    }
    if (kib == 0 || kib > 480 || bauds.front() <= 0) {
        std::fprintf(stderr, "bench_update: --kib must be 1..480 (the simulated application area), --baud positive\n");
        return 2;
    }
    std::printf("serial firmware update over a pty, %zu KiB image (REBOOT BL, erase, write%s)\n", kib,
                full ? ", read-back, reset, LOG VERSION" : "; flash compared in-process");
    std::printf("%8s %10s %10s %12s %10s %10s  %s\n", "baud", "write s", "write", "read-back", "whole", "total s",
                "result");
    bool pass = true;
    for (int baud : bauds) {
        const Figures f = runOnce(baud, kib * 1024, full);
        const QString result = f.ok ? QStringLiteral("flash == image") : QStringLiteral("FAILED: ") + f.message;
        if (full)
            std::printf("%8d %10.2f %9.1f%% %11.1f%% %9.1f%% %10.2f  %s\n", baud, f.writeSeconds, 100 * f.write,
                        100 * f.verify, 100 * f.whole, f.totalSeconds, qPrintable(result));
        else
            std::printf("%8d %10.2f %9.1f%% %12s %10s %10s  %s\n", baud, f.writeSeconds, 100 * f.write, "-", "-", "-",
                        qPrintable(result));
        std::fflush(stdout);
        pass = pass && f.ok;
        if (baud == 115200 && f.write < kTarget)
            pass = false;
    }
    std::printf("fractions of the raw capacity baud/10 B/s; target: write >= %.0f %% at 115200 -> %s\n", 100 * kTarget,
                pass ? "met" : "NOT met");
    return pass ? 0 : 1;
}
