#pragma once
// Intel HEX (record types 00-05) and raw binary loader for firmware images.
//
// Rules (stricter than every vendor loader, see hipnuc-protocol-notes.md 3.4):
//   * every non-blank line is one record ":LLAAAATT<data>CC" (CR/LF or LF; blank lines skipped);
//   * each record's checksum is checked; the byte count must match the line length;
//   * 00 data (length 0 allowed, ignored), 01 end of file (length 0, address 0, required,
//     nothing but blank lines after it), 02 extended segment address (base = value << 4),
//     03 start segment address (CS:IP, kept as entry point), 04 extended linear address
//     (base = value << 16), 05 start linear address (entry point); other types are refused;
//   * records may come in any order; two records that write the same address are refused;
//     gaps between records are filled with 0xFF; the image starts at the lowest address;
//   * a data record must not run past 4 GiB; the span from the lowest to the highest address
//     is bounded by Limits::maxImageBytes before the image is allocated;
//   * every error names the line (1-based) it was found on.
// A raw .bin is taken as is at an explicit start address.
#include "protocol/ihex/firmware_image.h"

#include <QCoreApplication>
#include <QString>

#include <cstdint>
#include <optional>
#include <string_view>

namespace imudesk::protocol::ihex {

struct LoadResult {
    std::optional<FirmwareImage> image;
    QString error;   // empty when image is set
    int line = 0;    // line of the error (0: the file as a whole)
    bool ok() const { return image.has_value(); }
};

class IntelHexLoader {
    Q_DECLARE_TR_FUNCTIONS(IntelHexLoader)

public:
    struct Limits {
        uint64_t maxImageBytes = 16u * 1024u * 1024u;   // span lowest..highest address
        uint64_t maxFileBytes = 64u * 1024u * 1024u;     // input text size
    };

    static LoadResult parseHex(std::string_view text, const Limits &limits);
    static LoadResult parseHex(std::string_view text) { return parseHex(text, Limits{}); }
    static LoadResult fromBinary(std::string_view bytes, uint32_t startAddress, const Limits &limits);
    static LoadResult fromBinary(std::string_view bytes, uint32_t startAddress)
    {
        return fromBinary(bytes, startAddress, Limits{});
    }
    // Reads a file: ".bin" (case-insensitive) needs binStart, anything else is Intel HEX.
    static LoadResult loadFile(const QString &path, std::optional<uint32_t> binStart, const Limits &limits);
    static LoadResult loadFile(const QString &path, std::optional<uint32_t> binStart = std::nullopt)
    {
        return loadFile(path, binStart, Limits{});
    }
};

} // namespace imudesk::protocol::ihex
