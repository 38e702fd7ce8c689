#pragma once
// HiPNUC serial: the byte stream of a module's port (ASCII replies, binary frames of HI91,
// HI92, HI81 and HI83 packets, NMEA sentences). StreamDemux splits it; each frame's payload
// becomes packets (HI91 fast path, then every sub-packet) and each packet a sample, stamped
// through the frame clocks (clock/serial_frame_clocks.h): a read that ended inside a frame
// bounds its sampling instant. The Record's native unit is the protocol::hipnuc::Packet.
#include "clock/serial_frame_clocks.h"
#include "decode/stream_decoder.h"
#include "protocol/stream/stream_demux.h"

#include <vector>

namespace imudesk::decode {

class HipnucStreamDecoder final : public StreamDecoder {
public:
    static constexpr const char *kFamily = "HiPNUC serial";
    const char *family() const override { return kFamily; }
    // A packet's tag by its name ("HI91" -> 0x91); 0 for any other source.
    static int tagOf(const std::string &source);
    void configure(const std::map<std::string, std::string> &header) override;
    void setBaud(int baud) override { m_clocks.setBaud(baud); }
    void feed(const uint8_t *data, size_t n, int64_t hostNs, Sink &sink) override;
    bool midUnit() const override { return m_demux.pendingBytes() > 0; }
    void lineIdle(int64_t hostNs, Sink &sink) override;
    void finish(int64_t hostNs, Sink &sink) override;
    void restart() override;
    void reset() override;
    void resetCounters() override;
    Counters counters() const override;

    // What a boundary the device keeps starts (an ASCII command was answered): quarantined
    // text ends here.
    void endQuarantine() { m_demux.endQuarantine(); }
    const protocol::StreamDemux &demux() const { return m_demux; }
    const clock::SerialFrameClocks &frameClocks() const { return m_clocks; }

private:
    void dispatch(int64_t hostNs, Sink &sink);

    protocol::StreamDemux m_demux;
    std::vector<protocol::StreamEvent> m_events;
    clock::SerialFrameClocks m_clocks;
    uint64_t m_payloadErrors = 0;
};

} // namespace imudesk::decode
