#pragma once
// What PtySimulator needs from a simulated serial device, whatever the family: bytes in
// (received at the right baud), simulated time, bytes out tagged with the baud they were
// sent at, and the current baud. HipnucSerialDevice (HiPNUC modules) and Hec495Simulator
// (the Witlink compass) implement it.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace imudesk::sim {

// Bytes the device sent, in order. A chunk is one frame, sentence or reply; it may be split
// over several segments.
struct SerialSegment {
    int baud = 0;
    std::vector<uint8_t> bytes;
    uint64_t chunk = 0;
    bool chunkStart = false; // the first byte of the chunk is in this segment
    bool chunkEnd = false;   // the last byte of the chunk is in this segment
    bool data = false;       // a data frame or sentence (not a reply): may be dropped when the reader stalls
};

class SimulatedSerialDevice {
public:
    virtual ~SimulatedSerialDevice() = default;
    // Bytes from the host, received at the device's baud, at the current simulated time.
    virtual void receive(const uint8_t *data, size_t n) = 0;
    // Runs simulated time forward to nowUs (monotonic; earlier values are ignored).
    virtual void advanceTo(int64_t nowUs) = 0;
    virtual std::vector<SerialSegment> takeOutputSegments() = 0;
    // Current UART baud.
    virtual int baud() const = 0;
    virtual std::string productName() const = 0;
};

} // namespace imudesk::sim
