#include "capture_exporter.h"

#include "format/sample_json.h"
#include "capture/capture_decoder.h"
#include "capture/capture_reader.h"
#include "decode/vendor_layout.h"
#include "record/capture_source.h"
#include "format/csv_number.h"
#include "record/mat_export.h"
#include "capture/mcap_recording.h"

#include <QFile>
#include <QFileInfo>

#include <map>
#include <memory>

namespace imudesk::record {

namespace csv = format::csv;
using csv::appendInt;
using csv::appendNumber;

namespace {

constexpr size_t kFlushBytes = 1u << 20;

// One output file with a block buffer.
struct Output {
    QFile file;
    std::string buf;
    bool failed = false;
    explicit Output(const QString &path) : file(path) {}
    void flush()
    {
        if (buf.empty() || failed)
            return;
        if (file.write(buf.data(), qint64(buf.size())) != qint64(buf.size()))
            failed = true;
        buf.clear();
    }
    void maybeFlush()
    {
        if (buf.size() >= kFlushBytes)
            flush();
    }
};

class ExportSink : public capture::CaptureDecoder::Sink {
public:
    ExportSink(const CaptureExporter::Options &o, CaptureExporter::Result &r) : m_o(o), m_r(r)
    {
    }

    int64_t firstNs = 0;
    int64_t epochOffsetNs = 0; // host clock to the Unix epoch (the first chunk's two times)
    const capture::CaptureHeader *header = nullptr;
    // An imported vendor CSV (CaptureSource::convert): the chunk times are its pc_counter, written
    // back as they were, and the cells its next HI91 frame cannot give back.
    bool pcCounterIsChunkTime = false;
    // The capture's family's own layout (VendorCsv): null when its vendor has none.
    const decode::VendorLayout *layout = nullptr;
    decode::VendorLayout::Cells keptCells;
    model::WorldFrame worldFrame = model::WorldFrame::Enu; // the capture's module (its header)

    // MCAP: the device's channels, its identity and configuration written first (McapRecording).
    capture::McapRecording *mcap()
    {
        if (m_mcap || m_failed)
            return m_mcap.get();
        m_mcap = std::make_unique<capture::McapRecording>();
        QString error;
        if (!m_mcap->start(m_o.output, header ? *header : capture::CaptureHeader{}, epochOffsetNs, &error)) {
            m_r.error = error;
            m_failed = true;
            return nullptr;
        }
        m_r.files << m_o.output;
        return m_mcap.get();
    }
    void mcapWrite(const model::Sample &s)
    {
        if (auto *m = mcap()) {
            if (!m->append(s))
                mcapFailed();
            else
                ++m_r.frames;
        }
    }
    // MATLAB: the rows spooled as they come, the file written at the end.
    void matWrite(const model::Sample &s)
    {
        if (!m_mat) {
            m_mat = std::make_unique<MatExport>(firstNs, epochOffsetNs);
            m_matDevice = m_mat->addDevice(header ? *header : capture::CaptureHeader{});
        }
        if (m_matDevice < 0 || !m_mat->append(m_matDevice, s)) {
            m_failed = true;
            m_r.error = m_mat->error();
            return;
        }
        ++m_r.frames;
    }
    void mcapFailed()
    {
        if (!m_failed) {
            m_failed = true;
            m_r.error = CaptureExporter::tr("Writing %1 failed: %2. Check the free disk space.").arg(m_o.output, m_mcap->error());
        }
    }

    bool open(const QString &path, const char *header, Output *&out)
    {
        auto o = std::make_unique<Output>(path);
        if (!o->file.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
            m_r.error = CaptureExporter::tr("Cannot write %1: %2").arg(path, o->file.errorString());
            m_failed = true;
            return false;
        }
        m_r.files << path;
        if (header) {
            o->buf += header;
            o->buf += '\n';
        }
        out = o.get();
        m_outputs.push_back(std::move(o));
        return true;
    }

