#include "core/station/test_plan.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QSaveFile>

#include <cmath>

namespace imudesk::station {

namespace {
constexpr const char *kFormat = "imudesk-station-plan";

ParamSpec number(const char *key, const char *label, const char *unit, const char *tip, double def, double min,
                 double max)
{
    return ParamSpec{key, label, unit, tip, false, def, min, max, ""};
}
// A pass/fail upper limit: a number that may carry a marginal band (format 2).
ParamSpec limitNumber(const char *key, const char *label, const char *unit, const char *tip, double def,
                      double min, double max)
{
    ParamSpec p = number(key, label, unit, tip, def, min, max);
    p.limit = true;
    return p;
}
ParamSpec text(const char *key, const char *label, const char *tip, const char *def)
{
    return ParamSpec{key, label, "", tip, true, 0, 0, 0, def};
}
// A limit with a band in the JSON: {"high": limit, "marginal_high": band}.
constexpr const char *kHigh = "high";
constexpr const char *kMarginalHigh = "marginal_high";
} // namespace

double PlanStep::number(const char *key) const
{
    return params.value(QString::fromLatin1(key)).toDouble();
}

QString PlanStep::text(const char *key) const
{
    return params.value(QString::fromLatin1(key)).toString();
}

std::optional<double> PlanStep::marginalOf(const char *key) const
{
    const auto it = marginal.constFind(QString::fromLatin1(key));
    if (it == marginal.constEnd())
        return std::nullopt;
    bool ok = false;
    const double v = it->toDouble(&ok);
    return ok ? std::optional<double>(v) : std::nullopt;
}

const std::vector<StepKind> &TestPlan::allKinds()
{
    static const std::vector<StepKind> kinds{StepKind::Identify, StepKind::Firmware,  StepKind::Profile,
                                             StepKind::Static,   StepKind::Allan,     StepKind::Attitude,
                                             StepKind::MagCal,   StepKind::GyroScale, StepKind::Verify,
                                             StepKind::Save,     StepKind::Evidence};
    return kinds;
}

QString TestPlan::key(StepKind kind)
{
    switch (kind) {
    case StepKind::Identify: return QStringLiteral("identify");
    case StepKind::Firmware: return QStringLiteral("firmware");
    case StepKind::Profile: return QStringLiteral("profile");
    case StepKind::Static: return QStringLiteral("static");
    case StepKind::Allan: return QStringLiteral("allan");
    case StepKind::Attitude: return QStringLiteral("attitude");
    case StepKind::MagCal: return QStringLiteral("magcal");
    case StepKind::GyroScale: return QStringLiteral("gyro_scale");
    case StepKind::Verify: return QStringLiteral("verify");
    case StepKind::Save: return QStringLiteral("save");
    case StepKind::Evidence: return QStringLiteral("evidence");
    }
    return {};
}

std::optional<StepKind> TestPlan::kindFromKey(const QString &k)
{
    for (StepKind kind : allKinds())
        if (key(kind) == k)
            return kind;
    return std::nullopt;
}

QString TestPlan::title(StepKind kind)
{
    switch (kind) {
    case StepKind::Identify: return tr("Identify");
    case StepKind::Firmware: return tr("Firmware version");
    case StepKind::Profile: return tr("Apply profile");
    case StepKind::Static: return tr("Static noise and bias");
    case StepKind::Allan: return tr("Allan deviation");
    case StepKind::Attitude: return tr("Attitude (mounting)");
    case StepKind::MagCal: return tr("Magnetometer calibration");
    case StepKind::GyroScale: return tr("Gyro scale factor");
    case StepKind::Verify: return tr("Verify module");
    case StepKind::Save: return tr("Save configuration");
    case StepKind::Evidence: return tr("Record evidence");
    }
    return {};
}

QString TestPlan::description(StepKind kind)
{
    switch (kind) {
    case StepKind::Identify:
        return tr("The module reports an expected product and a firmware version within the range.");
    case StepKind::Firmware:
        return tr("Firmware older than the minimum is updated from the image and verified; newer passes as it is.");
    case StepKind::Profile:
        return tr("The profile's settings are applied and every one is read back.");
    case StepKind::Static:
        return tr("At rest: per-axis standard deviation and mean of the gyro, accelerometer noise and the "
                  "gravity magnitude against their limits.");
    case StepKind::Allan:
        return tr("The gyro's Allan deviation at the averaging time, worst axis, below the limit.");
    case StepKind::Attitude:
        return tr("Roll and pitch at rest within the tolerance of the expected orientation: the module is "
                  "mounted as intended.");
    case StepKind::MagCal:
        return tr("The module's own magnetometer calibration (MCAL) runs to the end and succeeds; the module "
                  "must be turned through every attitude meanwhile (a rotation fixture).");
    case StepKind::GyroScale:
        return tr("On a turntable: two turns each way; the gyro's scale-factor error below the limit.");
    case StepKind::Verify:
        return tr("Turned through at least 9 still poses (by hand or a fixture): the accelerometer's bias and scale, "
                  "the gyro's bias and scale and the attitude's tilt and heading, each within its limit.");
    case StepKind::Save: return tr("SAVECONFIG: the module keeps its settings after a restart.");
    case StepKind::Evidence: return tr("The module's output is recorded into the run folder as evidence.");
    }
    return {};
}

const std::vector<ParamSpec> &TestPlan::params(StepKind kind)
{
    static const std::vector<ParamSpec> identify{
        text("products", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Products"),
             QT_TRANSLATE_NOOP("imudesk::station::TestPlan",
                               "Product names the module may report, separated by commas (HI14 matches HI14R3)"),
             "HI14"),
        text("firmware_min", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Lowest firmware"),
             QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Oldest firmware accepted, e.g. 1.6.6; empty: any"),
             "1.5.5"),
        text("firmware_max", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Highest firmware"),
             QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Newest firmware accepted; empty: any"), ""),
    };
    static const std::vector<ParamSpec> firmware{
        text("minimum", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "At least"),
             QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Modules with older firmware are updated"), "1.7.1"),
        text("image", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Image"),
             QT_TRANSLATE_NOOP("imudesk::station::TestPlan",
                               "Intel HEX or binary image, relative to the plan's folder; without one an older "
                               "module fails this step"),
             ""),
    };
    static const std::vector<ParamSpec> profile{
        text("profile", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Profile"),
             QT_TRANSLATE_NOOP("imudesk::station::TestPlan",
                               "Configuration profile (.json, saved from the profile dialog), relative to the "
                               "plan's folder"),
             ""),
    };
    static const std::vector<ParamSpec> still{
        number("seconds", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Duration"), "s",
               QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "How long the module is measured at rest"), 5, 1,
               600),
        limitNumber("gyro_std_max_dps", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Gyro noise max"), "°/s",
                    QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Largest standard deviation of each gyro axis"),
                    0.05, 0, 100),
        limitNumber("gyro_bias_max_dps", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Gyro bias max"), "°/s",
                    QT_TRANSLATE_NOOP("imudesk::station::TestPlan",
                                      "Largest magnitude of each gyro axis's mean at rest"),
                    0.5, 0, 100),
        limitNumber("acc_std_max_mg", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Accelerometer noise max"), "mG",
                    QT_TRANSLATE_NOOP("imudesk::station::TestPlan",
                                      "Largest standard deviation of each accelerometer axis"),
                    3, 0, 1000),
        limitNumber("gravity_tol_mg", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Gravity tolerance"), "mG",
                    QT_TRANSLATE_NOOP("imudesk::station::TestPlan",
                                      "The mean acceleration's magnitude may differ from 1 G by this much"),
                    20, 0, 1000),
    };
    static const std::vector<ParamSpec> allan{
        number("seconds", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Duration"), "s",
               QT_TRANSLATE_NOOP("imudesk::station::TestPlan",
                                 "How long the module is measured at rest (at least 10 averaging times)"),
               20, 5, 3600),
        number("tau_s", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Averaging time"), "s",
               QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "τ at which the Allan deviation is read"), 1, 0.01,
               360),
        limitNumber("sigma_max_dps", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "σ(τ) max"), "°/s",
                    QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Largest Allan deviation of any gyro axis at τ"),
                    0.01, 0, 100),
    };
    static const std::vector<ParamSpec> attitude{
        number("roll_deg", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Expected roll"), "°",
               QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Roll of the module in its fixture (Z up: 0)"), 0,
               -180, 180),
        number("pitch_deg", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Expected pitch"), "°",
               QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Pitch of the module in its fixture (Z up: 0)"), 0,
               -90, 90),
        limitNumber("tolerance_deg", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Tolerance"), "°",
                    QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Largest difference of roll and of pitch"), 5, 0.1,
                    90),
        number("seconds", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Duration"), "s",
               QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "The angles are averaged over this time"), 2, 0.5, 60),
    };
    static const std::vector<ParamSpec> magcal{
        number("timeout_s", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Time limit"), "s",
               QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "The calibration fails when it has not ended by then"),
               150, 10, 1200),
    };
    static const std::vector<ParamSpec> gyroScale{
        limitNumber("max_error_pct", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Scale error max"), "%",
                    QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Largest scale-factor error of the Z gyro"), 0.5, 0,
                    100),
        number("timeout_s", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Time limit"), "s",
               QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "The run fails when the turns have not ended by then"),
               180, 10, 1200),
    };
    static const std::vector<ParamSpec> verify{
        number("seconds", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Duration"), "s",
               QT_TRANSLATE_NOOP("imudesk::station::TestPlan",
                                 "How long the module is turned through its poses (3 s still in each, at least 9)"),
               90, 20, 1200),
        number("gravity_ms2", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Local gravity"), "m/s²",
               QT_TRANSLATE_NOOP("imudesk::station::TestPlan",
                                 "The station's gravity (m/s²); 0: standard gravity assumed, with its uncertainty"),
               0, 0, 9.9),
        limitNumber("acc_bias_max_mg", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Accelerometer bias max"), "mg",
                    QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Largest accelerometer bias of any axis"), 10, 0,
                    1000),
        limitNumber("acc_scale_max_pct", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Accelerometer scale error max"),
                    "%", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Largest accelerometer scale error of any axis"),
                    0.5, 0, 100),
        limitNumber("gyro_bias_max_dps", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Gyro bias max"), "°/s",
                    QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Largest gyro bias of any axis"), 0.5, 0, 100),
        limitNumber("gyro_scale_max_pct", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Gyro scale error max"), "%",
                    QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Largest gyro scale error of any axis"), 0.5, 0, 100),
        limitNumber("tilt_max_deg", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Tilt error max"), "°",
                    QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Largest roll or pitch error of the module's attitude"),
                    0.3, 0, 90),
        limitNumber("heading_max_deg", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Heading error max"), "°",
                    QT_TRANSLATE_NOOP("imudesk::station::TestPlan",
                                      "Largest heading error of the module's attitude (needs a magnetometer)"),
                    1.0, 0, 180),
    };
    static const std::vector<ParamSpec> none;
    static const std::vector<ParamSpec> evidence{
        number("seconds", QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "Duration"), "s",
               QT_TRANSLATE_NOOP("imudesk::station::TestPlan", "How long the module's output is recorded"), 5, 1,
               3600),
    };
    switch (kind) {
    case StepKind::Identify: return identify;
    case StepKind::Firmware: return firmware;
    case StepKind::Profile: return profile;
    case StepKind::Static: return still;
    case StepKind::Allan: return allan;
    case StepKind::Attitude: return attitude;
    case StepKind::MagCal: return magcal;
    case StepKind::GyroScale: return gyroScale;
    case StepKind::Verify: return verify;
    case StepKind::Save: return none;
    case StepKind::Evidence: return evidence;
    }
    return none;
}

