// imudesk-cli commands that talk to a device: ports, probe, read, send, simulate.
#include "cli_context.h"
#include "device/hec495_session.h"
#include "links/link_opener.h"
#include "format/sample_json.h"
#include "sim/pty_simulator.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSerialPortInfo>
#include <QThread>

#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

namespace imudesk::cli {

namespace {

QCommandLineOption baudOption()
{
    return QCommandLineOption(QStringLiteral("baud"), QStringLiteral("Baud rate (default: auto-detect)."),
                              QStringLiteral("B"));
}
QCommandLineOption jsonOption()
{
    return QCommandLineOption(QStringLiteral("json"), QStringLiteral("Machine-readable JSON output."));
}

bool baudFrom(const QCommandLineParser &p, int *baud)
{
    *baud = 0;
    if (!p.isSet(QStringLiteral("baud")))
        return true;
    bool ok = false;
    *baud = p.value(QStringLiteral("baud")).toInt(&ok);
    if (!ok || *baud <= 0) {
        fail(QStringLiteral("--baud needs a positive number, got '%1'").arg(p.value(QStringLiteral("baud"))),
             ExitUsage);
        return false;
    }
    return true;
}

QJsonObject identityJson(const model::DeviceIdentity &id)
{
    QJsonObject o;
    o[QStringLiteral("product")] = QString::fromStdString(id.productName);
    o[QStringLiteral("firmware")] = id.firmware ? QString::fromStdString(id.firmware->toString()) : QString();
    o[QStringLiteral("bootloader")] = id.bootloader ? QString::fromStdString(id.bootloader->toString()) : QString();
    o[QStringLiteral("serial")] = QString::fromStdString(id.serial);
    o[QStringLiteral("build")] = QString::fromStdString(id.build);
    o[QStringLiteral("product_family")] = QString::fromLatin1(model::familyName(id.family()));
    o[QStringLiteral("world_frame")] = QString::fromLatin1(model::worldFrameName(id.worldFrame));
    return o;
}

} // namespace

int cmdPorts(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(jsonOption());
    if (!parseArgs(p, args, QStringLiteral("imudesk-cli ports [--json]")))
        return ExitUsage;
    const auto ports = QSerialPortInfo::availablePorts();
    if (p.isSet(QStringLiteral("json"))) {
        QJsonArray arr;
        for (const auto &info : ports) {
            QJsonObject o;
            o[QStringLiteral("port")] = info.systemLocation();
            o[QStringLiteral("name")] = info.portName();
            o[QStringLiteral("description")] = info.description();
            o[QStringLiteral("manufacturer")] = info.manufacturer();
            o[QStringLiteral("serial_number")] = info.serialNumber();
            if (info.hasVendorIdentifier())
                o[QStringLiteral("vid")] = QStringLiteral("%1").arg(info.vendorIdentifier(), 4, 16, QLatin1Char('0'));
            if (info.hasProductIdentifier())
                o[QStringLiteral("pid")] = QStringLiteral("%1").arg(info.productIdentifier(), 4, 16, QLatin1Char('0'));
            arr.append(o);
        }
        out(QString::fromUtf8(QJsonDocument(arr).toJson(QJsonDocument::Compact)));
        return ExitOk;
    }
    if (ports.isEmpty())
        out(QStringLiteral("no serial ports found (a simulated device: imudesk-cli simulate --pty)"));
    for (const auto &info : ports)
        out(QStringLiteral("%1\t%2\t%3").arg(info.systemLocation(), info.description(), info.serialNumber()));
    return ExitOk;
}

int cmdProbe(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(baudOption());
    p.addOption(jsonOption());
    p.addPositionalArgument(QStringLiteral("PORT"), QStringLiteral("Serial port, e.g. /dev/ttyUSB0"));
    if (!parseArgs(p, args, QStringLiteral("imudesk-cli probe PORT [--baud B] [--json]")))
        return ExitUsage;
    if (p.positionalArguments().size() != 1)
        return fail(QStringLiteral("probe needs exactly one PORT"), ExitUsage);
    int baud = 0;
    if (!baudFrom(p, &baud))
        return ExitUsage;
    const QString port = p.positionalArguments().front();
    // The port is opened once: the detection tells the family and the rate, and its session
    // takes the port over (device::LinkOpener).
    device::LinkOpener opener;
    device::LinkRequest request = device::LinkRequest::serial(port, baud);
    request.autoReconnect = false;
    QString error;
    bool ready = false;
    QObject::connect(&opener, &device::LinkOpener::ready, [&] { ready = true; });
    QObject::connect(&opener, &device::LinkOpener::failed, [&](const QString &why) { error = why; });
    opener.open(request);
    // At most 11 rates of under a second each; leave room.
    waitFor([&] { return ready || !error.isEmpty(); }, 30000);
    if (!ready) {
        opener.cancel();
        return fail(interrupted() ? QStringLiteral("interrupted")
                    : error.isEmpty() ? QStringLiteral("timed out probing %1").arg(port) : error,
                    interrupted() ? ExitInterrupted : ExitFailure);
    }
    device::LinkOpener::Opened link = opener.take();
    const int found = opener.request().baud;
    if (auto *compass = qobject_cast<device::Hec495Session *>(link.link.get())) {
        printHec495Probe(port, found, opener.request().deviceAddress, p.isSet(QStringLiteral("json")));
        compass->close();
        return ExitOk;
    }
    auto *session = qobject_cast<device::DeviceSession *>(link.link.get());
    if (!session)
        return fail(QStringLiteral("%1: no serial device session").arg(port));
    model::DeviceIdentity id;
    if (!connectSession(*session, port, found, &id, nullptr, &error))
        return fail(error, interrupted() ? ExitInterrupted : ExitFailure);
    if (p.isSet(QStringLiteral("json"))) {
        QJsonObject o = identityJson(id);
        o[QStringLiteral("port")] = port;
        o[QStringLiteral("baud")] = found;
        o[QStringLiteral("identified")] = id.usable();
        o[QStringLiteral("family")] = QStringLiteral("hipnuc");
        out(QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact)));
    } else {
        out(QStringLiteral("port: %1").arg(port));
        out(QStringLiteral("baud: %1").arg(found));
        if (id.usable()) {
            out(QStringLiteral("product: %1").arg(QString::fromStdString(id.productName)));
            out(QStringLiteral("firmware: %1").arg(id.firmware ? QString::fromStdString(id.firmware->toString()) : QString()));
            out(QStringLiteral("bootloader: %1")
                    .arg(id.bootloader ? QString::fromStdString(id.bootloader->toString()) : QString()));
            out(QStringLiteral("serial: %1").arg(QString::fromStdString(id.serial)));
            out(QStringLiteral("world frame: %1").arg(QString::fromLatin1(model::worldFrameName(id.worldFrame))));
        } else {
            out(QStringLiteral("identity: not answered (the device streams frames but ignored LOG VERSION)"));
        }
    }
    return ExitOk;
}

