#pragma once
// Waits (turning the event loop) for the result of a CanSession request; a result with the
// message "no result" when none came within timeoutMs.
#include "device/can_session.h"
#include "try_bounds.h"

#include <QObject>

namespace imudesk::test {

inline device::CanRequestResult waitCanResult(device::CanSession &s, quint64 id, int timeoutMs = 5000)
{
    device::CanRequestResult out;
    bool done = false;
    const QMetaObject::Connection c =
        QObject::connect(&s, &device::CanSession::requestFinished, &s, [&](const device::CanRequestResult &r) {
            if (r.id == id) {
                out = r;
                done = true;
            }
        });
    const bool finished = imudesk::test::waitFor([&done] { return done; }, timeoutMs);
    QObject::disconnect(c);
    if (!finished)
        out.message = QStringLiteral("no result");
    return out;
}

} // namespace imudesk::test
