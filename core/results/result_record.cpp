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
        if (v.marginalLow)
            o.insert(QStringLiteral("marginal_low"), *v.marginalLow);
        if (v.marginalHigh)
            o.insert(QStringLiteral("marginal_high"), *v.marginalHigh);
        if (v.marginal)
            o.insert(QStringLiteral("marginal"), true);
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
                                            {QStringLiteral("start_time"), iso(run.started)},
                                            {QStringLiteral("end_time"), iso(run.finished)}}},
        {QStringLiteral("fixture_slot"), slot},
        {QStringLiteral("serial"), serial},
        {QStringLiteral("serial_hex"), QString::fromLatin1(serialRaw.toHex())},
        {QStringLiteral("product"), product},
        {QStringLiteral("firmware_before"), firmwareBefore},
        {QStringLiteral("firmware_after"), firmwareAfter},
        {QStringLiteral("attempt"), attempt},
        {QStringLiteral("outcome"), outcomeKey(outcome)},
        {QStringLiteral("marginal"), marginal},
        {QStringLiteral("start_time"), iso(started)},
        {QStringLiteral("end_time"), iso(finished)},
        {QStringLiteral("steps"), steps},
        {QStringLiteral("measurements"), measurements},
        {QStringLiteral("artifacts"), artifacts}};
}

std::optional<ModuleRecord> ModuleRecord::fromJson(const QJsonObject &o)
{
    const auto time = [](const QJsonValue &v) {
        const QString s = v.toString();
        return s.isEmpty() ? QDateTime() : QDateTime::fromString(s, Qt::ISODateWithMs);
    };
    const auto number = [](const QJsonObject &o, const char *key) -> std::optional<double> {
        const QJsonValue v = o.value(QLatin1String(key));
        return v.isDouble() ? std::optional<double>(v.toDouble()) : std::nullopt;
    };
    const auto outcome = outcomeFromKey(o.value(QStringLiteral("outcome")).toString());
    const QJsonObject r = o.value(QStringLiteral("run")).toObject();
    if (o.value(QStringLiteral("uuid")).toString().isEmpty() || !outcome || r.value(QStringLiteral("uuid")).toString().isEmpty())
        return std::nullopt;
    ModuleRecord m;
    m.uuid = o.value(QStringLiteral("uuid")).toString();
    m.run = {r.value(QStringLiteral("uuid")).toString(), r.value(QStringLiteral("station_id")).toString(),
             r.value(QStringLiteral("operator")).toString(), r.value(QStringLiteral("plan")).toString(),
             r.value(QStringLiteral("plan_sha256")).toString(), r.value(QStringLiteral("imudesk_version")).toString(),
             time(r.value(QStringLiteral("start_time"))), time(r.value(QStringLiteral("end_time")))};
    m.slot = o.value(QStringLiteral("fixture_slot")).toString();
    m.serial = o.value(QStringLiteral("serial")).toString();
    m.serialRaw = QByteArray::fromHex(o.value(QStringLiteral("serial_hex")).toString().toLatin1());
    m.product = o.value(QStringLiteral("product")).toString();
    m.firmwareBefore = o.value(QStringLiteral("firmware_before")).toString();
    m.firmwareAfter = o.value(QStringLiteral("firmware_after")).toString();
    m.attempt = o.value(QStringLiteral("attempt")).toInt(1);
    m.outcome = *outcome;
    m.marginal = o.value(QStringLiteral("marginal")).toBool();
    m.started = time(o.value(QStringLiteral("start_time")));
    m.finished = time(o.value(QStringLiteral("end_time")));
    for (const QJsonValue &v : o.value(QStringLiteral("steps")).toArray()) {
        const QJsonObject s = v.toObject();
        const QString key = s.value(QStringLiteral("outcome")).toString();
        StepRecord st;
        st.index = s.value(QStringLiteral("index")).toInt();
        st.kind = s.value(QStringLiteral("kind")).toString();
        st.name = s.value(QStringLiteral("name")).toString();
        st.skipped = key == QLatin1String("SKIPPED");
        st.outcome = outcomeFromKey(key).value_or(Outcome::Pass);
        st.detail = s.value(QStringLiteral("detail")).toString();
        st.started = time(s.value(QStringLiteral("start_time")));
        st.finished = time(s.value(QStringLiteral("end_time")));
        m.steps.push_back(st);
    }
    for (const QJsonValue &v : o.value(QStringLiteral("measurements")).toArray()) {
        const QJsonObject x = v.toObject();
        MeasurementRecord mr;
        mr.step = x.value(QStringLiteral("step")).toInt();
        mr.name = x.value(QStringLiteral("name")).toString();
        mr.value = x.value(QStringLiteral("value")).toDouble();
        mr.unit = x.value(QStringLiteral("unit")).toString();
        mr.comparator = x.value(QStringLiteral("comparator")).toString();
        mr.low = number(x, "low");
        mr.high = number(x, "high");
        mr.marginalLow = number(x, "marginal_low");
        mr.marginalHigh = number(x, "marginal_high");
        mr.outcome = outcomeFromKey(x.value(QStringLiteral("outcome")).toString()).value_or(Outcome::Error);
        mr.marginal = x.value(QStringLiteral("marginal")).toBool();
        m.measurements.push_back(mr);
    }
    for (const QJsonValue &v : o.value(QStringLiteral("artifacts")).toArray()) {
        const QJsonObject a = v.toObject();
        m.artifacts.push_back({a.value(QStringLiteral("kind")).toString(), a.value(QStringLiteral("mime_type")).toString(),
                               a.value(QStringLiteral("sha256")).toString(), a.value(QStringLiteral("location")).toString()});
    }
    return m;
}

