#include "all_data_record.h"
#include "model/attitude.h"

#include <cstring>

namespace imudesk::protocol::witlink {

namespace {

uint32_t u32le(const uint8_t *p)
{
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

float f32le(const uint8_t *p)
{
    const uint32_t u = u32le(p);
    float f;
    std::memcpy(&f, &u, sizeof f);
    return f;
}

void putU32(std::vector<uint8_t> &out, uint32_t u)
{
    for (int i = 0; i < 4; ++i)
        out.push_back(uint8_t(u >> (8 * i)));
}

void putF32(std::vector<uint8_t> &out, float f)
{
    uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    putU32(out, u);
}

} // namespace

std::optional<AllDataRecord> AllDataRecord::decode(const uint8_t *p, size_t n)
{
    if (n != kSize)
        return std::nullopt;
    AllDataRecord r;
    size_t at = 0;
    auto next = [&] {
        const float f = f32le(p + at);
        at += 4;
        return f;
    };
    r.pitch = next();
    r.roll = next();
    r.heading = next();
    for (auto *v : {&r.acc, &r.mag, &r.gyr})
        for (auto &x : *v)
            x = next();
    r.magRoll = next();
    for (auto &x : r.reserved)
        x = next();
    r.timeMs = u32le(p + at);
    return r;
}

std::vector<uint8_t> AllDataRecord::encode() const
{
    std::vector<uint8_t> out;
    out.reserve(kSize);
    putF32(out, pitch);
    putF32(out, roll);
    putF32(out, heading);
    for (const auto *v : {&acc, &mag, &gyr})
        for (float x : *v)
            putF32(out, x);
    putF32(out, magRoll);
    for (float x : reserved)
        putF32(out, x);
    putU32(out, timeMs);
    return out;
}

model::Sample AllDataRecord::toSample(int64_t hostTimeNs) const
{
    model::Sample s;
    s.source = "HEC495";
    s.hostTimeNs = hostTimeNs;
    s.fields = model::FieldEuler | model::FieldAcc | model::FieldGyr | model::FieldDeviceTime | model::FieldMagRelative
        | model::FieldMagRoll;
    s.pitch = pitch;
    s.roll = roll;
    model::setCompassHeading(s, heading, false); // yaw: ENU, counter-clockwise; heading as sent
    s.acc = {acc[0], acc[1], acc[2]};
    s.gyr = {gyr[0], gyr[1], gyr[2]};
    s.magRelative = {mag[0], mag[1], mag[2]};
    s.magRollDeg = magRoll;
    s.deviceTimeMs = timeMs;
    return s;
}

} // namespace imudesk::protocol::witlink
