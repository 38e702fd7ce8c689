#pragma once
// A production test plan (issue 22): the steps a bench station runs on every module of a tray,
// each with its limits. A versioned JSON document:
//   {"format": "imudesk-station-plan", "version": 2, "name": "HI14 incoming test",
//    "steps": [{"step": "identify", "products": "HI14", "firmware_min": "1.6.0"},
//              {"step": "static", "seconds": 5, "gyro_std_max_dps": 0.05,
//               "gyro_bias_max_dps": {"high": 0.5, "marginal_high": 0.3}, ...},
//              {"step": "gyro_scale", "enabled": false}, ...]}
// Every step kind has a fixed set of parameters (params()): a number within its range or a
// text; a missing parameter takes its default, an unknown one or a value out of range is
// refused with the step's number and the parameter's name. Paths (profile, firmware image)
// are relative to the plan file's folder. Steps run in the order listed; a step with
// "enabled": false is reported as skipped.
//
// Version 2 (issue 38): a pass/fail limit (ParamSpec::limit) may carry a marginal band, written
// as {"high": limit, "marginal_high": band}: a value up to the band passes, one past it up to
// the limit passes marked marginal (as OpenHTF's marginal_maximum), one past the limit fails.
// A limit without a band is still written as a plain number, so a version 1 plan differs from
// its version 2 form only in "version"; version 1 plans load and are saved as version 2.
#include <QByteArray>
#include <QCoreApplication>
#include <QString>
#include <QVariant>
#include <QVariantMap>

#include <optional>
#include <vector>

namespace imudesk::station {

enum class StepKind {
    Identify,  // expected product(s) and firmware range
    Firmware,  // firmware at least V: update from the image if older, then verify
    Profile,   // apply a configuration profile with read-back
    Static,    // noise and bias at rest, gravity magnitude
    Allan,     // Allan deviation of the gyro at one averaging time
    Attitude,  // roll/pitch against the expected orientation (mounting verified)
    MagCal,    // device-side magnetometer calibration (MCAL), must succeed
    GyroScale, // gyro scale-factor run on a turntable (optional)
    Verify,    // the module check (issue 55): turned through still poses, its sensors and attitude judged
    Save,      // SAVECONFIG
    Evidence,  // record M seconds into the run folder
};

struct ParamSpec {
    const char *key;     // JSON name
    const char *label;   // QT_TRANSLATE_NOOP("imudesk::station::TestPlan", ...)
    const char *unit;    // shown beside the value; empty for none
    const char *tooltip; // QT_TRANSLATE_NOOP as label
    bool text = false;   // a text (path, product list, version) instead of a number
    double defaultValue = 0;
    double min = 0, max = 0;
    const char *defaultText = "";
    bool limit = false;  // a pass/fail upper limit: may carry a marginal band (format 2)
};

struct PlanStep {
    StepKind kind = StepKind::Identify;
    bool enabled = true;
    QVariantMap params; // every parameter of the kind, defaults filled in
    QVariantMap marginal; // limit parameter's key -> its marginal band (double); absent: no band

    double number(const char *key) const;
    QString text(const char *key) const;
    std::optional<double> marginalOf(const char *key) const;
};

class TestPlan {
    Q_DECLARE_TR_FUNCTIONS(imudesk::station::TestPlan)

public:
    static constexpr int kVersion = 2;
    static constexpr qint64 kMaxBytes = 256 * 1024;

    QString name;
    std::vector<PlanStep> steps;
    QString baseDir; // the plan file's folder (relative paths); not saved
    int loadedVersion = kVersion; // the format the plan was read in (fromJson); not saved

    static const std::vector<StepKind> &allKinds();
    static QString key(StepKind kind);                       // "identify", ...
    static std::optional<StepKind> kindFromKey(const QString &key);
    static QString title(StepKind kind);                     // translated, e.g. "Static noise and bias"
    static QString description(StepKind kind);               // translated, one sentence
    static const std::vector<ParamSpec> &params(StepKind kind);
    static const ParamSpec *param(StepKind kind, const QString &key);
    // A step of the kind with every parameter at its default, except those in overrides.
    static PlanStep defaultStep(StepKind kind, const QVariantMap &overrides = {});
    // The example plan (docs/examples/station-hi14.json is this, saved).
    static TestPlan example();

    static std::optional<TestPlan> fromJson(const QByteArray &json, QString *error);
    QByteArray toJson() const;
    static std::optional<TestPlan> load(const QString &path, QString *error);
    bool save(const QString &path, QString *error) const;
    // A path given in the plan, made absolute against baseDir.
    QString resolve(const QString &path) const;
    // Checks one value for a parameter: empty when acceptable, else why (translated).
    static QString checkValue(StepKind kind, const QString &key, const QVariant &value);
    // Checks a marginal band for the limit `key` whose value is `high`: a number within the
    // parameter's range and below the limit; empty when acceptable, else why (translated).
    static QString checkMarginal(StepKind kind, const QString &key, const QVariant &marginal, const QVariant &high);
    // Said to the user when the plan was read in an older format (translated); else empty.
    QString conversionNote() const;
    // Every step's values checked; empty when the plan can run.
    QStringList problems() const;
};

} // namespace imudesk::station
