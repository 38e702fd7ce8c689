#include "j1939_config.h"
#include "j1939.h"

#include <QCoreApplication>

namespace imudesk::protocol::can::j1939 {

uint16_t intervalRegister(uint32_t pgn)
{
    return uint16_t(0x0100 | (pgn & 0xFF));
}

std::optional<uint32_t> pgnOfIntervalRegister(uint16_t reg)
{
    if ((reg & 0xFF00) != 0x0100)
        return std::nullopt;
    const uint32_t pgn = 0xFF00u | (reg & 0xFFu);
    if (!isDataPgn(pgn))
        return std::nullopt;
    return pgn;
}

bool validInterval(uint32_t ms)
{
    return ms >= uint32_t(kMinIntervalMs) && ms <= uint32_t(kMaxIntervalMs);
}

int baudFromCode(uint32_t code)
{
    static constexpr int rates[] = {1000000, 800000, 500000, 250000, 125000};
    return code < 5 ? rates[code] : 0;
}

int codeFromBaud(int bitrate)
{
    for (uint32_t c = 0; c < 5; ++c)
        if (baudFromCode(c) == bitrate)
            return int(c);
    return -1;
}

CanFrame encodeReg(const RegMessage &m)
{
    CanFrame f;
    f.id = makeId(kDataPriority, PgnConfig, m.sa, m.da);
    f.extended = true;
    f.len = 8;
    putU16(f, 0, m.addr);
    f.data[2] = m.cmd;
    f.data[3] = m.status;
    putU32(f, 4, m.value);
    return f;
}

std::optional<RegMessage> parseReg(const CanFrame &f)
{
    if (!f.extended || f.remote || f.len != 8)
        return std::nullopt;
    const Id id = parseId(f.id);
    if (id.pgn() != PgnConfig)
        return std::nullopt;
    RegMessage m;
    m.da = id.ps;
    m.sa = id.sa;
    m.addr = u16At(f, 0);
    m.cmd = f.data[2];
    m.status = f.data[3];
    m.value = u32At(f, 4);
    return m;
}

RegMessage readRequest(uint8_t da, uint8_t sa, uint16_t addr)
{
    return RegMessage{da, sa, addr, CmdRead, 0, 1};
}

RegMessage writeRequest(uint8_t da, uint8_t sa, uint16_t addr, uint32_t value)
{
    return RegMessage{da, sa, addr, CmdWrite, 0, value};
}

RegMessage intervalRequest(uint8_t da, uint8_t sa, uint32_t pgn, uint32_t ms)
{
    return writeRequest(da, sa, intervalRegister(pgn), ms);
}

RegMessage triggerRequest(uint8_t da, uint8_t sa, uint32_t pgn)
{
    return writeRequest(da, sa, RegTrigger, pgn);
}

bool answers(const RegMessage &reply, const RegMessage &request)
{
    // A request to the broadcast address 255 is answered by every node, each from its own address.
    return (request.da == kBroadcast || reply.sa == request.da) && reply.da == request.sa && reply.addr == request.addr
        && reply.cmd == request.cmd;
}

QString describe(const RegMessage &m)
{
    const bool write = m.cmd == CmdWrite;
    QString what;
    if (const auto pgn = pgnOfIntervalRegister(m.addr)) {
        what = QCoreApplication::translate("J1939", "PGN %1 interval").arg(QString::number(*pgn, 16).toUpper());
        if (write)
            return QCoreApplication::translate("J1939", "write %1 = %2 ms").arg(what).arg(m.value);
    }
    switch (m.addr) {
    case RegCommand:
        if (write && m.value == CommandSave) return QCoreApplication::translate("J1939", "save configuration");
        if (write && m.value == CommandFactory) return QCoreApplication::translate("J1939", "factory defaults");
        if (write && m.value == CommandReset) return QCoreApplication::translate("J1939", "reset");
        what = QCoreApplication::translate("J1939", "command register");
        break;
    case RegTrigger:
        if (write)
            return QCoreApplication::translate("J1939", "trigger PGN %1").arg(QString::number(m.value, 16).toUpper());
        what = QCoreApplication::translate("J1939", "trigger");
        break;
    case RegBaud: what = QCoreApplication::translate("J1939", "CAN baud code"); break;
    case RegNodeId: what = QCoreApplication::translate("J1939", "node ID"); break;
    case RegOutputEnable: what = QCoreApplication::translate("J1939", "output enable"); break;
    case RegInclSignX: what = QCoreApplication::translate("J1939", "inclinometer X sign"); break;
    case RegInclSignY: what = QCoreApplication::translate("J1939", "inclinometer Y sign"); break;
    case RegAttitudeReset: what = QCoreApplication::translate("J1939", "attitude reset"); break;
    case RegVersion: what = QCoreApplication::translate("J1939", "firmware version"); break;
    default:
        if (what.isEmpty())
            what = QCoreApplication::translate("J1939", "register 0x%1").arg(m.addr, 4, 16, QLatin1Char('0'));
        break;
    }
    if (write)
        return QCoreApplication::translate("J1939", "write %1 = %2 (status %3)").arg(what).arg(m.value).arg(m.status);
    return QCoreApplication::translate("J1939", "read %1 -> %2 (status %3)").arg(what).arg(m.value).arg(m.status);
}

} // namespace imudesk::protocol::can::j1939