namespace {

// One sample as a line of text (read's human output).
void printSampleLine(const model::Sample &s, model::WorldFrame frame)
{
    // A module set to NWU (CONFIG IMU COORD 4): its angles say so.
    std::printf("%s t=%.0f ms acc=[%.3f %.3f %.3f] G gyr=[%.2f %.2f %.2f] deg/s rpy%s=[%.2f %.2f %.2f] deg\n",
                s.source.c_str(), s.deviceTimeMs, s.acc.x, s.acc.y, s.acc.z, s.gyr.x, s.gyr.y, s.gyr.z,
                frame == model::WorldFrame::Nwu ? "(NWU)" : "", s.roll, s.pitch, s.yaw);
}

} // namespace

int cmdRead(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(baudOption());
    p.addOption(jsonOption());
    p.addOption(QCommandLineOption(QStringLiteral("duration"), QStringLiteral("Seconds to read (default: until Ctrl+C)."),
                                   QStringLiteral("S")));
    p.addOption(QCommandLineOption(QStringLiteral("once"),
                                   QStringLiteral("Take one sample: LOG <TYPE> ONMARK ONCE, print the frame it brings."),
                                   QStringLiteral("TYPE")));
    p.addPositionalArgument(QStringLiteral("PORT"), QStringLiteral("Serial port"));
    if (!parseArgs(p, args, QStringLiteral("imudesk-cli read PORT [--baud B] [--duration S | --once HI91|HI81|HI83|GGA|...] [--json]")))
        return ExitUsage;
    if (p.positionalArguments().size() != 1)
        return fail(QStringLiteral("read needs exactly one PORT"), ExitUsage);
    int baud = 0;
    if (!baudFrom(p, &baud))
        return ExitUsage;
    double duration = -1;
    if (p.isSet(QStringLiteral("duration"))) {
        bool ok = false;
        duration = p.value(QStringLiteral("duration")).toDouble(&ok);
        if (!ok || duration <= 0)
            return fail(QStringLiteral("--duration needs a positive number of seconds"), ExitUsage);
    }
    const bool json = p.isSet(QStringLiteral("json"));
    std::optional<protocol::hipnuc::Command> once;
    if (p.isSet(QStringLiteral("once"))) {
        protocol::hipnuc::Message m{};
        if (!protocol::hipnuc::parseMessage(p.value(QStringLiteral("once")).toUpper().toStdString(), m))
            return fail(QStringLiteral("--once needs a message type such as HI91, HI83 or GGA"), ExitUsage);
        once = protocol::hipnuc::commands::logOnMark(m, true);
        if (!once->ok())
            return fail(QString::fromStdString(once->error), ExitUsage);
    }
    device::DeviceSession session;
    QString error;
    model::DeviceIdentity id;
    int found = baud;
    if (!connectSession(session, p.positionalArguments().front(), baud, &id, &found, &error))
        return fail(error, interrupted() ? ExitInterrupted : ExitFailure);
    if (once) {
        // v1.7.1 4.6.8.15: one frame of that type, as a SYNC_IN pulse would trigger. What
        // the module streams meanwhile is not printed: the first sample of that type is the one.
        const std::string type = p.value(QStringLiteral("once")).toUpper().toStdString();
        std::optional<protocol::hipnuc::AsciiReply> reply;
        QString why;
        const quint64 cmdId = session.sendCommand(*once, 2000, &why);
        QObject::connect(&session, &device::DeviceSession::commandFinished, &session,
                         [&](quint64 done, const protocol::hipnuc::AsciiReply &r) {
                             if (done == cmdId)
                                 reply = r;
                         });
        uint64_t from = session.store().totalAppended();
        std::optional<model::Sample> got;
        waitFor([&] {
            for (const auto &x : session.store().since(from, SIZE_MAX, &from))
                if (!got && x.source == type)
                    got = x;
            return got.has_value() || (reply && !reply->ok());
        }, 3000);
        if (reply && !reply->ok())
            return fail(QStringLiteral("%1: the module answered %2").arg(QString::fromStdString(once->text),
                                                                       QString::fromStdString(reply->errorLine)));
        if (!got)
            return fail(QStringLiteral("no %1 frame came within 3 s of %2").arg(QString::fromStdString(type),
                                                                                QString::fromStdString(once->text)));
        if (json)
            outRaw(format::sampleToJson(*got, id.worldFrame));
        else
            printSampleLine(*got, id.worldFrame);
        std::fflush(stdout);
        return ExitOk;
    }
    bool lost = false;
    QString lostMessage;
    QObject::connect(&session, &device::DeviceSession::errorOccurred, [&](const QString &m) {
        lost = true;
        lostMessage = m;
    });
    device::SessionStats stats;
    QObject::connect(&session, &device::DeviceSession::statsUpdated,
                     [&](const device::SessionStats &s) { stats = s; });
    uint64_t seq = session.store().totalAppended();
    uint64_t printed = 0;
    int64_t lastTextNs = 0;
    auto drain = [&] {
        const auto batch = session.store().since(seq, SIZE_MAX, &seq);
        for (const auto &s : batch) {
            ++printed;
            if (json) {
                outRaw(format::sampleToJson(s, id.worldFrame));
            } else if (s.hostTimeNs - lastTextNs >= 100'000'000) { // text: 10 lines/s at most
                lastTextNs = s.hostTimeNs;
                printSampleLine(s, id.worldFrame);
            }
        }
        std::fflush(stdout);
        return false;
    };
    waitFor([&] { return drain() || lost; }, duration > 0 ? int(duration * 1000) : -1);
    drain();
    if (!json && !lost) { // one more statistics report, so the summary counts the whole run
        const uint64_t seen = stats.bytesIn;
        waitFor([&] { return stats.bytesIn != seen; }, 700);
    }
    if (!json)
        out(QStringLiteral("samples: %1, frames: %2, crc errors: %3, bytes skipped: %4")
                .arg(printed)
                .arg(stats.frames)
                .arg(stats.crcErrors)
                .arg(stats.bytesSkipped));
    if (lost)
        return fail(lostMessage);
    return ExitOk;
}

