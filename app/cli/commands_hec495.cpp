// imudesk-cli commands for the Witlink HEC495 compass: "hec495 PORT ACTION", the family
// detection behind "probe", and "simulate --device hec495".
#include "cli_context.h"
#include "operator_input.h"
#include "device/hec495_session.h"
#include "protocol/nmea/nmea_sample.h"
#include "sim/hec495_simulator.h"
#include "sim/pty_simulator.h"

#include <QElapsedTimer>
#include <QJsonArray>

#include <cmath>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>


#include <memory>
#include <optional>

namespace imudesk::cli {

namespace {

namespace wl = protocol::witlink;
using device::Hec495Result;
using device::Hec495Session;

const QString kUsage = QStringLiteral(
    "imudesk-cli hec495 PORT [--baud B] [--address N] [--json] ACTION\n"
    "  ACTION: read [--count N] | angle pitch|roll|heading|all | nmea [--count N] | info | declination [VALUE]\n"
    "          | baud B | rate HZ | content default|internal|all|nmea | address N | save | reset\n"
    "          | calibrate auto12|all|small-tilt|planar [--save] [--timeout S]\n"
    "          | calibrate manual [--auto-interval S] [--save] [--timeout S]\n"
    "  calibrate asks on stdin before it saves (0x09); --save saves without asking (scripts).");

void printJson(const QJsonObject &o)
{
    out(QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact)));
}

QJsonObject recordJson(const wl::AllDataRecord &r)
{
    auto arr = [](const std::array<float, 3> &v) { return QJsonArray{double(v[0]), double(v[1]), double(v[2])}; };
    QJsonObject o;
    o[QStringLiteral("pitch")] = double(r.pitch);
    o[QStringLiteral("roll")] = double(r.roll);
    o[QStringLiteral("heading")] = double(r.heading);
    o[QStringLiteral("acc")] = arr(r.acc);
    o[QStringLiteral("mag")] = arr(r.mag);
    o[QStringLiteral("gyr")] = arr(r.gyr);
    o[QStringLiteral("mag_roll")] = double(r.magRoll);
    o[QStringLiteral("time_ms")] = double(r.timeMs);
    return o;
}

// Sends one request and waits for its result (the session retries by itself).
std::optional<Hec495Result> await(Hec495Session &s, quint64 id)
{
    std::optional<Hec495Result> result;
    QObject ctx;
    QObject::connect(&s, &Hec495Session::commandFinished, &ctx, [&](quint64 done, const Hec495Result &r) {
        if (done == id)
            result = r;
    });
    waitFor([&] { return result.has_value(); }, 15000);
    return result;
}

// Prints a finished request; returns the exit code.
int report(const std::optional<Hec495Result> &r, bool json, const QString &action, QJsonObject extra = {})
{
    if (!r)
        return fail(QStringLiteral("interrupted"), ExitInterrupted);
    if (!r->ok())
        return fail(QStringLiteral("%1: %2").arg(action, r->message));
    if (json) {
        extra[QStringLiteral("action")] = action;
        extra[QStringLiteral("status")] = QStringLiteral("ok");
        extra[QStringLiteral("attempts")] = r->attempts;
        printJson(extra);
    } else {
        out(r->message);
    }
    return ExitOk;
}

// A line for the operator on stderr (stdout stays the command's output).
void note(const QString &line)
{
    std::fprintf(stderr, "%s\n", qPrintable(line));
    std::fflush(stderr);
}

// 0x09: the module fits and saves what it collected; prints the fit error and points.
int saveCalibration(Hec495Session &s, const QString &methodName, int points, bool json)
{
    const auto saved = await(s, s.saveCalibration());
    if (!saved || !saved->ok())
        return fail(QStringLiteral("calibration not saved after %1 points: %2")
                        .arg(points)
                        .arg(saved ? saved->message : QStringLiteral("interrupted")));
    QJsonObject o;
    o[QStringLiteral("method")] = methodName;
    o[QStringLiteral("fit_error")] = double(saved->reply.fitError);
    o[QStringLiteral("points")] = saved->reply.points;
    if (saved->reply.fitError > 10.0f && !json)
        out(QStringLiteral("the fit error is above 10: calibrate again (the manual's advice)"));
    return report(saved, json, QStringLiteral("calibrate"), o);
}

