#include "magnetometer_file.h"

#include "calib/sample_csv.h"
#include "capture/capture_format.h"
#include "decode/file_import.h"
#include "record/capture_source.h"
#include "record/sample_file.h"

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

// A capture, vendor CSV, raw dump or a session's member: the first frame type that carries a
// magnetometer in uT.
Result readRecording(const QString &path, const QString &device)
{
    Result r;
    std::string type;
    const SampleFile::Opened opened = SampleFile::forEachSample(path, device, [&](const model::Sample &s) {
        if (!s.has(model::FieldMag) || r.samples.size() >= MagnetometerFile::kMaxSamples)
            return;
        if (type.empty())
            type = s.source;
        if (s.source == type)
            r.samples.emplace_back(s.mag.x, s.mag.y, s.mag.z);
    });
    r.kind = opened.kind;
    r.device = opened.device;
    r.notes = opened.notes;
    if (!opened.ok) {
        r.error = opened.error;
        return r;
    }
    if (r.samples.empty()) {
        r.error = MagnetometerFile::tr("%1 holds no magnetometer samples in µT (a %2): record the module's output "
                                       "with its magnetometer (HI91, HI81 or HI83)")
                      .arg(QDir::toNativeSeparators(path), r.kind);
        return r;
    }
    r.source = QString::fromStdString(type);
    r.ok = true;
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
    if (QFileInfo(path).isDir())
        return readRecording(path, device);
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return failed(tr("cannot read %1: %2").arg(QDir::toNativeSeparators(path), f.errorString()));
    const QByteArray head = f.peek(decode::kSniffBytes);
    const QByteArray start = head.trimmed();
    const bool capture = head.startsWith(QByteArray(capture::kMagic, sizeof capture::kMagic));
    const QByteArray firstLine = start.left(start.indexOf('\n')).trimmed();
    bool text = !capture && !start.isEmpty();
    for (char ch : firstLine)
        text = text && ((ch >= 0x20 && ch < 0x7f) || ch == '\t' || ch == '\r' || uint8_t(ch) >= 0x80);
    const bool json = text && start.startsWith('{');
    const bool csv = text && !json && firstLine.contains(',') && !firstLine.startsWith('$');
    if (!json && !csv) {
        f.close();
        return readRecording(path, device);
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
