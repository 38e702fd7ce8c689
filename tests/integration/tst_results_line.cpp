// The line's results database (issue 38) on a real PostgreSQL server from Debian's package,
// started by the test (tests/common/pg_server.h): the schema created by ImuDesk and a schema 1
// migrated; a station's role that reads and inserts and cannot delete; hostile values stored and
// read verbatim; four `imudesk-cli station` processes with four simulated modules each
// uploading at once (16 records, none lost or doubled, the yield counted); the server stopped in
// the middle of a run (the results wait in the station's SQLite, the count waiting is known,
// every one arrives once when the server is back); a batch sent twice stored once.
#include "../common/cli_run.h"
#include "../common/pg_server.h"
#include "../common/result_records.h"
#include "../common/test_main.h"
#include "sim/hipnuc_serial_device.h"
#include "sim/pty_simulator.h"
#include "sim/simulated_transport.h"
#include "core/results/results_store.h"
#include "core/results/results_uploader.h"
#include "core/station/result_conversion.h"
#include "core/station/station_runner.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSignalSpy>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>

#include <memory>
#include <vector>

using namespace imudesk;
using results::Outcome;
using results::ResultsStore;

namespace {

// A short plan: identify, two seconds at rest, save.
station::TestPlan shortPlan(const QString &name)
{
    station::TestPlan plan;
    plan.name = name;
    using station::StepKind;
    plan.steps.push_back(station::TestPlan::defaultStep(StepKind::Identify, {{QStringLiteral("products"), QStringLiteral("HI14")}}));
    plan.steps.push_back(station::TestPlan::defaultStep(StepKind::Static, {{QStringLiteral("seconds"), 2.0}}));
    plan.steps.push_back(station::TestPlan::defaultStep(StepKind::Save));
    return plan;
}

int count(const test::PgServer &pg, const QString &sql)
{
    QString out, error;
    if (!pg.psql(sql, &out, &error))
        return -1;
    return out.toInt();
}

} // namespace

class TstResultsLine : public QObject {
    Q_OBJECT
    test::PgServer m_pg;

private Q_SLOTS:
    void initTestCase()
    {
        QString error;
        QVERIFY2(m_pg.start(&error), qPrintable(error));
        // The line's set-up, as docs/RESULTS_DATABASE.md gives it: the schema by ImuDesk, a login
        // role for the stations that may read and insert only.
        QVERIFY2(m_pg.psql(QStringLiteral("CREATE ROLE imudesk_station LOGIN"), nullptr, &error), qPrintable(error));
        const auto setup = test::runCli({QStringLiteral("results"), QStringLiteral("setup"), QStringLiteral("--results"), m_pg.url(),
                                         QStringLiteral("--station-role"), QStringLiteral("imudesk_station")});
        QVERIFY2(setup.code == 0, qPrintable(setup.out + setup.err));
        QVERIFY2(setup.out.contains(QStringLiteral("schema %1").arg(ResultsStore::kSchemaVersion)), qPrintable(setup.out));
    }