// The manual method (0x67 per point) paced by the operator: a prompt per point, Enter collects
// it; "f" finishes once the minimum is reached, "q" stops without saving. --auto-interval S
// collects every S seconds instead (scripts). The calibration is saved (0x09) only with --save
// or the operator's yes; otherwise it is stopped (0x12) and the old one stays.
int calibrateManual(Hec495Session &s, double autoIntervalS, bool saveWithoutAsking, int timeoutS, bool json)
{
    const int minimum = sim::Hec495Calibration::minimumPoints(wl::CalibrationMethod::Manual);
    const auto started = await(s, s.startCalibration(wl::CalibrationMethod::Manual));
    if (!started || !started->ok())
        return report(started, json, QStringLiteral("calibrate"));
    OperatorInput input;
    int points = 0;
    const auto collect = [&]() -> bool {
        const auto r = await(s, s.collectCalibrationPoint());
        if (!r || !r->ok()) {
            note(QStringLiteral("point not collected: %1").arg(r ? r->message : QStringLiteral("interrupted")));
            return false;
        }
        points = r->reply.points;
        if (!json)
            out(QStringLiteral("point %1").arg(points));
        return true;
    };
    const auto stop = [&](const QString &why, int code) {
        await(s, s.stopCalibration());
        return fail(QStringLiteral("%1; calibration stopped, nothing saved (the previous calibration stays)").arg(why),
                    code);
    };
    if (autoIntervalS > 0) {
        QElapsedTimer t;
        t.start();
        while (points < minimum && t.elapsed() < qint64(timeoutS) * 1000 && !interrupted()) {
            collect();
            waitFor([] { return false; }, int(autoIntervalS * 1000));
        }
    } else {
        bool finished = false;
        while (!finished && !interrupted()) {
            std::fprintf(stderr,
                         "point %d: turn the compass to a new orientation and hold it still, then press Enter "
                         "(f + Enter to finish%s, q + Enter to stop)\n",
                         points + 1, points < minimum ? qPrintable(QStringLiteral(" after %1 points").arg(minimum)) : "");
            std::fflush(stderr);
            const auto l = input.line();
            if (!l || *l == QLatin1String("f")) {
                if (points >= minimum)
                    finished = true;
                else if (!l)
                    return stop(QStringLiteral("the input ended after %1 of at least %2 points (pace the points "
                                               "with Enter, or give --auto-interval S)")
                                    .arg(points)
                                    .arg(minimum),
                                ExitFailure);
                else
                    note(QStringLiteral("at least %1 points are needed; %2 so far").arg(minimum).arg(points));
            } else if (*l == QLatin1String("q")) {
                return stop(QStringLiteral("stopped by the operator after %1 points").arg(points), ExitFailure);
            } else {
                collect();
            }
        }
    }
    if (interrupted())
        return stop(QStringLiteral("interrupted"), ExitInterrupted);
    if (points < minimum)
        return stop(QStringLiteral("%1 of at least %2 points within %3 s").arg(points).arg(minimum).arg(timeoutS),
                    ExitFailure);
    if (!saveWithoutAsking
        && !input.confirm(QStringLiteral("%1 points collected. Save this calibration to the compass?").arg(points)))
        return stop(QStringLiteral("not confirmed (answer y, or give --save)"), ExitFailure);
    return saveCalibration(s, QStringLiteral("manual"), points, json);
}

