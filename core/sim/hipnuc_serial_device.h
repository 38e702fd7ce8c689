#pragma once
// Serves a HipnucSimulator through the SimulatedSerialDevice interface (PtySimulator).
#include "sim/hipnuc_simulator.h"
#include "sim/simulated_serial_device.h"

namespace imudesk::sim {

class HipnucSerialDevice : public SimulatedSerialDevice {
public:
    explicit HipnucSerialDevice(SimOptions options = {}) : m_sim(std::move(options)) {}

    void receive(const uint8_t *data, size_t n) override { m_sim.receive(data, n); }
    void advanceTo(int64_t nowUs) override { m_sim.advanceTo(nowUs); }
    std::vector<SerialSegment> takeOutputSegments() override;
    int baud() const override { return m_sim.baud(); }
    std::string productName() const override { return m_sim.productName(); }

    HipnucSimulator &simulator() { return m_sim; }

private:
    HipnucSimulator m_sim;
};

} // namespace imudesk::sim
