// imudesk-cli bridge: connected devices' samples, live, to Foxglove, Lichtblick and PlotJuggler
// (bridge/live_bridge.h).
#include "bridge/live_bridge.h"
#include "cli_context.h"
#include "device_links.h"

#include <QCommandLineParser>
#include <QElapsedTimer>

#include <cstdio>
#include <memory>
#include <vector>

namespace imudesk::cli {

int cmdBridge(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(QCommandLineOption(QStringLiteral("listen"),
                                   QStringLiteral("Foxglove WebSocket server address and port (default 127.0.0.1:8765; "
                                                  "another address than loopback lets anyone on the network read the data: "
                                                  "the protocol has no authentication)."),
                                   QStringLiteral("ADDR:PORT")));
    p.addOption(QCommandLineOption(QStringLiteral("udp"),
                                   QStringLiteral("Also send every sample to PlotJuggler's UDP server (JSON), e.g. 127.0.0.1:9870."),
                                   QStringLiteral("HOST:PORT")));
    p.addOption(QCommandLineOption(QStringLiteral("no-websocket"), QStringLiteral("UDP only: no WebSocket server.")));
    p.addOption(QCommandLineOption(QStringLiteral("duration"), QStringLiteral("Seconds to run (default: until Ctrl+C)."),
                                   QStringLiteral("S")));
    p.addOption(QCommandLineOption(QStringLiteral("baud"), QStringLiteral("Baud rate of the serial ports (default: auto-detect)."),
                                   QStringLiteral("B")));
    p.addOption(QCommandLineOption(QStringLiteral("client-buffer-mb"),
                                   QStringLiteral("Unsent data a client may have before its messages are dropped (default 8)."),
                                   QStringLiteral("MB")));
    p.addPositionalArgument(QStringLiteral("PORT[,PORT...]"),
                            QStringLiteral("Devices: serial ports (PORT or PORT:BAUD), modbus:PORT[@ID], modbus-hec495:PORT[@ID] "
                                           "or can:PLUGIN:INTERFACE[:PROTOCOL]"));
    const QString usage = QStringLiteral("imudesk-cli bridge PORT[,PORT...] [--listen ADDR:PORT] [--udp HOST:PORT] "
                                         "[--no-websocket] [--duration S] [--baud B] [--client-buffer-mb N]");
    if (!parseArgs(p, args, usage))
        return ExitUsage;
    if (p.positionalArguments().size() != 1)
        return fail(QStringLiteral("bridge needs the devices: PORT or PORT,PORT,..."), ExitUsage);
    bridge::BridgeOptions o;
    QString error;
    if (p.isSet(QStringLiteral("listen")) && !bridge::LiveBridge::parseHostPort(p.value(QStringLiteral("listen")), &o.address, &o.port, &error))
        return fail(error, ExitUsage);
    if (p.isSet(QStringLiteral("udp"))) {
        o.udp = true;
        if (!bridge::LiveBridge::parseHostPort(p.value(QStringLiteral("udp")), &o.udpHost, &o.udpPort, &error))
            return fail(error, ExitUsage);
    }
    o.websocket = !p.isSet(QStringLiteral("no-websocket"));
    if (!o.websocket && !o.udp)
        return fail(QStringLiteral("--no-websocket needs --udp: there would be nothing to send to"), ExitUsage);
    double duration = -1;
    int baud = 0;
    if (p.isSet(QStringLiteral("duration"))) {
        bool ok = false;
        duration = p.value(QStringLiteral("duration")).toDouble(&ok);
        if (!ok || duration <= 0)
            return fail(QStringLiteral("--duration needs a positive number of seconds"), ExitUsage);
    }
    if (p.isSet(QStringLiteral("baud"))) {
        bool ok = false;
        baud = p.value(QStringLiteral("baud")).toInt(&ok);
        if (!ok || baud <= 0)
            return fail(QStringLiteral("--baud needs a positive number"), ExitUsage);
    }
    if (p.isSet(QStringLiteral("client-buffer-mb"))) {
        bool ok = false;
        const double mb = p.value(QStringLiteral("client-buffer-mb")).toDouble(&ok);
        if (!ok || mb <= 0)
            return fail(QStringLiteral("--client-buffer-mb needs a positive number"), ExitUsage);
        o.clientBufferBytes = qint64(mb * (1 << 20));
    }

    const QStringList specs = p.positionalArguments().front().split(QLatin1Char(','), Qt::SkipEmptyParts);
    std::vector<OpenDevice> devices;
    if (const int code = openDevices(specs, baud, devices); code != ExitOk)
        return code;

    bridge::LiveBridge bridge;
    QObject::connect(&bridge, &bridge::LiveBridge::logged,
                     [](const QString &line) { std::fprintf(stderr, "bridge: %s\n", qPrintable(line)); });
    if (!bridge.start(o, &error))
        return fail(error);
    // Frames the devices sent that never reached ImuDesk (a counter or clock that skipped): the
    // clients miss them too, and the summary says how many.
    auto framesLost = std::make_shared<std::vector<uint64_t>>(devices.size(), 0); // outlives the links' signals
    for (size_t i = 0; i < devices.size(); ++i) {
        OpenDevice &d = devices[i];
        bridge.addDevice(d.link.link->sharedStore(), headerOf(d)); // named by capture::deviceName
        QObject::connect(d.link.link.get(), &device::DeviceLink::statsUpdated,
                         [framesLost, i](const device::SessionStats &st) { (*framesLost)[i] = st.framesLost; });
    }
    if (o.websocket)
        out(QStringLiteral("bridge %1 serving %2 device(s) (Ctrl+C stops)").arg(bridge.url()).arg(devices.size()));
    else
        out(QStringLiteral("bridge: UDP to %1:%2 from %3 device(s) (Ctrl+C stops)")
                .arg(o.udpHost.toString()).arg(o.udpPort).arg(devices.size()));
    QElapsedTimer clock;
    clock.start();
    waitFor([] { return false; }, duration > 0 ? int(duration * 1000) : -1);
    // The stores' last samples out before the end.
    waitFor([] { return false; }, 100);
    const bridge::BridgeStats s = bridge.stats();
    bridge.stop();
    for (OpenDevice &d : devices)
        d.link.link->close();
    uint64_t lostBefore = 0;
    for (uint64_t n : *framesLost)
        lostBefore += n;
    out(QStringLiteral("bridged %1 s: %2 samples from %3 device(s), %4 missed; %5 messages sent to %6 connection(s), %7 dropped; "
                       "%8 datagrams sent, %9 refused")
            .arg(double(clock.elapsed()) / 1000.0, 0, 'f', 1)
            .arg(s.samples)
            .arg(s.devices)
            .arg(s.samplesMissed)
            .arg(s.messagesSent)
            .arg(s.connections)
            .arg(s.messagesDropped)
            .arg(s.datagramsSent)
            .arg(s.datagramErrors));
    out(QStringLiteral("frames lost before the bridge (the devices' counters skipped): %1").arg(lostBefore));
    return ExitOk; // Ctrl+C is how a bridge without --duration ends
}

} // namespace imudesk::cli
