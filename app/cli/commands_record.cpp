// imudesk-cli record: every byte a device sends, to a capture file (docs/FILE_FORMATS.md, "Capture file format").
#include "cli_context.h"
#include "file_size_limit.h"
#include "device_links.h"
#include "record/group_recording.h"
#include "links/link_opener.h"
#include "protocol/can/can_decoder.h"
#include "protocol/hipnuc/ascii_command.h"
#include "record/mcap_recorder.h"
#include "capture/mcap_recording.h"
#include "capture/capture_header.h"
#include "record/recording.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>

#include <memory>
#include <vector>

#include <cstdio>
#include <cstring>
#include <optional>

namespace imudesk::cli {

namespace {

// record PORT,PORT,... -o FOLDER: every device into one session folder (record/group_recording.h).
int recordGroup(const QStringList &specs, const QString &folder, double duration, int baud)
{
    std::vector<OpenDevice> devices;
    if (const int code = openDevices(specs, baud, devices); code != ExitOk)
        return code;
    std::vector<device::GroupRecording::Member> members;
    for (OpenDevice &d : devices) {
        auto *session = qobject_cast<device::Session *>(d.link.link.get());
        if (!session)
            return fail(QStringLiteral("%1: this link cannot be recorded").arg(d.spec));
        // Named for the file and the manifest by GroupRecording (capture::deviceName), not by its port.
        members.push_back({session, QString(), d.spec, d.identity});
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
    for (OpenDevice &d : devices)
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

// record PORT,PORT,... -o run.mcap: every device's samples into one MCAP file
// (record/mcap_recorder.h: each session hands its samples to the recorder's tap for it).
int recordGroupMcap(const QStringList &specs, const QString &path, double duration, int baud)
{
    std::vector<OpenDevice> devices;
    if (const int code = openDevices(specs, baud, devices); code != ExitOk)
        return code;
    std::vector<record::McapRecorder::Device> members;
    for (OpenDevice &d : devices) { // named by capture::deviceName: its serial number, else family and address
        if (!qobject_cast<device::Session *>(d.link.link.get()))
            return fail(QStringLiteral("%1: this link cannot be recorded").arg(d.spec));
        members.push_back({headerOf(d), std::string()});
    }
    record::McapRecorder recording;
    QString error;
    if (!recording.start(path, members, &error))
        return fail(error);
    for (size_t i = 0; i < devices.size(); ++i)
        static_cast<device::Session *>(devices[i].link.link.get())->startRecording(path, recording.tap(i));
    out(QStringLiteral("recording %1 devices to %2 (Ctrl+C stops)").arg(devices.size()).arg(path));
    QElapsedTimer clock;
    clock.start();
    waitFor([&] { return !recording.error().isEmpty(); }, duration > 0 ? int(duration * 1000) : -1);
    for (OpenDevice &d : devices)
        d.link.link->close(); // the sessions let go of their taps before the file is closed
    const QString why = recording.stop();
    const std::vector<uint64_t> written = recording.samples();
    out(QStringLiteral("recorded %1 s into %2: %3 bytes, %4 samples missed")
            .arg(double(clock.elapsed()) / 1000.0, 0, 'f', 1)
            .arg(path)
            .arg(recording.bytesWritten())
            .arg(recording.missed()));
    for (size_t i = 0; i < devices.size(); ++i)
        out(QStringLiteral("  %1: %2 samples").arg(devices[i].spec).arg(written[i]));
    return why.isEmpty() ? ExitOk : fail(why);
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
                                           "-o names (or, for a name ending in .mcap, into one MCAP file) (a port may be PORT:BAUD, modbus:PORT[@ID], modbus-hec495:PORT[@ID] or "
                                           "can:PLUGIN:INTERFACE[:PROTOCOL])"));
    const QString usage = QStringLiteral("imudesk-cli record PORT -o FILE [--duration S] [--baud B] [--split-mb N] "
                                         "[--split-minutes N]\n       imudesk-cli record PORT,PORT[,...] -o FOLDER|FILE.mcap "
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
        outliveFileSizeLimit();
        if (capture::McapRecording::isMcapPath(path))
            return recordGroupMcap(specs, path, duration, int(baudValue));
        return recordGroup(specs, path, duration, int(baudValue));
    }
    // A file size limit (ulimit -f) must end the recording with a message, not kill it.
    outliveFileSizeLimit();

    device::DeviceSession session;
    session.setAutoReconnect(true); // a pulled cable pauses the recording; the file stays open
    QString error;
    model::DeviceIdentity id;
    int found = int(baudValue);
    if (!connectSession(session, p.positionalArguments().front(), int(baudValue), &id, &found, &error))
        return fail(error, interrupted() ? ExitInterrupted : ExitFailure);

    // The configuration snapshot: the KEY=VALUE lines of LOG COMCONFIG, when the device answers.
    capture::CaptureHeader extra;
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

    if (capture::McapRecording::isMcapPath(path) && (splitMb > 0 || splitMinutes > 0))
        return fail(QStringLiteral("--split-mb and --split-minutes are for captures (.imucap), not MCAP"), ExitUsage);
    capture::CaptureWriter::Options options;
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
    record::startRecording(session, path, extra, options);
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
