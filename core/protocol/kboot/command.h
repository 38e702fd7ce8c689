#pragma once
// KBOOT command and response payloads (hipnuc-protocol-notes.md 3.1, 3.2):
// tag, flags, reserved, parameter count, then that many u32 little-endian parameters.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace imudesk::protocol::kboot {

enum class CommandTag : uint8_t {
    FlashEraseAll = 0x01,
    FlashEraseRegion = 0x02,
    ReadMemory = 0x03,
    WriteMemory = 0x04,
    FillMemory = 0x05,
    FlashSecurityDisable = 0x06,
    GetProperty = 0x07,
    ReceiveSbFile = 0x08,
    Execute = 0x09,
    Call = 0x0A,
    Reset = 0x0B,
    SetProperty = 0x0C,
    FlashEraseAllUnsecure = 0x0D,
    FlashProgramOnce = 0x0E,
    FlashReadOnce = 0x0F,
    FlashReadResource = 0x10,
    ConfigureQuadSpi = 0x11,
    GenericResponse = 0xA0,
    ReadMemoryResponse = 0xA3,
    GetPropertyResponse = 0xA7,
};

enum class PropertyTag : uint32_t {
    CurrentVersion = 0x01,
    FlashStartAddress = 0x03,
    FlashSizeInBytes = 0x04,
    FlashSectorSize = 0x05,
    MaxPacketSize = 0x0B,
    BootloaderVersion = 0x10, // SystemDeviceId in NXP numbering; HiPNUC's "bootloader version"
    AppVersion = 0x39,        // non-standard, OLD HiPNUC host only
};

// At most this many parameters are accepted in a payload (KBOOT commands use up to 7).
inline constexpr size_t kMaxParams = 32;

struct Command {
    uint8_t tag = 0;
    uint8_t flags = 0;     // bit 0: a data phase follows (KBOOT "has data phase")
    std::vector<uint32_t> params;

    std::vector<uint8_t> encode() const;
    // Nullopt when the payload is shorter than 4 bytes, the count exceeds kMaxParams or
    // the payload does not hold exactly paramCount words.
    static std::optional<Command> decode(const std::vector<uint8_t> &payload);
    friend bool operator==(const Command &, const Command &) = default;
};

// Host commands.
Command getProperty(PropertyTag property, bool withMemoryId = false);
Command flashEraseRegion(uint32_t address, uint32_t length);
Command writeMemory(uint32_t address, uint32_t length);
Command readMemory(uint32_t address, uint32_t length);
Command reset();

// Device responses.
Command genericResponse(uint32_t status, uint8_t commandTag);
Command getPropertyResponse(uint32_t status, const std::vector<uint32_t> &values);
Command readMemoryResponse(uint32_t status, uint32_t byteCount);

} // namespace imudesk::protocol::kboot
