#include "core/station/station_session.h"

#include "sim/hipnuc_serial_device.h"
#include "sim/pty_simulator.h"
#include "sim/simulated_transport.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QTimer>

#include <algorithm>

namespace imudesk::station {

StationSession::StationSession(QObject *parent) : QObject(parent) {}

StationSession::~StationSession()
{
    // The runner's sessions close before the simulated modules they talk to go away.
    m_runner.reset();
    stopSimulatedTray();
}

// ---------------------------------------------------------------- what is remembered

void StationSession::loadSettings()
{
    QSettings store;
    m_settings.load(store);
}

void StationSession::remember()
{
    if (!m_remember)
        return;
    QSettings store;
    m_settings.save(store);
}

QString StationSession::reportFolder() const
{
    return m_settings.reportFolder.isEmpty() ? StationSettings::defaultReportFolder() : m_settings.reportFolder;
}

void StationSession::setReportFolder(const QString &dir)
{
    if (dir == m_settings.reportFolder)
        return;
    m_settings.reportFolder = dir;
    remember();
}

void StationSession::setLineDatabase(const QString &url, const QString &artifactFolder)
{
    m_settings.lineDatabase = url;
    m_settings.artifactFolder = artifactFolder;
    remember(); // the next start uploads there
}

// ---------------------------------------------------------------- the plan

TestPlan StationSession::demoPlan()
{
    TestPlan plan = TestPlan::example();
    for (PlanStep &s : plan.steps) {
        if (s.kind == StepKind::Firmware)
            s.params[QStringLiteral("image")] = QString();
        if (s.kind == StepKind::Profile)
            s.enabled = false;
    }
    return plan;
}

bool StationSession::openPlan(const QString &path, QString *error)
{
    QString why;
    const auto plan = TestPlan::load(path, &why);
    if (!plan) {
        if (error)
            *error = tr("The plan %1 could not be opened: %2").arg(QDir::toNativeSeparators(path), why);
        return false;
    }
    setPlan(*plan, QFileInfo(path).absoluteFilePath());
    return true;
}

void StationSession::setPlan(const TestPlan &plan, const QString &path)
{
    m_plan = plan;
    m_planPath = path;
    m_havePlan = true;
    if (!path.isEmpty() && path != m_settings.planPath) {
        m_settings.planPath = path;
        remember();
    }
    Q_EMIT planChanged();
    Q_EMIT changed();
}

// ---------------------------------------------------------------- the simulated tray

bool StationSession::startSimulatedTray(int count, bool withFaults, QString *error)
{
    if (running()) {
        if (error)
            *error = tr("Wait for the run to end, or cancel it, before changing the simulated tray.");
        return false;
    }
    count = std::clamp(count, 1, int(kMaxTraySize));
    stopSimulatedTray();
    // The three faulty modules: spread over a tray of six or more, else the first ones.
    const auto faultAt = [count](int i) {
        const int step = count >= 6 ? 2 : 1, first = count >= 6 ? 1 : 0;
        if (i < first || (i - first) % step != 0)
            return -1;
        const int fault = (i - first) / step;
        return fault < 3 ? fault : -1;
    };
    QHash<QString, sim::SimOptions> inProcess; // port -> module, for an in-process tray
    for (int i = 0; i < count; ++i) {
        sim::SimOptions o;
        o.model = "HI14";
        o.firmware = "1.7.1";
        o.baud = kSimulatedBaud;
        o.seed = uint64_t(i + 1);
        o.faults.magCalFixture = true; // the tray turns every module while its MCAL collects
        QString note = tr("a good module");
        switch (withFaults ? faultAt(i) : -1) {
        case 0:
            o.faults.gyroNoiseFactor = sim::SimFaults::kNoisyGyroFactor;
            note = tr("a noisy gyro (%1 times the noise)").arg(sim::SimFaults::kNoisyGyroFactor);
            break;
        case 1:
            o.faults.mountingErrorDeg = {sim::SimFaults::kWrongMountingRollDeg, 0, 0};
            note = tr("mounted wrongly (on its side, roll %1°)").arg(sim::SimFaults::kWrongMountingRollDeg);
            break;
        case 2:
            o.firmware = "1.6.6";
            note = tr("old firmware");
            break;
        default: break;
        }
        QString port;
        if (m_simInProcess) {
            port = QStringLiteral("sim:tray-%1").arg(i + 1);
            inProcess.insert(port, o);
        } else {
            auto sim = std::make_unique<sim::PtySimulator>(o);
            QString why;
            if (!sim->start(&why)) {
                stopSimulatedTray();
                if (error)
                    *error = tr("The simulated modules could not start: %1").arg(why);
                return false;
            }
            port = sim->devicePath();
            m_sims.push_back(std::move(sim));
        }
        m_simPorts << port;
        m_simNotes.insert(port, tr("Simulated HI14 %1 of %2, firmware %3: %4")
                                    .arg(i + 1)
                                    .arg(count)
                                    .arg(QString::fromStdString(o.firmware), note));
    }
    if (m_simInProcess) {
        // A module just powered on at each connection (a re-run's module starts afresh, where
        // a pseudo-terminal's keeps running); null for any other port: a serial port.
        m_simTransports = [modules = std::move(inProcess),
                           scale = m_simTimeScale](const QString &port) -> std::unique_ptr<io::Transport> {
            const auto it = modules.constFind(port);
            if (it == modules.constEnd())
                return nullptr;
            auto link = std::make_unique<sim::SimulatedTransport>(std::make_unique<sim::HipnucSerialDevice>(*it));
            link->setTimeScale(scale);
            return link;
        };
    }
    Q_EMIT trayChanged();
    Q_EMIT changed();
    return true;
}

void StationSession::setSimulatedTrayInProcess(bool inProcess, double timeScale)
{
    m_simInProcess = inProcess;
    m_simTimeScale = timeScale > 0 ? timeScale : 1.0;
}

void StationSession::stopSimulatedTray()
{
    for (auto &sim : m_sims)
        sim->stop();
    m_sims.clear();
    m_simTransports = nullptr;
    if (m_simPorts.isEmpty())
        return;
    m_simPorts.clear();
    m_simNotes.clear();
    Q_EMIT trayChanged();
    Q_EMIT changed();
}

// ---------------------------------------------------------------- the run

bool StationSession::running() const
{
    return m_runner && m_runner->running();
}

bool StationSession::anyFailed() const
{
    if (m_runner)
        for (int i = 0; i < m_runner->moduleCount(); ++i)
            if (m_runner->module(i).verdict == Verdict::Fail)
                return true;
    return false;
}

int StationSession::baudFor(const QString &port) const
{
    return m_simPorts.contains(port) ? kSimulatedBaud : m_runBaud;
}

bool StationSession::start(const QStringList &ports, QString *error)
{
    const auto refuse = [error](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    if (running())
        return refuse(QString()); // the Start button is off meanwhile
    if (!m_havePlan)
        return refuse(tr("Open a test plan first (Open…), or start from the example."));
    if (const QStringList problems = m_plan.problems(); !problems.isEmpty())
        return refuse(tr("The plan \"%1\" cannot run:\n• %2\nEdit it (Edit…) and start again.")
                          .arg(m_plan.name, problems.join(QStringLiteral("\n• "))));
    if (ports.isEmpty())
        return refuse(tr("Check the ports of the modules to test first."));
    auto runner = std::make_unique<StationRunner>(m_plan, ports);
    // A tray of simulated modules is known to talk at 115200 baud; real ones are detected.
    const bool allSimulated =
        std::all_of(ports.begin(), ports.end(), [this](const QString &p) { return m_simPorts.contains(p); });
    m_runBaud = allSimulated ? kSimulatedBaud : 0;
    runner->setBaud(m_runBaud);
    // An in-process tray's modules (setSimulatedTrayInProcess), while the tray is there; the
    // serial port for every other port.
    runner->setTransportFactory([this](const QString &port) -> std::unique_ptr<io::Transport> {
        return m_simTransports ? m_simTransports(port) : nullptr;
    });
    QString why;
    const QString folder = RunFolder::newRunPath(reportFolder(), m_plan);
    if (!runner->setRunFolder(folder, &why))
        return refuse(tr("The report folder cannot be used: %1").arg(why));
    runner->setReportWriter(m_writer);
    if (!m_settings.lineDatabase.isEmpty()) {
        results::UploaderOptions line;
        line.server = m_settings.lineDatabase;
        line.artifactFolder = m_settings.artifactFolder;
        runner->setLineDatabase(line);
    }
    connect(runner.get(), &StationRunner::moduleFinished, this, &StationSession::onModuleFinished);
    connect(runner.get(), &StationRunner::finished, this, [this] {
        Q_EMIT runFinished();
        Q_EMIT changed();
    });
    m_pendingOpen.clear();
    m_reportErrorsTold = 0;
    Q_EMIT runStarted(runner.get()); // the tiles follow it before the runner before it goes
    m_runner = std::move(runner);
    m_runner->start();
    Q_EMIT changed();
    return true;
}

void StationSession::cancel()
{
    if (running())
        m_runner->cancel();
}

bool StationSession::rerunFailed()
{
    if (!m_runner)
        return false;
    QList<int> failed;
    for (int i = 0; i < m_runner->moduleCount(); ++i)
        if (m_runner->module(i).verdict == Verdict::Fail)
            failed << i;
    if (failed.isEmpty())
        return false;
    m_runner->rerun(failed);
    Q_EMIT changed();
    return true;
}

void StationSession::onModuleFinished(int index)
{
    Q_EMIT moduleFinished(index);
    if (m_pendingOpen.remove(index) && m_runner) {
        // The module's session closes its port in its own thread: its workspace a moment later.
        const QString port = m_runner->module(index).port;
        const int baud = baudFor(port);
        QTimer::singleShot(kPortReleaseMs, this, [this, port, baud] { Q_EMIT workspaceReady(port, baud); });
    }
    Q_EMIT changed();
}

void StationSession::openModule(int index)
{
    if (!m_runner || index < 0 || index >= m_runner->moduleCount())
        return;
    const ModuleResult &r = m_runner->module(index);
    if (r.verdict == Verdict::Running) {
        // Its port is the station's until the test ends: the workspace opens then.
        m_pendingOpen.insert(index);
        Q_EMIT changed();
        return;
    }
    Q_EMIT workspaceReady(r.port, baudFor(r.port));
}

QString StationSession::summaryLine() const
{
    if (!m_runner)
        return tr("No run yet.");
    const StationRunner::Summary s = m_runner->summary();
    QString text = tr("%1 passed · %2 failed · %3 running · %4 waiting")
                       .arg(s.passed)
                       .arg(s.failed)
                       .arg(s.running)
                       .arg(s.waiting);
    if (!m_pendingOpen.isEmpty()) {
        QList<int> waiting = m_pendingOpen.values();
        std::sort(waiting.begin(), waiting.end());
        QStringList ports;
        for (int i : waiting)
            ports << m_runner->module(i).port;
        text += ports.size() == 1
            ? tr(" — the workspace of %1 opens when its test has ended").arg(ports.first())
            : tr(" — the workspaces of %1 open when their tests have ended").arg(ports.join(QStringLiteral(", ")));
    }
    return text;
}

QStringList StationSession::takeNewReportErrors()
{
    if (!m_runner)
        return {};
    const QStringList &errors = m_runner->reportErrors();
    if (errors.size() <= m_reportErrorsTold)
        return {};
    const QStringList fresh = errors.mid(m_reportErrorsTold);
    m_reportErrorsTold = int(errors.size());
    return fresh;
}

} // namespace imudesk::station
