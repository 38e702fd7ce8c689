#pragma once
// Runs a test plan (test_plan.h) on one HiPNUC module over its own engine session
// (DeviceSession): connects, runs the steps in order, stops at the first failure (the rest
// are reported as skipped) and closes the port at the end, so it is free for the module's
// workspace or a re-run. Never blocks; lives in the caller's thread (the session's work is in
// its own worker thread).
//
// A module that disappears (the link fails or nothing arrives for kSilenceMs while a step
// waits for data) fails the running step with what happened; the firmware step closes the
// session on purpose while the updater owns the port and opens it again afterwards.
#include "core/station/station_result.h"
#include "core/station/test_plan.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <functional>
#include <memory>
#include <vector>

namespace imudesk::io {
class Transport;
}
namespace imudesk::device {
class DeviceSession;
struct SessionStats;
}
namespace imudesk::model {
struct Sample;
}
namespace imudesk::settings {
class ConfigurationController;
}
namespace imudesk::firmware {
class FirmwareUpdater;
}
namespace imudesk::calib {
class MagCalSession;
class GyroScaleRun;
}

namespace imudesk::station {

// Makes the byte transport of a module's session for its port name. Empty, or returning null:
// the serial port (io::SerialTransport), as in production. Tests hand out a
// sim::SimulatedTransport per port to run simulated modules in the same process, without a
// pseudo-terminal. Called on every (re)connection: after a firmware update, and on a re-run.
// The firmware step's updater still opens the port by its name, so a plan that has to update
// a module's firmware needs a real (or pseudo-terminal) port.
using TransportFactory = std::function<std::unique_ptr<io::Transport>(const QString &port)>;

class ModuleRunner : public QObject {
    Q_OBJECT

public:
    static constexpr int kConnectTimeoutMs = 20000;
    // Longer than a loaded PC's stalls (seen up to ~3 s with eight simulators in one process
    // under full load), far shorter than any unplugged module's silence.
    static constexpr int kSilenceMs = 5000;
    static constexpr int kPollMs = 100;
    static constexpr size_t kMaxSamples = 2000000; // one step's samples (Allan over an hour at 500 Hz)

    struct Options {
        int baud = 0;             // 0: auto-detect
        QString evidencePath;     // where the evidence step records (.imucap); empty: no recording
        TransportFactory transport; // the session's transport; empty: the serial port
    };

    ModuleRunner(TestPlan plan, QString port, Options options, QObject *parent = nullptr);
    ~ModuleRunner() override;

    void start();
    // Stops at once: the running step fails as cancelled, the port is closed.
    void cancel();
    bool running() const { return m_running; }
    const ModuleResult &result() const { return m_result; }
    // A step the plan turns off: its detail in the result, the reports and the tiles (translated).
    static QString disabledDetail();
    const QString &port() const { return m_port; }
    // Frames the session counted as lost over the whole run (device timestamp gaps).
    quint64 framesLost() const { return m_framesLost; }
    quint64 frames() const { return m_frames; }

Q_SIGNALS:
    // The result changed (step, progress, verdict); cheap to emit, views refresh on a clock.
    void changed();
    void finished();

private:
    void openSession();
    void onConnected();
    void runStep();
    void endStep(Verdict verdict, const QString &detail = QString());
    void finish();
    void fail(const QString &detail);
    void poll();
    void onLinkLost(const QString &detail);
    double stepWeight(const PlanStep &s) const;
    void updateProgress(double fraction);
    StepResult &step() { return m_result.steps[size_t(m_index)]; }
    const PlanStep &planStep() const { return m_plan.steps[size_t(m_index)]; }
    // A value held against the running step's limit parameter `limitKey` (measure) or its
    // magnitude against it (measureMagnitude), with the limit's marginal band when the plan
    // gives one, added to the running step; true when within the limit (marginal or not).
    bool measure(const QString &name, double value, const QString &unit, const char *limitKey);
    bool measureMagnitude(const QString &name, double value, const QString &unit, const char *limitKey);
    // The measurement both build (not yet added).
    Measurement limited(const QString &name, double value, const QString &unit, const char *limitKey,
                        bool magnitude) const;
    void info(const QString &name, double value, const QString &unit);

    // steps
    void runIdentify();
    void runFirmware();
    void runProfile();
    void startCollecting(double seconds);
    // Seconds of device time the collected samples cover.
    double collectedSeconds() const;
    void evaluateStatic();
    // The module stayed still during the step (calib/motion_check.h); otherwise the step ends
    // "cannot judge" and the module's record is ERROR.
    bool judgeableStill();
    void evaluateAllan();
    void evaluateAttitude();
    void evaluateVerify();
    void runMagCal();
    void runGyroScale();
    void runSave();
    void runEvidence();

    TestPlan m_plan;
    QString m_port;
    Options m_options;
    ModuleResult m_result;
    int m_index = -1;
    bool m_running = false;
    bool m_connected = false;
    bool m_closingOnPurpose = false;
    bool m_readingIdentity = false; // the read after (re)connecting, not an apply's read-back

    std::unique_ptr<device::DeviceSession> m_session;
    std::unique_ptr<settings::ConfigurationController> m_controller;
    std::unique_ptr<firmware::FirmwareUpdater> m_updater;
    std::unique_ptr<calib::MagCalSession> m_magCal;
    std::unique_ptr<calib::GyroScaleRun> m_gyroScale;

    QTimer m_pollTimer;
    QTimer m_deadline;         // the running step's (or connection's) time limit
    QElapsedTimer m_stepClock;
    QElapsedTimer m_lastData;  // since the last sample arrived
    double m_stepSeconds = 0;  // the running step's expected duration (progress)
    bool m_collecting = false;
    quint64 m_nextSeq = 0;
    std::string m_source;      // the frame type samples are taken from (the first with a gyro)
    std::vector<model::Sample> m_samples;
    quint64 m_framesLost = 0, m_frames = 0, m_framesLostAtStart = 0;
    int m_workingBaud = 0;
};

} // namespace imudesk::station
