// imudesk-cli export: a capture (or a vendor CSV or raw byte dump) to vendor CSV, tidy CSV or
// JSON Lines (docs/FILE_FORMATS.md, "CSV layouts");
// imudesk-cli import: a vendor HI91 CSV to a capture.
#include "cli_context.h"
#include "format/mcap/mcap_repair.h"
#include "record/capture_exporter.h"
#include "record/capture_source.h"
#include "record/session_exporter.h"

#include <QFileInfo>

#include <cmath>
#include <cstdio>

namespace imudesk::cli {

int cmdExport(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(QCommandLineOption(QStringLiteral("format"), QStringLiteral("vendor-csv, csv (tidy), jsonl, mcap (ROS 2 messages: PlotJuggler, Foxglove, Lichtblick) or mat (MATLAB, a struct per device in SI units)."),
                                   QStringLiteral("F"), QStringLiteral("csv")));
    p.addOption(QCommandLineOption({QStringLiteral("o"), QStringLiteral("output")},
                                   QStringLiteral("Output file (default: the capture's name with .csv / .jsonl / .mcap / .mat)."),
                                   QStringLiteral("OUT")));
    p.addOption(QCommandLineOption(QStringLiteral("from"), QStringLiteral("Start, seconds since the recording began."),
                                   QStringLiteral("S")));
    p.addOption(QCommandLineOption(QStringLiteral("to"), QStringLiteral("End, seconds since the recording began."),
                                   QStringLiteral("S")));
    p.addOption(QCommandLineOption(QStringLiteral("progress"), QStringLiteral("Print progress to stderr.")));
    p.addOption(QCommandLineOption(QStringLiteral("grid-ms"),
                                   QStringLiteral("A recorded session: resample every device onto one grid of this many ms "
                                                  "(tidy CSV)."),
                                   QStringLiteral("MS")));
    p.addOption(QCommandLineOption(QStringLiteral("pulse-hz"),
                                   QStringLiteral("A recorded session of modules triggered by one SYNC_IN pulse source "
                                                  "(LOG ... ONMARK 1) at HZ: one row per pulse, each device's frame of it."),
                                   QStringLiteral("HZ")));
    p.addPositionalArgument(QStringLiteral("FILE"),
                            QStringLiteral("A capture, a vendor HI91 CSV, a raw byte dump (recognised by content), or the "
                                           "folder of a recorded session (record PORT,PORT,...)."));
    if (!parseArgs(p, args,
                   QStringLiteral("imudesk-cli export FILE --format vendor-csv|csv|jsonl|mcap|mat [-o OUT] [--from S --to S] [--progress]\n"
                                  "       imudesk-cli export SESSION_FOLDER --format csv|jsonl|mcap|mat [-o OUT] [--grid-ms MS | --pulse-hz HZ]")))
        return ExitUsage;
    if (p.positionalArguments().size() != 1)
        return fail(QStringLiteral("export needs exactly one capture FILE"), ExitUsage);
    const auto format = record::CaptureExporter::parseFormat(p.value(QStringLiteral("format")));
    if (!format)
        return fail(QStringLiteral("unknown --format '%1' (vendor-csv, csv, jsonl, mcap or mat)").arg(p.value(QStringLiteral("format"))),
                    ExitUsage);
    record::CaptureExporter::Options o;
    o.format = *format;
    const QString input = p.positionalArguments().front();
    if (record::SessionManifest::isSessionFolder(input)) {
        record::SessionExporter::Options so;
        so.format = *format;
        so.output = p.isSet(QStringLiteral("o")) ? p.value(QStringLiteral("o"))
                                                 : input + record::CaptureExporter::extension(*format);
        if (p.isSet(QStringLiteral("grid-ms"))) {
            bool ok = false;
            so.gridMs = p.value(QStringLiteral("grid-ms")).toDouble(&ok);
            if (!ok || !std::isfinite(so.gridMs) || so.gridMs < 0.01)
                return fail(QStringLiteral("--grid-ms needs at least 0.01 ms"), ExitUsage);
        }
        if (p.isSet(QStringLiteral("pulse-hz"))) {
            bool ok = false;
            so.pulseHz = p.value(QStringLiteral("pulse-hz")).toDouble(&ok);
            if (!ok || !std::isfinite(so.pulseHz) || so.pulseHz <= 0 || so.pulseHz > 10000 || so.gridMs > 0)
                return fail(QStringLiteral("--pulse-hz needs the pulse rate in Hz (and no --grid-ms)"), ExitUsage);
        }
        if (p.isSet(QStringLiteral("from")) || p.isSet(QStringLiteral("to")))
            return fail(QStringLiteral("--from/--to are for one capture; a session exports whole"), ExitUsage);
        const auto r = record::SessionExporter::run(input, so);
        if (!r.ok)
            return fail(r.error);
        for (const QString &n : r.notes)
            std::fprintf(stderr, "imudesk-cli: note: %s\n", qPrintable(n));
        QStringList per;
        for (uint64_t n : r.samplesByDevice)
            per << QString::number(n);
        out(QStringLiteral("wrote %1").arg(so.output));
        out(QStringLiteral("%1 rows (samples per device: %2)").arg(r.rows).arg(per.join(QStringLiteral(", "))));
        if (so.pulseHz > 0)
            out(QStringLiteral("pulses: %1, with a frame of every device: %2").arg(r.pulses).arg(r.pulsesComplete));
        return ExitOk;
    }
    if (p.isSet(QStringLiteral("grid-ms")) || p.isSet(QStringLiteral("pulse-hz")))
        return fail(QStringLiteral("--grid-ms and --pulse-hz are for a recorded session's folder"), ExitUsage);
    o.output = p.value(QStringLiteral("o"));
    if (o.output.isEmpty()) {
        const QFileInfo info(input);
        o.output = info.path() + QLatin1Char('/') + info.completeBaseName() + record::CaptureExporter::extension(o.format);
    }
    if (!fromToOptions(p, &o.fromS, &o.toS))
        return ExitUsage;
    const bool showProgress = p.isSet(QStringLiteral("progress"));
    int lastPercent = -1;
    const auto r = record::CaptureExporter::run(input, o, [&](double f) {
        const int percent = int(f * 100);
        if (showProgress && percent != lastPercent) {
            std::fprintf(stderr, "\r%3d %%", percent);
            lastPercent = percent;
        }
        return !interrupted();
    });
    if (showProgress)
        std::fputs("\n", stderr);
    if (r.cancelled)
        return fail(QStringLiteral("interrupted; the partial output was removed"), ExitInterrupted);
    if (!r.ok)
        return fail(r.error);
    for (const QString &n : r.notes)
        std::fprintf(stderr, "imudesk-cli: note: %s\n", qPrintable(n));
    if (!r.warning.isEmpty())
        std::fprintf(stderr, "imudesk-cli: warning: %s\n", qPrintable(r.warning));
    for (const QString &f : r.files)
        out(QStringLiteral("wrote %1").arg(f));
    out(QStringLiteral("%1 rows%2").arg(r.frames).arg(
        r.skipped ? QStringLiteral(", %1 frames without a vendor layout (HI92, HEC495) skipped").arg(r.skipped) : QString()));
    return ExitOk;
}

} // namespace imudesk::cli

