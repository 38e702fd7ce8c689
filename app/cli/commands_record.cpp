// imudesk-cli record: every byte a device sends, to a capture file (README, "Capture file format").
#include "cli_context.h"
#include "protocol/hipnuc/ascii_command.h"
#include "record/capture_header.h"

#include <QFileInfo>

#include <csignal>
#include <optional>

namespace imudesk::cli {

int cmdRecord(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(QCommandLineOption({QStringLiteral("o"), QStringLiteral("output")},
                                   QStringLiteral("Capture file to write (e.g. run.imucap)."), QStringLiteral("FILE")));
    p.addOption(QCommandLineOption(QStringLiteral("duration"),
                                   QStringLiteral("Seconds to record (default: until Ctrl+C)."), QStringLiteral("S")));
    p.addOption(QCommandLineOption(QStringLiteral("baud"), QStringLiteral("Baud rate (default: auto-detect)."),
                                   QStringLiteral("B")));
    p.addOption(QCommandLineOption(QStringLiteral("split-mb"),
                                   QStringLiteral("Start a new file every N MB (name-001.imucap, ...)."),
                                   QStringLiteral("N")));
    p.addOption(QCommandLineOption(QStringLiteral("split-minutes"),
                                   QStringLiteral("Start a new file every N minutes."), QStringLiteral("N")));
    p.addPositionalArgument(QStringLiteral("PORT"), QStringLiteral("Serial port"));
    const QString usage =
        QStringLiteral("imudesk-cli record PORT -o FILE [--duration S] [--baud B] [--split-mb N] [--split-minutes N]");
    if (!parseArgs(p, args, usage))
        return ExitUsage;
    if (p.positionalArguments().size() != 1 || !p.isSet(QStringLiteral("o")))
        return fail(QStringLiteral("record needs one PORT and -o FILE"), ExitUsage);
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
