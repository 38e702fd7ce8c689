#include "csv_capture_converter.h"

#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"
#include "record/capture_format.h"

#include <QFile>
#include <QFileInfo>

#include <cmath>

namespace imudesk::record {

namespace hp = protocol::hipnuc;

CsvCaptureConverter::Result CsvCaptureConverter::convert(const QString &csvPath, const QString &capturePath)
{
    Result r;
    QFile out(capturePath);
    if (!out.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        r.error = tr("Cannot write %1: %2").arg(capturePath, out.errorString());
        return r;
    }
    CaptureHeader header;
    header.set(CaptureHeader::kLinkKind, "vendor CSV import");
    header.set(CaptureHeader::kPort, QFileInfo(csvPath).fileName().toStdString());
    header.set(CaptureHeader::kApplication, "imudesk");
    std::vector<uint8_t> buf = capture::encodeFileHeader(header);
    bool writeFailed = false;
    auto flush = [&] {
        if (!buf.empty() && out.write(reinterpret_cast<const char *>(buf.data()), qint64(buf.size())) != qint64(buf.size()))
            writeFailed = true;
        buf.clear();
    };
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
        capture::appendChunk(buf, capture::ChunkReceived, s.hostTimeNs, 0, frame.data(), frame.size());
        if (buf.size() >= (1u << 20))
            flush();
    });
    flush();
    out.close();
    if (!r.import.ok) {
        QFile::remove(capturePath);
        r.error = r.import.error;
        return r;
    }
    if (writeFailed) {
        r.error = tr("Writing %1 failed: %2. Check the free disk space.").arg(capturePath, out.errorString());
        return r;
    }
    r.ok = true;
    return r;
}

} // namespace imudesk::record
