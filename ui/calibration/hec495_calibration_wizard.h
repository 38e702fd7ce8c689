#pragma once
// Magnetic calibration of a Witlink HEC495 compass (HEC495 manual, "校准方法" and commands
// 2.8-2.11): the five methods (automatic 12-point 0x63, manual 0x65, automatic
// all-orientation 0x08, 12-point small tilt 0x64, planar 0x60).
//   1. Method page: the methods with the manual's instructions, where each suits and its limits.
//   2. Run page: start; the method's target poses (calib::CompassPoseTracker) on a
//      heading/pitch/roll display (CompassPoseView) lit as the device collects points (0x66,
//      Hec495Session::calibrationPoint), the live attitude from the session's SampleStore on
//      a 30 Hz clock, the valid-point count, "Collect point" (0x67, manual method), Stop
//      (0x12), Save (0x09) and Clear (0x10). Failures (FF replies, timeouts) are shown on
//      the page with what to do. An automatic method, whose points the module took by itself,
//      asks before it saves: Save shows how many points were collected and that the compass's
//      calibration will be replaced; only "Save to the compass" sends 0x09, "Not yet" goes on.
//   3. Result page: FitErr and point count of the save reply (77 09 00 89 FitErr...), and the
//      verdict: above 10 the manual says calibrate again, offered with one button.
// A saved calibration is kept in the calibration history (runSaver()): the method, FitErr,
// points and the attitude samples streamed during the run.
// Leaving the wizard while a run is active (or starting) sends Stop. The session must
// outlive the wizard.
#include "calib/compass_pose_tracker.h"
#include "calib/sample_csv.h"
#include "calibration/calibration_run_saver.h"

#include <QTimer>
#include <QWizard>

#include <optional>

QT_BEGIN_NAMESPACE
class QButtonGroup;
class QLabel;
class QProgressBar;
class QPushButton;
class QWidget;
QT_END_NAMESPACE

namespace imudesk::device {
class Hec495Session;
struct Hec495Result;
}

namespace imudesk::ui {

class CompassPoseView;

class Hec495CalibrationWizard : public QWizard {
    Q_OBJECT
public:
    enum PageId { MethodPage, RunPage, ResultPage };
    enum class RunState { Idle, Starting, Running, Collecting, Stopping, Saving, Clearing };
    static constexpr int kRefreshMs = 33;
    // A target is at hand within this many degrees of heading. Wider than half the 30 deg
    // spacing: during a run the module shows its uncalibrated heading, off by its iron, and
    // the tracker prefers a target not yet collected where two overlap.
    static constexpr double kHeadingToleranceDeg = 25.0;

    explicit Hec495CalibrationWizard(device::Hec495Session &session, QWidget *parent = nullptr);
    ~Hec495CalibrationWizard() override;

    void setMethod(calib::CompassCalMethod method);
    calib::CompassCalMethod method() const;
    const calib::CompassPoseTracker &tracker() const { return m_tracker; }
    RunState runState() const { return m_state; }
    bool running() const { return m_running; }
    bool saved() const { return m_fitErr.has_value(); }
    std::optional<float> fitError() const { return m_fitErr; }
    int savedPoints() const { return m_savedPoints; }
    bool redoRecommended() const { return m_fitErr && !calib::CompassPoseTracker::fitErrAcceptable(*m_fitErr); }

    QPushButton *startButton() const { return m_start; }
    QPushButton *collectButton() const { return m_collect; }
    QPushButton *stopButton() const { return m_stop; }
    QPushButton *saveButton() const { return m_save; }
    // The confirmation an automatic method asks before it saves (hidden otherwise).
    QWidget *saveConfirmation() const { return m_confirm; }
    QPushButton *confirmSaveButton() const { return m_confirmSave; }
    QPushButton *cancelSaveButton() const { return m_cancelSave; }
    QPushButton *clearButton() const { return m_clearButton; }
    QPushButton *againButton() const { return m_again; }
    CompassPoseView *poseView() const { return m_view; }
    QString statusText() const;
    QString errorText() const;
    QString resultText() const;

    CalibrationRunSaver &runSaver() { return m_saver; }
    QJsonObject resultJson() const;

    bool validateCurrentPage() override;
    void done(int result) override;

Q_SIGNALS:
    // A request of this wizard finished (tests, logs).
    void requestFinished(const imudesk::device::Hec495Result &result);

private:
    void buildMethodPage();
    void buildRunPage();
    void buildResultPage();
    void onPageChanged(int id);
    void refresh();
    void send(RunState state, quint64 id);
    void onCommandFinished(quint64 id, const device::Hec495Result &result);
    void onPoint(int count);
    void handleFailure(RunState state, const device::Hec495Result &result);
    void calibrateAgain();
    void updateControls();
    void updateCount();
    void setError(const QString &text);

    device::Hec495Session &m_session;
    calib::CompassPoseTracker m_tracker;
    QTimer m_clock;
    RunState m_state = RunState::Idle;
    quint64 m_pending = 0;
    bool m_running = false;
    std::optional<float> m_fitErr;
    int m_savedPoints = 0;
    uint64_t m_seq = 0;
    calib::SampleTable m_rows;
    CalibrationRunSaver m_saver;

    QButtonGroup *m_methods = nullptr;
    QLabel *m_instructions = nullptr;
    QLabel *m_method = nullptr;
    CompassPoseView *m_view = nullptr;
    QLabel *m_count = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_legend = nullptr;
    QLabel *m_hint = nullptr;
    QLabel *m_status = nullptr;
    QLabel *m_error = nullptr;
    QPushButton *m_start = nullptr;
    QPushButton *m_collect = nullptr;
    QPushButton *m_stop = nullptr;
    QPushButton *m_save = nullptr;
    QWidget *m_confirm = nullptr;
    QLabel *m_confirmText = nullptr;
    QPushButton *m_confirmSave = nullptr;
    QPushButton *m_cancelSave = nullptr;
    QPushButton *m_clearButton = nullptr;
    QLabel *m_result = nullptr;
    QPushButton *m_again = nullptr;
};

} // namespace imudesk::ui
