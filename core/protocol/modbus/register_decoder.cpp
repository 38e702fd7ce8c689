#include "register_decoder.h"

#include "model/attitude.h"

namespace imudesk::protocol::modbus {

namespace {

std::optional<model::Vec3> vec(const RegisterBlock &b, uint16_t first, double scale)
{
    const auto x = b.i16(first), y = b.i16(uint16_t(first + 1)), z = b.i16(uint16_t(first + 2));
    if (!x || !y || !z)
        return std::nullopt;
    return model::Vec3{*x * scale, *y * scale, *z * scale};
}

double scaleOf(uint16_t address)
{
    const RegisterDef *d = RegisterMap::hipnucAll().find(address);
    return d ? d->scale : 1.0;
}

} // namespace

model::Sample RegisterDecoder::hipnucSample(const RegisterBlock &b)
{
    model::Sample s;
    s.source = kHipnucSource;
    if (auto v = vec(b, 0x34, scaleOf(0x34))) {
        s.acc = *v;
        s.fields |= model::FieldAcc;
    }
    if (auto v = vec(b, 0x37, scaleOf(0x37))) {
        s.gyr = *v;
        s.fields |= model::FieldGyr;
    }
    if (auto v = vec(b, 0x3A, scaleOf(0x3A))) {
        s.mag = *v;
        s.fields |= model::FieldMag;
    }
    const auto roll = b.i32(0x3D), pitch = b.i32(0x3F), yaw = b.i32(0x41);
    if (roll && pitch && yaw) {
        const double k = scaleOf(0x3D);
        s.roll = *roll * k;
        s.pitch = *pitch * k;
        s.yaw = *yaw * k;
        s.fields |= model::FieldEuler;
    }
    if (auto t = b.i16(reg::kTemp)) {
        s.temperatureC = *t * scaleOf(reg::kTemp);
        s.fields |= model::FieldTemperature;
    }
    if (auto p = b.i32(0x44)) {
        s.pressurePa = *p * scaleOf(0x44);
        s.fields |= model::FieldPressure;
    }
    const auto q0 = b.i16(0x46), q1 = b.i16(0x47), q2 = b.i16(0x48), q3 = b.i16(0x49);
    if (q0 && q1 && q2 && q3) {
        const double k = scaleOf(0x46);
        s.quat = {*q0 * k, *q1 * k, *q2 * k, *q3 * k};
        s.fields |= model::FieldQuat;
    }
    const auto ix = b.i16(0x4A), iy = b.i16(0x4B);
    if (ix && iy) {
        s.inclinationX = *ix * scaleOf(0x4A);
        s.inclinationY = *iy * scaleOf(0x4B);
        s.fields |= model::FieldInclination;
    }
    if (auto h = b.i16(reg::kHeave)) {
        s.heaveSurgeSway = {*h * scaleOf(reg::kHeave), 0, 0};
        s.fields |= model::FieldHeave;
    }
    return s;
}

model::Sample RegisterDecoder::hec495Sample(const RegisterBlock &b)
{
    model::Sample s;
    s.source = kHec495Source;
    const auto pitch = b.f32le(0x04), roll = b.f32le(0x06), heading = b.f32le(0x08);
    if (pitch && roll && heading) {
        s.pitch = *pitch;
        s.roll = *roll;
        model::setCompassHeading(s, *heading, false); // one convention for every device and link
        s.fields |= model::FieldEuler;
    }
    return s;
}

model::Sample RegisterDecoder::sample(DeviceKind kind, const RegisterBlock &block)
{
    return kind == DeviceKind::Hec495 ? hec495Sample(block) : hipnucSample(block);
}

} // namespace imudesk::protocol::modbus
