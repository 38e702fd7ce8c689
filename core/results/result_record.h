#pragma once
// One module's test, as the results database keeps it (issue 38), shaped like an OpenHTF test
// record: the run it belongs to (station, operator, plan and its SHA-256, ImuDesk's version), the
// module (fixture slot, serial, product, firmware before and after, attempt, outcome), its steps,
// its measurements with their limits and outcome, and its artifacts (PDF, recording) with their
// SHA-256. Outcomes: PASS, FAIL, ERROR (the equipment failed: the port went away, the module did
// not answer; not counted against the product's yield) and ABORTED (the operator cancelled).
// Value types; every record has a UUID, which makes storing it twice harmless. A station's
// result becomes one in core/station (result_conversion.h): this folder knows no station.
#include <QByteArray>
#include <QDateTime>
#include <QJsonObject>
#include <QString>

#include <optional>
#include <vector>

namespace imudesk::results {

enum class Outcome { Pass, Fail, Error, Aborted };
QString outcomeKey(Outcome o); // "PASS", "FAIL", "ERROR", "ABORTED"
std::optional<Outcome> outcomeFromKey(const QString &key);

struct RunRecord {
    QString uuid;
    QString stationId; // the station's host name unless set
    QString operatorName;
    QString planName;
    QString planSha256; // of the plan's JSON as run
    QString imudeskVersion;
    QDateTime started, finished;
};

struct StepRecord {
    int index = 0;
    QString kind;  // the plan's step key ("static", ...)
    QString name;  // as shown
    Outcome outcome = Outcome::Pass;
    bool skipped = false;
    QString detail;
    QDateTime started, finished;
};

struct MeasurementRecord {
    int step = 0; // index of its step
    QString name;
    double value = 0;
    QString unit;
    QString comparator; // "LE", "ABS_LE", "INFO"
    std::optional<double> low, high;
    // The marginal band inside the limits (plan format 2): a pass beyond it is marked marginal.
    std::optional<double> marginalLow, marginalHigh;
    Outcome outcome = Outcome::Pass;
    bool marginal = false;
};

struct ArtifactRecord {
    QString kind;  // "report", "recording"
    QString mime;  // "application/pdf", ...
    QString sha256;
    QString location; // its path
};

struct ModuleRecord {
    QString uuid;
    RunRecord run;
    QString slot; // the fixture slot (the port)
    QString serial, product, firmwareBefore, firmwareAfter;
    QByteArray serialRaw; // the serial's bytes as the module sent them (serial shows them, escaped where not UTF-8)
    int attempt = 1;
    Outcome outcome = Outcome::Pass;
    bool marginal = false; // a pass with a measurement in its marginal band
    QDateTime started, finished;
    std::vector<StepRecord> steps;
    std::vector<MeasurementRecord> measurements;
    std::vector<ArtifactRecord> artifacts;

    // The record as JSON, shaped like an OpenHTF test record (one per module: the run's fields
    // at the top, the steps as phases with their measurements, the artifacts as attachments).
    QJsonObject toJson() const;
    // A record written by toJson(), read back (results import, tests); nullopt when it is not one.
    static std::optional<ModuleRecord> fromJson(const QJsonObject &o);
    // The record in OpenHTF's own JSON layout (dut_id, phases with measurements keyed by name
    // and their validators, outcome, marginal): the run folder holds one per module, for
    // factories that collect OpenHTF records.
    QJsonObject toOpenHtfJson() const;
};

// A new UUID (RFC 4122 version 4), without braces.
QString newUuid();
// SHA-256 of a file in hex; empty when it cannot be read.
QString fileSha256(const QString &path);

} // namespace imudesk::results
