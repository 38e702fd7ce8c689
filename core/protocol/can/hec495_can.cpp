#include "hec495_can.h"

#include "model/attitude.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace imudesk::protocol::can::hec495 {

namespace {
constexpr uint32_t kBases[kPdoCount] = {0x180, 0x280, 0x380, 0x480, 0x1C0, 0x2C0};
constexpr double kAngleDiv = 100.0;
constexpr double kAccDiv = 10000.0;
} // namespace

int baudFromCode(uint32_t code)
{
    switch (code) {
    case 1: return 500000;
    case 2: return 250000;
    case 3: return 125000;
    case 4: return 100000;
    case 5: return 50000;
    case 6: return 30000;
    case 7: return 20000;
    case 8: return 10000;
    default: return 0;
    }
}

int codeFromBaud(int bitrate)
{
    for (uint32_t c = 1; c <= 8; ++c)
        if (baudFromCode(c) == bitrate)
            return int(c);
    return -1;
}

double rateHzFromCode(uint32_t code)
{
    static constexpr double rates[] = {0, 5, 10, 20, 25, 50, 100};
    return code < 7 ? rates[code] : 0;
}

int heartbeatPeriodMs(uint32_t n)
{
    return 100 * (int(n & 0xFF) + 1);
}

std::optional<uint8_t> heartbeatCode(int ms)
{
    if (ms < kMinHeartbeatMs || ms > kMaxHeartbeatMs)
        return std::nullopt;
    return uint8_t((ms + 50) / 100 - 1);
}

uint32_t pdoBase(int slot)
{
    return slot >= 0 && slot < kPdoCount ? kBases[slot] : 0;
}

int pdoSlotOfId(uint32_t cobId)
{
    if (cobId > 0x7FF)
        return -1;
    // 0x1C0 + n and 0x2C0 + n (n = 1..63) lie inside 0x180 + 0x41..0x7F and 0x280 + 0x41..0x7F:
    // those two slots are looked for first, so a node above 63 reads as one of them.
    for (int s : {4, 5, 0, 1, 2, 3}) {
        const uint32_t base = kBases[s];
        const uint32_t span = (base & 0x40) ? 0x40 : 0x80;
        if (cobId > base && cobId < base + span)
            return s;
    }
    return -1;
}

double fixedValue(const uint8_t *b, double divisor)
{
    const double mag = double(uint16_t(b[0] | (b[1] << 8))) / divisor;
    return b[2] == 0x01 ? -mag : mag;
}

void putFixed(uint8_t *b, double value, double divisor)
{
    const double m = std::min(std::round(std::fabs(value) * divisor), 65535.0);
    const auto u = uint16_t(m);
    b[0] = uint8_t(u & 0xFF);
    b[1] = uint8_t(u >> 8);
    b[2] = (value < 0 && u != 0) ? 0x01 : 0x00;
}

bool looksFixed(const CanFrame &f)
{
    return f.len == 8 && f.data[6] == 0 && f.data[7] == 0 && f.data[2] <= 1 && f.data[5] <= 1;
}

