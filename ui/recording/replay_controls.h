#pragma once
// Transport controls for a ReplaySession: play/pause, speed (0.1x to 10x or as fast as
// possible), a timeline slider to seek, loop, and the position and duration.
#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QSlider;

namespace imudesk::capture {
class CaptureHeader;
}

namespace imudesk::record {
class ReplaySession;
}

namespace imudesk::ui {

class ReplayControls : public QWidget {
    Q_OBJECT
public:
    explicit ReplayControls(QWidget *parent = nullptr);

    // The replay to control (not owned); nullptr disables the controls.
    void setSession(record::ReplaySession *session);
    double duration() const { return m_duration; }
    double position() const { return m_position; }
    // Speed factors offered; 0 is "as fast as possible".
    static const QList<double> &speeds();

private:
    void onOpened(double durationS, const capture::CaptureHeader &header);
    void onPosition(double seconds);
    void onPlaying(bool playing);
    void seekToSlider();
    void updateLabel();

    record::ReplaySession *m_session = nullptr;
    QPushButton *m_play = nullptr;
    QComboBox *m_speed = nullptr;
    QSlider *m_timeline = nullptr;
    QCheckBox *m_loop = nullptr;
    QLabel *m_time = nullptr;
    QLabel *m_linked = nullptr; // a session's replay: the devices move together
    double m_duration = 0;
    double m_position = 0;
    bool m_playing = false;
    bool m_deviceClock = false; // a raw byte dump: the times are the device's (CaptureHeader::kHostTime)
};

} // namespace imudesk::ui
