#pragma once
// The production station's state (issue 54 point 4), which the station window only shows: the
// plan and where it came from, what the station remembers (report folder, plan, line database),
// the simulated tray, the run (a StationRunner: its modules and their verdicts), the modules
// whose workspace waits for the end of their test, the summary line and the report errors not
// yet told. The window (ui/station/station_view.h) gives it the ports the user checked and the
// report writer (PDF needs QtGui), and shows what it says.
#include "core/station/station_runner.h"
#include "core/station/station_settings.h"
#include "core/station/test_plan.h"

#include <QHash>
#include <QObject>
#include <QSet>
#include <QStringList>

#include <functional>
#include <memory>
#include <vector>

namespace imudesk::io {
class Transport;
}
namespace imudesk::sim {
class PtySimulator;
}

namespace imudesk::station {

class StationSession : public QObject {
    Q_OBJECT

public:
    static constexpr int kDemoTraySize = 8;
    static constexpr int kMaxTraySize = 16;
    static constexpr int kSimulatedBaud = 115200;
    // A module's port is closed by its session's thread just after its test ended: a workspace
    // asked for while it was under test opens this much later.
    static constexpr int kPortReleaseMs = 300;

    explicit StationSession(QObject *parent = nullptr);
    ~StationSession() override;

    // --- What the station remembers (QSettings), unless told not to (a --screenshot run or a
    // test leaves the user's settings alone).
    void loadSettings();
    void setRemembering(bool on) { m_remember = on; }
    const StationSettings &settings() const { return m_settings; }
    // Where run folders are made (one per start: "<plan>-<date>-<time>"); empty: the default.
    QString reportFolder() const;
    void setReportFolder(const QString &dir);
    void setLineDatabase(const QString &url, const QString &artifactFolder);

    // --- The plan: from a file (false with *error when it does not load), or given.
    bool openPlan(const QString &path, QString *error);
    void setPlan(const TestPlan &plan, const QString &path);
    const TestPlan &plan() const { return m_plan; }
    const QString &planPath() const { return m_planPath; }
    bool hasPlan() const { return m_havePlan; }
    // The example plan (TestPlan::example()) without what it needs from files beside it: the
    // firmware step keeps its minimum but has no image (an older module fails it), the profile
    // step is off. What --station-demo runs when no plan is given.
    static TestPlan demoPlan();

    // --- The simulated tray: `count` HI14 modules; with faults, three of them fail (a noisy
    // gyro, a wrong mounting, firmware 1.6.6); every one sits on a rotation fixture so that a
    // magnetometer calibration step can pass. On pseudo-terminals by default (the station then
    // takes the real serial path, and a module's workspace can open its port); in process (for
    // tests) each module sits behind a sim::SimulatedTransport made at every connection, its
    // clock timeScale times faster than real time, and its ports are only names ("sim:tray-N").
    bool startSimulatedTray(int count, bool withFaults, QString *error);
    void stopSimulatedTray();
    void setSimulatedTrayInProcess(bool inProcess, double timeScale = 1.0);
    bool simulatedTrayInProcess() const { return m_simInProcess; }
    const QStringList &simulatedPorts() const { return m_simPorts; } // in tray order
    // What the simulated module on that port is ("Simulated HI14 2 of 8, firmware 1.7.1: ...").
    QString simulatedNote(const QString &port) const { return m_simNotes.value(port); }

    // --- The run. The report writer is given to every run's runner.
    void setReportWriter(StationRunner::ReportWriter writer) { m_writer = std::move(writer); }
    // Runs the plan on the ports; false with *error (what to do) when it cannot.
    bool start(const QStringList &ports, QString *error);
    void cancel();
    // Runs the modules that failed again, into the same run folder (their next attempt).
    bool rerunFailed();
    bool running() const;
    bool anyFailed() const;
    bool hasRunFolder() const { return m_runner && !m_runner->runFolder().isEmpty(); }
    const StationRunner *runner() const { return m_runner.get(); }
    // The rate a module's workspace opens its port at (a simulated tray's is known; 0: detect).
    int baudFor(const QString &port) const;
    // A module's workspace: workspaceReady now, or when its test has ended (the summary line
    // says which wait).
    void openModule(int index);
    // "n passed · n failed · n running · n waiting", and which workspaces wait for their test;
    // "No run yet." before a run.
    QString summaryLine() const;
    // The runner's report errors not told yet (each is told once).
    QStringList takeNewReportErrors();

Q_SIGNALS:
    void planChanged();
    void trayChanged();
    // A new run's runner (the tiles follow it); the one before it is gone.
    void runStarted(const StationRunner *runner);
    void moduleFinished(int index);
    void runFinished();
    // The summary line or what can be done changed.
    void changed();
    // The module's port is free for its workspace.
    void workspaceReady(const QString &port, int baud);

private:
    void remember();
    void onModuleFinished(int index);

    TestPlan m_plan;
    QString m_planPath;
    bool m_havePlan = false;
    StationSettings m_settings;
    bool m_remember = true;

    StationRunner::ReportWriter m_writer;
    std::unique_ptr<StationRunner> m_runner;
    int m_runBaud = 0;
    int m_reportErrorsTold = 0;
    QSet<int> m_pendingOpen; // modules whose workspace was asked for while under test

    std::vector<std::unique_ptr<sim::PtySimulator>> m_sims;
    bool m_simInProcess = false;
    double m_simTimeScale = 1.0;
    // The in-process tray's transports by port name (null for any other port); empty without one.
    std::function<std::unique_ptr<io::Transport>(const QString &port)> m_simTransports;
    QStringList m_simPorts;
    QHash<QString, QString> m_simNotes;
};

} // namespace imudesk::station
