// The station's results database (core/results, issue 38): records stored in one transaction
// and read back whole, a UUID stored once, hostile text stored and read verbatim without
// touching anything else, yield per firmware and slot with ERROR and ABORTED left out, the
// station's result classified (a module gone is ERROR, a cancel ABORTED), a database of a newer
// schema refused.
#include "core/results/results_store.h"
#include "../common/test_main.h"

#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>

using namespace imudesk;
using namespace imudesk::results;

namespace {
RunRecord run(const QString &plan = QStringLiteral("HI14 incoming"))
{
    RunRecord r;
    r.uuid = newUuid();
    r.stationId = QStringLiteral("bench-3");
    r.operatorName = QStringLiteral("li");
    r.planName = plan;
    r.planSha256 = QString(64, QLatin1Char('a'));
    r.imudeskVersion = QStringLiteral("0.1.0");
    r.started = QDateTime(QDate(2026, 11, 30), QTime(8, 0), Qt::UTC);
    return r;
}

ModuleRecord module(const RunRecord &r, const QString &serial, Outcome outcome, const QString &firmware = QStringLiteral("1.7.1"),
                    const QString &slot = QStringLiteral("/dev/ttyUSB0"), int attempt = 1, int minute = 0)
{
    ModuleRecord m;
    m.uuid = newUuid();
    m.run = r;
    m.slot = slot;
    m.serial = serial;
    m.product = QStringLiteral("HI14R3");
    m.firmwareBefore = firmware;
    m.attempt = attempt;
    m.outcome = outcome;
    m.started = r.started.addSecs(60 * minute);
    m.finished = m.started.addSecs(30);
    m.steps.push_back({0, QStringLiteral("identify"), QStringLiteral("Identify"), Outcome::Pass, false, QStringLiteral("HI14R3"),
                       m.started, m.started.addSecs(1)});
    m.steps.push_back({1, QStringLiteral("static"), QStringLiteral("Static noise and bias"), outcome, false, QString(),
                       m.started.addSecs(1), m.finished});
    MeasurementRecord v;
    v.step = 1;
    v.name = QStringLiteral("gyro_std_x");
    v.value = outcome == Outcome::Fail ? 0.41 : 0.012;
    v.unit = QStringLiteral("°/s");
    v.comparator = QStringLiteral("LE");
    v.high = 0.05;
    v.outcome = outcome == Outcome::Fail ? Outcome::Fail : Outcome::Pass;
    m.measurements.push_back(v);
    MeasurementRecord info;
    info.step = 1;
    info.name = QStringLiteral("temperature");
    info.value = 31.5;
    info.unit = QStringLiteral("°C");
    info.comparator = QStringLiteral("INFO");
    m.measurements.push_back(info);
    m.artifacts.push_back({QStringLiteral("report"), QStringLiteral("application/pdf"), QString(64, QLatin1Char('b')),
                           QStringLiteral("/runs/x.pdf")});
    return m;
}
} // namespace

