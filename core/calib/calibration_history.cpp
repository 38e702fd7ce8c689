#include "calib/calibration_history.h"

#include <QDir>
#include <QFileInfo>
#include <QFile>
#include <QJsonDocument>
#include <QSaveFile>
#include <QStandardPaths>

#include <algorithm>

namespace imudesk::calib {

namespace {
const QString kRecordFile = QStringLiteral("record.json");
const QString kSamplesFile = QStringLiteral("samples.csv");
constexpr qint64 kMaxRecordBytes = 4 * 1024 * 1024;
constexpr qint64 kMaxSamplesBytes = 256 * 1024 * 1024;
} // namespace

QJsonObject CalibrationRecord::toJson() const
{
    QJsonObject o;
    o.insert(QStringLiteral("kind"), kind);
    o.insert(QStringLiteral("time"), time.toUTC().toString(Qt::ISODateWithMs));
    QJsonObject dev;
    dev.insert(QStringLiteral("serial"), deviceSerial);
    dev.insert(QStringLiteral("product"), product);
    dev.insert(QStringLiteral("firmware"), firmware);
    o.insert(QStringLiteral("device"), dev);
    o.insert(QStringLiteral("result"), result);
    o.insert(QStringLiteral("samples"), sampleCount);
    return o;
}

bool CalibrationRecord::fromJson(const QJsonObject &o, CalibrationRecord &out)
{
    CalibrationRecord r;
    r.kind = o.value(QStringLiteral("kind")).toString();
    r.time = QDateTime::fromString(o.value(QStringLiteral("time")).toString(), Qt::ISODateWithMs);
    if (r.kind.isEmpty() || !r.time.isValid())
        return false;
    r.time = r.time.toUTC();
    const QJsonObject dev = o.value(QStringLiteral("device")).toObject();
    r.deviceSerial = dev.value(QStringLiteral("serial")).toString();
    r.product = dev.value(QStringLiteral("product")).toString();
    r.firmware = dev.value(QStringLiteral("firmware")).toString();
    r.result = o.value(QStringLiteral("result")).toObject();
    r.sampleCount = o.value(QStringLiteral("samples")).toInt();
    out = r;
    return true;
}

CalibrationHistory::CalibrationHistory(QString root)
    : m_root(std::move(root))
{
}

QString CalibrationHistory::defaultRoot()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/calibrations");
}

QString CalibrationHistory::deviceFolderName(const QString &serial)
{
    QString s;
    for (QChar c : serial)
        if ((c.isLetterOrNumber() && c.unicode() < 128) || c == QLatin1Char('-') || c == QLatin1Char('_'))
            s += c;
    s.truncate(64);
    return s.isEmpty() ? QStringLiteral("unknown") : s;
}

bool CalibrationHistory::save(CalibrationRecord &record, const SampleTable &samples, QString *error) const
{
    auto failWith = [error](const QString &m) {
        if (error)
            *error = m;
        return false;
    };
    if (record.kind.isEmpty())
        return failWith(tr("A calibration record needs a kind."));
    if (!record.time.isValid())
        record.time = QDateTime::currentDateTimeUtc();
    record.time = record.time.toUTC();
    record.sampleCount = int(samples.rows.size());
    QString kind;
    for (QChar c : record.kind)
        kind += c.isLetterOrNumber() && c.unicode() < 128 ? c : QLatin1Char('_');
    const QString deviceDir = m_root + QLatin1Char('/') + deviceFolderName(record.deviceSerial);
    const QString base = record.time.toString(QStringLiteral("yyyyMMdd'T'HHmmsszzz")) + QLatin1Char('-') + kind;
    QString dir = deviceDir + QLatin1Char('/') + base;
    for (int n = 2; QFileInfo::exists(dir) && n < 1000; ++n)
        dir = deviceDir + QLatin1Char('/') + base + QLatin1Char('-') + QString::number(n);
    if (QFileInfo::exists(dir) || !QDir().mkpath(dir))
        return failWith(tr("Cannot create the folder %1: check that the disk is writable.").arg(dir));
    QSaveFile json(dir + QLatin1Char('/') + kRecordFile);
    if (!json.open(QIODevice::WriteOnly))
        return failWith(tr("Cannot write %1: %2").arg(json.fileName(), json.errorString()));
    json.write(QJsonDocument(record.toJson()).toJson());
    if (!json.commit())
        return failWith(tr("Cannot write %1: %2").arg(json.fileName(), json.errorString()));
    QSaveFile csv(dir + QLatin1Char('/') + kSamplesFile);
    if (!csv.open(QIODevice::WriteOnly))
        return failWith(tr("Cannot write %1: %2").arg(csv.fileName(), csv.errorString()));
    csv.write(SampleCsv::write(samples));
    if (!csv.commit())
        return failWith(tr("Cannot write %1: %2").arg(csv.fileName(), csv.errorString()));
    record.folder = dir;
    return true;
}

QStringList CalibrationHistory::devices() const
{
    return QDir(m_root).entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name);
}

QList<CalibrationRecord> CalibrationHistory::list(const QString &deviceSerial) const
{
    QList<CalibrationRecord> out;
    const QDir dir(m_root + QLatin1Char('/') + deviceFolderName(deviceSerial));
    const QStringList runs = dir.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name);
    for (const QString &run : runs) {
        if (out.size() >= kMaxListed)
            break;
        QFile f(dir.filePath(run) + QLatin1Char('/') + kRecordFile);
        if (f.size() > kMaxRecordBytes || !f.open(QIODevice::ReadOnly))
            continue;
        CalibrationRecord r;
        if (!CalibrationRecord::fromJson(QJsonDocument::fromJson(f.readAll()).object(), r))
            continue;
        r.folder = dir.filePath(run);
        out.append(r);
    }
    std::stable_sort(out.begin(), out.end(), [](const CalibrationRecord &a, const CalibrationRecord &b) {
        return a.time != b.time ? a.time > b.time : a.folder > b.folder;
    });
    return out;
}

bool CalibrationHistory::loadSamples(const CalibrationRecord &record, SampleTable &out, QString *error) const
{
    QFile f(record.folder + QLatin1Char('/') + kSamplesFile);
    if (f.size() > kMaxSamplesBytes) {
        if (error)
            *error = tr("%1 is too large to load.").arg(f.fileName());
        return false;
    }
    if (!f.open(QIODevice::ReadOnly)) {
        if (error)
            *error = tr("Cannot read %1: %2").arg(f.fileName(), f.errorString());
        return false;
    }
    return SampleCsv::parse(f.readAll(), out, error);
}

bool CalibrationHistory::remove(const CalibrationRecord &record) const
{
    if (record.folder.isEmpty() || !record.folder.startsWith(m_root + QLatin1Char('/')))
        return false;
    return QDir(record.folder).removeRecursively();
}

} // namespace imudesk::calib