const ParamSpec *TestPlan::param(StepKind kind, const QString &k)
{
    for (const ParamSpec &p : params(kind))
        if (k == QLatin1String(p.key))
            return &p;
    return nullptr;
}

PlanStep TestPlan::defaultStep(StepKind kind, const QVariantMap &overrides)
{
    PlanStep s;
    s.kind = kind;
    for (const ParamSpec &p : params(kind))
        s.params.insert(QString::fromLatin1(p.key),
                        p.text ? QVariant(QString::fromUtf8(p.defaultText)) : QVariant(p.defaultValue));
    for (auto it = overrides.begin(); it != overrides.end(); ++it)
        s.params[it.key()] = it.value();
    return s;
}

TestPlan TestPlan::example()
{
    TestPlan plan;
    plan.name = QStringLiteral("HI14 incoming test");
    for (StepKind kind : allKinds()) {
        PlanStep s = defaultStep(kind);
        if (kind == StepKind::Identify)
            s.params[QStringLiteral("firmware_min")] = QStringLiteral("1.6.6");
        if (kind == StepKind::Firmware)
            s.params[QStringLiteral("image")] = QStringLiteral("hi14-sim-1.7.1.hex");
        if (kind == StepKind::Profile)
            s.params[QStringLiteral("profile")] = QStringLiteral("station-hi14-profile.json");
        if (kind == StepKind::GyroScale)
            s.enabled = false; // needs a turntable
        if (kind == StepKind::Verify)
            s.enabled = false; // needs the module turned through its poses (by hand or a fixture)
        plan.steps.push_back(s);
    }
    return plan;
}

