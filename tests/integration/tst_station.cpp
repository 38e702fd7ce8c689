// The production station (issue 22) on a tray of simulated HI14 modules, each served on its
// own pseudo-terminal: one with a noisy gyro, one mounted on its side, one with old firmware
// that the plan updates, one clean, and one whose cable is pulled during the plan. The runner
// tests them at once and names the failing step and values; the run folder gets a PDF per
// module, summary.jsonl and summary.csv, and a re-run of a failed module appends to it. The
// same tray through `imudesk-cli station`.
//
// The CLI tray runs over pseudo-terminals, and so does the module with old firmware in the tray
// of five (its update opens the port by name): they prove the real serial path. The other
// modules run in process (StationRunner::setTransportFactory with sim::SimulatedTransport).
#include "../common/cli_run.h"
#include "../common/firmware_files.h"
#include "../common/test_main.h"
#include "protocol/ihex/intel_hex_writer.h"
#include "reports/station_report.h"
#include "sim/hipnuc_serial_device.h"
#include "sim/pty_simulator.h"
#include "sim/simulated_transport.h"
#include "core/station/run_folder.h"
#include "core/results/results_store.h"
#include "core/station/station_runner.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QGuiApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QMap>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <memory>
#include <vector>

using namespace imudesk;
using station::Verdict;

namespace {

struct Tray {
    std::vector<std::unique_ptr<sim::PtySimulator>> sims;
    QStringList ports;
    // In process: each module is made by transports() for its port name ("sim:tray-N"), its
    // clock running timeScale times faster than real time.
    bool inProcess = false;
    double timeScale = 1.0;
    QMap<QString, sim::SimOptions> modules;

    explicit Tray(bool inProc = false, double scale = 1.0) : inProcess(inProc), timeScale(scale) {}

    // overPty: this module on a pseudo-terminal even in an in-process tray.
    bool add(const char *faults, const char *firmware, uint64_t seed, bool overPty = false,
             sim::Motion motion = sim::Motion::Static)
    {
        sim::SimOptions o;
        o.motion = motion;
        o.firmware = firmware;
        o.seed = seed;
        std::string error;
        if (!sim::parseSimFaults(faults, o.faults, &error))
            return false;
        if (inProcess && !overPty) {
            const QString port = QStringLiteral("sim:tray-%1").arg(ports.size() + 1);
            modules.insert(port, o);
            ports << port;
            return true;
        }
        auto s = std::make_unique<sim::PtySimulator>(o);
        if (!s->start())
            return false;
        ports << s->devicePath();
        sims.push_back(std::move(s));
        return true;
    }
    // The station's transports for the in-process modules: a fresh module (powered on) at each
    // connection; any other port is a serial port.
    station::TransportFactory transports() const
    {
        return [modules = modules, scale = timeScale](const QString &port) -> std::unique_ptr<io::Transport> {
            const auto it = modules.constFind(port);
            if (it == modules.constEnd())
                return nullptr;
            auto link = std::make_unique<sim::SimulatedTransport>(std::make_unique<sim::HipnucSerialDevice>(*it));
            link->setTimeScale(scale);
            if (it->faults.unplugAtS >= 0) // as PtySimulator does
                link->unplugAt(std::llround(it->faults.unplugAtS * 1e6));
            return link;
        };
    }
    // The four of the issue's acceptance: noisy gyro, on its side, old firmware, clean. The one
    // with old firmware is always on a pseudo-terminal: the update opens its port by name.
    bool addFour(uint64_t seed)
    {
        return add("noisy-gyro", "1.7.1", seed) && add("wrong-mounting", "1.7.1", seed + 1)
            && add("", "1.6.6", seed + 2, true) && add("", "1.7.1", seed + 3);
    }
};

// A short plan with every kind of check the tray's faults trip: identify, firmware (update
// from image), profile, static noise, attitude, save, evidence.
station::TestPlan trayPlan(const QTemporaryDir &dir)
{
    protocol::ihex::FirmwareImage image = test::appImage("1.7.1", 16 * 1024, 7);
    test::writeFile(dir, QStringLiteral("app-1.7.1.hex"), protocol::ihex::IntelHexWriter::write(image));
    test::writeFile(dir, QStringLiteral("profile.json"),
                    R"({"format": "imudesk-profile", "version": 1,
                        "settings": {"ATT.MODE": "1", "LOG.HI91": "0.01"}})");
    station::TestPlan plan;
    plan.name = QStringLiteral("tray test");
    plan.baseDir = dir.path();
    auto add = [&plan](station::StepKind kind, QVariantMap params = {}) {
        plan.steps.push_back(station::TestPlan::defaultStep(kind, params));
    };
    using station::StepKind;
    add(StepKind::Identify, {{QStringLiteral("products"), QStringLiteral("HI14")},
                             {QStringLiteral("firmware_min"), QStringLiteral("1.6.6")}});
    add(StepKind::Firmware, {{QStringLiteral("minimum"), QStringLiteral("1.7.1")},
                             {QStringLiteral("image"), QStringLiteral("app-1.7.1.hex")}});
    add(StepKind::Profile, {{QStringLiteral("profile"), QStringLiteral("profile.json")}});
    add(StepKind::Static, {{QStringLiteral("seconds"), 3.0}});
    add(StepKind::Attitude, {{QStringLiteral("seconds"), 1.0}});
    add(StepKind::Save);
    add(StepKind::Evidence, {{QStringLiteral("seconds"), 1.0}});
    return plan;
}

