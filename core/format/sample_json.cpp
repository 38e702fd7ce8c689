#include "sample_json.h"

#include <array>
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

template <typename T, size_t N> void array(std::string &out, const char *k, const std::array<T, N> &v)
{
    key(out, k);
    out += '[';
    for (size_t i = 0; i < N; ++i) {
        if (i)
            out += ',';
        out += number(double(v[i]));
    }
    out += ']';
}

// The HI83 fields no other frame has (model::Hi83Extra), under the manual's names.
void hi83Extra(std::string &out, const model::Hi83Extra &x)
{
    if (x.has(6)) {
        char date[16];
        std::snprintf(date, sizeof date, "%04u-%02u-%02u", unsigned(x.utcDate[0]), unsigned(x.utcDate[1]),
                      unsigned(x.utcDate[2]));
        key(out, "utc_date");
        out += '"';
        out += date;
        out += '"';
    }
    if (x.has(11))
        array(out, "heave_surge_sway_frq", x.hssFreqHz);
    if (x.has(13))
        array(out, "acc_enu", x.accEnu);
    if (x.has(15)) {
        key(out, "solq_heading");
        out += std::to_string(x.solqHeading);
        key(out, "nv_heading");
        out += std::to_string(x.nvHeading);
    }
    if (x.has(16)) {
        key(out, "od_speed");
        out += number(x.odSpeedMs);
    }
    if (x.has(17)) {
        key(out, "undulation");
        out += number(x.undulationM);
    }
    if (x.has(18)) {
        key(out, "diff_age");
        out += number(x.diffAgeS);
    }
    if (x.has(19)) {
        key(out, "node_id");
        out += std::to_string(x.nodeId);
    }
    if (x.has(25))
        array(out, "event_counter", x.eventCounter);
    if (x.has(26))
        array(out, "kf_acc_bias", x.kfAccBias);
    if (x.has(27))
        array(out, "kf_gyr_bias", x.kfGyrBias);
    if (x.has(28))
        array(out, "gnss_std", x.gnssStd);
    if (x.has(29))
        array(out, "gnss_heading_info", x.dualHeading);
    if (x.has(30))
        array(out, "gnss_lon_lat_msl", x.gnssLonLatMsl);
    if (x.has(31))
        array(out, "gnss_vel", x.gnssVelEnu);
}

} // namespace

std::string sampleToJson(const model::Sample &s, model::WorldFrame worldFrame)
{
    using namespace model;
    std::string out;
    out.reserve(400);
    out += "{\"type\":\"" + s.source + '"';
    // The three times (issue 36): the device's own (system_time below), the arrival and the
    // common time on the host clock (ns), with the common time's half-width for polled devices.
    if (s.hostTimeNs != 0) {
        key(out, "host_time_ns");
        out += std::to_string(s.hostTimeNs);
    }
    if (s.commonTimeNs != 0) {
        key(out, "common_time_ns");
        out += std::to_string(s.commonTimeNs);
    }
    if (s.commonUncertaintyNs != 0) {
        key(out, "common_uncertainty_ns");
        out += std::to_string(s.commonUncertaintyNs);
    }
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
    if (worldFrame != WorldFrame::Enu && (s.has(FieldEuler) || s.has(FieldQuat))) {
        key(out, "world_frame");
        out += std::string("\"") + worldFrameName(worldFrame) + '"';
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
    if (s.has(FieldGnss)) {
        if (s.gnssQuality >= 0) {
            key(out, "gnss_quality");
            out += std::to_string(s.gnssQuality);
        }
        if (s.gnssSatellites >= 0) {
            key(out, "satellites");
            out += std::to_string(s.gnssSatellites);
        }
        if (s.utcTimeOfDayS >= 0) {
            key(out, "utc_time_s");
            out += number(s.utcTimeOfDayS);
        }
    }
    if (s.has(FieldHeading)) {
        key(out, s.headingTrue ? "heading_true" : "heading_magnetic");
        out += number(s.headingDeg);
    }
    if (s.has(FieldMagRelative))
        vec(out, "mag_relative", s.magRelative); // no unit: the horizontal northward field is 1
    if (s.has(FieldMagRoll)) {
        key(out, "mag_roll");
        out += number(s.magRollDeg);
    }
    if (s.has(FieldHi83Extra) && s.hi83)
        hi83Extra(out, *s.hi83);
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
