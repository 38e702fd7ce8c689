#include "sample_json.h"

#include <cmath>
#include <cstdio>

namespace imudesk::format {

std::string number(double v)
{
    if (!std::isfinite(v))
        return "null"; // JSON has no NaN/Inf
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

namespace {

void key(std::string &out, const char *k)
{
    out += ",\"";
    out += k;
    out += "\":";
}

void vec(std::string &out, const char *k, const model::Vec3 &v)
{
    key(out, k);
    out += '[' + number(v.x) + ',' + number(v.y) + ',' + number(v.z) + ']';
}

} // namespace

std::string sampleToJson(const model::Sample &s)
{
    using namespace model;
    std::string out;
    out.reserve(400);
    out += "{\"type\":\"" + s.source + '"';
    if (s.has(FieldMainStatus)) {
        key(out, "main_status");
        out += std::to_string(s.mainStatus);
    }
    if (s.has(FieldInsStatus)) {
        key(out, "ins_status");
        out += std::to_string(s.insStatus);
    }
    if (s.has(FieldTemperature)) {
        key(out, "temperature");
        out += number(s.temperatureC);
    }
    if (s.has(FieldPressure)) {
        key(out, "pressure");
        out += number(s.pressurePa);
    }
    if (s.has(FieldDeviceTime)) {
        key(out, "system_time");
        out += number(s.deviceTimeMs);
    }
    if (s.has(FieldAcc))
        vec(out, "acc", s.acc);
    if (s.has(FieldGyr))
        vec(out, "gyr", s.gyr);
    if (s.has(FieldMag))
        vec(out, "mag", s.mag);
    if (s.has(FieldEuler)) {
        key(out, "roll");
        out += number(s.roll);
        key(out, "pitch");
        out += number(s.pitch);
        key(out, "yaw");
        out += number(s.yaw);
    }
    if (s.has(FieldQuat)) {
        key(out, "quat");
        out += '[' + number(s.quat.w) + ',' + number(s.quat.x) + ',' + number(s.quat.y) + ',' + number(s.quat.z) + ']';
    }
    if (s.has(FieldPosition)) {
        key(out, "lat");
        out += number(s.latitudeDeg);
        key(out, "lon");
        out += number(s.longitudeDeg);
        key(out, "alt");
        out += number(s.altitudeM);
    }
    if (s.has(FieldVelocity))
        vec(out, "vel_enu", s.velEnu);
    if (s.has(FieldHeave))
        vec(out, "heave_surge_sway", s.heaveSurgeSway);
    if (s.has(FieldInclination)) {
        key(out, "inclination");
        out += '[' + number(s.inclinationX) + ',' + number(s.inclinationY) + ']';
    }
    out += '}';
    return out;
}

std::string summaryToJson(const protocol::hipnuc::FrameDecoder::Counters &c, uint64_t nmeaSentences,
                          uint64_t payloadErrors, double seconds)
{
    std::string frames = "{";
    bool first = true;
    for (int tag = 0; tag < 256; ++tag) {
        if (!c.perTag[size_t(tag)])
            continue;
        char name[16];
        std::snprintf(name, sizeof name, "\"HI%02X\":", tag);
        if (!first)
            frames += ',';
        frames += name + std::to_string(c.perTag[size_t(tag)]);
        first = false;
    }
    if (nmeaSentences) {
        if (!first)
            frames += ',';
        frames += "\"NMEA\":" + std::to_string(nmeaSentences);
    }
    frames += '}';
    const double mbps = seconds > 0 ? double(c.bytesIn) / 1e6 / seconds : 0.0;
    return "{\"summary\": {\"frames\": " + frames + ", \"crc_errors\": " + std::to_string(c.crcErrors)
        + ", \"length_errors\": " + std::to_string(c.lengthErrors) + ", \"bytes_skipped\": "
        + std::to_string(c.bytesSkipped) + ", \"payload_errors\": " + std::to_string(payloadErrors)
        + ", \"bytes\": " + std::to_string(c.bytesIn) + ", \"seconds\": " + number(seconds)
        + ", \"mb_per_s\": " + number(mbps) + "}}";
}

} // namespace imudesk::format