const station::StepResult *stepOf(const station::ModuleResult &m, station::StepKind kind)
{
    for (const auto &s : m.steps)
        if (s.kind == kind)
            return &s;
    return nullptr;
}

const station::Measurement *valueOf(const station::StepResult &s, const QString &name)
{
    for (const auto &v : s.values)
        if (v.name == name)
            return &v;
    return nullptr;
}

} // namespace

class TestStation : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void trayOfFiveInParallel();
    void cliTray();
    void examplePlanPassesOnCleanHi14();
    void disabledStepsSayDisabled();
    void marginalBandPassesMarked();
    void movedModuleCannotBeJudged_data();
    void movedModuleCannotBeJudged();
    void verifyStepJudgesTheModule();
};

void TestStation::trayOfFiveInParallel()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    // In process at the real pace (the parallel run's time is checked), but the module with old
    // firmware on a pseudo-terminal: its update and its session go through the serial port code.
    Tray tray(true);
    QVERIFY(tray.addFour(11));
    QVERIFY(tray.add("unplug=4", "1.7.1", 15));
    const station::TestPlan plan = trayPlan(dir);
    QVERIFY2(plan.problems().isEmpty(), qPrintable(plan.problems().join(u'\n')));

    station::StationRunner runner(plan, tray.ports);
    runner.setTransportFactory(tray.transports());
    QString error;
    const QString runDir = dir.filePath(QStringLiteral("run"));
    QVERIFY2(runner.setRunFolder(runDir, &error), qPrintable(error));
    runner.setReportWriter(&ui::writeStationReport);
    QSignalSpy done(&runner, &station::StationRunner::finished);
    QElapsedTimer clock;
    clock.start();
    runner.start();
    QVERIFY(runner.running());
    QVERIFY(done.wait(120000));
    const double seconds = clock.elapsed() / 1000.0;

    // 1: noisy gyro -> fails the static step, naming the gyro's standard deviation.
    const auto &noisy = runner.module(0);
    QCOMPARE(noisy.verdict, Verdict::Fail);
    QCOMPARE(noisy.steps[size_t(noisy.failedStep())].kind, station::StepKind::Static);
    const auto *gx = valueOf(*stepOf(noisy, station::StepKind::Static), QStringLiteral("gyro_std_x"));
    QVERIFY(gx && !gx->ok && gx->value > 0.2);
    QVERIFY2(noisy.failureSummary().contains(QStringLiteral("gyro_std_x")), qPrintable(noisy.failureSummary()));
    QCOMPARE(stepOf(noisy, station::StepKind::Attitude)->verdict, Verdict::Skipped);

    // 2: on its side -> fails the attitude step with a roll error of about 90 degrees.
    const auto &tilted = runner.module(1);
    QCOMPARE(tilted.verdict, Verdict::Fail);
    QCOMPARE(tilted.steps[size_t(tilted.failedStep())].kind, station::StepKind::Attitude);
    const auto *roll = valueOf(*stepOf(tilted, station::StepKind::Attitude), QStringLiteral("roll_error"));
    QVERIFY(roll && !roll->ok);
    QVERIFY2(std::abs(roll->value) > 80 && std::abs(roll->value) < 100, qPrintable(QString::number(roll->value)));

    // 3: firmware 1.6.6 -> updated to 1.7.1 by the plan, then passes.
    const auto &old = runner.module(2);
    QVERIFY2(old.verdict == Verdict::Pass, qPrintable(old.failureSummary()));
    QCOMPARE(old.firmware, QStringLiteral("1.6.6"));
    QCOMPARE(old.firmwareAfter, QStringLiteral("1.7.1"));
    QVERIFY(valueOf(*stepOf(old, station::StepKind::Firmware), QStringLiteral("bytes_written")));

    // 4: clean -> passes; nothing updated.
    const auto &clean = runner.module(3);
    QVERIFY2(clean.verdict == Verdict::Pass, qPrintable(clean.failureSummary()));
    QVERIFY(clean.firmwareAfter.isEmpty());
    QVERIFY(QFile::exists(clean.evidencePath));

    // 5: the cable pulled at 4 s -> that module fails as gone; the others went on.
    const auto &pulled = runner.module(4);
    QCOMPARE(pulled.verdict, Verdict::Fail);
    QVERIFY2(pulled.failureSummary().contains(QStringLiteral("disappeared"))
                 || pulled.failureSummary().contains(QStringLiteral("no data")),
             qPrintable(pulled.failureSummary()));

    const auto s = runner.summary();
    QCOMPARE(s.passed, 2);
    QCOMPARE(s.failed, 3);
    QVERIFY(!runner.allPassed());
    // In parallel, whatever the machine's load: every module had started before the first one
    // finished, and the run took well under the modules' times added up (what five in turn would
    // take: about 6 s of measuring each plus an update of about 2 s).
    QDateTime lastStart, firstEnd;
    double inTurn = 0;
    for (int i = 0; i < runner.moduleCount(); ++i) {
        const auto &m = runner.module(i);
        QVERIFY(m.started.isValid() && m.finished.isValid());
        lastStart = lastStart.isValid() ? std::max(lastStart, m.started) : m.started;
        firstEnd = firstEnd.isValid() ? std::min(firstEnd, m.finished) : m.finished;
        inTurn += m.started.msecsTo(m.finished) / 1000.0;
    }
    QVERIFY2(lastStart < firstEnd, qPrintable(lastStart.toString(Qt::ISODateWithMs) + QStringLiteral(" >= ")
                                              + firstEnd.toString(Qt::ISODateWithMs)));
    QVERIFY2(seconds < 0.6 * inTurn, qPrintable(QStringLiteral("%1 s in parallel, %2 s in turn").arg(seconds).arg(inTurn)));

    // Reports: a PDF per module, one JSON line per module, the tidy CSV.
    QVERIFY2(runner.reportErrors().isEmpty(), qPrintable(runner.reportErrors().join(u'\n')));
    for (int i = 0; i < runner.moduleCount(); ++i) {
        QFile pdf(runner.module(i).reportPath);
        QVERIFY2(pdf.open(QIODevice::ReadOnly), qPrintable(runner.module(i).reportPath));
        QVERIFY(pdf.read(4) == "%PDF");
    }
    station::RunFolder folder;
    QVERIFY(folder.open(runDir, plan, &error));
    const auto entries = folder.entries();
    QCOMPARE(entries.size(), 5);
    QCOMPARE(entries.at(0).value(QStringLiteral("serial")).toString(), noisy.serial);
    QStringList verdicts;
    for (const auto &e : entries)
        if (e.value(QStringLiteral("serial")).toString() == noisy.serial)
            QCOMPARE(e.value(QStringLiteral("failed_step")).toString(), QStringLiteral("static"));
    QFile csv(QDir(runDir).filePath(QStringLiteral("summary.csv")));
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(csv.readAll()).split(u'\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.first(), station::RunFolder::csvHeader());
    QVERIFY(std::any_of(lines.begin(), lines.end(), [&](const QString &l) {
        return l.startsWith(noisy.serial) && l.contains(QStringLiteral(",static,fail,")) && l.contains(QStringLiteral("gyro_std_x"));
    }));

    // The results database beside the run folder (issue 38): every module committed, the pulled
    // one as ERROR (the equipment, not the product) and left out of the yield.
    {
        results::ResultsStore store;
        QVERIFY2(store.open(dir.filePath(QStringLiteral("results.sqlite")), &error), qPrintable(error));
        QCOMPARE(store.moduleCount(), 5);
        const auto pulledHistory = store.history(pulled.serial);
        QCOMPARE(int(pulledHistory.size()), 1);
        QCOMPARE(pulledHistory[0].outcome, results::Outcome::Error);
        const auto y = store.yield(plan.name, QDateTime());
        QCOMPARE(y.total.pass, 2);
        QCOMPARE(y.total.fail, 2);
        QCOMPARE(y.total.error, 1);
        QCOMPARE(y.total.yield(), 0.5);
        QCOMPARE(y.byFirmware.at(QStringLiteral("1.6.6")).pass, 1);
        const auto noisyHistory = store.history(noisy.serial);
        QCOMPARE(int(noisyHistory.size()), 1);
        QCOMPARE(noisyHistory[0].outcome, results::Outcome::Fail);
        const auto m = std::find_if(noisyHistory[0].measurements.begin(), noisyHistory[0].measurements.end(),
                                    [](const results::MeasurementRecord &v) { return v.name == QLatin1String("gyro_std_x"); });
        QVERIFY(m != noisyHistory[0].measurements.end());
        QCOMPARE(m->outcome, results::Outcome::Fail);
        QCOMPARE(m->comparator, QStringLiteral("LE"));
        QVERIFY(m->high && *m->high > 0 && m->value > *m->high);
        QCOMPARE(noisyHistory[0].slot, tray.ports[0]);
        const auto report = std::find_if(noisyHistory[0].artifacts.begin(), noisyHistory[0].artifacts.end(),
                                         [](const results::ArtifactRecord &a) { return a.kind == QLatin1String("report"); });
        QVERIFY(report != noisyHistory[0].artifacts.end());
        QCOMPARE(report->sha256, results::fileSha256(noisy.reportPath));
        QCOMPARE(report->sha256.size(), 64);
    }

    // A re-run of the noisy module appends attempt 2 to the same run.
    QSignalSpy again(&runner, &station::StationRunner::moduleFinished);
    runner.rerun({0});
    QVERIFY(again.wait(60000));
    QCOMPARE(runner.module(0).attempt, 2);
    QCOMPARE(folder.entries().size(), 6);
    QCOMPARE(folder.nextAttempt(noisy.serial), 3);
    QVERIFY(runner.module(0).reportPath.endsWith(QStringLiteral("-attempt2.pdf")));
    results::ResultsStore store;
    QVERIFY(store.open(dir.filePath(QStringLiteral("results.sqlite")), &error));
    const auto twice = store.history(noisy.serial);
    QCOMPARE(int(twice.size()), 2);
    QCOMPARE(twice[1].attempt, 2);
}