QString TestPlan::checkValue(StepKind kind, const QString &k, const QVariant &value)
{
    const ParamSpec *p = param(kind, k);
    if (!p)
        return tr("%1 has no parameter \"%2\"").arg(key(kind), k);
    if (p->text) {
        if (value.typeId() != QMetaType::QString)
            return tr("\"%1\" must be a text").arg(k);
        if ((k == QLatin1String("minimum") || k == QLatin1String("firmware_min") || k == QLatin1String("firmware_max"))) {
            const QString v = value.toString().trimmed();
            static const QRegularExpression version(QStringLiteral("^\\d+(\\.\\d+){0,2}$"));
            if (!(v.isEmpty() && k != QLatin1String("minimum")) && !version.match(v).hasMatch())
                return tr("\"%1\" must be a firmware version such as 1.7.1, not \"%2\"").arg(k, v);
        }
        return {};
    }
    bool ok = false;
    const double v = value.toDouble(&ok);
    if (!ok || !std::isfinite(v) || value.typeId() == QMetaType::QString || value.typeId() == QMetaType::Bool)
        return tr("\"%1\" must be a number").arg(k);
    if (v < p->min || v > p->max)
        return tr("\"%1\" = %2 is outside %3 … %4 %5").arg(k).arg(v).arg(p->min).arg(p->max).arg(
            QString::fromUtf8(p->unit));
    return {};
}

