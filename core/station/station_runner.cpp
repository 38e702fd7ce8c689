#include "core/station/station_runner.h"

#include "core/station/result_conversion.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDir>
#include <QFileInfo>
#include <QSysInfo>
#include <QTimer>

#include <algorithm>

namespace imudesk::station {

StationRunner::StationRunner(TestPlan plan, QStringList ports, QObject *parent)
    : QObject(parent), m_plan(std::move(plan)), m_ports(std::move(ports))
{
    for (const QString &port : m_ports) {
        m_modules.push_back(ModuleResult::pending(port, m_plan));
        m_runners.emplace_back();
    }
}

StationRunner::~StationRunner() = default;

void StationRunner::setStation(const QString &stationId, const QString &operatorName)
{
    if (!stationId.isEmpty())
        m_run.stationId = stationId;
    if (!operatorName.isEmpty())
        m_run.operatorName = operatorName;
}

void StationRunner::setLineDatabase(const results::UploaderOptions &options)
{
    m_line = options;
}

bool StationRunner::setRunFolder(const QString &dir, QString *error, const QString &resultsFolder)
{
    m_haveFolder = m_folder.open(dir, m_plan, error);
    if (!m_haveFolder)
        return false;
    // The station's database in the folder the user named (by default beside the run folders);
    // a run goes on without it (said in the report errors), its folder keeps every result.
    const QDir place(resultsFolder.isEmpty() ? QFileInfo(m_folder.path()).absolutePath()
                                             : QFileInfo(resultsFolder).absoluteFilePath());
    QString why;
    if (!m_results.open(place.filePath(QLatin1String(results::ResultsStore::kFileName)), &why))
        m_reportErrors << why;
    m_run.uuid = results::newUuid();
    if (m_run.stationId.isEmpty())
        m_run.stationId = QSysInfo::machineHostName();
    if (m_run.operatorName.isEmpty())
        m_run.operatorName = qEnvironmentVariable("USER");
    m_run.planName = m_plan.name;
    m_run.planSha256 = QString::fromLatin1(QCryptographicHash::hash(m_plan.toJson(), QCryptographicHash::Sha256).toHex());
    m_run.imudeskVersion = QCoreApplication::applicationVersion();
    m_run.started = QDateTime::currentDateTimeUtc();
    return true;
}

const ModuleResult &StationRunner::module(int i) const
{
    return m_modules[size_t(i)];
}

void StationRunner::start()
{
    if (m_line && m_results.isOpen() && !m_uploader) {
        results::UploaderOptions o = *m_line;
        o.outbox = m_results.location();
        m_uploader = std::make_unique<results::ResultsUploader>(o);
        m_uploader->start();
    }
    for (int i = 0; i < int(m_modules.size()); ++i)
        if (!m_runners[size_t(i)])
            startModule(i);
}

void StationRunner::rerun(const QList<int> &modules)
{
    for (int i : modules)
        if (i >= 0 && i < int(m_modules.size()) && !(m_runners[size_t(i)] && m_runners[size_t(i)]->running()))
            startModule(i);
}

void StationRunner::startModule(int i)
{
    ModuleRunner::Options o;
    o.baud = m_baud;
    o.transport = m_transport;
    if (m_haveFolder)
        o.evidencePath = m_folder.evidencePath(m_ports.at(i));
    if (auto &old = m_runners[size_t(i)])
        old.release()->deleteLater(); // may be inside its own finished() signal
    auto runner = std::make_unique<ModuleRunner>(m_plan, m_ports.at(i), o);
    connect(runner.get(), &ModuleRunner::changed, this, [this, i, r = runner.get()] {
        const int attempt = m_modules[size_t(i)].attempt;
        m_modules[size_t(i)] = r->result();
        m_modules[size_t(i)].attempt = attempt;
        Q_EMIT moduleChanged(i);
    });
    connect(runner.get(), &ModuleRunner::finished, this, [this, i] { onModuleFinished(i); });
    m_runners[size_t(i)] = std::move(runner);
    ++m_active;
    m_runners[size_t(i)]->start();
}

void StationRunner::onModuleFinished(int i)
{
    --m_active;
    ModuleResult &r = m_modules[size_t(i)];
    r = m_runners[size_t(i)]->result();
    if (m_haveFolder) {
        r.attempt = m_folder.nextAttempt(r.serial);
        QString error;
        // The database first: a result is never only in memory.
        const results::ModuleRecord record = toResultRecord(r, m_run);
        const bool stored = m_results.isOpen() && m_results.commit(record, &error);
        if (m_results.isOpen() && !stored)
            m_reportErrors << error;
        if (m_writer) {
            const QString pdf = m_folder.reportPath(r);
            r.reportPath = pdf;
            if (!m_writer(r, m_plan, pdf, &error)) {
                r.reportPath.clear();
                m_reportErrors << error;
            } else if (stored) {
                m_results.addArtifact(record.uuid, {QStringLiteral("report"), QStringLiteral("application/pdf"),
                                                    results::fileSha256(pdf), pdf}, nullptr);
            }
        }
        if (stored) {
            // The record as stored (with its report), in OpenHTF's layout, into the run folder.
            results::ModuleRecord full = record;
            if (auto back = m_results.module(record.uuid))
                full = std::move(*back);
            if (!m_folder.writeOpenHtf(full.uuid, full.toOpenHtfJson(), &error))
                m_reportErrors << error;
        }
        if (m_uploader)
            m_uploader->kick();
        if (!m_folder.append(r, &error))
            m_reportErrors << error;
    }
    Q_EMIT moduleChanged(i);
    Q_EMIT moduleFinished(i);
    if (m_active == 0)
        Q_EMIT finished();
}

void StationRunner::cancel()
{
    for (auto &r : m_runners)
        if (r && r->running())
            r->cancel();
}

bool StationRunner::running() const
{
    return m_active > 0;
}

StationRunner::Summary StationRunner::summary() const
{
    Summary s;
    for (const ModuleResult &r : m_modules) {
        switch (r.verdict) {
        case Verdict::Pass: ++s.passed; break;
        case Verdict::Fail: ++s.failed; break;
        case Verdict::Running: ++s.running; break;
        default: ++s.waiting; break;
        }
    }
    return s;
}

bool StationRunner::allPassed() const
{
    return !m_modules.empty()
        && std::all_of(m_modules.begin(), m_modules.end(), [](const ModuleResult &r) { return r.verdict == Verdict::Pass; });
}

quint64 StationRunner::framesLost() const
{
    quint64 n = 0;
    for (const auto &r : m_runners)
        if (r)
            n += r->framesLost();
    return n;
}

quint64 StationRunner::frames() const
{
    quint64 n = 0;
    for (const auto &r : m_runners)
        if (r)
            n += r->frames();
    return n;
}

} // namespace imudesk::station
