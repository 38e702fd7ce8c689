// imudesk-cli calibrate PORT ACTION: the device-side calibrations of the GUI's wizards, driven
// by the same core procedures, for scripts on a bench.
//   mag            CONFIG MCAL START, STAT/PROGRESS polled (calib::MagCalSession), then the
//                  wizard's heading check (calib::HeadingCheck) unless --no-heading-check
//   heading-check  the heading check alone: one level turn, the heading followed
//   gyro-scale     CONFIG USRCAL START <ANGLE>, the turn followed on the samples
//                  (calib::GyroScaleRun), CONFIG USRCAL STOP once the module stopped
//                  (calib::GyroCalSession); the device's OK/ERR is the verdict
//   level          CONFIG ATT RST 3 (auto level) on a still, nearly level module
//   heading-reset  CONFIG ATT RST 1 on a still module (firmware 1.7.1)
//   hec495-clear   the HEC495's "clear calibration" (0x10)
// Progress goes to stderr, the result to stdout (--json: one object); the exit code is 0 only
// when the calibration passed.
#include "calib/gyro_cal_session.h"
#include "calib/gyro_scale_run.h"
#include "calib/heading_check.h"
#include "calib/mag_cal_session.h"
#include "cli_context.h"
#include "device/hec495_session.h"
#include "protocol/hipnuc/ascii_command.h"
#include "protocol/hipnuc/ascii_reply.h"

#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <cstdio>