    // A database of schema 1 on the server is migrated by the owner; a station's role, which may
    // not change tables, is told to have the owner run the set-up.
    void schemaMigratedOnServer()
    {
        QString error;
        QVERIFY2(m_pg.psql(QStringLiteral("CREATE DATABASE old_line"), nullptr, &error), qPrintable(error));
        const QString v1 = QStringLiteral(
            "CREATE TABLE schema_version (version INTEGER NOT NULL); INSERT INTO schema_version VALUES (1);"
            "CREATE TABLE run (uuid TEXT PRIMARY KEY, station_id TEXT, operator TEXT, plan_name TEXT, plan_sha256 TEXT, "
            "imudesk_version TEXT, started TEXT, finished TEXT);"
            "CREATE TABLE module (uuid TEXT PRIMARY KEY, run_uuid TEXT NOT NULL REFERENCES run(uuid), slot TEXT, serial TEXT, "
            "product TEXT, firmware_before TEXT, firmware_after TEXT, attempt INTEGER, outcome TEXT NOT NULL, started TEXT, "
            "finished TEXT, uploaded INTEGER NOT NULL DEFAULT 0);"
            "CREATE TABLE step (module_uuid TEXT NOT NULL REFERENCES module(uuid), idx INTEGER NOT NULL, kind TEXT, name TEXT, "
            "outcome TEXT, skipped INTEGER, detail TEXT, started TEXT, finished TEXT, PRIMARY KEY (module_uuid, idx));"
            "CREATE TABLE measurement (module_uuid TEXT NOT NULL REFERENCES module(uuid), step INTEGER NOT NULL, name TEXT NOT "
            "NULL, value DOUBLE PRECISION, unit TEXT, comparator TEXT, low DOUBLE PRECISION, high DOUBLE PRECISION, outcome TEXT, "
            "PRIMARY KEY (module_uuid, step, name));"
            "CREATE TABLE artifact (module_uuid TEXT NOT NULL REFERENCES module(uuid), kind TEXT NOT NULL, mime TEXT, "
            "sha256 TEXT, location TEXT, PRIMARY KEY (module_uuid, kind));"
            "INSERT INTO run VALUES ('r1', 'bench-1', 'li', 'old plan', '', '0.1', '2026-11-01T08:00:00.000Z', '');"
            "INSERT INTO module VALUES ('m1', 'r1', 's', 'SN-OLD', 'HI14R3', '1.7.1', '', 1, 'PASS', "
            "'2026-11-01T08:00:00.000Z', '', 0);"
            "GRANT SELECT, INSERT ON ALL TABLES IN SCHEMA public TO imudesk_station;");
        QProcess psql;
        psql.start(QStringLiteral("psql"), {QStringLiteral("-X"), QStringLiteral("-q"), QStringLiteral("-v"), QStringLiteral("ON_ERROR_STOP=1"),
                                            QStringLiteral("-h"), m_pg.socketDir(), QStringLiteral("-p"),
                                            QString::number(m_pg.port()), QStringLiteral("-U"),
                                            QLatin1String(test::PgServer::kOwner), QStringLiteral("-d"), QStringLiteral("old_line"),
                                            QStringLiteral("-c"), v1});
        QVERIFY(psql.waitForFinished(30000));
        QVERIFY2(psql.exitCode() == 0, psql.readAllStandardError().constData());
        {
            ResultsStore station;
            QVERIFY(!station.open(m_pg.url(QStringLiteral("imudesk_station"), QStringLiteral("old_line")), &error));
            QVERIFY2(error.contains(QStringLiteral("schema 2")) || error.contains(QStringLiteral("permission denied"))
                         || error.contains(QStringLiteral("must be owner")),
                     qPrintable(error));
        }
        ResultsStore owner;
        QVERIFY2(owner.open(m_pg.url(QLatin1String(test::PgServer::kOwner), QStringLiteral("old_line")), &error), qPrintable(error));
        QCOMPARE(owner.schemaVersion(), ResultsStore::kSchemaVersion);
        const auto h = owner.history(QStringLiteral("SN-OLD"));
        QCOMPARE(int(h.size()), 1);
        QCOMPARE(h[0].run.planName, QStringLiteral("old plan"));
    }

    // The station's role reads and inserts; it cannot delete or change a result, and a refused
    // statement changes nothing.
    void stationRoleCannotDelete()
    {
        ResultsStore station;
        QString error;
        QVERIFY2(station.open(m_pg.url(QStringLiteral("imudesk_station")), &error), qPrintable(error));
        const results::RunRecord r = test::sampleRun(QStringLiteral("role plan"));
        const auto m = test::sampleModule(r, QStringLiteral("SN-ROLE"), Outcome::Pass);
        QVERIFY2(station.commit(m, &error), qPrintable(error));
        QVERIFY2(station.commit(m, &error), qPrintable(error)); // again: nothing happens, no UPDATE needed
        QCOMPARE(int(station.history(QStringLiteral("SN-ROLE")).size()), 1);
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QPSQL"), QStringLiteral("role-check"));
        db.setHostName(m_pg.socketDir());
        db.setPort(m_pg.port());
        db.setUserName(QStringLiteral("imudesk_station"));
        db.setDatabaseName(QStringLiteral("postgres"));
        QVERIFY2(db.open(), qPrintable(db.lastError().text()));
        {
            QSqlQuery q(db);
            for (const QString &sql : {QStringLiteral("DELETE FROM measurement"), QStringLiteral("DELETE FROM module"),
                                       QStringLiteral("UPDATE module SET outcome = 'PASS'"), QStringLiteral("DROP TABLE run"),
                                       QStringLiteral("TRUNCATE artifact")}) {
                QVERIFY2(!q.exec(sql), qPrintable(sql));
                QVERIFY2(q.lastError().text().contains(QStringLiteral("permission denied"))
                             || q.lastError().text().contains(QStringLiteral("must be owner")),
                         qPrintable(q.lastError().text()));
            }
        }
        db.close();
        db = QSqlDatabase();
        QSqlDatabase::removeDatabase(QStringLiteral("role-check"));
        QCOMPARE(count(m_pg, QStringLiteral("SELECT COUNT(*) FROM module WHERE serial = 'SN-ROLE'")), 1);
        QCOMPARE(count(m_pg, QStringLiteral("SELECT COUNT(*) FROM measurement m JOIN module o ON o.uuid = m.module_uuid "
                                            "WHERE o.serial = 'SN-ROLE'")),
                 2);
    }

