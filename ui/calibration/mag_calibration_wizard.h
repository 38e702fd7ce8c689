#pragma once
// Magnetometer calibration wizard (manual v1.7.1 4.6.7.9 and chapter 9, v1.6.6 8.1):
//   intro (when 9-axis mode helps, outdoor/indoor advice) -> mode check (switch to AHRS:
//   CONFIG ATT MODE 1, SAVECONFIG, REBOOT) -> environment (|B| 20..60 uT, spread over
//   orientations <= 10 uT) -> rotation (live MagSphereView with covered cells and the
//   missing rotation; the device-side run, calib::MagCalSession, beside it; "Fit" runs our
//   calib::MagCalibrator on the same samples) -> result (verdict, metrics, before/after
//   sphere, the predicted heading error with the hard- and soft-iron uncertainty, the
//   troubleshooting of 9.31 when it is not usable) -> heading check (turn
//   360 deg flat: the heading must change continuously, no jump > 10 deg).
// Constructed with the device's session and its firmware (which picks the device flow);
// reads the SampleStore on a 20 Hz clock. Each fit shown on the result page is kept in the
// calibration history (runSaver(): root and the device's identity); the page says where.
//
// Two calibrations, kept apart: ImuDesk's fit of the raw samples (result(), its verdict the
// headline) and the device's own run (deviceCalibration(), its verdict beside it on the
// result page and in the saved run as "device_calibration"). Once the device reports success
// it corrects its own output, so later samples are not raw: ImuDesk's collection ends there,
// without the samples that arrived after the device's last "still calibrating" reply.
// A fit is one run with one set of figures: computed once (MagCalResult) and read out from
// it on the rotation page (until more samples come in), the result page, the saved run and
// the report. A usable fit ends the collection; after a refused one the user may turn on,
// and the result page fits again when more samples came in.
//
// Folder ui/calibration/: the calibration wizards (magnetometer, gyro scale, attitude reset,
// HEC495), the calibration history dialog, the PDF report, CalibrationRunSaver (which keeps
// each finished run in the history) and the wizards' pictures (MagSphereView, TurnGauge). It
// mirrors core/calib: the flows and fits are calib's value classes and state machines
// (MagCalSession, MagCalibrator, GyroScaleRun, StillnessDetector, CompassPoseTracker,
// SphereCoverage) and runs are stored by calib::CalibrationHistory. The wizards take the
// device's DeviceSession or Hec495Session and read its SampleStore on a clock; the history
// dialog lists runs through models::CalibrationHistoryModel in a QTableView.
#include "calib/heading_turn_check.h"
#include "calib/mag_cal_result.h"
#include "calib/mag_cal_session.h"
#include "calib/mag_environment_judge.h"
#include "calibration/calibration_run_saver.h"
#include "model/device_identity.h"
#include "settings/configuration_controller.h"

#include <QJsonObject>
#include <QTimer>
#include <QWizard>

#include <vector>

QT_BEGIN_NAMESPACE
class QLabel;
class QProgressBar;
class QPushButton;
QT_END_NAMESPACE

namespace imudesk::device {
class DeviceSession;
}

namespace imudesk::ui {

class MagSphereView;

class MagCalibrationWizard : public QWizard {
    Q_OBJECT
public:
    enum PageId { IntroPage, ModePage, EnvironmentPage, RotationPage, ResultPage, HeadingPage };
    static constexpr size_t kMaxSamples = 20000;
    static constexpr double kMaxHeadingJumpDeg = calib::HeadingTurnCheck::kMaxJumpDeg;
    static constexpr int kLiveReplicates = 12; // resampled fits behind the live verdict (final fit: more)
    static constexpr int kRebootSettleMs = 2500; // after REBOOT, before reading the mode back

    MagCalibrationWizard(device::DeviceSession &session, const model::FirmwareVersion &firmware,
                         QWidget *parent = nullptr);

