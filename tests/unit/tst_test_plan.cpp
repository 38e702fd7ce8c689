// The station's test plan format (core/station/test_plan.h) and its run folder
// (core/station/run_folder.h): the example plan shipped in docs/examples is the one the code
// builds and loads without problems; a plan survives a save and load; every kind of bad input
// is refused with the step and parameter named; the run folder appends attempts and refuses a
// folder of another plan; the tidy CSV has one row per measured value. Format version 2 (issue
// 38): a version 1 plan loads and says it is converted, every limit's marginal band survives a
// save and load, a limit without one is still a plain number, and a bad band is refused or
// listed as a problem with the step and the limit named; marginal values reach the results' JSON.
#include "core/station/run_folder.h"
#include "core/station/station_result.h"
#include "core/station/test_plan.h"
#include "../common/test_main.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
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

// The value of a parameter of the plan's first step, as the plan's JSON writes it.
QJsonValue firstStepValue(const TestPlan &plan, const QString &key)
{
    return QJsonDocument::fromJson(plan.toJson()).object().value(QStringLiteral("steps")).toArray().at(0).toObject().value(key);
}

} // namespace

class TestTestPlan : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void exampleFileIsTheExample();
    void roundTrip();
    void versionOneConverts();
    void marginalRoundTrip_data();
    void marginalRoundTrip();
    void marginalProblems_data();
    void marginalProblems();
    void refused_data();
    void refused();
    void missingFiles();
    void failureSummary();
    void marginalInResults();
    void runFolderAppends();
};

void TestTestPlan::exampleFileIsTheExample()
{
    QString error;
    const auto plan = TestPlan::load(kExamples + QStringLiteral("/station-hi14.json"), &error);
    QVERIFY2(plan, qPrintable(error));
    QCOMPARE(plan->toJson(), TestPlan::example().toJson());
    // In the current format: the editor has nothing to say about converting it.
    QCOMPARE(plan->loadedVersion, TestPlan::kVersion);
    QVERIFY(plan->conversionNote().isEmpty());
    QVERIFY2(plan->problems().isEmpty(), qPrintable(plan->problems().join(u'\n')));
    QCOMPARE(plan->steps.size(), TestPlan::allKinds().size());
    // Every step kind is in it; only the turntable run and the module check (turned by hand) are off.
    for (const PlanStep &s : plan->steps)
        QCOMPARE(s.enabled, s.kind != StepKind::GyroScale && s.kind != StepKind::Verify);
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

void TestTestPlan::versionOneConverts()
{
    QString error;
    const auto old = TestPlan::fromJson(R"({"format": "imudesk-station-plan", "version": 1, "name": "old",
                                            "steps": [{"step": "static", "seconds": 3, "gyro_std_max_dps": 0.07},
                                                      {"step": "attitude", "tolerance_deg": 2}]})",
                                        &error);
    QVERIFY2(old, qPrintable(error));
    QCOMPARE(old->loadedVersion, 1);
    QVERIFY2(old->conversionNote().contains(QStringLiteral("version 1")), qPrintable(old->conversionNote()));
    QCOMPARE(old->steps[0].number("gyro_std_max_dps"), 0.07);
    QVERIFY(!old->steps[0].marginalOf("gyro_std_max_dps"));
    // Saved as version 2, its limits still plain numbers; read again, nothing to convert.
    const QJsonObject saved = QJsonDocument::fromJson(old->toJson()).object();
    QCOMPARE(saved.value(QStringLiteral("version")).toInt(), 2);
    const QJsonObject still = saved.value(QStringLiteral("steps")).toArray().at(0).toObject();
    QVERIFY(still.value(QStringLiteral("gyro_std_max_dps")).isDouble());
    QCOMPARE(still.value(QStringLiteral("gyro_std_max_dps")).toDouble(), 0.07);
    const auto again = TestPlan::fromJson(old->toJson(), &error);
    QVERIFY2(again, qPrintable(error));
    QCOMPARE(again->loadedVersion, 2);
    QVERIFY(again->conversionNote().isEmpty());
    QCOMPARE(again->toJson(), old->toJson());
    // A version 2 plan without bands: every limit is written as a plain number.
    const QJsonArray steps =
        QJsonDocument::fromJson(TestPlan::example().toJson()).object().value(QStringLiteral("steps")).toArray();
    int limits = 0;
    for (const QJsonValue &step : steps) {
        const QJsonObject o = step.toObject();
        const StepKind kind = *TestPlan::kindFromKey(o.value(QStringLiteral("step")).toString());
        for (const ParamSpec &p : TestPlan::params(kind))
            if (p.limit) {
                ++limits;
                QVERIFY2(o.value(QLatin1String(p.key)).isDouble(), p.key);
            }
    }
    QCOMPARE(limits, 13); // static 4, allan 1, attitude 1, gyro_scale 1, verify 6
}