QString TestPlan::checkMarginal(StepKind kind, const QString &k, const QVariant &marginal, const QVariant &high)
{
    const ParamSpec *p = param(kind, k);
    if (!p)
        return tr("%1 has no parameter \"%2\"").arg(key(kind), k);
    if (!p->limit)
        return tr("\"%1\" is not a limit: it has no marginal band").arg(k);
    bool ok = false;
    const double v = marginal.toDouble(&ok);
    if (!ok || !std::isfinite(v) || marginal.typeId() == QMetaType::QString || marginal.typeId() == QMetaType::Bool)
        return tr("\"%1\": \"marginal_high\" must be a number").arg(k);
    const QString unit = *p->unit ? QStringLiteral(" ") + QString::fromUtf8(p->unit) : QString();
    if (v < p->min || v > p->max)
        return tr("\"%1\": \"marginal_high\" = %2 is outside %3 … %4%5")
            .arg(k)
            .arg(v)
            .arg(p->min)
            .arg(p->max)
            .arg(unit);
    // Equal to the limit would be a band no value falls into: refused rather than kept silently.
    if (!(v < high.toDouble()))
        return tr("\"%1\": \"marginal_high\" = %2%4 is not below the limit %3%4")
            .arg(k)
            .arg(v)
            .arg(high.toDouble())
            .arg(unit);
    return {};
}