void TestStation::cliTray()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    Tray tray;
    QVERIFY(tray.addFour(21));
    const station::TestPlan plan = trayPlan(dir);
    const QString planPath = dir.filePath(QStringLiteral("plan.json"));
    QString error;
    QVERIFY2(plan.save(planPath, &error), qPrintable(error));
    const QString runDir = dir.filePath(QStringLiteral("cli-run"));
    const auto r = test::runCli({QStringLiteral("station"), planPath, tray.ports.join(u','), QStringLiteral("--report"),
                                 runDir, QStringLiteral("--json")},
                                120000);
    QCOMPARE(r.code, 1); // not every module passed
    QMap<QString, QJsonObject> byPort;
    QJsonObject summary;
    for (const QString &line : r.out.split(u'\n', Qt::SkipEmptyParts)) {
        const QJsonObject o = QJsonDocument::fromJson(line.toUtf8()).object();
        if (o.value(QStringLiteral("event")).toString() == QStringLiteral("summary"))
            summary = o;
        else
            byPort.insert(o.value(QStringLiteral("port")).toString(), o);
    }
    QCOMPARE(byPort.size(), 4);
    QCOMPARE(byPort.value(tray.ports[0]).value(QStringLiteral("verdict")).toString(), QStringLiteral("fail"));
    QCOMPARE(byPort.value(tray.ports[0]).value(QStringLiteral("failed_step")).toString(), QStringLiteral("static"));
    QVERIFY(byPort.value(tray.ports[0]).value(QStringLiteral("failure")).toString().contains(QStringLiteral("gyro_std")));
    QCOMPARE(byPort.value(tray.ports[1]).value(QStringLiteral("failed_step")).toString(), QStringLiteral("attitude"));
    QVERIFY2(byPort.value(tray.ports[2]).value(QStringLiteral("verdict")).toString() == QStringLiteral("pass"),
             qPrintable(QJsonDocument(byPort.value(tray.ports[2])).toJson(QJsonDocument::Compact)));
    QCOMPARE(byPort.value(tray.ports[2]).value(QStringLiteral("firmware_after")).toString(), QStringLiteral("1.7.1"));
    QVERIFY2(byPort.value(tray.ports[3]).value(QStringLiteral("verdict")).toString() == QStringLiteral("pass"),
             qPrintable(QJsonDocument(byPort.value(tray.ports[3])).toJson(QJsonDocument::Compact)));
    QCOMPARE(summary.value(QStringLiteral("passed")).toInt(), 2);
    QCOMPARE(summary.value(QStringLiteral("failed")).toInt(), 2);
    QVERIFY2(r.err.contains(QStringLiteral("step 4/7 Static noise and bias")), qPrintable(r.err));
    for (const QJsonObject &o : byPort) {
        QFile pdf(o.value(QStringLiteral("report")).toString());
        QVERIFY2(pdf.open(QIODevice::ReadOnly), qPrintable(pdf.fileName()));
        QVERIFY(pdf.read(4) == "%PDF");
    }

    // Only the passing modules: exit code 0.
    const auto ok = test::runCli({QStringLiteral("station"), planPath, tray.ports[3], QStringLiteral("--report"), runDir},
                                 120000);
    QVERIFY2(ok.code == 0, qPrintable(ok.out + ok.err));
    QVERIFY(ok.out.startsWith(QStringLiteral("PASS ")));
    // The results database in the run folder the command line named: the module tested twice
    // has two attempts, the plan's yield counts every module.
    const QString db = QDir(runDir).filePath(QStringLiteral("results.sqlite"));
    const QString serial = byPort.value(tray.ports[3]).value(QStringLiteral("serial")).toString();
    const auto history = test::runCli({QStringLiteral("results"), QStringLiteral("serial"), serial, QStringLiteral("--db"), db,
                                       QStringLiteral("--json")});
    QVERIFY2(history.code == 0, qPrintable(history.err));
    const QJsonArray attempts = history.json().value(QStringLiteral("attempts")).toArray();
    QCOMPARE(attempts.size(), 2);
    QCOMPARE(attempts.at(1).toObject().value(QStringLiteral("attempt")).toInt(), 2);
    QCOMPARE(attempts.at(0).toObject().value(QStringLiteral("outcome")).toString(), QStringLiteral("PASS"));
    const auto yield = test::runCli({QStringLiteral("results"), QStringLiteral("yield"), QStringLiteral("--plan"), plan.name,
                                     QStringLiteral("--db"), db, QStringLiteral("--json")});
    QVERIFY2(yield.code == 0, qPrintable(yield.err));
    const QJsonObject total = yield.json().value(QStringLiteral("total")).toObject();
    QCOMPARE(total.value(QStringLiteral("pass")).toInt(), 3);
    QCOMPARE(total.value(QStringLiteral("fail")).toInt(), 2);
    // A plan that does not load: a clear error, exit code 1, nothing run.
    test::writeFile(dir, QStringLiteral("bad.json"), R"({"format": "imudesk-station-plan", "version": 1,
        "steps": [{"step": "static", "seconds": 0}]})");
    const auto bad = test::runCli({QStringLiteral("station"), dir.filePath(QStringLiteral("bad.json")), tray.ports[3]});
    QCOMPARE(bad.code, 1);
    QVERIFY2(bad.err.contains(QStringLiteral("step 1 (static)")) && bad.err.contains(QStringLiteral("seconds")),
             qPrintable(bad.err));
}

