#include "mat_export.h"

#include "capture/device_name.h"
#include "capture/mcap_recording.h"

#include <QDateTime>

#include <cmath>
#include <limits>

namespace imudesk::record {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<format::mat::MatFile::Field> fields()
{
    return {{"time_common", "s", {}},
            {"time_device", "s", {}},
            {"time_arrival", "s", {}},
            {"time_common_uncertainty", "s", {}},
            {"main_status", "1", {}},
            {"acc", "m/s^2", {"x", "y", "z"}},
            {"gyr", "rad/s", {"x", "y", "z"}},
            {"mag", "T", {"x", "y", "z"}},
            {"euler", "rad", {"roll", "pitch", "yaw"}},
            {"quat", "1", {"w", "x", "y", "z"}},
            {"pressure", "Pa", {}},
            {"temperature", "degC", {}},
            {"position", "deg, deg, m", {"lat", "lon", "alt"}},
            {"vel", "m/s", {"e", "n", "u"}},
            // A compass's (HEC495): heading clockwise from north, its relative field, magnetic roll.
            {"heading", "rad", {}},
            {"mag_relative", "1", {"x", "y", "z"}},
            {"mag_roll", "rad", {}}};
}
constexpr size_t kColumns = 1 + 1 + 1 + 1 + 1 + 3 + 3 + 3 + 3 + 4 + 1 + 1 + 3 + 3 + 1 + 3 + 1;
} // namespace

MatExport::MatExport(int64_t originNs, int64_t epochOffsetNs)
    : m_originNs(originNs), m_epochOffsetNs(epochOffsetNs), m_row(kColumns)
{
}

int MatExport::addDevice(const capture::CaptureHeader &header, const std::string &label)
{
    std::map<std::string, std::string> info = capture::McapRecording::deviceMetadata(header);
    if (m_epochOffsetNs != 0) {
        const int64_t originUnixNs = m_originNs + m_epochOffsetNs;
        info["time_origin_unix_ns"] = std::to_string(originUnixNs);
        info["time_origin_utc"] = QDateTime::fromMSecsSinceEpoch(originUnixNs / 1'000'000, Qt::UTC)
                                      .toString(Qt::ISODateWithMs).toStdString();
    }
    info["time_common"] = "the sample's sampling instant on the host's clock, from the device's counter through "
                          "ImuDesk's clock model (NaN: none)";
    info["world_frame"] = header.identity().worldFrame == model::WorldFrame::Nwu ? "NWU" : "ENU";
    // "SN_0042": the name the user guide's MATLAB example uses (capture/device_name.h).
    return m_file.addStruct(matlabDeviceName(header, label), info, fields());
}

bool MatExport::append(int device, const model::Sample &s)
{
    using namespace model;
    double *r = m_row.data();
    const auto put = [&r](double v) { *r++ = v; };
    const auto vec = [&](SampleField f, const Vec3 &v, double k) {
        for (double c : {v.x, v.y, v.z})
            put(s.has(f) ? c * k : kNaN);
    };
    put(s.commonTimeNs != 0 ? double(s.commonTimeNs - m_originNs) / 1e9 : kNaN);
    put(s.has(FieldDeviceTime) ? s.deviceTimeMs / 1000.0 : kNaN);
    put(double(s.hostTimeNs - m_originNs) / 1e9);
    put(s.commonUncertaintyNs != 0 ? double(s.commonUncertaintyNs) / 1e9 : kNaN);
    put(s.has(FieldMainStatus) ? double(s.mainStatus) : kNaN);
    vec(FieldAcc, s.acc, kGravity);
    vec(FieldGyr, s.gyr, kDegToRad);
    vec(FieldMag, s.mag, 1e-6);
    for (double a : {s.roll, s.pitch, s.yaw})
        put(s.has(FieldEuler) ? a * kDegToRad : kNaN);
    for (double q : {s.quat.w, s.quat.x, s.quat.y, s.quat.z})
        put(s.has(FieldQuat) ? q : kNaN);
    put(s.has(FieldPressure) ? s.pressurePa : kNaN);
    put(s.has(FieldTemperature) ? s.temperatureC : kNaN);
    for (double p : {s.latitudeDeg, s.longitudeDeg, s.altitudeM})
        put(s.has(FieldPosition) ? p : kNaN);
    vec(FieldVelocity, s.velEnu, 1.0);
    put(s.has(FieldHeading) ? s.headingDeg * kDegToRad : kNaN);
    vec(FieldMagRelative, s.magRelative, 1.0);
    put(s.has(FieldMagRoll) ? s.magRollDeg * kDegToRad : kNaN);
    return m_file.appendRow(device, m_row.data());
}

bool MatExport::write(const QString &path)
{
    return m_file.write(path);
}

} // namespace imudesk::record