namespace {
// Assigns value v to the quantity q (0 X angle / pitch, 1 Y angle / roll, 2 Z angle / heading,
// 3..5 acc, 6..8 gyr, 9..11 mag).
constexpr uint32_t kComp[12] = {CompPitch, CompRoll, CompYaw, CompAccX, CompAccY, CompAccZ,
                                CompGyrX,  CompGyrY, CompGyrZ, CompMagX, CompMagY, CompMagZ};
void assign(model::Sample &s, int q, double v)
{
    switch (q) {
    case 0: s.pitch = v; s.fields |= model::FieldEuler; break;
    case 1: s.roll = v; s.fields |= model::FieldEuler; break;
    case 2: model::setCompassHeading(s, v, false); s.fields |= model::FieldEuler; break;
    case 3: s.acc.x = v; s.fields |= model::FieldAcc; break;
    case 4: s.acc.y = v; s.fields |= model::FieldAcc; break;
    case 5: s.acc.z = v; s.fields |= model::FieldAcc; break;
    case 6: s.gyr.x = v; s.fields |= model::FieldGyr; break;
    case 7: s.gyr.y = v; s.fields |= model::FieldGyr; break;
    case 8: s.gyr.z = v; s.fields |= model::FieldGyr; break;
    // The field is relative on CAN as on serial (manual 2.5): not uT, so not Sample::mag.
    case 9: s.magRelative.x = v; s.fields |= model::FieldMagRelative; break;
    case 10: s.magRelative.y = v; s.fields |= model::FieldMagRelative; break;
    case 11: s.magRelative.z = v; s.fields |= model::FieldMagRelative; break;
    default: break;
    }
}
void assign(PdoResult &r, int q, double v)
{
    assign(r.sample, q, v);
    if (q >= 0 && q < 12)
        r.components |= kComp[q];
}
double pick(const model::Sample &s, int q)
{
    // The compass sends its heading (clockwise), ±180 as its serial record does.
    const double heading = s.has(model::FieldHeading) ? model::wrap180(s.headingDeg) : model::wrap180(-s.yaw);
    const double v[12] = {s.pitch, s.roll, heading, s.acc.x, s.acc.y, s.acc.z, s.gyr.x, s.gyr.y, s.gyr.z,
                          s.magRelative.x, s.magRelative.y, s.magRelative.z};
    return q >= 0 && q < 12 ? v[q] : 0;
}
// Quantities in the two halves of each slot.
constexpr int kFloatLayout[kPdoCount][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {8, 9}, {10, 11}};
constexpr int kFixedLayout[kPdoCount][2] = {{0, 3}, {1, 4}, {2, 5}, {6, 9}, {7, 10}, {8, 11}};
bool isAngleLike(int q) { return q <= 2 || (q >= 6 && q <= 8); }
} // namespace

std::optional<PdoResult> decodePdo(const CanFrame &f, int mode)
{
    if (f.extended || f.remote || f.len != 8)
        return std::nullopt;
    const int slot = pdoSlotOfId(f.id);
    if (slot < 0)
        return std::nullopt;
    PdoResult r;
    r.slot = slot;
    r.node = uint8_t(f.id - pdoBase(slot));
    r.fixed = mode < 0 ? looksFixed(f) : mode == ModeFixed;
    r.sample.source = "HEC495 CAN";
    if (r.fixed) {
        for (int h = 0; h < 2; ++h) {
            const int q = kFixedLayout[slot][h];
            assign(r, q, fixedValue(f.data.data() + 3 * h, isAngleLike(q) ? kAngleDiv : kAccDiv));
        }
    } else {
        for (int h = 0; h < 2; ++h)
            assign(r, kFloatLayout[slot][h], double(f32At(f, size_t(4 * h))));
    }
    return r;
}

std::optional<PdoResult> decodeExtended(const CanFrame &f)
{
    if (!f.extended || f.remote || f.len != 8 || (f.id != kExtDataXId && f.id != kExtDataYId))
        return std::nullopt;
    PdoResult r;
    const bool y = f.id == kExtDataYId;
    r.slot = y ? 1 : 0;
    r.fixed = true;
    r.extendedVariant = true;
    r.sample.source = "HEC495 CAN";
    assign(r, y ? 1 : 0, fixedValue(f.data.data(), kAngleDiv));
    assign(r, y ? 4 : 3, fixedValue(f.data.data() + 3, kAccDiv));
    return r;
}

