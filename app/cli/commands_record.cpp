// imudesk-cli record: every byte a device sends, to a capture file (README, "Capture file format").
#include "cli_context.h"
#include "device/group_recording.h"
#include "device/link_opener.h"
#include "protocol/can/can_decoder.h"
#include "protocol/hipnuc/ascii_command.h"
#include "record/mcap_recording.h"
#include "record/capture_header.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>

#include <memory>
#include <vector>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <optional>

namespace imudesk::cli {

namespace {

// One device of `record PORT,PORT,...`: a serial port (its family found as probe finds it;
// PORT:BAUD at that rate),
// modbus:PORT[@ID] (a HiPNUC module's Modbus RTU; modbus-hec495:PORT[@ID] for the compass), or
// can:PLUGIN:INTERFACE[:PROTOCOL] (protocol auto, j1939, canopen or hec495).
bool linkOf(const QString &spec, int baud, device::LinkRequest *out, QString *error)
{
    auto bad = [&](const QString &why) {
        *error = QStringLiteral("%1: %2").arg(spec, why);
        return false;
    };
    if (spec.startsWith(QLatin1String("can:"))) {
        const QStringList parts = spec.mid(4).split(QLatin1Char(':'));
        if (parts.size() < 2 || parts.size() > 3 || parts[0].isEmpty() || parts[1].isEmpty())
            return bad(QStringLiteral("a CAN device is can:PLUGIN:INTERFACE[:PROTOCOL], e.g. can:socketcan:can0:canopen"));
        device::CanSessionOptions o;
        o.plugin = parts[0];
        o.interfaceName = parts[1];
        if (parts.size() == 3) {
            const auto proto = protocol::can::parseProtocol(parts[2]);
            if (!proto)
                return bad(QStringLiteral("unknown CAN protocol '%1' (auto, j1939, canopen, hec495)").arg(parts[2]));
            o.protocol = *proto;
        }
        *out = device::LinkRequest::canBus(o);
        return true;
    }
    for (const char *prefix : {"modbus:", "modbus-hec495:"}) {
        if (!spec.startsWith(QLatin1String(prefix)))
            continue;
        QString rest = spec.mid(int(std::strlen(prefix)));
        device::ModbusOptions o;
        o.kind = std::strcmp(prefix, "modbus:") == 0 ? protocol::modbus::DeviceKind::Hipnuc
                                                      : protocol::modbus::DeviceKind::Hec495;
        const int at = int(rest.lastIndexOf(QLatin1Char('@')));
        if (at >= 0) {
            bool ok = false;
            o.nodeId = rest.mid(at + 1).toInt(&ok);
            if (!ok || o.nodeId < 1 || o.nodeId > 247)
                return bad(QStringLiteral("a Modbus node ID is 1..247"));
            rest = rest.left(at);
        }
        if (rest.isEmpty())
            return bad(QStringLiteral("no port after '%1'").arg(QLatin1String(prefix)));
        o.port = rest;
        o.baud = baud;
        *out = device::LinkRequest::modbusDevice(o);
        return true;
    }
    // PORT:BAUD: that device's rate (the family is still recognised, at that rate only).
    QString port = spec;
    const int colon = int(spec.lastIndexOf(QLatin1Char(':')));
    if (colon > 0) {
        bool ok = false;
        const int own = spec.mid(colon + 1).toInt(&ok);
        if (!ok || own <= 0)
            return bad(QStringLiteral("a serial device is PORT or PORT:BAUD"));
        port = spec.left(colon);
        baud = own;
    }
    *out = device::LinkRequest::serial(port, baud);
    return true;
}

// record PORT,PORT,... -o FOLDER: every device into one session folder (device/group_recording.h).
int recordGroup(const QStringList &specs, const QString &folder, double duration, int baud)
{
    struct Device {
        QString spec;
        std::unique_ptr<device::LinkOpener> opener;
        device::OpenedLink link;
        model::DeviceIdentity identity;
        device::SessionState state = device::SessionState::Closed;
        QString error;
        bool ready = false;
    };
    std::vector<Device> devices(size_t(specs.size()));
    for (int i = 0; i < specs.size(); ++i) {
        Device &d = devices[size_t(i)];
        d.spec = specs[i];
        device::LinkRequest request;
        QString error;
        if (!linkOf(d.spec, baud, &request, &error))
            return fail(error, ExitUsage);
        d.opener = std::make_unique<device::LinkOpener>();
        QObject::connect(d.opener.get(), &device::LinkOpener::ready, [&d] { d.ready = true; });
        QObject::connect(d.opener.get(), &device::LinkOpener::failed, [&d](const QString &why) { d.error = why; });
        d.opener->open(request);
    }
    // The detections run side by side: at most 11 rates of under a second each.
    waitFor([&] {
        for (const Device &d : devices)
            if (!d.ready && d.error.isEmpty())
                return false;
        return true;
    }, 30000);
    for (Device &d : devices) {
        if (!d.ready) {
            d.opener->cancel();
            return fail(QStringLiteral("%1: %2").arg(d.spec, d.error.isEmpty() ? QStringLiteral("timed out opening it") : d.error),
                        interrupted() ? ExitInterrupted : ExitFailure);
        }
        d.link = d.opener->take();
        QObject::connect(d.link.link.get(), &device::DeviceLink::identityChanged,
                         [&d](const model::DeviceIdentity &id) { d.identity = id; });
        QObject::connect(d.link.link.get(), &device::DeviceLink::stateChanged,
                         [&d](device::SessionState st, const QString &detail) {
                             d.state = st;
                             if (st == device::SessionState::Failed)
                                 d.error = detail;
                         });
        if (d.link.start)
            d.link.start();
    }
    waitFor([&] {
        for (const Device &d : devices)
            if (d.state != device::SessionState::Connected && d.error.isEmpty())
                return false;
        return true;
    }, 15000);
    std::vector<device::GroupRecording::Member> members;
    for (Device &d : devices) {
        auto *session = qobject_cast<device::Session *>(d.link.link.get());
        if (d.state != device::SessionState::Connected || !session)
            return fail(QStringLiteral("%1: %2").arg(d.spec, !session ? QStringLiteral("this link cannot be recorded")
                                                     : d.error.isEmpty() ? QStringLiteral("did not connect within 15 s")
                                                                         : d.error),
                        interrupted() ? ExitInterrupted : ExitFailure);
        // A name for the file and the manifest: the port without /dev/ ("ttyUSB0", "pts-3").
        QString name = d.spec;
        if (name.startsWith(QLatin1String("/dev/")))
            name = name.mid(5).section(QLatin1Char(':'), 0, 0); // without its :BAUD
        name.replace(QLatin1Char('/'), QLatin1Char('-'));
        members.push_back({session, name, d.spec, d.identity});
    }
    device::GroupRecording group;
    QString error;
    if (!group.start(folder, members, &error))
        return fail(error);
    bool finished = false;
    QString manifestPath, finishError;
    QObject::connect(&group, &device::GroupRecording::finished, [&](const QString &path, const QString &why) {
        finished = true;
        manifestPath = path;
        finishError = why;
    });
    QObject::connect(&group, &device::GroupRecording::deviceEvent, [&](int index, const QString &what) {
        std::fprintf(stderr, "%s: %s\n", qPrintable(specs[index]), qPrintable(what));
    });
    out(QStringLiteral("recording %1 devices to %2 (Ctrl+C stops)").arg(specs.size()).arg(folder));
    QElapsedTimer clock;
    clock.start();
    waitFor([&] { return finished; }, duration > 0 ? int(duration * 1000) : -1);
    group.stop();
    // Ctrl+C ends the waiting above; the recordings still get their 10 s to close their files
    // and the manifest to be written (waitFor would return at once once a signal came).
    QElapsedTimer closing;
    closing.start();
    while (!finished && closing.elapsed() < 10000)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
    if (!finished)
        return fail(QStringLiteral("the recordings did not stop within 10 s"));
    out(QStringLiteral("recorded %1 s into %2").arg(double(clock.elapsed()) / 1000.0, 0, 'f', 1).arg(folder));
    for (const auto &d : group.manifest().devices) {
        QStringList clocks;
        for (const device::ClockStats &c : d.clocks)
            clocks << QStringLiteral("%1 %2 %3").arg(QString::fromStdString(c.source),
                                                   QLatin1String(record::clockMethodName(c.method)),
                                                   QLatin1String(record::clockStateName(c.state)));
        out(QStringLiteral("  %1 (%2): %3 bytes, %4 frames -> %5%6%7")
                .arg(d.name, d.linkKind)
                .arg(d.bytes)
                .arg(d.frames)
                .arg(d.file, clocks.isEmpty() ? QString() : QStringLiteral("; clocks: ") + clocks.join(QStringLiteral(", ")),
                     d.droppedOut() ? QStringLiteral("; DROPPED OUT (marked in session.json)") : QString()));
    }
    for (Device &d : devices)
        d.link.link->close();
    if (!finishError.isEmpty())
        return fail(finishError);
    // A device whose capture stopped on its own (a full disk) or that recorded nothing fails the
    // command, as a single recording that stops does; one that dropped out is reported above.
    for (const auto &d : group.manifest().devices) {
        for (const auto &e : d.events)
            if (e.what == QLatin1String("recording stopped"))
                return fail(QStringLiteral("%1: %2").arg(d.name, e.detail));
        if (d.bytes == 0)
            return fail(QStringLiteral("%1: nothing was recorded").arg(d.name));
    }
    return ExitOk; // Ctrl+C is how a recording without --duration ends
}

} // namespace

int cmdRecord(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(QCommandLineOption({QStringLiteral("o"), QStringLiteral("output")},
                                   QStringLiteral("Capture file to write (e.g. run.imucap; a name ending in .mcap records MCAP: ROS 2 messages that PlotJuggler, Foxglove and Lichtblick open)."), QStringLiteral("FILE")));
    p.addOption(QCommandLineOption(QStringLiteral("duration"),
                                   QStringLiteral("Seconds to record (default: until Ctrl+C)."), QStringLiteral("S")));
    p.addOption(QCommandLineOption(QStringLiteral("baud"), QStringLiteral("Baud rate (default: auto-detect)."),
                                   QStringLiteral("B")));
    p.addOption(QCommandLineOption(QStringLiteral("split-mb"),
                                   QStringLiteral("Start a new file every N MB (name-001.imucap, ...)."),
                                   QStringLiteral("N")));
    p.addOption(QCommandLineOption(QStringLiteral("split-minutes"),
                                   QStringLiteral("Start a new file every N minutes."), QStringLiteral("N")));
    p.addPositionalArgument(QStringLiteral("PORT[,PORT...]"),
                            QStringLiteral("Serial port; several, comma-separated, record one session into the folder "
                                           "-o names (a port may be PORT:BAUD, modbus:PORT[@ID], modbus-hec495:PORT[@ID] or "
                                           "can:PLUGIN:INTERFACE[:PROTOCOL])"));
    const QString usage = QStringLiteral("imudesk-cli record PORT -o FILE [--duration S] [--baud B] [--split-mb N] "
                                         "[--split-minutes N]\n       imudesk-cli record PORT,PORT[,...] -o FOLDER "
                                         "[--duration S] [--baud B]");
    if (!parseArgs(p, args, usage))
        return ExitUsage;
    if (p.positionalArguments().size() != 1 || !p.isSet(QStringLiteral("o")))
        return fail(QStringLiteral("record needs one PORT (or PORT,PORT,...) and -o FILE"), ExitUsage);
    auto positive = [&](const char *name, double *v) {
        if (!p.isSet(QLatin1String(name)))
            return true;
        bool ok = false;
        *v = p.value(QLatin1String(name)).toDouble(&ok);
        if (ok && *v > 0)
            return true;
        fail(QStringLiteral("--%1 needs a positive number").arg(QLatin1String(name)), ExitUsage);
        return false;
    };
    double duration = -1, baudValue = 0, splitMb = 0, splitMinutes = 0;
    if (!positive("duration", &duration) || !positive("baud", &baudValue) || !positive("split-mb", &splitMb)
        || !positive("split-minutes", &splitMinutes))
        return ExitUsage;
    const QString path = p.value(QStringLiteral("o"));
    const QStringList specs = p.positionalArguments().front().split(QLatin1Char(','), Qt::SkipEmptyParts);
    if (specs.size() > 1) {
        if (splitMb > 0 || splitMinutes > 0)
            return fail(QStringLiteral("--split-mb and --split-minutes are for one device's capture"), ExitUsage);
        std::signal(SIGXFSZ, SIG_IGN);
        return recordGroup(specs, path, duration, int(baudValue));
    }
    // A file size limit (ulimit -f) must end the recording with a message, not kill it.
    std::signal(SIGXFSZ, SIG_IGN);

    device::DeviceSession session;
    session.setAutoReconnect(true); // a pulled cable pauses the recording; the file stays open
    QString error;
    model::DeviceIdentity id;
    int found = int(baudValue);
    if (!connectSession(session, p.positionalArguments().front(), int(baudValue), &id, &found, &error))
        return fail(error, interrupted() ? ExitInterrupted : ExitFailure);

    // The configuration snapshot: the KEY=VALUE lines of LOG COMCONFIG, when the device answers.
    record::CaptureHeader extra;
    std::optional<protocol::hipnuc::AsciiReply> reply;
    const quint64 query = session.sendCommand(protocol::hipnuc::commands::logComConfig(), 1000);
    QObject::connect(&session, &device::DeviceSession::commandFinished,
                     [&](quint64 done, const protocol::hipnuc::AsciiReply &r) {
                         if (done == query)
                             reply = r;
                     });
    waitFor([&] { return reply.has_value(); }, 3000);
    if (reply && reply->ok())
        extra.setConfig(reply->values);

    if (record::McapRecording::isMcapPath(path) && (splitMb > 0 || splitMinutes > 0))
        return fail(QStringLiteral("--split-mb and --split-minutes are for captures (.imucap), not MCAP"), ExitUsage);
    record::CaptureWriter::Options options;
    options.splitBytes = int64_t(splitMb * 1024 * 1024);
    options.splitSeconds = int64_t(splitMinutes * 60);
    bool started = false, stopped = false;
    QString stopReason;
    quint64 bytes = 0, frames = 0;
    QObject::connect(&session, &device::DeviceSession::recordingStarted, [&](const QString &) { started = true; });
    QObject::connect(&session, &device::DeviceSession::recordingStopped, [&](const QString &reason) {
        stopped = true;
        stopReason = reason;
    });
    QObject::connect(&session, &device::DeviceSession::recordingProgress, [&](quint64 b, quint64 f) {
        bytes = b;
        frames = f;
    });
    session.startRecording(path, extra, options);
    waitFor([&] { return started || stopped; }, 5000);
    if (!started)
        return fail(stopReason.isEmpty() ? QStringLiteral("recording did not start") : stopReason);
    out(QStringLiteral("recording %1 from %2 at %3 baud (Ctrl+C stops)")
            .arg(path, p.positionalArguments().front())
            .arg(found));
    QElapsedTimer clock;
    clock.start();
    waitFor([&] { return stopped; }, duration > 0 ? int(duration * 1000) : -1);
    if (!stopped) {
        session.stopRecording();
        waitFor([&] { return stopped; }, 10000);
    }
    out(QStringLiteral("recorded %1 s: %2 bytes, %3 frames to %4")
            .arg(double(clock.elapsed()) / 1000.0, 0, 'f', 1)
            .arg(bytes)
            .arg(frames)
            .arg(path));
    if (!stopReason.isEmpty())
        return fail(stopReason);
    return ExitOk;
}

} // namespace imudesk::cli
