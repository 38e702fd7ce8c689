#include "core/station/result_conversion.h"

namespace imudesk::station {

results::ModuleRecord toResultRecord(const ModuleResult &r, const results::RunRecord &run)
{
    using results::MeasurementRecord;
    using results::ModuleRecord;
    using results::Outcome;
    using results::StepRecord;
    ModuleRecord m;
    m.uuid = results::newUuid();
    m.run = run;
    m.slot = r.port;
    m.serial = r.serial;
    m.serialRaw = r.serialRaw.isEmpty() ? r.serial.toUtf8() : r.serialRaw;
    m.product = r.product;
    m.firmwareBefore = r.firmware;
    m.firmwareAfter = r.firmwareAfter;
    m.attempt = r.attempt;
    m.started = r.started;
    m.finished = r.finished;
    switch (r.end) {
    case ModuleResult::End::EquipmentFailed:
    case ModuleResult::End::NotJudged: m.outcome = Outcome::Error; break;
    case ModuleResult::End::Cancelled: m.outcome = Outcome::Aborted; break;
    case ModuleResult::End::Completed: m.outcome = r.verdict == Verdict::Pass ? Outcome::Pass : Outcome::Fail; break;
    }
    for (int i = 0; i < int(r.steps.size()); ++i) {
        const StepResult &s = r.steps[size_t(i)];
        StepRecord st;
        st.index = i;
        st.kind = TestPlan::key(s.kind);
        st.name = s.title;
        st.skipped = s.verdict == Verdict::Skipped;
        st.outcome = s.verdict == Verdict::Fail ? (m.outcome == Outcome::Fail ? Outcome::Fail : m.outcome) : Outcome::Pass;
        st.detail = s.detail;
        st.started = s.started;
        st.finished = s.finished;
        m.steps.push_back(st);
        for (const Measurement &v : s.values) {
            MeasurementRecord mr;
            mr.step = i;
            mr.name = v.name;
            mr.value = v.value;
            mr.unit = v.unit;
            mr.comparator = v.comparator;
            if (v.comparator != QLatin1String("INFO"))
                mr.high = v.high;
            if (v.comparator == QLatin1String("ABS_LE"))
                mr.low = -v.high;
            if (v.marginalHigh && v.comparator != QLatin1String("INFO")) {
                mr.marginalHigh = *v.marginalHigh;
                if (v.comparator == QLatin1String("ABS_LE"))
                    mr.marginalLow = -*v.marginalHigh;
            }
            mr.outcome = v.ok ? Outcome::Pass : Outcome::Fail;
            mr.marginal = v.ok && v.marginal;
            m.marginal |= mr.marginal;
            m.measurements.push_back(mr);
        }
    }
    m.marginal = m.marginal && m.outcome == Outcome::Pass;
    if (!r.reportPath.isEmpty())
        m.artifacts.push_back({QStringLiteral("report"), QStringLiteral("application/pdf"), results::fileSha256(r.reportPath),
                               r.reportPath});
    if (!r.evidencePath.isEmpty())
        m.artifacts.push_back({QStringLiteral("recording"), QStringLiteral("application/x-imudesk-capture"),
                               results::fileSha256(r.evidencePath), r.evidencePath});
    return m;
}

} // namespace imudesk::station
