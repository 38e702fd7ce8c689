// The station's verify step (issue 55): the module check (core/verify/module_check.h) on the
// samples the step collected while the module was turned through its poses. Each figure goes
// into the step's measurements, so the PDF, the results database and the OpenHTF JSON carry it
// with its limit and marginal band: the worst axis of each three-axis figure, the larger of the
// roll and pitch errors, the heading error when the module has a magnetometer; the 95 % bound
// of each beside it (INFO). A figure the recording cannot back fails the step as "cannot
// judge", with what to do, and the module is not counted against the product (NotJudged).
#include "core/station/module_runner.h"
#include "verify/module_check.h"
#include "verify/motion_input.h"

#include <cmath>

namespace imudesk::station {

void ModuleRunner::evaluateVerify()
{
    const PlanStep &s = planStep();
    verify::MotionInput input;
    for (const model::Sample &x : m_samples)
        input.add(x);
    verify::CheckOptions options;
    if (s.number("gravity_ms2") > 0)
        options.gravityMs2 = s.number("gravity_ms2");
    const verify::CheckReport r = verify::checkModule(input.samples(), options);
    info(QStringLiteral("poses"), r.distinctPoses, QString());

    // What must be judged for a verdict (as the check's own): the accelerometer, the gyro's bias
    // and the tilt.
    const verify::Figure *notJudged = nullptr;
    QString why;
    if (!r.accBiasMg.judged)
        why = r.accBiasMg.why;
    else if (!r.gyroBiasDps.judged)
        why = r.gyroBiasDps.why;
    else if (!r.rollErrDeg.judged)
        notJudged = &r.rollErrDeg;
    if (notJudged)
        why = notJudged->why;
    if (!why.isEmpty()) {
        m_result.end = ModuleResult::End::NotJudged;
        fail(tr("cannot judge: %1").arg(why));
        return;
    }
    bool ok = true;
    auto worst3 = [&](const QString &name, const verify::Figure3 &f, const QString &unit, const char *limit) {
        Eigen::Index axis = 0;
        f.value.cwiseAbs().maxCoeff(&axis);
        ok = measureMagnitude(name, f.value[axis], unit, limit) && ok;
        info(name + QStringLiteral("_bound95"), 1.959964 * f.sigma[axis], unit);
    };
    worst3(QStringLiteral("acc_bias"), r.accBiasMg, QStringLiteral("mg"), "acc_bias_max_mg");
    worst3(QStringLiteral("acc_scale_error"), r.accScalePct, QStringLiteral("%"), "acc_scale_max_pct");
    worst3(QStringLiteral("gyro_bias"), r.gyroBiasDps, QStringLiteral("°/s"), "gyro_bias_max_dps");
    if (r.gyroScalePct.judged)
        worst3(QStringLiteral("gyro_scale_error"), r.gyroScalePct, QStringLiteral("%"), "gyro_scale_max_pct");
    if (r.gyroMisalignmentDeg.judged)
        info(QStringLiteral("gyro_misalignment"), r.gyroMisalignmentDeg.value, QStringLiteral("°"));
    const verify::Figure &tilt =
        std::fabs(r.rollErrDeg.value) >= std::fabs(r.pitchErrDeg.value) ? r.rollErrDeg : r.pitchErrDeg;
    ok = measureMagnitude(QStringLiteral("tilt_error"), tilt.value, QStringLiteral("°"), "tilt_max_deg") && ok;
    info(QStringLiteral("tilt_error_bound95"), tilt.bound95(), QStringLiteral("°"));
    if (r.headingErrDeg.judged) {
        ok = measureMagnitude(QStringLiteral("heading_error"), r.headingErrDeg.value, QStringLiteral("°"), "heading_max_deg")
            && ok;
        info(QStringLiteral("heading_error_bound95"), r.headingErrDeg.bound95(), QStringLiteral("°"));
    }
    if (r.dynamicRmsDeg.judged)
        info(QStringLiteral("attitude_error_moving_rms"), r.dynamicRmsDeg.value, QStringLiteral("°"));
    if (r.dynamicLagMs.judged)
        info(QStringLiteral("attitude_lag"), r.dynamicLagMs.value, QStringLiteral("ms"));
    endStep(ok ? Verdict::Pass : Verdict::Fail,
            tr("%1 poses; %2").arg(r.distinctPoses).arg(r.reasons.isEmpty() ? QString() : r.reasons.front()));
}

} // namespace imudesk::station
