#pragma once
// Calibrate > Verify module… (issue 55): is the module right? The operator turns it through
// still poses while the wizard shows the faces done and to do, "hold still" with a countdown
// and a live tally; then the module check (core/verify/module_check.h) on what was recorded:
// every figure with its 95 % bound, its limits and its verdict, the reasons in words. The run
// is kept in the calibration history (kind "verify", the samples with it), and its report can
// be written as a PDF.
// Reads the session's SampleStore on a 10 Hz clock (never per sample); the recording is
// bounded (verify::MotionInput::kMaxSamples). The bench's gravity (latitude and height, or a
// measured value) is remembered between runs.
#include "calib/sample_csv.h"
#include "calibration/calibration_run_saver.h"
#include "verify/module_check.h"
#include "verify/motion_input.h"

#include <QElapsedTimer>
#include <QTimer>
#include <QWizard>

#include <array>

QT_BEGIN_NAMESPACE
class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QPlainTextEdit;
QT_END_NAMESPACE

namespace imudesk::device {
class DeviceSession;
}

namespace imudesk::ui {

// The twelve poses as tiles: the body axis that points up, done (green) or to do.
class PoseTiles : public QWidget {
    Q_OBJECT
public:
    static constexpr int kTiles = 12;
    explicit PoseTiles(QWidget *parent = nullptr);
    // The tile whose up axis is nearest to `up` (body frame), -1 when none is within 25°.
    static int tileOf(const Eigen::Vector3d &up);
    static Eigen::Vector3d tileUp(int tile);
    static QString tileName(int tile); // "+Z up", "+X +Y up", ...
    void setDone(const std::array<bool, kTiles> &done, int current);
    const std::array<bool, kTiles> &done() const { return m_done; }
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent *) override;

private:
    std::array<bool, kTiles> m_done{};
    int m_current = -1;
};

class VerifyModuleWizard : public QWizard {
    Q_OBJECT
public:
    enum PageId { PosesPage, ResultPage };
    static constexpr int kClockMs = 100;
    static constexpr double kHoldS = 3.0; // the countdown: a pose counts after this long still

    explicit VerifyModuleWizard(device::DeviceSession &session, QWidget *parent = nullptr);

    // For tests: samples as if the session had delivered them, and the check on what is held.
    void addSamples(const std::vector<model::Sample> &samples);
    void analyse();
    const verify::CheckReport &report() const { return m_report; }
    const PoseTiles *tiles() const { return m_tiles; }
    QPushButton *startButton() const { return m_start; }
    QPushButton *stopButton() const { return m_stop; }
    QLabel *tallyLabel() const { return m_tally; }
    QLabel *holdLabel() const { return m_hold; }
    QTableWidget *figureTable() const { return m_table; }
    QLabel *verdictLabel() const { return m_verdict; }
    CalibrationRunSaver &runSaver() { return m_saver; }
    QJsonObject resultJson() const;
    verify::CheckOptions options() const;
    bool validateCurrentPage() override;
    void initializePage(int id) override;

private:
    void clearRecording();
    void start();
    void stop();
    void poll();
    void refreshTally();
    void showResult();
    void saveRun();
    void exportPdf();
    void rememberGravity();

    device::DeviceSession &m_session;
    QTimer m_clock;
    uint64_t m_seq = 0;
    bool m_recording = false;
    verify::MotionInput m_input;
    calib::SampleTable m_rows;
    verify::CheckReport m_report;
    CalibrationRunSaver m_saver;
    struct FoundPoses {
        bool valid = false;
        std::vector<verify::Pose> poses;
        qint64 costMs = 0;
        QElapsedTimer since;
    } m_found;

    QDoubleSpinBox *m_latitude = nullptr;
    QDoubleSpinBox *m_height = nullptr;
    QCheckBox *m_gravityKnown = nullptr;
    QDoubleSpinBox *m_gravity = nullptr;
    PoseTiles *m_tiles = nullptr;
    QLabel *m_hold = nullptr;
    QLabel *m_tally = nullptr;
    QProgressBar *m_progress = nullptr;
    QPushButton *m_start = nullptr;
    QPushButton *m_stop = nullptr;
    QLabel *m_verdict = nullptr;
    QTableWidget *m_table = nullptr;
    QPlainTextEdit *m_reasons = nullptr;
    QLabel *m_saved = nullptr;
    QPushButton *m_pdf = nullptr;
};

} // namespace imudesk::ui