    Output *output(const QString &type, const char *header)
    {
        if (m_o.format != CaptureExporter::Format::VendorCsv) {
            if (!m_single)
                open(m_o.output, m_o.format == CaptureExporter::Format::TidyCsv ? CaptureExporter::tidyHeader(worldFrame) : nullptr,
                     m_single);
            return m_single;
        }
        auto it = m_byType.find(type);
        if (it != m_byType.end())
            return it->second;
        // Written where it is told: one frame type goes to the output as named; a second one
        // moves the first to OUT_<type>.csv and goes to its own OUT_<type>.csv (finish() says so).
        Output *out = nullptr;
        if (m_byType.empty()) {
            open(m_o.output, header, out);
        } else {
            if (m_byType.size() == 1 && !moveFirstAside())
                return nullptr;
            open(CaptureExporter::vendorPath(m_o.output, type), header, out);
        }
        m_byType[type] = out;
        return out;
    }

    // The record's row in the vendor's layout; false when the layout has none for it.
    bool vendorRow(const decode::Record &rec, int64_t hostNs)
    {
        QString type;
        const char *head = nullptr;
        if (!layout || !layout->fileOf(rec, type, head))
            return false;
        // An imported vendor CSV's pc_counter is the chunks' time, written back as it was.
        const double pcCounterMs = pcCounterIsChunkTime ? double(hostNs) / 1e6 : double(hostNs - firstNs) / 1e6;
        Output *out = output(type, head);
        if (out)
            layout->appendRow(out->buf, rec, pcCounterMs, keptCells);
        keptCells.clear();
        written(out);
        return true;
    }

    // Each sample of the capture's family, stamped by its decoder as the live session stamped it.
    void onSample(const model::Sample &s, const decode::Record &rec) override
    {
        switch (m_o.format) {
        case CaptureExporter::Format::VendorCsv:
            if (!vendorRow(rec, s.hostTimeNs))
                ++m_r.skipped; // the vendor's tool has no layout for it
            break;
        case CaptureExporter::Format::TidyCsv: {
            Output *out = output(QString(), nullptr);
            if (out)
                CaptureExporter::appendTidyRow(out->buf, s, rec.tag, firstNs);
            written(out);
            break;
        }
        case CaptureExporter::Format::JsonLines: {
            Output *out = output(QString(), nullptr);
            if (out) {
                out->buf += format::sampleToJson(s, worldFrame);
                out->buf += '\n';
            }
            written(out);
            break;
        }
        case CaptureExporter::Format::Mcap:
            mcapWrite(s);
            break;
        case CaptureExporter::Format::Mat:
            matWrite(s);
            break;
        }
    }

    void onText(decode::TextKind kind, const std::string &sentence, int64_t) override
    {
        if (kind == decode::TextKind::Line)
            return;
        Output *out = nullptr;
        if (m_o.format == CaptureExporter::Format::VendorCsv) {
            if ((out = output(QStringLiteral("NMEA"), nullptr))) {
                out->buf += sentence;
                out->buf += '\n';
            }
        } else if (m_o.format == CaptureExporter::Format::JsonLines) {
            if ((out = output(QString(), nullptr)))
                out->buf += "{\"type\":\"NMEA\",\"sentence\":\"" + sentence + "\"}\n";
        } else {
            return; // the tidy CSV, MCAP and MATLAB hold samples only
        }
        written(out);
    }

    // The first frame type's file, written as the output's name, becomes OUT_<type>.csv.
    bool moveFirstAside()
    {
        const auto &[type, first] = *m_byType.begin();
        const QString to = CaptureExporter::vendorPath(m_o.output, type);
        first->flush();
        first->file.close();
        QFile::remove(to);
        if (first->failed || !QFile::rename(m_o.output, to)) {
            m_failed = true;
            m_r.error = CaptureExporter::tr("Cannot write %1: %2").arg(to, first->file.errorString());
            return false;
        }
        first->file.setFileName(to);
        if (!first->file.open(QIODevice::WriteOnly | QIODevice::Append)) {
            m_failed = true;
            m_r.error = CaptureExporter::tr("Cannot write %1: %2").arg(to, first->file.errorString());
            return false;
        }
        m_r.files.replace(m_r.files.indexOf(m_o.output), to);
        return true;
    }

