#pragma once
// The HiPNUC identity registers 0x70..0x82 (v1.7.1 6.18, v1.6.6 4.4): PNAME (8 registers of
// ASCII), SW_VERSION (0x78), BL_VERSION (0x79), SN (0x7F..0x82). A version register holds the
// version times 100 (0x98 = 152 = "V1.52"); as a FirmwareVersion its digits are read as
// major.minor.patch (152 -> 1.5.2, 171 -> 1.7.1), the form the serial path uses.
#include "model/device_identity.h"
#include "register_block.h"

#include <cstdint>
#include <optional>
#include <string>

namespace imudesk::protocol::modbus {

class IdentityBlock {
public:
    std::string productName;
    uint16_t swVersion = 0;
    uint16_t blVersion = 0;
    std::string serial; // 16 hex digits

    // nullopt when the block lacks 0x70..0x82.
    static std::optional<IdentityBlock> decode(const RegisterBlock &block);
    // Registers 0x70..0x83 (kIdentityCount) for this identity.
    std::vector<uint16_t> encode() const;

    static std::string versionText(uint16_t v); // "V1.52"
    static std::optional<model::FirmwareVersion> version(uint16_t v);
    model::DeviceIdentity toDeviceIdentity() const;
};

} // namespace imudesk::protocol::modbus