// An automatic method (0x63, 0x08, 0x64, 0x60): the module collects by itself; at the end the
// calibration is saved (0x09) only with --save or the operator's yes, as the manual method's;
// otherwise it is stopped (0x12) and the old one stays.
int calibrate(Hec495Session &s, const QString &methodName, bool saveWithoutAsking, int timeoutS, bool json)
{
    wl::CalibrationMethod method;
    if (!wl::commands::parseCalibrationMethod(methodName.toStdString(), method))
        return fail(QStringLiteral("unknown calibration method '%1' (auto12, manual, all, small-tilt, planar)")
                        .arg(methodName),
                    ExitUsage);
    int points = 0;
    QObject ctx;
    QObject::connect(&s, &Hec495Session::calibrationPoint, &ctx, [&](int n) {
        points = n;
        if (!json)
            out(QStringLiteral("point %1").arg(n));
    });
    const auto started = await(s, s.startCalibration(method));
    if (!started || !started->ok())
        return report(started, json, QStringLiteral("calibrate"));
    // Automatic methods collect by themselves (12 at most, 96 for "all").
    const int target = method == wl::CalibrationMethod::AllOrientation ? sim::Hec495Calibration::kMaxPoints : 12;
    QElapsedTimer t;
    t.start();
    while (points < target && t.elapsed() < qint64(timeoutS) * 1000 && !interrupted())
        waitFor([&] { return points >= target; }, 250);
    const auto stop = [&](const QString &why, int code) {
        await(s, s.stopCalibration());
        return fail(QStringLiteral("%1; calibration stopped, nothing saved (the previous calibration stays)").arg(why),
                    code);
    };
    if (interrupted())
        return stop(QStringLiteral("interrupted"), ExitInterrupted);
    if (!saveWithoutAsking) {
        OperatorInput input;
        if (!input.confirm(QStringLiteral("%1 points collected. Save this calibration to the compass?").arg(points)))
            return stop(QStringLiteral("not confirmed (answer y, or give --save)"), ExitFailure);
    }
    return saveCalibration(s, methodName, points, json);
}

} // namespace

void printHec495Probe(const QString &port, int baud, int address, bool json)
{
    if (json) {
        QJsonObject o;
        o[QStringLiteral("port")] = port;
        o[QStringLiteral("baud")] = baud;
        o[QStringLiteral("family")] = QStringLiteral("hec495");
        o[QStringLiteral("product")] = QStringLiteral("HEC495");
        o[QStringLiteral("address")] = address;
        o[QStringLiteral("identified")] = true;
        printJson(o);
    } else {
        out(QStringLiteral("port: %1").arg(port));
        out(QStringLiteral("baud: %1").arg(baud));
        out(QStringLiteral("family: hec495"));
        out(QStringLiteral("product: HEC495"));
        out(QStringLiteral("address: %1").arg(address));
    }
}

int simulateHec495(const QCommandLineParser &p)
{
    sim::Hec495Options o;
    bool ok = true;
    if (p.isSet(QStringLiteral("baud"))) {
        o.baud = p.value(QStringLiteral("baud")).toInt(&ok);
        if (!ok || !wl::commands::baudCode(o.baud))
            return fail(QStringLiteral("--baud must be one of 2400 4800 9600 19200 115200 for the HEC495"), ExitUsage);
    }
    const int address = p.value(QStringLiteral("address")).toInt(&ok, 0);
    if (!ok || address < 0 || address > 255)
        return fail(QStringLiteral("--address must be 0 to 255"), ExitUsage);
    o.address = uint8_t(address);
    if (!sim::parseMotion(p.value(QStringLiteral("motion")).toStdString(), o.motion))
        return fail(QStringLiteral("--motion must be static, spin, tumble or bearings (turned to the 8 marks of a compass rose)"), ExitUsage);
    o.seed = p.value(QStringLiteral("seed")).toULongLong(&ok);
    if (!ok)
        return fail(QStringLiteral("--seed needs a whole number"), ExitUsage);
    // The compass's faults: calibrated before (its hard iron corrected), a heading off by DEG.
    for (const QString &item : p.value(QStringLiteral("faults")).split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QString word = item.section(QLatin1Char('='), 0, 0).trimmed().toLower();
        if (word == QLatin1String("calibrated") && !item.contains(QLatin1Char('='))) {
            o.calibrated = true;
        } else if (word == QLatin1String("heading-bias")) {
            o.headingBiasDeg = item.section(QLatin1Char('='), 1).toDouble(&ok);
            if (!ok || std::fabs(o.headingBiasDeg) > 180)
                return fail(QStringLiteral("heading-bias=DEG needs degrees in -180..180, got '%1'").arg(item), ExitUsage);
        } else {
            return fail(QStringLiteral("unknown HEC495 fault '%1' (accepted: calibrated, heading-bias=DEG)").arg(item),
                        ExitUsage);
        }
    }
    sim::PtySimulator simulator(std::make_unique<sim::Hec495Simulator>(o));
    QString error;
    if (!simulator.start(&error))
        return fail(QStringLiteral("could not create a pseudo-terminal: %1").arg(error));
    out(QStringLiteral("pty: %1").arg(simulator.devicePath()));
    waitFor([] { return false; }, -1); // until SIGINT/SIGTERM
    simulator.stop();
    return ExitOk;
}