namespace imudesk::cli {

int cmdImport(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(QCommandLineOption({QStringLiteral("o"), QStringLiteral("output")},
                                   QStringLiteral("Capture file to write (default: the CSV's name with .imucap)."),
                                   QStringLiteral("OUT")));
    p.addPositionalArgument(QStringLiteral("CSV"), QStringLiteral("HI91 CSV written by the vendor's PC tool."));
    if (!parseArgs(p, args, QStringLiteral("imudesk-cli import CSV [-o OUT.imucap]")))
        return ExitUsage;
    if (p.positionalArguments().size() != 1)
        return fail(QStringLiteral("import needs exactly one CSV file"), ExitUsage);
    const QString input = p.positionalArguments().front();
    QString output = p.value(QStringLiteral("o"));
    if (output.isEmpty()) {
        const QFileInfo info(input);
        output = info.path() + QLatin1Char('/') + info.completeBaseName() + QStringLiteral(".imucap");
    }
    const auto r = record::CaptureSource::convert(input, output);
    for (const QString &note : r.notes)
        std::fprintf(stderr, "imudesk-cli: %s\n", qPrintable(note));
    if (!r.ok)
        return fail(r.error);
    if (r.kind == record::CaptureSource::Kind::VendorCsv)
        out(QStringLiteral("wrote %1: %2 frames, %3 malformed lines left out").arg(output).arg(r.import.rows).arg(r.import.badLines));
    else
        out(QStringLiteral("wrote %1: %2 bytes, %3 frames, %4 NMEA sentences").arg(output).arg(r.import.bytes).arg(r.import.frames).arg(r.import.sentences));
    return ExitOk;
}

int cmdRepair(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(QCommandLineOption({QStringLiteral("o"), QStringLiteral("output")},
                                   QStringLiteral("Write the repaired file here (default: replace FILE, once the "
                                                  "repaired copy is whole)."),
                                   QStringLiteral("OUT")));
    p.addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("An MCAP file that was not closed (a recording killed)."));
    if (!parseArgs(p, args, QStringLiteral("imudesk-cli repair FILE.mcap [-o OUT.mcap]")))
        return ExitUsage;
    if (p.positionalArguments().size() != 1)
        return fail(QStringLiteral("repair needs exactly one MCAP file"), ExitUsage);
    const QString input = p.positionalArguments().front();
    const QString output = p.isSet(QStringLiteral("o")) ? p.value(QStringLiteral("o")) : input + QStringLiteral(".repairing");
    if (QFileInfo(output).absoluteFilePath() == QFileInfo(input).absoluteFilePath())
        return fail(QStringLiteral("-o must name another file (without -o the file is replaced when the repair is done)"),
                    ExitUsage);
    const auto r = format::mcap::repairMcap(input, output);
    if (!r.ok) {
        QFile::remove(output);
        return fail(r.error);
    }
    if (!p.isSet(QStringLiteral("o"))) {
        QFile::remove(input);
        if (!QFile::rename(output, input))
            return fail(QStringLiteral("the repaired file is %1: it could not replace %2").arg(output, input));
    }
    const QString written = p.isSet(QStringLiteral("o")) ? output : input;
    out(QStringLiteral("%1 %2: %3 messages over %4 s, %5 chunks read%6")
            .arg(r.wasComplete ? QStringLiteral("rewrote (it was complete)") : QStringLiteral("repaired"), written)
            .arg(r.messages)
            .arg(r.messages ? double(r.lastTimeNs - r.firstTimeNs) / 1e9 : 0.0, 0, 'f', 3)
            .arg(r.chunksRead)
            .arg(r.bytesLeftOut ? QStringLiteral("; %1 bytes at the end (a record cut short) left out").arg(r.bytesLeftOut)
                                : QString()));
    return ExitOk;
}

} // namespace imudesk::cli