    bool failed() const { return m_failed; }
    bool finish()
    {
        if (m_o.format == CaptureExporter::Format::VendorCsv && m_byType.size() > 1)
            m_r.notes << CaptureExporter::tr("The capture holds %1 frame types; the vendor layout has a file for each: %2")
                             .arg(m_byType.size())
                             .arg(m_r.files.join(QStringLiteral(", ")));
        if (m_o.format == CaptureExporter::Format::Mcap) {
            mcap(); // an empty range still gives a file (with the device's metadata)
            if (m_mcap && m_mcap->isOpen() && !m_mcap->stop().isEmpty())
                mcapFailed();
            return !m_failed;
        }
        if (m_o.format == CaptureExporter::Format::Mat) {
            if (!m_mat) { // an empty range still gives a file (with the device's struct, 0 rows)
                m_mat = std::make_unique<MatExport>(firstNs, epochOffsetNs);
                m_matDevice = m_mat->addDevice(header ? *header : capture::CaptureHeader{});
            }
            if (m_failed)
                return false;
            if (!m_mat->write(m_o.output)) {
                m_failed = true;
                m_r.error = m_mat->error();
                return false;
            }
            m_r.files << m_o.output;
            return true;
        }
        if (m_o.format != CaptureExporter::Format::VendorCsv && !m_single)
            output(QString(), nullptr); // an empty range still gives a file (with its header)
        for (auto &o : m_outputs) {
            o->flush();
            o->file.close();
            if (o->failed && !m_failed) {
                m_failed = true;
                m_r.error = CaptureExporter::tr("Writing %1 failed: %2. Check the free disk space.")
                                .arg(o->file.fileName(), o->file.errorString());
            }
        }
        return !m_failed;
    }
    void removeOutputs()
    {
        if (m_mcap) {
            m_mcap->abandon();
            QFile::remove(m_o.output);
        }
        for (auto &o : m_outputs) {
            o->file.close();
            QFile::remove(o->file.fileName());
        }
        m_r.files.clear();
    }

private:
    void written(Output *out)
    {
        if (!out)
            return;
        ++m_r.frames;
        out->maybeFlush();
        if (out->failed && !m_failed) {
            m_failed = true;
            m_r.error = CaptureExporter::tr("Writing %1 failed: %2. Check the free disk space.")
                            .arg(out->file.fileName(), out->file.errorString());
        }
    }

