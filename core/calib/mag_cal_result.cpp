#include "calib/mag_cal_result.h"

#include <QJsonArray>

#include <cmath>

namespace imudesk::calib {

namespace {

// A figure that may be unknown (NaN) or unbounded (inf): JSON null for unknown, a large
// finite number for unbounded (JSON has no infinity).
QJsonValue figure(double v)
{
    if (std::isnan(v))
        return QJsonValue(QJsonValue::Null);
    return std::isinf(v) ? QJsonValue(v > 0 ? 1e12 : -1e12) : QJsonValue(v);
}

double figureFrom(const QJsonValue &v)
{
    return v.isDouble() ? v.toDouble() : std::numeric_limits<double>::quiet_NaN();
}

} // namespace

const char *modeName(MagCalMode m)
{
    switch (m) {
    case MagCalMode::Full3D: return "full";
    case MagCalMode::HardIronOnly: return "hard_iron_only";
    case MagCalMode::Planar2D: return "planar";
    }
    return "full";
}

const char *verdictName(MagVerdict v)
{
    switch (v) {
    case MagVerdict::Pass: return "pass";
    case MagVerdict::Warn: return "warn";
    case MagVerdict::Fail: return "fail";
    case MagVerdict::Refused: return "refused";
    }
    return "refused";
}

bool parseMode(const QString &text, MagCalMode &out)
{
    for (MagCalMode m : {MagCalMode::Full3D, MagCalMode::HardIronOnly, MagCalMode::Planar2D})
        if (text.compare(QLatin1String(modeName(m)), Qt::CaseInsensitive) == 0) {
            out = m;
            return true;
        }
    return false;
}

bool parseVerdict(const QString &text, MagVerdict &out)
{
    for (MagVerdict v : {MagVerdict::Pass, MagVerdict::Warn, MagVerdict::Fail, MagVerdict::Refused})
        if (text.compare(QLatin1String(verdictName(v)), Qt::CaseInsensitive) == 0) {
            out = v;
            return true;
        }
    return false;
}

QString MagCalResult::verdictText(MagVerdict v)
{
    switch (v) {
    case MagVerdict::Pass: return tr("Pass");
    case MagVerdict::Warn: return tr("Warning");
    case MagVerdict::Fail: return tr("Fail");
    case MagVerdict::Refused: return tr("Refused");
    }
    return {};
}

QJsonObject MagCalResult::toJson() const
{
    QJsonObject o;
    o.insert(QStringLiteral("mode"), QLatin1String(modeName(mode)));
    o.insert(QStringLiteral("hard_iron"), QJsonArray{hardIron.x(), hardIron.y(), hardIron.z()});
    QJsonArray rows;
    for (int r = 0; r < 3; ++r)
        rows.append(QJsonArray{softIron(r, 0), softIron(r, 1), softIron(r, 2)});
    o.insert(QStringLiteral("soft_iron"), rows);
    o.insert(QStringLiteral("field_ut"), fieldUt);
    o.insert(QStringLiteral("fit_error_pct"), fitErrorPct);
    o.insert(QStringLiteral("coverage_pct"), coveragePct);
    o.insert(QStringLiteral("verdict"), QLatin1String(verdictName(verdict)));
    o.insert(QStringLiteral("reason"), reason);
    o.insert(QStringLiteral("residual_rms_ut"), residualRmsUt);
    o.insert(QStringLiteral("eigen_ratio"), eigenRatio);
    o.insert(QStringLiteral("samples"), samples);
    o.insert(QStringLiteral("outliers"), outliers);
    o.insert(QStringLiteral("hard_iron_only_offered"), hardIronOnlyOffered);
    o.insert(QStringLiteral("planar_offered"), planarOffered);
    o.insert(QStringLiteral("z_offset_known"), zOffsetKnown);
    o.insert(QStringLiteral("hard_iron_sigma_ut"), figure(hardIronSigmaUt));
    o.insert(QStringLiteral("soft_iron_sigma_pct"), figure(softIronSigmaPct));
    o.insert(QStringLiteral("predicted_heading_error_deg"), figure(predictedHeadingErrorDeg));
    o.insert(QStringLiteral("predicted_heading_error_95_deg"), figure(predictedHeadingError95Deg));
    return o;
}

bool MagCalResult::fromJson(const QJsonObject &o, MagCalResult &out)
{
    MagCalResult r;
    if (!parseMode(o.value(QStringLiteral("mode")).toString(), r.mode)
        || !parseVerdict(o.value(QStringLiteral("verdict")).toString(), r.verdict))
        return false;
    const QJsonArray hi = o.value(QStringLiteral("hard_iron")).toArray();
    const QJsonArray si = o.value(QStringLiteral("soft_iron")).toArray();
    if (hi.size() != 3 || si.size() != 3)
        return false;
    for (int i = 0; i < 3; ++i) {
        r.hardIron[i] = hi.at(i).toDouble();
        const QJsonArray row = si.at(i).toArray();
        if (row.size() != 3)
            return false;
        for (int j = 0; j < 3; ++j)
            r.softIron(i, j) = row.at(j).toDouble();
    }
    r.reason = o.value(QStringLiteral("reason")).toString();
    r.fieldUt = o.value(QStringLiteral("field_ut")).toDouble();
    r.fitErrorPct = o.value(QStringLiteral("fit_error_pct")).toDouble();
    r.coveragePct = o.value(QStringLiteral("coverage_pct")).toDouble();
    r.residualRmsUt = o.value(QStringLiteral("residual_rms_ut")).toDouble();
    r.eigenRatio = o.value(QStringLiteral("eigen_ratio")).toDouble();
    r.samples = o.value(QStringLiteral("samples")).toInt();
    r.outliers = o.value(QStringLiteral("outliers")).toInt();
    r.hardIronOnlyOffered = o.value(QStringLiteral("hard_iron_only_offered")).toBool();
    r.planarOffered = o.value(QStringLiteral("planar_offered")).toBool();
    r.zOffsetKnown = o.value(QStringLiteral("z_offset_known")).toBool(true);
    // Absent in results written before the accuracy was estimated: unknown.
    r.hardIronSigmaUt = figureFrom(o.value(QStringLiteral("hard_iron_sigma_ut")));
    r.softIronSigmaPct = figureFrom(o.value(QStringLiteral("soft_iron_sigma_pct")));
    r.predictedHeadingErrorDeg = figureFrom(o.value(QStringLiteral("predicted_heading_error_deg")));
    r.predictedHeadingError95Deg = figureFrom(o.value(QStringLiteral("predicted_heading_error_95_deg")));
    out = r;
    return true;
}

} // namespace imudesk::calib
