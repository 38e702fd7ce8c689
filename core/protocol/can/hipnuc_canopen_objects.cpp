#include "hipnuc_canopen_objects.h"
#include "canopen.h"
#include "j1939_config.h"
#include "sdo.h"

namespace imudesk::protocol::can::canopen::hipnuc {

uint16_t nodeIdObject(int major, int minor, int patch)
{
    (void)patch;
    return (major > 1 || (major == 1 && minor >= 7)) ? ObjNodeId : ObjNodeIdV166;
}

bool isNodeIdObject(uint16_t index)
{
    return index == ObjNodeId || index == ObjNodeIdV166;
}

CanFrame readRevision(uint8_t node) { return sdoRead(node, ObjIdentity, kSubRevision); }

std::optional<uint16_t> nodeIdObjectOfRevision(uint32_t revision)
{
    if (revision == 0)
        return std::nullopt;
    return nodeIdObject(int(revision >> 16), int((revision >> 8) & 0xFF), int(revision & 0xFF));
}

bool isV166Revision(uint32_t revision)
{
    return revision != 0 && nodeIdObjectOfRevision(revision) == ObjNodeIdV166;
}

CanFrame retarget(const CanFrame &sdoRequest, uint16_t index)
{
    CanFrame f = sdoRequest;
    f.data[1] = uint8_t(index & 0xFF); // CiA 301: the index follows the command byte, low byte first
    f.data[2] = uint8_t(index >> 8);
    return f;
}

CanFrame setNodeId(uint8_t node, uint8_t newId, uint16_t object) { return sdoWrite(node, object, 0, newId, 4); }
CanFrame command(uint8_t node, CommandValue v) { return sdoWrite(node, ObjCommand, 0, v, 4); }
CanFrame setBaud(uint8_t node, uint8_t code) { return sdoWrite(node, ObjBaud, 0, code, 4); }
CanFrame setTpdoPeriod(uint8_t node, int channel, uint16_t ms)
{
    return sdoWrite(node, tpdoCommIndex(channel), kSubEventTimer, ms, 2);
}
CanFrame setTransmissionType(uint8_t node, int channel, uint8_t type)
{
    return sdoWrite(node, tpdoCommIndex(channel), kSubTransmissionType, type, 1);
}
CanFrame setHeartbeat(uint8_t node, uint16_t ms) { return sdoWrite(node, ObjHeartbeat, 0, ms, 2); }
CanFrame setInclZero(uint8_t node, uint8_t mode) { return sdoWrite(node, ObjInclZero, 0, mode, 4); }
CanFrame setInclSign(uint8_t node, bool yAxis, bool reversed)
{
    return sdoWrite(node, yAxis ? ObjInclSignY : ObjInclSignX, 0, reversed ? 1 : 0, 4);
}

// v1.7.1 8.28.44.23 lists four codes for 0x209A: 0 = 1000K, 2 = 500K, 3 = 250K, 4 = 125K. The
// J1939 register 0x9A's 1 = 800K (7.23) is not among them, so it is neither sent nor read as 800K.
int baudFromCode(uint32_t code)
{
    return code == 1 ? 0 : j1939::baudFromCode(code);
}

int codeFromBaud(int bitrate)
{
    const int code = j1939::codeFromBaud(bitrate);
    return code == 1 ? -1 : code;
}

} // namespace imudesk::protocol::can::canopen::hipnuc
