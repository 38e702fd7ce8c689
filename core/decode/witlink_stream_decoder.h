#pragma once
// HEC495 serial: Witlink frames (77 len addr cmd data sum). Its records and angles frames
// become samples; an answer to a request has the request's bracket as its common time
// (clock/clock_model.h: bracketTime), output the module sends on its own keeps its arrival
// alone. The bytes of no frame (the NMEA output, noise) go through the text demultiplexer.
// The Record's native unit is the protocol::witlink::Reply.
//
// Which frame answers a request: in a capture, any frame after a recorded request (sent());
// live, the family's FrameHook decides (command and address) and may set a frame aside (an
// RS-485 echo of its own request).
#include "clock/clock_model.h"
#include "decode/stream_decoder.h"
#include "protocol/stream/stream_demux.h"
#include "protocol/witlink/frame_decoder.h"
#include "protocol/witlink/reply.h"

#include <vector>

namespace imudesk::decode {

class WitlinkStreamDecoder final : public StreamDecoder {
public:
    static constexpr const char *kFamily = "HEC495 serial";

    struct FrameVerdict {
        bool skip = false;    // not the module's (an echo of the request): not decoded, not counted
        bool answers = false; // the answer to the request sent at sentNs
        int64_t sentNs = 0;
    };
    class FrameHook {
    public:
        virtual ~FrameHook() = default;
        // Each frame, before its sample: what it is to the request under way. The hook may act
        // on it at once (finish the request): the sample follows in the same feed.
        virtual FrameVerdict frame(const protocol::witlink::Frame &f, const protocol::witlink::Reply &r) = 0;
    };
    void setHook(FrameHook *hook) { m_hook = hook; }

    const char *family() const override { return kFamily; }
    void configure(const std::map<std::string, std::string> &header) override;
    void setBaud(int) override {}
    void feed(const uint8_t *data, size_t n, int64_t hostNs, Sink &sink) override;
    void sent(int64_t hostNs) override { m_sentNs = hostNs; }
    bool midUnit() const override { return m_frames.pendingBytes() > 0; }
    void lineIdle(int64_t hostNs, Sink &sink) override;
    void finish(int64_t hostNs, Sink &sink) override;
    void restart() override;
    void reset() override;
    void resetCounters() override;
    Counters counters() const override;

    const clock::BracketTally &brackets() const { return m_brackets; }

private:
    void handle(int64_t hostNs, Sink &sink, bool idle, const uint8_t *data, size_t n);

    FrameHook *m_hook = nullptr;
    protocol::witlink::FrameDecoder m_frames;
    std::vector<protocol::witlink::Frame> m_decoded;
    protocol::StreamDemux m_text; // the text between frames: NMEA sentences
    std::vector<protocol::StreamEvent> m_textEvents;
    std::map<std::string, uint64_t> m_byType;
    uint64_t m_payloadErrors = 0;
    clock::BracketTally m_brackets; // the polled samples' request->answer intervals
    int64_t m_sentNs = 0;           // the last request's time, until its answer
};

} // namespace imudesk::decode
