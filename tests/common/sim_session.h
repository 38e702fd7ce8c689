#pragma once
// Tests: a DeviceSession whose link is a simulated HiPNUC module in this process
// (sim::SimulatedTransport over sim::HipnucSerialDevice): no pseudo-terminal and no simulator
// thread, so session tests run quickly and steadily on a loaded machine. The real serial path
// (QSerialPort on a pty, hang-ups, busy and forbidden ports) is proved by the few tests that
// still use sim::PtySimulator.
//
// The transport, and with it the simulated module, lives in the session's engine thread:
// withDevice() runs a function there and waits for it, as PtySimulator::withDevice does. The
// HiPNUC-serial form of inproc_link.h's InProcSession, with the module's state at hand.
#include "inproc_link.h"

#include "device/device_session.h"
#include "jobs/thread_sync.h"
#include "sim/hipnuc_serial_device.h"
#include "sim/simulated_transport.h"

#include <QTest>

#include <functional>
#include <memory>

namespace imudesk::test {

class SimSession {
public:
    // The address the session opens (any name: the link is the simulated module).
    static constexpr const char *kAddress = "sim:HI14";

    // timeScale: device seconds per real second (sim::SimulatedTransport::setTimeScale), for
    // tests whose checks are on the module's own clock (a fixture turning, a calibration run).
    explicit SimSession(sim::SimOptions options = {}, double timeScale = 1.0)
        : m_link(new sim::SimulatedTransport(std::make_unique<sim::HipnucSerialDevice>(std::move(options))))
        , session(nullptr, std::unique_ptr<io::Transport>(m_link))
    {
        m_link->setTimeScale(timeScale);
    }
    SimSession(const SimSession &) = delete;
    SimSession &operator=(const SimSession &) = delete;

    // baud 0: auto-detection.
    void open(int baud = 115200) { session.open(QString::fromLatin1(kAddress), baud); }

    // Runs fn on the simulated module in the engine's thread and waits for it.
    void withDevice(const std::function<void(sim::HipnucSimulator &)> &fn)
    {
        withLinkDevice<sim::HipnucSerialDevice>(m_link, [&fn](sim::HipnucSerialDevice &d) { fn(d.simulator()); });
    }
    sim::HipnucSimulator::State deviceState()
    {
        auto s = sim::HipnucSimulator::State::App;
        withDevice([&s](sim::HipnucSimulator &d) { s = d.state(); });
        return s;
    }
    int deviceBaud()
    {
        int b = 0;
        withDevice([&b](sim::HipnucSimulator &d) { b = d.baud(); });
        return b;
    }
    // Frames the module's UART model dropped (more than the line carries).
    uint64_t droppedFrames()
    {
        uint64_t n = 0;
        withDevice([&n](sim::HipnucSimulator &d) { n = d.droppedFrames(); });
        return n;
    }

    // The cable is pulled (the link fails) and plugged in again (the session may reopen it).
    void unplug() { inLink([](sim::SimulatedTransport &l) { l.unplug(); }); }
    void replug() { inLink([](sim::SimulatedTransport &l) { l.replug(); }); }

private:
    void inLink(void (*fn)(sim::SimulatedTransport &))
    {
        sim::SimulatedTransport *link = m_link;
        jobs::callAndWait(link, [link, fn] { fn(*link); });
    }

    sim::SimulatedTransport *m_link; // owned by the session

public:
    device::DeviceSession session;
};

// Opens `s` at `baud` (0: auto-detection); the calling test has failed
// (QTest::currentTestFailed()) unless the session is Connected within 15 s.
inline void connectSession(SimSession &s, int baud = 115200)
{
    s.open(baud);
    QTRY_COMPARE_WITH_TIMEOUT(s.session.state(), device::SessionState::Connected, 15000);
}

} // namespace imudesk::test
