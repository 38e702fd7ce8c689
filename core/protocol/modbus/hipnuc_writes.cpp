#include "hipnuc_writes.h"

#include "model/mounting.h"
#include "register_map.h"

namespace imudesk::protocol::modbus {

WriteRequest HipnucWrites::save()
{
    return {reg::kCtrl, 0x0000};
}

WriteRequest HipnucWrites::factoryReset()
{
    return {reg::kCtrl, 0x0001};
}

WriteRequest HipnucWrites::reset()
{
    return {reg::kCtrl, 0x00FF};
}

const std::vector<int> &HipnucWrites::bauds()
{
    static const std::vector<int> table = {4800, 9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600};
    return table;
}

std::optional<int> HipnucWrites::baudForCode(uint16_t code)
{
    if (code >= bauds().size())
        return std::nullopt;
    return bauds()[code];
}

std::optional<uint16_t> HipnucWrites::codeForBaud(int baud)
{
    for (size_t i = 0; i < bauds().size(); ++i)
        if (bauds()[i] == baud)
            return uint16_t(i);
    return std::nullopt;
}

std::optional<WriteRequest> HipnucWrites::baud(int baud)
{
    const auto code = codeForBaud(baud);
    if (!code)
        return std::nullopt;
    return WriteRequest{reg::kBaud, *code};
}

std::optional<WriteRequest> HipnucWrites::nodeId(int id)
{
    if (id < 1 || id > 128)
        return std::nullopt;
    return WriteRequest{reg::kNodeId, uint16_t(id)};
}

WriteRequest HipnucWrites::headingMode(bool nineAxis)
{
    return {reg::kHeadingMode, uint16_t(nineAxis ? 1 : 0)};
}

// v1.7.1 6.17.26 / v1.6.6 4.3.5 write 2 to level ("50 06 00 A5 00 02 15 A9"), while the register
// table (v1.7.1 6.16, v1.6.6 4.2) lists 3 = level once and 5 = cancel and calls other values
// invalid. The worked example's bytes are what the vendor's own tool is shown to send, so ImuDesk
// sends them; describe() and the register's description say so, and 3 is accepted as well.
WriteRequest HipnucWrites::autoLevel(bool on)
{
    return {reg::kAutoLevel, uint16_t(on ? 2 : 5)};
}

const std::vector<int> &HipnucWrites::legacyMountings()
{
    // v1.6.6 4.3.4 order; the v1.7.1 6.17.25 table gives the same five as codes.
    static const std::vector<int> codes = {24, 43, 52, 520, 421};
    return codes;
}

std::optional<WriteRequest> HipnucWrites::mounting(model::ManualEdition edition, int code)
{
    if (!model::Mounting::isValidCode(code))
        return std::nullopt;
    if (edition == model::ManualEdition::V171)
        return WriteRequest{reg::kUrfr, uint16_t(code)};
    const auto &legacy = legacyMountings();
    for (size_t i = 0; i < legacy.size(); ++i)
        if (legacy[i] == code)
            return WriteRequest{reg::kUrfr, uint16_t(i)};
    return std::nullopt;
}

std::optional<int> HipnucWrites::mountingCode(model::ManualEdition edition, uint16_t value)
{
    if (edition == model::ManualEdition::V171)
        return model::Mounting::isValidCode(value) ? std::optional<int>(value) : std::nullopt;
    if (value < legacyMountings().size())
        return legacyMountings()[value];
    return std::nullopt;
}

QString HipnucWrites::describe(const WriteRequest &w)
{
    switch (w.address) {
    case reg::kCtrl:
        if (w.value == 0)
            return tr("save the configuration to flash");
        if (w.value == 1)
            return tr("restore the factory settings");
        if (w.value == 0xFF)
            return tr("reset the module");
        break;
    case reg::kBaud:
        if (const auto b = baudForCode(w.value))
            return tr("set the baud rate to %1").arg(*b);
        break;
    case reg::kNodeId: return tr("set the node ID to %1").arg(w.value);
    case reg::kHeadingMode: return w.value ? tr("switch to 9-axis mode") : tr("switch to 6-axis mode");
    case reg::kAutoLevel:
        if (w.value == 5)
            return tr("cancel the levelling (value 5)");
        if (w.value == 2)
            return tr("level once (value 2, as the manual's worked example sends it; its register table lists 3)");
        if (w.value == 3)
            return tr("level once (value 3, as the manual's register table defines it)");
        break;
    case reg::kUrfr: return tr("set the mounting (URFR value %1)").arg(w.value);
    default: break;
    }
    return tr("write %1 to register 0x%2").arg(w.value).arg(w.address, 4, 16, QLatin1Char('0'));
}

} // namespace imudesk::protocol::modbus
