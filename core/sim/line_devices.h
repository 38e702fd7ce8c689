#pragma once
// Two things at the far end of a serial port that are not devices, for the bench sweep's tests
// and benchmark (core/discovery): a line where nothing answers (an adapter with nothing on it),
// and a line that sends bytes forming no frame of any family (a device at another framing, a
// swapped RS-485 pair). Served on a pseudo-terminal by PtySimulator like any simulated device.
#include "sim/simulated_serial_device.h"

#include <random>

namespace imudesk::sim {

class SilentLine final : public SimulatedSerialDevice {
public:
    explicit SilentLine(int baud = 115200) : m_baud(baud) {}
    void receive(const uint8_t *, size_t) override {}
    void advanceTo(int64_t) override {}
    std::vector<SerialSegment> takeOutputSegments() override { return {}; }
    int baud() const override { return m_baud; }
    std::string productName() const override { return "silent line"; }

private:
    int m_baud;
};

// Random bytes at `bytesPerSecond` (never a 0x5A 0xA5 HiPNUC sync, a 0x77 Witlink start, a '$'
// or a printable line: nothing a detection could take for a frame).
class NoiseLine final : public SimulatedSerialDevice {
public:
    explicit NoiseLine(int baud = 115200, int bytesPerSecond = 2000, uint64_t seed = 1);
    void receive(const uint8_t *, size_t) override {}
    void advanceTo(int64_t nowUs) override;
    std::vector<SerialSegment> takeOutputSegments() override;
    int baud() const override { return m_baud; }
    std::string productName() const override { return "noise"; }

private:
    int m_baud;
    int m_rate;
    std::mt19937_64 m_random;
    int64_t m_lastUs = -1;
    double m_owed = 0;
    std::vector<uint8_t> m_out;
    uint64_t m_chunk = 0;
};

} // namespace imudesk::sim