// docs/examples/station-hi14.json, every step of it, on a clean simulated HI14 on a rotation
// fixture (for the magnetometer calibration), and the same plan failing that step on a module
// with a motor beside it.
//
// In process, the modules' clocks 16 times faster than real time: the plan's 27 s of measuring
// and the fixture's ~45 s of turns are seconds of device time (the runner measures on the
// module's clock), so they take about 5 s of real time (81 s over ptys at the real pace). The evidence step records for 1 s
// of real time instead of 5: the recording's length is not checked here.
void TestStation::examplePlanPassesOnCleanHi14()
{
    QString error;
    const auto loaded = station::TestPlan::load(
        QDir::cleanPath(QString::fromUtf8(IMUDESK_TEST_DATA) + QStringLiteral("/../../docs/examples/station-hi14.json")), &error);
    QVERIFY2(loaded, qPrintable(error));
    QVERIFY2(loaded->problems().isEmpty(), qPrintable(loaded->problems().join(u'\n')));
    station::TestPlan plan = *loaded;
    for (auto &step : plan.steps)
        if (step.kind == station::StepKind::Evidence)
            step.params.insert(QStringLiteral("seconds"), 1.0);
    QVERIFY2(plan.problems().isEmpty(), qPrintable(plan.problems().join(u'\n')));
    QTemporaryDir dir;
    Tray tray(true, 16.0);
    QVERIFY(tray.add("fixture", "1.7.1", 31));
    QVERIFY(tray.add("fixture,mag-disturbance", "1.7.1", 32));
    station::StationRunner runner(plan, tray.ports);
    runner.setTransportFactory(tray.transports());
    QVERIFY2(runner.setRunFolder(dir.filePath(QStringLiteral("run")), &error), qPrintable(error));
    QSignalSpy done(&runner, &station::StationRunner::finished);
    runner.start();
    QVERIFY(done.wait(240000));
    const auto &clean = runner.module(0);
    QVERIFY2(clean.verdict == Verdict::Pass, qPrintable(clean.failureSummary()));
    for (const auto &s : clean.steps)
        QCOMPARE(s.verdict, s.kind == station::StepKind::GyroScale || s.kind == station::StepKind::Verify ? Verdict::Skipped : Verdict::Pass);
    QVERIFY(QFile::exists(clean.evidencePath));
    const auto &disturbed = runner.module(1);
    QCOMPARE(disturbed.verdict, Verdict::Fail);
    QCOMPARE(disturbed.steps[size_t(disturbed.failedStep())].kind, station::StepKind::MagCal);
    QVERIFY2(disturbed.failureSummary().contains(QStringLiteral("STAT=4")), qPrintable(disturbed.failureSummary()));
    QCOMPARE(runner.framesLost(), 0u);
}

