#include "simulated_can_frame_link.h"

#include <QCoreApplication>

#include <algorithm>

namespace imudesk::sim {

SimulatedCanFrameLink::SimulatedCanFrameLink(CanSimDevice &device, int bitrate)
    : m_device(device), m_frameUs(std::max<int64_t>(1, int64_t(kBitsPerFrame) * 1000000 / std::max(bitrate, 1000)))
{
}

bool SimulatedCanFrameLink::usable(QString *error) const
{
    if (m_open && !m_unplugged)
        return true;
    *error = QCoreApplication::translate("SimulatedCanFrameLink", "the simulated CAN bus is not connected");
    return false;
}

bool SimulatedCanFrameLink::open(QString *error)
{
    if (m_unplugged)
        return usable(error);
    m_open = true;
    return true;
}

void SimulatedCanFrameLink::advance(int64_t us)
{
    const int64_t end = m_nowUs + us;
    while (m_nowUs < end) {
        m_nowUs = std::min(end, m_nowUs + kStepUs);
        for (const auto &f : m_device.poll(double(m_nowUs) * 1e-6))
            m_queue.push_back(f);
    }
}

bool SimulatedCanFrameLink::send(const protocol::can::CanFrame &frame, QString *error)
{
    if (!usable(error))
        return false;
    m_sent.push_back(frame);
    advance(m_frameUs);
    for (const auto &f : m_device.handle(frame, double(m_nowUs) * 1e-6))
        m_queue.push_back(f);
    return true;
}

bool SimulatedCanFrameLink::receive(std::vector<protocol::can::CanFrame> &out, int timeoutMs, QString *error)
{
    if (!usable(error))
        return false;
    const int64_t deadline = m_nowUs + int64_t(std::max(timeoutMs, 0)) * 1000;
    while (m_queue.empty() && m_nowUs < deadline)
        advance(std::min<int64_t>(kStepUs, deadline - m_nowUs));
    out.insert(out.end(), m_queue.begin(), m_queue.end());
    m_queue.clear();
    return true;
}

void SimulatedCanFrameLink::sleepMs(int ms)
{
    advance(int64_t(std::max(ms, 0)) * 1000);
}

} // namespace imudesk::sim
