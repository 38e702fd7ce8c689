#include "csv_capture_converter.h"

#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"
#include "record/converted_capture.h"

#include <cmath>

namespace imudesk::record {

namespace hp = protocol::hipnuc;

CsvCaptureConverter::Result CsvCaptureConverter::convert(const QString &csvPath, const QString &capturePath)
{
    Result r;
    ConvertedCapture out;
    if (!out.open(capturePath, csvPath, "vendor CSV import", {}, &r.error))
        return r;
    r.import = VendorCsvImporter::read(csvPath, [&](const model::Sample &s) {
        hp::Hi91 h;
        h.temperature = int8_t(std::lround(std::clamp(s.temperatureC, -128.0, 127.0)));
        h.pressure = float(s.pressurePa);
        h.systemTime = uint32_t(std::max(0.0, s.deviceTimeMs));
        h.acc = {float(s.acc.x), float(s.acc.y), float(s.acc.z)};
        h.gyr = {float(s.gyr.x), float(s.gyr.y), float(s.gyr.z)};
        h.mag = {float(s.mag.x), float(s.mag.y), float(s.mag.z)};
        h.roll = float(s.roll);
        h.pitch = float(s.pitch);
        h.yaw = float(s.yaw);
        h.quat = {float(s.quat.w), float(s.quat.x), float(s.quat.y), float(s.quat.z)};
        const auto frame = hp::buildFrame(hp::encode(h));
        out.append(s.hostTimeNs, frame.data(), frame.size());
    });
    if (!r.import.ok) {
        out.discard();
        r.error = r.import.error;
        return r;
    }
    if (!out.finish(&r.error))
        return r;
    r.ok = true;
    return r;
}

} // namespace imudesk::record
