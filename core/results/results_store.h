#pragma once
// The station's results database (issue 38): every finished module record (result_record.h)
// committed in one transaction to an SQLite file (Qt SQL's QSQLITE driver, Debian's
// libqt6sql6-sqlite), beside the station's run folders. A record stored twice (the same UUID) is
// stored once. Reads: a serial number's whole history, and yield per firmware and per fixture
// slot of a plan (ERROR and ABORTED are counted apart and left out of the yield: the equipment
// or the operator ended them, not the product).
//
// Plain class; use it in the thread that opened it (Qt SQL's rule). Errors come back as text.
#include "core/results/result_record.h"

#include <QString>

#include <map>
#include <vector>

namespace imudesk::results {

class ResultsStore {
public:
    static constexpr int kSchemaVersion = 1;
    static constexpr const char *kFileName = "results.sqlite";

    ResultsStore();
    ~ResultsStore();
    ResultsStore(const ResultsStore &) = delete;
    ResultsStore &operator=(const ResultsStore &) = delete;

    // Opens (creating it and its schema when new) the database file; false with *error.
    bool open(const QString &path, QString *error);
    bool isOpen() const;
    void close();
    const QString &path() const { return m_path; }

    // Stores the module, its run (once), steps, measurements and artifacts in one transaction.
    // true when stored now or already there (the same UUID).
    bool commit(const ModuleRecord &m, QString *error);
    // An artifact written after its module was stored (the PDF report): its row added.
    bool addArtifact(const QString &moduleUuid, const ArtifactRecord &a, QString *error);
    // Module records in the database.
    int moduleCount() const;

    // Every attempt of a serial number, oldest first, with its steps, measurements, artifacts.
    std::vector<ModuleRecord> history(const QString &serial, QString *error = nullptr) const;

    struct Counts {
        int pass = 0, fail = 0, error = 0, aborted = 0;
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

private:
    bool exec(const QString &sql, QString *error) const;
    QString m_connection;
    QString m_path;
};

} // namespace imudesk::results
