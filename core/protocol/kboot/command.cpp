#include "command.h"

namespace imudesk::protocol::kboot {

std::vector<uint8_t> Command::encode() const
{
    std::vector<uint8_t> b{tag, flags, 0, uint8_t(params.size())};
    b.reserve(4 + 4 * params.size());
    for (uint32_t p : params)
        for (int i = 0; i < 4; ++i)
            b.push_back(uint8_t(p >> (8 * i)));
    return b;
}

std::optional<Command> Command::decode(const std::vector<uint8_t> &payload)
{
    if (payload.size() < 4)
        return std::nullopt;
    const size_t count = payload[3];
    if (count > kMaxParams || payload.size() != 4 + 4 * count)
        return std::nullopt;
    Command c;
    c.tag = payload[0];
    c.flags = payload[1];
    c.params.resize(count);
    for (size_t i = 0; i < count; ++i) {
        const uint8_t *p = payload.data() + 4 + 4 * i;
        c.params[i] = uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
    }
    return c;
}

Command getProperty(PropertyTag property, bool withMemoryId)
{
    Command c{uint8_t(CommandTag::GetProperty), 0, {uint32_t(property)}};
    if (withMemoryId)
        c.params.push_back(0);
    return c;
}

Command flashEraseRegion(uint32_t address, uint32_t length)
{
    return Command{uint8_t(CommandTag::FlashEraseRegion), 0, {address, length}};
}

Command writeMemory(uint32_t address, uint32_t length)
{
    // NXP blhost sets flag bit 0 (data phase); the HiPNUC hosts send 0 (notes 3.5), so do we.
    return Command{uint8_t(CommandTag::WriteMemory), 0, {address, length}};
}

Command readMemory(uint32_t address, uint32_t length)
{
    return Command{uint8_t(CommandTag::ReadMemory), 0, {address, length}};
}

Command reset()
{
    return Command{uint8_t(CommandTag::Reset), 0, {}};
}

Command genericResponse(uint32_t status, uint8_t commandTag)
{
    return Command{uint8_t(CommandTag::GenericResponse), 0, {status, commandTag}};
}

Command getPropertyResponse(uint32_t status, const std::vector<uint32_t> &values)
{
    Command c{uint8_t(CommandTag::GetPropertyResponse), 0, {status}};
    c.params.insert(c.params.end(), values.begin(), values.end());
    return c;
}

Command readMemoryResponse(uint32_t status, uint32_t byteCount)
{
    return Command{uint8_t(CommandTag::ReadMemoryResponse), 1, {status, byteCount}};
}

} // namespace imudesk::protocol::kboot
