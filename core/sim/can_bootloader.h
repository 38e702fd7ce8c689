#pragma once
// The CAN bootloader of a simulated HiPNUC CANopen module (hipnuc-protocol-notes 4.5), with its
// flash. Plain value class driven by CanSimDevice: handle() takes the host's SDO requests at
// time t (µs), takeDue(t) returns the replies whose time has come, takeRequest() tells the
// device to start the application or that power was lost.
//
//   0x1F51:05  (write) already in the bootloader: acknowledged
//   0x1F51:06  (write) "confirm": acknowledged
//   0x1F51:01  initiate segmented download with the size: refused when 0 or larger than the
//              application area; erases the sectors the size covers (eraseUsPerSector each,
//              the reply comes after the erase), the application is invalid from here on
//              segments: toggle checked, bytes 1..7 echoed in the reply (PY-NEW expects it), the
//              last segment's byte count decoded as the vendor does: n = ((15 - (cs & 0x0F)) / 2) + 1;
//              data written at appStart + offset; the last one makes the application valid
//   0x1F51:09  (write) acknowledged, then the application starts (refused without a valid one)
//   0x1F56:01  (upload) CiA 302 program software identification: CRC-32 (IEEE) of the bytes of
//              the last completed download as they are in flash; unless Options.crcObject is off
//   host abort (0x80): the transfer ends. Any other SDO gets no reply (the vendor bootloader only
//   knows its own object).
//
// Flash: by default 512 KiB in 4 KiB sectors; the first 32 KiB are the bootloader, the
// application area starts at 0x8000 (the layout of KbootBootloader).
//
// Fault injection (segment numbers count from 1 after each initiate; each fires once):
//   abortSegment N      the bootloader answers segment N with an SDO abort (general error)
//   silentSegment N     segment N gets no reply (and is discarded)
//   corruptSegment N    the reply to segment N carries the wrong toggle bit
//   badEchoSegment N    the reply to segment N echoes a damaged byte 1
//   powerLossSegment N  power is lost when segment N arrives (not written): the module restarts
//                       in its bootloader, the application invalid
//   flipByteAt K        the byte at offset K of the download is written with its lowest bit flipped
//                       (the CRC of 0x1F56:1 then differs from the image's)
#include "protocol/can/can_frame.h"
#include "protocol/can/sdo.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace imudesk::sim {

class CanBootloader {
public:
    struct Options {
        uint32_t flashSize = 512 * 1024;
        uint32_t sectorSize = 4096;
        uint32_t appStart = 0x8000;
        int64_t eraseUsPerSector = 20000; // 120 sectors: 2.4 s, inside the host's 8 s
        int64_t replyUs = 300;            // reply latency
        bool crcObject = true;            // 0x1F56:1 answered
    };
    struct Faults {
        int abortSegment = 0;
        int silentSegment = 0;
        int corruptSegment = 0;
        int powerLossSegment = 0;
        int badEchoSegment = 0;
        int64_t flipByteAt = -1;
    };
    struct Stats {
        uint64_t segments = 0, downloads = 0, abortsSent = 0, abortsReceived = 0, sectorsErased = 0,
                 bytesWritten = 0, starts = 0;
    };
    enum class Request { None, StartApplication, PowerLoss };

    explicit CanBootloader(Options options);
    CanBootloader() : CanBootloader(Options{}) {}

    // The bootloader starts (after a reset, a power cycle or 0x1F51:05) at time t.
    void start(uint8_t node, int64_t tUs);
    // An SDO request from the host (already parsed; raw is the frame) at time t.
    void handle(const protocol::can::canopen::SdoMessage &m, const protocol::can::CanFrame &raw, int64_t tUs);
    // Replies due at t, in order.
    std::vector<protocol::can::CanFrame> takeDue(int64_t tUs);
    // What the module has to do now (StartApplication once its reply is out; PowerLoss at once).
    Request takeRequest(int64_t tUs);

    const Options &options() const { return m_options; }
    Options &mutableOptions() { return m_options; }
    Faults &faults() { return m_faults; }
    const Stats &stats() const { return m_stats; }
    bool downloading() const { return m_downloading; }
    const std::vector<uint8_t> &flash() const { return m_flash; }
    std::vector<uint8_t> applicationArea() const;
    bool applicationValid() const { return m_appValid; }
    // The version text after KbootBootloader::kVersionMarker in the application area, if any.
    std::optional<std::string> applicationVersion() const;
    // Programs an application at appStart as a completed download would (start-up, tests).
    void installApplication(const std::vector<uint8_t> &image);

private:
    struct Pending {
        protocol::can::CanFrame frame;
        int64_t dueUs;
    };
    void reply(const protocol::can::CanFrame &f, int64_t dueUs);
    void abort(uint16_t index, uint8_t sub, uint32_t code, int64_t tUs);
    void handleSegment(const protocol::can::CanFrame &raw, int64_t tUs);
    void initiate(uint32_t size, int64_t tUs);

    Options m_options;
    Faults m_faults;
    Stats m_stats;
    std::vector<uint8_t> m_flash;
    bool m_appValid = false;
    uint8_t m_node = 8;
    std::vector<Pending> m_pending;
    Request m_request = Request::None;
    int64_t m_requestAtUs = 0;

    bool m_downloading = false;
    uint32_t m_size = 0, m_offset = 0;
    bool m_toggle = false;
    int m_segment = 0;
    uint32_t m_lastDownloadSize = 0; // 0: no completed download since the last erase
};

} // namespace imudesk::sim
