#include "report_json.h"

#include "model/sample.h"

#include <QJsonArray>

#include <cmath>

namespace imudesk::verify {

namespace {

QJsonValue number(double v, bool judged)
{
    return judged && std::isfinite(v) ? QJsonValue(v) : QJsonValue();
}

QJsonValue triple(const Eigen::Vector3d &v, bool judged)
{
    if (!judged)
        return QJsonValue();
    return QJsonArray{v.x(), v.y(), v.z()};
}

void putFigure3(QJsonObject &o, const char *name, const Figure3 &f)
{
    const QString key = QLatin1String(name);
    o[key] = triple(f.value, f.judged);
    o[key + QLatin1String("_sigma")] = triple(f.sigma, f.judged);
    if (!f.judged)
        o[key + QLatin1String("_why")] = f.why;
}

void putFigure(QJsonObject &o, const QString &key, const Figure &f)
{
    o[key] = number(f.value, f.judged);
    o[key + QLatin1String("_sigma")] = number(f.sigma, f.judged);
    if (!f.judged)
        o[key + QLatin1String("_why")] = f.why;
}

// The three misalignment angles by the pair of axes they join.
QJsonValue pairs(const Eigen::Vector3d &deg, bool judged)
{
    if (!judged)
        return QJsonValue();
    return QJsonObject{{QStringLiteral("xy"), deg.x()}, {QStringLiteral("xz"), deg.y()}, {QStringLiteral("yz"), deg.z()}};
}

} // namespace

QJsonObject toJson(const CheckReport &r, const QString &source)
{
    QJsonObject o;
    o[QStringLiteral("source")] = source;
    o[QStringLiteral("samples")] = double(r.samples);
    o[QStringLiteral("duration_s")] = r.durationS;
    o[QStringLiteral("still_intervals")] = int(r.poses.size());
    o[QStringLiteral("poses")] = r.distinctPoses;
    o[QStringLiteral("gravity_m_s2")] = r.gravityG * model::kGravity;
    o[QStringLiteral("gravity_given")] = r.gravityGiven;
    putFigure3(o, "acc_bias_mg", r.accBiasMg);
    putFigure3(o, "acc_scale_error_pct", r.accScalePct);
    putFigure(o, QStringLiteral("acc_misalignment_deg"), r.accMisalignmentDeg);
    o[QStringLiteral("acc_misalignment_axes_deg")] = pairs(r.accMisalignmentAxesDeg, r.accMisalignmentDeg.judged);
    if (r.accBiasMg.judged)
        o[QStringLiteral("acc_fit_residual_mg")] = r.accResidualMg;
    putFigure3(o, "gyro_bias_dps", r.gyroBiasDps);
    putFigure3(o, "gyro_scale_error_pct", r.gyroScalePct);
    putFigure(o, QStringLiteral("gyro_misalignment_deg"), r.gyroMisalignmentDeg);
    o[QStringLiteral("gyro_misalignment_axes_deg")] = pairs(r.gyroMisalignmentAxesDeg, r.gyroMisalignmentDeg.judged);
    o[QStringLiteral("gyro_turns")] = r.gyroTurns;
    QJsonObject att;
    putFigure(att, QStringLiteral("roll"), r.rollErrDeg);
    putFigure(att, QStringLiteral("pitch"), r.pitchErrDeg);
    putFigure(att, QStringLiteral("heading"), r.headingErrDeg);
    o[QStringLiteral("attitude_error_deg")] = att;
    QJsonObject dyn;
    putFigure(dyn, QStringLiteral("rms_deg"), r.dynamicRmsDeg);
    putFigure(dyn, QStringLiteral("max_deg"), r.dynamicMaxDeg);
    putFigure(dyn, QStringLiteral("lag_ms"), r.dynamicLagMs);
    o[QStringLiteral("dynamic")] = dyn;
    if (r.hardIronRemoved)
        o[QStringLiteral("hard_iron_removed_ut")] = QJsonArray{r.hardIronUt.x(), r.hardIronUt.y(), r.hardIronUt.z()};
    QJsonArray poses;
    for (const Pose &p : r.poses) {
        QJsonObject j{{QStringLiteral("from_s"), p.fromS},
                      {QStringLiteral("to_s"), p.toS},
                      {QStringLiteral("distinct"), p.distinct},
                      {QStringLiteral("acc_g"), QJsonArray{p.acc.x(), p.acc.y(), p.acc.z()}},
                      {QStringLiteral("roll_error_deg"), number(p.rollErrDeg, p.tiltUsed)},
                      {QStringLiteral("pitch_error_deg"), number(p.pitchErrDeg, p.tiltUsed)},
                      {QStringLiteral("heading_error_deg"), number(p.headingErrDeg, p.headingUsed)}};
        if (!p.setAside.isEmpty())
            j[QStringLiteral("set_aside")] = p.setAside;
        poses.append(j);
    }
    o[QStringLiteral("pose_list")] = poses;
    o[QStringLiteral("verdict")] = QString::fromLatin1(verdictName(r.verdict));
    o[QStringLiteral("reasons")] = QJsonArray::fromStringList(r.reasons);
    return o;
}


} // namespace imudesk::verify
