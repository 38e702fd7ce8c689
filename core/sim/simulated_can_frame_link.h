#pragma once
// firmware::CanFrameLink to a CanSimDevice in the same process, on a simulated clock: sending
// a frame takes its time on the bus (bitrate), reads advance time in kStepUs steps, polling the
// device, until frames arrive or the timeout passes. A CAN update then runs in milliseconds of
// real time and deterministically. Every frame sent is kept (sent()) for golden tests. Not
// thread-safe; for tests and benchmarks.
#include "can_sim_device.h"
#include "io/can_frame_link.h"

#include <deque>

namespace imudesk::sim {

class SimulatedCanFrameLink : public firmware::CanFrameLink {
public:
    static constexpr int64_t kStepUs = 100;
    static constexpr int kBitsPerFrame = 130; // an 8-byte standard frame with stuffing, roughly

    explicit SimulatedCanFrameLink(CanSimDevice &device, int bitrate = 500000);

    bool open(QString *error) override;
    void close() override { m_open = false; }
    bool isOpen() const override { return m_open; }
    bool send(const protocol::can::CanFrame &frame, QString *error) override;
    bool receive(std::vector<protocol::can::CanFrame> &out, int timeoutMs, QString *error) override;
    void clearInput() override { m_queue.clear(); }
    void sleepMs(int ms) override;
    int64_t nowUs() const override { return m_nowUs; }

    const std::vector<protocol::can::CanFrame> &sent() const { return m_sent; }
    void clearSent() { m_sent.clear(); }
    // The bus is unplugged: send() and receive() fail (a transport error).
    void setUnplugged(bool on) { m_unplugged = on; }

private:
    void advance(int64_t us);
    bool usable(QString *error) const;

    CanSimDevice &m_device;
    int64_t m_frameUs;
    int64_t m_nowUs = 0;
    bool m_open = false;
    bool m_unplugged = false;
    std::deque<protocol::can::CanFrame> m_queue;
    std::vector<protocol::can::CanFrame> m_sent;
};

} // namespace imudesk::sim
