#include "results_store.h"

#include <QAtomicInt>
#include <QCoreApplication>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QVariant>

#include <cmath>
#include <limits>

namespace imudesk::results {

namespace {
QAtomicInt g_connections;

QString tr(const char *text)
{
    return QCoreApplication::translate("imudesk::results::ResultsStore", text);
}

QString iso(const QDateTime &t)
{
    return t.isValid() ? t.toUTC().toString(Qt::ISODateWithMs) : QString();
}
QDateTime fromIso(const QString &s)
{
    return s.isEmpty() ? QDateTime() : QDateTime::fromString(s, Qt::ISODateWithMs);
}
QVariant optional(const std::optional<double> &v)
{
    return v ? QVariant(*v) : QVariant(); // NULL
}

// Prepares sql, binds values in their order and runs it.
bool run(QSqlQuery &q, const QString &sql, std::initializer_list<QVariant> values)
{
    q.prepare(sql);
    for (const QVariant &v : values)
        q.addBindValue(v);
    return q.exec();
}

bool insertArtifact(QSqlQuery &q, const QString &moduleUuid, const ArtifactRecord &a)
{
    return run(q, QStringLiteral("INSERT OR REPLACE INTO artifact (module_uuid, kind, mime, sha256, location) VALUES (?, ?, ?, ?, ?)"),
               {moduleUuid, a.kind, a.mime, a.sha256, a.location});
}

constexpr const char *kSchema[] = {
    "CREATE TABLE IF NOT EXISTS schema_version (version INTEGER NOT NULL)",
    "CREATE TABLE IF NOT EXISTS run (uuid TEXT PRIMARY KEY, station_id TEXT, operator TEXT, plan_name TEXT, "
    "plan_sha256 TEXT, imudesk_version TEXT, started TEXT, finished TEXT)",
    "CREATE TABLE IF NOT EXISTS module (uuid TEXT PRIMARY KEY, run_uuid TEXT NOT NULL REFERENCES run(uuid), slot TEXT, "
    "serial TEXT, product TEXT, firmware_before TEXT, firmware_after TEXT, attempt INTEGER, outcome TEXT NOT NULL, "
    "started TEXT, finished TEXT, uploaded INTEGER NOT NULL DEFAULT 0)",
    "CREATE INDEX IF NOT EXISTS module_serial ON module(serial)",
    "CREATE INDEX IF NOT EXISTS module_run ON module(run_uuid)",
    "CREATE TABLE IF NOT EXISTS step (module_uuid TEXT NOT NULL REFERENCES module(uuid), idx INTEGER NOT NULL, "
    "kind TEXT, name TEXT, outcome TEXT, skipped INTEGER, detail TEXT, started TEXT, finished TEXT, "
    "PRIMARY KEY (module_uuid, idx))",
    "CREATE TABLE IF NOT EXISTS measurement (module_uuid TEXT NOT NULL REFERENCES module(uuid), step INTEGER NOT NULL, "
    "name TEXT NOT NULL, value REAL, unit TEXT, comparator TEXT, low REAL, high REAL, outcome TEXT, "
    "PRIMARY KEY (module_uuid, step, name))",
    "CREATE INDEX IF NOT EXISTS measurement_name ON measurement(name)",
    "CREATE TABLE IF NOT EXISTS artifact (module_uuid TEXT NOT NULL REFERENCES module(uuid), kind TEXT NOT NULL, "
    "mime TEXT, sha256 TEXT, location TEXT, PRIMARY KEY (module_uuid, kind))",
};
} // namespace

double ResultsStore::Counts::yield() const
{
    return pass + fail > 0 ? double(pass) / double(pass + fail) : std::numeric_limits<double>::quiet_NaN();
}

ResultsStore::ResultsStore() : m_connection(QStringLiteral("imudesk-results-%1").arg(g_connections.fetchAndAddRelaxed(1))) {}

ResultsStore::~ResultsStore()
{
    close();
}

bool ResultsStore::isOpen() const
{
    return QSqlDatabase::contains(m_connection) && QSqlDatabase::database(m_connection, false).isOpen();
}

void ResultsStore::close()
{
    if (!QSqlDatabase::contains(m_connection))
        return;
    QSqlDatabase::database(m_connection, false).close();
    QSqlDatabase::removeDatabase(m_connection);
}

bool ResultsStore::exec(const QString &sql, QString *error) const
{
    QSqlQuery q(QSqlDatabase::database(m_connection, false));
    if (q.exec(sql))
        return true;
    if (error)
        *error = q.lastError().text();
    return false;
}

bool ResultsStore::open(const QString &path, QString *error)
{
    close();
    m_path = path;
    if (!QSqlDatabase::isDriverAvailable(QStringLiteral("QSQLITE"))) {
        if (error)
            *error = tr("Qt's SQLite driver is not installed (on Debian: the package libqt6sql6-sqlite).");
        return false;
    }
    QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), m_connection);
    db.setDatabaseName(path);
    if (!db.open()) {
        if (error)
            *error = tr("Cannot open the results database %1: %2").arg(path, db.lastError().text());
        close();
        return false;
    }
    // Writers wait for each other (two stations' processes on one file) instead of failing.
    exec(QStringLiteral("PRAGMA busy_timeout = 5000"), nullptr);
    exec(QStringLiteral("PRAGMA foreign_keys = ON"), nullptr);
    for (const char *sql : kSchema)
        if (!exec(QString::fromLatin1(sql), error)) {
            close();
            return false;
        }
    QSqlQuery v(db);
    if (v.exec(QStringLiteral("SELECT version FROM schema_version")) && !v.next()) {
        QSqlQuery put(db);
        put.prepare(QStringLiteral("INSERT INTO schema_version (version) VALUES (?)"));
        put.addBindValue(kSchemaVersion);
        put.exec();
    } else if (v.isValid() && v.value(0).toInt() > kSchemaVersion) {
        if (error)
            *error = tr("%1 was written by a newer ImuDesk (schema %2; this one knows %3): update ImuDesk to use it")
                         .arg(path).arg(v.value(0).toInt()).arg(kSchemaVersion);
        close();
        return false;
    }
    return true;
}

