#include "j1939.h"

#include <algorithm>
#include <cmath>

namespace imudesk::protocol::can::j1939 {

using model::Sample;

Id parseId(uint32_t canId)
{
    Id id;
    id.priority = uint8_t((canId >> 26) & 0x7);
    id.edp = uint8_t((canId >> 25) & 0x1);
    id.dp = uint8_t((canId >> 24) & 0x1);
    id.pf = uint8_t((canId >> 16) & 0xFF);
    id.ps = uint8_t((canId >> 8) & 0xFF);
    id.sa = uint8_t(canId & 0xFF);
    return id;
}

uint32_t makeId(uint8_t priority, uint32_t pgn, uint8_t sa, uint8_t da)
{
    const uint8_t pf = uint8_t((pgn >> 8) & 0xFF);
    const uint8_t ps = pf < 0xF0 ? da : uint8_t(pgn & 0xFF);
    return (uint32_t(priority & 7) << 26) | (((pgn >> 16) & 0x3u) << 24) | (uint32_t(pf) << 16) | (uint32_t(ps) << 8) | sa;
}

const char *errorName(DecodeError e)
{
    switch (e) {
    case DecodeError::None: return "ok";
    case DecodeError::NotExtended: return "not an extended frame";
    case DecodeError::NotDataPgn: return "not a data PGN";
    case DecodeError::TooShort: return "data too short for the PGN";
    case DecodeError::RemoteFrame: return "remote frame";
    }
    return "?";
}

const std::vector<uint32_t> &dataPgns()
{
    static const std::vector<uint32_t> pgns = {PgnTime, PgnAcc, PgnGyr, PgnRollPitch, PgnHeading,
                                               PgnMag,  PgnQuat, PgnIncl, PgnCanFd0};
    return pgns;
}

bool isDataPgn(uint32_t pgn)
{
    const auto &p = dataPgns();
    return std::find(p.begin(), p.end(), pgn) != p.end();
}

int minimumLength(uint32_t pgn)
{
    switch (pgn) {
    case PgnAcc:
    case PgnGyr:
    case PgnMag: return 6;
    case PgnHeading: return 4;
    case PgnCanFd0: return 64;
    default: return 8;
    }
}

const char *pgnName(uint32_t pgn)
{
    switch (pgn) {
    case PgnTime: return "time";
    case PgnAcc: return "acc";
    case PgnGyr: return "gyr";
    case PgnMag: return "mag";
    case PgnRollPitch: return "roll/pitch";
    case PgnHeading: return "heading";
    case PgnQuat: return "quaternion";
    case PgnIncl: return "inclinometer";
    case PgnCanFd0: return "CAN FD IMU";
    case PgnConfig: return "configuration";
    default: return nullptr;
    }
}

namespace {

model::Vec3 vec16(const CanFrame &f, size_t at, double scale)
{
    return {i16At(f, at) * scale, i16At(f, at + 2) * scale, i16At(f, at + 4) * scale};
}

void putVec16(CanFrame &f, size_t at, const model::Vec3 &v, double scale)
{
    putU16(f, at, uint16_t(toI16(v.x, scale)));
    putU16(f, at + 2, uint16_t(toI16(v.y, scale)));
    putU16(f, at + 4, uint16_t(toI16(v.z, scale)));
}

// Euler yaw (+-180, counter-clockwise) from a 0..360 clockwise heading, and back.
double yawFromHeading(double headingCw)
{
    double y = -headingCw;
    while (y <= -180.0)
        y += 360.0;
    while (y > 180.0)
        y -= 360.0;
    return y;
}

double headingFromYaw(double yaw)
{
    double h = std::fmod(-yaw, 360.0);
    if (h < 0)
        h += 360.0;
    return h;
}

} // namespace

DecodeResult decodeData(const CanFrame &f)
{
    DecodeResult r;
    if (!f.extended) {
        r.error = DecodeError::NotExtended;
        return r;
    }
    const Id id = parseId(f.id);
    const uint32_t pgn = id.pgn();
    if (!isDataPgn(pgn)) {
        r.error = DecodeError::NotDataPgn;
        return r;
    }
    if (f.remote) {
        r.error = DecodeError::RemoteFrame;
        return r;
    }
    if (f.len < minimumLength(pgn)) {
        r.error = DecodeError::TooShort;
        return r;
    }
    DataFrame &d = r.data;
    d.pgn = pgn;
    d.sourceAddress = id.sa;
    Sample &s = d.sample;
    s.source = "J1939";
    switch (pgn) {
    case PgnTime: {
        UtcTime t;
        t.year = 2000 + f.at(0);
        t.month = f.at(1);
        t.day = f.at(2);
        t.hour = f.at(3);
        t.minute = f.at(4);
        t.second = f.at(5);
        t.ms = u16At(f, 6);
        d.time = t;
        break;
    }
    case PgnAcc:
        s.acc = vec16(f, 0, kAccScale);
        s.fields |= model::FieldAcc;
        break;
    case PgnGyr:
        s.gyr = vec16(f, 0, kGyrScale);
        s.fields |= model::FieldGyr;
        break;
    case PgnMag:
        s.mag = vec16(f, 0, kMagScale);
        s.fields |= model::FieldMag;
        break;
    case PgnRollPitch:
        s.roll = i32At(f, 0) * kAngleScale;
        s.pitch = i32At(f, 4) * kAngleScale;
        s.fields |= model::FieldEuler;
        break;
    case PgnHeading:
        d.headingCwDeg = u32At(f, 0) * kAngleScale;
        // v1.7.1 adds the +-180 CCW form in bytes 4..7; v1.6.6 leaves them reserved, so the
        // Euler yaw is derived from the heading, which both firmware versions send.
        d.hasYawPm180 = f.len >= 8;
        s.yaw = yawFromHeading(d.headingCwDeg);
        s.fields |= model::FieldEuler;
        break;
    case PgnQuat:
        s.quat = {i16At(f, 0) * kQuatScale, i16At(f, 2) * kQuatScale, i16At(f, 4) * kQuatScale, i16At(f, 6) * kQuatScale};
        s.fields |= model::FieldQuat;
        break;
    case PgnIncl:
        s.inclinationX = i32At(f, 0) * kAngleScale;
        s.inclinationY = i32At(f, 4) * kAngleScale;
        s.fields |= model::FieldInclination;
        break;
    case PgnCanFd0:
        s.mainStatus = u16At(f, 0);
        s.deviceTimeMs = u32At(f, 4);
        s.acc = vec16(f, 8, kAccScale);
        s.gyr = vec16(f, 14, kGyrScale);
        s.mag = vec16(f, 20, kMagScale);
        s.roll = i32At(f, 26) * kAngleScale;
        s.pitch = i32At(f, 30) * kAngleScale;
        s.yaw = i32At(f, 34) * kAngleScale;
        s.quat = {i16At(f, 38) * kQuatScale, i16At(f, 40) * kQuatScale, i16At(f, 42) * kQuatScale, i16At(f, 44) * kQuatScale};
        s.temperatureC = i16At(f, 46) * kTempScale;
        s.fields |= model::FieldMainStatus | model::FieldDeviceTime | model::FieldAcc | model::FieldGyr | model::FieldMag
            | model::FieldEuler | model::FieldQuat | model::FieldTemperature;
        break;
    default: break;
    }
    return r;
}

CanFrame encodeTime(uint8_t sa, const UtcTime &t)
{
    CanFrame f;
    f.id = makeId(kDataPriority, PgnTime, sa);
    f.extended = true;
    f.len = 8;
    f.data[0] = uint8_t(std::clamp(t.year - 2000, 0, 255));
    f.data[1] = uint8_t(t.month);
    f.data[2] = uint8_t(t.day);
    f.data[3] = uint8_t(t.hour);
    f.data[4] = uint8_t(t.minute);
    f.data[5] = uint8_t(t.second);
    putU16(f, 6, uint16_t(t.ms));
    return f;
}

CanFrame encodeData(uint32_t pgn, uint8_t sa, const Sample &s, bool withYawPm180)
{
    CanFrame f;
    f.id = makeId(kDataPriority, pgn, sa);
    f.extended = true;
    f.len = 8;
    switch (pgn) {
    case PgnAcc: putVec16(f, 0, s.acc, kAccScale); break;
    case PgnGyr: putVec16(f, 0, s.gyr, kGyrScale); break;
    case PgnMag: putVec16(f, 0, s.mag, kMagScale); break;
    case PgnRollPitch:
        putU32(f, 0, uint32_t(toI32(s.roll, kAngleScale)));
        putU32(f, 4, uint32_t(toI32(s.pitch, kAngleScale)));
        break;
    case PgnHeading:
        putU32(f, 0, uint32_t(toI32(headingFromYaw(s.yaw), kAngleScale)));
        if (withYawPm180)
            putU32(f, 4, uint32_t(toI32(s.yaw, kAngleScale)));
        break;
    case PgnQuat:
        putU16(f, 0, uint16_t(toI16(s.quat.w, kQuatScale)));
        putU16(f, 2, uint16_t(toI16(s.quat.x, kQuatScale)));
        putU16(f, 4, uint16_t(toI16(s.quat.y, kQuatScale)));
        putU16(f, 6, uint16_t(toI16(s.quat.z, kQuatScale)));
        break;
    case PgnIncl:
        putU32(f, 0, uint32_t(toI32(s.inclinationX, kAngleScale)));
        putU32(f, 4, uint32_t(toI32(s.inclinationY, kAngleScale)));
        break;
    case PgnCanFd0:
        f.fd = true;
        f.len = 64;
        putU16(f, 0, s.mainStatus);
        putU32(f, 4, uint32_t(s.deviceTimeMs));
        putVec16(f, 8, s.acc, kAccScale);
        putVec16(f, 14, s.gyr, kGyrScale);
        putVec16(f, 20, s.mag, kMagScale);
        putU32(f, 26, uint32_t(toI32(s.roll, kAngleScale)));
        putU32(f, 30, uint32_t(toI32(s.pitch, kAngleScale)));
        putU32(f, 34, uint32_t(toI32(s.yaw, kAngleScale)));
        putU16(f, 38, uint16_t(toI16(s.quat.w, kQuatScale)));
        putU16(f, 40, uint16_t(toI16(s.quat.x, kQuatScale)));
        putU16(f, 42, uint16_t(toI16(s.quat.y, kQuatScale)));
        putU16(f, 44, uint16_t(toI16(s.quat.z, kQuatScale)));
        putU16(f, 46, uint16_t(toI16(s.temperatureC, kTempScale)));
        break;
    default: f.len = 0; break;
    }
    return f;
}

} // namespace imudesk::protocol::can::j1939
