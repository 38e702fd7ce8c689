#pragma once
// What a station run found: per module, every step of the plan with its verdict, the values
// it measured and the limits they were held against. Value types, shared by the runner, the
// reports (run_folder.h, the PDF in ui/station) and the station view.
#include "core/station/test_plan.h"

#include <QDateTime>
#include <QJsonObject>
#include <QMetaType>
#include <QString>

#include <optional>
#include <vector>

namespace imudesk::station {

enum class Verdict { Pending, Running, Pass, Fail, Skipped };
QString verdictKey(Verdict v);   // "pending", "running", "pass", "fail", "skipped"
QString verdictText(Verdict v);  // translated
// Bytes a module sent as text, shown verbatim: UTF-8 where they are UTF-8, any other byte and
// any control character as \xNN (a serial number that is not UTF-8 stays readable and unique).
QString bytesAsText(const QByteArray &raw);
// A time as the summaries write it: UTC, ISO 8601 with ms; empty when not set.
QString isoUtc(const QDateTime &t);

struct Measurement {
    QString name;   // e.g. "gyro_std_x"
    double value = 0;
    QString unit;   // e.g. "°/s"
    QString limit;  // e.g. "≤ 0.05"; empty: information only
    bool ok = true;
    // The limit as numbers (the results database): "LE" value <= high, "ABS_LE" |value| <= high,
    // "INFO" none (information only).
    QString comparator = QStringLiteral("INFO");
    double high = 0;
    // The plan's marginal band (plan format 2): a value past marginalHigh (|value| for ABS_LE)
    // but within high passes marked marginal.
    std::optional<double> marginalHigh = std::nullopt;
    bool marginal = false;
};

struct StepResult {
    StepKind kind = StepKind::Identify;
    QString title;     // translated step title
    Verdict verdict = Verdict::Pending;
    QString detail;    // what was found, or why it failed (translated)
    std::vector<Measurement> values;
    QDateTime started, finished;
    QJsonObject toJson() const;
};

struct ModuleResult {
    QString port;
    QString serial, product, firmware; // firmware: as found (before any update)
    QByteArray serialRaw;              // the serial number's bytes as the module sent them
    QString firmwareAfter;             // after an update, else empty
    Verdict verdict = Verdict::Pending;
    int currentStep = -1;              // index into steps while running
    double progress = 0;               // 0..1 of the whole plan
    std::vector<StepResult> steps;     // one per plan step
    QDateTime started, finished;
    QString evidencePath;              // the recording of the evidence step, if any
    QString reportPath;                // the PDF, once written
    int attempt = 1;                   // 1 + earlier runs of this serial in the same run folder
    // How the run ended beside its verdict: the equipment failed (the module disappeared, its
    // port could not be opened: not the product's fault, not counted against its yield) or the
    // operator cancelled it, or a measurement could not be judged (the module moved during a
    // step that needs it still: its figures would be the motion's, not the product's).
    enum class End { Completed, EquipmentFailed, Cancelled, NotJudged };
    End end = End::Completed;

    // A module not yet tested: every step of the plan pending.
    static ModuleResult pending(const QString &port, const TestPlan &plan);
    // The first failed step (index), or -1.
    int failedStep() const;
    // "Static noise and bias: gyro_std_x 0.41 °/s (limit ≤ 0.05)" for a failure; empty otherwise.
    QString failureSummary() const;
    // Whether any value passed inside its marginal band (the module may still pass).
    bool marginal() const;
    QJsonObject toJson() const;
};

} // namespace imudesk::station

Q_DECLARE_METATYPE(imudesk::station::ModuleResult)