namespace imudesk::cli {

namespace {

const QString kUsage = QStringLiteral(
    "imudesk-cli calibrate PORT mag|heading-check|gyro-scale|level|heading-reset|hec495-clear [--baud B] [--json]\n"
    "  mag [--timeout S] [--heading-timeout S] [--no-heading-check]\n"
    "                                   turn the module through every direction until the device reports success,\n"
    "                                   then turn it level one full turn: the heading must follow without a jump\n"
    "                                   above 10 deg (the wizard's heading check)\n"
    "  heading-check [--heading-timeout S]  the heading check alone\n"
    "  gyro-scale [--angle DEG] [--timeout S]  turn the module DEG (720..1800) about its Z axis at 20..100 deg/s,\n"
    "                                   then hold it still\n"
    "  level | heading-reset            keep the module still (level: within 5 deg of level or upside down)\n"
    "  hec495-clear [--address N]       clear the HEC495's calibration");

void progress(const QString &line)
{
    std::fprintf(stderr, "%s\n", line.toLocal8Bit().constData());
    std::fflush(stderr);
}

struct Outcome {
    bool passed = false;
    QString message;
    QJsonObject details;
};

int finish(const QString &action, const Outcome &o, bool json)
{
    if (json) {
        QJsonObject j = o.details;
        j[QStringLiteral("action")] = action;
        j[QStringLiteral("verdict")] = o.passed ? QStringLiteral("pass") : QStringLiteral("fail");
        j[QStringLiteral("message")] = o.message;
        out(QString::fromUtf8(QJsonDocument(j).toJson(QJsonDocument::Compact)));
    } else {
        out(QStringLiteral("%1: %2: %3").arg(action, o.passed ? QStringLiteral("pass") : QStringLiteral("fail"),
                                              o.message));
    }
    if (interrupted())
        return ExitInterrupted;
    return o.passed ? ExitOk : ExitFailure;
}

// Waits up to windowMs for samples and says whether the module held still (and, for a level,
// lies within 5 deg of level or of upside down), as the attitude-reset wizard requires.
bool stillEnough(device::DeviceSession &s, bool needLevel, QString *why)
{
    uint64_t seq = s.store().totalAppended();
    double maxRate = 0, roll = 0, pitch = 0;
    int n = 0;
    bool euler = false;
    waitFor([&] {
        for (const auto &x : s.store().since(seq, SIZE_MAX, &seq)) {
            if (x.has(model::FieldGyr)) {
                maxRate = std::max(maxRate, std::sqrt(x.gyr.x * x.gyr.x + x.gyr.y * x.gyr.y + x.gyr.z * x.gyr.z));
                ++n;
            }
            if (x.has(model::FieldEuler)) {
                roll = x.roll;
                pitch = x.pitch;
                euler = true;
            }
        }
        return false;
    }, 1000);
    if (n == 0) {
        *why = QStringLiteral("no samples with angular rate arrived in 1 s: enable an output (e.g. LOG HI91 ONTIME 0.01)");
        return false;
    }
    if (maxRate > 2.0) {
        *why = QStringLiteral("the module moved (up to %1 deg/s in the last second): keep it still and run again")
                   .arg(maxRate, 0, 'f', 1);
        return false;
    }
    if (needLevel) {
        const bool upright = std::fabs(roll) <= 5 && std::fabs(pitch) <= 5;
        const bool upsideDown = std::fabs(std::fabs(roll) - 180) <= 5 && std::fabs(pitch) <= 5;
        if (!euler || !(upright || upsideDown)) {
            *why = QStringLiteral("roll %1, pitch %2 deg: auto level needs the module within 5 deg of level or of "
                                  "upside down; put it there and run again")
                       .arg(roll, 0, 'f', 1)
                       .arg(pitch, 0, 'f', 1);
            return false;
        }
    }
    return true;
}

Outcome attitudeReset(device::DeviceSession &s, int rst)
{
    Outcome o;
    QString why;
    if (!stillEnough(s, rst == 3, &why)) {
        o.message = why;
        return o;
    }
    const auto command = protocol::hipnuc::commands::attReset(rst);
    progress(QStringLiteral("sending %1").arg(QString::fromStdString(command.text)));
    std::optional<protocol::hipnuc::AsciiReply> reply;
    QString error;
    const quint64 id = s.sendCommand(command, 2000, &error);
    if (id == 0) {
        o.message = error;
        return o;
    }
    auto c = QObject::connect(&s, &device::DeviceSession::commandFinished, &s,
                              [&](quint64 done, const protocol::hipnuc::AsciiReply &r) {
                                  if (done == id)
                                      reply = r;
                              });
    waitFor([&] { return reply.has_value(); }, 10000);
    QObject::disconnect(c);
    o.details[QStringLiteral("command")] = QString::fromStdString(command.text);
    if (!reply) {
        o.message = QStringLiteral("no reply to %1").arg(QString::fromStdString(command.text));
        return o;
    }
    o.passed = reply->ok();
    o.message = o.passed ? QStringLiteral("the device answered OK")
                         : QStringLiteral("the device refused: %1%2")
                               .arg(QString::fromStdString(reply->errorLine),
                                    rst == 1 ? QStringLiteral(" (heading reset needs firmware 1.7.1)") : QString());
    return o;
}

Outcome magnetometer(device::DeviceSession &s, const model::DeviceIdentity &id, int timeoutS)
{
    calib::MagCalProcedure::Options options;
    options.timeoutMs = timeoutS * 1000;
    calib::MagCalSession mcal(s, options);
    Outcome o;
    bool done = false;
    int lastProgress = -1, lastStat = -2;
    QObject::connect(&mcal, &calib::MagCalSession::progressChanged, &mcal,
                     [&](int stat, int percent, const QString &message) {
                         if (stat == lastStat && percent == lastProgress)
                             return;
                         lastStat = stat;
                         lastProgress = percent;
                         progress(QStringLiteral("mag: STAT %1, %2 %: %3").arg(stat).arg(percent).arg(message));
                     });
    QObject::connect(&mcal, &calib::MagCalSession::finished, &mcal, [&](bool ok, const QString &message) {
        done = true;
        o.passed = ok;
        o.message = message;
    });
    const auto flow = id.firmware ? calib::MagCalProcedure::flowFor(*id.firmware) : calib::MagCalProcedure::Flow::Mcal;
    if (flow == calib::MagCalProcedure::Flow::Background)
        progress(QStringLiteral("mag: firmware %1 calibrates in the background; turn the module through every direction")
                     .arg(QString::fromStdString(id.firmware->toString())));
    else
        progress(QStringLiteral("mag: CONFIG MCAL START; turn the module slowly through every direction"));
    mcal.start(flow);
    waitFor([&] { return done; }, timeoutS * 1000 + 10000);
    if (!done) {
        mcal.cancel();
        o.message = interrupted() ? QStringLiteral("interrupted at %1 %").arg(std::max(lastProgress, 0))
                                  : QStringLiteral("no result after %1 s").arg(timeoutS);
    }
    o.details[QStringLiteral("stat")] = mcal.procedure().stat();
    o.details[QStringLiteral("progress")] = mcal.procedure().progress();
    return o;
}

// The wizard's heading check (calib::HeadingCheck): one level turn of 360 deg in a steady field,
// the heading followed; it fails on a jump above 10 deg while level, and otherwise says what to
// do (keep the module level, the field is disturbed, keep turning).
Outcome headingCheck(device::DeviceSession &s, int timeoutS)
{
    Outcome o;
    calib::HeadingCheck check;
    progress(QStringLiteral("heading: turn the module level one full turn (360 deg), slowly"));
    uint64_t seq = s.store().totalAppended();
    int reported = 0;
    bool any = false;
    const auto done = [&] {
        const auto st = check.status();
        return st == calib::HeadingCheck::Status::Passed || st == calib::HeadingCheck::Status::Jumps;
    };
    waitFor([&] {
        for (const model::Sample &x : s.store().since(seq, SIZE_MAX, &seq)) {
            any = any || (x.fields & model::FieldEuler);
            check.add(x);
        }
        if (int(check.levelTurnDeg() / 90) > reported) {
            reported = int(check.levelTurnDeg() / 90);
            progress(QStringLiteral("heading: turned %1 deg level, largest step %2 deg")
                         .arg(check.levelTurnDeg(), 0, 'f', 0)
                         .arg(check.largestJudgedStepDeg(), 0, 'f', 1));
        }
        return done();
    }, timeoutS * 1000);
    o.passed = check.passed();
    switch (check.status()) {
    case calib::HeadingCheck::Status::Passed:
        o.message = QStringLiteral("the heading followed the turn smoothly (largest step %1 deg)")
                        .arg(check.largestJudgedStepDeg(), 0, 'f', 1);
        break;
    case calib::HeadingCheck::Status::Jumps:
        o.message = QStringLiteral("the heading jumped %1 deg (more than %2) while the module was level: calibrate "
                                   "again (chapter 9.31)")
                        .arg(check.largestJudgedStepDeg(), 0, 'f', 1)
                        .arg(calib::HeadingCheck::kMaxJumpDeg, 0, 'f', 0);
        break;
    default:
        o.message = interrupted() ? QStringLiteral("interrupted")
                    : !any ? QStringLiteral("no heading arrived in %1 s: the module's output has no Euler angles").arg(timeoutS)
                           : QStringLiteral("cannot judge after %1 s: %2").arg(timeoutS).arg(check.advice());
        break;
    }
    o.details[QStringLiteral("heading_turned_deg")] = std::round(check.levelTurnDeg() * 10) / 10;
    o.details[QStringLiteral("heading_max_step_deg")] = std::round(check.largestJudgedStepDeg() * 100) / 100;
    o.details[QStringLiteral("heading_check")] = o.passed ? QStringLiteral("pass") : QStringLiteral("fail");
    return o;
}

// MCAL, then (when it passed, and unless skipped) the heading check: both must pass.
Outcome magnetometerChecked(device::DeviceSession &s, const model::DeviceIdentity &id, int timeoutS, bool heading,
                            int headingTimeoutS)
{
    Outcome o = magnetometer(s, id, timeoutS);
    if (!heading || !o.passed || interrupted()) {
        o.details[QStringLiteral("heading_check")] = heading ? QStringLiteral("not run") : QStringLiteral("skipped");
        return o;
    }
    const Outcome h = headingCheck(s, headingTimeoutS);
    for (auto it = h.details.begin(); it != h.details.end(); ++it)
        o.details[it.key()] = it.value();
    o.passed = h.passed;
    o.message = QStringLiteral("%1; heading check: %2").arg(o.message, h.message);
    return o;
}

Outcome gyroScale(device::DeviceSession &s, int angle, int timeoutS)
{
    Outcome o;
    calib::GyroCalSession gyro(s);
    bool done = false;
    QObject::connect(&gyro, &calib::GyroCalSession::finished, &gyro, [&](bool ok, const QString &message) {
        done = true;
        o.passed = ok;
        o.message = message;
    });
    if (!gyro.start(angle)) {
        o.message = QStringLiteral("the angle must be %1 to %2 deg").arg(calib::GyroCalSession::kMinAngle).arg(calib::GyroCalSession::kMaxAngle);
        return o;
    }
    calib::GyroScaleRun::Options ro;
    ro.legs = 1;
    ro.targetDeg = angle;
    ro.biasWindowS = 1.0;
    calib::GyroScaleRun run(ro);
    run.start();
    uint64_t seq = s.store().totalAppended();
    progress(QStringLiteral("gyro-scale: CONFIG USRCAL START %1; turn the module %1 deg about Z at 20 to 100 deg/s, "
                            "then hold it still")
                 .arg(angle));
    int lastTenth = -1;
    waitFor([&] {
        if (done) // the device refused the start
            return true;
        for (const auto &x : s.store().since(seq, SIZE_MAX, &seq))
            if (x.has(model::FieldGyr) && x.has(model::FieldDeviceTime))
                run.addSample(x.deviceTimeMs, {x.gyr.x, x.gyr.y, x.gyr.z},
                              x.has(model::FieldAcc) ? Eigen::Vector3d(x.acc.x, x.acc.y, x.acc.z) : Eigen::Vector3d::Zero());
        const int tenth = int(std::fabs(run.currentAngleDeg()) / (angle / 10.0));
        if (tenth != lastTenth && run.state() == calib::GyroScaleRun::State::Turning) {
            lastTenth = tenth;
            progress(QStringLiteral("gyro-scale: %1 of %2 deg at %3 deg/s")
                         .arg(std::fabs(run.currentAngleDeg()), 0, 'f', 0)
                         .arg(angle)
                         .arg(std::fabs(run.currentRateDps()), 0, 'f', 0));
        }
        return run.state() == calib::GyroScaleRun::State::Finished;
    }, timeoutS * 1000);
    if (!done) {
        if (run.state() != calib::GyroScaleRun::State::Finished)
            progress(QStringLiteral("gyro-scale: %1; stopping").arg(interrupted() ? QStringLiteral("interrupted")
                                                                                 : QStringLiteral("time is up")));
        else
            progress(QStringLiteral("gyro-scale: the module stopped; CONFIG USRCAL STOP"));
        gyro.stop();
        // The answer, or the request's own timeout, ends the run; this bound only guards
        // against neither arriving (a host so loaded that the session's thread did not run).
        waitFor([&] { return done; }, 15000);
    }
    const auto r = run.result();
    o.details[QStringLiteral("angle_deg")] = angle;
    o.details[QStringLiteral("turned_deg")] = r.legs.empty() ? std::fabs(run.currentAngleDeg()) : std::fabs(r.legs.front().angleDeg);
    if (r.complete)
        o.details[QStringLiteral("scale_error_pct_estimate")] = r.scaleErrorPct;
    if (!done)
        o.message = QStringLiteral("no answer to CONFIG USRCAL STOP");
    else if (o.passed && r.complete)
        o.message += QStringLiteral(" (ImuDesk's estimate of the scale error before: %1 %)").arg(r.scaleErrorPct, 0, 'f', 2);
    return o;
}

Outcome hec495Clear(const QString &port, int baud, int address)
{
    Outcome o;
    device::Hec495Session s;
    s.setPollingRate(0);
    QString failure;
    QObject::connect(&s, &device::Hec495Session::errorOccurred, &s, [&](const QString &m) { failure = m; });
    s.open(port, baud, address);
    waitFor([&] { return s.state() == device::SessionState::Connected || !failure.isEmpty(); }, 30000);
    if (s.state() != device::SessionState::Connected) {
        o.message = failure.isEmpty() ? QStringLiteral("interrupted") : failure;
        return o;
    }
    std::optional<device::Hec495Result> result;
    const quint64 id = s.clearCalibration();
    QObject::connect(&s, &device::Hec495Session::commandFinished, &s, [&](quint64 done, const device::Hec495Result &r) {
        if (done == id)
            result = r;
    });
    progress(QStringLiteral("hec495-clear: clear calibration (0x10)"));
    waitFor([&] { return result.has_value(); }, 10000);
    if (!result) {
        o.message = QStringLiteral("no result");
        return o;
    }
    o.passed = result->ok();
    o.message = o.passed ? QStringLiteral("the compass's calibration is cleared (factory state)") : result->message;
    return o;
}

} // namespace

int cmdCalibrate(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(QCommandLineOption(QStringLiteral("baud"), QStringLiteral("Baud rate (default: detect)."),
                                   QStringLiteral("B"), QStringLiteral("0")));
    p.addOption(QCommandLineOption(QStringLiteral("json"), QStringLiteral("Print the result as one JSON object.")));
    p.addOption(QCommandLineOption(QStringLiteral("timeout"),
                                   QStringLiteral("mag, gyro-scale: seconds to wait (default 180 and 120)."),
                                   QStringLiteral("S")));
    p.addOption(QCommandLineOption(QStringLiteral("heading-timeout"),
                                   QStringLiteral("mag, heading-check: seconds for the level turn (default 60)."),
                                   QStringLiteral("S"), QStringLiteral("60")));
    p.addOption(QCommandLineOption(QStringLiteral("no-heading-check"), QStringLiteral("mag: skip the heading check.")));
    p.addOption(QCommandLineOption(QStringLiteral("angle"), QStringLiteral("gyro-scale: the turn, 720..1800 deg (default 720)."),
                                   QStringLiteral("DEG"), QStringLiteral("720")));
    p.addOption(QCommandLineOption(QStringLiteral("address"), QStringLiteral("hec495-clear: the module address (default 0)."),
                                   QStringLiteral("N"), QStringLiteral("0")));
    p.addPositionalArgument(QStringLiteral("PORT"), QStringLiteral("Serial port"));
    p.addPositionalArgument(QStringLiteral("ACTION"),
                            QStringLiteral("mag, heading-check, gyro-scale, level, heading-reset or hec495-clear"));
    if (!parseArgs(p, args, kUsage))
        return ExitUsage;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2)
        return fail(QStringLiteral("calibrate needs PORT and ACTION (usage: %1)").arg(kUsage), ExitUsage);
    const QString port = pos.at(0), action = pos.at(1);
    static const QStringList kActions = {QStringLiteral("mag"), QStringLiteral("heading-check"), QStringLiteral("gyro-scale"),
                                         QStringLiteral("level"),
                                         QStringLiteral("heading-reset"), QStringLiteral("hec495-clear")};
    if (!kActions.contains(action))
        return fail(QStringLiteral("unknown calibration '%1' (usage: %2)").arg(action, kUsage), ExitUsage);
    bool ok = false;
    const int baud = p.value(QStringLiteral("baud")).toInt(&ok);
    if (!ok || baud < 0)
        return fail(QStringLiteral("--baud must be a baud rate"), ExitUsage);
    const int angle = p.value(QStringLiteral("angle")).toInt(&ok);
    if (!ok || angle < calib::GyroCalSession::kMinAngle || angle > calib::GyroCalSession::kMaxAngle)
        return fail(QStringLiteral("--angle must be %1 to %2 deg (the manual's USRCAL range)")
                        .arg(calib::GyroCalSession::kMinAngle)
                        .arg(calib::GyroCalSession::kMaxAngle),
                    ExitUsage);
    int timeoutS = action == QLatin1String("mag") ? 180 : 120;
    if (p.isSet(QStringLiteral("timeout"))) {
        timeoutS = p.value(QStringLiteral("timeout")).toInt(&ok);
        if (!ok || timeoutS <= 0 || timeoutS > 3600)
            return fail(QStringLiteral("--timeout needs 1 to 3600 s"), ExitUsage);
    }
    const int headingTimeoutS = p.value(QStringLiteral("heading-timeout")).toInt(&ok);
    if (!ok || headingTimeoutS <= 0 || headingTimeoutS > 3600)
        return fail(QStringLiteral("--heading-timeout needs 1 to 3600 s"), ExitUsage);
    const bool json = p.isSet(QStringLiteral("json"));
    if (action == QLatin1String("hec495-clear")) {
        const int address = p.value(QStringLiteral("address")).toInt(&ok, 0);
        if (!ok || address < 0 || address > 255)
            return fail(QStringLiteral("--address must be 0 to 255"), ExitUsage);
        return finish(action, hec495Clear(port, baud, address), json);
    }

    device::DeviceSession session;
    model::DeviceIdentity identity;
    QString error;
    if (!connectSession(session, port, baud, &identity, nullptr, &error))
        return fail(error, interrupted() ? ExitInterrupted : ExitFailure);
    if (action == QLatin1String("mag"))
        return finish(action,
                      magnetometerChecked(session, identity, timeoutS, !p.isSet(QStringLiteral("no-heading-check")),
                                          headingTimeoutS),
                      json);
    if (action == QLatin1String("heading-check"))
        return finish(action, headingCheck(session, headingTimeoutS), json);
    if (action == QLatin1String("gyro-scale"))
        return finish(action, gyroScale(session, angle, timeoutS), json);
    return finish(action, attitudeReset(session, action == QLatin1String("level") ? 3 : 1), json);
}

} // namespace imudesk::cli