    // Modules that report the serial x'); DROP TABLE run;-- and one whose bytes are not UTF-8,
    // under a plan named with 10 kB, through the station, its SQLite and the upload; and a record
    // whose serial holds a NUL through `results upload`. Stored and read back verbatim, every
    // table still there.
    void hostileValuesVerbatim()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QByteArray evil = "x'); DROP TABLE run;--";
        sim::SimOptions o;
        o.seed = 77;
        o.serial = evil.toStdString();
        sim::PtySimulator sim(o);
        QVERIFY(sim.start());
        // A second module whose serial's bytes are not UTF-8 (erased flash reads 0xFF).
        const QByteArray raw("\xff\xfe\x80SN-\xc3", 7);
        sim::SimOptions o2;
        o2.seed = 78;
        o2.serial = raw.toStdString();
        sim::PtySimulator sim2(o2);
        QVERIFY(sim2.start());
        const station::TestPlan plan = shortPlan(QString(10 * 1024, QLatin1Char('P')) + QStringLiteral("'); DROP TABLE module;--"));
        station::StationRunner runner(plan, {sim.devicePath(), sim2.devicePath()});
        QString error;
        QVERIFY2(runner.setRunFolder(dir.filePath(QStringLiteral("run")), &error), qPrintable(error));
        results::UploaderOptions line;
        line.server = m_pg.url(QStringLiteral("imudesk_station"));
        line.pollMs = 200;
        runner.setLineDatabase(line);
        QSignalSpy done(&runner, &station::StationRunner::finished);
        runner.start();
        QVERIFY(done.wait(120000));
        QCOMPARE(runner.module(0).serial, QString::fromUtf8(evil));
        QCOMPARE(runner.module(1).serialRaw, raw);
        QCOMPARE(runner.module(1).serial, QStringLiteral("\\xff\\xfe\\x80SN-\\xc3"));
        QCOMPARE(runner.module(1).verdict, station::Verdict::Pass);
        QVERIFY(runner.uploader());
        QTRY_COMPARE_WITH_TIMEOUT(runner.resultsStore().pendingCount(), 0, 30000); // the outbox itself
        ResultsStore server;
        QVERIFY2(server.open(m_pg.url(), &error), qPrintable(error));
        const auto a = server.history(QString::fromUtf8(evil));
        QCOMPARE(int(a.size()), 1);
        QCOMPARE(a[0].serialRaw, evil);
        QCOMPARE(a[0].run.planName, plan.name);
        const auto a2 = server.history(runner.module(1).serial);
        QCOMPARE(int(a2.size()), 1);
        QCOMPARE(a2[0].serialRaw, raw);
        ResultsStore::Filter typed; // found by a part of it typed as shown
        typed.serial = QStringLiteral("\\xfe\\x80SN");
        const auto found = server.search(typed);
        QCOMPARE(int(found.size()), 1);
        QCOMPARE(found[0].serialRaw, raw);
        QCOMPARE(QDir(dir.filePath(QStringLiteral("run/openhtf"))).entryList(QDir::Files).size(), 2);

