#pragma once
// The device side of the gyro Z scale calibration (manual v1.7.1 4.6.7.11, v1.6.6
// 2.2.4): "CONFIG USRCAL START <ANGLE>" (720..1800 deg), the user turns the module,
// then "CONFIG USRCAL STOP": OK = calibrated, ERR = failed (turned angle not within
// +-5 deg of ANGLE, rate outside 20..100 deg/s, or not started).
#include <QObject>
#include <QString>

namespace imudesk::device {
class DeviceSession;
}
namespace imudesk::protocol::hipnuc {
struct AsciiReply;
}

namespace imudesk::calib {

class GyroCalSession : public QObject {
    Q_OBJECT
public:
    enum class State { Idle, Starting, Running, Stopping, Succeeded, Failed };
    Q_ENUM(State)
    static constexpr int kMinAngle = 720, kMaxAngle = 1800;

    explicit GyroCalSession(device::DeviceSession &session, QObject *parent = nullptr);

    // False (and nothing sent) when angle is outside 720..1800.
    bool start(int angleDeg);
    // Sends STOP; only while Running.
    bool stop();
    State state() const { return m_state; }
    int angle() const { return m_angle; }
    QString message() const { return m_message; }

Q_SIGNALS:
    void stateChanged(imudesk::calib::GyroCalSession::State state, const QString &message);
    void finished(bool succeeded, const QString &message);

private:
    void setState(State s, const QString &message);
    void onCommandFinished(quint64 id, const protocol::hipnuc::AsciiReply &reply);

    device::DeviceSession &m_session;
    State m_state = State::Idle;
    int m_angle = 0;
    quint64 m_pending = 0;
    QString m_message;
};

} // namespace imudesk::calib
