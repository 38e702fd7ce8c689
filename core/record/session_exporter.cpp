#include "session_exporter.h"

#include "decode/stream_decoder.h"
#include "format/sample_json.h"
#include "model/sample.h"
#include "clock/trigger_pairing.h"
#include "record/capture_sample_stream.h"
#include "format/csv_number.h"
#include "capture/device_name.h"
#include "record/mat_export.h"
#include "capture/mcap_recording.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QSaveFile>

#include <cmath>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <set>

namespace imudesk::record {

namespace csv = format::csv;

namespace {

// Linear interpolation of a device's values at t between two samples.
struct Interpolated {
    double acc[3], gyr[3], rpy[3];
};
std::optional<Interpolated> interpolate(const model::Sample &a, int64_t ta, const model::Sample &b, int64_t tb, int64_t t)
{
    if (tb <= ta || t < ta || t > tb)
        return std::nullopt;
    const double f = double(t - ta) / double(tb - ta);
    auto mix = [f](double x, double y) { return x + (y - x) * f; };
    // Angles across +-180: the short way round.
    auto mixAngle = [f](double x, double y) {
        double d = std::remainder(y - x, 360.0);
        return std::remainder(x + d * f, 360.0);
    };
    Interpolated v{};
    v.acc[0] = mix(a.acc.x, b.acc.x) * model::kGravity;
    v.acc[1] = mix(a.acc.y, b.acc.y) * model::kGravity;
    v.acc[2] = mix(a.acc.z, b.acc.z) * model::kGravity;
    v.gyr[0] = mix(a.gyr.x, b.gyr.x) * model::kDegToRad;
    v.gyr[1] = mix(a.gyr.y, b.gyr.y) * model::kDegToRad;
    v.gyr[2] = mix(a.gyr.z, b.gyr.z) * model::kDegToRad;
    v.rpy[0] = mixAngle(a.roll, b.roll);
    v.rpy[1] = mixAngle(a.pitch, b.pitch);
    v.rpy[2] = mixAngle(a.yaw, b.yaw);
    return v;
}

// The stream whose next sample comes first on the session's aligned time; streams.size() when
// every stream has ended.
size_t nextInTime(const std::vector<std::unique_ptr<CaptureSampleStream>> &streams)
{
    size_t next = streams.size();
    int64_t best = 0;
    for (size_t i = 0; i < streams.size(); ++i)
        if (const model::Sample *p = streams[i]->peek()) {
            const int64_t k = streams[i]->key(*p);
            if (next == streams.size() || k < best) {
                next = i;
                best = k;
            }
        }
    return next;
}

// The session as one MCAP file: each device's channels under its own name (its serial number,
// or the session's name for it when two devices share one), every sample at its aligned time;
// session.json and each device's configuration as attachments, each device's identity as metadata.
void writeMcap(const QString &folder, const SessionManifest &manifest,
               std::vector<std::unique_ptr<CaptureSampleStream>> &streams, const SessionExporter::Options &o,
               SessionExporter::Result &r)
{
    namespace fm = format::mcap;
    const QDateTime started = QDateTime::fromString(manifest.startedUtc, Qt::ISODateWithMs);
    const int64_t epochOffsetNs =
        started.isValid() && manifest.startedHostNs != 0 ? started.toMSecsSinceEpoch() * 1'000'000 - manifest.startedHostNs : 0;
    fm::McapWriter w;
    if (!w.open(o.output, capture::McapRecording::writerOptions())) {
        r.error = SessionExporter::tr("Cannot write %1: %2").arg(o.output, w.error());
        return;
    }
    const uint64_t now = uint64_t(QDateTime::currentMSecsSinceEpoch()) * 1'000'000u;
    w.addMetadata("session", {{"started_utc", manifest.startedUtc.toStdString()},
                              {"devices", std::to_string(streams.size())}});
    w.addMetadata("time", capture::McapRecording::timeMetadata());
    QFile json(QDir(folder).filePath(QLatin1String(SessionManifest::kFileName)));
    if (json.open(QIODevice::ReadOnly))
        w.attach("session.json", "application/json", json.readAll().toStdString(), now, now);
    std::vector<std::unique_ptr<fm::SampleChannels>> channels;
    std::set<std::string> names;
    for (size_t i = 0; i < streams.size(); ++i) {
        const capture::CaptureHeader &h = streams[i]->header();
        // The manifest's name is the label (an older session's names its port): the device's
        // own name first (capture/device_name.h), _2 for a second of the same.
        const std::string name = fm::SampleChannels::uniqueName(deviceName(h, manifest.devices[i].name.toStdString()),
                                                                [&names](const std::string &n) { return names.count(n) > 0; });
        names.insert(name);
        fm::SampleChannels::Device d = capture::McapRecording::channelsOf(h, name);
        d.onChangeOnly = true; // a file's layout
        w.addMetadata("device " + d.name, d.metadata);
        if (const std::string config = capture::McapRecording::configurationJson(h); !config.empty())
            w.attach(d.name + "/configuration.json", "application/json", config, now, now);
        channels.push_back(std::make_unique<fm::SampleChannels>(w, d));
    }
    for (size_t next; (next = nextInTime(streams)) < streams.size();) {
        if (!channels[next]->write(streams[next]->take(), epochOffsetNs))
            break;
        ++r.rows;
        if (o.cancelled && (r.rows & 0xFFF) == 0 && o.cancelled()) {
            w.abandon();
            QFile::remove(o.output);
            r.error = SessionExporter::tr("Export cancelled.");
            return;
        }
    }
    if (!w.close()) {
        QFile::remove(o.output);
        r.error = SessionExporter::tr("Writing %1 failed: %2. Free some space or choose another place.").arg(o.output, w.error());
        return;
    }
    for (const auto &st : streams)
        r.samplesByDevice.push_back(st->samples);
    r.ok = true;
}

// A recorded session into one MATLAB file: a struct per device, its samples at their aligned
// times, every device's times from the session's start.
void writeMat(const SessionManifest &manifest, std::vector<std::unique_ptr<CaptureSampleStream>> &streams,
              const SessionExporter::Options &o, SessionExporter::Result &r)
{
    const QDateTime started = QDateTime::fromString(manifest.startedUtc, Qt::ISODateWithMs);
    const int64_t epochOffsetNs =
        started.isValid() && manifest.startedHostNs != 0 ? started.toMSecsSinceEpoch() * 1'000'000 - manifest.startedHostNs : 0;
    MatExport mat(manifest.startedHostNs, epochOffsetNs);
    std::vector<int> structs;
    for (size_t i = 0; i < streams.size(); ++i) {
        const capture::CaptureHeader &h = streams[i]->header();
        const int index = mat.addDevice(h, manifest.devices[i].name.toStdString());
        if (index < 0) {
            r.error = mat.error();
            return;
        }
        structs.push_back(index);
    }
    for (size_t next; (next = nextInTime(streams)) < streams.size();) {
        if (!mat.append(structs[next], streams[next]->take())) {
            r.error = mat.error();
            return;
        }
        ++r.rows;
        if (o.cancelled && (r.rows & 0xFFF) == 0 && o.cancelled()) {
            r.error = SessionExporter::tr("Export cancelled.");
            return;
        }
    }
    if (!mat.write(o.output)) {
        r.error = mat.error();
        return;
    }
    for (const auto &st : streams)
        r.samplesByDevice.push_back(st->samples);
    r.ok = true;
}

} // namespace

SessionExporter::Result SessionExporter::run(const QString &folder, const Options &o)
{
    Result r;
    SessionManifest manifest;
    if (!SessionManifest::load(folder, &manifest, &r.error))
        return r;
    if (o.format == CaptureExporter::Format::VendorCsv) {
        r.error = tr("A session of several devices exports to tidy CSV, JSON Lines, MCAP or MATLAB; the vendor's layout has "
                     "one device per file (export each capture on its own for it).");
        return r;
    }
    if ((o.gridMs > 0 || o.pulseHz > 0) && o.format != CaptureExporter::Format::TidyCsv) {
        r.error = tr("A grid or trigger pairs are written as tidy CSV (--format csv).");
        return r;
    }
    if (o.output.isEmpty()) {
        r.error = tr("No output file was given.");
        return r;
    }
    if (!std::isfinite(o.gridMs) || !std::isfinite(o.pulseHz) || (o.gridMs > 0 && o.gridMs < 0.01)
        || o.pulseHz > 10000 || (o.gridMs > 0 && o.pulseHz > 0)) {
        r.error = tr("A grid of at least 0.01 ms, or a pulse rate up to 10 kHz, not both.");
        return r;
    }
    std::vector<std::unique_ptr<CaptureSampleStream>> streams;
    for (const SessionManifest::Device &d : manifest.devices) {
        auto s = std::make_unique<CaptureSampleStream>();
        s->name = d.name;
        s->offsetNs = std::llround(d.offsetNs);
        QString error;
        if (!s->open(QDir(folder).filePath(d.file), &error)) {
            r.error = tr("Device %1: %2").arg(d.name, error);
            return r;
        }
        if (d.droppedOut())
            r.notes << tr("Device %1 dropped out during the recording (session.json says when); its data ends there.")
                           .arg(d.name);
        streams.push_back(std::move(s));
    }
    if (streams.empty()) {
        r.error = tr("The session holds no device.");
        return r;
    }
    if (o.format == CaptureExporter::Format::Mcap) {
        writeMcap(folder, manifest, streams, o, r);
        return r;
    }
    if (o.format == CaptureExporter::Format::Mat) {
        writeMat(manifest, streams, o, r);
        return r;
    }
    QSaveFile file(o.output);
    if (!file.open(QIODevice::WriteOnly)) {
        r.error = tr("Cannot write %1: %2").arg(o.output, file.errorString());
        return r;
    }
    const int64_t origin = manifest.startedHostNs;
    std::string buf;
    auto flush = [&](bool force) {
        if (!force && buf.size() < (1u << 20))
            return true;
        const bool ok = file.write(buf.data(), qint64(buf.size())) == qint64(buf.size());
        buf.clear();
        return ok;
    };
    bool writeOk = true;
    if (o.pulseHz > 0) {
        // Every triggered frame (a frame with a device time) of every device, compactly; then one
        // row per pulse index.
        struct Frame {
            int64_t commonNs;
            double v[9];
        };
        const auto period = int64_t(1e9 / o.pulseHz);
        clock::TriggerPairing pairing(period);
        std::vector<std::vector<Frame>> frames(streams.size());
        for (size_t i = 0; i < streams.size(); ++i) {
            CaptureSampleStream &s = *streams[i];
            int64_t first = 0;
            std::string source; // the device's triggered frame type
            while (s.peek()) {
                const model::Sample x = s.take();
                if (!x.has(model::FieldDeviceTime) || x.commonTimeNs == 0)
                    continue;
                if (source.empty())
                    source = x.source;
                if (x.source != source)
                    continue;
                if (o.cancelled && (s.samples & 0xFFF) == 0 && o.cancelled()) {
                    r.error = tr("Export cancelled.");
                    return r;
                }
                if (first == 0)
                    first = x.commonTimeNs;
                // The clock model settles within its first 2 s: the frame that ties this
                // device's count to the others' comes after them.
                const bool aligned = x.commonTimeNs - first >= 2'000'000'000;
                pairing.add(int(i), std::llround(x.deviceTimeMs * 1e6), x.commonTimeNs, aligned);
                frames[i].push_back(Frame{x.commonTimeNs,
                                          {x.acc.x * model::kGravity, x.acc.y * model::kGravity, x.acc.z * model::kGravity,
                                           x.gyr.x * model::kDegToRad, x.gyr.y * model::kDegToRad,
                                           x.gyr.z * model::kDegToRad, x.roll, x.pitch, x.yaw}});
            }
        }
        std::map<int64_t, std::vector<const Frame *>> rows;
        for (size_t i = 0; i < streams.size(); ++i) {
            const auto idx = pairing.indices(int(i));
            for (size_t j = 0; j < idx.size(); ++j)
                if (idx[j]) {
                    auto &row = rows[*idx[j]];
                    row.resize(streams.size(), nullptr);
                    row[i] = &frames[i][j];
                }
        }
        buf += "pulse,time_s";
        for (auto &s : streams)
            for (const char *col : {"acc_x_mps2", "acc_y_mps2", "acc_z_mps2", "gyr_x_radps", "gyr_y_radps", "gyr_z_radps",
                                    "roll_deg", "pitch_deg", "yaw_deg"})
                buf += ',' + s->name.toStdString() + '_' + col;
        buf += '\n';
        const int64_t firstIndex = rows.empty() ? 0 : rows.begin()->first; // pulses counted from 0
        for (const auto &[index, row] : rows) {
            // The pulse's time: the mean of its frames' common times.
            double sum = 0;
            int n = 0;
            for (const Frame *f : row)
                if (f) {
                    sum += double(f->commonNs - origin);
                    ++n;
                }
            buf += std::to_string(index - firstIndex);
            buf += ',';
            csv::appendFixed(buf, sum / n / 1e9, 6);
            for (const Frame *f : row)
                for (int k = 0; k < 9; ++k) {
                    buf += ',';
                    if (f)
                        csv::appendFixed(buf, f->v[k], 6);
                }
            buf += '\n';
            ++r.rows;
            if (!(writeOk = flush(false)))
                break;
        }
        const clock::TriggerPairing::Summary sum = pairing.summary();
        r.pulses = sum.pulses;
        r.pulsesComplete = sum.complete;
        if (sum.unindexed > 0)
            r.notes << tr("%1 frames of devices whose clock never aligned have no pulse index.").arg(sum.unindexed);
    } else if (o.gridMs <= 0) {
        if (o.format == CaptureExporter::Format::TidyCsv) {
            buf += "device,";
            buf += CaptureExporter::tidyHeader(streams.front()->worldFrame());
            buf += '\n';
        }
        // The next sample of all devices, by aligned time.
        for (size_t i; (i = nextInTime(streams)) < streams.size();) {
            CaptureSampleStream *next = streams[i].get();
            const model::Sample s = next->take();
            const std::string name = next->name.toStdString();
            if (o.format == CaptureExporter::Format::TidyCsv) {
                buf += name;
                buf += ',';
                CaptureExporter::appendTidyRow(buf, s, decode::recordTagOf(s.source), origin);
            } else {
                const std::string json = format::sampleToJson(s, next->worldFrame());
                buf += "{\"device\":\"" + name + "\",";
                buf.append(json, 1, std::string::npos);
                buf += '\n';
            }
            ++r.rows;
            if (!(writeOk = flush(false)))
                break;
            if (o.cancelled && (r.rows & 0xFFF) == 0 && o.cancelled()) {
                r.error = tr("Export cancelled.");
                return r;
            }
        }
    } else {
        // The grid: each device's two samples around the instant.
        buf += "time_s";
        for (auto &s : streams)
            for (const char *col : {"acc_x_mps2", "acc_y_mps2", "acc_z_mps2", "gyr_x_radps", "gyr_y_radps", "gyr_z_radps",
                                    "roll_deg", "pitch_deg", "yaw_deg"})
                buf += ',' + s->name.toStdString() + '_' + col;
        buf += '\n';
        struct Around {
            std::optional<model::Sample> prev;
            int64_t prevKey = 0;
        };
        std::vector<Around> around(streams.size());
        const auto step = int64_t(o.gridMs * 1e6);
        const auto maxGap = int64_t(o.maxGapMs * 1e6);
        // The grid starts at the first sample of any device, on a whole step from the origin.
        int64_t first = INT64_MAX;
        for (auto &s : streams)
            if (const model::Sample *p = s->peek())
                first = std::min(first, s->key(*p));
        if (first != INT64_MAX) {
            int64_t t = origin + ((first - origin) / step + 1) * step;
            for (;;) {
                bool anyLeft = false;
                std::string row;
                csv::appendFixed(row, double(t - origin) / 1e9, 6);
                for (size_t i = 0; i < streams.size(); ++i) {
                    CaptureSampleStream &s = *streams[i];
                    Around &a = around[i];
                    const model::Sample *p = nullptr;
                    while ((p = s.peek()) && s.key(*p) <= t) {
                        a.prevKey = s.key(*p);
                        a.prev = s.take();
                    }
                    anyLeft = anyLeft || p;
                    std::optional<Interpolated> v;
                    if (p && a.prev && s.key(*p) - a.prevKey <= maxGap)
                        v = interpolate(*a.prev, a.prevKey, *p, s.key(*p), t);
                    for (int k = 0; k < 9; ++k) {
                        row += ',';
                        if (v)
                            csv::appendFixed(row, k < 3 ? v->acc[k] : k < 6 ? v->gyr[k - 3] : v->rpy[k - 6], 6);
                    }
                }
                if (!anyLeft)
                    break;
                buf += row;
                buf += '\n';
                ++r.rows;
                if (!(writeOk = flush(false)))
                    break;
                t += step;
            }
        }
    }
    for (size_t i = 0; i < streams.size(); ++i) {
        r.samplesByDevice.push_back(streams[i]->samples);
        if (streams[i]->samples == 0)
            r.notes << tr("Device %1 (%2): nothing in its capture that ImuDesk decodes offline (Modbus "
                          "captures are not decoded yet); it is left out.")
                           .arg(manifest.devices[i].name, manifest.devices[i].linkKind);
    }
    if (!writeOk || !flush(true) || !file.commit()) {
        r.error = tr("Writing %1 failed: %2. Free some space or choose another place.").arg(o.output, file.errorString());
        return r;
    }
    r.ok = true;
    return r;
}

} // namespace imudesk::record