int cmdHec495(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(QCommandLineOption(QStringLiteral("baud"), QStringLiteral("Baud rate (default: detect)."),
                                   QStringLiteral("B")));
    p.addOption(QCommandLineOption(QStringLiteral("address"), QStringLiteral("Module address (default 0)."),
                                   QStringLiteral("N"), QStringLiteral("0")));
    p.addOption(QCommandLineOption(QStringLiteral("json"), QStringLiteral("Machine-readable JSON output.")));
    p.addOption(QCommandLineOption(QStringLiteral("count"), QStringLiteral("read, nmea: records or sentences to print (default 1)."),
                                   QStringLiteral("N"), QStringLiteral("1")));
    p.addOption(QCommandLineOption(QStringLiteral("timeout"),
                                   QStringLiteral("calibrate: seconds to collect points (default 30)."),
                                   QStringLiteral("S"), QStringLiteral("30")));
    p.addOption(QCommandLineOption(QStringLiteral("auto-interval"),
                                   QStringLiteral("calibrate manual: collect a point every S seconds instead of on "
                                                  "the operator's Enter (scripts)."),
                                   QStringLiteral("S")));
    p.addOption(QCommandLineOption(QStringLiteral("save"),
                                   QStringLiteral("calibrate: save the calibration without asking.")));
    p.addPositionalArgument(QStringLiteral("PORT"), QStringLiteral("Serial port"));
    p.addPositionalArgument(QStringLiteral("ACTION"), QStringLiteral("What to do (see usage)"));
    // A negative value ("declination -3.2") is an argument, not an option.
    static const QRegularExpression negative(QStringLiteral("^-[0-9][0-9.]*$"));
    static const QString kNegative = QStringLiteral("\x01");
    QStringList cooked = args;
    for (auto &a : cooked)
        if (negative.match(a).hasMatch())
            a = kNegative + a.mid(1);
    if (!parseArgs(p, cooked, kUsage))
        return ExitUsage;
    QStringList pos = p.positionalArguments();
    for (auto &a : pos)
        if (a.startsWith(kNegative))
            a = QLatin1Char('-') + a.mid(kNegative.size());
    if (pos.size() < 2)
        return fail(QStringLiteral("hec495 needs PORT and an ACTION (usage: %1)").arg(kUsage), ExitUsage);
    const QString port = pos.at(0), action = pos.at(1);
    const QStringList rest = pos.mid(2);
    bool ok = true;
    int baud = 0;
    if (p.isSet(QStringLiteral("baud"))) {
        baud = p.value(QStringLiteral("baud")).toInt(&ok);
        if (!ok || !wl::commands::baudCode(baud))
            return fail(QStringLiteral("--baud must be one of 2400 4800 9600 19200 115200"), ExitUsage);
    }
    const int address = p.value(QStringLiteral("address")).toInt(&ok, 0);
    if (!ok || address < 0 || address > 255)
        return fail(QStringLiteral("--address must be 0 to 255"), ExitUsage);
    const bool json = p.isSet(QStringLiteral("json"));
    static const QMap<QString, int> kArgs = {{"read", 0}, {"angle", 1}, {"nmea", 0}, {"info", 0}, {"declination", -1}, {"baud", 1},
                                             {"rate", 1}, {"content", 1}, {"address", 1},    {"save", 0},
                                             {"reset", 0}, {"calibrate", 1}};
    if (!kArgs.contains(action))
        return fail(QStringLiteral("unknown action '%1' (usage: %2)").arg(action, kUsage), ExitUsage);
    const int want = kArgs.value(action);
    if ((want >= 0 && rest.size() != want) || (want < 0 && rest.size() > 1))
        return fail(QStringLiteral("wrong number of arguments for '%1' (usage: %2)").arg(action, kUsage), ExitUsage);

    if (p.isSet(QStringLiteral("auto-interval"))
        && !(action == QLatin1String("calibrate") && rest.value(0) == QLatin1String("manual")))
        return fail(QStringLiteral("--auto-interval is for 'calibrate manual' (the other methods collect by themselves)"),
                    ExitUsage);
    if (p.isSet(QStringLiteral("save")) && action != QLatin1String("calibrate"))
        return fail(QStringLiteral("--save is for 'calibrate' (save the calibration without asking)"), ExitUsage);
    Hec495Session s;
    s.setPollingRate(0); // only the requests asked for
    QString failure;
    QObject::connect(&s, &Hec495Session::errorOccurred, &s, [&](const QString &m) { failure = m; });
    s.open(port, baud, address);
    waitFor([&] { return s.state() == device::SessionState::Connected || !failure.isEmpty(); }, 30000);
    if (s.state() != device::SessionState::Connected)
        return fail(failure.isEmpty() ? QStringLiteral("interrupted") : failure,
                    interrupted() ? ExitInterrupted : ExitFailure);
    const QString arg = rest.value(0);

    if (action == QLatin1String("read")) {
        const int count = p.value(QStringLiteral("count")).toInt(&ok);
        if (!ok || count <= 0)
            return fail(QStringLiteral("--count needs a positive number"), ExitUsage);
        for (int i = 0; i < count; ++i) {
            const auto r = await(s, s.readAll());
            if (!r || !r->ok())
                return report(r, json, action);
            const auto &rec = r->reply.record;
            if (json)
                printJson(recordJson(rec));
            else
                out(QStringLiteral("pitch %1 roll %2 heading %3 deg, acc [%4 %5 %6] g, gyr [%7 %8 %9] deg/s, t=%10 ms")
                        .arg(double(rec.pitch), 0, 'f', 2).arg(double(rec.roll), 0, 'f', 2)
                        .arg(double(rec.heading), 0, 'f', 2).arg(double(rec.acc[0]), 0, 'f', 3)
                        .arg(double(rec.acc[1]), 0, 'f', 3).arg(double(rec.acc[2]), 0, 'f', 3)
                        .arg(double(rec.gyr[0]), 0, 'f', 2).arg(double(rec.gyr[1]), 0, 'f', 2)
                        .arg(double(rec.gyr[2]), 0, 'f', 2).arg(rec.timeMs));
        }
        return ExitOk;
    }
    if (action == QLatin1String("angle")) {
        // The single reads of 2.1-2.4: pitch, roll, heading, or the three at once.
        static const QMap<QString, wl::Command> kAngles = {{QStringLiteral("pitch"), wl::Command::ReadPitch},
                                                           {QStringLiteral("roll"), wl::Command::ReadRoll},
                                                           {QStringLiteral("heading"), wl::Command::ReadHeading},
                                                           {QStringLiteral("all"), wl::Command::ReadAngles}};
        if (!kAngles.contains(arg))
            return fail(QStringLiteral("angle takes pitch, roll, heading or all"), ExitUsage);
        const auto r = await(s, s.request(kAngles.value(arg)));
        QJsonObject o;
        if (r && r->ok()) {
            if (r->reply.kind == wl::Reply::Kind::Angles) {
                o[QStringLiteral("pitch")] = r->reply.pitch;
                o[QStringLiteral("roll")] = r->reply.roll;
                o[QStringLiteral("heading")] = r->reply.heading;
            } else {
                o[arg] = r->reply.angle;
            }
        }
        return report(r, json, action, o);
    }
    if (action == QLatin1String("nmea")) {
        // The sentences of output content NMEA 0183 ("content nmea", then "rate HZ"), as they
        // arrive; --json adds the heading of the ones that carry it.
        const int count = p.value(QStringLiteral("count")).toInt(&ok);
        if (!ok || count <= 0)
            return fail(QStringLiteral("--count needs a positive number"), ExitUsage);
        int seen = 0;
        QObject::connect(&s, &Hec495Session::nmeaReceived, &s, [&](const QString &sentence) {
            if (seen >= count)
                return;
            ++seen;
            if (!json) {
                out(sentence);
                return;
            }
            QJsonObject o{{QStringLiteral("sentence"), sentence}};
            if (auto sample = protocol::nmea::sampleOf(sentence.toStdString()); sample && sample->has(model::FieldHeading))
                o[sample->headingTrue ? QStringLiteral("heading_true") : QStringLiteral("heading_magnetic")] =
                    sample->headingDeg;
            printJson(o);
        });
        waitFor([&] { return seen >= count || !failure.isEmpty(); }, 5000 + 1000 * count);
        if (seen < count)
            return fail(failure.isEmpty() ? QStringLiteral("%1 of %2 NMEA sentences arrived: set the output content to "
                                                           "NMEA (content nmea) and an output rate (rate HZ)")
                                                .arg(seen)
                                                .arg(count)
                                          : failure,
                        interrupted() ? ExitInterrupted : ExitFailure);
        return ExitOk;
    }
    if (action == QLatin1String("info")) {
        const auto q = await(s, s.queryAddress());
        const auto d = await(s, s.readDeclination());
        if (!q || !q->ok())
            return report(q, json, action);
        if (!d || !d->ok())
            return report(d, json, action);
        QJsonObject o;
        o[QStringLiteral("product")] = QStringLiteral("HEC495");
        o[QStringLiteral("family")] = QStringLiteral("hec495");
        o[QStringLiteral("port")] = port;
        o[QStringLiteral("baud")] = s.baud();
        o[QStringLiteral("address")] = int(q->reply.deviceAddress);
        o[QStringLiteral("declination")] = d->reply.declination;
        o[QStringLiteral("streaming")] = s.streaming();
        if (json) {
            printJson(o);
        } else {
            for (auto it = o.begin(); it != o.end(); ++it)
                out(QStringLiteral("%1: %2").arg(it.key(), it.value().toVariant().toString()));
        }
        return ExitOk;
    }
    if (action == QLatin1String("declination")) {
        if (rest.isEmpty()) {
            const auto r = await(s, s.readDeclination());
            QJsonObject o;
            if (r && r->ok())
                o[QStringLiteral("declination")] = r->reply.declination;
            return report(r, json, action, o);
        }
        const double v = arg.toDouble(&ok);
        if (!ok)
            return fail(QStringLiteral("the declination must be a number of degrees"), ExitUsage);
        return report(await(s, s.setDeclination(v)), json, action, {{QStringLiteral("declination"), v}});
    }
    if (action == QLatin1String("baud")) {
        const int b = arg.toInt(&ok);
        if (!ok)
            return fail(QStringLiteral("the baud must be a number"), ExitUsage);
        return report(await(s, s.setBaud(b)), json, action, {{QStringLiteral("baud"), b}});
    }
    if (action == QLatin1String("rate")) {
        const int hz = arg.toInt(&ok);
        if (!ok)
            return fail(QStringLiteral("the rate must be a number of Hz (0 = question/answer)"), ExitUsage);
        return report(await(s, s.setOutputRate(hz)), json, action, {{QStringLiteral("rate_hz"), hz}});
    }
    if (action == QLatin1String("content")) {
        wl::OutputContent c;
        if (!wl::commands::parseOutputContent(arg.toStdString(), c))
            return fail(QStringLiteral("content must be default, internal, all or nmea"), ExitUsage);
        return report(await(s, s.setOutputContent(c)), json, action, {{QStringLiteral("content"), arg}});
    }
    if (action == QLatin1String("address")) {
        const int a = arg.toInt(&ok, 0);
        if (!ok)
            return fail(QStringLiteral("the address must be a number"), ExitUsage);
        return report(await(s, s.setAddress(a)), json, action, {{QStringLiteral("address"), a}});
    }
    if (action == QLatin1String("save"))
        return report(await(s, s.saveSettings()), json, action);
    if (action == QLatin1String("reset"))
        return report(await(s, s.factoryReset()), json, action);
    // calibrate
    const int timeoutS = p.value(QStringLiteral("timeout")).toInt(&ok);
    if (!ok || timeoutS <= 0)
        return fail(QStringLiteral("--timeout needs a positive number of seconds"), ExitUsage);
    if (arg == QLatin1String("manual")) {
        double interval = 0;
        if (p.isSet(QStringLiteral("auto-interval"))) {
            interval = p.value(QStringLiteral("auto-interval")).toDouble(&ok);
            if (!ok || interval < 0.1 || interval > 60)
                return fail(QStringLiteral("--auto-interval needs 0.1 to 60 seconds"), ExitUsage);
        }
        return calibrateManual(s, interval, p.isSet(QStringLiteral("save")), timeoutS, json);
    }
    return calibrate(s, arg, p.isSet(QStringLiteral("save")), timeoutS, json);
}

} // namespace imudesk::cli