    const CaptureExporter::Options &m_o;
    CaptureExporter::Result &m_r;
    std::vector<std::unique_ptr<Output>> m_outputs;
    std::map<QString, Output *> m_byType;
    Output *m_single = nullptr;
    bool m_failed = false;
    std::unique_ptr<capture::McapRecording> m_mcap;
    std::unique_ptr<MatExport> m_mat;
    int m_matDevice = -1;
};

} // namespace

QString CaptureExporter::extension(Format format)
{
    switch (format) {
    case Format::JsonLines: return QStringLiteral(".jsonl");
    case Format::Mcap: return QStringLiteral(".mcap");
    case Format::Mat: return QStringLiteral(".mat");
    case Format::VendorCsv:
    case Format::TidyCsv: break;
    }
    return QStringLiteral(".csv");
}

std::optional<CaptureExporter::Format> CaptureExporter::parseFormat(const QString &name)
{
    if (name == QLatin1String("vendor-csv"))
        return Format::VendorCsv;
    if (name == QLatin1String("csv"))
        return Format::TidyCsv;
    if (name == QLatin1String("jsonl"))
        return Format::JsonLines;
    if (name == QLatin1String("mcap"))
        return Format::Mcap;
    if (name == QLatin1String("mat"))
        return Format::Mat;
    return std::nullopt;
}

QString CaptureExporter::vendorPath(const QString &output, const QString &type)
{
    const QFileInfo info(output);
    const QString suffix = type == QLatin1String("NMEA") ? QStringLiteral("txt") : QStringLiteral("csv");
    const QString stem = info.suffix().isEmpty() ? output : output.left(output.size() - info.suffix().size() - 1);
    return stem + QLatin1Char('_') + type + QLatin1Char('.') + suffix;
}

const char *CaptureExporter::tidyHeader(model::WorldFrame worldFrame)
{
    // One header, its attitude columns named for the frame the module reports in.
    const auto header = [](const char *frame) {
        const std::string f = frame;
        return "time_s,host_time_s,frame_tag,main_status,acc_x_mps2,acc_y_mps2,acc_z_mps2,gyr_x_radps,gyr_y_radps,"
               "gyr_z_radps,mag_x_uT,mag_y_uT,mag_z_uT,roll" + f + "_deg,pitch" + f + "_deg,yaw" + f + "_deg,quat" + f
            + "_w,quat" + f + "_x,quat" + f + "_y,quat" + f + "_z,pressure_Pa,temperature_degC,lat_deg,lon_deg,alt_m,"
              "vel_e_mps,vel_n_mps,vel_u_mps,common_time_s,common_uncertainty_s,heading_deg,mag_rel_x,mag_rel_y,"
              "mag_rel_z,mag_roll_deg";
    };
    static const std::string enu = header(""), nwu = header("_nwu");
    return (worldFrame == model::WorldFrame::Nwu ? nwu : enu).c_str();
}

void CaptureExporter::appendTidyRow(std::string &out, const model::Sample &s, int frameTag, int64_t originNs)
{
    const double hostS = double(s.hostTimeNs - originNs) / 1e9;
    using namespace model;
    // Values come from single-precision frames: float text keeps every digit they have.
    auto num = [&](double v) {
        out += ',';
        appendNumber(out, float(v));
    };
    auto gap = [&](int n) { out.append(size_t(n), ','); };
    auto vec = [&](SampleField f, const Vec3 &v, double k) {
        if (s.has(f)) {
            num(v.x * k);
            num(v.y * k);
            num(v.z * k);
        } else {
            gap(3);
        }
    };
    if (s.has(FieldDeviceTime))
        csv::appendFixed(out, s.deviceTimeMs / 1000.0, 6);
    out += ',';
    csv::appendFixed(out, hostS, 6);
    out += ',';
    appendInt(out, frameTag);
    out += ',';
    if (s.has(FieldMainStatus))
        appendInt(out, s.mainStatus);
    vec(FieldAcc, s.acc, kGravity);
    vec(FieldGyr, s.gyr, kDegToRad);
    vec(FieldMag, s.mag, 1.0);
    if (s.has(FieldEuler)) {
        num(s.roll);
        num(s.pitch);
        num(s.yaw);
    } else {
        gap(3);
    }
    if (s.has(FieldQuat)) {
        num(s.quat.w);
        num(s.quat.x);
        num(s.quat.y);
        num(s.quat.z);
    } else {
        gap(4);
    }
    if (s.has(FieldPressure))
        num(s.pressurePa);
    else
        gap(1);
    if (s.has(FieldTemperature))
        num(s.temperatureC);
    else
        gap(1);
    if (s.has(FieldPosition)) { // double precision in HI81/HI83
        for (double v : {s.latitudeDeg, s.longitudeDeg, s.altitudeM}) {
            out += ',';
            appendNumber(out, v);
        }
    } else {
        gap(3);
    }
    vec(FieldVelocity, s.velEnu, 1.0);
    out += ',';
    if (s.commonTimeNs != 0)
        csv::appendFixed(out, double(s.commonTimeNs - originNs) / 1e9, 6);
    out += ',';
    if (s.commonUncertaintyNs != 0)
        csv::appendFixed(out, double(s.commonUncertaintyNs) / 1e9, 6);
    // A compass's heading, clockwise from north 0..360 (yaw above is the world frame's, ENU).
    if (s.has(FieldHeading))
        num(s.headingDeg);
    else
        gap(1);
    // The HEC495's relative magnetic field (no unit) and magnetic roll (tool face, deg).
    vec(FieldMagRelative, s.magRelative, 1.0);
    if (s.has(FieldMagRoll))
        num(s.magRollDeg);
    else
        gap(1);
    out += '\n';
}

CaptureExporter::Result CaptureExporter::run(const QString &capturePath, const Options &options,
                                             const Progress &progress)
{
    Result r;
    if (options.output.isEmpty()) {
        r.error = tr("No output file was given.");
        return r;
    }
    if (!(options.toS >= options.fromS)) {
        r.error = tr("The time range is empty (from %1 s to %2 s).").arg(options.fromS).arg(options.toS);
        return r;
    }
    // A capture, or a vendor CSV or raw byte dump converted to one (recognised by content).
    CaptureSource source;
    capture::CaptureReader reader;
    if (!source.prepare(capturePath, &r.error) || !reader.open(source.capturePath(), &r.error))
        return r;
    r.notes = source.notes();
    const double total = double(std::max<qint64>(reader.size(), 1));
    ExportSink sink(options, r);
    sink.worldFrame = reader.header().identity().worldFrame;
    if (sink.worldFrame == model::WorldFrame::Nwu && options.format == Format::VendorCsv)
        r.notes << tr("The module reports its attitude in North-West-Up (CONFIG IMU COORD 4); the vendor CSV's "
                      "layout has no column to say so: its angles and quaternion are NWU.");
    capture::CaptureDecoder decoder;
    if (!decoder.configure(reader.header())) {
        r.error = decoder.error();
        return r;
    }
    sink.header = &reader.header();
    if (options.format == Format::VendorCsv)
        sink.layout = decode::vendorLayoutFor(decoder.family());
    sink.pcCounterIsChunkTime = reader.header().value(capture::CaptureHeader::kPcCounter) == "chunk time";
    capture::CaptureReader::Chunk c;
    capture::CaptureReader::Result res;
    bool first = true;
    qint64 nextReport = 0;
    const int64_t fromNs = int64_t(options.fromS * 1e9);
    const double toNs = options.toS * 1e9;
    while ((res = reader.next(c)) == capture::CaptureReader::Result::Chunk || res == capture::CaptureReader::Result::Damaged) {
        if (res == capture::CaptureReader::Result::Damaged)
            continue;
        if (first) {
            sink.firstNs = c.monotonicNs;
            // The capture's clock on the Unix epoch: the first chunk's wall time less its host time.
            sink.epochOffsetNs = c.wallUs > 0 ? c.wallUs * 1000 - c.monotonicNs : 0;
            first = false;
        }
        const int64_t rel = c.monotonicNs - sink.firstNs;
        if (double(rel) > toNs)
            break;
        if (c.kind == capture::ChunkVendorCells) {
            // For the frame of the next chunk (only the vendor CSV has columns for them).
            if (rel >= fromNs && options.format == Format::VendorCsv)
                if (sink.layout)
                    sink.keptCells =
                        sink.layout->decodeCells(std::string_view(reinterpret_cast<const char *>(c.data), c.size));
            continue;
        }
        if (rel >= fromNs)
            decoder.feedChunk(c, sink);
        sink.keptCells.clear();
        if (sink.failed())
            break;
        if (progress && reader.position() >= nextReport) {
            nextReport = reader.position() + (1 << 20);
            if (!progress(double(reader.position()) / total)) {
                r.cancelled = true;
                sink.removeOutputs();
                r.error = tr("Export cancelled.");
                return r;
            }
        }
    }
    if (!sink.failed())
        decoder.finish(sink);
    if (res == capture::CaptureReader::Result::Truncated)
        r.warning = reader.message();
    else if (reader.damagedChunks() > 0)
        r.warning = tr("%n damaged chunk(s) were skipped", nullptr, int(reader.damagedChunks()));
    r.ok = sink.finish();
    if (progress && r.ok)
        progress(1.0);
    return r;
}

} // namespace imudesk::record
