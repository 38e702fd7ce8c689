#pragma once
// CAN: the frame records of a CAN link (protocol/can/can_record.h: J1939, CANopen, the
// HEC495's CAN output). CanDecoder decodes each frame; a node's data frames merge into one
// sample per frame (a record's components update the last sample), each with the
// interface's receive stamp less the frame's time on the bus as its common time. One node is
// followed: the one configured (a capture's header names it), else the first that sends data.
// The Record's native unit is the protocol::can::DecodedFrame.
//
// Live, the family's FrameHook sees every frame first (the node list, a job's answers) and
// may take it (an answer is not a sample).
#include "decode/stream_decoder.h"
#include "protocol/can/can_decoder.h"
#include "protocol/can/can_record.h"

#include <vector>

namespace imudesk::decode {

class CanStreamDecoder final : public StreamDecoder {
public:
    static constexpr const char *kFamily = "CAN";

    class FrameHook {
    public:
        virtual ~FrameHook() = default;
        // Each frame, decoded; true takes it (no sample comes of it).
        virtual bool frame(const protocol::can::CanFrame &f, const protocol::can::DecodedFrame &d, int64_t hostNs) = 0;
        // The decoder started following this node (the first that sent data).
        virtual void nodeFollowed(int /*node*/) {}
    };
    void setHook(FrameHook *hook) { m_hook = hook; }

    const char *family() const override { return kFamily; }
    // can.protocol, can.node and can.hec495_mode (the bit rate comes by setBaud).
    void configure(const std::map<std::string, std::string> &header) override;
    void setBaud(int bitrate) override { m_bitrate = bitrate; }
    void feed(const uint8_t *data, size_t n, int64_t hostNs, Sink &sink) override;
    bool midUnit() const override { return false; } // records arrive whole
    void lineIdle(int64_t, Sink &) override {}
    void finish(int64_t, Sink &) override {}
    void restart() override { m_reader.reset(); }
    void reset() override;
    void resetCounters() override;
    Counters counters() const override;

    // The node followed (-1: none yet); setting it starts a new merged sample.
    int node() const { return m_node; }
    void setNode(int node);
    protocol::can::CanDecoder &decoder() { return m_decoder; }
    const protocol::can::CanDecoder &decoder() const { return m_decoder; }
    uint64_t stampedSamples() const { return m_stamped; }
    uint64_t unstampedSamples() const { return m_unstamped; }

private:
    FrameHook *m_hook = nullptr;
    protocol::can::CanDecoder m_decoder;
    protocol::can::CanRecordReader m_reader;
    std::vector<protocol::can::CanRecord> m_records;
    std::map<std::string, uint64_t> m_byType;
    model::Sample m_merged;
    int m_node = -1;
    int m_bitrate = 0;
    uint64_t m_frames = 0;
    uint64_t m_bytesIn = 0;
    uint64_t m_errorFrames = 0;
    uint64_t m_stamped = 0;
    uint64_t m_unstamped = 0;
};

} // namespace imudesk::decode
