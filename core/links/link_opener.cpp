#include "link_opener.h"

#include "device/can_session.h"
#include "device/modbus_session.h"
#include "links/serial_family_scan.h"
#include "device/session.h"
#include "io/serial_transport.h"
#include "record/replay_session.h"
#include "sim/can_simulator.h"
#include "sim/modbus_simulator.h"
#include "sim/pty_simulator.h"

#include <QFileInfo>
#include <QTimer>

namespace imudesk::device {

namespace {

// The detection phase of a serial link: the engine with SerialFamilyScan as its family.
class ScanSession : public Session {
public:
    ScanSession(std::vector<int> bauds, int deviceAddress, std::unique_ptr<io::Transport> transport)
        : Session(std::make_unique<SerialFamilyScan>(std::move(bauds), deviceAddress), std::move(transport),
                  QStringLiteral("imudesk-detect"), SerialFamilyScan::kLineIdleMs)
    {
        setAutoReconnect(false);
    }
    template <class F>
    void onFound(QObject *context, F f)
    {
        connect(static_cast<SerialFamilyScan *>(family()), &SerialFamilyScan::found, context, std::move(f));
    }
    void start(const QString &port, int baud) { openLink(port, baud); }
    quint64 bytesHeard() const { return static_cast<SerialFamilyScan *>(family())->bytesHeard(); }
};

} // namespace

LinkRequest LinkRequest::serial(const QString &port, int baud, const QString &family)
{
    LinkRequest r;
    r.kind = Kind::Serial;
    r.address = port;
    r.baud = baud;
    r.family = family;
    return r;
}

LinkRequest LinkRequest::modbusDevice(const ModbusOptions &options)
{
    LinkRequest r;
    r.kind = Kind::Modbus;
    r.address = options.port;
    r.modbus = options;
    return r;
}

LinkRequest LinkRequest::canBus(const CanSessionOptions &options)
{
    LinkRequest r;
    r.kind = Kind::Can;
    r.address = options.plugin + QLatin1Char(':') + options.interfaceName;
    r.can = options;
    return r;
}

LinkRequest LinkRequest::capture(const QString &path)
{
    LinkRequest r;
    r.kind = Kind::Capture;
    r.address = path;
    return r;
}

LinkRequest LinkRequest::simulatedSerial(const QString &family, sim::Motion motion, std::any options, int baud)
{
    LinkRequest r = serial(QString(), baud, family);
    r.simulate = true;
    r.motion = motion;
    r.simulator = std::move(options);
    return r;
}

LinkRequest LinkRequest::simulatedHipnuc(const sim::SimOptions &options, int baud)
{
    return simulatedSerial(QStringLiteral("hipnuc"), options.motion, options, baud);
}

LinkRequest LinkRequest::simulatedHec495(sim::Motion motion)
{
    return simulatedSerial(QStringLiteral("hec495"), motion);
}

bool startOnPty(LinkRequest &r, std::shared_ptr<sim::PtySimulator> simulator, const QString &failure, QString *error)
{
    QString why;
    if (!simulator->start(&why)) {
        if (error)
            *error = failure.arg(why);
        return false;
    }
    r.address = simulator->devicePath();
    r.autoReconnect = false; // a pty's number is reused: never wait for it to "come back"
    r.keepAlive = std::move(simulator);
    return true;
}

namespace {

std::unique_ptr<io::Transport> transportFor(const LinkRequest &r)
{
    return r.transport ? r.transport() : std::make_unique<io::SerialTransport>();
}

QString unknownFamily(const LinkRequest &r)
{
    return LinkOpener::tr("%1: no serial device family is called \"%2\"").arg(r.address, r.family);
}

// Starts the simulated device a request asks for and points the request at it.
bool startSimulator(LinkRequest &r, QString *error)
{
    QString why;
    switch (r.kind) {
    case LinkRequest::Kind::Serial: {
        const SerialFamilyKind *family = serialFamily(r.family);
        if (!family) {
            if (error)
                *error = unknownFamily(r);
            return false;
        }
        return family->startSimulator(r, error);
    }
    case LinkRequest::Kind::Modbus: {
        sim::ModbusSimOptions so;
        so.kind = r.modbus.kind;
        so.nodeId = r.modbus.nodeId;
        so.baud = r.modbus.baud;
        so.motion = r.motion;
        auto simulator = std::make_shared<sim::ModbusSimulator>(so);
        if (!simulator->start(&why)) {
            if (error)
                *error = LinkOpener::tr("The simulated Modbus device could not start: %1").arg(why);
            return false;
        }
        r.modbus.port = r.address = simulator->devicePath();
        r.keepAlive = simulator;
        return true;
    }
    case LinkRequest::Kind::Can: {
        sim::CanSimOptions so;
        so.hec495 = r.can.protocol == protocol::can::CanProtocol::Hec495;
        // The simulated HEC495 speaks standard frames on a "CANopen" bus, the extended variant
        // (0x18FA....) on a "J1939" one (CanSimOptions).
        const bool standardFrames = r.can.protocol == protocol::can::CanProtocol::CanOpen
                                 || (so.hec495 && !r.can.hec495Extended);
        so.protocol = standardFrames ? protocol::can::CanProtocol::CanOpen : protocol::can::CanProtocol::J1939;
        so.node = r.can.node;
        so.motion = r.motion;
        so.canFd = r.can.canFd && !so.hec495; // a HiPNUC J1939 module with CAN FD output: FF5A too
        auto simulator = std::make_shared<sim::CanSimulator>(so);
        if (!simulator->start(r.can.plugin, r.can.interfaceName, &why)) {
            if (error)
                *error = LinkOpener::tr("The simulated CAN device could not start on %1:%2: %3")
                             .arg(r.can.plugin, r.can.interfaceName, why);
            return false;
        }
        r.keepAlive = simulator;
        return true;
    }
    case LinkRequest::Kind::Capture: break;
    }
    if (error)
        *error = LinkOpener::tr("A capture file cannot be simulated.");
    return false;
}

} // namespace

LinkOpener::Opened LinkOpener::openNow(LinkRequest &r, QString *error)
{
    Opened o;
    if (r.simulate && !startSimulator(r, error))
        return o;
    switch (r.kind) {
    case LinkRequest::Kind::Serial: {
        if (r.family.isEmpty()) {
            if (error)
                *error = tr("%1: the device's family is found by a detection, which does not finish at once")
                             .arg(r.address);
            return o;
        }
        const SerialFamilyKind *family = serialFamily(r.family);
        if (!family) {
            if (error)
                *error = unknownFamily(r);
            return o;
        }
        o = family->open(r, transportFor(r));
        break;
    }
    case LinkRequest::Kind::Modbus: {
        auto s = std::make_unique<ModbusSession>();
        o.start = [p = s.get(), options = r.modbus] { p->open(options); };
        o.link = std::move(s);
        break;
    }
    case LinkRequest::Kind::Can: {
        auto s = std::make_unique<CanSession>();
        o.start = [p = s.get(), options = r.can] { p->open(options); };
        o.link = std::move(s);
        break;
    }
    case LinkRequest::Kind::Capture: {
        if (!QFileInfo(r.address).isReadable()) {
            if (error)
                *error = tr("%1 cannot be read. Check that the file exists and that you may read it.").arg(r.address);
            return o;
        }
        auto s = std::make_unique<record::ReplaySession>();
        s->setGroup(r.replayGroup);
        o.start = [p = s.get(), path = r.address, timeline = r.replay] { p->open(path, timeline); };
        o.link = std::move(s);
        break;
    }
    }
    o.keepAlive = std::move(r.keepAlive);
    return o;
}

LinkOpener::LinkOpener(QObject *parent) : QObject(parent) {}

LinkOpener::~LinkOpener() = default;

void LinkOpener::open(LinkRequest request)
{
    cancel();
    m_opened = {};
    m_bytesHeard = 0;
    m_request = std::move(request);
    m_running = true;
    if (m_request.kind != LinkRequest::Kind::Serial || !m_request.family.isEmpty()) {
        QString error;
        Opened o = openNow(m_request, &error);
        if (!o.link) {
            QTimer::singleShot(0, this, [this, error] {
                m_running = false;
                Q_EMIT failed(error);
            });
            return;
        }
        finish(std::move(o));
        return;
    }
    auto probe = std::make_unique<ScanSession>(m_request.baud > 0 ? std::vector<int>{m_request.baud}
                                                                  : std::vector<int>{},
                                               m_request.deviceAddress, transportFor(m_request));
    probe->onFound(this, [this](const QString &f, int baud, int address) { onFound(f, baud, address); });
    connect(probe.get(), &DeviceLink::stateChanged, this, [this](SessionState s, const QString &detail) {
        if (s == SessionState::Detecting && !detail.isEmpty())
            Q_EMIT detecting(detail);
        else if (s == SessionState::Failed && m_running) {
            m_running = false;
            m_bytesHeard = static_cast<ScanSession *>(m_probe.get())->bytesHeard();
            m_probe.release()->deleteLater(); // later: this runs in its signal
            Q_EMIT failed(detail);
        }
    });
    m_probe = std::move(probe);
    static_cast<ScanSession *>(m_probe.get())->start(m_request.address, m_request.baud);
}

void LinkOpener::cancel()
{
    m_running = false;
    if (m_probe) {
        m_probe->disconnect(this);
        m_probe.reset(); // closes its port
    }
}

void LinkOpener::onFound(const QString &family, int baud, int address)
{
    if (!m_probe || !m_running)
        return;
    std::unique_ptr<io::Transport> port = m_probe->releaseTransport();
    m_probe->disconnect(this);
    m_probe.release()->deleteLater(); // later: this runs in its signal
    m_request.family = family;
    m_request.baud = baud;
    if (address >= 0)
        m_request.deviceAddress = address;
    if (!port) {
        m_running = false;
        Q_EMIT failed(tr("the port of %1 was lost while it was handed to the device's session").arg(m_request.address));
        return;
    }
    Opened o = serialFamily(family)->open(m_request, std::move(port));
    o.keepAlive = std::move(m_request.keepAlive);
    finish(std::move(o));
}

void LinkOpener::finish(Opened opened)
{
    m_opened = std::move(opened);
    // From the event loop, as after a detection: the caller has returned from open() first.
    QTimer::singleShot(0, this, [this] {
        if (!m_opened.link)
            return;
        m_running = false;
        Q_EMIT ready();
    });
}

LinkOpener::Opened LinkOpener::take()
{
    Opened o = std::move(m_opened);
    m_opened = {};
    return o;
}

} // namespace imudesk::device