// A step the plan turns off is "disabled in the plan" wherever the result goes (the result,
// summary.jsonl, summary.csv, the report), also after an earlier step failed; the steps the
// failure kept from running say so. And a module that never answers fails at the first step
// the plan runs, not at one it turns off.
void TestStation::disabledStepsSayDisabled()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    Tray tray(true);
    QVERIFY(tray.add("", "1.7.1", 41));
    station::TestPlan plan;
    plan.name = QStringLiteral("disabled steps");
    using station::StepKind;
    // Identify fails: the tray holds an HI14, the plan wants an HI99.
    plan.steps.push_back(station::TestPlan::defaultStep(StepKind::Identify, {{QStringLiteral("products"), QStringLiteral("HI99")}}));
    plan.steps.push_back(station::TestPlan::defaultStep(StepKind::Static, {{QStringLiteral("seconds"), 1.0}}));
    plan.steps.back().enabled = false;
    plan.steps.push_back(station::TestPlan::defaultStep(StepKind::Save));
    QVERIFY2(plan.problems().isEmpty(), qPrintable(plan.problems().join(u'\n')));

    station::StationRunner runner(plan, tray.ports);
    runner.setTransportFactory(tray.transports());
    QString error;
    const QString runDir = dir.filePath(QStringLiteral("run"));
    QVERIFY2(runner.setRunFolder(runDir, &error), qPrintable(error));
    runner.setReportWriter(&ui::writeStationReport);
    QSignalSpy done(&runner, &station::StationRunner::finished);
    runner.start();
    QVERIFY(done.wait(60000));
    const station::ModuleResult &m = runner.module(0);
    QCOMPARE(m.verdict, Verdict::Fail);
    QCOMPARE(m.steps[size_t(m.failedStep())].kind, StepKind::Identify);
    const QString disabled = QStringLiteral("disabled in the plan");
    QCOMPARE(m.steps[1].verdict, Verdict::Skipped);
    QCOMPARE(m.steps[1].detail, disabled);
    QCOMPARE(m.steps[2].verdict, Verdict::Skipped);
    QCOMPARE(m.steps[2].detail, QStringLiteral("not run: \"%1\" failed").arg(m.steps[0].title));

    // summary.jsonl and summary.csv.
    station::RunFolder folder;
    QVERIFY2(folder.open(runDir, plan, &error), qPrintable(error));
    const auto entries = folder.entries();
    QCOMPARE(entries.size(), 1);
    const QJsonArray steps = entries.first().value(QStringLiteral("steps")).toArray();
    QCOMPARE(steps.at(1).toObject().value(QStringLiteral("detail")).toString(), disabled);
    QFile csv(QDir(runDir).filePath(QStringLiteral("summary.csv")));
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QStringList rows = QString::fromUtf8(csv.readAll()).split(u'\n', Qt::SkipEmptyParts);
    const auto staticRow = std::find_if(rows.begin(), rows.end(),
                                        [](const QString &r) { return r.contains(QStringLiteral(",2,static,skipped,")); });
    QVERIFY(staticRow != rows.end());
    QVERIFY2(staticRow->endsWith(disabled), qPrintable(*staticRow));
    // The report: the PDF was written from the same result; its text says it too.
    QVERIFY(QFile::exists(m.reportPath));
    const QString html = ui::StationReport::html(m, plan);
    QVERIFY(html.contains(QStringLiteral("<p>%1</p>").arg(disabled)));
    QCOMPARE(html.count(QStringLiteral("not run:")), 1); // the save step only

    // Nothing answers on the port: the connection failure lands on the first step that runs.
    station::TestPlan offFirst = plan;
    offFirst.steps[0].enabled = false;
    station::StationRunner gone(offFirst, {QStringLiteral("/dev/imudesk-no-such-port")});
    QSignalSpy goneDone(&gone, &station::StationRunner::finished);
    gone.start();
    QVERIFY(goneDone.wait(60000));
    const station::ModuleResult &g = gone.module(0);
    QCOMPARE(g.verdict, Verdict::Fail);
    QCOMPARE(g.steps[0].detail, disabled);
    QCOMPARE(g.steps[1].detail, disabled);
    QCOMPARE(g.steps[size_t(g.failedStep())].kind, StepKind::Save);
}