class TstResultsStore : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private Q_SLOTS:
    void storedWholeAndReadBack()
    {
        ResultsStore store;
        QString error;
        QVERIFY2(store.open(m_dir.filePath(QStringLiteral("a.sqlite")), &error), qPrintable(error));
        const RunRecord r = run();
        const ModuleRecord first = module(r, QStringLiteral("SN1"), Outcome::Fail, QStringLiteral("1.7.1"), QStringLiteral("/dev/ttyUSB0"), 1, 0);
        const ModuleRecord second = module(r, QStringLiteral("SN1"), Outcome::Pass, QStringLiteral("1.7.1"), QStringLiteral("/dev/ttyUSB1"), 2, 5);
        QVERIFY2(store.commit(second, &error), qPrintable(error)); // out of order: read back by time
        QVERIFY2(store.commit(first, &error), qPrintable(error));
        const auto h = store.history(QStringLiteral("SN1"));
        QCOMPARE(int(h.size()), 2);
        QCOMPARE(h[0].uuid, first.uuid);
        QCOMPARE(h[1].uuid, second.uuid);
        QCOMPARE(h[0].outcome, Outcome::Fail);
        QCOMPARE(h[0].run.uuid, r.uuid);
        QCOMPARE(h[0].run.planSha256, r.planSha256);
        QCOMPARE(h[0].run.stationId, QStringLiteral("bench-3"));
        QCOMPARE(h[0].started, first.started);
        QCOMPARE(h[1].slot, QStringLiteral("/dev/ttyUSB1"));
        QCOMPARE(int(h[0].steps.size()), 2);
        QCOMPARE(h[0].steps[1].kind, QStringLiteral("static"));
        QCOMPARE(int(h[0].measurements.size()), 2);
        const MeasurementRecord &g = h[0].measurements[0];
        QCOMPARE(g.name, QStringLiteral("gyro_std_x"));
        QCOMPARE(g.value, 0.41);
        QCOMPARE(g.unit, QStringLiteral("°/s"));
        QCOMPARE(g.comparator, QStringLiteral("LE"));
        QVERIFY(!g.low.has_value());
        QCOMPARE(g.high.value_or(-1), 0.05);
        QCOMPARE(g.outcome, Outcome::Fail);
        QVERIFY(!h[0].measurements[1].high.has_value()); // information only: no limit
        QCOMPARE(int(h[0].artifacts.size()), 1);
        QCOMPARE(h[0].artifacts[0].sha256, QString(64, QLatin1Char('b')));
        QVERIFY(store.history(QStringLiteral("SN2")).empty());
    }

    void oneUuidStoredOnce()
    {
        ResultsStore store;
        QString error;
        QVERIFY(store.open(m_dir.filePath(QStringLiteral("b.sqlite")), &error));
        const ModuleRecord m = module(run(), QStringLiteral("SN7"), Outcome::Pass);
        QVERIFY(store.commit(m, &error));
        QVERIFY(store.commit(m, &error)); // a retry after a lost acknowledgement
        QCOMPARE(store.moduleCount(), 1);
        QCOMPARE(int(store.history(QStringLiteral("SN7")).size()), 1);
        // Reopened: still there.
        store.close();
        QVERIFY(store.open(m_dir.filePath(QStringLiteral("b.sqlite")), &error));
        QCOMPARE(store.moduleCount(), 1);
    }

    void hostileTextVerbatim()
    {
        ResultsStore store;
        QString error;
        QVERIFY(store.open(m_dir.filePath(QStringLiteral("c.sqlite")), &error));
        const QString evil = QStringLiteral("x'); DROP TABLE run;--");
        const QString longPlan = QString(10 * 1024, QLatin1Char('P')) + QStringLiteral("\"';");
        const QString odd = QString::fromUtf8("\xe6\xa8\xa1\xe5\x9d\x97") + QChar(0xFFFD) + QStringLiteral("\t\n\\");
        RunRecord r = run(longPlan);
        ModuleRecord m = module(r, evil, Outcome::Pass);
        m.product = odd;
        QVERIFY2(store.commit(m, &error), qPrintable(error));
        const auto h = store.history(evil);
        QCOMPARE(int(h.size()), 1);
        QCOMPARE(h[0].serial, evil);
        QCOMPARE(h[0].product, odd);
        QCOMPARE(h[0].run.planName, longPlan);
        // Nothing else happened: the tables are all there and hold what they held.
        QSqlDatabase raw = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("raw-check"));
        raw.setDatabaseName(m_dir.filePath(QStringLiteral("c.sqlite")));
        QVERIFY(raw.open());
        {
            QSqlQuery q(raw);
            QVERIFY(q.exec(QStringLiteral("SELECT COUNT(*) FROM run")) && q.next());
            QCOMPARE(q.value(0).toInt(), 1);
        }
        raw.close();
        raw = QSqlDatabase();
        QSqlDatabase::removeDatabase(QStringLiteral("raw-check"));
        QCOMPARE(store.yield(longPlan, QDateTime()).total.pass, 1);
    }

    void yieldLeavesOutErrorAndAborted()
    {
        ResultsStore store;
        QString error;
        QVERIFY(store.open(m_dir.filePath(QStringLiteral("d.sqlite")), &error));
        const RunRecord r = run();
        int n = 0;
        for (int i = 0; i < 3; ++i)
            QVERIFY(store.commit(module(r, QStringLiteral("P%1").arg(i), Outcome::Pass, QStringLiteral("1.7.1"), QStringLiteral("A"), 1, n++), &error));
        QVERIFY(store.commit(module(r, QStringLiteral("F1"), Outcome::Fail, QStringLiteral("1.6.6"), QStringLiteral("B"), 1, n++), &error));
        QVERIFY(store.commit(module(r, QStringLiteral("E1"), Outcome::Error, QStringLiteral("1.7.1"), QStringLiteral("B"), 1, n++), &error));
        QVERIFY(store.commit(module(r, QStringLiteral("A1"), Outcome::Aborted, QStringLiteral("1.7.1"), QStringLiteral("A"), 1, n++), &error));
        QVERIFY(store.commit(module(run(QStringLiteral("other plan")), QStringLiteral("O1"), Outcome::Fail), &error));
        const auto y = store.yield(QStringLiteral("HI14 incoming"), QDateTime());
        QCOMPARE(y.total.pass, 3);
        QCOMPARE(y.total.fail, 1);
        QCOMPARE(y.total.error, 1);
        QCOMPARE(y.total.aborted, 1);
        QCOMPARE(y.total.yield(), 0.75);
        QCOMPARE(y.byFirmware.at(QStringLiteral("1.7.1")).yield(), 1.0);
        QCOMPARE(y.byFirmware.at(QStringLiteral("1.6.6")).yield(), 0.0);
        QCOMPARE(y.bySlot.at(QStringLiteral("B")).error, 1);
        QVERIFY(std::isnan(ResultsStore::Counts{}.yield()));
        // Since: the modules started after the third minute only.
        const auto later = store.yield(QStringLiteral("HI14 incoming"), r.started.addSecs(3 * 60));
        QCOMPARE(later.total.pass + later.total.fail + later.total.error + later.total.aborted, 3);
    }

    void stationResultClassified()
    {
        station::ModuleResult r;
        r.port = QStringLiteral("/dev/ttyUSB2");
        r.serial = QStringLiteral("SN9");
        r.verdict = station::Verdict::Fail;
        station::StepResult s;
        s.kind = station::StepKind::Static;
        s.verdict = station::Verdict::Fail;
        s.values.push_back(station::Measurement{QStringLiteral("gyro_bias_z"), -0.3, QStringLiteral("°/s"),
                                                QStringLiteral("|x| ≤ 0.2"), false, QStringLiteral("ABS_LE"), 0.2});
        r.steps.push_back(s);
        const ModuleRecord failed = ModuleRecord::fromStation(r, run());
        QCOMPARE(failed.outcome, Outcome::Fail);
        QCOMPARE(failed.slot, QStringLiteral("/dev/ttyUSB2"));
        QCOMPARE(failed.measurements[0].low.value_or(0), -0.2);
        QCOMPARE(failed.measurements[0].high.value_or(0), 0.2);
        QCOMPARE(failed.measurements[0].outcome, Outcome::Fail);
        r.end = station::ModuleResult::End::EquipmentFailed;
        QCOMPARE(ModuleRecord::fromStation(r, run()).outcome, Outcome::Error);
        r.end = station::ModuleResult::End::Cancelled;
        QCOMPARE(ModuleRecord::fromStation(r, run()).outcome, Outcome::Aborted);
        QVERIFY(ModuleRecord::fromStation(r, run()).uuid != ModuleRecord::fromStation(r, run()).uuid);
    }

    void newerSchemaRefused()
    {
        const QString path = m_dir.filePath(QStringLiteral("e.sqlite"));
        {
            ResultsStore store;
            QString error;
            QVERIFY(store.open(path, &error));
        }
        {
            QSqlDatabase raw = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("raw-newer"));
            raw.setDatabaseName(path);
            QVERIFY(raw.open());
            QSqlQuery q(raw);
            QVERIFY(q.exec(QStringLiteral("UPDATE schema_version SET version = 99")));
            raw.close();
        }
        QSqlDatabase::removeDatabase(QStringLiteral("raw-newer"));
        ResultsStore store;
        QString error;
        QVERIFY(!store.open(path, &error));
        QVERIFY2(error.contains(QStringLiteral("newer ImuDesk")), qPrintable(error));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstResultsStore)
#include "tst_results_store.moc"