void TestTestPlan::marginalRoundTrip_data()
{
    QTest::addColumn<QString>("step");
    QTest::addColumn<QString>("key");
    QTest::addColumn<double>("high");
    QTest::addColumn<double>("band");
    QTest::newRow("gyro noise") << "static" << "gyro_std_max_dps" << 0.05 << 0.04;
    QTest::newRow("gyro bias") << "static" << "gyro_bias_max_dps" << 0.5 << 0.3;
    QTest::newRow("acc noise") << "static" << "acc_std_max_mg" << 3.0 << 0.0;
    QTest::newRow("gravity") << "static" << "gravity_tol_mg" << 20.0 << 12.5;
    QTest::newRow("allan") << "allan" << "sigma_max_dps" << 0.01 << 0.008;
    QTest::newRow("attitude") << "attitude" << "tolerance_deg" << 5.0 << 4.0;
    QTest::newRow("scale") << "gyro_scale" << "max_error_pct" << 0.5 << 0.25;
}

void TestTestPlan::marginalRoundTrip()
{
    QFETCH(QString, step);
    QFETCH(QString, key);
    QFETCH(double, high);
    QFETCH(double, band);
    const QByteArray json = QStringLiteral(R"({"format": "imudesk-station-plan", "version": 2, "steps": [
                                               {"step": "%1", "%2": {"high": %3, "marginal_high": %4}}]})")
                                .arg(step, key)
                                .arg(high)
                                .arg(band)
                                .toUtf8();
    QString error;
    const auto plan = TestPlan::fromJson(json, &error);
    QVERIFY2(plan, qPrintable(error));
    const QByteArray k = key.toLatin1();
    QCOMPARE(plan->steps[0].number(k.constData()), high);
    QCOMPARE(plan->steps[0].marginalOf(k.constData()).value_or(-1), band);
    QVERIFY2(plan->problems().isEmpty(), qPrintable(plan->problems().join(u'\n')));
    // Written back as the object, and read back the same.
    const QJsonObject written = firstStepValue(*plan, key).toObject();
    QCOMPARE(written.value(QStringLiteral("high")).toDouble(), high);
    QCOMPARE(written.value(QStringLiteral("marginal_high")).toDouble(), band);
    QCOMPARE(written.size(), 2);
    const auto back = TestPlan::fromJson(plan->toJson(), &error);
    QVERIFY2(back, qPrintable(error));
    QCOMPARE(back->steps[0].marginalOf(k.constData()).value_or(-1), band);
    QCOMPARE(back->toJson(), plan->toJson());
    // Without the band the limit is a plain number again.
    TestPlan plain = *back;
    plain.steps[0].marginal.remove(key);
    QVERIFY(firstStepValue(plain, key).isDouble());
}

void TestTestPlan::marginalProblems_data()
{
    // A plan edited in memory (the plan editor): its bands are checked by problems().
    QTest::addColumn<QString>("key");
    QTest::addColumn<QVariant>("band");
    QTest::addColumn<QString>("expected"); // empty: no problem
    const QString limit = QStringLiteral("step 2 (static): \"gyro_std_max_dps\": \"marginal_high\"");
    QTest::newRow("inside") << "gyro_std_max_dps" << QVariant(0.04) << QString();
    QTest::newRow("zero") << "gyro_std_max_dps" << QVariant(0.0) << QString();
    QTest::newRow("at the limit") << "gyro_std_max_dps" << QVariant(0.05)
                                  << limit + QStringLiteral(" = 0.05 °/s is not below the limit 0.05 °/s");
    QTest::newRow("above the limit") << "gyro_std_max_dps" << QVariant(0.2)
                                     << limit + QStringLiteral(" = 0.2 °/s is not below the limit 0.05 °/s");
    QTest::newRow("negative") << "gyro_std_max_dps" << QVariant(-0.01)
                              << limit + QStringLiteral(" = -0.01 is outside 0 … 100 °/s");
    QTest::newRow("text") << "gyro_std_max_dps" << QVariant(QStringLiteral("0.04"))
                          << limit + QStringLiteral(" must be a number");
    QTest::newRow("not a limit") << "seconds" << QVariant(3.0)
                                 << QStringLiteral("step 2 (static): \"seconds\" is not a limit");
}

void TestTestPlan::marginalProblems()
{
    QFETCH(QString, key);
    QFETCH(QVariant, band);
    QFETCH(QString, expected);
    TestPlan plan;
    plan.steps.push_back(TestPlan::defaultStep(StepKind::Save));
    plan.steps.push_back(TestPlan::defaultStep(StepKind::Static));
    plan.steps[1].marginal.insert(key, band);
    const QStringList problems = plan.problems();
    if (expected.isEmpty()) {
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(u'\n')));
        return;
    }
    QCOMPARE(problems.size(), 1);
    QVERIFY2(problems[0].startsWith(expected), qPrintable(problems[0]));
}