        // And a NUL, which no serial line's reply carries and PostgreSQL's text cannot hold: the
        // bytes kept as they are, the text shows them as \xNN.
        const QByteArray notUtf8("\xff\xfe\x80SN-\x00\xc3", 8);
        station::ModuleResult r = runner.module(0);
        r.serialRaw = notUtf8;
        r.serial = station::bytesAsText(notUtf8);
        QCOMPARE(r.serial, QStringLiteral("\\xff\\xfe\\x80SN-\\x00\\xc3"));
        // In a database of its own: the runner's uploader, still polling its results.sqlite,
        // would otherwise send it before the CLI does.
        ResultsStore local;
        QVERIFY(local.open(dir.filePath(QStringLiteral("other-station.sqlite")), &error));
        QVERIFY2(local.commit(station::toResultRecord(r, runner.runRecord()), &error), qPrintable(error));
        QCOMPARE(local.pendingCount(), 1);
        const auto upload = test::runCli({QStringLiteral("results"), QStringLiteral("upload"), QStringLiteral("--db"),
                                          dir.filePath(QStringLiteral("other-station.sqlite")), QStringLiteral("--results"),
                                          m_pg.url(QStringLiteral("imudesk_station"))});
        QVERIFY2(upload.code == 0, qPrintable(upload.out + upload.err));
        QVERIFY2(upload.out.startsWith(QStringLiteral("1 uploaded")), qPrintable(upload.out));
        const auto b = server.history(r.serial);
        QCOMPARE(int(b.size()), 1);
        QCOMPARE(b[0].serialRaw, notUtf8);
        // Nothing else happened on the server.
        QCOMPARE(count(m_pg, QStringLiteral("SELECT COUNT(*) FROM information_schema.tables WHERE table_schema = 'public'")), 6);
        QVERIFY(count(m_pg, QStringLiteral("SELECT COUNT(*) FROM run")) >= 1);
        // The CLI shows the serials as stored.
        const auto cli = test::runCli({QStringLiteral("results"), QStringLiteral("serial"), QString::fromUtf8(evil),
                                       QStringLiteral("--results"), m_pg.url(), QStringLiteral("--json")});
        QVERIFY2(cli.code == 0, qPrintable(cli.err));
        const QJsonArray attempts = cli.json().value(QStringLiteral("attempts")).toArray();
        QCOMPARE(attempts.size(), 1);
        QCOMPARE(attempts.at(0).toObject().value(QStringLiteral("serial")).toString(), QString::fromUtf8(evil));
        const auto shown = test::runCli({QStringLiteral("results"), QStringLiteral("serial"), r.serial, QStringLiteral("--results"),
                                         m_pg.url(), QStringLiteral("--json")});
        const QJsonObject first = shown.json().value(QStringLiteral("attempts")).toArray().at(0).toObject();
        QCOMPARE(first.value(QStringLiteral("serial_hex")).toString(), QString::fromLatin1(notUtf8.toHex()));
    }

    // Four stations, four simulated modules each, one noisy: every station a separate
    // imudesk-cli process, all uploading to the server at once, the reports copied to a shared
    // folder. 16 records arrive, none lost, none twice; the yield counts 12 passes and 4 fails.
    void fourStationsAtOnce()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const station::TestPlan plan = shortPlan(QStringLiteral("line plan"));
        const QString planPath = dir.filePath(QStringLiteral("plan.json"));
        QString error;
        QVERIFY2(plan.save(planPath, &error), qPrintable(error));
        std::vector<std::unique_ptr<sim::PtySimulator>> sims;
        std::vector<std::unique_ptr<QProcess>> stations;
        const QString shared = dir.filePath(QStringLiteral("shared"));
        for (int s = 0; s < 4; ++s) {
            QStringList ports;
            for (int m = 0; m < 4; ++m) {
                sim::SimOptions o;
                o.seed = 1000 + 10 * s + m;
                std::string why;
                QVERIFY(sim::parseSimFaults(m == 0 ? "noisy-gyro" : "", o.faults, &why));
                sims.push_back(std::make_unique<sim::PtySimulator>(o));
                QVERIFY(sims.back()->start());
                ports << sims.back()->devicePath();
            }
            auto p = std::make_unique<QProcess>();
            p->start(QString::fromUtf8(IMUDESK_CLI_PATH),
                     {QStringLiteral("station"), planPath, ports.join(u','), QStringLiteral("--report"),
                      dir.filePath(QStringLiteral("station%1/run").arg(s)), QStringLiteral("--results"),
                      m_pg.url(QStringLiteral("imudesk_station")), QStringLiteral("--artifacts"), shared,
                      QStringLiteral("--station-id"), QStringLiteral("station-%1").arg(s), QStringLiteral("--json"),
                      QStringLiteral("--upload-wait"), QStringLiteral("60")});
            stations.push_back(std::move(p));
        }
        for (auto &p : stations) {
            QVERIFY(p->waitForFinished(240000));
            const QString err = QString::fromUtf8(p->readAllStandardError());
            QVERIFY2(p->exitCode() == 1, qPrintable(err)); // the noisy module fails
            QVERIFY2(err.contains(QStringLiteral("every result uploaded")), qPrintable(err));
            const QStringList lines = QString::fromUtf8(p->readAllStandardOutput()).split(u'\n', Qt::SkipEmptyParts);
            const QJsonObject summary = QJsonDocument::fromJson(lines.last().toUtf8()).object();
            QCOMPARE(summary.value(QStringLiteral("waiting_upload")).toInt(), 0);
        }
        const QString inPlan = QStringLiteral("FROM module m JOIN run r ON r.uuid = m.run_uuid WHERE r.plan_name = 'line plan'");
        QCOMPARE(count(m_pg, QStringLiteral("SELECT COUNT(*) ") + inPlan), 16);
        QCOMPARE(count(m_pg, QStringLiteral("SELECT COUNT(DISTINCT m.serial) ") + inPlan), 16);
        QCOMPARE(count(m_pg, QStringLiteral("SELECT COUNT(DISTINCT r.station_id) ") + inPlan), 4);
        // Every measurement of every station's SQLite is on the server.
        int local = 0;
        for (int s = 0; s < 4; ++s) {
            ResultsStore db;
            QVERIFY(db.open(dir.filePath(QStringLiteral("station%1/run/results.sqlite").arg(s)), &error));
            QCOMPARE(db.pendingCount(), 0);
            for (const auto &m : db.search({}))
                local += int(db.module(m.uuid)->measurements.size());
        }
        QCOMPARE(count(m_pg, QStringLiteral("SELECT COUNT(*) FROM measurement v JOIN module m ON m.uuid = v.module_uuid "
                                            "JOIN run r ON r.uuid = m.run_uuid WHERE r.plan_name = 'line plan'")),
                 local);
        // The reports are in the shared folder, as the server records them, whole.
        QString out;
        QVERIFY(m_pg.psql(QStringLiteral("SELECT a.location || '|' || a.sha256 FROM artifact a JOIN module m ON m.uuid = "
                                         "a.module_uuid JOIN run r ON r.uuid = m.run_uuid WHERE r.plan_name = 'line plan' "
                                         "AND a.kind = 'report'"),
                          &out, &error));
        const QStringList reports = out.split(u'\n', Qt::SkipEmptyParts);
        QCOMPARE(reports.size(), 16);
        for (const QString &row : reports) {
            const QStringList parts = row.split(u'|');
            QVERIFY2(parts[0].startsWith(shared), qPrintable(parts[0]));
            QCOMPARE(results::fileSha256(parts[0]), parts[1]);
        }
        const auto yield = test::runCli({QStringLiteral("results"), QStringLiteral("yield"), QStringLiteral("--plan"),
                                         QStringLiteral("line plan"), QStringLiteral("--results"), m_pg.url(), QStringLiteral("--json")});
        QVERIFY2(yield.code == 0, qPrintable(yield.err));
        const QJsonObject total = yield.json().value(QStringLiteral("total")).toObject();
        QCOMPARE(total.value(QStringLiteral("pass")).toInt(), 12);
        QCOMPARE(total.value(QStringLiteral("fail")).toInt(), 4);
        QCOMPARE(total.value(QStringLiteral("error")).toInt(), 0);
        // The export has one row per measurement.
        const auto csv = test::runCli({QStringLiteral("results"), QStringLiteral("export"), QStringLiteral("--since"),
                                       QStringLiteral("2020-01-01"), QStringLiteral("--plan"), QStringLiteral("line plan"),
                                       QStringLiteral("--results"), m_pg.url()});
        QVERIFY2(csv.code == 0, qPrintable(csv.err));
        QCOMPARE(csv.out.split(u'\n', Qt::SkipEmptyParts).size(), 1 + local);
        const auto jsonl = test::runCli({QStringLiteral("results"), QStringLiteral("export"), QStringLiteral("--since"),
                                         QStringLiteral("2020-01-01"), QStringLiteral("--plan"), QStringLiteral("line plan"),
                                         QStringLiteral("--format"), QStringLiteral("jsonl"), QStringLiteral("--results"), m_pg.url()});
        QVERIFY2(jsonl.code == 0, qPrintable(jsonl.err));
        const QStringList records = jsonl.out.split(u'\n', Qt::SkipEmptyParts);
        QCOMPARE(records.size(), 16);
        for (const QString &line : records)
            QVERIFY(results::ModuleRecord::fromJson(QJsonDocument::fromJson(line.toUtf8()).object()));
    }

    // The server goes away before the modules finish: the station finishes, the results wait
    // in its SQLite and the count waiting is known; when the server is back each arrives once.
    void serverStoppedMidRun()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QMap<QString, sim::SimOptions> modules;
        QStringList ports;
        for (int i = 0; i < 4; ++i) {
            sim::SimOptions o;
            o.seed = 500 + i;
            ports << QStringLiteral("sim:line-%1").arg(i);
            modules.insert(ports.last(), o);
        }
        station::StationRunner runner(shortPlan(QStringLiteral("outage plan")), ports);
        runner.setTransportFactory([modules](const QString &port) -> std::unique_ptr<io::Transport> {
            if (!modules.contains(port))
                return nullptr;
            return std::make_unique<sim::SimulatedTransport>(std::make_unique<sim::HipnucSerialDevice>(modules.value(port)));
        });
        QString error;
        QVERIFY2(runner.setRunFolder(dir.filePath(QStringLiteral("run")), &error), qPrintable(error));
        results::UploaderOptions line;
        line.server = m_pg.url(QStringLiteral("imudesk_station"));
        line.firstRetryMs = 200;
        line.maxRetryMs = 800;
        line.pollMs = 200;
        runner.setLineDatabase(line);
        QSignalSpy done(&runner, &station::StationRunner::finished);
        runner.start();
        QVERIFY(runner.uploader());
        QTRY_VERIFY_WITH_TIMEOUT(runner.uploader()->connected(), 10000); // it reached the server once
        m_pg.stop();
        QVERIFY(done.wait(120000));
        // Every module finished; all four wait, and the uploader says it cannot reach the server.
        QSignalSpy state(runner.uploader(), &results::ResultsUploader::stateChanged);
        QVERIFY(state.wait(5000));
        QCOMPARE(state.last().at(0).toInt(), 4);
        QCOMPARE(state.last().at(1).toBool(), false);
        QVERIFY(!state.last().at(2).toString().isEmpty());
        QCOMPARE(runner.uploader()->pending(), 4);
        ResultsStore local;
        QVERIFY(local.open(dir.filePath(QStringLiteral("results.sqlite")), &error));
        QCOMPARE(local.pendingCount(), 4);
        QVERIFY2(m_pg.start(&error), qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(runner.resultsStore().pendingCount(), 0, 30000); // the outbox itself
        const QString inPlan = QStringLiteral("FROM module m JOIN run r ON r.uuid = m.run_uuid WHERE r.plan_name = 'outage plan'");
        QCOMPARE(count(m_pg, QStringLiteral("SELECT COUNT(*) ") + inPlan), 4);
        // The same again by hand (`results upload`, and a batch whose answer was lost): once.
        std::vector<results::ModuleRecord> again;
        for (const auto &m : local.search({}))
            again.push_back(*local.module(m.uuid));
        ResultsStore server;
        QVERIFY2(server.open(m_pg.url(QStringLiteral("imudesk_station")), &error), qPrintable(error));
        QVERIFY2(server.commit(again, &error), qPrintable(error));
        const auto upload = test::runCli({QStringLiteral("results"), QStringLiteral("upload"), QStringLiteral("--db"),
                                          dir.filePath(QStringLiteral("results.sqlite")), QStringLiteral("--results"),
                                          m_pg.url(QStringLiteral("imudesk_station"))});
        QVERIFY2(upload.code == 0, qPrintable(upload.err));
        QVERIFY2(upload.out.contains(QStringLiteral("0 uploaded")) && upload.out.contains(QStringLiteral("0 waiting")),
                 qPrintable(upload.out));
        QCOMPARE(count(m_pg, QStringLiteral("SELECT COUNT(*) ") + inPlan), 4);
        QCOMPARE(count(m_pg, QStringLiteral("SELECT COUNT(*) FROM step s JOIN module m ON m.uuid = s.module_uuid JOIN run r ON "
                                            "r.uuid = m.run_uuid WHERE r.plan_name = 'outage plan'")),
                 12);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstResultsLine)
#include "tst_results_line.moc"