QString TestPlan::conversionNote() const
{
    if (loadedVersion >= kVersion)
        return {};
    return tr("This plan was written in format version %1; it is converted to version %2 and will be saved as "
              "version %2.")
        .arg(loadedVersion)
        .arg(kVersion);
}

std::optional<TestPlan> TestPlan::fromJson(const QByteArray &json, QString *error)
{
    auto failWith = [error](const QString &why) -> std::optional<TestPlan> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (json.size() > kMaxBytes)
        return failWith(tr("the plan is larger than %1 KiB").arg(kMaxBytes / 1024));
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (doc.isNull())
        return failWith(tr("not JSON: %1 at byte %2").arg(parseError.errorString()).arg(parseError.offset));
    const QJsonObject root = doc.object();
    if (root.value(QStringLiteral("format")).toString() != QLatin1String(kFormat))
        return failWith(tr("not a station plan (\"format\" is not \"%1\")").arg(QLatin1String(kFormat)));
    const int version = root.value(QStringLiteral("version")).toInt(-1);
    if (version < 1 || version > kVersion)
        return failWith(tr("plan version %1 is not supported (this ImuDesk reads versions 1 to %2)")
                            .arg(root.value(QStringLiteral("version")).toVariant().toString())
                            .arg(kVersion));
    TestPlan plan;
    plan.loadedVersion = version;
    plan.name = root.value(QStringLiteral("name")).toString();
    const QJsonArray steps = root.value(QStringLiteral("steps")).toArray();
    if (steps.isEmpty())
        return failWith(tr("the plan has no steps"));
    for (int i = 0; i < steps.size(); ++i) {
        const QJsonObject o = steps.at(i).toObject();
        const QString k = o.value(QStringLiteral("step")).toString();
        const auto kind = kindFromKey(k);
        if (!kind)
            return failWith(tr("step %1: unknown step \"%2\"").arg(i + 1).arg(k));
        PlanStep s = defaultStep(*kind);
        for (auto it = o.begin(); it != o.end(); ++it) {
            if (it.key() == QLatin1String("step"))
                continue;
            if (it.key() == QLatin1String("enabled")) {
                if (!it.value().isBool())
                    return failWith(tr("step %1 (%2): \"enabled\" must be true or false").arg(i + 1).arg(k));
                s.enabled = it.value().toBool();
                continue;
            }
            // A limit with a band (version 2): {"high": limit, "marginal_high": band}. In a
            // version 1 plan, or for any other parameter, an object is refused as not a number.
            QJsonValue value = it.value();
            std::optional<QVariant> band;
            const ParamSpec *spec = param(*kind, it.key());
            if (version >= 2 && spec && spec->limit && value.isObject()) {
                const QJsonObject limit = value.toObject();
                for (auto f = limit.begin(); f != limit.end(); ++f)
                    if (f.key() != QLatin1String(kHigh) && f.key() != QLatin1String(kMarginalHigh))
                        return failWith(tr("step %1 (%2): \"%3\" has an unknown field \"%4\" (a limit is a number "
                                           "or {\"high\": …, \"marginal_high\": …})")
                                            .arg(i + 1)
                                            .arg(k, it.key(), f.key()));
                if (!limit.contains(QLatin1String(kHigh)))
                    return failWith(tr("step %1 (%2): \"%3\" has no \"high\" (the limit itself)")
                                        .arg(i + 1)
                                        .arg(k, it.key()));
                value = limit.value(QLatin1String(kHigh));
                if (limit.contains(QLatin1String(kMarginalHigh)))
                    band = limit.value(QLatin1String(kMarginalHigh)).toVariant();
            }
            const QVariant v = value.toVariant();
            if (const QString why = checkValue(*kind, it.key(), v); !why.isEmpty())
                return failWith(tr("step %1 (%2): %3").arg(i + 1).arg(k, why));
            if (band) {
                if (const QString why = checkMarginal(*kind, it.key(), *band, v); !why.isEmpty())
                    return failWith(tr("step %1 (%2): %3").arg(i + 1).arg(k, why));
                s.marginal[it.key()] = band->toDouble();
            }
            s.params[it.key()] = spec->text ? QVariant(v.toString()) : QVariant(v.toDouble());
        }
        plan.steps.push_back(std::move(s));
    }
    return plan;
}

