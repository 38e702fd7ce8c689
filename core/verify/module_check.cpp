// The module check in all, and its verdict (module_check.h).
#include "check_steps.h"
#include "local_gravity.h"

#include "model/sample.h"

#include <algorithm>
#include <cmath>

namespace imudesk::verify {

const char *verdictName(Verdict v)
{
    switch (v) {
    case Verdict::Pass: return "pass";
    case Verdict::Warn: return "warn";
    case Verdict::Fail: return "fail";
    case Verdict::CannotJudge: return "cannot judge";
    }
    return "?";
}

namespace {

struct NamedLimit {
    const char *name;
    Limit Limits::*member;
};
constexpr NamedLimit kLimitNames[] = {
    {"acc_bias_mg", &Limits::accBiasMg},         {"acc_scale_error_pct", &Limits::accScalePct},
    {"acc_misalignment_deg", &Limits::accMisalignmentDeg}, {"gyro_bias_dps", &Limits::gyroBiasDps},
    {"gyro_scale_error_pct", &Limits::gyroScalePct}, {"gyro_misalignment_deg", &Limits::gyroMisalignmentDeg},
    {"tilt_deg", &Limits::tiltDeg},
    {"heading_deg", &Limits::headingDeg},        {"dynamic_rms_deg", &Limits::dynamicRmsDeg},
    {"lag_ms", &Limits::lagMs},
};

// One figure's judgement: the worst axis's.
struct Judged {
    Verdict verdict = Verdict::CannotJudge;
    QString text;
    bool required = true; // a verdict needs it judged (else: cannot judge, unless a figure fails)
};

Verdict judge(double value, double sigma, const Limit &limit)
{
    const double bound = 1.959964 * sigma;
    if (std::fabs(value) + bound <= limit.pass)
        return Verdict::Pass;
    if (std::fabs(value) - bound > limit.fail)
        return Verdict::Fail;
    return Verdict::Warn;
}

int severity(Verdict v)
{
    switch (v) {
    case Verdict::Fail: return 3;
    case Verdict::Warn: return 2;
    case Verdict::Pass: return 1;
    case Verdict::CannotJudge: return 0;
    }
    return 0;
}

} // namespace

QString verdictText(Verdict v)
{
    switch (v) {
    case Verdict::Pass: return CheckReport::tr("pass");
    case Verdict::Warn: return CheckReport::tr("warn");
    case Verdict::Fail: return CheckReport::tr("fail");
    case Verdict::CannotJudge: return CheckReport::tr("cannot judge");
    }
    return {};
}

namespace {

// "accelerometer bias: 12.3 ± 0.8 mg (Z; 95 %), pass at most 10, fail above 25: warn".
Judged judgeFigure(const QString &what, const QString &unit, int decimals, const Eigen::Vector3d &value,
                   const Eigen::Vector3d &sigma, int axes, const Limit &limit)
{
    static const char *const kAxis[3] = {"X", "Y", "Z"};
    Judged j;
    int worst = 0;
    Verdict v = Verdict::Pass;
    for (int a = 0; a < axes; ++a) {
        const Verdict va = judge(value[a], sigma[a], limit);
        if (severity(va) > severity(v) || (severity(va) == severity(v) && std::fabs(value[a]) > std::fabs(value[worst]))) {
            v = va;
            worst = a;
        }
    }
    j.verdict = v;
    const QString axis = axes == 3 ? QStringLiteral(" (%1)").arg(QLatin1String(kAxis[worst])) : QString();
    j.text = CheckReport::tr("%1: %2 ± %3 %4%5 (95 %), pass at most %6, fail above %7: %8")
                 .arg(what)
                 .arg(value[worst], 0, 'f', decimals)
                 .arg(1.959964 * sigma[worst], 0, 'f', decimals)
                 .arg(unit, axis)
                 .arg(limit.pass)
                 .arg(limit.fail)
                 .arg(verdictText(v));
    return j;
}

Judged notJudged(const QString &what, const QString &why)
{
    return Judged{Verdict::CannotJudge, CheckReport::tr("%1: cannot judge, %2").arg(what, why), true};
}

} // namespace

Limit *Limits::byName(const QString &name)
{
    for (const NamedLimit &n : kLimitNames)
        if (name == QLatin1String(n.name))
            return &(this->*(n.member));
    return nullptr;
}

QStringList Limits::names()
{
    QStringList out;
    for (const NamedLimit &n : kLimitNames)
        out << QLatin1String(n.name);
    return out;
}

Verdict CheckReport::figureVerdict(const QString &limitName) const
{
    for (const auto &[name, verdict] : figureVerdicts)
        if (name == limitName)
            return verdict;
    return Verdict::CannotJudge;
}

CheckReport checkModule(const std::vector<MotionSample> &samples, const CheckOptions &options)
{
    CheckReport r;
    r.samples = samples.size();
    if (!samples.empty())
        r.durationS = samples.back().tS - samples.front().tS;
    r.gravityGiven = options.gravityMs2 > 0;
    r.gravityG = (r.gravityGiven ? options.gravityMs2 : kStandardGravity) / model::kGravity;
    r.poses = findStillPoses(samples, options);
    r.distinctPoses = groupPoses(r.poses, options.samePoseDeg);

    const QString holdStill = CheckReport::tr("hold the module still for 3 s in each of at least %1 orientations "
                                              "(every face up and down, then between them)")
                                  .arg(options.minPoses);
    AccFit acc;
    if (r.distinctPoses >= options.minPoses)
        acc = fitAccelerometer(r.poses, r.gravityG);
    if (acc.ok) {
        const AccFigures f = accFigures(acc);
        r.accCorrection = acc.correction;
        r.accBiasG = acc.biasG;
        r.accResidualMg = acc.rmsResidualG * 1000.0;
        r.accBiasMg = Figure3{true, f.biasMg, f.biasSigma, {}};
        Eigen::Vector3d scaleSigma = f.scaleSigma;
        if (!r.gravityGiven) // the place's gravity unknown: its spread is the scale's too
            scaleSigma = (scaleSigma.cwiseAbs2()
                          + Eigen::Vector3d::Constant(std::pow(100.0 * kAssumedGravitySigma / kStandardGravity, 2)))
                             .cwiseSqrt();
        r.accScalePct = Figure3{true, f.scalePct, scaleSigma, {}};
        r.accMisalignmentAxesDeg = f.misalignmentDeg;
        r.accMisalignmentAxesSigmaDeg = f.misalignmentSigma;
        Eigen::Index worst = 0;
        f.misalignmentDeg.cwiseAbs().maxCoeff(&worst);
        r.accMisalignmentDeg = Figure{true, f.misalignmentDeg[worst], f.misalignmentSigma[worst], {}};
    } else {
        const QString why = r.poses.empty()
            ? CheckReport::tr("no still pose: %1").arg(holdStill)
            : r.distinctPoses < options.minPoses
            ? CheckReport::tr("%1 distinct still poses, %2 needed: %3").arg(r.distinctPoses).arg(options.minPoses).arg(holdStill)
            : CheckReport::tr("the poses do not pin the accelerometer's errors: %1").arg(holdStill);
        r.accBiasMg.why = r.accScalePct.why = r.accMisalignmentDeg.why = why;
    }

    const GyroFit gyro = fitGyro(samples, r.poses, acc);
    r.gyroBiasDps = gyro.biasDps;
    if (r.poses.empty())
        r.gyroBiasDps.why = CheckReport::tr("no still pose: %1").arg(holdStill);
    r.gyroScalePct = gyro.scalePct;
    r.gyroMisalignmentDeg = gyro.misalignmentDeg;
    r.gyroMisalignmentAxesDeg = gyro.misalignmentAxesDeg;
    r.gyroMisalignmentAxesSigmaDeg = gyro.misalignmentAxesSigmaDeg;
    if (!r.gyroMisalignmentDeg.judged && r.gyroMisalignmentDeg.why.isEmpty())
        r.gyroMisalignmentDeg.why = r.gyroScalePct.why;
    r.gyroTurns = gyro.turns;

    const AttitudeCheck att = checkAttitude(r.poses, acc, options);
    r.rollErrDeg = att.roll;
    r.pitchErrDeg = att.pitch;
    r.headingErrDeg = att.heading;
    r.hardIronUt = att.hardIronUt;
    r.hardIronRemoved = att.hardIronRemoved;
    const DynamicCheck dyn = checkDynamic(samples, r.poses, acc, gyro, att, options);
    r.dynamicRmsDeg = dyn.rmsDeg;
    r.dynamicMaxDeg = dyn.maxDeg;
    r.dynamicLagMs = dyn.lagMs;

    // The verdict: every figure judged, the worst decides.
    const Limits &l = options.limits;
    std::vector<Judged> judged;
    auto note = [&r, &judged](const char *key) {
        r.figureVerdicts.emplace_back(QLatin1String(key), judged.back().verdict);
    };
    auto add3 = [&](const char *key, const QString &what, const QString &unit, int decimals, const Figure3 &f,
                    const Limit &limit) {
        judged.push_back(f.judged ? judgeFigure(what, unit, decimals, f.value, f.sigma, 3, limit) : notJudged(what, f.why));
        note(key);
    };
    auto add1 = [&](const char *key, const QString &what, const QString &unit, int decimals, const Figure &f,
                    const Limit &limit) {
        judged.push_back(f.judged ? judgeFigure(what, unit, decimals, Eigen::Vector3d(f.value, 0, 0),
                                                Eigen::Vector3d(f.sigma, 0, 0), 1, limit)
                                  : notJudged(what, f.why));
        note(key);
    };
    add3("acc_bias_mg", CheckReport::tr("accelerometer bias"), QStringLiteral("mg"), 2, r.accBiasMg, l.accBiasMg);
    add3("acc_scale_error_pct", CheckReport::tr("accelerometer scale error"), QStringLiteral("%"), 3, r.accScalePct, l.accScalePct);
    add1("acc_misalignment_deg", CheckReport::tr("accelerometer misalignment"), QStringLiteral("°"), 3, r.accMisalignmentDeg, l.accMisalignmentDeg);
    add3("gyro_bias_dps", CheckReport::tr("gyro bias"), QStringLiteral("°/s"), 3, r.gyroBiasDps, l.gyroBiasDps);
    add3("gyro_scale_error_pct", CheckReport::tr("gyro scale error"), QStringLiteral("%"), 3, r.gyroScalePct, l.gyroScalePct);
    add1("gyro_misalignment_deg", CheckReport::tr("gyro misalignment"), QStringLiteral("°"), 3, r.gyroMisalignmentDeg,
         l.gyroMisalignmentDeg);
    add1("roll_deg", CheckReport::tr("roll error"), QStringLiteral("°"), 3, r.rollErrDeg, l.tiltDeg);
    add1("pitch_deg", CheckReport::tr("pitch error"), QStringLiteral("°"), 3, r.pitchErrDeg, l.tiltDeg);
    add1("heading_deg", CheckReport::tr("heading error"), QStringLiteral("°"), 2, r.headingErrDeg, l.headingDeg);
    add1("dynamic_rms_deg", CheckReport::tr("attitude error while moving (RMS)"), QStringLiteral("°"), 2, r.dynamicRmsDeg, l.dynamicRmsDeg);
    add1("lag_ms", CheckReport::tr("attitude lag"), QStringLiteral("ms"), 1, r.dynamicLagMs, l.lagMs);
    // The gyro's scale (it needs turns about every axis) and the heading (a magnetometer) may
    // stay unjudged in a verdict; the accelerometer, the gyro's bias and the tilt may not.
    // (indices as added above: 4 gyro scale, 5 its misalignment, 8 heading, 9 and 10 the attitude
    // while moving)
    for (size_t optional : {4, 5, 8, 9, 10})
        judged[optional].required = false;
    std::stable_sort(judged.begin(), judged.end(),
                     [](const Judged &a, const Judged &b) { return severity(a.verdict) > severity(b.verdict); });
    const bool missing = std::any_of(judged.begin(), judged.end(),
                                     [](const Judged &j) { return j.required && j.verdict == Verdict::CannotJudge; });
    r.verdict = judged.front().verdict == Verdict::Fail || !missing ? judged.front().verdict : Verdict::CannotJudge;
    for (const Judged &j : judged)
        r.reasons << j.text;
    if (!r.gravityGiven)
        r.reasons << CheckReport::tr("the bench's gravity was not given: standard gravity (9.80665 m/s²) assumed, its "
                                     "uncertainty (±0.3 %) is in the scale figures; give --gravity or --latitude "
                                     "and --height");
    if (r.hardIronRemoved)
        r.reasons << CheckReport::tr("a hard iron of %1 µT (the poses' fields off centre) was removed for the heading "
                                     "reference: calibrate the magnetometer")
                         .arg(r.hardIronUt.norm(), 0, 'f', 1);
    for (const Pose &p : r.poses)
        if (!p.setAside.isEmpty() && !p.tiltUsed)
            continue;
        else if (!p.setAside.isEmpty())
            r.reasons << CheckReport::tr("pose at %1 s set aside for the heading: %2").arg(p.fromS, 0, 'f', 1).arg(p.setAside);
    return r;
}

} // namespace imudesk::verify
