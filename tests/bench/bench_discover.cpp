// bench_discover: one sweep of a bench (core/discovery, issue 56) against the same checks run
// one after the other, as today's dialogs run them.
//
// The bench (discovery::SimulatedBench): four pseudo-terminal ports (a HiPNUC module at 460800
// baud, an HEC495 at 4800 baud with address 7, a HiPNUC Modbus module at 38400 baud with id
// 17, a silent port) and one virtualcan bus (a J1939 module at address 12 and two CANopen
// modules sharing node 5).
//   * sweep: BenchSweep over all of it at once, timed until every device is found with its
//     rate and address and the conflict on node 5 is reported (target: at most 60 s);
//   * baseline: the same checks one after the other, as a user runs the dialogs today: Connect
//     with Auto on each port in turn, the CAN bus, then the Modbus scan on each port where
//     nothing answered; timed to the same point (the same probes, in the same order per port).
// Printed: both times, their ratio, and what each found.
//
//   bench_discover [--budget S]
// Exit status 1 when a target is missed (a device or the conflict not found, or over 60 s).
#include "core/discovery/bench_sweep.h"
#include "core/discovery/simulated_bench.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QLoggingCategory>
#include <QTimer>

#include <cstdio>
#include <cstring>
#include <algorithm>
#include <functional>
#include <vector>

using namespace imudesk;
using discovery::BenchSweep;
using discovery::FoundDevice;
using discovery::SweepOptions;

namespace {

struct Expect {
    QString port;
    FoundDevice::Link link;
    int rate;     // baud; CAN: bit/s
    int address;  // address, Modbus id, CAN node
    bool found = false;
    double at = -1; // seconds into the run
};

struct Run {
    double seconds = -1; // until everything expected was found; -1: not all
    int devices = 0;
    bool conflict = false;
};

// Runs sweeps of `steps` one after the other (one step: one sweep), until every expectation
// and the conflict are met or every step ended. Returns when that happens.
Run runSteps(const std::vector<SweepOptions> &steps, std::vector<Expect> expect)
{
    Run run;
    QElapsedTimer clock;
    clock.start();
    double conflictAt = -1;
    const auto complete = [&] {
        return run.conflict && std::all_of(expect.begin(), expect.end(), [](const Expect &e) { return e.found; });
    };
    for (const SweepOptions &o : steps) {
        BenchSweep sweep;
        QEventLoop loop;
        QObject::connect(&sweep, &BenchSweep::deviceFound, [&](const FoundDevice &d) {
            ++run.devices;
            for (Expect &e : expect) {
                const int rate = d.link == FoundDevice::Link::Can ? d.bitrate : d.baud;
                const int address = d.link == FoundDevice::Link::Can ? d.node : d.address;
                if (d.port == e.port && d.link == e.link && rate == e.rate && address == e.address && !e.found) {
                    e.found = true;
                    e.at = clock.elapsed() / 1000.0;
                }
            }
            if (complete())
                loop.quit();
        });
        QObject::connect(&sweep, &BenchSweep::conflictFound, [&](const discovery::Conflict &c) {
            if (c.address == 5 && !run.conflict) {
                run.conflict = true;
                conflictAt = clock.elapsed() / 1000.0;
            }
            if (complete())
                loop.quit();
        });
        QObject::connect(&sweep, &BenchSweep::finished, &loop, &QEventLoop::quit);
        sweep.start(o);
        if (sweep.running())
            loop.exec();
        sweep.cancel();
        if (complete()) {
            run.seconds = clock.elapsed() / 1000.0;
            break;
        }
    }
    for (const Expect &e : expect) {
        const char *link = e.link == FoundDevice::Link::Serial ? "serial" : e.link == FoundDevice::Link::Modbus ? "modbus" : "can";
        if (e.found)
            std::printf("   %5.1f s  %-6s %s  rate %d  address %d\n", e.at, link, qPrintable(e.port), e.rate, e.address);
        else
            std::printf("   not found: %s %s (%d, %d)\n", link, qPrintable(e.port), e.rate, e.address);
    }
    if (!run.conflict)
        std::printf("   the conflict on node 5 was not reported\n");
    else
        std::printf("   %5.1f s  conflict on CAN node 5 reported\n", conflictAt);
    return run;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    // The simulated Modbus server hears every probe at a wrong rate as a broken frame.
    QLoggingCategory::setFilterRules(QStringLiteral("qt.modbus*=false\nqt.canbus*=false"));
    int budgetS = 60;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--budget") && i + 1 < argc)
            budgetS = std::atoi(argv[++i]);
        else {
            std::fprintf(stderr, "usage: bench_discover [--budget S]\n");
            return 2;
        }
    }
    discovery::SimulatedBench bench(QStringLiteral("tcp://127.0.0.1:24502/can0"));
    QString error;
    if (!bench.start(&error)) {
        std::fprintf(stderr, "bench_discover: %s\n", qPrintable(error));
        return 1;
    }
    const QString bus = bench.canBuses().value(0);
    const std::vector<Expect> expect = {
        {bench.hipnucPort(), FoundDevice::Link::Serial, 460800, -1},
        {bench.hec495Port(), FoundDevice::Link::Serial, 4800, 7},
        {bench.modbusPort(), FoundDevice::Link::Modbus, 38400, 17},
        {bus, FoundDevice::Link::Can, 500000, 12},
        {bus, FoundDevice::Link::Can, 500000, 5},
    };
    SweepOptions all;
    all.machinePorts = all.machineCan = false;
    all.ports = bench.ports();
    all.canBuses = bench.canBuses();
    all.budgetMs = budgetS * 1000;

    std::printf("bench_discover: 4 ports (HiPNUC 460800, HEC495 4800/7, Modbus 38400/17, silent) and %s\n",
                qPrintable(bus));
    const Run sweep = runSteps({all}, expect);
    std::printf("  sweep:    %6.1f s  (%d devices reported)\n", sweep.seconds, sweep.devices);

    // Today's dialogs one after the other: Auto on each port, the CAN bus, then the Modbus scan on
    // the ports where nothing answered (timed until everything is found: the silent port's scan,
    // last, is not waited for).
    std::vector<SweepOptions> steps;
    for (const QString &port : bench.ports()) {
        SweepOptions o = all;
        o.ports = {port};
        o.canBuses = {};
        o.modbus = false;
        steps.push_back(o);
    }
    SweepOptions can = all;
    can.ports = {};
    steps.push_back(can);
    for (const QString &port : {bench.modbusPort(), bench.silentPort()}) {
        SweepOptions o = all;
        o.ports = {port};
        o.canBuses = {};
        o.serialFamilies = false;
        steps.push_back(o);
    }
    const Run baseline = runSteps(steps, expect);
    std::printf("  baseline: %6.1f s  (the same checks one after the other)\n", baseline.seconds);
    bool ok = sweep.seconds >= 0 && sweep.seconds <= 60.0;
    if (sweep.seconds >= 0 && baseline.seconds > 0)
        std::printf("  sweep / baseline: %.2f\n", sweep.seconds / baseline.seconds);
    std::printf("  target: every device and the conflict within 60 s: %s\n", ok ? "met" : "MISSED");
    bench.stop();
    return ok ? 0 : 1;
}
