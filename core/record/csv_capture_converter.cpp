#include "csv_capture_converter.h"

#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"
#include "decode/hipnuc_stream_decoder.h"
#include "record/converted_capture.h"
#include "decode/hipnuc_vendor_csv.h"

#include <cmath>

namespace imudesk::record {

namespace hp = protocol::hipnuc;

CsvCaptureConverter::Result CsvCaptureConverter::convert(const QString &csvPath, const QString &capturePath)
{
    Result r;
    ConvertedCapture out;
    capture::CaptureHeader header;
    header.set(capture::CaptureHeader::kPcCounter, "chunk time");
    if (!out.open(capturePath, csvPath, "vendor CSV import", decode::HipnucStreamDecoder::kFamily, header, &r.error))
        return r;
    const std::vector<std::string> layout = decode::vendor_csv::hi91Names();
    r.import = VendorCsvImporter::readRows(csvPath, [&](const model::Sample &s, const VendorCsvImporter::Row &row) {
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
        // Every cell the export would not write as the file has it (pps_sync_stamp, incli_x,
        // incli_y: HI91 has no such field; a norm or a time written otherwise) goes into the
        // capture beside the frame.
        const std::vector<std::string> again = decode::vendor_csv::hi91Cells(h, double(s.hostTimeNs) / 1e6);
        decode::vendor_csv::Cells keep;
        for (size_t i = 1; i < row.names.size() && i < row.cells.size(); ++i)
            for (size_t c = 1; c < layout.size() && c < again.size(); ++c)
                if (row.names[i] == layout[c] && row.cells[i] != again[c])
                    keep.emplace_back(layout[c], std::string(row.cells[i]));
        if (!keep.empty()) {
            const std::string cells = decode::vendor_csv::encodeCells(keep);
            out.append(s.hostTimeNs, reinterpret_cast<const uint8_t *>(cells.data()), cells.size(),
                       capture::ChunkVendorCells);
        }
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
