#pragma once
// The device side of the HiPNUC magnetometer calibration as a plain state machine (no
// timers, no I/O): it says which command to send next and interprets the replies.
//
//  Firmware >= 1.7.0 (manual v1.7.1 4.6.7.9 and 9.30.49-50): "CONFIG MCAL START", then
//    "LOG MCAL STAT" every pollIntervalMs: STAT=1 calibrating (PROGRESS 0..100),
//    STAT=2 verifying (hold still), STAT=3 done, STAT=4 failed, STAT=0 idle.
//  Older firmware (manual v1.6.6 8.1.1, 8.1.3): calibration runs in the background in
//    9-axis mode; "LOG MAGCONFIG" is polled and "MB=x, y, z" different from 0,0,0 means
//    it succeeded.
// Every step is bounded: timeoutMs overall, maxMissedPolls consecutive polls without reply.
#include "model/device_identity.h"
#include "protocol/hipnuc/ascii_command.h"
#include "protocol/hipnuc/ascii_reply.h"

#include <Eigen/Core>

#include <QCoreApplication>
#include <QString>

namespace imudesk::calib {

class MagCalProcedure {
    Q_DECLARE_TR_FUNCTIONS(MagCalProcedure)

public:
    enum class Flow { Mcal, Background };
    enum class State { Idle, Starting, Calibrating, Verifying, Succeeded, Failed };

    struct Options {
        int pollIntervalMs = 500;
        int timeoutMs = 180000;
        int maxMissedPolls = 3;
    };
    struct Step {
        protocol::hipnuc::Command command; // made by the typed builders; no text: nothing more to send
        int delayMs = 0;                   // send it after this long
        bool hasCommand() const { return !command.text.empty(); }
    };

    static Flow flowFor(const model::FirmwareVersion &fw);
    static const char *stateName(State s);

    MagCalProcedure();
    explicit MagCalProcedure(Options options);

    // The first command.
    Step start(Flow flow);
    // The reply to the last command, elapsedMs since start(). Returns the next step.
    Step handleReply(const protocol::hipnuc::AsciiReply &reply, qint64 elapsedMs);

    Flow flow() const { return m_flow; }
    State state() const { return m_state; }
    bool finished() const { return m_state == State::Succeeded || m_state == State::Failed; }
    int stat() const { return m_stat; }          // last STAT (-1: none yet)
    int progress() const { return m_progress; }  // last PROGRESS (Background: 0 or 100)
    Eigen::Vector3d bias() const { return m_bias; } // MB (Background flow)
    QString message() const { return m_message; }   // what is happening / why it failed
    // The troubleshooting steps of chapter 9.31 (translated), for a failure.
    static QString troubleshooting();

private:
    Step fail(const QString &why);
    Step poll();

    Options m_options;
    Flow m_flow = Flow::Mcal;
    State m_state = State::Idle;
    int m_stat = -1;
    int m_progress = 0;
    int m_missed = 0;
    Eigen::Vector3d m_bias = Eigen::Vector3d::Zero();
    QString m_message;
};

} // namespace imudesk::calib
