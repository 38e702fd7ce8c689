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
// Folder ui/calibration/: the calibration wizards (magnetometer, gyro scale, attitude reset,
// HEC495), the calibration history dialog, the PDF report, CalibrationRunSaver (which keeps
// each finished run in the history) and the wizards' pictures (MagSphereView, TurnGauge). It
// mirrors core/calib: the flows and fits are calib's value classes and state machines
// (MagCalSession, MagCalibrator, GyroScaleRun, StillnessDetector, CompassPoseTracker,
// SphereCoverage) and runs are stored by calib::CalibrationHistory. The wizards take the
// device's DeviceSession or Hec495Session and read its SampleStore on a clock; the history
// dialog lists runs through models::CalibrationHistoryModel in a QTableView.
#include "calib/mag_cal_result.h"
#include "calib/mag_cal_session.h"
#include "calib/mag_environment_check.h"
#include "calibration/calibration_run_saver.h"
#include "model/device_identity.h"
#include "settings/configuration_controller.h"

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
    static constexpr double kMaxHeadingJumpDeg = 10.0;
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
    const calib::MagEnvironmentCheck &environment() const { return m_env; }
    const calib::MagCalResult &result() const { return m_result; }
    bool fitted() const { return m_fitted; }
    QString resultText() const;
    // Heading check: degrees turned so far, the largest jump between samples, passed.
    double headingTurnedDeg() const { return m_headingTurned; }
    double headingMaxJumpDeg() const { return m_headingMaxJump; }
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
    void pageChanged(int id);
    void saveRun();

    device::DeviceSession &m_session;
    model::FirmwareVersion m_firmware;
    calib::MagCalSession m_device;
    calib::MagEnvironmentCheck m_env;
    calib::MagCalResult m_result;
    bool m_fitted = false;
    bool m_runSaved = false;
    CalibrationRunSaver m_saver;
    QLabel *m_savedLabel = nullptr;
    std::vector<Eigen::Vector3d> m_samples;
    QTimer m_clock;
    uint64_t m_seq = 0;
    MagSphereView *m_sphere = nullptr;
    MagSphereView *m_after = nullptr;
    QLabel *m_envStatus = nullptr;
    QLabel *m_deviceStatus = nullptr;
    QProgressBar *m_deviceProgress = nullptr;
    QPushButton *m_startDevice = nullptr;
    QPushButton *m_fit = nullptr;
    QLabel *m_resultLabel = nullptr;
    QLabel *m_verdict = nullptr;
    QLabel *m_modeStatus = nullptr;
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
    double m_lastYaw = 0;
    bool m_haveYaw = false;
    double m_headingTurned = 0;
    double m_headingMaxJump = 0;
};

} // namespace imudesk::ui
