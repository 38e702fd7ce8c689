#pragma once
// Gyro Z scale-factor calibration wizard (manual v1.7.1 4.6.7.11, v1.6.6 2.2.4):
//   1. preparation checklist (level, steady, a mark to stop on, 720..1800 deg), and what
//      the module streams: the gyroscope's rate, with an offer to turn HI91 on only when
//      it is missing or too slow for ImuDesk to follow the turn;
//   2. the run: Start sends CONFIG USRCAL START <ANGLE> and starts our own estimate
//      (calib::GyroScaleRun on the streamed samples, device timestamps); the page shows
//      the angle turned, turns, the rate against the 20..100 deg/s band, the evenness,
//      and "stop now" at the target +-5 deg; Stop sends CONFIG USRCAL STOP;
//   3. the result: the device's OK/ERR and our estimate of the scale error.
// Constructed with the device's session; reads samples from its SampleStore on a 20 Hz
// clock (never per sample) and talks to the device only through the session's queued API.
// A run the device answered (OK or ERR) is kept in the calibration history (runSaver()):
// target angle, the device's reply, our estimate and the streamed samples.
#include "calib/gyro_cal_session.h"
#include "calib/gyro_scale_run.h"
#include "calib/sample_csv.h"
#include "calibration/calibration_run_saver.h"

#include <QElapsedTimer>
#include <QTimer>
#include <QWizard>

QT_BEGIN_NAMESPACE
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
QT_END_NAMESPACE

namespace imudesk::device {
class DeviceSession;
}

namespace imudesk::ui {

class TurnGauge;

class GyroScaleWizard : public QWizard {
    Q_OBJECT
public:
    enum PageId { PreparePage, RunPage, ResultPage };

    explicit GyroScaleWizard(device::DeviceSession &session, QWidget *parent = nullptr);

    // For tests and the integrator.
    QPushButton *startButton() const { return m_start; }
    QPushButton *stopButton() const { return m_stop; }
    // The preparation page's check of the stream: gyroscope samples per second (-1 before the
    // first check), and the button that turns HI91 on, shown only when they are too few.
    static constexpr double kMinGyroRateHz = 50.0; // ImuDesk's angle and stop cue, not the module's
    static constexpr int kStreamCheckMs = 1000;
    double gyroRateHz() const { return m_gyroRateHz; }
    QPushButton *enableOutputButton() const { return m_enableOutput; }
    const TurnGauge *gauge() const { return m_gauge; }
    QLabel *streamStatusLabel() const { return m_streamStatus; }
    void checkStream();
    QSpinBox *angleBox() const { return m_angle; }
    const calib::GyroScaleRun &run() const { return m_run; }
    const calib::GyroCalSession &deviceCalibration() const { return m_device; }
    QString resultText() const;
    bool validateCurrentPage() override;
    CalibrationRunSaver &runSaver() { return m_saver; }
    QJsonObject resultJson() const;

private:
    void startRun();
    void stopRun();
    void refresh();
    void onDeviceState(calib::GyroCalSession::State state, const QString &message);
    void saveRun();
    void enableGyroOutput();

    device::DeviceSession &m_session;
    calib::GyroCalSession m_device;
    calib::GyroScaleRun m_run;
    QTimer m_clock;
    QTimer m_streamClock;
    QElapsedTimer m_streamSince;
    uint64_t m_streamSeq = 0;
    double m_gyroRateHz = -1.0;
    quint64 m_outputCommand = 0;
    QLabel *m_streamStatus = nullptr;
    QPushButton *m_enableOutput = nullptr;
    uint64_t m_seq = 0;
    bool m_done = false;
    int m_target = 0;
    calib::SampleTable m_rows;
    CalibrationRunSaver m_saver;
    QSpinBox *m_angle = nullptr;
    QPushButton *m_start = nullptr;
    QPushButton *m_stop = nullptr;
    QLabel *m_guidance = nullptr;
    QLabel *m_readout = nullptr;
    QLabel *m_deviceStatus = nullptr;
    QProgressBar *m_progress = nullptr;
    QProgressBar *m_rate = nullptr;
    QLabel *m_result = nullptr;
    TurnGauge *m_gauge = nullptr;
};

} // namespace imudesk::ui
