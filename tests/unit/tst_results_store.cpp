// The station's results database (core/results, issue 38): records stored in one transaction
// and read back whole, a UUID stored once, hostile text stored and read verbatim without
// touching anything else, yield per firmware and slot with ERROR and ABORTED left out, the
// station's result classified (a module gone is ERROR, a cancel ABORTED), a database of a newer
// schema refused.
#include "core/results/results_store.h"
#include "core/station/result_conversion.h"
#include "../common/result_records.h"
#include "../common/test_main.h"

#include <QJsonArray>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace imudesk;
using namespace imudesk::results;

namespace {
RunRecord run(const QString &plan = QStringLiteral("HI14 incoming"))
{
    return test::sampleRun(plan);
}
ModuleRecord module(const RunRecord &r, const QString &serial, Outcome outcome, const QString &firmware = QStringLiteral("1.7.1"),
                    const QString &slot = QStringLiteral("/dev/ttyUSB0"), int attempt = 1, int minute = 0)
{
    return test::sampleModule(r, serial, outcome, firmware, slot, attempt, minute);
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
        const ModuleRecord failed = station::toResultRecord(r, run());
        QCOMPARE(failed.outcome, Outcome::Fail);
        QCOMPARE(failed.slot, QStringLiteral("/dev/ttyUSB2"));
        QCOMPARE(failed.measurements[0].low.value_or(0), -0.2);
        QCOMPARE(failed.measurements[0].high.value_or(0), 0.2);
        QCOMPARE(failed.measurements[0].outcome, Outcome::Fail);
        r.end = station::ModuleResult::End::EquipmentFailed;
        QCOMPARE(station::toResultRecord(r, run()).outcome, Outcome::Error);
        r.end = station::ModuleResult::End::Cancelled;
        QCOMPARE(station::toResultRecord(r, run()).outcome, Outcome::Aborted);
        QVERIFY(station::toResultRecord(r, run()).uuid != station::toResultRecord(r, run()).uuid);
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

    // A database of schema 1 (as the first stations wrote it) is migrated in place: its module
    // is still there, and waits in the outbox.
    void olderSchemaMigrated()
    {
        const QString path = m_dir.filePath(QStringLiteral("v1.sqlite"));
        {
            QSqlDatabase raw = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("raw-v1"));
            raw.setDatabaseName(path);
            QVERIFY(raw.open());
            QSqlQuery q(raw);
            for (const char *sql :
                 {"CREATE TABLE schema_version (version INTEGER NOT NULL)", "INSERT INTO schema_version VALUES (1)",
                  "CREATE TABLE run (uuid TEXT PRIMARY KEY, station_id TEXT, operator TEXT, plan_name TEXT, plan_sha256 TEXT, "
                  "imudesk_version TEXT, started TEXT, finished TEXT)",
                  "CREATE TABLE module (uuid TEXT PRIMARY KEY, run_uuid TEXT NOT NULL REFERENCES run(uuid), slot TEXT, serial TEXT, "
                  "product TEXT, firmware_before TEXT, firmware_after TEXT, attempt INTEGER, outcome TEXT NOT NULL, started TEXT, "
                  "finished TEXT, uploaded INTEGER NOT NULL DEFAULT 0)",
                  "CREATE TABLE step (module_uuid TEXT NOT NULL REFERENCES module(uuid), idx INTEGER NOT NULL, kind TEXT, name TEXT, "
                  "outcome TEXT, skipped INTEGER, detail TEXT, started TEXT, finished TEXT, PRIMARY KEY (module_uuid, idx))",
                  "CREATE TABLE measurement (module_uuid TEXT NOT NULL REFERENCES module(uuid), step INTEGER NOT NULL, name TEXT "
                  "NOT NULL, value REAL, unit TEXT, comparator TEXT, low REAL, high REAL, outcome TEXT, PRIMARY KEY (module_uuid, "
                  "step, name))",
                  "CREATE TABLE artifact (module_uuid TEXT NOT NULL REFERENCES module(uuid), kind TEXT NOT NULL, mime TEXT, "
                  "sha256 TEXT, location TEXT, PRIMARY KEY (module_uuid, kind))",
                  "INSERT INTO run VALUES ('r1', 'bench-1', 'li', 'old plan', '', '0.1', '2026-11-01T08:00:00.000Z', '')",
                  "INSERT INTO module VALUES ('m1', 'r1', '/dev/ttyUSB0', 'SN-OLD', 'HI14R3', '1.7.1', '', 1, 'PASS', "
                  "'2026-11-01T08:00:00.000Z', '2026-11-01T08:01:00.000Z', 0)",
                  "INSERT INTO measurement VALUES ('m1', 1, 'gyro_std_x', 0.01, '°/s', 'LE', NULL, 0.05, 'PASS')"})
                QVERIFY2(q.exec(QString::fromUtf8(sql)), sql);
            raw.close();
        }
        QSqlDatabase::removeDatabase(QStringLiteral("raw-v1"));
        ResultsStore store;
        QString error;
        QVERIFY2(store.open(path, &error, false) == false, "a store told not to migrate must refuse schema 1");
        QVERIFY2(error.contains(QStringLiteral("results setup")), qPrintable(error));
        QVERIFY2(store.open(path, &error), qPrintable(error));
        QCOMPARE(store.schemaVersion(), ResultsStore::kSchemaVersion);
        const auto h = store.history(QStringLiteral("SN-OLD"));
        QCOMPARE(int(h.size()), 1);
        QCOMPARE(h[0].run.planName, QStringLiteral("old plan"));
        QCOMPARE(int(h[0].measurements.size()), 1);
        QVERIFY(!h[0].measurements[0].marginalHigh);
        QCOMPARE(store.pendingCount(), 1);
        // Open again: nothing to migrate, nothing changed.
        store.close();
        QVERIFY(store.open(path, &error));
        QCOMPARE(store.moduleCount(), 1);
    }