bool ResultsStore::commit(const ModuleRecord &m, QString *error)
{
    QSqlDatabase db = QSqlDatabase::database(m_connection, false);
    if (!db.isOpen()) {
        if (error)
            *error = tr("the results database is not open");
        return false;
    }
    const auto failed = [&](const QSqlQuery &q) {
        if (error)
            *error = tr("Storing the result of %1 in %2 failed: %3. It is still in the run folder.").arg(m.serial, m_path, q.lastError().text());
        db.rollback();
        return false;
    };
    if (!db.transaction()) {
        if (error)
            *error = db.lastError().text();
        return false;
    }
    QSqlQuery q(db);
    if (!run(q, QStringLiteral("SELECT 1 FROM module WHERE uuid = ?"), {m.uuid}))
        return failed(q);
    if (q.next()) { // stored already: nothing to do
        db.rollback();
        return true;
    }
    if (!run(q,
             QStringLiteral("INSERT OR IGNORE INTO run (uuid, station_id, operator, plan_name, plan_sha256, imudesk_version, "
                            "started, finished) VALUES (?, ?, ?, ?, ?, ?, ?, ?)"),
             {m.run.uuid, m.run.stationId, m.run.operatorName, m.run.planName, m.run.planSha256, m.run.imudeskVersion,
              iso(m.run.started), iso(m.run.finished)}))
        return failed(q);
    if (!run(q,
             QStringLiteral("INSERT INTO module (uuid, run_uuid, slot, serial, product, firmware_before, firmware_after, "
                            "attempt, outcome, started, finished) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"),
             {m.uuid, m.run.uuid, m.slot, m.serial, m.product, m.firmwareBefore, m.firmwareAfter, m.attempt,
              outcomeKey(m.outcome), iso(m.started), iso(m.finished)}))
        return failed(q);
    for (const StepRecord &s : m.steps)
        if (!run(q,
                 QStringLiteral("INSERT INTO step (module_uuid, idx, kind, name, outcome, skipped, detail, started, finished) "
                                "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)"),
                 {m.uuid, s.index, s.kind, s.name, outcomeKey(s.outcome), s.skipped ? 1 : 0, s.detail, iso(s.started),
                  iso(s.finished)}))
            return failed(q);
    for (const MeasurementRecord &v : m.measurements)
        if (!run(q,
                 QStringLiteral("INSERT OR REPLACE INTO measurement (module_uuid, step, name, value, unit, comparator, low, "
                                "high, outcome) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)"),
                 {m.uuid, v.step, v.name, v.value, v.unit, v.comparator, optional(v.low), optional(v.high),
                  outcomeKey(v.outcome)}))
            return failed(q);
    for (const ArtifactRecord &a : m.artifacts)
        if (!insertArtifact(q, m.uuid, a))
            return failed(q);
    if (!db.commit()) {
        if (error)
            *error = tr("Storing the result of %1 in %2 failed: %3. It is still in the run folder.").arg(m.serial, m_path, db.lastError().text());
        db.rollback();
        return false;
    }
    return true;
}

bool ResultsStore::addArtifact(const QString &moduleUuid, const ArtifactRecord &a, QString *error)
{
    QSqlQuery q(QSqlDatabase::database(m_connection, false));
    if (insertArtifact(q, moduleUuid, a))
        return true;
    if (error)
        *error = q.lastError().text();
    return false;
}

int ResultsStore::moduleCount() const
{
    QSqlQuery q(QSqlDatabase::database(m_connection, false));
    return q.exec(QStringLiteral("SELECT COUNT(*) FROM module")) && q.next() ? q.value(0).toInt() : 0;
}