    MagSphereView *sphere() const { return m_sphere; }
    QPushButton *fitButton() const { return m_fit; }
    QPushButton *startDeviceButton() const { return m_startDevice; }
    QPushButton *switchModeButton() const { return m_switchMode; }
    // The working mode as read on the mode page ("0", "1", "4"; empty before the read).
    QString attMode() const { return m_attMode; }
    // The live figures of the rotation page, refreshed with the sphere.
    QString liveFiguresText() const;
    // The verdict as a headline: its text, and pass/warn/fail colour by object name.
    QLabel *verdictHeadline() const { return m_verdict; }
    const calib::MagCalSession &deviceCalibration() const { return m_device; }
    // The environment page's judge of the spot (the module's iron fitted out first).
    const calib::MagEnvironmentJudge &environment() const { return m_env; }
    // The environment page's live figures and its verdict line.
    QString environmentFiguresText() const;
    QLabel *environmentVerdict() const { return m_envStatus; }
    const calib::MagCalResult &result() const { return m_result; }
    bool fitted() const { return m_fitted; }
    // The samples ImuDesk's fit takes: raw ones only, collected on the rotation page.
    size_t sampleCount() const { return m_samples.size(); }
    // Whether the rotation page still takes samples for ImuDesk's fit.
    bool collecting() const { return m_collecting; }
    QString resultText() const;
    // The device's own calibration as a verdict: Pass when it reported success, Fail when it
    // failed, Warn while it runs; false when it was not started.
    bool deviceVerdict(calib::MagVerdict &verdict) const;
    // Its line on the result page (what the device concluded), empty when it was not started.
    QString deviceResultText() const;
    // The device's run for the saved result ("device_calibration"); empty when not started.
    QJsonObject deviceResultJson() const;
    // Heading check: degrees turned so far, the largest jump between samples, passed.
    double headingTurnedDeg() const { return m_headingCheck.turnedDeg(); }
    double headingMaxJumpDeg() const { return m_headingCheck.maxJumpDeg(); }
    bool headingCheckPassed() const;
    // Where finished runs are kept: set its root and the device's identity before the run.
    CalibrationRunSaver &runSaver() { return m_saver; }

private:
    void refresh();
    void runFit();
    void switchToAhrs();
    void readMode();
    void showMode(bool ok, const QString &error);
    void liveFit();
    void showEnvironment();
    QString stepsText() const;
    QString modeTableText() const;
    void pageChanged(int id);
    void saveRun();
    void showDeviceVerdict();
    void deviceProgressed(int stat, int progress, const QString &message);
    void deviceFinished(bool ok, const QString &message);
    // The rotation page reads out the fitted run (true) or the samples coming in (false).
    void showRunOnRotationPage(bool run);

    device::DeviceSession &m_session;
    model::FirmwareVersion m_firmware;
    calib::MagCalSession m_device;
    calib::MagEnvironmentJudge m_env;
    calib::MagCalResult m_result;
    bool m_fitted = false;
    bool m_collecting = true;
    bool m_showingRun = false;
    bool m_deviceStarted = false;
    // m_samples.size() when the device last said it was still calibrating: the samples up to
    // there are raw for certain.
    size_t m_rawBeforeDevice = 0;
    QLabel *m_deviceVerdict = nullptr;
    bool m_runSaved = false;
    CalibrationRunSaver m_saver;
    QLabel *m_savedLabel = nullptr;
    std::vector<Eigen::Vector3d> m_samples;
    QTimer m_clock;
    uint64_t m_seq = 0;
    MagSphereView *m_sphere = nullptr;
    MagSphereView *m_after = nullptr;
    QLabel *m_envStatus = nullptr;
    QLabel *m_envFigures = nullptr;
    MagSphereView *m_envSphere = nullptr;
    QLabel *m_deviceStatus = nullptr;
    QProgressBar *m_deviceProgress = nullptr;
    QPushButton *m_startDevice = nullptr;
    QPushButton *m_fit = nullptr;
    QLabel *m_resultLabel = nullptr;
    QLabel *m_verdict = nullptr;
    QLabel *m_modeStatus = nullptr;
    QLabel *m_modeTable = nullptr;
    QPushButton *m_switchMode = nullptr;
    settings::ConfigurationController m_config;
    QString m_attMode;
    bool m_switching = false;
    QLabel *m_figures = nullptr;
    QLabel *m_liveVerdict = nullptr;
    calib::MagCalResult m_live;
    bool m_haveLive = false;
    QTimer m_fitClock;
    double m_minField = 0, m_maxField = 0;
    QLabel *m_headingStatus = nullptr;
    calib::HeadingTurnCheck m_headingCheck; // the heading page's turn (core: the CLI runs the same)
};

} // namespace imudesk::ui
