// imudesk-cli verify: is the module right? (issue 55, core/verify/module_check.h) Its
// accelerometer, gyro and attitude judged from a recording of it turned by hand through still
// poses: a capture, a vendor CSV, a raw dump, a recorded session (one device), or a port whose
// module is recorded for --duration seconds while the operator turns it.
#include "cli_context.h"
#include "device/hec495_session.h"
#include "record/sample_file.h"
#include "verify/compass_check.h"
#include "verify/local_gravity.h"
#include "verify/motion_input.h"
#include "verify/report_json.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <cstdio>

namespace imudesk::cli {

namespace {

constexpr const char *kUsage =
    "imudesk-cli verify CAPTURE|SESSION|PORT [--gravity M_S2 | --latitude DEG --height M] [--declination DEG] "
    "[--device NAME] [--duration S] [--baud B] [--limit NAME=PASS/FAIL ...] [--json]\n"
    "       imudesk-cli verify HEC495_PORT|CAPTURE --bearings DEG,DEG,... [--address N] [--duration S] [--baud B] [--json]";

// A compass's sample: its heading and, with it, its pitch and roll.
bool compassSampleOf(const model::Sample &s, verify::CompassSample &out)
{
    if (!s.has(model::FieldHeading) || !s.has(model::FieldEuler))
        return false;
    out.tS = verify::sampleTimeS(s);
    out.headingDeg = s.headingDeg;
    out.pitchDeg = s.pitch;
    out.rollDeg = s.roll;
    return true;
}

QJsonObject compassJson(const verify::CompassReport &r, const verify::CompassCheckOptions &o, const QString &source)
{
    auto figure = [](QJsonObject &j, const QString &key, const verify::Figure &f) {
        j[key] = f.judged ? QJsonValue(f.value) : QJsonValue();
        j[key + QLatin1String("_sigma")] = f.judged ? QJsonValue(f.sigma) : QJsonValue();
        if (!f.judged)
            j[key + QLatin1String("_why")] = f.why;
    };
    QJsonObject j;
    j[QStringLiteral("source")] = source;
    QJsonArray bearings;
    for (double b : o.bearingsDeg)
        bearings.append(b);
    j[QStringLiteral("bearings_deg")] = bearings;
    j[QStringLiteral("bearings_held")] = r.bearingsHeld;
    QJsonArray stops;
    for (const verify::CompassStop &s : r.stops)
        stops.append(QJsonObject{{QStringLiteral("from_s"), s.fromS},
                                 {QStringLiteral("to_s"), s.toS},
                                 {QStringLiteral("heading_deg"), s.headingDeg},
                                 {QStringLiteral("bearing_deg"), s.bearing >= 0 ? QJsonValue(o.bearingsDeg[size_t(s.bearing)]) : QJsonValue()},
                                 {QStringLiteral("error_deg"), s.bearing >= 0 ? QJsonValue(s.errorDeg) : QJsonValue()},
                                 {QStringLiteral("pitch_deg"), s.pitchDeg},
                                 {QStringLiteral("roll_deg"), s.rollDeg}});
    j[QStringLiteral("stops")] = stops;
    figure(j, QStringLiteral("heading_error_deg"), r.worstHeadingErrDeg);
    if (r.worstHeadingErrDeg.judged)
        j[QStringLiteral("heading_error_bearing_deg")] = r.worstBearingDeg;
    figure(j, QStringLiteral("heading_offset_deg"), r.meanHeadingErrDeg);
    QJsonObject tilt;
    figure(tilt, QStringLiteral("pitch"), r.pitchErrDeg);
    figure(tilt, QStringLiteral("roll"), r.rollErrDeg);
    j[QStringLiteral("tilt_error_deg")] = tilt;
    j[QStringLiteral("verdict")] = QString::fromLatin1(verify::verdictName(r.verdict));
    j[QStringLiteral("reasons")] = QJsonArray::fromStringList(r.reasons);
    return j;
}

// The live compass: its samples for `duration` seconds (the session polls it), stops counted on stderr.
int recordCompass(const QString &port, int baud, int address, double duration, std::vector<verify::CompassSample> &out,
                  QString *source)
{
    device::Hec495Session session;
    QString failure;
    QObject::connect(&session, &device::Hec495Session::errorOccurred, &session, [&](const QString &m) { failure = m; });
    session.open(port, baud, address);
    waitFor([&] { return session.state() == device::SessionState::Connected || !failure.isEmpty(); }, 30000);
    if (session.state() != device::SessionState::Connected)
        return fail(failure.isEmpty() ? QStringLiteral("interrupted") : failure, interrupted() ? ExitInterrupted : ExitFailure);
    std::fprintf(stderr,
                 "imudesk-cli: verify: recording the compass on %s for %.0f s: turn it on a level compass rose to each "
                 "marked bearing and hold it there for 3 s; Ctrl+C ends early\n",
                 qPrintable(port), duration);
    uint64_t seq = session.store().totalAppended();
    auto drain = [&] {
        for (const auto &s : session.store().since(seq, SIZE_MAX, &seq))
            if (verify::CompassSample c; compassSampleOf(s, c) && out.size() < verify::MotionInput::kMaxSamples)
                out.push_back(c);
        return false;
    };
    waitFor([&] { return drain() || !failure.isEmpty(); }, int(duration * 1000));
    drain();
    if (!failure.isEmpty())
        std::fprintf(stderr, "imudesk-cli: verify: %s; judging what arrived before\n", qPrintable(failure));
    *source = QStringLiteral("%1 (HEC495, address %2)").arg(port).arg(address);
    return ExitOk;
}

int exitOf(verify::Verdict v)
{
    switch (v) {
    case verify::Verdict::Pass: return ExitOk;
    case verify::Verdict::Warn:
    case verify::Verdict::Fail: return ExitFailure;
    case verify::Verdict::CannotJudge: return 2;
    }
    return ExitFailure;
}

void printText(const verify::CheckReport &r, const QString &source)
{
    std::printf("%s: %zu samples, %.1f s; %zu still intervals, %d distinct poses; gravity %.5f m/s²%s\n",
                qPrintable(source), r.samples, r.durationS, r.poses.size(), r.distinctPoses,
                r.gravityG * model::kGravity, r.gravityGiven ? "" : " (assumed)");
    std::printf("verdict: %s\n", verify::verdictName(r.verdict));
    for (const QString &reason : r.reasons)
        std::printf("  %s\n", qPrintable(reason));
}

// The live case: the module's samples for `duration` seconds, poses counted on stderr as the
// operator turns it.
int recordFromPort(const QString &port, int baud, double duration, verify::MotionInput &input, QString *source)
{
    device::DeviceSession session;
    QString error;
    model::DeviceIdentity id;
    int found = baud;
    if (!connectSession(session, port, baud, &id, &found, &error))
        return fail(error, interrupted() ? ExitInterrupted : ExitFailure);
    std::fprintf(stderr,
                 "imudesk-cli: verify: recording %s for %.0f s: hold the module still for 3 s in each of at least 9 "
                 "orientations (every face up and down, then between them); Ctrl+C ends early\n",
                 qPrintable(port), duration);
    bool lost = false;
    QString lostMessage;
    QObject::connect(&session, &device::DeviceSession::errorOccurred, [&](const QString &m) {
        lost = true;
        lostMessage = m;
    });
    uint64_t seq = session.store().totalAppended();
    size_t analysedAt = 0;
    int poses = 0;
    auto drain = [&] {
        for (const auto &s : session.store().since(seq, SIZE_MAX, &seq))
            input.add(s);
        // The tally every 2 s of data: poses held so far.
        if (input.samples().size() >= analysedAt + 800) {
            analysedAt = input.samples().size();
            auto found = verify::findStillPoses(input.samples(), verify::CheckOptions{});
            const int distinct = verify::groupPoses(found, verify::CheckOptions{}.samePoseDeg);
            if (distinct != poses) {
                poses = distinct;
                std::fprintf(stderr, "imudesk-cli: verify: %d distinct still poses (9 needed)\n", poses);
            }
        }
        return input.full();
    };
    waitFor([&] { return drain() || lost; }, int(duration * 1000));
    drain();
    if (lost)
        std::fprintf(stderr, "imudesk-cli: verify: %s; judging what arrived before\n", qPrintable(lostMessage));
    *source = QStringLiteral("%1 (%2, %3 baud)").arg(port, QString::fromStdString(id.productName)).arg(found);
    return ExitOk;
}

} // namespace

int cmdVerify(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(QCommandLineOption(QStringLiteral("json"), QStringLiteral("Print the result as one JSON object.")));
    p.addOption(QCommandLineOption(QStringLiteral("gravity"),
                                   QStringLiteral("The bench's gravity in m/s² (e.g. 9.7936 from a gravity survey)."),
                                   QStringLiteral("M_S2")));
    p.addOption(QCommandLineOption(QStringLiteral("latitude"),
                                   QStringLiteral("The bench's latitude in degrees: its normal gravity (WGS 84)."),
                                   QStringLiteral("DEG")));
    p.addOption(QCommandLineOption(QStringLiteral("height"),
                                   QStringLiteral("The bench's height above the ellipsoid in m, with --latitude (default 0)."),
                                   QStringLiteral("M")));
    p.addOption(QCommandLineOption(QStringLiteral("declination"),
                                   QStringLiteral("Magnetic declination in degrees, east positive, for a module that "
                                                  "reports true heading (default 0: magnetic heading)."),
                                   QStringLiteral("DEG")));
    p.addOption(QCommandLineOption(QStringLiteral("device"),
                                   QStringLiteral("The device of a recorded session to judge."), QStringLiteral("NAME")));
    p.addOption(QCommandLineOption(QStringLiteral("duration"),
                                   QStringLiteral("PORT: seconds to record while the module is turned (default 120)."),
                                   QStringLiteral("S"), QStringLiteral("120")));
    p.addOption(QCommandLineOption(QStringLiteral("baud"), QStringLiteral("PORT: baud rate (default: detect)."),
                                   QStringLiteral("B")));
    p.addOption(QCommandLineOption(QStringLiteral("limit"),
                                   QStringLiteral("A limit of the verdict, NAME=PASS/FAIL (e.g. heading_deg=0.5/2); "
                                                  "names: %1.")
                                       .arg(verify::Limits::names().join(QStringLiteral(", "))),
                                   QStringLiteral("NAME=PASS/FAIL")));
    p.addOption(QCommandLineOption(QStringLiteral("bearings"),
                                   QStringLiteral("A compass (HEC495): the marked bearings of a level compass rose it is "
                                                  "turned to, degrees clockwise from north, comma-separated (e.g. "
                                                  "0,90,180,270)."),
                                   QStringLiteral("DEG,DEG,...")));
    p.addOption(QCommandLineOption(QStringLiteral("address"), QStringLiteral("A compass on a port: its address (default 0)."),
                                   QStringLiteral("N"), QStringLiteral("0")));
    p.addPositionalArgument(QStringLiteral("SOURCE"),
                            QStringLiteral("A capture, a vendor CSV, a raw dump, a recorded session's folder, or a "
                                           "serial port to record from."));
    if (!parseArgs(p, args, QString::fromLatin1(kUsage)))
        return ExitUsage;
    if (p.positionalArguments().size() != 1)
        return fail(QStringLiteral("verify needs exactly one CAPTURE, SESSION or PORT"), ExitUsage);

    verify::CheckOptions options;
    auto numberOption = [&p](const char *name, double lo, double hi, double *out) {
        if (!p.isSet(QLatin1String(name)))
            return true;
        bool ok = false;
        *out = p.value(QLatin1String(name)).toDouble(&ok);
        return ok && *out >= lo && *out <= hi;
    };
    if (p.isSet(QStringLiteral("gravity")) && p.isSet(QStringLiteral("latitude")))
        return fail(QStringLiteral("give either --gravity or --latitude (and --height), not both"), ExitUsage);
    if (!numberOption("gravity", 9.7, 9.9, &options.gravityMs2))
        return fail(QStringLiteral("--gravity needs m/s^2 between 9.7 and 9.9, got '%1'").arg(p.value(QStringLiteral("gravity"))),
                    ExitUsage);
    double latitude = 0, height = 0;
    if (!numberOption("latitude", -90, 90, &latitude))
        return fail(QStringLiteral("--latitude needs degrees in -90..90, got '%1'").arg(p.value(QStringLiteral("latitude"))),
                    ExitUsage);
    if (!numberOption("height", -500, 9000, &height))
        return fail(QStringLiteral("--height needs metres in -500..9000, got '%1'").arg(p.value(QStringLiteral("height"))),
                    ExitUsage);
    if (p.isSet(QStringLiteral("height")) && !p.isSet(QStringLiteral("latitude")))
        return fail(QStringLiteral("--height goes with --latitude"), ExitUsage);
    if (p.isSet(QStringLiteral("latitude")))
        options.gravityMs2 = verify::normalGravity(latitude, height);
    if (!numberOption("declination", -180, 180, &options.declinationDeg))
        return fail(QStringLiteral("--declination needs degrees in -180..180, got '%1'").arg(p.value(QStringLiteral("declination"))),
                    ExitUsage);
    for (const QString &spec : p.values(QStringLiteral("limit"))) {
        const int eq = spec.indexOf(QLatin1Char('='));
        const QStringList parts = spec.mid(eq + 1).split(QLatin1Char('/'));
        verify::Limit *limit = eq > 0 ? options.limits.byName(spec.left(eq)) : nullptr;
        bool okPass = false, okFail = false;
        const double pass = parts.size() == 2 ? parts[0].toDouble(&okPass) : 0;
        const double failAt = parts.size() == 2 ? parts[1].toDouble(&okFail) : 0;
        if (!limit || !okPass || !okFail || pass < 0 || failAt < pass)
            return fail(QStringLiteral("--limit needs NAME=PASS/FAIL with 0 <= PASS <= FAIL, NAME one of %1; got '%2'")
                            .arg(verify::Limits::names().join(QStringLiteral(", ")), spec),
                        ExitUsage);
        *limit = verify::Limit{pass, failAt};
    }

    const QString target = p.positionalArguments().front();
    verify::MotionInput input;
    QString source;
    // A serial port by its name (a pseudo-terminal too); anything else is a file or a folder.
    const QFileInfo fi(target);
    const bool isPort = !fi.isFile() && !fi.isDir()
        && (target.startsWith(QLatin1String("/dev/"))
            || QRegularExpression(QStringLiteral("^COM[0-9]+$"), QRegularExpression::CaseInsensitiveOption).match(target).hasMatch());
    if (p.isSet(QStringLiteral("bearings"))) {
        verify::CompassCheckOptions co;
        co.bearingsDeg.clear();
        for (const QString &b : p.value(QStringLiteral("bearings")).split(QLatin1Char(','), Qt::SkipEmptyParts)) {
            bool ok = false;
            const double v = b.trimmed().toDouble(&ok);
            if (!ok || v < 0 || v >= 360)
                return fail(QStringLiteral("--bearings needs degrees in 0..360 separated by commas, got '%1'").arg(b), ExitUsage);
            co.bearingsDeg.push_back(v);
        }
        if (co.bearingsDeg.size() < 2)
            return fail(QStringLiteral("--bearings needs at least two bearings (e.g. 0,90,180,270)"), ExitUsage);
        std::vector<verify::CompassSample> compass;
        if (isPort) {
            double duration = 60;
            if (!numberOption("duration", 1, 3600, &duration))
                return fail(QStringLiteral("--duration needs seconds in 1..3600"), ExitUsage);
            bool ok = false;
            const int address = p.value(QStringLiteral("address")).toInt(&ok);
            const int baud = p.isSet(QStringLiteral("baud")) ? p.value(QStringLiteral("baud")).toInt() : 0;
            if (!ok || address < 0 || address > 255)
                return fail(QStringLiteral("--address needs 0..255"), ExitUsage);
            if (const int rc = recordCompass(target, baud, address, duration, compass, &source); rc != ExitOk)
                return rc;
        } else {
            const auto opened = record::SampleFile::forEachSample(target, p.value(QStringLiteral("device")), [&](const model::Sample &s) {
                if (verify::CompassSample c; compassSampleOf(s, c) && compass.size() < verify::MotionInput::kMaxSamples)
                    compass.push_back(c);
            });
            if (!opened.ok)
                return fail(opened.error);
            source = QStringLiteral("%1 (%2)").arg(QDir::toNativeSeparators(target), opened.kind);
        }
        if (compass.empty())
            return fail(QStringLiteral("%1 gave no heading with pitch and roll: a compass (HEC495) is needed for --bearings")
                            .arg(QDir::toNativeSeparators(target)));
        if (const verify::Limit *h = options.limits.byName(QStringLiteral("heading_deg")))
            co.headingDeg = *h;
        if (const verify::Limit *t = options.limits.byName(QStringLiteral("tilt_deg")))
            co.tiltDeg = *t;
        const verify::CompassReport report = verify::checkCompass(compass, co);
        if (p.isSet(QStringLiteral("json"))) {
            outRaw(QJsonDocument(compassJson(report, co, source)).toJson(QJsonDocument::Compact).toStdString());
        } else {
            std::printf("%s: %zu samples, %zu stops, %d of %zu bearings held\n", qPrintable(source), compass.size(),
                        report.stops.size(), report.bearingsHeld, co.bearingsDeg.size());
            std::printf("verdict: %s\n", verify::verdictName(report.verdict));
            for (const QString &reason : report.reasons)
                std::printf("  %s\n", qPrintable(reason));
        }
        std::fflush(stdout);
        return exitOf(report.verdict);
    }
    if (isPort) {
        double duration = 120;
        if (!numberOption("duration", 1, 3600, &duration) || duration <= 0)
            return fail(QStringLiteral("--duration needs seconds in 1..3600"), ExitUsage);
        int baud = 0;
        if (p.isSet(QStringLiteral("baud"))) {
            bool ok = false;
            baud = p.value(QStringLiteral("baud")).toInt(&ok);
            if (!ok || baud <= 0)
                return fail(QStringLiteral("--baud needs a baud rate such as 115200"), ExitUsage);
        }
        if (const int rc = recordFromPort(target, baud, duration, input, &source); rc != ExitOk)
            return rc;
    } else {
        const auto opened = record::SampleFile::forEachSample(target, p.value(QStringLiteral("device")),
                                                              [&input](const model::Sample &s) { input.add(s); });
        if (!opened.ok)
            return fail(opened.error);
        for (const QString &note : opened.notes)
            std::fprintf(stderr, "imudesk-cli: note: %s\n", qPrintable(note));
        source = QStringLiteral("%1 (%2%3)").arg(QDir::toNativeSeparators(target), opened.kind,
                                                 opened.device.isEmpty() ? QString() : QStringLiteral(", ") + opened.device);
    }
    if (input.samples().empty())
        return fail(QStringLiteral("%1 holds no samples with both an accelerometer and a gyro: record the module's "
                                   "HI91 (or HI81, HI83) output")
                        .arg(QDir::toNativeSeparators(target)));
    if (input.passedOver() > 0)
        std::fprintf(stderr, "imudesk-cli: note: %zu %s samples without an accelerometer and a gyro passed over\n",
                     input.passedOver(), input.source().c_str());
    if (input.clockJumps() > 0)
        std::fprintf(stderr, "imudesk-cli: note: the module's clock ran backwards %zu times (a restart?); carried across\n",
                     input.clockJumps());
    source += QStringLiteral(", %1").arg(QString::fromStdString(input.source()));

    const verify::CheckReport report = verify::checkModule(input.samples(), options);
    if (p.isSet(QStringLiteral("json")))
        outRaw(QJsonDocument(verify::toJson(report, source)).toJson(QJsonDocument::Compact).toStdString());
    else
        printText(report, source);
    std::fflush(stdout);
    return exitOf(report.verdict);
}

} // namespace imudesk::cli
