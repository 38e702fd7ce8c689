#include "discovery/discovery_result.h"

#include <QCoreApplication>
#include <QJsonArray>

namespace imudesk::discovery {

QString FoundDevice::linkId(Link l)
{
    switch (l) {
    case Link::Serial: return QStringLiteral("serial");
    case Link::Modbus: return QStringLiteral("modbus");
    case Link::Can: return QStringLiteral("can");
    }
    return {};
}

QJsonObject FoundDevice::toJson() const
{
    QJsonObject o;
    o[QStringLiteral("link")] = linkId(link);
    o[QStringLiteral("port")] = port;
    if (link == Link::Can) {
        o[QStringLiteral("bitrate")] = bitrate > 0 ? QJsonValue(bitrate) : QJsonValue();
        if (bitrate <= 0 && !bitrateWhy.isEmpty())
            o[QStringLiteral("bitrate_why")] = bitrateWhy;
        o[QStringLiteral("node")] = node;
    } else {
        o[QStringLiteral("baud")] = baud;
        if (address >= 0)
            o[QStringLiteral("address")] = address;
    }
    o[QStringLiteral("family")] = family;
    o[QStringLiteral("model")] = model.isEmpty() ? QJsonValue() : QJsonValue(model);
    o[QStringLiteral("serial")] = serial.isEmpty() ? QJsonValue() : QJsonValue(serial);
    o[QStringLiteral("firmware")] = firmware.isEmpty() ? QJsonValue() : QJsonValue(firmware);
    if (!note.isEmpty())
        o[QStringLiteral("note")] = note;
    return o;
}

QJsonObject Conflict::toJson() const
{
    return QJsonObject{{QStringLiteral("port"), port},
                       {QStringLiteral("link"), link},
                       {link == QLatin1String("can") ? QStringLiteral("node") : QStringLiteral("address"), address},
                       {QStringLiteral("evidence"), evidence},
                       {QStringLiteral("advice"), advice}};
}

QString PortNote::kindId(Kind k)
{
    switch (k) {
    case Kind::Busy: return QStringLiteral("busy");
    case Kind::Silent: return QStringLiteral("silent");
    case Kind::Garbage: return QStringLiteral("garbage");
    case Kind::NoPermission: return QStringLiteral("no-permission");
    case Kind::Failed: return QStringLiteral("failed");
    case Kind::OutOfTime: return QStringLiteral("out-of-time");
    case Kind::Cancelled: return QStringLiteral("cancelled");
    }
    return {};
}

QJsonObject PortNote::toJson() const
{
    return QJsonObject{{QStringLiteral("port"), port}, {QStringLiteral("kind"), kindId(kind)}, {QStringLiteral("text"), text}};
}

int SweepResult::exitCode() const
{
    if (!conflicts.isEmpty())
        return 1;
    return devices.isEmpty() ? 2 : 0;
}

QJsonObject SweepResult::toJson() const
{
    QJsonArray d, c, n;
    for (const auto &x : devices)
        d.append(x.toJson());
    for (const auto &x : conflicts)
        c.append(x.toJson());
    for (const auto &x : notes)
        n.append(x.toJson());
    return QJsonObject{{QStringLiteral("devices"), d},
                       {QStringLiteral("conflicts"), c},
                       {QStringLiteral("ports"), n},
                       {QStringLiteral("seconds"), qRound(seconds * 10) / 10.0},
                       {QStringLiteral("cancelled"), cancelled}};
}

QStringList SweepResult::textLines() const
{
    // For a terminal (imudesk-cli discover): English, as the CLI's other output; the texts of
    // the notes and conflicts come translated from where they were made.
    const auto text = [](const char *s) { return QString::fromLatin1(s); };
    QStringList lines;
    for (const auto &x : devices) {
        QString where;
        if (x.link == FoundDevice::Link::Can)
            where = text("%1 node %2, %3").arg(x.port).arg(x.node).arg(x.bitrate > 0 ? text("%1 bit/s").arg(x.bitrate)
                                                                                    : text("bit rate unknown"));
        else if (x.address >= 0)
            where = text("%1 at %2 baud, address %3").arg(x.port).arg(x.baud).arg(x.address);
        else
            where = text("%1 at %2 baud").arg(x.port).arg(x.baud);
        QStringList what{x.family};
        if (!x.model.isEmpty())
            what << x.model;
        if (!x.firmware.isEmpty())
            what << text("firmware %1").arg(x.firmware);
        if (!x.serial.isEmpty())
            what << text("SN %1").arg(x.serial);
        lines << text("found  %1 [%2]: %3").arg(where, FoundDevice::linkId(x.link), what.join(QStringLiteral(", ")));
    }
    for (const auto &x : conflicts)
        lines << text("CONFLICT %1 address %2: %3 %4").arg(x.port).arg(x.address).arg(x.evidence, x.advice);
    for (const auto &x : notes)
        lines << text("%1  %2: %3").arg(PortNote::kindId(x.kind), x.port, x.text);
    return lines;
}

} // namespace imudesk::discovery