CanFrame encodePdo(int slot, uint8_t node, const model::Sample &s, bool fixed)
{
    CanFrame f;
    f.id = pdoBase(slot) + node;
    f.len = 8;
    if (slot < 0 || slot >= kPdoCount)
        return f;
    if (fixed) {
        for (int h = 0; h < 2; ++h) {
            const int q = kFixedLayout[slot][h];
            putFixed(f.data.data() + 3 * h, pick(s, q), isAngleLike(q) ? kAngleDiv : kAccDiv);
        }
    } else {
        putF32(f, 0, float(pick(s, kFloatLayout[slot][0])));
        putF32(f, 4, float(pick(s, kFloatLayout[slot][1])));
    }
    return f;
}

CanFrame encodeExtended(bool yAxis, const model::Sample &s)
{
    CanFrame f;
    f.id = yAxis ? kExtDataYId : kExtDataXId;
    f.extended = true;
    f.len = 8;
    putFixed(f.data.data(), yAxis ? s.roll : s.pitch, kAngleDiv);
    putFixed(f.data.data() + 3, yAxis ? s.acc.y : s.acc.x, kAccDiv);
    return f;
}

CanFrame writeRequest(uint8_t node, uint16_t index, uint8_t value, bool extended)
{
    CanFrame f;
    f.id = extended ? kExtRequestId : 0x600u + node;
    f.extended = extended;
    f.len = 8;
    f.data[0] = 0x22;
    putU16(f, 1, index);
    f.data[4] = value;
    return f;
}

CanFrame writeReply(uint8_t node, uint16_t index, bool extended)
{
    CanFrame f;
    f.id = extended ? kExtReplyId : 0x580u + node;
    f.extended = extended;
    f.len = 8;
    f.data[0] = 0x60;
    putU16(f, 1, index);
    return f;
}

std::optional<WriteMessage> parseWrite(const CanFrame &f)
{
    if (f.remote || f.len != 8)
        return std::nullopt;
    WriteMessage m;
    if (f.extended) {
        if (f.id != kExtRequestId && f.id != kExtReplyId)
            return std::nullopt;
        m.extended = true;
        m.reply = f.id == kExtReplyId;
    } else {
        const uint32_t base = f.id & 0x780;
        if ((base != 0x600 && base != 0x580) || (f.id & 0x7F) == 0 || f.id > 0x7FF)
            return std::nullopt;
        m.reply = base == 0x580;
        m.node = uint8_t(f.id & 0x7F);
    }
    if ((m.reply && f.data[0] != 0x60) || (!m.reply && f.data[0] != 0x22))
        return std::nullopt;
    m.index = u16At(f, 1);
    m.sub = f.data[3];
    m.value = f.data[4];
    return m;
}

CanFrame startAll() { return CanFrame(0x000, false, {0x01, 0x00}); }
CanFrame stopAll() { return CanFrame(0x000, false, {0x02, 0x00}); }

QString describeObject(uint16_t index, uint8_t value)
{
    switch (index) {
    case ObjNodeId: return QCoreApplication::translate("HEC495", "node ID = %1").arg(value);
    case ObjBaud: return QCoreApplication::translate("HEC495", "CAN baud = %1 bit/s").arg(baudFromCode(value));
    case ObjPdoMode: return QCoreApplication::translate("HEC495", "PDO mode = %1").arg(value);
    case ObjHeartbeat: return QCoreApplication::translate("HEC495", "heartbeat = %1 ms").arg(heartbeatPeriodMs(value));
    case ObjPdoStart:
        return value ? QCoreApplication::translate("HEC495", "start PDO") : QCoreApplication::translate("HEC495", "stop PDO");
    case ObjPdoRate: return QCoreApplication::translate("HEC495", "PDO rate = %1 Hz").arg(rateHzFromCode(value));
    case ObjWorkMode: return QCoreApplication::translate("HEC495", "work mode = 0x%1").arg(value, 2, 16, QLatin1Char('0'));
    default:
        return QCoreApplication::translate("HEC495", "object 0x%1 = %2").arg(index, 4, 16, QLatin1Char('0')).arg(value);
    }
}

} // namespace imudesk::protocol::can::hec495
