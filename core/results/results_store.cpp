#include "results_store.h"

#include <QAtomicInt>
#include <QCoreApplication>
#include <QSqlDatabase>
#include <QSqlDriver>
#include <QSqlError>
#include <QSqlQuery>
#include <QUrl>
#include <QUrlQuery>
#include <QVariant>

#include <algorithm>
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
std::optional<double> optionalOf(const QVariant &v)
{
    return v.isNull() ? std::nullopt : std::optional<double>(v.toDouble());
}

// Prepares sql, binds values in their order and runs it.
bool run(QSqlQuery &q, const QString &sql, const QVariantList &values)
{
    if (!q.prepare(sql))
        return false;
    for (const QVariant &v : values)
        q.addBindValue(v);
    return q.exec();
}

// The schema's versions: each list turns the one before it into the next. {BLOB} and {REAL} are
// the dialect's names for bytes and doubles (PostgreSQL's REAL is single precision).
const std::vector<std::vector<const char *>> &migrations()
{
    static const std::vector<std::vector<const char *>> m{
        {
            "CREATE TABLE IF NOT EXISTS schema_version (version INTEGER NOT NULL)",
            "CREATE TABLE IF NOT EXISTS run (uuid TEXT PRIMARY KEY, station_id TEXT, operator TEXT, plan_name TEXT, "
            "plan_sha256 TEXT, imudesk_version TEXT, started TEXT, finished TEXT)",
            "CREATE TABLE IF NOT EXISTS module (uuid TEXT PRIMARY KEY, run_uuid TEXT NOT NULL REFERENCES run(uuid), "
            "slot TEXT, serial TEXT, product TEXT, firmware_before TEXT, firmware_after TEXT, attempt INTEGER, "
            "outcome TEXT NOT NULL, started TEXT, finished TEXT, uploaded INTEGER NOT NULL DEFAULT 0)",
            "CREATE INDEX IF NOT EXISTS module_serial ON module(serial)",
            "CREATE INDEX IF NOT EXISTS module_run ON module(run_uuid)",
            "CREATE TABLE IF NOT EXISTS step (module_uuid TEXT NOT NULL REFERENCES module(uuid), idx INTEGER NOT NULL, "
            "kind TEXT, name TEXT, outcome TEXT, skipped INTEGER, detail TEXT, started TEXT, finished TEXT, "
            "PRIMARY KEY (module_uuid, idx))",
            "CREATE TABLE IF NOT EXISTS measurement (module_uuid TEXT NOT NULL REFERENCES module(uuid), "
            "step INTEGER NOT NULL, name TEXT NOT NULL, value {REAL}, unit TEXT, comparator TEXT, low {REAL}, "
            "high {REAL}, outcome TEXT, PRIMARY KEY (module_uuid, step, name))",
            "CREATE INDEX IF NOT EXISTS measurement_name ON measurement(name)",
            "CREATE TABLE IF NOT EXISTS artifact (module_uuid TEXT NOT NULL REFERENCES module(uuid), "
            "kind TEXT NOT NULL, mime TEXT, sha256 TEXT, location TEXT, PRIMARY KEY (module_uuid, kind))",
        },
        {
            // 2: the marginal band, the serial's bytes, the outbox's revision, and indexes for
            // the results window's searches.
            "ALTER TABLE module ADD COLUMN serial_raw {BLOB}",
            "ALTER TABLE module ADD COLUMN marginal INTEGER NOT NULL DEFAULT 0",
            "ALTER TABLE module ADD COLUMN rev INTEGER NOT NULL DEFAULT 1",
            "ALTER TABLE measurement ADD COLUMN marginal_low {REAL}",
            "ALTER TABLE measurement ADD COLUMN marginal_high {REAL}",
            "ALTER TABLE measurement ADD COLUMN marginal INTEGER NOT NULL DEFAULT 0",
            "CREATE INDEX IF NOT EXISTS module_started ON module(started)",
            "CREATE INDEX IF NOT EXISTS module_pending ON module(uploaded, rev)",
            "CREATE INDEX IF NOT EXISTS run_plan ON run(plan_name)",
        },
    };
    return m;
}

// An INSERT of many rows in one statement (one round trip to a server instead of one per row),
// prepared once per row count; a row already there is left as it is.
class RowsInsert {
public:
    RowsInsert(const QSqlDatabase &db, const char *head, int columns) : m_db(db), m_head(QString::fromLatin1(head)), m_columns(columns) {}

