#pragma once
// In-process links for the session, family and station tests (issue 33): the simulated device
// sits behind sim::SimulatedTransport in the session's own worker thread, so no
// pseudo-terminal and no simulator thread are involved, and nothing a loaded host does can drop
// bytes between them. The tests that prove the real serial path keep their pseudo-terminals.
#include "jobs/thread_sync.h"
#include "sim/simulated_transport.h"

#include <QString>

#include <functional>
#include <memory>

namespace imudesk::test {

// Runs fn with the link's device, as a Device, in the link's thread (the session's worker
// thread) and waits for it. The link must belong to a live session.
template <class Device>
void withLinkDevice(sim::SimulatedTransport *link, const std::function<void(Device &)> &fn)
{
    jobs::callAndWait(link, [link, &fn] { fn(dynamic_cast<Device &>(link->device())); });
}

// A session of type S (Hec495Session, ModbusSession, DeviceSession: any with the constructor
// (QObject *parent, std::unique_ptr<io::Transport>)) over its own in-process link to device.
// link stays valid as long as session does (the session owns it).
template <class S>
struct InProcSession {
    std::unique_ptr<S> session;
    sim::SimulatedTransport *link = nullptr;
    // The name the session opens; any text does, the link ignores it.
    QString port;

    template <class Device>
    void withDevice(const std::function<void(Device &)> &fn) const
    {
        withLinkDevice<Device>(link, fn);
    }
};

template <class S>
InProcSession<S> inProcSession(std::unique_ptr<sim::SimulatedSerialDevice> device, const QString &port,
                               double timeScale = 1.0)
{
    auto link = std::make_unique<sim::SimulatedTransport>(std::move(device));
    link->setTimeScale(timeScale);
    InProcSession<S> out;
    out.link = link.get();
    out.port = port;
    out.session = std::make_unique<S>(nullptr, std::move(link));
    return out;
}

} // namespace imudesk::test
