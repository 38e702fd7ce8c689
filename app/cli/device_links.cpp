#include "device_links.h"

#include "cli_context.h"
#include "protocol/can/can_decoder.h"

#include <cstring>

namespace imudesk::cli {

bool linkOf(const QString &spec, int baud, device::LinkRequest *out, QString *error)
{
    auto bad = [&](const QString &why) {
        *error = QStringLiteral("%1: %2").arg(spec, why);
        return false;
    };
    if (spec.startsWith(QLatin1String("can:"))) {
        const QStringList parts = spec.mid(4).split(QLatin1Char(':'));
        if (parts.size() < 2 || parts.size() > 3 || parts[0].isEmpty() || parts[1].isEmpty())
            return bad(QStringLiteral("a CAN device is can:PLUGIN:INTERFACE[:PROTOCOL], e.g. can:socketcan:can0:canopen"));
        device::CanSessionOptions o;
        o.plugin = parts[0];
        o.interfaceName = parts[1];
        if (parts.size() == 3) {
            const auto proto = protocol::can::parseProtocol(parts[2]);
            if (!proto)
                return bad(QStringLiteral("unknown CAN protocol '%1' (auto, j1939, canopen, hec495)").arg(parts[2]));
            o.protocol = *proto;
        }
        *out = device::LinkRequest::canBus(o);
        return true;
    }
    for (const char *prefix : {"modbus:", "modbus-hec495:"}) {
        if (!spec.startsWith(QLatin1String(prefix)))
            continue;
        QString rest = spec.mid(int(std::strlen(prefix)));
        device::ModbusOptions o;
        o.kind = std::strcmp(prefix, "modbus:") == 0 ? protocol::modbus::DeviceKind::Hipnuc
                                                      : protocol::modbus::DeviceKind::Hec495;
        const int at = int(rest.lastIndexOf(QLatin1Char('@')));
        if (at >= 0) {
            bool ok = false;
            o.nodeId = rest.mid(at + 1).toInt(&ok);
            if (!ok || o.nodeId < 1 || o.nodeId > 247)
                return bad(QStringLiteral("a Modbus node ID is 1..247"));
            rest = rest.left(at);
        }
        if (rest.isEmpty())
            return bad(QStringLiteral("no port after '%1'").arg(QLatin1String(prefix)));
        o.port = rest;
        o.baud = baud;
        *out = device::LinkRequest::modbusDevice(o);
        return true;
    }
    // PORT:BAUD: that device's rate (the family is still recognised, at that rate only).
    QString port = spec;
    const int colon = int(spec.lastIndexOf(QLatin1Char(':')));
    if (colon > 0) {
        bool ok = false;
        const int own = spec.mid(colon + 1).toInt(&ok);
        if (!ok || own <= 0)
            return bad(QStringLiteral("a serial device is PORT or PORT:BAUD"));
        port = spec.left(colon);
        baud = own;
    }
    *out = device::LinkRequest::serial(port, baud);
    return true;
}

record::CaptureHeader headerOf(const OpenDevice &d)
{
    record::CaptureHeader header;
    header.setIdentity(d.identity);
    header.set(record::CaptureHeader::kLinkKind, d.link.link->linkKind().toStdString());
    header.set(record::CaptureHeader::kPort, d.spec.toStdString());
    d.link.link->describeLink(header);
    return header;
}

int openDevices(const QStringList &specs, int baud, std::vector<OpenDevice> &devices)
{
    devices = std::vector<OpenDevice>(size_t(specs.size()));
    for (int i = 0; i < specs.size(); ++i) {
        OpenDevice &d = devices[size_t(i)];
        d.spec = specs[i];
        device::LinkRequest request;
        QString error;
        if (!linkOf(d.spec, baud, &request, &error))
            return fail(error, ExitUsage);
        d.opener = std::make_unique<device::LinkOpener>();
        QObject::connect(d.opener.get(), &device::LinkOpener::ready, [&d] { d.ready = true; });
        QObject::connect(d.opener.get(), &device::LinkOpener::failed, [&d](const QString &why) { d.error = why; });
        d.opener->open(request);
    }
    // The detections run side by side: at most 11 rates of under a second each.
    waitFor([&] {
        for (const OpenDevice &d : devices)
            if (!d.ready && d.error.isEmpty())
                return false;
        return true;
    }, 30000);
    for (OpenDevice &d : devices) {
        if (!d.ready) {
            d.opener->cancel();
            return fail(QStringLiteral("%1: %2").arg(d.spec, d.error.isEmpty() ? QStringLiteral("timed out opening it") : d.error),
                        interrupted() ? ExitInterrupted : ExitFailure);
        }
        d.link = d.opener->take();
        QObject::connect(d.link.link.get(), &device::DeviceLink::identityChanged,
                         [&d](const model::DeviceIdentity &id) { d.identity = id; });
        QObject::connect(d.link.link.get(), &device::DeviceLink::stateChanged,
                         [&d](device::SessionState st, const QString &detail) {
                             d.state = st;
                             if (st == device::SessionState::Failed)
                                 d.error = detail;
                         });
        if (d.link.start)
            d.link.start();
    }
    waitFor([&] {
        for (const OpenDevice &d : devices)
            if (d.state != device::SessionState::Connected && d.error.isEmpty())
                return false;
        return true;
    }, 15000);
    for (const OpenDevice &d : devices)
        if (d.state != device::SessionState::Connected)
            return fail(QStringLiteral("%1: %2").arg(d.spec, d.error.isEmpty() ? QStringLiteral("did not connect within 15 s") : d.error),
                        interrupted() ? ExitInterrupted : ExitFailure);
    return ExitOk;
}

} // namespace imudesk::cli
