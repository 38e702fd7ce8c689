#include "canopen.h"

namespace imudesk::protocol::can::canopen {

namespace {
struct Tpdo {
    uint32_t base;
    int number;
    int length;
    const char *content;
};
constexpr Tpdo kTpdos[kTpdoCount] = {
    {CobTpdo1, 1, 6, "acc"},        {CobTpdo2, 2, 6, "gyr"},      {CobTpdo3, 3, 6, "euler"},
    {CobTpdo4, 4, 8, "quaternion"}, {CobTpdo6, 6, 4, "pressure"}, {CobTpdo7, 7, 8, "inclinometer"},
};
bool validChannel(int c) { return c >= 0 && c < kTpdoCount; }
} // namespace

uint32_t tpdoBase(int channel) { return validChannel(channel) ? kTpdos[channel].base : 0; }
int tpdoNumber(int channel) { return validChannel(channel) ? kTpdos[channel].number : 0; }
int tpdoLength(int channel) { return validChannel(channel) ? kTpdos[channel].length : 0; }
uint16_t tpdoCommIndex(int channel) { return uint16_t(0x1800 + channel); }
const char *tpdoContent(int channel) { return validChannel(channel) ? kTpdos[channel].content : ""; }

int tpdoChannelOfBase(uint32_t base)
{
    for (int c = 0; c < kTpdoCount; ++c)
        if (kTpdos[c].base == base)
            return c;
    return -1;
}

bool isStandardNodeId(int node) { return node >= 1 && node <= 127; }
uint8_t nodeOf(uint32_t cobId) { return uint8_t(cobId & 0x7F); }
uint32_t baseOf(uint32_t cobId) { return cobId & 0x780; }

TpdoResult decodeTpdo(const CanFrame &f)
{
    TpdoResult r;
    const int channel = f.id <= 0x7FF ? tpdoChannelOfBase(baseOf(f.id)) : -1;
    if (channel < 0 || !isStandardNodeId(nodeOf(f.id)))
        return r;
    if (f.extended) {
        r.error = TpdoError::Extended;
        return r;
    }
    if (f.remote) {
        r.error = TpdoError::Remote;
        return r;
    }
    if (f.len != tpdoLength(channel)) {
        r.error = TpdoError::WrongLength;
        return r;
    }
    r.error = TpdoError::None;
    r.channel = channel;
    r.node = nodeOf(f.id);
    model::Sample &s = r.sample;
    s.source = "CANopen";
    switch (channel) {
    case 0:
        s.acc = {i16At(f, 0) * kAccScale, i16At(f, 2) * kAccScale, i16At(f, 4) * kAccScale};
        s.fields |= model::FieldAcc;
        break;
    case 1:
        s.gyr = {i16At(f, 0) * kGyrScale, i16At(f, 2) * kGyrScale, i16At(f, 4) * kGyrScale};
        s.fields |= model::FieldGyr;
        break;
    case 2:
        s.roll = i16At(f, 0) * kEulerScale;
        s.pitch = i16At(f, 2) * kEulerScale;
        s.yaw = i16At(f, 4) * kEulerScale;
        s.fields |= model::FieldEuler;
        break;
    case 3:
        s.quat = {i16At(f, 0) * kQuatScale, i16At(f, 2) * kQuatScale, i16At(f, 4) * kQuatScale, i16At(f, 6) * kQuatScale};
        s.fields |= model::FieldQuat;
        break;
    case 4:
        s.pressurePa = i32At(f, 0);
        s.fields |= model::FieldPressure;
        break;
    case 5:
        s.inclinationX = i32At(f, 0) * kInclScale;
        s.inclinationY = i32At(f, 4) * kInclScale;
        s.fields |= model::FieldInclination;
        break;
    default: break;
    }
    return r;
}

CanFrame encodeTpdo(int channel, uint8_t node, const model::Sample &s)
{
    CanFrame f;
    if (!validChannel(channel))
        return f;
    f.id = tpdoBase(channel) + node;
    f.len = uint8_t(tpdoLength(channel));
    auto put3 = [&f](double a, double b, double c, double scale) {
        putU16(f, 0, uint16_t(toI16(a, scale)));
        putU16(f, 2, uint16_t(toI16(b, scale)));
        putU16(f, 4, uint16_t(toI16(c, scale)));
    };
    switch (channel) {
    case 0: put3(s.acc.x, s.acc.y, s.acc.z, kAccScale); break;
    case 1: put3(s.gyr.x, s.gyr.y, s.gyr.z, kGyrScale); break;
    case 2: put3(s.roll, s.pitch, s.yaw, kEulerScale); break;
    case 3:
        put3(s.quat.w, s.quat.x, s.quat.y, kQuatScale);
        putU16(f, 6, uint16_t(toI16(s.quat.z, kQuatScale)));
        break;
    case 4: putU32(f, 0, uint32_t(toI32(s.pressurePa, 1.0))); break;
    case 5:
        putU32(f, 0, uint32_t(toI32(s.inclinationX, kInclScale)));
        putU32(f, 4, uint32_t(toI32(s.inclinationY, kInclScale)));
        break;
    default: break;
    }
    return f;
}

CanFrame encodeNmt(NmtCommand cmd, uint8_t node)
{
    return CanFrame(CobNmt, false, {uint8_t(cmd), node});
}

std::optional<NmtMessage> parseNmt(const CanFrame &f)
{
    if (f.extended || f.fd || f.id != CobNmt || f.len != 2 || f.remote)
        return std::nullopt;
    return NmtMessage{f.data[0], f.data[1]};
}

CanFrame encodeSync()
{
    CanFrame f;
    f.id = CobSync;
    return f;
}

bool isSync(const CanFrame &f)
{
    return !f.extended && f.id == CobSync && !f.remote && f.len <= 1;
}

CanFrame encodeHeartbeat(uint8_t node, uint8_t state)
{
    return CanFrame(CobHeartbeat + node, false, {state});
}

std::optional<Heartbeat> parseHeartbeat(const CanFrame &f)
{
    if (f.extended || f.fd || f.remote || f.len != 1 || baseOf(f.id) != CobHeartbeat || f.id > 0x7FF || !isStandardNodeId(nodeOf(f.id)))
        return std::nullopt;
    return Heartbeat{nodeOf(f.id), f.data[0]};
}

const char *stateName(uint8_t state)
{
    switch (state) {
    case StateBootUp: return "boot-up";
    case StateStopped: return "stopped";
    case StateOperational: return "operational";
    case StatePreOperational: return "pre-operational";
    default: return "unknown";
    }
}

} // namespace imudesk::protocol::can::canopen
