#pragma once
// Attitude reset / level wizard for CONFIG ATT RST 1/2/3/5 (manual v1.7.1 4.6.7.5, v1.6.6
// 2.2): pick the variant (its conditions are shown), then a live check that the module
// is still (calib::StillnessDetector: gyro and accelerometer spread over 1 s, held 2 s)
// and, for RST 3 (auto level), that pitch and roll are within 5 deg of level (or roll
// within 5 deg of 180, upside down); the command is sent only when the check passes; the
// last page shows the device's OK/ERR and the attitude after it.
// Constructed with the device's session; reads its SampleStore on a 20 Hz clock. A command
// the device answered is kept in the calibration history (runSaver()): the variant, the
// reply, the stillness figures when it was sent and the samples of the check page.
#include "calib/sample_csv.h"
#include "calib/stillness_detector.h"
#include "calibration/calibration_run_saver.h"

#include <QTimer>
#include <QWizard>

QT_BEGIN_NAMESPACE
class QButtonGroup;
class QLabel;
class QPushButton;
QT_END_NAMESPACE

namespace imudesk::device {
class DeviceSession;
}
namespace imudesk::protocol::hipnuc {
struct AsciiReply;
}

namespace imudesk::ui {

class AttitudeResetWizard : public QWizard {
    Q_OBJECT
public:
    enum PageId { ChoosePage, CheckPage, ResultPage };
    static constexpr double kStillForS = 2.0;
    static constexpr double kLevelLimitDeg = 5.0;

    explicit AttitudeResetWizard(device::DeviceSession &session, QWidget *parent = nullptr);

    void setVariant(int rst);               // 1, 2, 3 or 5
    int variant() const;
    bool conditionsMet() const { return m_conditionsMet; }
    QPushButton *sendButton() const { return m_send; }
    QString resultText() const;
    bool finishedOk() const { return m_ok; }
    bool validateCurrentPage() override;
    CalibrationRunSaver &runSaver() { return m_saver; }
    QJsonObject resultJson() const;

private:
    void refresh();
    void send();
    void onCommandFinished(quint64 id, const protocol::hipnuc::AsciiReply &reply);

    device::DeviceSession &m_session;
    calib::StillnessDetector m_still;
    QTimer m_clock;
    uint64_t m_seq = 0;
    QButtonGroup *m_variants = nullptr;
    QLabel *m_conditions = nullptr;
    QLabel *m_status = nullptr;
    QPushButton *m_send = nullptr;
    QLabel *m_result = nullptr;
    quint64 m_pending = 0;
    bool m_conditionsMet = false;
    bool m_done = false;
    bool m_ok = false;
    double m_roll = 0, m_pitch = 0, m_yaw = 0;
    QString m_reply;
    double m_sentStillForS = 0, m_sentGyroStd = 0, m_sentAccStd = 0;
    double m_sentRoll = 0, m_sentPitch = 0;
    calib::SampleTable m_rows;
    CalibrationRunSaver m_saver;
};

} // namespace imudesk::ui