    // values: the rows one after the other, `columns` each.
    bool insert(const QVariantList &values, QString *why)
    {
        const int rows = int(values.size()) / m_columns;
        for (int first = 0; first < rows; first += kMaxRows) {
            const int n = std::min(kMaxRows, rows - first);
            QSqlQuery &q = query(n);
            for (int i = 0; i < n * m_columns; ++i)
                q.bindValue(i, values[first * m_columns + i]);
            if (!q.exec()) {
                *why = q.lastError().text().trimmed();
                return false;
            }
        }
        return true;
    }

private:
    static constexpr int kMaxRows = 50;

    QSqlQuery &query(int rows)
    {
        auto it = m_prepared.find(rows);
        if (it == m_prepared.end()) {
            QStringList marks(m_columns, QStringLiteral("?"));
            const QString row = QLatin1Char('(') + marks.join(QStringLiteral(", ")) + QLatin1Char(')');
            QStringList all(rows, row);
            QSqlQuery q(m_db);
            q.prepare(m_head + QStringLiteral(" VALUES ") + all.join(QStringLiteral(", ")) + QStringLiteral(" ON CONFLICT DO NOTHING"));
            it = m_prepared.emplace(rows, std::move(q)).first;
        }
        return it->second;
    }

    QSqlDatabase m_db;
    QString m_head;
    int m_columns;
    std::map<int, QSqlQuery> m_prepared;
};

constexpr const char *kArtifactInsert = "INSERT INTO artifact (module_uuid, kind, mime, sha256, location)";

constexpr const char *kModuleColumns =
    "m.uuid, m.slot, m.serial, m.product, m.firmware_before, m.firmware_after, m.attempt, m.outcome, m.started, "
    "m.finished, r.uuid, r.station_id, r.operator, r.plan_name, r.plan_sha256, r.imudesk_version, r.started, "
    "r.finished, m.serial_raw, m.marginal";

ModuleRecord moduleFromRow(const QSqlQuery &q)
{
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
    m.serialRaw = q.value(18).toByteArray();
    m.marginal = q.value(19).toInt() != 0;
    return m;
}

void addCount(ResultsStore::Counts &c, Outcome o, bool marginal, int n)
{
    switch (o) {
    case Outcome::Pass: c.pass += n; c.marginal += marginal ? n : 0; break;
    case Outcome::Fail: c.fail += n; break;
    case Outcome::Error: c.error += n; break;
    case Outcome::Aborted: c.aborted += n; break;
    }
}
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

bool ResultsStore::isServerUrl(const QString &location)
{
    return location.startsWith(QLatin1String("postgresql://")) || location.startsWith(QLatin1String("postgres://"));
}

