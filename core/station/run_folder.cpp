#include "core/station/run_folder.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QRegularExpression>
#include <QSaveFile>

namespace imudesk::station {

namespace {
QString fileSafe(QString s)
{
    static const QRegularExpression bad(QStringLiteral("[^A-Za-z0-9._-]+"));
    s.replace(bad, QStringLiteral("_"));
    return s.isEmpty() ? QStringLiteral("module") : s;
}

QString csvField(const QString &s)
{
    if (!s.contains(QLatin1Char(',')) && !s.contains(QLatin1Char('"')) && !s.contains(QLatin1Char('\n')))
        return s;
    QString q = s;
    q.replace(QLatin1Char('"'), QStringLiteral("\"\""));
    return QLatin1Char('"') + q + QLatin1Char('"');
}

bool appendTo(const QString &path, const QByteArray &data, QString *error)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Append) || f.write(data) != data.size() || !f.flush()) {
        if (error)
            *error = RunFolder::tr("cannot write %1: %2. Free some space or choose another report folder.")
                         .arg(QDir::toNativeSeparators(path), f.errorString());
        return false;
    }
    return true;
}
} // namespace

QString RunFolder::newRunPath(const QString &parent, const TestPlan &plan)
{
    const QString name = fileSafe(plan.name.isEmpty() ? QStringLiteral("station") : plan.name);
    return QDir(parent).filePath(
        QStringLiteral("%1-%2").arg(name, QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss"))));
}

bool RunFolder::open(const QString &dir, const TestPlan &plan, QString *error)
{
    if (!QDir().mkpath(dir)) {
        if (error)
            *error = tr("cannot create the report folder %1: choose a folder you may write to")
                         .arg(QDir::toNativeSeparators(dir));
        return false;
    }
    m_dir = QFileInfo(dir).absoluteFilePath();
    const QString planPath = QDir(m_dir).filePath(QLatin1String(kPlanFile));
    if (QFileInfo::exists(planPath)) {
        QString why;
        const auto existing = TestPlan::load(planPath, &why);
        if (!existing || existing->toJson() != plan.toJson()) {
            if (error)
                *error = tr("%1 holds a run of another plan; choose a new folder so that results stay comparable")
                             .arg(QDir::toNativeSeparators(m_dir));
            return false;
        }
        return true;
    }
    return plan.save(planPath, error);
}

QList<QJsonObject> RunFolder::entries() const
{
    QList<QJsonObject> out;
    QFile f(QDir(m_dir).filePath(QLatin1String(kJsonlFile)));
    if (!f.open(QIODevice::ReadOnly))
        return out;
    while (!f.atEnd()) {
        const QByteArray line = f.readLine().trimmed();
        if (line.isEmpty())
            continue;
        const QJsonDocument d = QJsonDocument::fromJson(line);
        if (d.isObject())
            out << d.object();
    }
    return out;
}

int RunFolder::nextAttempt(const QString &serial) const
{
    int n = 0;
    for (const QJsonObject &o : entries())
        if (o.value(QStringLiteral("serial")).toString() == serial)
            ++n;
    return n + 1;
}

QString RunFolder::evidencePath(const QString &port) const
{
    return QDir(m_dir).filePath(QStringLiteral("evidence-%1-%2.imucap")
                                    .arg(fileSafe(QFileInfo(port).fileName()),
                                         QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss"))));
}

QString RunFolder::reportPath(const ModuleResult &r) const
{
    const QString who = r.serial.isEmpty() ? QStringLiteral("port-") + QFileInfo(r.port).fileName() : r.serial;
    return QDir(m_dir).filePath(QStringLiteral("%1-attempt%2.pdf").arg(fileSafe(who)).arg(r.attempt));
}

QString RunFolder::csvHeader()
{
    return QStringLiteral("serial,product,firmware,firmware_after,port,attempt,module_verdict,module_started,"
                          "module_finished,step_index,step,step_verdict,step_started,step_finished,name,value,unit,"
                          "limit,ok,detail");
}

QStringList RunFolder::csvRows(const ModuleResult &r)
{
    QStringList rows;
    const QString head = QStringList{csvField(r.serial), csvField(r.product), csvField(r.firmware),
                                     csvField(r.firmwareAfter), csvField(r.port), QString::number(r.attempt),
                                     verdictKey(r.verdict), isoUtc(r.started), isoUtc(r.finished)}
                             .join(QLatin1Char(','));
    for (size_t i = 0; i < r.steps.size(); ++i) {
        const StepResult &s = r.steps[i];
        const QString stepHead = QStringList{head, QString::number(i + 1), TestPlan::key(s.kind), verdictKey(s.verdict),
                                             isoUtc(s.started), isoUtc(s.finished)}
                                     .join(QLatin1Char(','));
        if (s.values.empty()) {
            rows << stepHead + QStringLiteral(",,,,,,") + csvField(s.detail);
            continue;
        }
        for (const Measurement &m : s.values)
            rows << QStringList{stepHead, csvField(m.name), QString::number(m.value, 'g', 9), csvField(m.unit),
                                csvField(m.limit), m.ok ? QStringLiteral("1") : QStringLiteral("0"), csvField(s.detail)}
                        .join(QLatin1Char(','));
    }
    return rows;
}

bool RunFolder::append(const ModuleResult &r, QString *error)
{
    const QString jsonl = QDir(m_dir).filePath(QLatin1String(kJsonlFile));
    const QString csv = QDir(m_dir).filePath(QLatin1String(kCsvFile));
    QByteArray csvData;
    if (!QFileInfo::exists(csv) || QFileInfo(csv).size() == 0)
        csvData += csvHeader().toUtf8() + '\n';
    for (const QString &row : csvRows(r))
        csvData += row.toUtf8() + '\n';
    return appendTo(jsonl, QJsonDocument(r.toJson()).toJson(QJsonDocument::Compact) + '\n', error)
        && appendTo(csv, csvData, error);
}

bool RunFolder::writeOpenHtf(const QString &moduleUuid, const QJsonObject &record, QString *error)
{
    const QDir dir(QDir(m_dir).filePath(QLatin1String(kOpenHtfDir)));
    QSaveFile f(dir.filePath(moduleUuid + QStringLiteral(".json")));
    const QByteArray data = QJsonDocument(record).toJson(QJsonDocument::Indented);
    if (!QDir().mkpath(dir.path()) || !f.open(QIODevice::WriteOnly) || f.write(data) != data.size() || !f.commit()) {
        if (error)
            *error = tr("Cannot write %1: %2. The result is in the results database and the summaries.")
                         .arg(QDir::toNativeSeparators(f.fileName()), f.errorString());
        return false;
    }
    return true;
}

} // namespace imudesk::station
