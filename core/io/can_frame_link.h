#pragma once
// The frame pipe a CAN firmware update runs over: a Qt CAN bus device (QtCanFrameLink) or, in
// tests, a simulated CAN module in the same process with virtual time (sim::SimulatedCanFrameLink).
// Blocking calls, used from one thread (the update's worker thread).
#include "protocol/can/can_frame.h"

#include <QString>

#include <cstdint>
#include <vector>

namespace imudesk::firmware {

class CanFrameLink {
public:
    virtual ~CanFrameLink() = default;
    virtual bool open(QString *error) = 0;
    virtual void close() = 0;
    virtual bool isOpen() const = 0;
    virtual bool send(const protocol::can::CanFrame &frame, QString *error) = 0;
    // Appends whatever arrives within timeoutMs (returns as soon as something arrived).
    // False only on a transport error (bus off, unplugged, closed).
    virtual bool receive(std::vector<protocol::can::CanFrame> &out, int timeoutMs, QString *error) = 0;
    // Drops frames received and not yet read.
    virtual void clearInput() = 0;
    virtual void sleepMs(int ms) = 0;
    // Monotonic clock of the link (µs): real time on a bus, simulated time in tests.
    virtual int64_t nowUs() const = 0;
};

} // namespace imudesk::firmware
