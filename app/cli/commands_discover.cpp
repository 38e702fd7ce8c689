// imudesk-cli discover: one sweep of the bench (issue 56, core/discovery/bench_sweep.h). Every
// serial port of the machine and those listed, every socketcan interface and the buses listed,
// at once; what answered, at which rate and address, and the conflicts with their evidence.
// Exit 0: something found and no conflict; 1: a conflict; 2: nothing found.
#include "cli_context.h"
#include "discovery/bench_sweep.h"
#include "io/can_transport.h"

#include <QJsonDocument>

#include <cstdio>

namespace imudesk::cli {

int cmdDiscover(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(QCommandLineOption(QStringLiteral("ports"),
                                   QStringLiteral("Serial ports to sweep besides the machine's (e.g. pseudo-terminals), comma-separated."),
                                   QStringLiteral("P1,P2")));
    p.addOption(QCommandLineOption(QStringLiteral("can"), QStringLiteral("CAN buses to sweep, PLUGIN:INTERFACE, comma-separated."),
                                   QStringLiteral("PLUGIN:IF,...")));
    p.addOption(QCommandLineOption(QStringLiteral("only-listed"),
                                   QStringLiteral("Sweep only the ports and buses given, not every one of the machine.")));
    p.addOption(QCommandLineOption(QStringLiteral("no-modbus"), QStringLiteral("Do not ask silent ports as Modbus RTU lines.")));
    p.addOption(QCommandLineOption(QStringLiteral("timeout"), QStringLiteral("The whole sweep at most, seconds (default 60)."),
                                   QStringLiteral("S"), QStringLiteral("60")));
    p.addOption(QCommandLineOption(QStringLiteral("json"), QStringLiteral("One JSON object: devices, conflicts, ports.")));
    if (!parseArgs(p, args,
                   QStringLiteral("imudesk-cli discover [--ports P1,P2,...] [--can PLUGIN:IF,...] [--only-listed] "
                                  "[--no-modbus] [--timeout S] [--json]")))
        return ExitUsage;
    if (!p.positionalArguments().isEmpty())
        return fail(QStringLiteral("discover takes no positional arguments: list ports with --ports"), ExitUsage);
    bool ok = false;
    const double seconds = p.value(QStringLiteral("timeout")).toDouble(&ok);
    if (!ok || seconds < 1 || seconds > 3600)
        return fail(QStringLiteral("--timeout needs a number of seconds from 1 to 3600"), ExitUsage);
    discovery::SweepOptions o;
    if (p.isSet(QStringLiteral("ports")))
        o.ports = p.value(QStringLiteral("ports")).split(QLatin1Char(','), Qt::SkipEmptyParts);
    if (p.isSet(QStringLiteral("can"))) {
        o.canBuses = p.value(QStringLiteral("can")).split(QLatin1Char(','), Qt::SkipEmptyParts);
        for (const QString &bus : o.canBuses)
            if (!io::CanAddress::parse(bus).complete())
                return fail(QStringLiteral("--can wants PLUGIN:INTERFACE (e.g. socketcan:can0), not '%1'").arg(bus),
                            ExitUsage);
    }
    o.machinePorts = o.machineCan = !p.isSet(QStringLiteral("only-listed"));
    o.modbus = !p.isSet(QStringLiteral("no-modbus"));
    o.budgetMs = int(seconds * 1000);
    const bool json = p.isSet(QStringLiteral("json"));

    discovery::BenchSweep sweep;
    const QStringList ports = discovery::BenchSweep::serialPortsOf(o);
    const QStringList buses = discovery::BenchSweep::canBusesOf(o);
    std::fprintf(stderr, "sweeping %lld serial port(s) and %lld CAN bus(es), at most %.0f s\n",
                 static_cast<long long>(ports.size()), static_cast<long long>(buses.size()), seconds);
    QObject::connect(&sweep, &discovery::BenchSweep::deviceFound, [](const discovery::FoundDevice &d) {
        std::fprintf(stderr, "  found %s on %s\n", qPrintable(d.family), qPrintable(d.port));
    });
    QObject::connect(&sweep, &discovery::BenchSweep::progress,
                     [last = -1](int done, int total, const QString &port, const QString &detail) mutable {
                         const int percent = total > 0 ? 100 * done / total : 0;
                         if (percent / 10 != last / 10 && !port.isEmpty()) {
                             std::fprintf(stderr, "  %3d %%  %s: %s\n", percent, qPrintable(port), qPrintable(detail));
                             last = percent;
                         }
                     });
    sweep.start(o);
    waitFor([&] { return !sweep.running(); }, o.budgetMs + 10000);
    if (sweep.running())
        sweep.cancel();
    const discovery::SweepResult &r = sweep.result();
    if (json)
        out(QString::fromUtf8(QJsonDocument(r.toJson()).toJson(QJsonDocument::Compact)));
    else {
        for (const QString &line : r.textLines())
            out(line);
        out(QStringLiteral("%1 device(s), %2 conflict(s) in %3 s")
                .arg(r.devices.size())
                .arg(r.conflicts.size())
                .arg(r.seconds, 0, 'f', 1));
    }
    if (interrupted())
        return ExitInterrupted;
    return r.exitCode();
}

} // namespace imudesk::cli
