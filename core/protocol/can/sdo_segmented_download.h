#pragma once
// Client side of a CANopen segmented SDO download (CiA 301), as the firmware update to object
// 0x1F51 sub 1 needs it (hipnuc-protocol-notes 4.5): initiate with the size, then 7-byte
// segments with an alternating toggle bit, each confirmed by the device. The last segment's
// "bytes not used" field follows either CiA 301 ((7 - n) << 1 | 1) or the HiPNUC bootloader's
// convention (17 - 2n).
#include "can_frame.h"
#include "sdo.h"

#include <cstdint>
#include <vector>

namespace imudesk::protocol::can::canopen {

class SdoSegmentedDownload {
public:
    enum class LastSegment { Cia301, Hipnuc };
    enum class Status { Running, Done, Failed };

    SdoSegmentedDownload(uint8_t node, uint16_t index, uint8_t sub, std::vector<uint8_t> data,
                         LastSegment style = LastSegment::Hipnuc);

    // The initiate request (0x21, size in bytes 4..7).
    CanFrame start();
    // Feeds a frame from the bus; when it is this transfer's reply, returns true and, while
    // Running, next() holds the frame to send.
    bool onFrame(const CanFrame &f);
    const CanFrame &next() const { return m_next; }
    Status status() const { return m_status; }
    uint32_t abortCode() const { return m_abort; }
    QString error() const { return m_error; }
    size_t sent() const { return m_offset; }
    size_t total() const { return m_data.size(); }
    int percent() const;

    // Command specifier of a segment with n data bytes (1..7), toggle t, last or not.
    static uint8_t segmentCs(int n, bool toggle, bool last, LastSegment style);

private:
    CanFrame segment();
    void fail(const QString &why, uint32_t code = 0);

    uint8_t m_node;
    uint16_t m_index;
    uint8_t m_sub;
    std::vector<uint8_t> m_data;
    LastSegment m_style;
    size_t m_offset = 0;
    bool m_toggle = false;
    bool m_initiated = false;
    size_t m_pendingBytes = 0;
    bool m_lastSent = false;
    Status m_status = Status::Running;
    uint32_t m_abort = 0;
    QString m_error;
    CanFrame m_next;
};

} // namespace imudesk::protocol::can::canopen
