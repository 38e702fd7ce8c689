#pragma once
// Writes a FirmwareImage as Intel HEX: type 04 records when the upper 16 address bits change,
// 00 records of up to 32 bytes (never crossing a 64 KiB boundary), 05 if an entry point is set,
// then 01. CRLF line ends, upper-case hex. Runs of 0xFF are written too (the loader fills gaps
// with 0xFF anyway; writing them keeps the image's exact extent).
#include "protocol/ihex/firmware_image.h"

#include <string>

namespace imudesk::protocol::ihex {

class IntelHexWriter {
public:
    static std::string write(const FirmwareImage &image, size_t bytesPerRecord = 32);
};

} // namespace imudesk::protocol::ihex
