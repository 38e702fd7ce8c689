#include "session_manifest.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>

namespace imudesk::record {

using device::ClockStats;
using State = clock::ClockModel::State;

const char *clockMethodName(ClockStats::Method m)
{
    switch (m) {
    case ClockStats::Method::Counter: return "counter";
    case ClockStats::Method::Bracket: return "bracket";
    case ClockStats::Method::Stamp: return "stamp";
    }
    return "counter";
}

const char *clockStateName(State s)
{
    switch (s) {
    case State::Aligned: return "aligned";
    case State::Uncertain: return "uncertain";
    case State::FreeRunning: return "free-running";
    }
    return "free-running";
}

namespace {

ClockStats::Method methodOf(const QString &name)
{
    if (name == QLatin1String("bracket"))
        return ClockStats::Method::Bracket;
    if (name == QLatin1String("stamp"))
        return ClockStats::Method::Stamp;
    return ClockStats::Method::Counter;
}

State stateOf(const QString &name)
{
    if (name == QLatin1String("aligned"))
        return State::Aligned;
    if (name == QLatin1String("uncertain"))
        return State::Uncertain;
    return State::FreeRunning;
}

} // namespace

bool SessionManifest::Device::droppedOut() const
{
    for (const Event &e : events)
        if (e.what == QLatin1String("disconnected") || e.what == QLatin1String("recording stopped"))
            return true;
    return false;
}

QByteArray SessionManifest::toJson() const
{
    QJsonObject root;
    root[QStringLiteral("format")] = QLatin1String(kFormat);
    root[QStringLiteral("version")] = kVersion;
    root[QStringLiteral("started_utc")] = startedUtc;
    root[QStringLiteral("started_host_ns")] = QString::number(startedHostNs);
    root[QStringLiteral("stopped_host_ns")] = QString::number(stoppedHostNs);
    QJsonArray devs;
    for (const Device &d : devices) {
        QJsonObject o;
        o[QStringLiteral("name")] = d.name;
        o[QStringLiteral("address")] = d.address;
        o[QStringLiteral("link_kind")] = d.linkKind;
        o[QStringLiteral("file")] = d.file;
        o[QStringLiteral("product")] = d.product;
        o[QStringLiteral("serial")] = d.serial;
        o[QStringLiteral("firmware")] = d.firmware;
        o[QStringLiteral("bytes")] = double(d.bytes);
        o[QStringLiteral("frames")] = double(d.frames);
        o[QStringLiteral("offset_ns")] = d.offsetNs;
        o[QStringLiteral("offset_method")] = d.offsetMethod;
        QJsonArray clocks;
        for (const ClockStats &c : d.clocks) {
            QJsonObject k;
            k[QStringLiteral("source")] = QString::fromStdString(c.source);
            k[QStringLiteral("method")] = QLatin1String(clockMethodName(c.method));
            k[QStringLiteral("state")] = QLatin1String(clockStateName(c.state));
            k[QStringLiteral("drift_ppm")] = c.driftPpm;
            k[QStringLiteral("jitter_ns")] = c.jitterNs;
            k[QStringLiteral("uncertainty_ns")] = c.uncertaintyNs;
            k[QStringLiteral("resets")] = c.resets;
            k[QStringLiteral("span_s")] = c.spanS;
            k[QStringLiteral("samples")] = double(c.samples);
            clocks.append(k);
        }
        o[QStringLiteral("clocks")] = clocks;
        QJsonArray events;
        for (const Event &e : d.events) {
            QJsonObject k;
            // As text: a double holds ns of a steady clock only to about 0.1 ms after weeks of uptime.
            k[QStringLiteral("host_ns")] = QString::number(e.hostNs);
            k[QStringLiteral("what")] = e.what;
            k[QStringLiteral("detail")] = e.detail;
            events.append(k);
        }
        o[QStringLiteral("events")] = events;
        devs.append(o);
    }
    root[QStringLiteral("devices")] = devs;
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

bool SessionManifest::fromJson(const QByteArray &json, SessionManifest *out, QString *error)
{
    QJsonParseError pe{};
    const QJsonDocument doc = QJsonDocument::fromJson(json, &pe);
    const QJsonObject root = doc.object();
    if (pe.error != QJsonParseError::NoError || root.value(QStringLiteral("format")).toString() != QLatin1String(kFormat)) {
        if (error)
            *error = pe.error != QJsonParseError::NoError
                ? QStringLiteral("not a session manifest: %1").arg(pe.errorString())
                : QStringLiteral("not a session manifest (its \"format\" is not \"%1\")").arg(QLatin1String(kFormat));
        return false;
    }
    if (root.value(QStringLiteral("version")).toInt() > kVersion) {
        if (error)
            *error = QStringLiteral("session manifest version %1 is newer than this ImuDesk reads (%2): update ImuDesk")
                         .arg(root.value(QStringLiteral("version")).toInt())
                         .arg(kVersion);
        return false;
    }
    SessionManifest m;
    m.startedUtc = root.value(QStringLiteral("started_utc")).toString();
    m.startedHostNs = root.value(QStringLiteral("started_host_ns")).toString().toLongLong();
    m.stoppedHostNs = root.value(QStringLiteral("stopped_host_ns")).toString().toLongLong();
    for (const QJsonValue &v : root.value(QStringLiteral("devices")).toArray()) {
        const QJsonObject o = v.toObject();
        Device d;
        d.name = o.value(QStringLiteral("name")).toString();
        d.address = o.value(QStringLiteral("address")).toString();
        d.linkKind = o.value(QStringLiteral("link_kind")).toString();
        d.file = o.value(QStringLiteral("file")).toString();
        d.product = o.value(QStringLiteral("product")).toString();
        d.serial = o.value(QStringLiteral("serial")).toString();
        d.firmware = o.value(QStringLiteral("firmware")).toString();
        d.bytes = quint64(o.value(QStringLiteral("bytes")).toDouble());
        d.frames = quint64(o.value(QStringLiteral("frames")).toDouble());
        d.offsetNs = o.value(QStringLiteral("offset_ns")).toDouble();
        d.offsetMethod = o.value(QStringLiteral("offset_method")).toString();
        for (const QJsonValue &cv : o.value(QStringLiteral("clocks")).toArray()) {
            const QJsonObject k = cv.toObject();
            ClockStats c;
            c.source = k.value(QStringLiteral("source")).toString().toStdString();
            c.method = methodOf(k.value(QStringLiteral("method")).toString());
            c.state = stateOf(k.value(QStringLiteral("state")).toString());
            c.driftPpm = k.value(QStringLiteral("drift_ppm")).toDouble();
            c.jitterNs = k.value(QStringLiteral("jitter_ns")).toDouble();
            c.uncertaintyNs = k.value(QStringLiteral("uncertainty_ns")).toDouble();
            c.resets = k.value(QStringLiteral("resets")).toInt();
            c.spanS = k.value(QStringLiteral("span_s")).toDouble();
            c.samples = quint64(k.value(QStringLiteral("samples")).toDouble());
            d.clocks.push_back(c);
        }
        for (const QJsonValue &ev : o.value(QStringLiteral("events")).toArray()) {
            const QJsonObject k = ev.toObject();
            d.events.push_back(Event{k.value(QStringLiteral("host_ns")).toString().toLongLong(),
                                     k.value(QStringLiteral("what")).toString(), k.value(QStringLiteral("detail")).toString()});
        }
        if (d.file.isEmpty() || d.file.contains(QLatin1Char('/')) || d.file.contains(QLatin1String(".."))) {
            if (error)
                *error = QStringLiteral("session manifest: device \"%1\" names no capture file in its folder").arg(d.name);
            return false;
        }
        m.devices.push_back(std::move(d));
    }
    *out = std::move(m);
    return true;
}

bool SessionManifest::save(const QString &folder, QString *error) const
{
    QSaveFile f(QDir(folder).filePath(QLatin1String(kFileName)));
    if (!f.open(QIODevice::WriteOnly) || f.write(toJson()) < 0 || !f.commit()) {
        if (error)
            *error = QStringLiteral("cannot write %1: %2").arg(f.fileName(), f.errorString());
        return false;
    }
    return true;
}

bool SessionManifest::load(const QString &folder, SessionManifest *out, QString *error)
{
    QFile f(QDir(folder).filePath(QLatin1String(kFileName)));
    if (!f.open(QIODevice::ReadOnly)) {
        if (error)
            *error = QStringLiteral("cannot open %1: %2").arg(f.fileName(), f.errorString());
        return false;
    }
    return fromJson(f.readAll(), out, error);
}

bool SessionManifest::isSessionFolder(const QString &path)
{
    return QFileInfo(path).isDir() && QFileInfo::exists(QDir(path).filePath(QLatin1String(kFileName)));
}

} // namespace imudesk::record
