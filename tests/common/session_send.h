#pragma once
// Sends an ASCII command through a DeviceSession and waits (turning the event loop) for
// its commandFinished; a reply still Pending means none came within timeoutMs + 10 s. The
// session ends every command by itself (its timeout is timeoutMs), so the bound only stops a
// test that would otherwise hang; it is generous for a host starved by other work.
#include "device/device_session.h"

#include <QSignalSpy>
#include <QTest>

namespace imudesk::test {

inline protocol::hipnuc::AsciiReply sendAndWait(device::DeviceSession &s, const QString &cmd, int timeoutMs)
{
    QSignalSpy spy(&s, &device::DeviceSession::commandFinished);
    const quint64 id = s.sendText(cmd, timeoutMs);
    protocol::hipnuc::AsciiReply r;
    r.status = protocol::hipnuc::AsciiReply::Status::Pending;
    (void)imudesk::test::waitFor(
        [&] {
            for (const auto &args : spy)
                if (args.at(0).toULongLong() == id) {
                    r = args.at(1).value<protocol::hipnuc::AsciiReply>();
                    return true;
                }
            return false;
        },
        timeoutMs + 10000);
    return r;
}

} // namespace imudesk::test