int cmdSend(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(baudOption());
    p.addOption(QCommandLineOption(QStringLiteral("timeout"), QStringLiteral("Reply timeout in ms (default 1000)."),
                                   QStringLiteral("MS"), QStringLiteral("1000")));
    p.addPositionalArgument(QStringLiteral("PORT"), QStringLiteral("Serial port"));
    p.addPositionalArgument(QStringLiteral("COMMAND"), QStringLiteral("ASCII command, e.g. \"LOG VERSION\""));
    if (!parseArgs(p, args, QStringLiteral("imudesk-cli send PORT [--baud B] [--timeout MS] \"COMMAND\"")))
        return ExitUsage;
    if (p.positionalArguments().size() != 2)
        return fail(QStringLiteral("send needs PORT and one quoted COMMAND"), ExitUsage);
    int baud = 0;
    if (!baudFrom(p, &baud))
        return ExitUsage;
    const int timeoutMs = p.value(QStringLiteral("timeout")).toInt();
    if (timeoutMs <= 0)
        return fail(QStringLiteral("--timeout needs a positive number of ms"), ExitUsage);
    const QString command = p.positionalArguments().at(1).trimmed();
    if (command.isEmpty() || command.contains(QLatin1Char('\r')) || command.contains(QLatin1Char('\n')))
        return fail(QStringLiteral("the command must be one non-empty line"), ExitUsage);
    device::DeviceSession session;
    QString error;
    if (!connectSession(session, p.positionalArguments().front(), baud, nullptr, nullptr, &error))
        return fail(error, interrupted() ? ExitInterrupted : ExitFailure);
    std::optional<protocol::hipnuc::AsciiReply> reply;
    const quint64 id = session.sendText(command, timeoutMs); // typed by the user, as in the console
    QObject::connect(&session, &device::DeviceSession::commandFinished,
                     [&](quint64 done, const protocol::hipnuc::AsciiReply &r) {
                         if (done == id)
                             reply = r;
                     });
    waitFor([&] { return reply.has_value(); }, timeoutMs + 5000);
    if (!reply)
        return fail(QStringLiteral("interrupted"), ExitInterrupted);
    for (const auto &line : reply->lines)
        out(QString::fromStdString(line));
    using S = protocol::hipnuc::AsciiReply::Status;
    switch (reply->status) {
    case S::Ok:
        out(QStringLiteral("OK"));
        return ExitOk;
    case S::Refused:
        return fail(QStringLiteral("device answered %1 to '%2'").arg(QString::fromStdString(reply->errorLine), command));
    case S::Timeout:
        return fail(QStringLiteral("no reply to '%1' within %2 ms (the device does not answer commands it does not "
                                   "know)")
                        .arg(command)
                        .arg(timeoutMs));
    default:
        return fail(QStringLiteral("'%1' was not completed: %2")
                        .arg(command, QString::fromStdString(reply->errorLine)));
    }
}

