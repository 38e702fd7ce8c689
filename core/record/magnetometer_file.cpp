#include "magnetometer_file.h"

#include "calib/sample_csv.h"
#include "capture/capture_decoder.h"
#include "capture/capture_format.h"
#include "capture/capture_reader.h"
#include "record/capture_source.h"
#include "record/session_manifest.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace imudesk::record {

namespace {

using Result = MagnetometerFile::Result;

Result failed(const QString &error)
{
    Result r;
    r.error = error;
    return r;
}

// "A, B and C" for a list of device names.
QString nameList(const QStringList &names)
{
    return names.join(QStringLiteral(", "));
}

Result readCapture(const QString &path)
{
    Result r;
    CaptureSource source;
    if (!source.prepare(path, &r.error))
        return r;
    r.kind = QString::fromLatin1(CaptureSource::kindName(source.kind()));
    r.notes << source.notes();
    capture::CaptureReader reader;
    if (!reader.open(source.capturePath(), &r.error))
        return r;
    struct Sink : capture::CaptureDecoder::Sink {
        Result *r = nullptr;
        std::string type;    // the frame type read: the first with a magnetometer
        uint64_t others = 0; // samples of that type without one
        void take(const model::Sample &s)
        {
            if (!s.has(model::FieldMag) || r->samples.size() >= MagnetometerFile::kMaxSamples) {
                if (!type.empty() && s.source == type)
                    ++others;
                return;
            }
            if (type.empty())
                type = s.source;
            if (s.source == type)
                r->samples.emplace_back(s.mag.x, s.mag.y, s.mag.z);
        }
        void onPacket(const protocol::hipnuc::Packet &p, int64_t) override { take(protocol::hipnuc::toSample(p)); }
        void onSample(const model::Sample &s, int64_t) override { take(s); }
    } sink;
    sink.r = &r;
    capture::CaptureDecoder decoder;
    decoder.configure(reader.header());
    capture::CaptureReader::Chunk c;
    capture::CaptureReader::Result res;
    while ((res = reader.next(c)) == capture::CaptureReader::Result::Chunk || res == capture::CaptureReader::Result::Damaged)
        if (res == capture::CaptureReader::Result::Chunk)
            decoder.feedChunk(c, sink);
    decoder.finish(sink);
    if (res == capture::CaptureReader::Result::Truncated)
        r.notes << reader.message();
    if (r.samples.empty()) {
        r.error = MagnetometerFile::tr("%1 holds no magnetometer samples in µT (a %2): record the module's output "
                                       "with its magnetometer (HI91, HI81 or HI83)")
                      .arg(QDir::toNativeSeparators(path), r.kind);
        return r;
    }
    r.source = QString::fromStdString(sink.type);
    r.ok = true;
    return r;
}

Result readSession(const QString &folder, const QString &device)
{
    SessionManifest manifest;
    QString error;
    if (!SessionManifest::load(folder, &manifest, &error))
        return failed(error);
    QStringList names;
    const SessionManifest::Device *chosen = nullptr;
    for (const auto &d : manifest.devices) {
        names << d.name;
        if (d.name == device)
            chosen = &d;
    }
    if (!device.isEmpty() && !chosen)
        return failed(MagnetometerFile::tr("the session %1 has no device %2; its devices: %3")
                          .arg(QDir::toNativeSeparators(folder), device, nameList(names)));
    if (!chosen) {
        if (manifest.devices.size() != 1)
            return failed(MagnetometerFile::tr("the session %1 holds %2 devices (%3): choose one with --device NAME")
                              .arg(QDir::toNativeSeparators(folder))
                              .arg(manifest.devices.size())
                              .arg(nameList(names)));
        chosen = &manifest.devices.front();
    }
    Result r = readCapture(QDir(folder).filePath(chosen->file));
    r.kind = MagnetometerFile::tr("session");
    r.device = chosen->name;
    return r;
}

Result readJsonLines(const QByteArray &text, const QString &device)
{
    Result r;
    r.kind = QStringLiteral("JSON Lines");
    QStringList devices;
    uint64_t without = 0, others = 0;
    qsizetype pos = 0;
    int lineNo = 0;
    while (pos < text.size()) {
        qsizetype end = text.indexOf('\n', pos);
        if (end < 0)
            end = text.size();
        ++lineNo;
        const QByteArray line = text.mid(pos, end - pos).trimmed();
        pos = end + 1;
        if (line.isEmpty())
            continue;
        QJsonParseError pe;
        const QJsonDocument doc = QJsonDocument::fromJson(line, &pe);
        if (!doc.isObject())
            return failed(MagnetometerFile::tr("line %1 is not a JSON object: %2").arg(lineNo).arg(pe.errorString()));
        const QJsonObject o = doc.object();
        if (o.contains(QLatin1String("device"))) {
            const QString d = o.value(QLatin1String("device")).toString();
            if (!devices.contains(d) && devices.size() < 100)
                devices << d;
            if (!device.isEmpty() && d != device) {
                ++others;
                continue;
            }
        }
        if (!o.contains(QLatin1String("mag"))) {
            ++without;
            continue;
        }
        const QJsonArray mag = o.value(QLatin1String("mag")).toArray();
        if (mag.size() != 3 || !mag.at(0).isDouble() || !mag.at(1).isDouble() || !mag.at(2).isDouble())
            return failed(MagnetometerFile::tr("line %1, key mag: three numbers [x, y, z] in µT are needed").arg(lineNo));
        if (r.samples.size() >= MagnetometerFile::kMaxSamples)
            return failed(MagnetometerFile::tr("more than %1 samples").arg(MagnetometerFile::kMaxSamples));
        r.samples.emplace_back(mag.at(0).toDouble(), mag.at(1).toDouble(), mag.at(2).toDouble());
    }
    if (device.isEmpty() && devices.size() > 1)
        return failed(MagnetometerFile::tr("the file holds %1 devices (%2): choose one with --device NAME")
                          .arg(devices.size())
                          .arg(nameList(devices)));
    if (!device.isEmpty() && !devices.contains(device))
        return failed(MagnetometerFile::tr("the file has no device %1; its devices: %2").arg(device, nameList(devices)));
    if (r.samples.empty())
        return failed(MagnetometerFile::tr("no line has a key mag (the magnetometer, µT)"));
    if (without > 0)
        r.notes << MagnetometerFile::tr("%1 lines without a magnetometer passed over").arg(without);
    r.device = devices.size() == 1 ? devices.front() : device;
    r.source = QStringLiteral("mag");
    r.ok = true;
    return r;
}

Result readCsv(const QByteArray &text, const QString &device)
{
    Result r;
    r.kind = QStringLiteral("CSV");
    calib::SampleCsv::ColumnChoice choice;
    choice.wanted = calib::SampleCsv::magnetometerColumns();
    choice.keyColumn = QStringLiteral("device");
    choice.keyValue = device;
    calib::SampleCsv::ColumnInfo info;
    calib::SampleTable table;
    if (!calib::SampleCsv::parseColumns(text, choice, table, &r.error, &info))
        return r;
    if (device.isEmpty() && info.keys.size() > 1)
        return failed(MagnetometerFile::tr("the file holds %1 devices (%2): choose one with --device NAME")
                          .arg(info.keys.size())
                          .arg(nameList(info.keys)));
    if (!device.isEmpty() && !info.keys.contains(device))
        return failed(info.keys.isEmpty()
                          ? MagnetometerFile::tr("--device %1: the file has no device column").arg(device)
                          : MagnetometerFile::tr("the file has no device %1; its devices: %2").arg(device, nameList(info.keys)));
    if (!calib::SampleCsv::magnetometer(table, r.samples, &r.error))
        return r;
    if (info.emptyRows > 0)
        r.notes << MagnetometerFile::tr("%1 rows without a magnetometer passed over").arg(info.emptyRows);
    r.source = table.columns.join(QStringLiteral(", "));
    r.device = info.keys.size() == 1 ? info.keys.front() : device;
    r.ok = true;
    return r;
}

} // namespace

