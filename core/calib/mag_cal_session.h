#pragma once
// Runs the device-side magnetometer calibration (MagCalProcedure) over a HiPNUC
// DeviceSession: sends the commands, polls on a timer, reports progress. Lives in the
// caller's thread (the session's API is queued); never blocks.
#include "calib/mag_cal_procedure.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace imudesk::device {
class DeviceSession;
}

namespace imudesk::calib {

class MagCalSession : public QObject {
    Q_OBJECT
public:
    explicit MagCalSession(device::DeviceSession &session, MagCalProcedure::Options options = {},
                           QObject *parent = nullptr);

    // Starts the flow the firmware needs (MagCalProcedure::flowFor).
    void start(MagCalProcedure::Flow flow);
    // Stops polling (the device's own calibration cannot be aborted by a command).
    void cancel();
    bool running() const { return m_running; }
    const MagCalProcedure &procedure() const { return m_procedure; }

Q_SIGNALS:
    // After every reply: STAT (-1 before the first), PROGRESS 0..100, what is happening.
    void progressChanged(int stat, int progress, const QString &message);
    void finished(bool succeeded, const QString &message);

private:
    void follow(const MagCalProcedure::Step &step);
    void sendNext();
    void onCommandFinished(quint64 id, const protocol::hipnuc::AsciiReply &reply);

    device::DeviceSession &m_session;
    MagCalProcedure m_procedure;
    QTimer m_timer;
    QElapsedTimer m_clock;
    protocol::hipnuc::Command m_next;
    quint64 m_pending = 0;
    bool m_running = false;
};

} // namespace imudesk::calib