    // The outbox: a module waits until its revision is marked uploaded; an artifact added later
    // raises the revision, so the module waits again; an older revision's mark does not clear it.
    void outboxFollowsRevisions()
    {
        ResultsStore store;
        QString error;
        QVERIFY(store.open(m_dir.filePath(QStringLiteral("outbox.sqlite")), &error));
        const RunRecord r = run();
        const ModuleRecord a = module(r, QStringLiteral("SN-A"), Outcome::Pass);
        const ModuleRecord b = module(r, QStringLiteral("SN-B"), Outcome::Fail, QStringLiteral("1.7.1"), QStringLiteral("/dev/ttyUSB1"), 1, 1);
        QVERIFY(store.commit(std::vector<ModuleRecord>{a, b}, &error));
        auto pending = store.pendingUploads(10);
        QCOMPARE(int(pending.size()), 2);
        QCOMPARE(pending[0].first, a.uuid);
        QCOMPARE(pending[0].second, 1);
        QVERIFY(store.markUploaded(a.uuid, 1, &error));
        QCOMPARE(store.pendingCount(), 1);
        QVERIFY(store.addArtifact(a.uuid, {QStringLiteral("recording"), QStringLiteral("application/x-imudesk-capture"),
                                           QString(64, QLatin1Char('c')), QStringLiteral("/runs/a.imudesk")},
                                  &error));
        pending = store.pendingUploads(10);
        QCOMPARE(int(pending.size()), 2);
        QCOMPARE(pending[0].second, 2);
        QVERIFY(store.markUploaded(a.uuid, 1, &error)); // an upload that read revision 1 ends late
        QCOMPARE(store.pendingCount(), 2);
        QVERIFY(store.markUploaded(a.uuid, 2, &error));
        QVERIFY(store.markUploaded(b.uuid, 1, &error));
        QCOMPARE(store.pendingCount(), 0);
        QCOMPARE(int(store.module(a.uuid)->artifacts.size()), 2);
    }

