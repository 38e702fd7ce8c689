// The station's test plan format (core/station/test_plan.h) and its run folder
// (core/station/run_folder.h): the example plan shipped in docs/examples is the one the code
// builds and loads without problems; a plan survives a save and load; every kind of bad input
// is refused with the step and parameter named; the run folder appends attempts and refuses a
// folder of another plan; the tidy CSV has one row per measured value.
#include "core/station/run_folder.h"
#include "core/station/station_result.h"
#include "core/station/test_plan.h"
#include "../common/test_main.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>

using namespace imudesk::station;

namespace {
// tests/data may not exist: the path is cleaned as text.
const QString kExamples = QDir::cleanPath(QString::fromUtf8(IMUDESK_TEST_DATA) + QStringLiteral("/../../docs/examples"));

ModuleResult sampleResult(const QString &serial, Verdict verdict)
{
    ModuleResult r;
    r.port = QStringLiteral("/dev/ttyUSB0");
    r.serial = serial;
    r.product = QStringLiteral("HI14R3");
    r.firmware = QStringLiteral("1.7.1");
    r.verdict = verdict;
    StepResult id;
    id.kind = StepKind::Identify;
    id.title = TestPlan::title(id.kind);
    id.verdict = Verdict::Pass;
    id.detail = QStringLiteral("HI14R3, firmware 1.7.1");
    StepResult st;
    st.kind = StepKind::Static;
    st.title = TestPlan::title(st.kind);
    st.verdict = verdict;
    st.values.push_back({QStringLiteral("gyro_std_x"), verdict == Verdict::Pass ? 0.02 : 0.41, QStringLiteral("°/s"),
                         QStringLiteral("≤ 0.05"), verdict == Verdict::Pass});
    st.values.push_back({QStringLiteral("samples"), 500, QString(), QString(), true});
    r.steps = {id, st};
    return r;
}
} // namespace

class TestTestPlan : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void exampleFileIsTheExample();
    void roundTrip();
    void refused_data();
    void refused();
    void missingFiles();
    void failureSummary();
    void runFolderAppends();
};

void TestTestPlan::exampleFileIsTheExample()
{
    QString error;
    const auto plan = TestPlan::load(kExamples + QStringLiteral("/station-hi14.json"), &error);
    QVERIFY2(plan, qPrintable(error));
    QCOMPARE(plan->toJson(), TestPlan::example().toJson());
    QVERIFY2(plan->problems().isEmpty(), qPrintable(plan->problems().join(u'\n')));
    QCOMPARE(plan->steps.size(), TestPlan::allKinds().size());
    // Every step kind is in it; only the turntable run is off.
    for (const PlanStep &s : plan->steps)
        QCOMPARE(s.enabled, s.kind != StepKind::GyroScale);
    QCOMPARE(plan->resolve(QStringLiteral("hi14-sim-1.7.1.hex")), QDir(kExamples).absoluteFilePath(QStringLiteral("hi14-sim-1.7.1.hex")));
}

void TestTestPlan::roundTrip()
{
    TestPlan plan = TestPlan::example();
    plan.name = QStringLiteral("中文 plan");
    plan.steps[3].params[QStringLiteral("seconds")] = 12.5;
    plan.steps[0].enabled = false;
    QString error;
    const auto back = TestPlan::fromJson(plan.toJson(), &error);
    QVERIFY2(back, qPrintable(error));
    QCOMPARE(back->name, plan.name);
    QCOMPARE(back->steps[3].number("seconds"), 12.5);
    QVERIFY(!back->steps[0].enabled);
    QCOMPARE(back->toJson(), plan.toJson());
    // A step given without parameters takes the defaults.
    const auto minimal = TestPlan::fromJson(R"({"format": "imudesk-station-plan", "version": 1,
                                                "steps": [{"step": "allan"}]})",
                                            &error);
    QVERIFY2(minimal, qPrintable(error));
    QCOMPARE(minimal->steps[0].number("tau_s"), 1.0);
    QCOMPARE(minimal->steps[0].number("seconds"), 20.0);
}

