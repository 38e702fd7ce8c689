#pragma once
// The byte pipe an update runs over: a serial port (SerialByteLink) or, in tests, a
// simulator in the same process with virtual time (sim::SimulatedByteLink). Blocking calls,
// used from one thread (the update's worker thread).
#include <QString>

#include <cstdint>
#include <vector>

namespace imudesk::firmware {

class ByteLink {
public:
    virtual ~ByteLink() = default;
    virtual bool open(int baud, QString *error) = 0;
    virtual void close() = 0;
    virtual bool isOpen() const = 0;
    virtual bool write(const std::vector<uint8_t> &bytes, QString *error) = 0;
    // Appends whatever arrives within timeoutMs (returns as soon as something arrived).
    // False only on a transport error (unplugged, closed).
    virtual bool read(std::vector<uint8_t> &out, int timeoutMs, QString *error) = 0;
    // Drops bytes received and not yet read.
    virtual void clearInput() = 0;
    virtual void sleepMs(int ms) = 0;
    // Monotonic clock of the link (µs): real time on a port, simulated time in tests.
    virtual int64_t nowUs() const = 0;
};

} // namespace imudesk::firmware
