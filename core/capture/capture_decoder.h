#pragma once
// The live session's decoding path for recorded bytes: StreamDemux splits the stream
// into HiPNUC frames, NMEA sentences and text lines; each frame's payload becomes HiPNUC
// packets (HI91 fast path, then every sub-packet). A capture of an HEC495 (link kind "HEC495
// serial") goes through the Witlink frame decoder instead, as Hec495Family does: its records
// and angles frames become samples (Sink::onSample), the text between them (NMEA output)
// sentences. A CAN capture (link kind "CAN") holds frame records (protocol/can/can_record.h):
// CanDecoder decodes them and the node's frames merge into samples as CanFamily does, each
// with the interface's receive stamp less the frame's time on the bus as its common time.
// Chunks are fed with their arrival time,
// and a pause of kLineIdleNs between chunks releases an unfinished candidate frame and
// ends the text quarantine exactly as the session's idle timer does, so a replay decodes
// what the live session decoded. Replay, export, analysis and `imudesk-cli decode` all decode
// through it. Plain value class.
#include "clock/clock_model.h"
#include "clock/serial_frame_clocks.h"
#include "protocol/can/can_decoder.h"
#include "protocol/can/can_record.h"
#include "protocol/hipnuc/payloads.h"
#include "capture/capture_reader.h"
#include "protocol/stream/stream_demux.h"
#include "protocol/witlink/frame_decoder.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace imudesk::capture {

class CaptureDecoder {
public:
    static constexpr int64_t kLineIdleNs = 30'000'000; // the session's kLineIdleMs

    class Sink {
    public:
        virtual ~Sink() = default;
        virtual void onPacket(const protocol::hipnuc::Packet &packet, int64_t hostNs) = 0;
        virtual void onNmea(const std::string & /*sentence*/, int64_t /*hostNs*/) {}
        // A sample of a family without HiPNUC packets (the HEC495's records and angles).
        virtual void onSample(const model::Sample & /*sample*/, int64_t /*hostNs*/) {}
        virtual void onLine(const std::string & /*line*/, int64_t /*hostNs*/) {}
        // A frame whose payload holds a packet the manual's tables cannot decode (counted in
        // payloadErrors(); the packets before it were delivered).
        virtual void onPayloadError(const protocol::hipnuc::PayloadResult & /*result*/, int64_t /*hostNs*/) {}
    };

    // Follows the capture's header: with idle markers recorded, the markers release held
    // bytes (exactly where the live session did) and pauses between chunks do not.
    void configure(const CaptureHeader &header);
    // One chunk of a capture, whatever its kind.
    void feedChunk(const CaptureReader::Chunk &chunk, Sink &sink);
    // Bytes that arrived at hostNs (host monotonic clock).
    void feed(const uint8_t *data, size_t n, int64_t hostNs, Sink &sink);
    // The line went idle at hostNs: release what an unfinished candidate holds.
    void lineIdle(int64_t hostNs, Sink &sink);
    // End of the capture: releases whatever is held.
    void finish(Sink &sink);
    // Forgets partial frames and lines (after a seek); counters are kept.
    void reset();

    const protocol::StreamDemux &demux() const { return m_demux; }
    bool witlink() const { return m_witlink; }
    bool can() const { return m_can; }
    const protocol::can::CanDecoder::Counters &canCounters() const { return m_canDecoder.counters(); }
    // CAN frames by kind ("TPDO", "SDO", "SYNC", ...), as the live session counts them.
    const std::map<std::string, uint64_t> &canFramesByType() const { return m_canByType; }
    const protocol::witlink::FrameDecoder::Counters &witlinkCounters() const { return m_witlinkDecoder.counters(); }
    // HEC495 frames decoded into samples, by kind ("HEC495 record", "HEC495 angles").
    const std::map<std::string, uint64_t> &witlinkFramesByType() const { return m_witlinkByType; }
    uint64_t payloadErrors() const { return m_payloadErrors; }
    // During Sink::onPacket: the packet's common time (ns on the capture's host clock), from its
    // device time through the clock model the live session used (clock/serial_frame_clocks.h),
    // fed with the same chunks; 0 without a device time or before the model has a sample.
    int64_t packetCommonNs() const { return m_packetCommonNs; }
    void resetCounters();

private:
    void dispatch(int64_t hostNs, Sink &sink);

    void feedWitlink(const uint8_t *data, size_t n, int64_t hostNs, Sink &sink, bool idle);
    void feedCan(const uint8_t *data, size_t n, int64_t hostNs, Sink &sink);

    protocol::StreamDemux m_demux;
    std::vector<protocol::StreamEvent> m_events;
    bool m_witlink = false; // an HEC495 capture
    protocol::witlink::FrameDecoder m_witlinkDecoder;
    std::vector<protocol::witlink::Frame> m_witlinkFrames;
    std::map<std::string, uint64_t> m_witlinkByType;
    bool m_can = false; // a CAN capture
    protocol::can::CanDecoder m_canDecoder;
    protocol::can::CanRecordReader m_canReader;
    std::vector<protocol::can::CanRecord> m_canRecords;
    std::map<std::string, uint64_t> m_canByType;
    model::Sample m_canMerged;
    int m_canNode = -1; // the node followed: the header's, else the first that sends data
    int64_t m_lastNs = 0;
    bool m_haveLast = false;
    bool m_timedIdle = true; // no markers recorded: infer idle lines from pauses between chunks
    uint64_t m_payloadErrors = 0;
    clock::SerialFrameClocks m_clocks;
    int64_t m_packetCommonNs = 0;
    int64_t m_lastSentNs = 0; // the last request's time, until its answer
};

} // namespace imudesk::capture
