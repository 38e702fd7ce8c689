#pragma once
// What session tests wait for: the session connected (waitConnected), and the statistics the
// session publishes (StatsProbe: the last ones and how many came).
#include "device/device_session.h"

#include <QObject>
#include <QTest>

namespace imudesk::test {

// Waits (turning the event loop) until s is Connected, at most timeoutMs; false at once when
// the session fails.
inline bool waitConnected(device::DeviceSession &s, int timeoutMs = 15000)
{
    (void)imudesk::test::waitFor(
        [&s] {
            return s.state() == device::SessionState::Connected || s.state() == device::SessionState::Failed;
        },
        timeoutMs);
    return s.state() == device::SessionState::Connected;
}

// Keeps the statistics a session publishes (once per statistics period); disconnects when it
// goes, so it may be declared after the session it watches.
class StatsProbe {
public:
    explicit StatsProbe(device::DeviceSession &s)
        : m_connection(QObject::connect(&s, &device::DeviceSession::statsUpdated, &s,
                                        [this](const device::SessionStats &st) {
                                            last = st;
                                            ++updates;
                                        }))
    {
    }
    ~StatsProbe() { QObject::disconnect(m_connection); }
    StatsProbe(const StatsProbe &) = delete;
    StatsProbe &operator=(const StatsProbe &) = delete;

    // The next stats published from now on, waited for at most timeoutMs (the default is for a
    // loaded machine, where the session's thread may wait seconds for a core); when none came,
    // says so and returns the last ones seen.
    device::SessionStats next(int timeoutMs = 15000)
    {
        const int before = updates;
        if (!imudesk::test::waitFor([this, before] { return updates != before; }, timeoutMs))
            qWarning("StatsProbe: no statistics for %d ms; the figures are the last ones seen", timeoutMs);
        return last;
    }

    device::SessionStats last;
    int updates = 0;

private:
    QMetaObject::Connection m_connection;
};

} // namespace imudesk::test
