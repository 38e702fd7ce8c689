#include "simulated_byte_link.h"

namespace imudesk::sim {

bool SimulatedByteLink::open(int baud, QString *)
{
    m_baud = baud;
    m_open = true;
    clearInput();
    return true;
}

bool SimulatedByteLink::write(const std::vector<uint8_t> &bytes, QString *error)
{
    if (!m_open) {
        if (error)
            *error = QStringLiteral("not open");
        return false;
    }
    m_written += bytes.size();
    if (m_sim.baud() == m_baud)
        m_sim.receive(bytes.data(), bytes.size());
    return true;
}

void SimulatedByteLink::collect(std::vector<uint8_t> &out)
{
    for (const auto &s : m_sim.takeOutputSegments()) {
        if (s.baud == m_baud)
            out.insert(out.end(), s.bytes.begin(), s.bytes.end());
        else
            out.insert(out.end(), s.bytes.size(), uint8_t(0xFF));
    }
}

bool SimulatedByteLink::read(std::vector<uint8_t> &out, int timeoutMs, QString *error)
{
    if (!m_open) {
        if (error)
            *error = QStringLiteral("not open");
        return false;
    }
    const size_t before = out.size();
    const int64_t deadline = m_sim.nowUs() + int64_t(timeoutMs) * 1000;
    collect(out);
    while (out.size() == before && m_sim.nowUs() < deadline) {
        m_sim.advanceTo(std::min(deadline, m_sim.nowUs() + kStepUs));
        collect(out);
    }
    return true;
}

void SimulatedByteLink::clearInput()
{
    m_sim.takeOutputSegments();
}

void SimulatedByteLink::sleepMs(int ms)
{
    m_sim.advanceTo(m_sim.nowUs() + int64_t(ms) * 1000);
}

} // namespace imudesk::sim
