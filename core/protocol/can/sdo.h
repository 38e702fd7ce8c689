#pragma once
// CANopen SDO frames (CiA 301 as used by the manuals' chapter 8 / 5 and the HEC495 manual):
// request 0x600 + node, reply 0x580 + node, always 8 bytes: command specifier, index (LE),
// sub-index, 4 data bytes. Expedited download and upload, abort codes, and the frames of a
// segmented download (used to send firmware to object 0x1F51).
#include "can_frame.h"
#include "canopen.h"

#include <QString>

#include <cstdint>
#include <optional>

namespace imudesk::protocol::can::canopen {

enum SdoCs : uint8_t {
    SdoDownload4 = 0x23,           // expedited, 4 bytes, size indicated
    SdoDownload3 = 0x27,
    SdoDownload2 = 0x2B,
    SdoDownload1 = 0x2F,
    SdoDownloadUnsized = 0x22,     // expedited, size not indicated (HEC495 manual)
    SdoDownloadSegmented = 0x21,   // initiate segmented download, size indicated in bytes 4..7
    SdoDownloadReply = 0x60,
    SdoUploadRequest = 0x40,
    SdoAbort = 0x80,
};

enum SdoAbortCode : uint32_t {
    AbortToggle = 0x05030000,
    AbortTimeout = 0x05040000,
    AbortCommand = 0x05040001,
    AbortOutOfMemory = 0x05040005,
    AbortUnsupported = 0x06010000,
    AbortWriteOnly = 0x06010001,
    AbortReadOnly = 0x06010002,
    AbortNoObject = 0x06020000,
    AbortLength = 0x06070010,
    AbortNoSubIndex = 0x06090011,
    AbortValueRange = 0x06090030,
    AbortValueHigh = 0x06090031,
    AbortValueLow = 0x06090032,
    AbortGeneral = 0x08000000,
    AbortStore = 0x08000020,
    AbortDeviceState = 0x08000022,
};
QString abortText(uint32_t code);

enum class SdoKind {
    Unknown,
    DownloadExpedited,   // host: write 1..4 bytes (or unsized 0x22)
    DownloadSegmentedInit,
    DownloadSegment,     // host: segment (cs 0x00..0x1F)
    DownloadReply,       // device: 0x60 initiate reply
    DownloadSegmentReply,// device: 0x20 / 0x30
    UploadRequest,       // host: 0x40
    UploadExpedited,     // device: 0x42..0x4F
    UploadSegmentedInit, // device: 0x41
    Abort,               // either side: 0x80
};

struct SdoMessage {
    uint8_t node = 0;
    bool fromDevice = false; // 0x580 + node
    uint8_t cs = 0;
    SdoKind kind = SdoKind::Unknown;
    uint16_t index = 0;
    uint8_t sub = 0;
    uint32_t value = 0;      // bytes 4..7 LE (abort code, expedited data or size)
    int size = 0;            // expedited data bytes (0 when not indicated)
};

// 0x580 + node or 0x600 + node with 8 data bytes; nullopt otherwise.
std::optional<SdoMessage> parseSdo(const CanFrame &f);

// Host requests.
CanFrame sdoWrite(uint8_t node, uint16_t index, uint8_t sub, uint32_t value, int size = 4); // 0x2F/0x2B/0x27/0x23
CanFrame sdoWriteUnsized(uint8_t node, uint16_t index, uint8_t sub, uint32_t value);        // 0x22
CanFrame sdoRead(uint8_t node, uint16_t index, uint8_t sub);                               // 0x40
// Device replies (simulator).
CanFrame sdoWriteReply(uint8_t node, uint16_t index, uint8_t sub);
CanFrame sdoReadReply(uint8_t node, uint16_t index, uint8_t sub, uint32_t value, int size);
CanFrame sdoAbortFrame(uint8_t node, uint16_t index, uint8_t sub, uint32_t code, bool fromDevice = true);

// Does the device reply answer the host request (same node, index, sub)?
bool sdoAnswers(const SdoMessage &reply, const SdoMessage &request);

// "SDO write 0x1800.05 = 10 (2 bytes)", "SDO abort 0x2000.00: object does not exist", ...
QString describe(const SdoMessage &m);

} // namespace imudesk::protocol::can::canopen