QString ResultsStore::displayLocation(const QString &location)
{
    if (!isServerUrl(location))
        return location;
    QUrl url(location);
    url.setPassword(QString());
    return url.toString();
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

QString ResultsStore::dialect(const char *sql) const
{
    QString s = QString::fromLatin1(sql);
    const bool pg = m_kind == Kind::PostgreSQL;
    s.replace(QLatin1String("{BLOB}"), pg ? QLatin1String("BYTEA") : QLatin1String("BLOB"));
    s.replace(QLatin1String("{REAL}"), pg ? QLatin1String("DOUBLE PRECISION") : QLatin1String("REAL"));
    return s;
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

int ResultsStore::readVersion() const
{
    QSqlDatabase db = QSqlDatabase::database(m_connection, false);
    if (!db.tables().contains(QStringLiteral("schema_version")))
        return 0;
    QSqlQuery v(db);
    return v.exec(QStringLiteral("SELECT MAX(version) FROM schema_version")) && v.next() ? v.value(0).toInt() : 0;
}

bool ResultsStore::migrate(QString *error)
{
    QSqlDatabase db = QSqlDatabase::database(m_connection, false);
    if (!db.transaction()) {
        if (error)
            *error = db.lastError().text();
        return false;
    }
    // Stations that start together against a new server: one creates the schema, the others
    // wait for it and find it made.
    if (m_kind == Kind::PostgreSQL)
        exec(QStringLiteral("SELECT pg_advisory_xact_lock(38038)"), nullptr);
    m_version = readVersion();
    const auto &steps = migrations();
    QString why;
    for (int v = m_version; v < int(steps.size()); ++v) {
        for (const char *sql : steps[size_t(v)])
            if (!exec(dialect(sql), &why)) {
                db.rollback();
                if (error)
                    *error = tr("Updating the results database %1 to schema %2 failed: %3")
                                 .arg(displayLocation(m_location)).arg(v + 1).arg(why);
                return false;
            }
        exec(QStringLiteral("DELETE FROM schema_version"), nullptr);
        QSqlQuery put(db);
        if (!run(put, QStringLiteral("INSERT INTO schema_version (version) VALUES (?)"), {v + 1})) {
            db.rollback();
            if (error)
                *error = put.lastError().text();
            return false;
        }
    }
    if (!db.commit()) {
        if (error)
            *error = db.lastError().text();
        db.rollback();
        return false;
    }
    m_version = kSchemaVersion;
    return true;
}

bool ResultsStore::open(const QString &location, QString *error, bool allowMigration)
{
    close();
    m_location = location;
    m_kind = isServerUrl(location) ? Kind::PostgreSQL : Kind::SQLite;
    const QString driver = m_kind == Kind::PostgreSQL ? QStringLiteral("QPSQL") : QStringLiteral("QSQLITE");
    if (!QSqlDatabase::isDriverAvailable(driver)) {
        if (error)
            *error = m_kind == Kind::PostgreSQL
                ? tr("Qt's PostgreSQL driver is not installed (on Debian: the package libqt6sql6-psql).")
                : tr("Qt's SQLite driver is not installed (on Debian: the package libqt6sql6-sqlite).");
        return false;
    }
    QSqlDatabase db = QSqlDatabase::addDatabase(driver, m_connection);
    // Gives up the connection (this handle first: a connection still referenced cannot go).
    const auto giveUp = [&] {
        db = QSqlDatabase();
        close();
        return false;
    };
    if (m_kind == Kind::PostgreSQL) {
        const QUrl url(location);
        const QUrlQuery query(url);
        // ?host=/run/postgresql names a socket folder (libpq's rule: a host starting with '/').
        db.setHostName(query.hasQueryItem(QStringLiteral("host")) ? query.queryItemValue(QStringLiteral("host"), QUrl::FullyDecoded)
                                                                  : url.host());
        if (url.port() > 0)
            db.setPort(url.port());
        else if (query.hasQueryItem(QStringLiteral("port")))
            db.setPort(query.queryItemValue(QStringLiteral("port")).toInt());
        db.setUserName(url.userName(QUrl::FullyDecoded));
        db.setPassword(url.password(QUrl::FullyDecoded));
        db.setDatabaseName(url.path(QUrl::FullyDecoded).mid(1));
        db.setConnectOptions(QStringLiteral("connect_timeout=5;application_name=imudesk"));
    } else {
        db.setDatabaseName(location);
    }
    if (!db.open()) {
        if (error)
            *error = tr("Cannot open the results database %1: %2").arg(displayLocation(location), db.lastError().text().trimmed());
        return giveUp();
    }
    if (m_kind == Kind::SQLite) {
        // Writers wait for each other (the station and its uploader) instead of failing.
        exec(QStringLiteral("PRAGMA busy_timeout = 10000"), nullptr);
        exec(QStringLiteral("PRAGMA journal_mode = WAL"), nullptr);
        exec(QStringLiteral("PRAGMA foreign_keys = ON"), nullptr);
    }
    m_version = readVersion();
    if (m_version > kSchemaVersion) {
        if (error)
            *error = tr("%1 was written by a newer ImuDesk (schema %2; this one knows %3): update ImuDesk to use it")
                         .arg(displayLocation(location)).arg(m_version).arg(kSchemaVersion);
        return giveUp();
    }
    if (m_version < kSchemaVersion) {
        if (!allowMigration) {
            if (error)
                *error = tr("The results database %1 has schema %2, this ImuDesk needs %3: have its owner run "
                            "\"imudesk-cli results setup\" on it.")
                             .arg(displayLocation(location)).arg(m_version).arg(kSchemaVersion);
            return giveUp();
        }
        if (!migrate(error))
            return giveUp();
    }
    return true;
}

bool ResultsStore::commit(const ModuleRecord &m, QString *error)
{
    return commit(std::vector<ModuleRecord>{m}, error);
}

bool ResultsStore::commit(const std::vector<ModuleRecord> &modules, QString *error)
{
    QSqlDatabase db = QSqlDatabase::database(m_connection, false);
    if (!db.isOpen()) {
        if (error)
            *error = tr("the results database is not open");
        return false;
    }
    if (!db.transaction()) {
        if (error)
            *error = db.lastError().text();
        return false;
    }
    const ModuleRecord *current = nullptr;
    const auto failed = [&](const QString &why) {
        if (error)
            *error = tr("Storing the result of %1 in %2 failed: %3. It is still in the run folder.")
                         .arg(current ? current->serial : QString(), displayLocation(m_location), why);
        db.rollback();
        return false;
    };
    // One prepared statement per table for the whole batch, a module's steps and measurements
    // each in one statement.
    RowsInsert runs(db, "INSERT INTO run (uuid, station_id, operator, plan_name, plan_sha256, imudesk_version, started, finished)", 8);
    RowsInsert mods(db, "INSERT INTO module (uuid, run_uuid, slot, serial, product, firmware_before, firmware_after, attempt, "
                        "outcome, started, finished, serial_raw, marginal)", 13);
    RowsInsert steps(db, "INSERT INTO step (module_uuid, idx, kind, name, outcome, skipped, detail, started, finished)", 9);
    RowsInsert values(db, "INSERT INTO measurement (module_uuid, step, name, value, unit, comparator, low, high, outcome, "
                          "marginal_low, marginal_high, marginal)", 12);
    RowsInsert files(db, kArtifactInsert, 5);
    QString why;
    for (const ModuleRecord &m : modules) {
        current = &m;
        if (!runs.insert({m.run.uuid, m.run.stationId, m.run.operatorName, m.run.planName, m.run.planSha256,
                          m.run.imudeskVersion, iso(m.run.started), iso(m.run.finished)},
                         &why))
            return failed(why);
        if (!mods.insert({m.uuid, m.run.uuid, m.slot, m.serial, m.product, m.firmwareBefore, m.firmwareAfter, m.attempt,
                          outcomeKey(m.outcome), iso(m.started), iso(m.finished),
                          m.serialRaw.isNull() ? QVariant(QByteArray("")) : QVariant(m.serialRaw), m.marginal ? 1 : 0},
                         &why))
            return failed(why);
        QVariantList rows;
        for (const StepRecord &s : m.steps)
            rows << m.uuid << s.index << s.kind << s.name << outcomeKey(s.outcome) << (s.skipped ? 1 : 0) << s.detail
                 << iso(s.started) << iso(s.finished);
        if (!steps.insert(rows, &why))
            return failed(why);
        rows.clear();
        for (const MeasurementRecord &v : m.measurements)
            rows << m.uuid << v.step << v.name << v.value << v.unit << v.comparator << optional(v.low) << optional(v.high)
                 << outcomeKey(v.outcome) << optional(v.marginalLow) << optional(v.marginalHigh) << (v.marginal ? 1 : 0);
        if (!values.insert(rows, &why))
            return failed(why);
        rows.clear();
        for (const ArtifactRecord &a : m.artifacts)
            rows << m.uuid << a.kind << a.mime << a.sha256 << a.location;
        if (!files.insert(rows, &why))
            return failed(why);
    }
    if (!db.commit()) {
        if (error)
            *error = tr("Storing results in %1 failed: %2. They are still in the run folder.")
                         .arg(displayLocation(m_location), db.lastError().text().trimmed());
        db.rollback();
        return false;
    }
    return true;
}

bool ResultsStore::addArtifact(const QString &moduleUuid, const ArtifactRecord &a, QString *error)
{
    QSqlDatabase db = QSqlDatabase::database(m_connection, false);
    db.transaction();
    QSqlQuery q(db);
    QString why;
    if (RowsInsert(db, kArtifactInsert, 5).insert({moduleUuid, a.kind, a.mime, a.sha256, a.location}, &why)
        && (m_kind == Kind::PostgreSQL
            || run(q, QStringLiteral("UPDATE module SET rev = rev + 1 WHERE uuid = ?"), {moduleUuid}))
        && db.commit())
        return true;
    if (error)
        *error = why.isEmpty() ? q.lastError().text() : why;
    db.rollback();
    return false;
}

int ResultsStore::moduleCount() const
{
    QSqlQuery q(QSqlDatabase::database(m_connection, false));
    return q.exec(QStringLiteral("SELECT COUNT(*) FROM module")) && q.next() ? q.value(0).toInt() : 0;
}

std::vector<std::pair<QString, int>> ResultsStore::pendingUploads(int limit, QString *error) const
{
    std::vector<std::pair<QString, int>> out;
    QSqlQuery q(QSqlDatabase::database(m_connection, false));
    if (!run(q, QStringLiteral("SELECT uuid, rev FROM module WHERE uploaded < rev ORDER BY started, uuid LIMIT ?"), {limit})) {
        if (error)
            *error = q.lastError().text();
        return out;
    }
    while (q.next())
        out.emplace_back(q.value(0).toString(), q.value(1).toInt());
    return out;
}

int ResultsStore::pendingCount() const
{
    QSqlQuery q(QSqlDatabase::database(m_connection, false));
    return q.exec(QStringLiteral("SELECT COUNT(*) FROM module WHERE uploaded < rev")) && q.next() ? q.value(0).toInt() : 0;
}

bool ResultsStore::markUploaded(const QString &moduleUuid, int revision, QString *error)
{
    return markUploaded(std::vector<std::pair<QString, int>>{{moduleUuid, revision}}, error);
}

bool ResultsStore::markUploaded(const std::vector<std::pair<QString, int>> &modules, QString *error)
{
    QSqlDatabase db = QSqlDatabase::database(m_connection, false);
    db.transaction();
    QSqlQuery q(db);
    q.prepare(QStringLiteral("UPDATE module SET uploaded = ? WHERE uuid = ? AND uploaded < ?"));
    for (const auto &[uuid, revision] : modules) {
        q.bindValue(0, revision);
        q.bindValue(1, uuid);
        q.bindValue(2, revision);
        if (!q.exec()) {
            if (error)
                *error = q.lastError().text();
            db.rollback();
            return false;
        }
    }
    if (db.commit())
        return true;
    if (error)
        *error = db.lastError().text();
    db.rollback();
    return false;
}

void ResultsStore::fillChildren(ModuleRecord &m) const
{
    QSqlQuery s(QSqlDatabase::database(m_connection, false));
    if (run(s, QStringLiteral("SELECT idx, kind, name, outcome, skipped, detail, started, finished FROM step "
                              "WHERE module_uuid = ? ORDER BY idx"),
            {m.uuid}))
        while (s.next())
            m.steps.push_back({s.value(0).toInt(), s.value(1).toString(), s.value(2).toString(),
                               outcomeFromKey(s.value(3).toString()).value_or(Outcome::Error), s.value(4).toInt() != 0,
                               s.value(5).toString(), fromIso(s.value(6).toString()), fromIso(s.value(7).toString())});
    if (run(s, QStringLiteral("SELECT step, name, value, unit, comparator, low, high, outcome, marginal_low, "
                              "marginal_high, marginal FROM measurement WHERE module_uuid = ? ORDER BY step, name"),
            {m.uuid}))
        while (s.next()) {
            MeasurementRecord v;
            v.step = s.value(0).toInt();
            v.name = s.value(1).toString();
            v.value = s.value(2).toDouble();
            v.unit = s.value(3).toString();
            v.comparator = s.value(4).toString();
            v.low = optionalOf(s.value(5));
            v.high = optionalOf(s.value(6));
            v.outcome = outcomeFromKey(s.value(7).toString()).value_or(Outcome::Error);
            v.marginalLow = optionalOf(s.value(8));
            v.marginalHigh = optionalOf(s.value(9));
            v.marginal = s.value(10).toInt() != 0;
            m.measurements.push_back(v);
        }
    if (run(s, QStringLiteral("SELECT kind, mime, sha256, location FROM artifact WHERE module_uuid = ? ORDER BY kind"), {m.uuid}))
        while (s.next())
            m.artifacts.push_back({s.value(0).toString(), s.value(1).toString(), s.value(2).toString(), s.value(3).toString()});
}

std::vector<ModuleRecord> ResultsStore::selectModules(const QString &where, const QVariantList &values, const QString &order,
                                                      int limit, QString *error) const
{
    std::vector<ModuleRecord> out;
    QSqlQuery q(QSqlDatabase::database(m_connection, false));
    q.setForwardOnly(true);
    QString sql = QStringLiteral("SELECT %1 FROM module m JOIN run r ON r.uuid = m.run_uuid").arg(QLatin1String(kModuleColumns));
    if (!where.isEmpty())
        sql += QStringLiteral(" WHERE ") + where;
    sql += QStringLiteral(" ORDER BY ") + order;
    if (limit > 0)
        sql += QStringLiteral(" LIMIT %1").arg(limit);
    if (!run(q, sql, values)) {
        if (error)
            *error = q.lastError().text();
        return out;
    }
    while (q.next())
        out.push_back(moduleFromRow(q));
    return out;
}

std::optional<ModuleRecord> ResultsStore::module(const QString &uuid, QString *error) const
{
    auto found = selectModules(QStringLiteral("m.uuid = ?"), {uuid}, QStringLiteral("m.uuid"), 1, error);
    if (found.empty())
        return std::nullopt;
    fillChildren(found.front());
    return std::move(found.front());
}

std::vector<ModuleRecord> ResultsStore::history(const QString &serial, QString *error) const
{
    auto out = selectModules(QStringLiteral("m.serial = ?"), {serial}, QStringLiteral("m.started, m.attempt"), 0, error);
    for (ModuleRecord &m : out)
        fillChildren(m);
    return out;
}

namespace {
// The WHERE clause of a filter, with its values.
std::pair<QString, QVariantList> whereOf(const ResultsStore::Filter &f)
{
    QStringList parts;
    QVariantList values;
    if (!f.serial.isEmpty()) {
        // A part of the serial, taken literally (its % and _ are no wildcards).
        QString pattern = f.serial;
        pattern.replace(QLatin1Char('!'), QLatin1String("!!")).replace(QLatin1Char('%'), QLatin1String("!%")).replace(QLatin1Char('_'), QLatin1String("!_"));
        parts << QStringLiteral("m.serial LIKE ? ESCAPE '!'");
        values << QStringLiteral("%") + pattern + QStringLiteral("%");
    }
    if (!f.plan.isEmpty()) {
        parts << QStringLiteral("r.plan_name = ?");
        values << f.plan;
    }
    if (!f.station.isEmpty()) {
        parts << QStringLiteral("r.station_id = ?");
        values << f.station;
    }
    if (f.from.isValid()) {
        parts << QStringLiteral("m.started >= ?");
        values << iso(f.from);
    }
    if (f.to.isValid()) {
        parts << QStringLiteral("m.started <= ?");
        values << iso(f.to);
    }
    return {parts.join(QStringLiteral(" AND ")), values};
}
} // namespace

std::vector<ModuleRecord> ResultsStore::search(const Filter &f, QString *error) const
{
    const auto [where, values] = whereOf(f);
    return selectModules(where, values, QStringLiteral("m.started DESC, m.uuid"), f.limit, error);
}

std::vector<ModuleRecord> ResultsStore::records(const Filter &f, QString *error) const
{
    const auto [where, values] = whereOf(f);
    auto out = selectModules(where, values, QStringLiteral("m.started, m.uuid"), f.limit, error);
    for (ModuleRecord &m : out)
        fillChildren(m);
    return out;
}

QStringList ResultsStore::planNames() const
{
    QStringList out;
    QSqlQuery q(QSqlDatabase::database(m_connection, false));
    if (q.exec(QStringLiteral("SELECT DISTINCT plan_name FROM run ORDER BY plan_name")))
        while (q.next())
            out << q.value(0).toString();
    return out;
}

QStringList ResultsStore::stationIds() const
{
    QStringList out;
    QSqlQuery q(QSqlDatabase::database(m_connection, false));
    if (q.exec(QStringLiteral("SELECT DISTINCT station_id FROM run ORDER BY station_id")))
        while (q.next())
            out << q.value(0).toString();
    return out;
}

QStringList ResultsStore::measurementNames(const QString &plan) const
{
    QStringList out;
    QSqlQuery q(QSqlDatabase::database(m_connection, false));
    if (run(q, QStringLiteral("SELECT DISTINCT v.name FROM measurement v JOIN module m ON m.uuid = v.module_uuid "
                              "JOIN run r ON r.uuid = m.run_uuid WHERE r.plan_name = ? ORDER BY v.name"),
            {plan}))
        while (q.next())
            out << q.value(0).toString();
    return out;
}

ResultsStore::Yield ResultsStore::yield(const QString &planName, const QDateTime &since, QString *error) const
{
    Yield y;
    QSqlQuery q(QSqlDatabase::database(m_connection, false));
    if (!run(q,
             QStringLiteral("SELECT m.firmware_before, m.slot, m.outcome, m.marginal, COUNT(*) FROM module m JOIN run r "
                            "ON r.uuid = m.run_uuid WHERE r.plan_name = ? AND COALESCE(m.started, '') >= ? "
                            "GROUP BY m.firmware_before, m.slot, m.outcome, m.marginal"),
             {planName, since.isValid() ? iso(since) : QStringLiteral("")})) { // "" (not NULL): every time is later
        if (error)
            *error = q.lastError().text();
        return y;
    }
    while (q.next()) {
        const Outcome o = outcomeFromKey(q.value(2).toString()).value_or(Outcome::Error);
        const bool marginal = q.value(3).toInt() != 0;
        const int n = q.value(4).toInt();
        addCount(y.total, o, marginal, n);
        addCount(y.byFirmware[q.value(0).toString()], o, marginal, n);
        addCount(y.bySlot[q.value(1).toString()], o, marginal, n);
    }
    return y;
}

std::vector<ResultsStore::Point> ResultsStore::series(const QString &plan, const QString &measurement, const QDateTime &from,
                                                      const QDateTime &to, QString *error) const
{
    std::vector<Point> out;
    QSqlQuery q(QSqlDatabase::database(m_connection, false));
    q.setForwardOnly(true);
    QString sql = QStringLiteral("SELECT m.started, v.value, m.serial, m.uuid, v.low, v.high, v.marginal_low, v.marginal_high, "
                                 "v.outcome FROM measurement v JOIN module m ON m.uuid = v.module_uuid JOIN run r ON "
                                 "r.uuid = m.run_uuid WHERE r.plan_name = ? AND v.name = ? AND m.outcome IN ('PASS', 'FAIL')");
    QVariantList values{plan, measurement};
    if (from.isValid()) {
        sql += QStringLiteral(" AND m.started >= ?");
        values << iso(from);
    }
    if (to.isValid()) {
        sql += QStringLiteral(" AND m.started <= ?");
        values << iso(to);
    }
    sql += QStringLiteral(" ORDER BY m.started, m.uuid");
    if (!run(q, sql, values)) {
        if (error)
            *error = q.lastError().text();
        return out;
    }
    while (q.next())
        out.push_back({fromIso(q.value(0).toString()), q.value(1).toDouble(), q.value(2).toString(), q.value(3).toString(),
                       optionalOf(q.value(4)), optionalOf(q.value(5)), optionalOf(q.value(6)), optionalOf(q.value(7)),
                       outcomeFromKey(q.value(8).toString()).value_or(Outcome::Error)});
    return out;
}

ResultsStore::Capability ResultsStore::capability(const std::vector<Point> &points)
{
    Capability c;
    c.cpk = std::numeric_limits<double>::quiet_NaN();
    c.n = int(points.size());
    if (points.empty())
        return c;
    double sum = 0;
    for (const Point &p : points)
        sum += p.value;
    c.mean = sum / c.n;
    double ss = 0;
    for (const Point &p : points)
        ss += (p.value - c.mean) * (p.value - c.mean);
    c.sigma = c.n > 1 ? std::sqrt(ss / (c.n - 1)) : 0;
    c.lsl = points.back().low;
    c.usl = points.back().high;
    if (c.sigma <= 0 || (!c.lsl && !c.usl))
        return c;
    double k = std::numeric_limits<double>::infinity();
    if (c.usl)
        k = std::min(k, (*c.usl - c.mean) / (3 * c.sigma));
    if (c.lsl)
        k = std::min(k, (c.mean - *c.lsl) / (3 * c.sigma));
    c.cpk = k;
    return c;
}

bool ResultsStore::grantStationRole(const QString &role, QString *error)
{
    if (m_kind != Kind::PostgreSQL) {
        if (error)
            *error = tr("Roles are a PostgreSQL server's; %1 is an SQLite file.").arg(m_location);
        return false;
    }
    QSqlDatabase db = QSqlDatabase::database(m_connection, false);
    const QString name = db.driver()->escapeIdentifier(role, QSqlDriver::TableName);
    const QString tables = QStringLiteral("schema_version, run, module, step, measurement, artifact");
    for (const QString &sql : {QStringLiteral("REVOKE ALL ON %1 FROM %2").arg(tables, name),
                               QStringLiteral("GRANT SELECT, INSERT ON %1 TO %2").arg(tables, name)})
        if (!exec(sql, error))
            return false;
    return true;
}

} // namespace imudesk::results