MagnetometerFile::Result MagnetometerFile::read(const QString &path, const QString &device)
{
    const QFileInfo fi(path);
    if (fi.isDir()) {
        if (!SessionManifest::isSessionFolder(path))
            return failed(tr("%1 is a folder without session.json: give a file, or a recorded session's folder")
                              .arg(QDir::toNativeSeparators(path)));
        return readSession(path, device);
    }
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return failed(tr("cannot read %1: %2").arg(QDir::toNativeSeparators(path), f.errorString()));
    const QByteArray head = f.peek(CaptureSource::kSniffBytes);
    const QByteArray start = head.trimmed();
    const bool capture = head.startsWith(QByteArray(capture::kMagic, sizeof capture::kMagic));
    const QByteArray firstLine = start.left(start.indexOf('\n')).trimmed();
    bool text = !capture && !start.isEmpty();
    for (char ch : firstLine)
        text = text && ((ch >= 0x20 && ch < 0x7f) || ch == '\t' || ch == '\r' || uint8_t(ch) >= 0x80);
    const bool json = text && start.startsWith('{');
    const bool csv = text && !json && firstLine.contains(',') && !firstLine.startsWith('$');
    if (!json && !csv) {
        if (!capture && !device.isEmpty())
            return failed(tr("--device chooses a device of a session: %1 is not one").arg(QDir::toNativeSeparators(path)));
        f.close();
        return readCapture(path);
    }
    if (f.size() > kMaxTextBytes)
        return failed(tr("%1 is larger than %2 MB; split it").arg(QDir::toNativeSeparators(path)).arg(kMaxTextBytes >> 20));
    const QByteArray all = f.readAll();
    Result r = json ? readJsonLines(all, device) : readCsv(all, device);
    if (!r.ok)
        r.error = tr("%1: %2").arg(QDir::toNativeSeparators(path), r.error);
    return r;
}

} // namespace imudesk::record
