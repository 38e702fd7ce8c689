#include "identity_block.h"

#include <cstdio>

namespace imudesk::protocol::modbus {

std::optional<IdentityBlock> IdentityBlock::decode(const RegisterBlock &block)
{
    const auto name = block.ascii(reg::kIdentityStart, 8);
    const auto sw = block.u16(reg::kSwVersion);
    const auto bl = block.u16(reg::kBlVersion);
    const auto sn = block.hex(reg::kSerial, 4);
    if (!name || !sw || !bl || !sn)
        return std::nullopt;
    IdentityBlock id;
    id.productName = *name;
    id.swVersion = *sw;
    id.blVersion = *bl;
    id.serial = *sn;
    return id;
}

std::vector<uint16_t> IdentityBlock::encode() const
{
    std::vector<uint16_t> regs(reg::kIdentityCount, 0);
    const auto name = RegisterBlock::wordsAscii(productName, 8);
    std::copy(name.begin(), name.end(), regs.begin());
    regs[reg::kSwVersion - reg::kIdentityStart] = swVersion;
    regs[reg::kBlVersion - reg::kIdentityStart] = blVersion;
    for (size_t i = 0; i < 4; ++i) {
        uint16_t w = 0;
        for (size_t k = i * 4; k < i * 4 + 4 && k < serial.size(); ++k) {
            const char c = serial[k];
            const int d = (c >= '0' && c <= '9') ? c - '0'
                : (c >= 'A' && c <= 'F')         ? c - 'A' + 10
                : (c >= 'a' && c <= 'f')         ? c - 'a' + 10
                                                 : 0;
            w = uint16_t((w << 4) | d);
        }
        regs[reg::kSerial - reg::kIdentityStart + i] = w;
    }
    return regs;
}

std::string IdentityBlock::versionText(uint16_t v)
{
    char buf[16];
    std::snprintf(buf, sizeof buf, "V%u.%02u", unsigned(v / 100), unsigned(v % 100));
    return buf;
}

std::optional<model::FirmwareVersion> IdentityBlock::version(uint16_t v)
{
    if (v == 0 || v > 999)
        return std::nullopt;
    return model::FirmwareVersion{v / 100, (v / 10) % 10, v % 10};
}

model::DeviceIdentity IdentityBlock::toDeviceIdentity() const
{
    model::DeviceIdentity id;
    id.productName = productName;
    id.serial = serial;
    id.firmware = version(swVersion);
    id.bootloader = version(blVersion);
    id.build = versionText(swVersion);
    return id;
}

} // namespace imudesk::protocol::modbus
