#include "payloads.h"

#include "byte_io.h"

#include <cmath>
#include <memory>

namespace imudesk::protocol::hipnuc {

using model::kGravity;
using model::kRadToDeg;

namespace {

void read(LeReader &r, Hi91 &p)
{
    p.mainStatus = r.get<uint16_t>();
    p.temperature = r.get<int8_t>();
    p.pressure = r.get<float>();
    p.systemTime = r.get<uint32_t>();
    r.get(p.acc);
    r.get(p.gyr);
    r.get(p.mag);
    p.roll = r.get<float>();
    p.pitch = r.get<float>();
    p.yaw = r.get<float>();
    r.get(p.quat);
}

void read(LeReader &r, Hi92 &p)
{
    p.status = r.get<uint16_t>();
    p.temperature = r.get<int8_t>();
    p.reserved = r.get<uint16_t>();
    p.pressure = r.get<int16_t>();
    p.heave = r.get<int16_t>();
    r.get(p.gyr);
    r.get(p.acc);
    r.get(p.mag);
    p.roll = r.get<int32_t>();
    p.pitch = r.get<int32_t>();
    p.yaw = r.get<int32_t>();
    r.get(p.quat);
}

void read(LeReader &r, Hi81 &p)
{
    p.mainStatus = r.get<uint16_t>();
    p.insStatus = r.get<uint8_t>();
    p.gpsWeek = r.get<uint16_t>();
    p.gpsTowMs = r.get<uint32_t>();
    p.reserved = r.get<uint16_t>();
    r.get(p.gyr);
    r.get(p.acc);
    r.get(p.mag);
    p.pressure = r.get<int16_t>();
    p.odSpeed = r.get<int16_t>();
    p.temperature = r.get<int8_t>();
    p.utcYear = r.get<uint8_t>();
    p.utcMonth = r.get<uint8_t>();
    p.utcDay = r.get<uint8_t>();
    p.utcHour = r.get<uint8_t>();
    p.utcMinute = r.get<uint8_t>();
    p.utcMs = r.get<uint16_t>();
    p.roll = r.get<int16_t>();
    p.pitch = r.get<int16_t>();
    p.yaw = r.get<uint16_t>();
    r.get(p.quat);
    p.lon = r.get<int32_t>();
    p.lat = r.get<int32_t>();
    p.msl = r.get<int32_t>();
    p.pdop = r.get<uint8_t>();
    p.hdop = r.get<uint8_t>();
    p.solqPos = r.get<uint8_t>();
    p.nvPos = r.get<uint8_t>();
    p.solqHeading = r.get<uint8_t>();
    p.nvHeading = r.get<uint8_t>();
    p.diffAge = r.get<uint8_t>();
    p.undulation = r.get<int16_t>();
    p.antStatus = r.get<uint8_t>();
    r.get(p.velEnu);
    r.get(p.accEnu);
    r.get(p.tail);
}

// HI83 fields in wire order: "后续数据段按位图从低位到高位顺序依次排列" (v1.7.1 manual 5.9.11,
// sizes in 5.9.12), ascending bit order. The vendor's SDK comments put 30 and 31 after 27
// and before 28 and 29, but that SDK refuses every frame with bits 20-29 and so never reads
// them; ImuDesk follows the manual (docs/user-guide.md, "HI83").
template <typename Io, typename H> void walkHi83(Io &io, H &p)
{
    const uint32_t m = p.bitmap;
    auto has = [m](int bit) { return (m >> bit) & 1u; };
    if (has(0)) io(p.accB);
    if (has(1)) io(p.gyrB);
    if (has(2)) io(p.magB);
    if (has(3)) io(p.rpy);
    if (has(4)) io(p.quat);
    if (has(5)) io.time(p);
    if (has(6)) io(p.utc);
    if (has(7)) io(p.pressure);
    if (has(8)) io(p.temperature);
    if (has(9)) io(p.inclination);
    if (has(10)) io(p.hss);
    if (has(11)) io(p.hssFreq);
    if (has(12)) io(p.velEnu);
    if (has(13)) io(p.accEnu);
    if (has(14)) io(p.insLonLatMsl);
    if (has(15)) io(p.gnssQualityNv);
    if (has(16)) io(p.odSpeed);
    if (has(17)) io(p.undulation);
    if (has(18)) io(p.diffAge);
    if (has(19)) io(p.nodeInfo);
    if (has(25)) io(p.eventCounter);
    if (has(26)) io(p.kfAccBias);
    if (has(27)) io(p.kfGyrBias);
    if (has(28)) io(p.gnssStd);
    if (has(29)) io(p.gnssHeadingInfo);
    if (has(30)) io(p.gnssLonLatMsl);
    if (has(31)) io(p.gnssVel);
}

struct Hi83Reader {
    LeReader &r;
    template <typename T, size_t N> void operator()(std::array<T, N> &a) { r.get(a); }
    template <typename T> void operator()(T &v) { v = r.get<T>(); }
    void time(Hi83 &p) { p.systemTimeUs = p.legacyTime32 ? uint64_t(r.get<uint32_t>()) * 1000u : r.get<uint64_t>(); }
};

struct Hi83Writer {
    LeWriter &w;
    template <typename T, size_t N> void operator()(const std::array<T, N> &a) { w.put(a); }
    template <typename T> void operator()(const T &v) { w.put<T>(v); }
    void time(const Hi83 &p)
    {
        if (p.legacyTime32)
            w.put<uint32_t>(uint32_t(p.systemTimeUs / 1000u));
        else
            w.put<uint64_t>(p.systemTimeUs);
    }
};

} // namespace

size_t Hi83::fieldSize(int bit)
{
    static constexpr uint8_t sizes[32] = {12, 12, 12, 12, 16, 8, 8, 4, 4, 12, 12, 12, 12, 12, 24, 4,
                                          4,  4,  4,  4,  0,  0, 0, 0, 0, 64, 12, 12, 12, 12, 24, 12};
    return (bit >= 0 && bit < 32) ? sizes[bit] : 0;
}

std::optional<size_t> Hi83::payloadSize(uint32_t bitmap, bool legacyTime32)
{
    if (bitmap & ~kSupportedMask)
        return std::nullopt;
    size_t n = 8;
    for (int b = 0; b < 32; ++b)
        if ((bitmap >> b) & 1u)
            n += (b == 5 && legacyTime32) ? 4 : fieldSize(b);
    return n;
}

const char *payloadErrorText(PayloadError e)
{
    switch (e) {
    case PayloadError::None: return "ok";
    case PayloadError::Empty: return "empty payload";
    case PayloadError::UnknownTag: return "unknown sub-packet tag";
    case PayloadError::Truncated: return "sub-packet truncated";
    case PayloadError::UnsupportedBits: return "HI83 bitmap has fields of unknown size";
    case PayloadError::SizeMismatch: return "HI83 length does not match its bitmap";
    }
    return "?";
}

bool decodeHi91(const uint8_t *data, size_t len, Hi91 &out)
{
    if (len != Hi91::kSize || data[0] != TagHi91)
        return false;
    LeReader r(data + 1, len - 1);
    read(r, out);
    return true;
}

PayloadResult decodePayload(const uint8_t *data, size_t len)
{
    PayloadResult res;
    if (len == 0) {
        res.error = PayloadError::Empty;
        return res;
    }
    size_t off = 0;
    auto fail = [&](PayloadError e) {
        res.error = e;
        res.errorOffset = off;
        res.errorTag = data[off];
        return res;
    };
    while (off < len) {
        const uint8_t tag = data[off];
        const size_t left = len - off;
        switch (tag) {
        case TagHi91: {
            if (left < Hi91::kSize) return fail(PayloadError::Truncated);
            Hi91 p;
            LeReader r(data + off + 1, Hi91::kSize - 1);
            read(r, p);
            res.packets.emplace_back(p);
            off += Hi91::kSize;
            break;
        }
        case TagHi92: {
            if (left < Hi92::kSize) return fail(PayloadError::Truncated);
            Hi92 p;
            LeReader r(data + off + 1, Hi92::kSize - 1);
            read(r, p);
            res.packets.emplace_back(p);
            off += Hi92::kSize;
            break;
        }
        case TagHi81: {
            if (left < Hi81::kSize) return fail(PayloadError::Truncated);
            Hi81 p;
            LeReader r(data + off + 1, Hi81::kSize - 1);
            read(r, p);
            res.packets.emplace_back(p);
            off += Hi81::kSize;
            break;
        }
        case TagHi83: {
            if (left < 8) return fail(PayloadError::Truncated);
            Hi83 p;
            LeReader h(data + off + 1, 7);
            p.mainStatus = h.get<uint16_t>();
            p.insStatus = h.get<uint8_t>();
            p.bitmap = h.get<uint32_t>();
            const auto size = Hi83::payloadSize(p.bitmap);
            if (!size) return fail(PayloadError::UnsupportedBits);
            // HI83 is variable: it must be the last sub-packet and fill the payload
            // exactly. Early 1.7.1 builds sent a 4-byte ms timestamp for bit 5;
            // that length is distinct (4 bytes shorter), so it is recognised, not guessed.
            size_t want = *size;
            if (left != want && (p.bitmap & (1u << 5)) && left == want - 4) {
                p.legacyTime32 = true;
                want -= 4;
            }
            if (left < want) return fail(PayloadError::Truncated);
            if (left != want) return fail(PayloadError::SizeMismatch);
            LeReader r(data + off + 8, want - 8);
            Hi83Reader io{r};
            walkHi83(io, p);
            res.packets.emplace_back(p);
            off += want;
            break;
        }
        default:
            return fail(PayloadError::UnknownTag);
        }
    }
    return res;
}

std::vector<uint8_t> encode(const Hi91 &p)
{
    std::vector<uint8_t> out;
    out.reserve(Hi91::kSize);
    LeWriter w(out);
    w.put<uint8_t>(TagHi91);
    w.put(p.mainStatus);
    w.put(p.temperature);
    w.put(p.pressure);
    w.put(p.systemTime);
    w.put(p.acc);
    w.put(p.gyr);
    w.put(p.mag);
    w.put(p.roll);
    w.put(p.pitch);
    w.put(p.yaw);
    w.put(p.quat);
    return out;
}

std::vector<uint8_t> encode(const Hi92 &p)
{
    std::vector<uint8_t> out;
    out.reserve(Hi92::kSize);
    LeWriter w(out);
    w.put<uint8_t>(TagHi92);
    w.put(p.status);
    w.put(p.temperature);
    w.put(p.reserved);
    w.put(p.pressure);
    w.put(p.heave);
    w.put(p.gyr);
    w.put(p.acc);
    w.put(p.mag);
    w.put(p.roll);
    w.put(p.pitch);
    w.put(p.yaw);
    w.put(p.quat);
    return out;
}

std::vector<uint8_t> encode(const Hi81 &p)
{
    std::vector<uint8_t> out;
    out.reserve(Hi81::kSize);
    LeWriter w(out);
    w.put<uint8_t>(TagHi81);
    w.put(p.mainStatus);
    w.put(p.insStatus);
    w.put(p.gpsWeek);
    w.put(p.gpsTowMs);
    w.put(p.reserved);
    w.put(p.gyr);
    w.put(p.acc);
    w.put(p.mag);
    w.put(p.pressure);
    w.put(p.odSpeed);
    w.put(p.temperature);
    w.put(p.utcYear);
    w.put(p.utcMonth);
    w.put(p.utcDay);
    w.put(p.utcHour);
    w.put(p.utcMinute);
    w.put(p.utcMs);
    w.put(p.roll);
    w.put(p.pitch);
    w.put(p.yaw);
    w.put(p.quat);
    w.put(p.lon);
    w.put(p.lat);
    w.put(p.msl);
    w.put(p.pdop);
    w.put(p.hdop);
    w.put(p.solqPos);
    w.put(p.nvPos);
    w.put(p.solqHeading);
    w.put(p.nvHeading);
    w.put(p.diffAge);
    w.put(p.undulation);
    w.put(p.antStatus);
    w.put(p.velEnu);
    w.put(p.accEnu);
    w.put(p.tail);
    return out;
}

std::vector<uint8_t> encode(const Hi83 &p)
{
    std::vector<uint8_t> out;
    LeWriter w(out);
    w.put<uint8_t>(TagHi83);
    w.put(p.mainStatus);
    w.put(p.insStatus);
    w.put(p.bitmap & Hi83::kSupportedMask);
    Hi83 q = p;
    q.bitmap &= Hi83::kSupportedMask;
    Hi83Writer io{w};
    walkHi83(io, q);
    return out;
}

std::vector<uint8_t> encode(const Packet &p)
{
    return std::visit([](const auto &x) { return encode(x); }, p);
}

std::vector<uint8_t> encode(const std::vector<Packet> &packets)
{
    std::vector<uint8_t> out;
    for (const auto &p : packets) {
        const auto b = encode(p);
        out.insert(out.end(), b.begin(), b.end());
    }
    return out;
}

std::string packetName(const Packet &p)
{
    switch (p.index()) {
    case 0: return "HI91";
    case 1: return "HI92";
    case 2: return "HI81";
    case 3: return "HI83";
    }
    return "?";
}

model::Sample toSample(const Hi91 &p)
{
    model::Sample s;
    s.source = "HI91";
    s.fields = model::FieldAcc | model::FieldGyr | model::FieldMag | model::FieldEuler | model::FieldQuat
        | model::FieldPressure | model::FieldTemperature | model::FieldDeviceTime | model::FieldMainStatus;
    s.mainStatus = p.mainStatus;
    s.temperatureC = p.temperature;
    s.pressurePa = p.pressure;
    s.deviceTimeMs = p.systemTime;
    s.acc = {p.acc[0], p.acc[1], p.acc[2]};
    s.gyr = {p.gyr[0], p.gyr[1], p.gyr[2]};
    s.mag = {p.mag[0], p.mag[1], p.mag[2]};
    s.roll = p.roll;
    s.pitch = p.pitch;
    s.yaw = p.yaw;
    s.quat = {p.quat[0], p.quat[1], p.quat[2], p.quat[3]};
    return s;
}

namespace {

model::Vec3 scaled(const std::array<int16_t, 3> &v, double k)
{
    return {v[0] * k, v[1] * k, v[2] * k};
}

model::Sample sampleOf(const Hi92 &p)
{
    model::Sample s;
    s.source = "HI92";
    s.fields = model::FieldAcc | model::FieldGyr | model::FieldMag | model::FieldEuler | model::FieldQuat
        | model::FieldPressure | model::FieldTemperature | model::FieldHeave;
    s.temperatureC = p.temperature;
    s.pressurePa = p.pressure + 100000.0;
    s.heaveSurgeSway = {p.heave * 0.01, 0, 0};
    s.gyr = scaled(p.gyr, 0.001 * kRadToDeg);
    s.acc = scaled(p.acc, 0.0048828 / kGravity);
    s.mag = scaled(p.mag, 0.030517);
    s.roll = p.roll * 0.001;
    s.pitch = p.pitch * 0.001;
    s.yaw = p.yaw * 0.001;
    s.quat = {p.quat[0] * 1e-4, p.quat[1] * 1e-4, p.quat[2] * 1e-4, p.quat[3] * 1e-4};
    return s;
}

model::Sample sampleOf(const Hi81 &p)
{
    model::Sample s;
    s.source = "HI81";
    s.fields = model::FieldAcc | model::FieldGyr | model::FieldMag | model::FieldEuler | model::FieldQuat
        | model::FieldPressure | model::FieldTemperature | model::FieldMainStatus | model::FieldInsStatus
        | model::FieldPosition | model::FieldVelocity | model::FieldDeviceTime;
    s.mainStatus = p.mainStatus;
    s.insStatus = p.insStatus;
    s.deviceTimeMs = p.gpsTowMs;
    s.gyr = scaled(p.gyr, 0.001 * kRadToDeg);
    s.acc = scaled(p.acc, 0.0048828 / kGravity);
    s.mag = scaled(p.mag, 0.030517);
    s.pressurePa = p.pressure + 100000.0;
    s.temperatureC = p.temperature;
    s.roll = p.roll * 0.01;
    s.pitch = p.pitch * 0.01;
    // HI81 carries heading (0..360 clockwise); Sample.yaw is the Euler yaw (counter-clockwise).
    double yaw = -p.yaw * 0.01;
    if (yaw <= -180.0) yaw += 360.0;
    s.yaw = yaw;
    s.quat = {p.quat[0] * 1e-4, p.quat[1] * 1e-4, p.quat[2] * 1e-4, p.quat[3] * 1e-4};
    s.longitudeDeg = p.lon * 1e-7;
    s.latitudeDeg = p.lat * 1e-7;
    s.altitudeM = p.msl * 1e-3;
    s.velEnu = scaled(p.velEnu, 0.01);
    return s;
}

model::Sample sampleOf(const Hi83 &p)
{
    model::Sample s;
    s.source = "HI83";
    s.fields = model::FieldMainStatus | model::FieldInsStatus;
    s.mainStatus = p.mainStatus;
    s.insStatus = p.insStatus;
    auto has = [&](int bit) { return (p.bitmap >> bit) & 1u; };
    if (has(0)) { s.fields |= model::FieldAcc; s.acc = {p.accB[0] / kGravity, p.accB[1] / kGravity, p.accB[2] / kGravity}; }
    if (has(1)) { s.fields |= model::FieldGyr; s.gyr = {p.gyrB[0] * kRadToDeg, p.gyrB[1] * kRadToDeg, p.gyrB[2] * kRadToDeg}; }
    if (has(2)) { s.fields |= model::FieldMag; s.mag = {p.magB[0], p.magB[1], p.magB[2]}; }
    if (has(3)) { s.fields |= model::FieldEuler; s.roll = p.rpy[0]; s.pitch = p.rpy[1]; s.yaw = p.rpy[2]; }
    if (has(4)) { s.fields |= model::FieldQuat; s.quat = {p.quat[0], p.quat[1], p.quat[2], p.quat[3]}; }
    if (has(5)) { s.fields |= model::FieldDeviceTime; s.deviceTimeMs = double(p.systemTimeUs) / 1000.0; }
    if (has(7)) { s.fields |= model::FieldPressure; s.pressurePa = p.pressure; }
    if (has(8)) { s.fields |= model::FieldTemperature; s.temperatureC = p.temperature; }
    if (has(9)) { s.fields |= model::FieldInclination; s.inclinationX = p.inclination[0]; s.inclinationY = p.inclination[1]; }
    if (has(10)) { s.fields |= model::FieldHeave; s.heaveSurgeSway = {p.hss[0], p.hss[1], p.hss[2]}; }
    if (has(12)) { s.fields |= model::FieldVelocity; s.velEnu = {p.velEnu[0], p.velEnu[1], p.velEnu[2]}; }
    if (has(14)) {
        s.fields |= model::FieldPosition;
        s.longitudeDeg = p.insLonLatMsl[0];
        s.latitudeDeg = p.insLonLatMsl[1];
        s.altitudeM = p.insLonLatMsl[2];
    }
    // UTC counts only with a date (v1.7.1 5.9.12: zero until GNSS time is known).
    const bool utcValid = has(6) && p.utc[0] != 0 && p.utc[1] != 0;
    if (utcValid) {
        s.fields |= model::FieldGnss;
        const unsigned ms = unsigned(p.utc[5]) | unsigned(p.utc[6]) << 8;
        s.utcTimeOfDayS = p.utc[3] * 3600.0 + p.utc[4] * 60.0 + ms / 1000.0;
    }
    if (has(15)) {
        s.fields |= model::FieldGnss;
        s.gnssQuality = p.gnssQualityNv[0];
        s.gnssSatellites = p.gnssQualityNv[1];
    }
    constexpr uint32_t kExtraBits = (1u << 6) | (1u << 11) | (1u << 13) | 0x000F8000u | 0xFE000000u;
    if (p.bitmap & kExtraBits) {
        auto x = std::make_shared<model::Hi83Extra>();
        x->bits = p.bitmap & kExtraBits;
        if (!utcValid)
            x->bits &= ~(1u << 6);
        x->utcDate = {uint16_t(2000 + p.utc[0]), p.utc[1], p.utc[2]};
        x->hssFreqHz = p.hssFreq;
        x->accEnu = p.accEnu;
        x->solqPos = p.gnssQualityNv[0];
        x->nvPos = p.gnssQualityNv[1];
        x->solqHeading = p.gnssQualityNv[2];
        x->nvHeading = p.gnssQualityNv[3];
        x->odSpeedMs = p.odSpeed;
        x->undulationM = p.undulation;
        x->diffAgeS = p.diffAge;
        x->nodeId = p.nodeInfo[0];
        x->eventCounter = p.eventCounter;
        x->kfAccBias = p.kfAccBias;
        x->kfGyrBias = p.kfGyrBias;
        x->gnssStd = p.gnssStd;
        x->dualHeading = p.gnssHeadingInfo;
        x->gnssLonLatMsl = p.gnssLonLatMsl;
        x->gnssVelEnu = p.gnssVel;
        if (x->bits) {
            s.fields |= model::FieldHi83Extra;
            s.hi83 = std::move(x);
        }
    }
    return s;
}

} // namespace

model::Sample toSample(const Packet &p)
{
    return std::visit(
        [](const auto &x) -> model::Sample {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, Hi91>)
                return toSample(x);
            else
                return sampleOf(x);
        },
        p);
}

PacketClock packetClock(const Packet &p)
{
    PacketClock c;
    if (const auto *h = std::get_if<Hi91>(&p))
        c = PacketClock{"HI91", true, double(h->systemTime), true, h->mainStatus};
    else if (const auto *h81 = std::get_if<Hi81>(&p))
        c = PacketClock{"HI81", true, double(h81->gpsTowMs), true, h81->mainStatus};
    else if (const auto *h83 = std::get_if<Hi83>(&p))
        c = PacketClock{"HI83", ((h83->bitmap >> 5) & 1u) != 0, double(h83->systemTimeUs) / 1000.0, true, h83->mainStatus};
    else
        c.source = "HI92";
    return c;
}

} // namespace imudesk::protocol::hipnuc
