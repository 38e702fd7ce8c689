#pragma once
// Waiting for a device that went away (a USB adapter pulled out, a module power-cycled):
// every kPollMs the transport is reopened at the rate the device was last heard at, until
// it opens, the user turns automatic reconnection off, or the session closes. The engine
// (session_engine.h) starts it when its link fails and carries on when it reopens; the
// plug-in says whether its family reconnects at all.
#include "io/transport.h"

#include <QObject>
#include <QTimer>

#include <cstdint>
#include <functional>

namespace imudesk::device {

class Reconnector : public QObject {
    Q_OBJECT
public:
    static constexpr int kPollMs = 500;

    Reconnector(io::Transport &transport, QObject *parent);

    bool enabled() const { return m_enabled; }
    void setEnabled(bool on);
    // Tries until the transport reopens at `baud`, then calls reopened (not when disabled).
    void start(int baud, std::function<void()> reopened);
    void stop();
    bool waiting() const { return m_timer.isActive(); }
    // Links reopened since resetCount (the statistics' "reconnects").
    uint64_t count() const { return m_count; }
    void resetCount() { m_count = 0; }

private:
    void attempt();

    io::Transport &m_transport;
    QTimer m_timer{this};
    bool m_enabled = true;
    int m_baud = 0;
    std::function<void()> m_reopened;
    QString m_lastError; // logged once, not every attempt
    uint64_t m_count = 0;
};

} // namespace imudesk::device