    // Search by a part of the serial (its % taken literally), by plan and station, newest first;
    // a measurement's series leaves ERROR out; Cpk against the limits, computed by hand here.
    void searchSeriesAndCapability()
    {
        ResultsStore store;
        QString error;
        QVERIFY(store.open(m_dir.filePath(QStringLiteral("search.sqlite")), &error));
        const RunRecord r = run(QStringLiteral("trend plan"));
        const double values[] = {0.01, 0.02, 0.03};
        std::vector<ModuleRecord> all;
        for (int i = 0; i < 3; ++i) {
            ModuleRecord m = module(r, QStringLiteral("SN%1-7%").arg(i), Outcome::Pass, QStringLiteral("1.7.1"),
                                    QStringLiteral("/dev/ttyUSB0"), 1, i);
            m.measurements[0].value = values[i];
            all.push_back(m);
        }
        ModuleRecord gone = module(r, QStringLiteral("SN9-x"), Outcome::Error, QStringLiteral("1.7.1"), QStringLiteral("/dev/ttyUSB0"), 1, 5);
        gone.measurements[0].value = 9;
        all.push_back(gone);
        QVERIFY(store.commit(all, &error));
        ResultsStore::Filter f;
        f.serial = QStringLiteral("7%");
        auto found = store.search(f, &error);
        QCOMPARE(int(found.size()), 3);
        QCOMPARE(found[0].serial, QStringLiteral("SN2-7%")); // newest first
        f.serial = QStringLiteral("N_");
        QCOMPARE(int(store.search(f).size()), 0); // _ is no wildcard
        f = {};
        f.plan = QStringLiteral("trend plan");
        f.station = QStringLiteral("bench-3");
        f.from = r.started.addSecs(60);
        QCOMPARE(int(store.search(f).size()), 3); // minutes 1, 2 and 5
        QCOMPARE(store.planNames(), QStringList{QStringLiteral("trend plan")});
        QCOMPARE(store.measurementNames(QStringLiteral("trend plan")),
                 (QStringList{QStringLiteral("gyro_std_x"), QStringLiteral("temperature")}));
        const auto points = store.series(QStringLiteral("trend plan"), QStringLiteral("gyro_std_x"), {}, {}, &error);
        QCOMPARE(int(points.size()), 3);
        QCOMPARE(points[2].value, 0.03);
        QCOMPARE(*points[0].high, 0.05);
        const auto c = ResultsStore::capability(points);
        QCOMPARE(c.n, 3);
        QVERIFY(qFuzzyCompare(c.mean, 0.02));
        QVERIFY(qFuzzyCompare(c.sigma, 0.01));
        QVERIFY(qFuzzyCompare(c.cpk, 1.0)); // (0.05 - 0.02) / (3 * 0.01)
        QVERIFY(std::isnan(ResultsStore::capability(store.series(QStringLiteral("trend plan"), QStringLiteral("temperature"), {}, {})).cpk));
    }

    // A pass with a value in its marginal band is counted as a pass and as marginal, and its
    // band comes back; the OpenHTF JSON says so, with OpenHTF's validators.
    void marginalPassAndOpenHtf()
    {
        ResultsStore store;
        QString error;
        QVERIFY(store.open(m_dir.filePath(QStringLiteral("marginal.sqlite")), &error));
        const RunRecord r = run(QStringLiteral("marginal plan"));
        ModuleRecord m = module(r, QStringLiteral("SN-M"), Outcome::Pass);
        m.measurements[0].value = 0.045;
        m.measurements[0].marginalHigh = 0.04;
        m.measurements[0].marginal = true;
        m.marginal = true;
        QVERIFY(store.commit(std::vector<ModuleRecord>{m, module(r, QStringLiteral("SN-N"), Outcome::Pass)}, &error));
        const auto y = store.yield(QStringLiteral("marginal plan"), {});
        QCOMPARE(y.total.pass, 2);
        QCOMPARE(y.total.marginal, 1);
        const auto back = store.history(QStringLiteral("SN-M"));
        QCOMPARE(int(back.size()), 1);
        QVERIFY(back[0].marginal);
        QCOMPARE(*back[0].measurements[0].marginalHigh, 0.04);
        QVERIFY(back[0].measurements[0].marginal);
        const QJsonObject htf = back[0].toOpenHtfJson();
        QCOMPARE(htf.value(QStringLiteral("dut_id")).toString(), QStringLiteral("SN-M"));
        QCOMPARE(htf.value(QStringLiteral("outcome")).toString(), QStringLiteral("PASS"));
        QVERIFY(htf.value(QStringLiteral("marginal")).toBool());
        const QJsonObject phase = htf.value(QStringLiteral("phases")).toArray().at(1).toObject();
        QCOMPARE(phase.value(QStringLiteral("name")).toString(), QStringLiteral("static"));
        const QJsonObject gyro = phase.value(QStringLiteral("measurements")).toObject().value(QStringLiteral("gyro_std_x")).toObject();
        QCOMPARE(gyro.value(QStringLiteral("measured_value")).toDouble(), 0.045);
        QCOMPARE(gyro.value(QStringLiteral("validators")).toArray().at(0).toString(), QStringLiteral("x <= 0.05"));
        QCOMPARE(gyro.value(QStringLiteral("marginal_validators")).toArray().at(0).toString(), QStringLiteral("x < 0.04"));
        QVERIFY(gyro.value(QStringLiteral("marginal")).toBool());
        // The record's own JSON (results export --format jsonl) reads back whole.
        const auto again = ModuleRecord::fromJson(back[0].toJson());
        QVERIFY(again);
        QCOMPARE(again->uuid, m.uuid);
        QCOMPARE(again->run.planName, r.planName);
        QCOMPARE(int(again->measurements.size()), 2);
        QCOMPARE(*again->measurements[0].marginalHigh, 0.04);
        QCOMPARE(again->serialRaw, back[0].serialRaw);
        QVERIFY(!ModuleRecord::fromJson(QJsonObject{{QStringLiteral("uuid"), QStringLiteral("x")}}));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstResultsStore)
#include "tst_results_store.moc"
