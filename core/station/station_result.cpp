#include "core/station/station_result.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QStringDecoder>

namespace imudesk::station {

QString verdictKey(Verdict v)
{
    switch (v) {
    case Verdict::Pending: return QStringLiteral("pending");
    case Verdict::Running: return QStringLiteral("running");
    case Verdict::Pass: return QStringLiteral("pass");
    case Verdict::Fail: return QStringLiteral("fail");
    case Verdict::Skipped: return QStringLiteral("skipped");
    }
    return {};
}

QString verdictText(Verdict v)
{
    switch (v) {
    case Verdict::Pending: return QCoreApplication::translate("imudesk::station::Verdict", "waiting");
    case Verdict::Running: return QCoreApplication::translate("imudesk::station::Verdict", "running");
    case Verdict::Pass: return QCoreApplication::translate("imudesk::station::Verdict", "pass");
    case Verdict::Fail: return QCoreApplication::translate("imudesk::station::Verdict", "fail");
    case Verdict::Skipped: return QCoreApplication::translate("imudesk::station::Verdict", "skipped");
    }
    return {};
}

QString isoUtc(const QDateTime &t)
{
    return t.isValid() ? t.toUTC().toString(Qt::ISODateWithMs) : QString();
}

QString bytesAsText(const QByteArray &raw)
{
    QString out;
    out.reserve(raw.size());
    int i = 0;
    while (i < raw.size()) {
        const auto b = static_cast<unsigned char>(raw[i]);
        // The length of the UTF-8 sequence this byte starts (0: not a lead byte).
        const int n = b < 0x80 ? 1 : (b >= 0xC2 && b <= 0xDF) ? 2 : (b >= 0xE0 && b <= 0xEF) ? 3 : (b >= 0xF0 && b <= 0xF4) ? 4 : 0;
        if (n > 1 && i + n <= raw.size()) {
            QString decoded;
            QStringDecoder utf8(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
            decoded = utf8(raw.mid(i, n));
            if (!utf8.hasError() && !decoded.contains(QChar::ReplacementCharacter)) {
                out += decoded;
                i += n;
                continue;
            }
        }
        if (n == 1 && b >= 0x20 && b != 0x7F && b != '\\')
            out += QLatin1Char(char(b));
        else if (n == 1 && b == '\\')
            out += QStringLiteral("\\\\");
        else
            out += QStringLiteral("\\x%1").arg(b, 2, 16, QLatin1Char('0'));
        ++i;
    }
    return out;
}

QJsonObject StepResult::toJson() const
{
    QJsonArray vals;
    for (const Measurement &m : values) {
        QJsonObject o{{QStringLiteral("name"), m.name},
                      {QStringLiteral("value"), m.value},
                      {QStringLiteral("unit"), m.unit},
                      {QStringLiteral("limit"), m.limit},
                      {QStringLiteral("ok"), m.ok}};
        // Only where there is a band: the summaries of plans without one stay as they were.
        if (m.marginalHigh)
            o.insert(QStringLiteral("marginal_high"), *m.marginalHigh);
        if (m.marginal)
            o.insert(QStringLiteral("marginal"), true);
        vals.append(o);
    }
    return QJsonObject{{QStringLiteral("step"), TestPlan::key(kind)},
                       {QStringLiteral("verdict"), verdictKey(verdict)},
                       {QStringLiteral("detail"), detail},
                       {QStringLiteral("values"), vals},
                       {QStringLiteral("started"), isoUtc(started)},
                       {QStringLiteral("finished"), isoUtc(finished)}};
}

ModuleResult ModuleResult::pending(const QString &port, const TestPlan &plan)
{
    ModuleResult r;
    r.port = port;
    for (const PlanStep &s : plan.steps) {
        StepResult st;
        st.kind = s.kind;
        st.title = TestPlan::title(s.kind);
        r.steps.push_back(st);
    }
    return r;
}

int ModuleResult::failedStep() const
{
    for (size_t i = 0; i < steps.size(); ++i)
        if (steps[i].verdict == Verdict::Fail)
            return int(i);
    return -1;
}

QString ModuleResult::failureSummary() const
{
    const int i = failedStep();
    if (i < 0)
        return {};
    const StepResult &s = steps[size_t(i)];
    QStringList bad;
    for (const Measurement &m : s.values)
        if (!m.ok)
            bad << QStringLiteral("%1 %2 %3 (%4)").arg(m.name).arg(m.value, 0, 'g', 4).arg(m.unit, m.limit).simplified();
    return bad.isEmpty() ? QStringLiteral("%1: %2").arg(s.title, s.detail)
                         : QStringLiteral("%1: %2").arg(s.title, bad.join(QStringLiteral("; ")));
}

bool ModuleResult::marginal() const
{
    for (const StepResult &s : steps)
        for (const Measurement &m : s.values)
            if (m.marginal)
                return true;
    return false;
}

QJsonObject ModuleResult::toJson() const
{
    QJsonArray st;
    for (const StepResult &s : steps)
        st.append(s.toJson());
    const int failed = failedStep();
    return QJsonObject{{QStringLiteral("port"), port},
                       {QStringLiteral("serial"), serial},
                       {QStringLiteral("product"), product},
                       {QStringLiteral("firmware"), firmware},
                       {QStringLiteral("firmware_after"), firmwareAfter},
                       {QStringLiteral("verdict"), verdictKey(verdict)},
                       {QStringLiteral("failed_step"), failed < 0 ? QString() : TestPlan::key(steps[size_t(failed)].kind)},
                       {QStringLiteral("failure"), failureSummary()},
                       {QStringLiteral("marginal"), marginal()},
                       {QStringLiteral("attempt"), attempt},
                       {QStringLiteral("started"), isoUtc(started)},
                       {QStringLiteral("finished"), isoUtc(finished)},
                       {QStringLiteral("evidence"), evidencePath},
                       {QStringLiteral("report"), reportPath},
                       {QStringLiteral("steps"), st}};
}

} // namespace imudesk::station
