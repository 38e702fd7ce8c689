#pragma once
// A results database (issue 38): every finished module record (result_record.h) committed in one
// transaction, through Qt SQL, either to the station's own SQLite file (QSQLITE, Debian's
// libqt6sql6-sqlite; results.sqlite beside the run folders, always written first) or to the
// line's PostgreSQL server (QPSQL, libqt6sql6-psql; postgresql://… URLs). One schema for both,
// versioned: ImuDesk creates it and migrates an older one; a newer one is refused.
//
// Every insert is keyed by the records' UUIDs and does nothing when the row is there, so a
// record stored twice (an upload retried after a lost answer, two stations' uploaders) is
// stored once, and a station's role needs INSERT and SELECT only (setupServer() grants them).
// The SQLite file is also the upload outbox: each module has a revision (raised when an
// artifact is added after it) and the revision last uploaded.
//
// Reads: a serial number's history, yield per firmware and fixture slot (ERROR and ABORTED are
// counted apart and left out: the equipment or the operator ended them, not the product), a
// search, and a measurement's values over time with its limits and Cpk.
//
// Plain class; use it in the thread that opened it (Qt SQL's rule). Errors come back as text.
#include "core/results/result_record.h"

#include <QString>
#include <QStringList>

#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace imudesk::results {

class ResultsStore {
public:
    static constexpr int kSchemaVersion = 2;
    static constexpr const char *kFileName = "results.sqlite";
    enum class Kind { SQLite, PostgreSQL };

    ResultsStore();
    ~ResultsStore();
    ResultsStore(const ResultsStore &) = delete;
    ResultsStore &operator=(const ResultsStore &) = delete;

    // Is this a server's address (postgresql://user[:password]@host[:port]/database[?host=/socket/dir])
    // rather than a file's path?
    static bool isServerUrl(const QString &location);
    // The URL without its password (for messages and the window).
    static QString displayLocation(const QString &location);

    // Opens (creating the file, creating or migrating the schema) a file path or a server URL;
    // false with *error. migrate = false: a missing or older schema is an error (a station's
    // role may not create tables).
    bool open(const QString &location, QString *error, bool migrate = true);
    bool isOpen() const;
    void close();
    const QString &location() const { return m_location; }
    Kind kind() const { return m_kind; }
    int schemaVersion() const { return m_version; }

    // Stores the modules, their runs, steps, measurements and artifacts in one transaction; rows
    // already there are left as they are. true when all are stored now or were already.
    bool commit(const ModuleRecord &m, QString *error);
    bool commit(const std::vector<ModuleRecord> &modules, QString *error);
    // An artifact written after its module was stored (the PDF report): its row added, and the
    // module's revision raised so that the uploader sends it on.
    bool addArtifact(const QString &moduleUuid, const ArtifactRecord &a, QString *error);
    // Module records in the database.
    int moduleCount() const;

    // The outbox (SQLite): modules whose revision was not uploaded yet, oldest first, with that
    // revision; markUploaded records that the revision reached the server.
    std::vector<std::pair<QString, int>> pendingUploads(int limit, QString *error = nullptr) const;
    int pendingCount() const;
    bool markUploaded(const QString &moduleUuid, int revision, QString *error);
    // The same for a batch, in one transaction.
    bool markUploaded(const std::vector<std::pair<QString, int>> &modules, QString *error);

    // One module with its steps, measurements and artifacts.
    std::optional<ModuleRecord> module(const QString &uuid, QString *error = nullptr) const;
    // Every attempt of a serial number (its text as shown), oldest first, complete.
    std::vector<ModuleRecord> history(const QString &serial, QString *error = nullptr) const;

    struct Filter {
        QString serial;  // part of the serial number; empty: any
        QString plan;    // the plan's name, exactly; empty: any
        QString station; // exactly; empty: any
        QDateTime from, to; // invalid: open
        int limit = 5000;
    };
    // Modules matching the filter, newest first, without steps and measurements.
    std::vector<ModuleRecord> search(const Filter &f, QString *error = nullptr) const;
    QStringList planNames() const;
    QStringList stationIds() const;
    // Names of the measurements taken under a plan (with limits or not), sorted.
    QStringList measurementNames(const QString &plan) const;
    // Modules matching f with every record complete (results export), oldest first.
    std::vector<ModuleRecord> records(const Filter &f, QString *error = nullptr) const;

    struct Counts {
        int pass = 0, fail = 0, error = 0, aborted = 0, marginal = 0;
        // pass / (pass + fail): what the product achieved; NaN when neither.
        double yield() const;
    };
    struct Yield {
        Counts total;
        std::map<QString, Counts> byFirmware; // as found (firmware before)
        std::map<QString, Counts> bySlot;
    };
    // Modules of the plan (by name) started at or after since (invalid: all).
    Yield yield(const QString &planName, const QDateTime &since, QString *error = nullptr) const;

    struct Point {
        QDateTime time;
        double value = 0;
        QString serial, moduleUuid;
        std::optional<double> low, high, marginalLow, marginalHigh;
        Outcome outcome = Outcome::Pass;
    };
    // A measurement's values under a plan, oldest first (ERROR and ABORTED modules left out).
    std::vector<Point> series(const QString &plan, const QString &measurement, const QDateTime &from,
                              const QDateTime &to, QString *error = nullptr) const;
    struct Capability {
        int n = 0;
        double mean = 0, sigma = 0; // sample standard deviation
        std::optional<double> lsl, usl;
        double cpk = 0; // NaN without a limit or with sigma 0
    };
    // Cpk of the values against the latest point's limits: min(USL − mean, mean − LSL) / 3σ.
    static Capability capability(const std::vector<Point> &points);

    // PostgreSQL: lets a station's role (an existing login role) read and insert results, and
    // nothing else (no UPDATE, no DELETE). Run with an owner's connection.
    bool grantStationRole(const QString &role, QString *error);

private:
    bool exec(const QString &sql, QString *error) const;
    bool migrate(QString *error);
    int readVersion() const;
    QString dialect(const char *sql) const;
    void fillChildren(ModuleRecord &m) const;
    std::vector<ModuleRecord> selectModules(const QString &where, const QVariantList &values, const QString &order,
                                            int limit, QString *error) const;
    QString m_connection;
    QString m_location;
    Kind m_kind = Kind::SQLite;
    int m_version = 0;
};

} // namespace imudesk::results
