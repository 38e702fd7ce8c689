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

int baudFromCode(uint32_t code) { return j1939::baudFromCode(code); }
int codeFromBaud(int bitrate) { return j1939::codeFromBaud(bitrate); }

} // namespace imudesk::protocol::can::canopen::hipnuc