// A marginal band (plan format 2) on the gyro noise limit, below a clean module's noise
// (SensorModel::kGyrNoiseDps, 0.02 °/s) while the limit is above it: the module passes, its gyro
// noise values are marked marginal and the step's detail names them; the limits without a band
// mark nothing.
void TestStation::marginalBandPassesMarked()
{
    Tray tray(true, 4.0);
    QVERIFY(tray.add("", "1.7.1", 51));
    station::TestPlan plan;
    plan.name = QStringLiteral("marginal band");
    plan.steps.push_back(station::TestPlan::defaultStep(
        station::StepKind::Static, {{QStringLiteral("seconds"), 2.0}, {QStringLiteral("gyro_std_max_dps"), 0.05}}));
    plan.steps.back().marginal.insert(QStringLiteral("gyro_std_max_dps"), 0.01);
    QVERIFY2(plan.problems().isEmpty(), qPrintable(plan.problems().join(u'\n')));
    station::StationRunner runner(plan, tray.ports);
    runner.setTransportFactory(tray.transports());
    QSignalSpy done(&runner, &station::StationRunner::finished);
    runner.start();
    QVERIFY(done.wait(60000));
    const station::ModuleResult &m = runner.module(0);
    QVERIFY2(m.verdict == Verdict::Pass, qPrintable(m.failureSummary()));
    QVERIFY(m.marginal());
    QCOMPARE(m.toJson().value(QStringLiteral("marginal")).toBool(), true);
    const station::StepResult *still = stepOf(m, station::StepKind::Static);
    QVERIFY(still);
    QCOMPARE(still->verdict, Verdict::Pass);
    for (const char *axis : {"x", "y", "z"}) {
        const station::Measurement *v = valueOf(*still, QStringLiteral("gyro_std_") + QLatin1String(axis));
        QVERIFY(v);
        QVERIFY2(v->ok && v->marginal, qPrintable(QString::number(v->value)));
        QCOMPARE(v->marginalHigh.value_or(-1), 0.01);
        QCOMPARE(v->limit, QStringLiteral("≤ 0.05 (marginal > 0.01)"));
    }
    const station::Measurement *bias = valueOf(*still, QStringLiteral("gyro_bias_x"));
    QVERIFY(bias);
    QVERIFY(!bias->marginal && !bias->marginalHigh);
    QVERIFY2(still->detail.contains(QStringLiteral("marginal: gyro_std_x, gyro_std_y, gyro_std_z")),
             qPrintable(still->detail));
}