void TestTestPlan::refused_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("expected");
    const QByteArray head = R"({"format": "imudesk-station-plan", "version": 1, "steps": )";
    const QByteArray head2 = R"({"format": "imudesk-station-plan", "version": 2, "steps": [{"step": "identify"}, )";
    QTest::newRow("not json") << QByteArray("{") << QStringLiteral("not JSON");
    QTest::newRow("other format") << QByteArray(R"({"format": "imudesk-profile", "version": 1})")
                                  << QStringLiteral("not a station plan");
    QTest::newRow("newer version") << QByteArray(R"({"format": "imudesk-station-plan", "version": 3, "steps": []})")
                                   << QStringLiteral("version 3");
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
    // Version 2's limits with a band: the step and the limit named.
    QTest::newRow("band at the limit")
        << head2 + R"({"step": "static", "gyro_std_max_dps": {"high": 0.05, "marginal_high": 0.05}}]})"
        << QStringLiteral("step 2 (static): \"gyro_std_max_dps\": \"marginal_high\" = 0.05 °/s is not below the "
                          "limit 0.05 °/s");
    QTest::newRow("band above the limit")
        << head2 + R"({"step": "allan", "sigma_max_dps": {"high": 0.01, "marginal_high": 0.02}}]})"
        << QStringLiteral("step 2 (allan): \"sigma_max_dps\": \"marginal_high\" = 0.02 °/s is not below");
    QTest::newRow("band not a number")
        << head2 + R"({"step": "attitude", "tolerance_deg": {"high": 5, "marginal_high": "4"}}]})"
        << QStringLiteral("step 2 (attitude): \"tolerance_deg\": \"marginal_high\" must be a number");
    QTest::newRow("band null")
        << head2 + R"({"step": "attitude", "tolerance_deg": {"high": 5, "marginal_high": null}}]})"
        << QStringLiteral("step 2 (attitude): \"tolerance_deg\": \"marginal_high\" must be a number");
    QTest::newRow("band out of range")
        << head2 + R"({"step": "attitude", "tolerance_deg": {"high": 5, "marginal_high": 0.05}}]})"
        << QStringLiteral("step 2 (attitude): \"tolerance_deg\": \"marginal_high\" = 0.05 is outside 0.1 … 90 °");
    QTest::newRow("unknown field")
        << head2 + R"({"step": "gyro_scale", "max_error_pct": {"high": 0.5, "marginal_low": 0.1}}]})"
        << QStringLiteral("step 2 (gyro_scale): \"max_error_pct\" has an unknown field \"marginal_low\"");
    QTest::newRow("no high") << head2 + R"({"step": "static", "gravity_tol_mg": {"marginal_high": 10}}]})"
                             << QStringLiteral("step 2 (static): \"gravity_tol_mg\" has no \"high\"");
    QTest::newRow("high out of range")
        << head2 + R"({"step": "static", "acc_std_max_mg": {"high": 2000, "marginal_high": 2}}]})"
        << QStringLiteral("step 2 (static): \"acc_std_max_mg\" = 2000 is outside 0");
    QTest::newRow("band on no limit") << head2 + R"({"step": "static", "seconds": {"high": 5}}]})"
                                      << QStringLiteral("step 2 (static): \"seconds\" must be a number");
    QTest::newRow("band in version 1")
        << head + R"([{"step": "static", "gyro_std_max_dps": {"high": 0.05, "marginal_high": 0.04}}]})"
        << QStringLiteral("step 1 (static): \"gyro_std_max_dps\" must be a number");
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

void TestTestPlan::marginalInResults()
{
    ModuleResult r = sampleResult(QStringLiteral("M1"), Verdict::Pass);
    QVERIFY(!r.marginal());
    QJsonObject value = r.toJson().value(QStringLiteral("steps")).toArray().at(1).toObject()
                            .value(QStringLiteral("values")).toArray().at(0).toObject();
    QVERIFY(!value.contains(QStringLiteral("marginal")) && !value.contains(QStringLiteral("marginal_high")));
    QCOMPARE(r.toJson().value(QStringLiteral("marginal")).toBool(true), false);
    // A value inside its band: the module still passes, marked marginal.
    Measurement &m = r.steps[1].values[0];
    m.marginalHigh = 0.01;
    m.marginal = true;
    QVERIFY(r.marginal());
    QCOMPARE(r.failedStep(), -1);
    const QJsonObject j = r.toJson();
    QCOMPARE(j.value(QStringLiteral("marginal")).toBool(), true);
    value = j.value(QStringLiteral("steps")).toArray().at(1).toObject().value(QStringLiteral("values")).toArray().at(0)
                .toObject();
    QCOMPARE(value.value(QStringLiteral("marginal")).toBool(), true);
    QCOMPARE(value.value(QStringLiteral("marginal_high")).toDouble(), 0.01);
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
