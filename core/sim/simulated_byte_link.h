#pragma once
// firmware::ByteLink to a HipnucSimulator in the same process, on the simulator's clock:
// reads advance simulated time in kStepUs steps until bytes arrive or the timeout passes,
// so an update runs in milliseconds of real time and deterministically. Bytes sent at a
// baud other than the link's arrive as 0xFF (framing errors); bytes written while the
// module listens at another baud are lost. Not thread-safe; for tests and benchmarks.
#include "io/byte_link.h"
#include "sim/hipnuc_simulator.h"

namespace imudesk::sim {

class SimulatedByteLink : public firmware::ByteLink {
public:
    static constexpr int64_t kStepUs = 200;

    explicit SimulatedByteLink(HipnucSimulator &sim) : m_sim(sim) {}

    bool open(int baud, QString *error) override;
    void close() override { m_open = false; }
    bool isOpen() const override { return m_open; }
    bool write(const std::vector<uint8_t> &bytes, QString *error) override;
    bool read(std::vector<uint8_t> &out, int timeoutMs, QString *error) override;
    void clearInput() override;
    void sleepMs(int ms) override;
    int64_t nowUs() const override { return m_sim.nowUs(); }

    uint64_t bytesWritten() const { return m_written; }

private:
    void collect(std::vector<uint8_t> &out);

    HipnucSimulator &m_sim;
    int m_baud = 115200;
    bool m_open = false;
    uint64_t m_written = 0;
};

} // namespace imudesk::sim
