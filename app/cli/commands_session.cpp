// imudesk-cli align: twist-to-align for a recorded session (issue 36 point 4). The devices on
// one fixture were turned sharply a few times; their gyro magnitudes on the common time are
// cross-correlated against a reference device's (clock::alignByTwist) and each device's offset
// is stored in session.json, where export and replay take it from.
#include "cli_context.h"
#include "clock/twist_align.h"
#include "record/capture_sample_stream.h"
#include "record/session_manifest.h"

#include <QDir>

#include <cmath>
#include <cstdio>

namespace imudesk::cli {

namespace {

// A device's |gyro| on its common time (offset not applied), within [fromNs, toNs] of the session.
clock::TwistSeries gyroSeries(const QString &path, int64_t fromNs, int64_t toNs, QString *error)
{
    clock::TwistSeries s;
    record::CaptureSampleStream stream;
    if (!stream.open(path, error))
        return s;
    while (const model::Sample *p = stream.peek()) {
        const model::Sample x = stream.take();
        (void)p;
        if (!x.has(model::FieldGyr) || x.commonTimeNs == 0 || x.commonTimeNs < fromNs || x.commonTimeNs > toNs)
            continue;
        s.timeNs.push_back(x.commonTimeNs);
        s.gyroDps.push_back(std::sqrt(x.gyr.x * x.gyr.x + x.gyr.y * x.gyr.y + x.gyr.z * x.gyr.z));
    }
    return s;
}

} // namespace

int cmdAlign(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(QCommandLineOption(QStringLiteral("reference"),
                                   QStringLiteral("The device the others are aligned to (its name in session.json; "
                                                  "default: the first with a gyroscope)."),
                                   QStringLiteral("NAME")));
    p.addOption(QCommandLineOption(QStringLiteral("from"), QStringLiteral("Start of the twists, s since the recording began."),
                                   QStringLiteral("S")));
    p.addOption(QCommandLineOption(QStringLiteral("to"), QStringLiteral("End of the twists, s since the recording began."),
                                   QStringLiteral("S")));
    p.addOption(QCommandLineOption(QStringLiteral("dry-run"), QStringLiteral("Print the offsets, do not store them.")));
    p.addPositionalArgument(QStringLiteral("FOLDER"), QStringLiteral("A recorded session (record PORT,PORT,... -o FOLDER)."));
    if (!parseArgs(p, args, QStringLiteral("imudesk-cli align FOLDER [--reference NAME] [--from S --to S] [--dry-run]")))
        return ExitUsage;
    if (p.positionalArguments().size() != 1)
        return fail(QStringLiteral("align needs the FOLDER of a recorded session"), ExitUsage);
    const QString folder = p.positionalArguments().front();
    record::SessionManifest m;
    QString error;
    if (!record::SessionManifest::load(folder, &m, &error))
        return fail(error);
    double fromS = 0, toS = 1e12;
    if (!fromToOptions(p, &fromS, &toS))
        return ExitUsage;
    const int64_t fromNs = m.startedHostNs + int64_t(fromS * 1e9), toNs = m.startedHostNs + int64_t(std::min(toS, 1e9) * 1e9);
    std::vector<clock::TwistSeries> series;
    for (const auto &d : m.devices) {
        series.push_back(gyroSeries(QDir(folder).filePath(d.file), fromNs, toNs, &error));
        if (!error.isEmpty())
            return fail(QStringLiteral("%1: %2").arg(d.name, error));
        series.back().name = d.name.toStdString();
    }
    int ref = -1;
    for (size_t i = 0; i < m.devices.size(); ++i) {
        const bool named = p.isSet(QStringLiteral("reference")) && m.devices[i].name == p.value(QStringLiteral("reference"));
        if (named || (!p.isSet(QStringLiteral("reference")) && ref < 0 && !series[i].timeNs.empty()))
            ref = int(i);
        if (named)
            break;
    }
    if (ref < 0)
        return fail(p.isSet(QStringLiteral("reference"))
                        ? QStringLiteral("no device named '%1' in the session").arg(p.value(QStringLiteral("reference")))
                        : QStringLiteral("no device of the session has gyroscope data with a common time"));
    if (series[size_t(ref)].timeNs.empty())
        return fail(QStringLiteral("the reference %1 has no gyroscope data with a common time").arg(m.devices[size_t(ref)].name));
    out(QStringLiteral("reference: %1").arg(m.devices[size_t(ref)].name));
    bool allOk = true;
    m.devices[size_t(ref)].offsetNs = 0;
    m.devices[size_t(ref)].offsetMethod = QStringLiteral("twist reference");
    for (size_t i = 0; i < m.devices.size(); ++i) {
        if (int(i) == ref)
            continue;
        auto &d = m.devices[i];
        if (series[i].timeNs.empty()) {
            out(QStringLiteral("%1: no gyroscope data with a common time; left as it was").arg(d.name));
            continue;
        }
        const clock::TwistAlignResult r = clock::alignByTwist(series[size_t(ref)], series[i]);
        if (!r.ok) {
            allOk = false;
            out(QStringLiteral("%1: not aligned: %2").arg(d.name, QString::fromStdString(r.whyNot)));
            continue;
        }
        out(QStringLiteral("%1: offset %2 ms (+- %3 ms), correlation %4, twists %5/%6")
                .arg(d.name)
                .arg(r.offsetNs / 1e6, 0, 'f', 3)
                .arg(r.uncertaintyNs / 1e6, 0, 'f', 3)
                .arg(r.correlation, 0, 'f', 4)
                .arg(r.twistsReference)
                .arg(r.twistsOther));
        d.offsetNs = r.offsetNs;
        d.offsetMethod = QStringLiteral("twist");
    }
    if (!p.isSet(QStringLiteral("dry-run"))) {
        if (!m.save(folder, &error))
            return fail(error);
        out(QStringLiteral("offsets stored in %1").arg(QDir(folder).filePath(QLatin1String(record::SessionManifest::kFileName))));
    }
    return allOk ? ExitOk : ExitFailure;
}

} // namespace imudesk::cli
