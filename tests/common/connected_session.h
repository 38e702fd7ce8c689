#pragma once
// Tests: a simulated module on a pseudo-terminal with a DeviceSession connected to it, the
// set-up that session, wizard and workspace tests begin with.
#include "device/device_session.h"
#include "sim/pty_simulator.h"

#include <QTest>

namespace imudesk::testing {

// Starts `simulator` and opens `session` on its pty at `baud`. The calling test has failed
// (QTest::currentTestFailed()) unless the session is Connected within 15 s.
inline void connectSession(sim::PtySimulator &simulator, device::DeviceSession &session, int baud = 115200)
{
    QString error;
    QVERIFY2(simulator.start(&error), qPrintable(error));
    session.open(simulator.devicePath(), baud);
    QTRY_COMPARE_WITH_TIMEOUT(session.state(), device::SessionState::Connected, 15000);
}

} // namespace imudesk::testing