std::vector<ModuleRecord> ResultsStore::history(const QString &serial, QString *error) const
{
    std::vector<ModuleRecord> out;
    QSqlDatabase db = QSqlDatabase::database(m_connection, false);
    QSqlQuery q(db);
    q.prepare(QStringLiteral("SELECT m.uuid, m.slot, m.serial, m.product, m.firmware_before, m.firmware_after, m.attempt, "
                             "m.outcome, m.started, m.finished, r.uuid, r.station_id, r.operator, r.plan_name, "
                             "r.plan_sha256, r.imudesk_version, r.started, r.finished FROM module m JOIN run r "
                             "ON r.uuid = m.run_uuid WHERE m.serial = ? ORDER BY m.started, m.attempt"));
    q.addBindValue(serial);
    if (!q.exec()) {
        if (error)
            *error = q.lastError().text();
        return out;
    }
    while (q.next()) {
        ModuleRecord m;
        m.uuid = q.value(0).toString();
        m.slot = q.value(1).toString();
        m.serial = q.value(2).toString();
        m.product = q.value(3).toString();
        m.firmwareBefore = q.value(4).toString();
        m.firmwareAfter = q.value(5).toString();
        m.attempt = q.value(6).toInt();
        m.outcome = outcomeFromKey(q.value(7).toString()).value_or(Outcome::Error);
        m.started = fromIso(q.value(8).toString());
        m.finished = fromIso(q.value(9).toString());
        m.run = {q.value(10).toString(), q.value(11).toString(), q.value(12).toString(), q.value(13).toString(),
                 q.value(14).toString(), q.value(15).toString(), fromIso(q.value(16).toString()),
                 fromIso(q.value(17).toString())};
        out.push_back(std::move(m));
    }
    for (ModuleRecord &m : out) {
        QSqlQuery s(db);
        s.prepare(QStringLiteral("SELECT idx, kind, name, outcome, skipped, detail, started, finished FROM step "
                                 "WHERE module_uuid = ? ORDER BY idx"));
        s.addBindValue(m.uuid);
        if (s.exec())
            while (s.next())
                m.steps.push_back({s.value(0).toInt(), s.value(1).toString(), s.value(2).toString(),
                                   outcomeFromKey(s.value(3).toString()).value_or(Outcome::Error), s.value(4).toInt() != 0,
                                   s.value(5).toString(), fromIso(s.value(6).toString()), fromIso(s.value(7).toString())});
        s.prepare(QStringLiteral("SELECT step, name, value, unit, comparator, low, high, outcome FROM measurement "
                                 "WHERE module_uuid = ? ORDER BY step, name"));
        s.addBindValue(m.uuid);
        if (s.exec())
            while (s.next()) {
                MeasurementRecord v;
                v.step = s.value(0).toInt();
                v.name = s.value(1).toString();
                v.value = s.value(2).toDouble();
                v.unit = s.value(3).toString();
                v.comparator = s.value(4).toString();
                if (!s.value(5).isNull())
                    v.low = s.value(5).toDouble();
                if (!s.value(6).isNull())
                    v.high = s.value(6).toDouble();
                v.outcome = outcomeFromKey(s.value(7).toString()).value_or(Outcome::Error);
                m.measurements.push_back(v);
            }
        s.prepare(QStringLiteral("SELECT kind, mime, sha256, location FROM artifact WHERE module_uuid = ? ORDER BY kind"));
        s.addBindValue(m.uuid);
        if (s.exec())
            while (s.next())
                m.artifacts.push_back({s.value(0).toString(), s.value(1).toString(), s.value(2).toString(), s.value(3).toString()});
    }
    return out;
}

ResultsStore::Yield ResultsStore::yield(const QString &planName, const QDateTime &since, QString *error) const
{
    Yield y;
    QSqlQuery q(QSqlDatabase::database(m_connection, false));
    q.prepare(QStringLiteral("SELECT m.firmware_before, m.slot, m.outcome, COUNT(*) FROM module m JOIN run r "
                             "ON r.uuid = m.run_uuid WHERE r.plan_name = ? AND COALESCE(m.started, '') >= ? "
                             "GROUP BY m.firmware_before, m.slot, m.outcome"));
    q.addBindValue(planName);
    q.addBindValue(since.isValid() ? iso(since) : QStringLiteral("")); // "" (not NULL): every time is later
    if (!q.exec()) {
        if (error)
            *error = q.lastError().text();
        return y;
    }
    while (q.next()) {
        const int n = q.value(3).toInt();
        const auto add = [n, &q](Counts &c) {
            switch (outcomeFromKey(q.value(2).toString()).value_or(Outcome::Error)) {
            case Outcome::Pass: c.pass += n; break;
            case Outcome::Fail: c.fail += n; break;
            case Outcome::Error: c.error += n; break;
            case Outcome::Aborted: c.aborted += n; break;
            }
        };
        add(y.total);
        add(y.byFirmware[q.value(0).toString()]);
        add(y.bySlot[q.value(1).toString()]);
    }
    return y;
}

} // namespace imudesk::results
