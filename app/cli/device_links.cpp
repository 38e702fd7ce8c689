#include "device_links.h"

#include "cli_context.h"
#include "protocol/can/can_decoder.h"

#include <QElapsedTimer>

#include <algorithm>
#include <cstdio>
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

capture::CaptureHeader headerOf(const OpenDevice &d)
{
    capture::CaptureHeader header;
    header.setIdentity(d.identity);
    header.set(capture::CaptureHeader::kLinkKind, d.link.link->linkKind().toStdString());
    header.set(capture::CaptureHeader::kPort, d.spec.toStdString());
    d.link.link->describeLink(header);
    return header;
}

namespace {

constexpr int kOpenMs = 30000;    // the detections, side by side
constexpr int kConnectMs = 15000; // each link from its start to Connected
constexpr int kIdentityMs = 10000; // LOG VERSION asked three times, then LOG COMCONFIG
constexpr int kQuietMs = 2000;    // a device that takes longer says what it is doing

// "did not connect within 15 s; it was still Detecting: trying 921600 baud"
QString waitedFor(const OpenDevice &d, const QString &what, int ms)
{
    QString text = QStringLiteral("did not %1 within %2 s").arg(what).arg(ms / 1000);
    if (!d.doing.isEmpty())
        text += QStringLiteral("; it was still at: %1").arg(d.doing);
    if (d.state == device::SessionState::Closed && d.doing.isEmpty())
        text += QStringLiteral("; nothing was heard from it (is the port right, the device powered?)");
    return text;
}

// After kQuietMs of waiting, each device's step on stderr whenever it changes ("/dev/ttyUSB0:
// Detecting: trying 460800 baud"): a slow detection on a loaded machine is seen, not silent.
class ProgressNotes {
public:
    explicit ProgressNotes(const std::vector<OpenDevice> &devices) : m_devices(devices), m_told(devices.size())
    {
        m_clock.start();
    }
    void restart() { m_clock.restart(); }
    void tell()
    {
        if (m_clock.elapsed() < kQuietMs)
            return;
        for (size_t i = 0; i < m_devices.size(); ++i) {
            const OpenDevice &d = m_devices[i];
            const bool settled = d.state == device::SessionState::Connected && !(d.link.link && d.link.link->identityPending());
            if (d.doing.isEmpty() || d.doing == m_told[i] || settled)
                continue;
            m_told[i] = d.doing;
            std::fprintf(stderr, "%s: %s\n", qPrintable(d.spec), qPrintable(d.doing));
            std::fflush(stderr);
        }
    }

private:
    const std::vector<OpenDevice> &m_devices;
    std::vector<QString> m_told;
    QElapsedTimer m_clock;
};

} // namespace

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
        QObject::connect(d.opener.get(), &device::LinkOpener::detecting, [&d](const QString &what) { d.doing = what; });
        d.opener->open(request);
    }
    // The detections run side by side: at most 11 rates of under a second each. A device that
    // takes longer than a moment says what it is doing (stderr), so a wait is never silent.
    ProgressNotes notes(devices);
    waitFor([&] {
        notes.tell();
        for (const OpenDevice &d : devices)
            if (!d.ready && d.error.isEmpty())
                return false;
        return true;
    }, kOpenMs);
    for (OpenDevice &d : devices) {
        if (!d.ready) {
            d.opener->cancel();
            return fail(QStringLiteral("%1: %2").arg(d.spec, d.error.isEmpty() ? waitedFor(d, QStringLiteral("open"), kOpenMs) : d.error),
                        interrupted() ? ExitInterrupted : ExitFailure);
        }
        d.link = d.opener->take();
        QObject::connect(d.link.link.get(), &device::DeviceLink::identityChanged,
                         [&d](const model::DeviceIdentity &id) { d.identity = id; });
        QObject::connect(d.link.link.get(), &device::DeviceLink::stateChanged,
                         [&d](device::SessionState st, const QString &detail) {
                             d.state = st;
                             d.doing = QStringLiteral("%1%2").arg(QString::fromLatin1(device::stateName(st)),
                                                                 detail.isEmpty() ? QString() : QStringLiteral(": ") + detail);
                             if (st == device::SessionState::Failed)
                                 d.error = detail;
                         });
        if (d.link.start)
            d.link.start();
    }
    notes.restart();
    waitFor([&] {
        notes.tell();
        for (const OpenDevice &d : devices)
            if (d.state != device::SessionState::Connected && d.error.isEmpty())
                return false;
        return true;
    }, kConnectMs);
    for (const OpenDevice &d : devices)
        if (d.state != device::SessionState::Connected)
            return fail(QStringLiteral("%1: %2").arg(d.spec, d.error.isEmpty() ? waitedFor(d, QStringLiteral("connect"), kConnectMs) : d.error),
                        interrupted() ? ExitInterrupted : ExitFailure);
    // Its serial and product name it in files and topics: a module found at a known rate is
    // connected before it has said who it is (LOG VERSION), and named "device" if not waited for.
    for (OpenDevice &d : devices)
        if (d.link.link->identityPending())
            d.doing = QStringLiteral("asking who it is (LOG VERSION)");
    notes.restart();
    waitFor([&] {
        notes.tell();
        return std::none_of(devices.begin(), devices.end(),
                            [](const OpenDevice &d) { return d.link.link->identityPending(); });
    }, kIdentityMs);
    for (const OpenDevice &d : devices)
        if (d.link.link->identityPending())
            std::fprintf(stderr, "imudesk-cli: warning: %s did not say who it is within %d s (LOG VERSION): it is named "
                                 "by its link\n", qPrintable(d.spec), kIdentityMs / 1000);
    return interrupted() ? ExitInterrupted : ExitOk;
}

} // namespace imudesk::cli
