#include "hipnuc_vendor_csv.h"

#include "decode/hipnuc_stream_decoder.h"
#include "decode/vendor_layout.h"

#include "format/csv_number.h"

#include <cmath>
#include <cstdio>

namespace imudesk::decode::vendor_csv {

namespace hp = protocol::hipnuc;
using format::csv::appendInt;
using format::csv::appendNumber;

const char *hi91Header()
{
    return "HI91,pc_counter,sys_time,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,mag_x,mag_y,mag_z,roll,pitch,yaw,"
           "pps_sync_stamp,incli_x,incli_y,quat_w,quat_x,quat_y,quat_z,temperature,pressure,acc_norm,gyr_norm,"
           "mag_norm";
}

const char *hi81Header()
{
    return "HI81,pc_counter,main_status,ins_status,gps_week,gps_tow,gyr_x,gyr_y,gyr_z,acc_x,acc_y,acc_z,mag_x,mag_y,"
           "mag_z,pressure,od_speed,temperature,utc_year,utc_month,utc_day,utc_hour,utc_minute,utc_ms,roll,pitch,yaw,"
           "quat_w,quat_x,quat_y,quat_z,lon,lat,msl,pdop,hdop,solq_pos,nv_pos,solq_heading,nv_heading,diff_age,"
           "undulation,ant_status,vel_e,vel_n,vel_u,acc_e,acc_n,acc_u";
}

const char *hi83Header()
{
    return "HI83,pc_counter,main_status,ins_status,data_bitmap,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,mag_x,mag_y,mag_z,"
           "roll,pitch,yaw,quat_w,quat_x,quat_y,quat_z,sys_time_us,utc_year,utc_month,utc_day,utc_hour,utc_minute,"
           "utc_ms,pressure,temperature,incli_x,incli_y,incli_yaw,heave,surge,sway,heave_freq,surge_freq,sway_freq,"
           "vel_e,vel_n,vel_u,acc_e,acc_n,acc_u,ins_lon,ins_lat,ins_msl,solq_pos,nv_pos,solq_heading,nv_heading,"
           "od_speed,undulation,diff_age,node_id,gnss_lon,gnss_lat,gnss_msl,gnss_vel_e,gnss_vel_n,gnss_vel_u,"
           // Bits 25-29 (v1.7.1 5.9.12), after the columns the vendor's tool writes.
           "evt_gravity,evt_mag,evt_gnss_pos,evt_gnss_vel,evt_dual_heading,evt_nhc,evt_zupt,evt_zaru,evt_zihr,evt_od,"
           "evt_10,evt_11,evt_12,evt_13,evt_14,evt_15,kf_acc_bias_x,kf_acc_bias_y,kf_acc_bias_z,kf_gyr_bias_x,"
           "kf_gyr_bias_y,kf_gyr_bias_z,gnss_pos_std,gnss_vel_std,gnss_std_reserved,dual_baseline,dual_pitch,"
           "dual_heading";
}

namespace {

template<typename T, size_t N>
void floats(std::string &out, const std::array<T, N> &v)
{
    for (const T &x : v) {
        out += ',';
        appendNumber(out, x);
    }
}

template<size_t N>
void scaledInts(std::string &out, const std::array<int16_t, N> &v, double k)
{
    for (int16_t x : v) {
        out += ',';
        appendNumber(out, x * k);
    }
}

void field(std::string &out, double v)
{
    out += ',';
    appendNumber(out, v);
}

void intField(std::string &out, int64_t v)
{
    out += ',';
    appendInt(out, v);
}

float norm(const std::array<float, 3> &v)
{
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

void empty(std::string &out, int n)
{
    out.append(size_t(n), ',');
}

} // namespace

void appendRow(std::string &out, const hp::Hi91 &p, double pcCounterMs)
{
    out += "HI91,";
    appendNumber(out, pcCounterMs);
    intField(out, p.systemTime);
    floats(out, p.acc);
    floats(out, p.gyr);
    floats(out, p.mag);
    out += ',';
    appendNumber(out, p.roll);
    out += ',';
    appendNumber(out, p.pitch);
    out += ',';
    appendNumber(out, p.yaw);
    out += ",0,0,0"; // pps_sync_stamp, incli_x, incli_y: HI91 carries none of them
    floats(out, p.quat);
    intField(out, p.temperature);
    out += ',';
    appendNumber(out, p.pressure);
    out += ',';
    appendNumber(out, norm(p.acc));
    out += ',';
    appendNumber(out, norm(p.gyr));
    out += ',';
    appendNumber(out, norm(p.mag));
    out += '\n';
}

namespace {
std::vector<std::string> splitCells(std::string_view row)
{
    std::vector<std::string> cells;
    size_t start = 0;
    for (;;) {
        const size_t comma = row.find(',', start);
        cells.emplace_back(row.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
        if (comma == std::string_view::npos)
            return cells;
        start = comma + 1;
    }
}
} // namespace

std::vector<std::string> hi91Names()
{
    return splitCells(hi91Header());
}

std::vector<std::string> hi91Cells(const hp::Hi91 &p, double pcCounterMs)
{
    std::string row;
    appendRow(row, p, pcCounterMs);
    if (!row.empty() && row.back() == '\n')
        row.pop_back();
    return splitCells(row);
}

std::string encodeCells(const Cells &cells)
{
    std::string out;
    for (const auto &[name, text] : cells) {
        out += name;
        out += '=';
        out += text;
        out += '\n';
    }
    return out;
}

Cells decodeCells(std::string_view text)
{
    Cells cells;
    while (!text.empty()) {
        const size_t end = text.find('\n');
        const std::string_view line = text.substr(0, end);
        const size_t eq = line.find('=');
        if (eq != std::string_view::npos && eq > 0)
            cells.emplace_back(std::string(line.substr(0, eq)), std::string(line.substr(eq + 1)));
        if (end == std::string_view::npos)
            break;
        text.remove_prefix(end + 1);
    }
    return cells;
}

void appendRow(std::string &out, const hp::Hi91 &p, double pcCounterMs, const Cells &keep)
{
    if (keep.empty()) {
        appendRow(out, p, pcCounterMs);
        return;
    }
    static const std::vector<std::string> names = hi91Names();
    std::vector<std::string> cells = hi91Cells(p, pcCounterMs);
    for (const auto &[name, text] : keep)
        for (size_t i = 1; i < names.size() && i < cells.size(); ++i)
            if (names[i] == name && text.find_first_of(",\n\r") == std::string::npos)
                cells[i] = text;
    for (size_t i = 0; i < cells.size(); ++i) {
        if (i)
            out += ',';
        out += cells[i];
    }
    out += '\n';
}

void appendRow(std::string &out, const hp::Hi81 &p, double pcCounterMs)
{
    constexpr double kDeg = 57.29577951308232;
    out += "HI81,";
    appendNumber(out, pcCounterMs);
    intField(out, p.mainStatus);
    intField(out, p.insStatus);
    intField(out, p.gpsWeek);
    intField(out, p.gpsTowMs);
    scaledInts(out, p.gyr, 0.001 * kDeg); // deg/s
    scaledInts(out, p.acc, 0.0048828);    // m/s^2
    scaledInts(out, p.mag, 0.030517);     // uT
    field(out, p.pressure + 100000.0);
    field(out, p.odSpeed * 0.01);
    intField(out, p.temperature);
    intField(out, p.utcYear);
    intField(out, p.utcMonth);
    intField(out, p.utcDay);
    intField(out, p.utcHour);
    intField(out, p.utcMinute);
    intField(out, p.utcMs);
    field(out, p.roll * 0.01);
    field(out, p.pitch * 0.01);
    field(out, p.yaw * 0.01);
    for (int16_t q : p.quat)
        field(out, q * 1e-4);
    field(out, p.lon * 1e-7);
    field(out, p.lat * 1e-7);
    field(out, p.msl * 1e-3);
    intField(out, p.pdop);
    intField(out, p.hdop);
    intField(out, p.solqPos);
    intField(out, p.nvPos);
    intField(out, p.solqHeading);
    intField(out, p.nvHeading);
    intField(out, p.diffAge);
    field(out, p.undulation * 0.01);
    intField(out, p.antStatus);
    scaledInts(out, p.velEnu, 0.01);
    scaledInts(out, p.accEnu, 0.0048828);
    out += '\n';
}

void appendRow(std::string &out, const hp::Hi83 &p, double pcCounterMs)
{
    auto has = [&](int bit) { return (p.bitmap & (1u << bit)) != 0; };
    auto group = [&](int bit, const auto &values) {
        if (has(bit))
            floats(out, values);
        else
            empty(out, int(std::size(values)));
    };
    out += "HI83,";
    appendNumber(out, pcCounterMs);
    intField(out, p.mainStatus);
    intField(out, p.insStatus);
    out += ",0x";
    char hex[9];
    std::snprintf(hex, sizeof hex, "%08X", p.bitmap);
    out += hex;
    group(0, p.accB);
    group(1, p.gyrB);
    group(2, p.magB);
    group(3, p.rpy);
    group(4, p.quat);
    if (has(5))
        intField(out, int64_t(p.systemTimeUs));
    else
        empty(out, 1);
    if (has(6)) {
        for (int i = 0; i < 5; ++i)
            intField(out, p.utc[size_t(i)]);
        intField(out, p.utc[5] | (p.utc[6] << 8));
    } else {
        empty(out, 6);
    }
    if (has(7))
        field(out, p.pressure);
    else
        empty(out, 1);
    if (has(8))
        field(out, p.temperature);
    else
        empty(out, 1);
    group(9, p.inclination);
    group(10, p.hss);
    group(11, p.hssFreq);
    group(12, p.velEnu);
    group(13, p.accEnu);
    group(14, p.insLonLatMsl);
    if (has(15))
        for (uint8_t v : p.gnssQualityNv)
            intField(out, v);
    else
        empty(out, 4);
    for (int bit : {16, 17, 18}) {
        const float v = bit == 16 ? p.odSpeed : bit == 17 ? p.undulation : p.diffAge;
        if (has(bit))
            field(out, v);
        else
            empty(out, 1);
    }
    if (has(19))
        intField(out, p.nodeInfo[0]);
    else
        empty(out, 1);
    group(30, p.gnssLonLatMsl);
    group(31, p.gnssVel);
    if (has(25))
        for (uint32_t v : p.eventCounter)
            intField(out, int64_t(v));
    else
        empty(out, int(p.eventCounter.size()));
    group(26, p.kfAccBias);
    group(27, p.kfGyrBias);
    group(28, p.gnssStd);
    group(29, p.gnssHeadingInfo);
    out += '\n';
}

} // namespace imudesk::decode::vendor_csv

namespace imudesk::decode {

namespace {

// The vendor's CSV of a HiPNUC module's packets: HI91, HI81 and HI83 have a layout; HI92
// (raw integers) has none in the vendor's tool.
class HipnucVendorLayout final : public VendorLayout {
public:
    static const protocol::hipnuc::Packet *packetOf(const Record &r)
    {
        return r.family == std::string_view(HipnucStreamDecoder::kFamily)
                   ? static_cast<const protocol::hipnuc::Packet *>(r.native)
                   : nullptr;
    }
    bool fileOf(const Record &record, QString &type, const char *&header) const override
    {
        const auto *p = packetOf(record);
        if (!p)
            return false;
        if (std::holds_alternative<protocol::hipnuc::Hi91>(*p)) {
            type = m_hi91;
            header = vendor_csv::hi91Header();
        } else if (std::holds_alternative<protocol::hipnuc::Hi81>(*p)) {
            type = m_hi81;
            header = vendor_csv::hi81Header();
        } else if (std::holds_alternative<protocol::hipnuc::Hi83>(*p)) {
            type = m_hi83;
            header = vendor_csv::hi83Header();
        } else {
            return false;
        }
        return true;
    }
    void appendRow(std::string &out, const Record &record, double pcCounterMs, const Cells &keep) const override
    {
        const auto *p = packetOf(record);
        if (!p)
            return;
        if (const auto *h = std::get_if<protocol::hipnuc::Hi91>(p))
            vendor_csv::appendRow(out, *h, pcCounterMs, keep);
        else if (const auto *h81 = std::get_if<protocol::hipnuc::Hi81>(p))
            vendor_csv::appendRow(out, *h81, pcCounterMs);
        else if (const auto *h83 = std::get_if<protocol::hipnuc::Hi83>(p))
            vendor_csv::appendRow(out, *h83, pcCounterMs);
    }
    Cells decodeCells(std::string_view text) const override { return vendor_csv::decodeCells(text); }

private:
    const QString m_hi91 = QStringLiteral("HI91"), m_hi81 = QStringLiteral("HI81"), m_hi83 = QStringLiteral("HI83");
};

} // namespace

const VendorLayout *vendorLayoutFor(const std::string &family)
{
    static const HipnucVendorLayout hipnuc;
    if (family == HipnucStreamDecoder::kFamily)
        return &hipnuc;
    return nullptr;
}

} // namespace imudesk::decode