QByteArray TestPlan::toJson() const
{
    QJsonArray steps;
    for (const PlanStep &s : this->steps) {
        QJsonObject o;
        o.insert(QStringLiteral("step"), key(s.kind));
        if (!s.enabled)
            o.insert(QStringLiteral("enabled"), false);
        for (const ParamSpec &p : params(s.kind)) {
            const QString k = QString::fromLatin1(p.key);
            // Without a band a limit stays a plain number: such plans read as they did in version 1.
            const auto band = p.limit ? s.marginalOf(p.key) : std::nullopt;
            if (band)
                o.insert(k, QJsonObject{{QLatin1String(kHigh), s.number(p.key)},
                                        {QLatin1String(kMarginalHigh), *band}});
            else
                o.insert(k, p.text ? QJsonValue(s.text(p.key)) : QJsonValue(s.number(p.key)));
        }
        steps.append(o);
    }
    QJsonObject root{{QStringLiteral("format"), QLatin1String(kFormat)},
                     {QStringLiteral("version"), kVersion},
                     {QStringLiteral("name"), name},
                     {QStringLiteral("steps"), steps}};
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

std::optional<TestPlan> TestPlan::load(const QString &path, QString *error)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        if (error)
            *error = tr("cannot open %1: %2").arg(QDir::toNativeSeparators(path), f.errorString());
        return std::nullopt;
    }
    auto plan = fromJson(f.read(kMaxBytes + 1), error);
    if (plan)
        plan->baseDir = QFileInfo(path).absolutePath();
    return plan;
}

bool TestPlan::save(const QString &path, QString *error) const
{
    QSaveFile f(path);
    const QByteArray data = toJson();
    if (!f.open(QIODevice::WriteOnly) || f.write(data) != data.size() || !f.commit()) {
        if (error)
            *error = tr("cannot write %1: %2. Choose another folder or free some space.")
                         .arg(QDir::toNativeSeparators(path), f.errorString());
        return false;
    }
    return true;
}

QString TestPlan::resolve(const QString &path) const
{
    if (path.isEmpty() || QFileInfo(path).isAbsolute() || baseDir.isEmpty())
        return path;
    return QDir(baseDir).filePath(path);
}

QStringList TestPlan::problems() const
{
    QStringList out;
    if (steps.empty())
        out << tr("the plan has no steps");
    for (size_t i = 0; i < steps.size(); ++i) {
        const PlanStep &s = steps[i];
        for (auto it = s.params.begin(); it != s.params.end(); ++it)
            if (const QString why = checkValue(s.kind, it.key(), it.value()); !why.isEmpty())
                out << tr("step %1 (%2): %3").arg(i + 1).arg(key(s.kind), why);
        for (auto it = s.marginal.begin(); it != s.marginal.end(); ++it)
            if (const QString why = checkMarginal(s.kind, it.key(), it.value(), s.params.value(it.key()));
                !why.isEmpty())
                out << tr("step %1 (%2): %3").arg(i + 1).arg(key(s.kind), why);
        if (!s.enabled)
            continue;
        auto needFile = [&](const char *k, bool required) {
            const QString p = s.text(k);
            if (p.isEmpty()) {
                if (required)
                    out << tr("step %1 (%2): no %3 file given").arg(i + 1).arg(key(s.kind), QLatin1String(k));
                return;
            }
            if (!QFileInfo::exists(resolve(p)))
                out << tr("step %1 (%2): %3 not found").arg(i + 1).arg(key(s.kind), QDir::toNativeSeparators(resolve(p)));
        };
        if (s.kind == StepKind::Profile)
            needFile("profile", true);
        if (s.kind == StepKind::Firmware)
            needFile("image", false);
    }
    return out;
}

} // namespace imudesk::station