int cmdSimulate(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(QCommandLineOption(QStringLiteral("pty"), QStringLiteral("Serve the device on a pseudo-terminal.")));
    p.addOption(QCommandLineOption(QStringLiteral("model"), QStringLiteral("Product model (default HI14)."),
                                   QStringLiteral("MODEL"), QStringLiteral("HI14")));
    p.addOption(QCommandLineOption(QStringLiteral("firmware"), QStringLiteral("1.7.1 (default) or 1.6.6."),
                                   QStringLiteral("VERSION"), QStringLiteral("1.7.1")));
    p.addOption(QCommandLineOption(QStringLiteral("baud"), QStringLiteral("Device baud rate (default 115200)."),
                                   QStringLiteral("B"), QStringLiteral("115200")));
    p.addOption(QCommandLineOption(QStringLiteral("pps"),
                                   QStringLiteral("A GNSS receiver on SYNC_IN/PPS: the clock aligns to UTC at the first "
                                                  "second (UTC_UNSYNC clears) and each second triggers ONMARK 1 output.")));
    p.addOption(QCommandLineOption(QStringLiteral("motion"),
                                   QStringLiteral("static (default), spin, tumble, turntable (still 3 s, 720 deg "
                                                  "one way at 45 deg/s, still, 720 deg back: a gyro-scale run) or twists "
                                                  "(a fixture turned sharply now and then, the same for every module "
                                                  "simulated on this host: twist-to-align) or poses (turned by hand "
                                                  "through 12 still poses: verify) or bearings (a compass turned to the 8 marks of a "
                                                  "level rose: verify --bearings)."),
                                   QStringLiteral("MOTION"), QStringLiteral("static")));
    p.addOption(QCommandLineOption(QStringLiteral("seed"), QStringLiteral("Random seed (default 1)."),
                                   QStringLiteral("N"), QStringLiteral("1")));
    p.addOption(QCommandLineOption(QStringLiteral("serial"),
                                   QStringLiteral("HiPNUC on a pty: the serial number (UUID) it reports instead of the "
                                                  "seed's, byte for byte; \\xNN writes any byte."),
                                   QStringLiteral("TEXT")));
    p.addOption(QCommandLineOption(
        QStringLiteral("faults"),
        QStringLiteral("HiPNUC on a pty: faults of this module, comma-separated: noisy-gyro[=F] (gyro noise x F, "
                       "default 20), mounting=R/P/Y or wrong-mounting (90/0/0; deg), mag-disturbance[=U] (uT, "
                       "default 40: MCAL fails), unplug=T (cable pulled T s after the start), fixture (turned "
                       "through every attitude while an MCAL runs), acc-bias=X/Y/Z (mg), acc-scale=X/Y/Z (%), "
                       "acc-misalignment=YX/ZX/ZY (deg), acc-error=MG/PCT (every axis), gyro-scale=PCT or X/Y/Z (%), "
                       "attitude-bias=R/P/H (deg, heading clockwise), filter-lag=MS (the attitude late). "
                       "HEC495: calibrated (its hard iron corrected and saved before), heading-bias=DEG."),
        QStringLiteral("LIST")));
    p.addOption(QCommandLineOption(QStringLiteral("clock"),
                                   QStringLiteral("HiPNUC on a pty: the module's oscillator, PPM[,OFFSET_MS[,STEP_AT_S,STEP_MS]] "
                                                  "(e.g. 40 or -25,0,30,5: -25 ppm, its time jumping 5 ms at 30 s)."),
                                   QStringLiteral("SPEC")));
    p.addOption(QCommandLineOption(QStringLiteral("adapter"),
                                   QStringLiteral("On a pty: a USB adapter between the device and the host, TIMER_MS[,JITTER_US"
                                                  "[,FIXED_US]] (e.g. 16: an FTDI's default latency timer)."),
                                   QStringLiteral("SPEC")));
    p.addOption(QCommandLineOption(QStringLiteral("sync-in"),
                                   QStringLiteral("HiPNUC on a pty: a pulse source on SYNC_IN at HZ; every module simulated "
                                                  "on this host with the same rate sees the same edges (LOG HI91 ONMARK 1 "
                                                  "then sends a frame at each)."),
                                   QStringLiteral("HZ")));
    addModbusSimulateOptions(p); // also --device hipnuc|hec495
    addFlashDumpOption(p);
    p.addOption(QCommandLineOption(QStringLiteral("address"), QStringLiteral("HEC495 module address (default 0)."),
                                   QStringLiteral("N"), QStringLiteral("0")));
    p.addOption(QCommandLineOption(QStringLiteral("can"), QStringLiteral("Serve a CAN device on PLUGIN:INTERFACE."),
                                   QStringLiteral("SPEC")));
    p.addOption(QCommandLineOption(QStringLiteral("protocol"), QStringLiteral("CAN: j1939 (default) or canopen."),
                                   QStringLiteral("PROTO"), QStringLiteral("j1939")));
    p.addOption(QCommandLineOption(QStringLiteral("node"), QStringLiteral("CAN: node ID (default 8, HEC495 5)."),
                                   QStringLiteral("N"), QStringLiteral("-1")));
    p.addOption(QCommandLineOption(QStringLiteral("fd"),
                                   QStringLiteral("CAN: a HiPNUC J1939 module on a CAN FD bus, which also sends the "
                                                  "64-byte PGN 0xFF5A every 10 ms.")));
    const QString usage = QStringLiteral("imudesk-cli simulate --pty [--device hipnuc|hec495] [--model HI14] "
                                         "[--firmware 1.7.1] [--serial SN] [--baud 115200] [--address N] "
                                         "[--motion static|spin|tumble|turntable|twists|poses|bearings] [--pps] [--seed N] [--faults LIST] "
                                         "[--clock PPM[,OFFSET_MS[,STEP_AT_S,STEP_MS]]] [--adapter TIMER_MS[,JITTER_US[,FIXED_US]]] "
                                         "[--sync-in HZ] "
                                         "[--flash-dump FILE] [--modbus [--id N]] | --can PLUGIN:INTERFACE [--protocol j1939|canopen] "
                                         "[--device hipnuc|hec495] [--node N] [--fd] [--flash-dump FILE]");
    if (!parseArgs(p, args, usage))
        return ExitUsage;
    if (p.isSet(QStringLiteral("faults"))
        && (p.isSet(QStringLiteral("can")) || p.isSet(QStringLiteral("modbus"))
            || (p.value(QStringLiteral("device")) != QLatin1String("hipnuc")
                && p.value(QStringLiteral("device")) != QLatin1String("hec495"))))
        return fail(QStringLiteral("--faults is for a HiPNUC module or an HEC495 on a pty (simulate --pty [--device "
                                   "hipnuc|hec495])"),
                    ExitUsage);
    if (p.isSet(QStringLiteral("fd"))
        && (!p.isSet(QStringLiteral("can")) || p.value(QStringLiteral("device")) != QLatin1String("hipnuc")
            || p.value(QStringLiteral("protocol")).toLower() != QLatin1String("j1939")))
        return fail(QStringLiteral("--fd is for a HiPNUC J1939 module on CAN (simulate --can PLUGIN:IF --protocol j1939 --fd): "
                                   "the manuals give CAN FD output (PGN 0xFF5A) for J1939 only"),
                    ExitUsage);
    if (p.isSet(QStringLiteral("can"))) {
        sim::Motion m = sim::Motion::Static;
        if (!sim::parseMotion(p.value(QStringLiteral("motion")).toStdString(), m))
            return fail(QStringLiteral("--motion must be static, spin, tumble, turntable, twists, poses or bearings"), ExitUsage);
        return simulateCan(p.value(QStringLiteral("can")), p.value(QStringLiteral("protocol")), p.value(QStringLiteral("device")),
                           p.value(QStringLiteral("node")).toInt(), m, p.value(QStringLiteral("seed")).toULongLong(),
                           p.value(QStringLiteral("firmware")), p.isSet(QStringLiteral("fd")),
                           p.value(QStringLiteral("flash-dump")));
    }
    if (!p.isSet(QStringLiteral("pty")))
        return fail(QStringLiteral("simulate needs --pty (usage: %1)").arg(usage), ExitUsage);
    if (p.isSet(QStringLiteral("modbus")))
        return simulateModbus(p);
    if (p.value(QStringLiteral("device")) == QLatin1String("hec495"))
        return simulateHec495(p);
    if (p.value(QStringLiteral("device")) != QLatin1String("hipnuc"))
        return fail(QStringLiteral("--device must be hipnuc or hec495"), ExitUsage);
    sim::SimOptions o;
    o.model = p.value(QStringLiteral("model")).toStdString();
    o.firmware = p.value(QStringLiteral("firmware")).toStdString();
    const auto fw = model::FirmwareVersion::parse(o.firmware);
    if (!fw || *fw < model::FirmwareVersion{1, 5, 5} || *fw > model::FirmwareVersion{1, 7, 1})
        return fail(QStringLiteral("--firmware must be a version from 1.5.5 to 1.7.1"), ExitUsage);
    bool ok = false;
    o.baud = p.value(QStringLiteral("baud")).toInt(&ok);
    if (!ok || !protocol::hipnuc::commands::isSupportedBaud(o.baud))
        return fail(QStringLiteral("--baud must be one of 4800 9600 19200 38400 57600 115200 230400 256000 460800 921600"),
                    ExitUsage);
    if (!sim::parseMotion(p.value(QStringLiteral("motion")).toStdString(), o.motion))
        return fail(QStringLiteral("--motion must be static, spin, tumble, turntable, twists, poses or bearings"), ExitUsage);
    o.ppsInput = p.isSet(QStringLiteral("pps"));
    if (p.isSet(QStringLiteral("serial"))) {
        // \xNN escapes (a test's bytes that are not UTF-8), the rest as UTF-8.
        const QByteArray text = p.value(QStringLiteral("serial")).toUtf8();
        for (int i = 0; i < text.size(); ++i) {
            if (text[i] == '\\' && i + 3 < text.size() && text[i + 1] == 'x') {
                bool hex = false;
                const int b = text.mid(i + 2, 2).toInt(&hex, 16);
                if (hex) {
                    o.serial.push_back(char(b));
                    i += 3;
                    continue;
                }
            }
            o.serial.push_back(text[i]);
        }
        if (o.serial.empty() || o.serial.find_first_of("\r\n") != std::string::npos)
            return fail(QStringLiteral("--serial needs text without line breaks"), ExitUsage);
    }
    o.seed = p.value(QStringLiteral("seed")).toULongLong(&ok);
    if (!ok)
        return fail(QStringLiteral("--seed needs a whole number"), ExitUsage);
    std::string faultError;
    if (!sim::parseSimFaults(p.value(QStringLiteral("faults")).toStdString(), o.faults, &faultError))
        return fail(QStringLiteral("--faults: %1").arg(QString::fromStdString(faultError)), ExitUsage);
    // Numbers separated by commas: at least `least`, at most `most`.
    auto numbers = [&](const char *name, int least, int most, std::vector<double> *v) {
        if (!p.isSet(QLatin1String(name)))
            return true;
        for (const QString &part : p.value(QLatin1String(name)).split(QLatin1Char(','))) {
            bool good = false;
            v->push_back(part.toDouble(&good));
            if (!good)
                return false;
        }
        return int(v->size()) >= least && int(v->size()) <= most;
    };
    std::vector<double> clockSpec, adapterSpec;
    if (!numbers("clock", 1, 4, &clockSpec) || clockSpec.size() == 3)
        return fail(QStringLiteral("--clock is PPM[,OFFSET_MS[,STEP_AT_S,STEP_MS]], e.g. 40 or -25,0,30,5"), ExitUsage);
    if (!numbers("adapter", 1, 3, &adapterSpec) || (!adapterSpec.empty() && adapterSpec[0] < 0))
        return fail(QStringLiteral("--adapter is TIMER_MS[,JITTER_US[,FIXED_US]], e.g. 16"), ExitUsage);
    sim::ClockError clock;
    if (!clockSpec.empty()) {
        clock.driftPpm = clockSpec[0];
        clock.offsetUs = clockSpec.size() > 1 ? clockSpec[1] * 1000 : 0;
        if (clockSpec.size() == 4) {
            clock.stepAtS = clockSpec[2];
            clock.stepUs = clockSpec[3] * 1000;
        }
        bool finite = true;
        for (double v : clockSpec)
            finite = finite && std::isfinite(v);
        if (!finite || std::abs(clock.driftPpm) > 1000 || clock.offsetUs < 0 || clock.stepUs < 0
            || (clockSpec.size() == 4 && clock.stepAtS < 0))
            return fail(QStringLiteral("--clock: a drift within +-1000 ppm, an offset >= 0 ms and a step forward "
                                       "(>= 0 ms, at >= 0 s)"),
                        ExitUsage);
    }
    sim::AdapterLatency adapter;
    if (!adapterSpec.empty()) {
        adapter.latencyTimerMs = adapterSpec[0];
        adapter.jitterUs = adapterSpec.size() > 1 ? adapterSpec[1] : 0;
        adapter.fixedUs = adapterSpec.size() > 2 ? adapterSpec[2] : 0;
    }

    double syncInHz = 0;
    if (p.isSet(QStringLiteral("sync-in"))) {
        syncInHz = p.value(QStringLiteral("sync-in")).toDouble(&ok);
        if (!ok || !std::isfinite(syncInHz) || syncInHz <= 0 || syncInHz > 1000)
            return fail(QStringLiteral("--sync-in needs a pulse rate in Hz, up to 1000"), ExitUsage);
    }

    sim::PtySimulator simulator(o);
    simulator.setClock(clock);
    simulator.setAdapter(adapter);
    simulator.setSyncIn(syncInHz);
    QString error;
    if (!simulator.start(&error))
        return fail(QStringLiteral("could not create a pseudo-terminal: %1").arg(error));
    out(QStringLiteral("pty: %1").arg(simulator.devicePath()));
    waitFor([] { return false; }, -1); // until SIGINT/SIGTERM
    const int dumped = writeFlashDump(simulator, p);
    simulator.stop();
    return dumped;
}

} // namespace imudesk::cli