QJsonObject ModuleRecord::toOpenHtfJson() const
{
    const auto millis = [](const QDateTime &t) { return t.isValid() ? QJsonValue(double(t.toMSecsSinceEpoch())) : QJsonValue(); };
    // A phase per step; its measurements keyed by name, with their validators as OpenHTF writes
    // them ("x <= 0.05") and the marginal band beside them.
    QJsonArray phases;
    for (const StepRecord &s : steps) {
        QJsonObject ms;
        for (const MeasurementRecord &v : measurements) {
            if (v.step != s.index)
                continue;
            QJsonArray validators, marginal;
            if (v.comparator == QLatin1String("LE") && v.high)
                validators.append(QStringLiteral("x <= %1").arg(*v.high, 0, 'g', 12));
            if (v.comparator == QLatin1String("ABS_LE") && v.high)
                validators.append(QStringLiteral("%1 <= x <= %2").arg(-*v.high, 0, 'g', 12).arg(*v.high, 0, 'g', 12));
            if (v.marginalHigh)
                marginal.append(v.marginalLow ? QStringLiteral("%1 < x < %2").arg(*v.marginalLow, 0, 'g', 12).arg(*v.marginalHigh, 0, 'g', 12)
                                              : QStringLiteral("x < %1").arg(*v.marginalHigh, 0, 'g', 12));
            QJsonObject m{{QStringLiteral("name"), v.name},
                          {QStringLiteral("measured_value"), v.value},
                          {QStringLiteral("units"), QJsonObject{{QStringLiteral("suffix"), v.unit}}},
                          {QStringLiteral("outcome"), v.outcome == Outcome::Pass ? QStringLiteral("PASS") : QStringLiteral("FAIL")},
                          {QStringLiteral("marginal"), v.marginal},
                          {QStringLiteral("validators"), validators}};
            if (!marginal.isEmpty())
                m.insert(QStringLiteral("marginal_validators"), marginal);
            if (v.low)
                m.insert(QStringLiteral("low"), *v.low);
            if (v.high)
                m.insert(QStringLiteral("high"), *v.high);
            ms.insert(v.name, m);
        }
        phases.append(QJsonObject{
            {QStringLiteral("name"), s.kind},
            {QStringLiteral("descriptor_id"), s.index},
            {QStringLiteral("start_time_millis"), millis(s.started)},
            {QStringLiteral("end_time_millis"), millis(s.finished)},
            {QStringLiteral("outcome"), s.skipped ? QStringLiteral("SKIP") : s.outcome == Outcome::Pass ? QStringLiteral("PASS")
                                      : s.outcome == Outcome::Fail ? QStringLiteral("FAIL") : QStringLiteral("ERROR")},
            {QStringLiteral("result"), QJsonObject{{QStringLiteral("detail"), s.detail}, {QStringLiteral("title"), s.name}}},
            {QStringLiteral("measurements"), ms}});
    }
    QJsonObject attachments;
    for (const ArtifactRecord &a : artifacts)
        attachments.insert(a.kind, QJsonObject{{QStringLiteral("mimetype"), a.mime},
                                               {QStringLiteral("sha256"), a.sha256},
                                               {QStringLiteral("location"), a.location}});
    return QJsonObject{
        {QStringLiteral("dut_id"), serial},
        {QStringLiteral("station_id"), run.stationId},
        {QStringLiteral("start_time_millis"), millis(started)},
        {QStringLiteral("end_time_millis"), millis(finished)},
        {QStringLiteral("outcome"), outcomeKey(outcome)},
        {QStringLiteral("marginal"), marginal},
        {QStringLiteral("outcome_details"), QJsonArray()},
        {QStringLiteral("metadata"),
         QJsonObject{{QStringLiteral("test_name"), run.planName},
                     {QStringLiteral("plan_sha256"), run.planSha256},
                     {QStringLiteral("run_uuid"), run.uuid},
                     {QStringLiteral("module_uuid"), uuid},
                     {QStringLiteral("operator_name"), run.operatorName},
                     {QStringLiteral("fixture_slot"), slot},
                     {QStringLiteral("product"), product},
                     {QStringLiteral("firmware_before"), firmwareBefore},
                     {QStringLiteral("firmware_after"), firmwareAfter},
                     {QStringLiteral("attempt"), attempt},
                     {QStringLiteral("serial_hex"), QString::fromLatin1(serialRaw.toHex())}}},
        {QStringLiteral("code_info"), QJsonObject{{QStringLiteral("name"), QStringLiteral("ImuDesk")},
                                                  {QStringLiteral("version"), run.imudeskVersion}}},
        {QStringLiteral("phases"), phases},
        {QStringLiteral("attachments"), attachments}};
}

} // namespace imudesk::results
