// bench_results: the results database (issue 38) on the station's SQLite and on a PostgreSQL
// server started here from Debian's package (tests/common/pg_server.h).
//
//   1. 1,000 module records (7 steps, 20 measurements and a report each) committed one by one
//      into the station's SQLite, as the station does, then uploaded to the server by the
//      uploader's code (batches of 100). Target: the upload in at most 10 s. Baseline in the
//      same run: the same records uploaded one per transaction to a second database.
//   2. Both databases filled to 100,000 measurements (5,000 modules), then the yield of a plan,
//      the history of a serial number (five attempts) and a measurement's series over every
//      module. Target: each at most 1 s on SQLite and on PostgreSQL. Baseline: a count over the
//      whole measurement table.
//
//   bench_results [--modules N]
//
// Exit status: 0 when every target is met, 1 otherwise, 2 when the server cannot start.
#include "../common/pg_server.h"
#include "../common/result_records.h"
#include "core/results/results_store.h"
#include "core/results/results_uploader.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>

#include <cstdio>

namespace {

using namespace imudesk;
using results::ModuleRecord;
using results::Outcome;
using results::ResultsStore;

const QString kPlan = QStringLiteral("bench plan");

// A module as a long plan leaves it: 7 steps, 20 measurements with limits, a report.
ModuleRecord benchModule(const results::RunRecord &run, int i)
{
    const Outcome outcome = i % 10 == 3 ? Outcome::Fail : i % 50 == 7 ? Outcome::Error : Outcome::Pass;
    ModuleRecord m = test::sampleModule(run, QStringLiteral("SN%1").arg(i / 5, 6, 10, QLatin1Char('0')), outcome,
                                        i % 3 ? QStringLiteral("1.7.1") : QStringLiteral("1.6.6"),
                                        QStringLiteral("/dev/ttyUSB%1").arg(i % 8), 1 + i % 5, i);
    m.measurements.clear();
    m.steps.resize(2);
    for (int s = 2; s < 7; ++s)
        m.steps.push_back({s, QStringLiteral("step%1").arg(s), QStringLiteral("Step %1").arg(s), Outcome::Pass, false,
                           QString(), m.started, m.finished});
    for (int k = 0; k < 20; ++k) {
        results::MeasurementRecord v;
        v.step = 1 + k % 6;
        v.name = QStringLiteral("value_%1").arg(k, 2, 10, QLatin1Char('0'));
        v.value = 0.01 + 0.001 * ((i * 7 + k * 13) % 17);
        v.unit = QStringLiteral("°/s");
        v.comparator = QStringLiteral("LE");
        v.high = 0.05;
        v.marginalHigh = 0.025;
        v.marginal = v.value > 0.025;
        v.outcome = outcome == Outcome::Fail && k == 0 ? Outcome::Fail : Outcome::Pass;
        m.marginal = m.marginal || (v.marginal && outcome == Outcome::Pass);
        m.measurements.push_back(v);
    }
    return m;
}

double seconds(const QElapsedTimer &t)
{
    return double(t.nsecsElapsed()) / 1e9;
}

bool g_ok = true;

void verdict(const char *what, double value, double target, const char *unit)
{
    const bool ok = value <= target;
    g_ok = g_ok && ok;
    std::printf("  %-46s %9.3f %s  (target <= %g %s) %s\n", what, value, unit, target, unit, ok ? "ok" : "!! MISSED");
}

// The three queries over a filled database, with the full-count baseline.
void queries(ResultsStore &db, const char *name)
{
    QElapsedTimer t;
    t.start();
    const auto y = db.yield(kPlan, {});
    const double yieldS = seconds(t);
    t.restart();
    const auto h = db.history(QStringLiteral("SN%1").arg(123, 6, 10, QLatin1Char('0')));
    const double historyS = seconds(t);
    t.restart();
    const auto s = db.series(kPlan, QStringLiteral("value_07"), {}, {});
    const double seriesS = seconds(t);
    std::printf("%s: yield %d pass / %d fail / %d error (%d marginal), history %zu attempts, series %zu points\n", name,
                y.total.pass, y.total.fail, y.total.error, y.total.marginal, h.size(), s.size());
    verdict("yield of the plan", yieldS, 1.0, "s");
    verdict("history of one serial number", historyS, 1.0, "s");
    verdict("series of one measurement", seriesS, 1.0, "s");
    if (h.size() != 5 || y.total.pass + y.total.fail + y.total.error == 0) {
        std::printf("  !! wrong answer\n");
        g_ok = false;
    }
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    int modules = 1000;
    const QStringList args = app.arguments();
    if (const int i = int(args.indexOf(QStringLiteral("--modules"))); i > 0 && i + 1 < args.size())
        modules = args.at(i + 1).toInt();
    if (modules <= 0) {
        std::fprintf(stderr, "usage: bench_results [--modules N]\n");
        return 2;
    }
    test::PgServer pg;
    QString error;
    if (!pg.start(&error) || !pg.psql(QStringLiteral("CREATE DATABASE baseline"), nullptr, &error)) {
        std::fprintf(stderr, "bench_results: %s\n", qPrintable(error));
        return 2;
    }
    QTemporaryDir dir;
    ResultsStore outbox, server, baseline;
    if (!outbox.open(dir.filePath(QStringLiteral("results.sqlite")), &error) || !server.open(pg.url(), &error)
        || !baseline.open(pg.url(QLatin1String(test::PgServer::kOwner), QStringLiteral("baseline")), &error)) {
        std::fprintf(stderr, "bench_results: %s\n", qPrintable(error));
        return 2;
    }

    std::printf("bench_results: %d module records, 20 measurements each\n", modules);
    results::RunRecord run = test::sampleRun(kPlan);
    std::vector<ModuleRecord> records;
    for (int i = 0; i < modules; ++i)
        records.push_back(benchModule(run, i));
    QElapsedTimer t;
    t.start();
    for (const ModuleRecord &m : records)
        if (!outbox.commit(m, &error)) {
            std::fprintf(stderr, "bench_results: %s\n", qPrintable(error));
            return 1;
        }
    const double stationS = seconds(t);
    std::printf("  station commits (one transaction each):        %9.3f s  (%.2f ms per module)\n", stationS,
                1e3 * stationS / modules);
    t.restart();
    int sent = 0;
    if (!results::uploadPending(outbox, server, QString(), 100, &sent, &error) || sent != modules) {
        std::fprintf(stderr, "bench_results: upload: %s (%d sent)\n", qPrintable(error), sent);
        return 1;
    }
    const double uploadS = seconds(t);
    t.restart();
    for (const ModuleRecord &m : records)
        baseline.commit(m, &error);
    const double baselineS = seconds(t);
    std::printf("  baseline, one module per transaction:          %9.3f s\n", baselineS);
    verdict("upload of the records (batches of 100)", uploadS, 10.0, "s");
    std::printf("  upload / baseline: %.2f\n", uploadS / baselineS);
    if (server.moduleCount() != modules || outbox.pendingCount() != 0) {
        std::printf("  !! %d modules on the server, %d waiting\n", server.moduleCount(), outbox.pendingCount());
        g_ok = false;
    }

    // Fill both to 100,000 measurements.
    const int total = 5000;
    std::vector<ModuleRecord> batch;
    for (int i = modules; i < total; ++i) {
        batch.push_back(benchModule(run, i));
        if (batch.size() == 500 || i + 1 == total) {
            if (!outbox.commit(batch, &error) || !server.commit(batch, &error)) {
                std::fprintf(stderr, "bench_results: %s\n", qPrintable(error));
                return 1;
            }
            batch.clear();
        }
    }
    for (ResultsStore *db : {&outbox, &server}) {
        QSqlDatabase conn = QSqlDatabase::addDatabase(db->kind() == ResultsStore::Kind::SQLite ? QStringLiteral("QSQLITE")
                                                                                              : QStringLiteral("QPSQL"),
                                                      QStringLiteral("bench-count"));
        if (db->kind() == ResultsStore::Kind::SQLite) {
            conn.setDatabaseName(db->location());
        } else {
            conn.setHostName(pg.socketDir());
            conn.setPort(pg.port());
            conn.setUserName(QLatin1String(test::PgServer::kOwner));
            conn.setDatabaseName(QStringLiteral("postgres"));
        }
        conn.open();
        {
            QSqlQuery q(conn);
            if (db->kind() == ResultsStore::Kind::PostgreSQL)
                q.exec(QStringLiteral("ANALYZE"));
            t.restart();
            q.exec(QStringLiteral("SELECT COUNT(*), SUM(value) FROM measurement"));
            q.next();
            std::printf("%s: %lld measurements; baseline full count %.3f s\n",
                        db->kind() == ResultsStore::Kind::SQLite ? "SQLite" : "PostgreSQL", q.value(0).toLongLong(), seconds(t));
        }
        conn.close();
        conn = QSqlDatabase();
        QSqlDatabase::removeDatabase(QStringLiteral("bench-count"));
        queries(*db, db->kind() == ResultsStore::Kind::SQLite ? "  SQLite" : "  PostgreSQL");
    }
    std::printf(g_ok ? "bench_results: every target met\n" : "bench_results: !! a target was missed\n");
    return g_ok ? 0 : 1;
}