// Issue 53: a module that moves during the noise/bias or the Allan step is not judged on
// numbers that are the motion's: the step says "cannot judge" and why, no limit is applied, and
// its record is ERROR (not counted against the product); a still module is judged as before.
void TestStation::movedModuleCannotBeJudged_data()
{
    QTest::addColumn<int>("step");
    QTest::addColumn<int>("motion");
    QTest::addColumn<bool>("judged");
    QTest::newRow("static, tumbling") << int(station::StepKind::Static) << int(sim::Motion::Tumble) << false;
    QTest::newRow("allan, on a turntable") << int(station::StepKind::Allan) << int(sim::Motion::Spin) << false;
    QTest::newRow("allan, still") << int(station::StepKind::Allan) << int(sim::Motion::Static) << true;
}

void TestStation::movedModuleCannotBeJudged()
{
    QFETCH(int, step);
    QFETCH(int, motion);
    QFETCH(bool, judged);
    Tray tray(true, 4.0);
    QVERIFY(tray.add("", "1.7.1", 61, false, sim::Motion(motion)));
    station::TestPlan plan;
    plan.name = QStringLiteral("moved");
    // Limits no number of a moving module could fail: only the motion check stops it.
    if (station::StepKind(step) == station::StepKind::Static)
        plan.steps.push_back(station::TestPlan::defaultStep(
            station::StepKind::Static, {{QStringLiteral("seconds"), 3.0}, {QStringLiteral("gyro_std_max_dps"), 100.0},
                                        {QStringLiteral("gyro_bias_max_dps"), 100.0}, {QStringLiteral("acc_std_max_mg"), 1000.0},
                                        {QStringLiteral("gravity_tol_mg"), 1000.0}}));
    else
        plan.steps.push_back(station::TestPlan::defaultStep(
            station::StepKind::Allan, {{QStringLiteral("seconds"), 5.0}, {QStringLiteral("tau_s"), 0.1},
                                       {QStringLiteral("sigma_max_dps"), 100.0}}));
    QVERIFY2(plan.problems().isEmpty(), qPrintable(plan.problems().join(u'\n')));
    station::StationRunner runner(plan, tray.ports);
    runner.setTransportFactory(tray.transports());
    QSignalSpy done(&runner, &station::StationRunner::finished);
    runner.start();
    QVERIFY(done.wait(60000));
    const station::ModuleResult &m = runner.module(0);
    const station::StepResult *s = stepOf(m, station::StepKind(step));
    QVERIFY(s);
    if (judged) {
        QVERIFY2(m.verdict == Verdict::Pass, qPrintable(m.failureSummary()));
        QCOMPARE(m.end, station::ModuleResult::End::Completed);
        return;
    }
    QCOMPARE(s->verdict, Verdict::Fail); // never a pass
    QVERIFY2(s->detail.startsWith(QStringLiteral("cannot judge: the module moved: Allan deviation needs a still recording")),
             qPrintable(s->detail));
    QCOMPARE(m.end, station::ModuleResult::End::NotJudged);
    for (const station::Measurement &v : s->values)
        QVERIFY2(v.comparator == QStringLiteral("INFO"), qPrintable(v.name)); // nothing judged on a number
    QVERIFY(m.failureSummary().contains(QStringLiteral("cannot judge")));
}