void TestTestPlan::refused_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("expected");
    const QByteArray head = R"({"format": "imudesk-station-plan", "version": 1, "steps": )";
    QTest::newRow("not json") << QByteArray("{") << QStringLiteral("not JSON");
    QTest::newRow("other format") << QByteArray(R"({"format": "imudesk-profile", "version": 1})")
                                  << QStringLiteral("not a station plan");
    QTest::newRow("newer version") << QByteArray(R"({"format": "imudesk-station-plan", "version": 2, "steps": []})")
                                   << QStringLiteral("version 2");
    QTest::newRow("no steps") << head + "[]}" << QStringLiteral("no steps");
    QTest::newRow("unknown step") << head + R"([{"step": "identify"}, {"step": "shake"}]})"
                                  << QStringLiteral("step 2: unknown step \"shake\"");
    QTest::newRow("unknown parameter") << head + R"([{"step": "static", "secs": 5}]})"
                                       << QStringLiteral("static has no parameter \"secs\"");
    QTest::newRow("out of range") << head + R"([{"step": "static", "seconds": 0}]})"
                                  << QStringLiteral("\"seconds\" = 0 is outside 1");
    QTest::newRow("text for a number") << head + R"([{"step": "attitude", "tolerance_deg": "5"}]})"
                                       << QStringLiteral("\"tolerance_deg\" must be a number");
    QTest::newRow("number for a text") << head + R"([{"step": "profile", "profile": 3}]})"
                                       << QStringLiteral("\"profile\" must be a text");
    QTest::newRow("bad version") << head + R"([{"step": "firmware", "minimum": "latest"}]})"
                                 << QStringLiteral("firmware version such as 1.7.1");
    QTest::newRow("enabled not bool") << head + R"([{"step": "save", "enabled": "no"}]})"
                                      << QStringLiteral("\"enabled\" must be true or false");
    QTest::newRow("too large") << QByteArray(TestPlan::kMaxBytes + 1, ' ') << QStringLiteral("larger than");
}

void TestTestPlan::refused()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, expected);
    QString error;
    QVERIFY(!TestPlan::fromJson(json, &error));
    QVERIFY2(error.contains(expected), qPrintable(error));
}

void TestTestPlan::missingFiles()
{
    QTemporaryDir dir;
    TestPlan plan = TestPlan::example();
    plan.baseDir = dir.path(); // neither the profile nor the image is there
    const QStringList problems = plan.problems();
    QCOMPARE(problems.size(), 2);
    QVERIFY(problems[0].contains(QStringLiteral("step 2 (firmware)")));
    QVERIFY(problems[1].contains(QStringLiteral("step 3 (profile)")));
    // A disabled step's file is not needed; a profile step needs one.
    plan.steps[1].enabled = false;
    plan.steps[2].params[QStringLiteral("profile")] = QString();
    QCOMPARE(plan.problems(), QStringList{QStringLiteral("step 3 (profile): no profile file given")});
}

void TestTestPlan::failureSummary()
{
    const ModuleResult bad = sampleResult(QStringLiteral("A1"), Verdict::Fail);
    QCOMPARE(bad.failedStep(), 1);
    QCOMPARE(bad.failureSummary(), TestPlan::title(StepKind::Static) + QStringLiteral(": gyro_std_x 0.41 °/s (≤ 0.05)"));
    const QJsonObject j = bad.toJson();
    QCOMPARE(j.value(QStringLiteral("failed_step")).toString(), QStringLiteral("static"));
    QCOMPARE(j.value(QStringLiteral("steps")).toArray().size(), 2);
    QCOMPARE(sampleResult(QStringLiteral("A2"), Verdict::Pass).failedStep(), -1);
}

void TestTestPlan::runFolderAppends()
{
    QTemporaryDir dir;
    const QString runDir = dir.filePath(QStringLiteral("a/run"));
    RunFolder folder;
    QString error;
    QVERIFY2(folder.open(runDir, TestPlan::example(), &error), qPrintable(error));
    QVERIFY(QFile::exists(runDir + QStringLiteral("/plan.json")));
    ModuleResult r = sampleResult(QStringLiteral("SN,1"), Verdict::Fail);
    r.attempt = folder.nextAttempt(r.serial);
    QCOMPARE(r.attempt, 1);
    QVERIFY(folder.append(r, &error));
    // Opened again (another session): the same plan appends, the attempt goes up.
    RunFolder again;
    QVERIFY2(again.open(runDir, TestPlan::example(), &error), qPrintable(error));
    QCOMPARE(again.nextAttempt(r.serial), 2);
    r.attempt = 2;
    r.verdict = Verdict::Pass;
    QVERIFY(again.append(r, &error));
    QCOMPARE(again.entries().size(), 2);
    QCOMPARE(again.entries().at(1).value(QStringLiteral("attempt")).toInt(), 2);
    QVERIFY(again.reportPath(r).endsWith(QStringLiteral("SN_1-attempt2.pdf")));
    // CSV: the header once, then one row per value (two values, two steps: identify has none).
    QFile csv(runDir + QStringLiteral("/summary.csv"));
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(csv.readAll()).split(u'\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 1 + 2 * 3);
    QCOMPARE(lines[0], RunFolder::csvHeader());
    QVERIFY2(lines[2].startsWith(QStringLiteral("\"SN,1\",HI14R3,1.7.1,,/dev/ttyUSB0,1,fail,")), qPrintable(lines[2]));
    QVERIFY(lines[2].contains(QStringLiteral(",static,fail,")) && lines[2].contains(QStringLiteral(",gyro_std_x,0.41,")));
    // Another plan in the same folder is refused.
    TestPlan other = TestPlan::example();
    other.name = QStringLiteral("other");
    RunFolder third;
    QVERIFY(!third.open(runDir, other, &error));
    QVERIFY2(error.contains(QStringLiteral("another plan")), qPrintable(error));
}

IMUDESK_TEST_GUILESS_MAIN(TestTestPlan)
#include "tst_test_plan.moc"
