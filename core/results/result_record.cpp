#include "result_record.h"

#include <QCryptographicHash>
#include <QFile>
#include <QJsonArray>
#include <QUuid>

namespace imudesk::results {

QString outcomeKey(Outcome o)
{
    switch (o) {
    case Outcome::Pass: return QStringLiteral("PASS");
    case Outcome::Fail: return QStringLiteral("FAIL");
    case Outcome::Error: return QStringLiteral("ERROR");
    case Outcome::Aborted: return QStringLiteral("ABORTED");
    }
    return {};
}

std::optional<Outcome> outcomeFromKey(const QString &key)
{
    for (Outcome o : {Outcome::Pass, Outcome::Fail, Outcome::Error, Outcome::Aborted})
        if (outcomeKey(o) == key)
            return o;
    return std::nullopt;
}

QString newUuid()
{
    return QUuid::createUuid().toString(QUuid::WithoutBraces);
}

QString fileSha256(const QString &path)
{
    QFile f(path);
    if (path.isEmpty() || !f.open(QIODevice::ReadOnly))
        return {};
    QCryptographicHash h(QCryptographicHash::Sha256);
    if (!h.addData(&f))
        return {};
    return QString::fromLatin1(h.result().toHex());
}

ModuleRecord ModuleRecord::fromStation(const station::ModuleResult &r, const RunRecord &run)
{
    using station::Verdict;
    ModuleRecord m;
    m.uuid = newUuid();
    m.run = run;
    m.slot = r.port;
    m.serial = r.serial;
    m.product = r.product;
    m.firmwareBefore = r.firmware;
    m.firmwareAfter = r.firmwareAfter;
    m.attempt = r.attempt;
    m.started = r.started;
    m.finished = r.finished;
    switch (r.end) {
    case station::ModuleResult::End::EquipmentFailed: m.outcome = Outcome::Error; break;
    case station::ModuleResult::End::Cancelled: m.outcome = Outcome::Aborted; break;
    case station::ModuleResult::End::Completed: m.outcome = r.verdict == Verdict::Pass ? Outcome::Pass : Outcome::Fail; break;
    }
    for (int i = 0; i < int(r.steps.size()); ++i) {
        const station::StepResult &s = r.steps[size_t(i)];
        StepRecord st;
        st.index = i;
        st.kind = station::TestPlan::key(s.kind);
        st.name = s.title;
        st.skipped = s.verdict == Verdict::Skipped;
        st.outcome = s.verdict == Verdict::Fail ? (m.outcome == Outcome::Fail ? Outcome::Fail : m.outcome) : Outcome::Pass;
        st.detail = s.detail;
        st.started = s.started;
        st.finished = s.finished;
        m.steps.push_back(st);
        for (const station::Measurement &v : s.values) {
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
            mr.outcome = v.ok ? Outcome::Pass : Outcome::Fail;
            m.measurements.push_back(mr);
        }
    }
    if (!r.reportPath.isEmpty())
        m.artifacts.push_back({QStringLiteral("report"), QStringLiteral("application/pdf"), fileSha256(r.reportPath), r.reportPath});
    if (!r.evidencePath.isEmpty())
        m.artifacts.push_back({QStringLiteral("recording"), QStringLiteral("application/x-imudesk-capture"),
                               fileSha256(r.evidencePath), r.evidencePath});
    return m;
}

QJsonObject ModuleRecord::toJson() const
{
    const auto iso = [](const QDateTime &t) { return t.isValid() ? t.toUTC().toString(Qt::ISODateWithMs) : QString(); };
    QJsonArray steps, measurements, artifacts;
    for (const StepRecord &s : this->steps)
        steps.append(QJsonObject{{QStringLiteral("index"), s.index},
                                 {QStringLiteral("kind"), s.kind},
                                 {QStringLiteral("name"), s.name},
                                 {QStringLiteral("outcome"), s.skipped ? QStringLiteral("SKIPPED") : outcomeKey(s.outcome)},
                                 {QStringLiteral("detail"), s.detail},
                                 {QStringLiteral("start_time"), iso(s.started)},
                                 {QStringLiteral("end_time"), iso(s.finished)}});
    for (const MeasurementRecord &v : this->measurements) {
        QJsonObject o{{QStringLiteral("step"), v.step},
                      {QStringLiteral("name"), v.name},
                      {QStringLiteral("value"), v.value},
                      {QStringLiteral("unit"), v.unit},
                      {QStringLiteral("comparator"), v.comparator},
                      {QStringLiteral("outcome"), outcomeKey(v.outcome)}};
        if (v.low)
            o.insert(QStringLiteral("low"), *v.low);
        if (v.high)
            o.insert(QStringLiteral("high"), *v.high);
        measurements.append(o);
    }
    for (const ArtifactRecord &a : this->artifacts)
        artifacts.append(QJsonObject{{QStringLiteral("kind"), a.kind}, {QStringLiteral("mime_type"), a.mime},
                                     {QStringLiteral("sha256"), a.sha256}, {QStringLiteral("location"), a.location}});
    return QJsonObject{
        {QStringLiteral("uuid"), uuid},
        {QStringLiteral("run"), QJsonObject{{QStringLiteral("uuid"), run.uuid},
                                            {QStringLiteral("station_id"), run.stationId},
                                            {QStringLiteral("operator"), run.operatorName},
                                            {QStringLiteral("plan"), run.planName},
                                            {QStringLiteral("plan_sha256"), run.planSha256},
                                            {QStringLiteral("imudesk_version"), run.imudeskVersion},
                                            {QStringLiteral("start_time"), iso(run.started)}}},
        {QStringLiteral("fixture_slot"), slot},
        {QStringLiteral("serial"), serial},
        {QStringLiteral("product"), product},
        {QStringLiteral("firmware_before"), firmwareBefore},
        {QStringLiteral("firmware_after"), firmwareAfter},
        {QStringLiteral("attempt"), attempt},
        {QStringLiteral("outcome"), outcomeKey(outcome)},
        {QStringLiteral("start_time"), iso(started)},
        {QStringLiteral("end_time"), iso(finished)},
        {QStringLiteral("steps"), steps},
        {QStringLiteral("measurements"), measurements},
        {QStringLiteral("artifacts"), artifacts}};
}

} // namespace imudesk::results