// The verify step (issue 55) on three simulated modules turned by hand through their poses at
// four times real time: a good one passes with every figure measured against its limit, one
// whose heading is 3° off fails on it, one left on the table cannot be judged.
void TestStation::verifyStepJudgesTheModule()
{
    Tray tray(true, 4.0);
    QVERIFY(tray.add("", "1.7.1", 71, false, sim::Motion::Poses));
    QVERIFY(tray.add("attitude-bias=0/0/3", "1.7.1", 72, false, sim::Motion::Poses));
    QVERIFY(tray.add("", "1.7.1", 73, false, sim::Motion::Static));
    station::TestPlan plan;
    plan.name = QStringLiteral("verify");
    plan.steps.push_back(station::TestPlan::defaultStep(
        station::StepKind::Verify, {{QStringLiteral("seconds"), 80.0}, {QStringLiteral("gravity_ms2"), 9.8}}));
    QVERIFY2(plan.problems().isEmpty(), qPrintable(plan.problems().join(u'\n')));
    station::StationRunner runner(plan, tray.ports);
    runner.setTransportFactory(tray.transports());
    QSignalSpy done(&runner, &station::StationRunner::finished);
    runner.start();
    QVERIFY(done.wait(120000));

    const station::ModuleResult &good = runner.module(0);
    QVERIFY2(good.verdict == Verdict::Pass, qPrintable(good.failureSummary()));
    const station::StepResult *g = stepOf(good, station::StepKind::Verify);
    QVERIFY(g);
    for (const char *name : {"acc_bias", "acc_scale_error", "gyro_bias", "gyro_scale_error", "tilt_error", "heading_error"}) {
        const station::Measurement *v = valueOf(*g, QLatin1String(name));
        QVERIFY2(v && v->comparator != QStringLiteral("INFO") && v->ok, name);
    }
    QVERIFY(valueOf(*g, QStringLiteral("poses"))->value >= 9);

    const station::ModuleResult &bad = runner.module(1);
    QCOMPARE(bad.verdict, Verdict::Fail);
    const station::Measurement *h = valueOf(*stepOf(bad, station::StepKind::Verify), QStringLiteral("heading_error"));
    QVERIFY(h && !h->ok);
    QVERIFY2(std::fabs(h->value - 3.0) < 0.5, qPrintable(QString::number(h->value)));

    const station::ModuleResult &still = runner.module(2);
    QCOMPARE(still.end, station::ModuleResult::End::NotJudged);
    QVERIFY2(stepOf(still, station::StepKind::Verify)->detail.startsWith(QStringLiteral("cannot judge: ")),
             qPrintable(stepOf(still, station::StepKind::Verify)->detail));
}

IMUDESK_TEST_MAIN(TestStation)
#include "tst_station.moc"
