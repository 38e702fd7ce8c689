#include "can_session.h"
#include "device/can_family.h"
#include "io/can_transport.h"
#include "protocol/can/can_decoder.h"
#include "capture/capture_header.h"

#include "protocol/can/canopen.h"
#include "protocol/can/hec495_can.h"
#include "protocol/can/hipnuc_canopen_objects.h"
#include "protocol/can/j1939.h"
#include "protocol/can/j1939_config.h"
#include "protocol/can/sdo.h"

#include <QCanBus>
#include <QMetaObject>
#include <QThread>

#include <algorithm>
#include <functional>

namespace imudesk::device {

using namespace protocol::can;
namespace hip = protocol::can::canopen::hipnuc;

CanSession::CanSession(QObject *parent, std::unique_ptr<io::Transport> transport)
    : Session(std::make_unique<CanFamily>(), transport ? std::move(transport) : std::make_unique<io::CanTransport>(),
              QStringLiteral("imudesk-can"), 0, parent, io::canThread())
{
    qRegisterMetaType<CanFrameEvents>();
    qRegisterMetaType<CanNodeInfo>();
    qRegisterMetaType<CanRequestResult>();
    qRegisterMetaType<CanSessionOptions>();
    auto *f = static_cast<CanFamily *>(family());
    connect(f, &CanFamily::framesSeen, this, &CanSession::framesSeen);
    connect(f, &CanFamily::nodeDiscovered, this, &CanSession::nodeDiscovered);
    connect(f, &CanFamily::jobFinished, this, &CanSession::requestFinished);
    // Every family's requests end in requestEnded too, in the session's one id space.
    connect(this, &CanSession::requestFinished, this, &CanSession::announceEnded<CanRequestResult>);
    connect(f, &CanFamily::scanProgress, this, &CanSession::scanProgress);
    connect(f, &CanFamily::scanFinished, this, &CanSession::scanFinished);
    connect(f, &CanFamily::protocolDetected, this, [this](int p) {
        m_detected = p;
        Q_EMIT protocolDetected(p);
    });
    connect(f, &CanFamily::targetNodeChanged, this, [this](int n) {
        m_target = n;
        Q_EMIT targetNodeChanged(n);
    });
}

CanSession::~CanSession() = default;

QStringList CanSession::plugins()
{
    return QCanBus::instance()->plugins();
}

QList<int> CanSession::moduleBitrates(CanProtocol protocol, bool hec495Extended)
{
    if (protocol == CanProtocol::Auto)
        return {}; // no device's setting yet
    const std::vector<int> rates = protocol::can::canBitrates(protocol, hec495Extended).rates;
    return QList<int>(rates.begin(), rates.end());
}

QStringList CanSession::interfaces(const QString &plugin, QString *error)
{
    QStringList out;
    const auto list = QCanBus::instance()->availableDevices(plugin, error);
    for (const auto &info : list)
        out << info.name();
    return out;
}

void CanSession::open(const CanSessionOptions &options)
{
    m_options = options;
    m_target = options.node;
    m_detected = int(options.protocol);
    inFamily<CanFamily>([options](CanFamily &f) { f.configure(options); });
    openLink(options.plugin + QLatin1Char(':') + options.interfaceName, options.bitrate);
}

CanProtocol CanSession::protocol() const
{
    return m_options.protocol != CanProtocol::Auto ? m_options.protocol : CanProtocol(m_detected.load());
}

QString CanSession::linkKind() const
{
    switch (protocol()) {
    case CanProtocol::J1939: return tr("HiPNUC J1939");
    case CanProtocol::CanOpen: return tr("HiPNUC CANopen");
    case CanProtocol::Hec495: return tr("HEC495 CAN");
    case CanProtocol::Auto: break;
    }
    return tr("CAN");
}

void CanSession::describeLink(capture::CaptureHeader &header) const
{
    if (protocol() == CanProtocol::Auto)
        return;
    header.set(capture::CaptureHeader::kCanProtocol, ::imudesk::protocol::can::protocolName(protocol()));
    header.set(capture::CaptureHeader::kCanNode, std::to_string(node()));
}

uint8_t CanSession::node() const
{
    const int t = m_target.load();
    if (t >= 0)
        return uint8_t(t);
    return protocol() == CanProtocol::Hec495 ? hec495::kDefaultNode : canopen::kDefaultNode;
}

quint64 CanSession::submitJob(CanJob job)
{
    job.id = takeRequestId();
    const quint64 id = job.id;
    inFamily<CanFamily>([job](CanFamily &f) { f.submitJob(job); });
    return id;
}

quint64 CanSession::refuseJob(const QString &why)
{
    const quint64 id = takeRequestId();
    const CanRequestResult r{id, false, 0, why, RequestStatus::NotSent, {}, {}};
    QMetaObject::invokeMethod(this, [this, r] { Q_EMIT requestFinished(r); }, Qt::QueuedConnection);
    return id;
}

CanJobStep CanSession::j1939Write(uint16_t addr, uint32_t value, const QString &what) const
{
    CanJobStep s;
    s.tx = j1939::encodeReg(j1939::writeRequest(node(), m_options.hostAddress, addr, value));
    s.expect = CanJobStep::Expect::J1939Reply;
    s.expectValue = value;
    s.timeoutMs = m_options.requestTimeoutMs;
    s.what = what;
    return s;
}

CanJobStep CanSession::j1939Read(uint16_t addr, const QString &what) const
{
    CanJobStep s;
    s.tx = j1939::encodeReg(j1939::readRequest(node(), m_options.hostAddress, addr));
    s.expect = CanJobStep::Expect::J1939Reply;
    s.timeoutMs = m_options.requestTimeoutMs;
    s.what = what;
    return s;
}

CanJobStep CanSession::sdoWriteStep(uint16_t index, uint8_t sub, uint32_t value, int size, const QString &what) const
{
    CanJobStep s;
    s.tx = canopen::sdoWrite(node(), index, sub, value, size);
    s.expect = CanJobStep::Expect::SdoReply;
    s.timeoutMs = m_options.requestTimeoutMs;
    s.what = what;
    return s;
}

CanJobStep CanSession::sdoReadStep(uint16_t index, uint8_t sub, const QString &what) const
{
    CanJobStep s;
    s.tx = canopen::sdoRead(node(), index, sub);
    s.expect = CanJobStep::Expect::SdoReply;
    s.timeoutMs = m_options.requestTimeoutMs;
    s.what = what;
    return s;
}

CanJobStep CanSession::hecStep(uint16_t index, uint8_t value, const QString &what) const
{
    CanJobStep s;
    s.tx = hec495::writeRequest(node(), index, value, m_options.hec495Extended);
    s.expect = CanJobStep::Expect::Hec495Reply;
    s.timeoutMs = m_options.requestTimeoutMs;
    s.what = what;
    return s;
}

CanJobStep CanSession::firmwareProbe(FirmwareAdapt then) const
{
    CanJobStep probe = sdoReadStep(hip::ObjIdentity, hip::kSubRevision, tr("read the firmware version"));
    probe.optional = true;
    probe.adapt = std::move(then);
    return probe;
}

CanJobStep CanSession::nodeIdObjectProbe() const
{
    return firmwareProbe([fallback = m_options.hipnucNodeIdObject](std::optional<uint32_t> revision, CanJob &job, size_t at) {
        const std::optional<uint16_t> reported = revision ? hip::nodeIdObjectOfRevision(*revision) : std::nullopt;
        const uint16_t object = reported.value_or(fallback);
        for (size_t i = at + 1; i < job.steps.size(); ++i) {
            CanJobStep &step = job.steps[i];
            const auto sdo = step.hasTx ? canopen::parseSdo(step.tx) : std::nullopt;
            if (sdo && hip::isNodeIdObject(sdo->index))
                step.tx = hip::retarget(step.tx, object);
        }
        job.title += reported ? tr(" (object 0x%1, firmware %2.%3.%4)")
                                    .arg(object, 4, 16, QLatin1Char('0'))
                                    .arg(*revision >> 16)
                                    .arg((*revision >> 8) & 0xFF)
                                    .arg(*revision & 0xFF)
                              : tr(" (object 0x%1: the module reports no firmware version)").arg(object, 4, 16, QLatin1Char('0'));
    });
}

quint64 CanSession::readRegister(uint16_t addr)
{
    if (protocol() != CanProtocol::J1939)
        return refuseJob(tr("register access needs a J1939 device"));
    return submitJob(CanJob{0, tr("read register 0x%1").arg(addr, 4, 16, QLatin1Char('0')), {j1939Read(addr, tr("read register"))}});
}

quint64 CanSession::writeRegister(uint16_t addr, uint32_t value)
{
    if (protocol() != CanProtocol::J1939)
        return refuseJob(tr("register access needs a J1939 device"));
    CanJobStep write = j1939Write(addr, value, tr("write register"));
    if (node() == j1939::kBroadcast)
        write.expectValue.reset(); // every node's echo is in the result's answers
    return submitJob(CanJob{0, tr("write register 0x%1").arg(addr, 4, 16, QLatin1Char('0')), {write}});
}

quint64 CanSession::sdoRead(uint16_t index, uint8_t sub)
{
    return submitJob(CanJob{0, tr("SDO read"), {sdoReadStep(index, sub, tr("SDO read"))}});
}

quint64 CanSession::sdoWrite(uint16_t index, uint8_t sub, uint32_t value, int size)
{
    return submitJob(CanJob{0, tr("SDO write"), {sdoWriteStep(index, sub, value, size, tr("SDO write"))}});
}

quint64 CanSession::hec495Write(uint16_t index, uint8_t value)
{
    return submitJob(CanJob{0, hec495::describeObject(index, value), {hecStep(index, value, hec495::describeObject(index, value))}});
}

std::vector<protocol::can::CanSetting> CanSession::settingsCatalogue() const
{
    return protocol::can::canSettings(protocol(), m_options.hipnucNodeIdObject, m_options.hec495Extended);
}

quint64 CanSession::readSetting(const protocol::can::CanSetting &setting)
{
    using A = protocol::can::CanSetting::Access;
    const QString title = tr("read %1").arg(setting.name);
    if (!setting.readable)
        return refuseJob(tr("%1 cannot be read: %2").arg(setting.name, setting.note));
    switch (setting.access) {
    case A::J1939Register: {
        if (protocol() != CanProtocol::J1939)
            return refuseJob(tr("%1 is a J1939 register: the device speaks another protocol").arg(setting.name));
        // A value of several registers (the Modbus list's R_H/R_L, PNAME, SN): each register in
        // turn, the result's values in register order.
        CanJob job{0, title, {}};
        for (int i = 0; i < std::max(1, setting.words); ++i)
            job.steps.push_back(j1939Read(uint16_t(setting.address + i), title));
        return submitJob(std::move(job));
    }
    case A::CanOpenObject:
        if (protocol() != CanProtocol::CanOpen)
            return refuseJob(tr("%1 is a CANopen object: the device speaks another protocol").arg(setting.name));
        if (hip::isNodeIdObject(setting.address))
            return submitJob(CanJob{0, title, {nodeIdObjectProbe(), sdoReadStep(setting.address, setting.sub, title)}});
        return submitJob(CanJob{0, title, {sdoReadStep(setting.address, setting.sub, title)}});
    case A::Hec495Object: break;
    }
    return refuseJob(tr("%1 cannot be read: %2").arg(setting.name, setting.note));
}

quint64 CanSession::writeSetting(const protocol::can::CanSetting &setting, uint32_t raw)
{
    using A = protocol::can::CanSetting::Access;
    if (!setting.writable)
        return refuseJob(tr("%1 is read only").arg(setting.name));
    const QString shown = setting.show(raw);
    switch (setting.access) {
    case A::J1939Register: {
        if (protocol() != CanProtocol::J1939)
            return refuseJob(tr("%1 is a J1939 register: the device speaks another protocol").arg(setting.name));
        if (!setting.readable) // URFR 0xA6: the manual gives no read
            return submitJob(CanJob{0, tr("%1 = %2, confirmed by the module's reply (it cannot be read back)").arg(setting.name, shown),
                                    {j1939Write(setting.address, raw, tr("write %1").arg(setting.name))}});
        CanJobStep rb = j1939Read(setting.address, tr("read back %1").arg(setting.name));
        rb.expectValue = raw;
        return submitJob(CanJob{0, tr("%1 = %2, verified by reading it back").arg(setting.name, shown),
                                {j1939Write(setting.address, raw, tr("write %1").arg(setting.name)), rb}});
    }
    case A::CanOpenObject: {
        if (protocol() != CanProtocol::CanOpen)
            return refuseJob(tr("%1 is a CANopen object: the device speaks another protocol").arg(setting.name));
        CanJobStep rb = sdoReadStep(setting.address, setting.sub, tr("read back %1").arg(setting.name));
        rb.expectValue = raw;
        CanJob job{0, tr("%1 = %2, verified by reading it back").arg(setting.name, shown),
                   {sdoWriteStep(setting.address, setting.sub, raw, setting.size, tr("write %1").arg(setting.name)), rb}};
        if (hip::isNodeIdObject(setting.address))
            job.steps.insert(job.steps.begin(), nodeIdObjectProbe());
        return submitJob(std::move(job));
    }
    case A::Hec495Object:
        if (protocol() != CanProtocol::Hec495)
            return refuseJob(tr("%1 is an HEC495 object: the device speaks another protocol").arg(setting.name));
        if (raw > 0xFF)
            return refuseJob(tr("%1: the HEC495 takes one byte").arg(setting.name));
        return submitJob(CanJob{0, tr("%1 = %2, confirmed by the module's reply (it cannot be read back)").arg(setting.name, shown),
                                {hecStep(setting.address, uint8_t(raw), tr("write %1").arg(setting.name))}});
    }
    return refuseJob(tr("%1 cannot be written").arg(setting.name));
}

quint64 CanSession::setOutputPeriod(uint32_t pgnOrChannel, int ms)
{
    switch (protocol()) {
    case CanProtocol::J1939: {
        if (!j1939::isDataPgn(pgnOrChannel))
            return refuseJob(tr("0x%1 is not a data PGN").arg(pgnOrChannel, 0, 16));
        if (!j1939::validInterval(uint32_t(ms)))
            return refuseJob(tr("the interval must be %1 to %2 ms").arg(j1939::kMinIntervalMs).arg(j1939::kMaxIntervalMs));
        const uint16_t reg = j1939::intervalRegister(pgnOrChannel);
        CanJobStep rb = j1939Read(reg, tr("read back the interval"));
        rb.expectValue = uint32_t(ms);
        return submitJob(CanJob{0, tr("PGN %1 interval %2 ms").arg(QString::number(pgnOrChannel, 16).toUpper()).arg(ms),
                             {j1939Write(reg, uint32_t(ms), tr("set the interval")), rb}});
    }
    case CanProtocol::CanOpen: {
        const int c = int(pgnOrChannel);
        if (c < 0 || c >= canopen::kTpdoCount || ms < 0 || ms > 0xFFFF)
            return refuseJob(tr("TPDO channel 0..5 and a period of 0..65535 ms, please"));
        CanJobStep rb = sdoReadStep(canopen::tpdoCommIndex(c), hip::kSubEventTimer, tr("read back the TPDO period"));
        rb.expectValue = uint32_t(ms);
        return submitJob(CanJob{0, tr("TPDO%1 period %2 ms").arg(canopen::tpdoNumber(c)).arg(ms),
                             {sdoWriteStep(canopen::tpdoCommIndex(c), hip::kSubEventTimer, uint32_t(ms), 2, tr("set the TPDO period")), rb}});
    }
    case CanProtocol::Hec495:
        return refuseJob(tr("the HEC495 has one PDO rate: use setHec495Rate"));
    case CanProtocol::Auto: break;
    }
    return refuseJob(tr("the protocol is not known yet: choose it or wait for traffic"));
}

quint64 CanSession::setHec495Rate(int code)
{
    if (code < 0 || code > 6)
        return refuseJob(tr("the HEC495 rate code is 0 (off) to 6 (100 Hz)"));
    return hec495Write(hec495::ObjPdoRate, uint8_t(code));
}

quint64 CanSession::setSyncMode(int channel, bool sync)
{
    if (protocol() != CanProtocol::CanOpen || channel < 0 || channel >= canopen::kTpdoCount)
        return refuseJob(tr("SYNC mode needs a CANopen device and a TPDO channel 0..5"));
    const uint8_t type = sync ? hip::kTransmissionSync : hip::kTransmissionAsync;
    CanJobStep rb = sdoReadStep(canopen::tpdoCommIndex(channel), hip::kSubTransmissionType, tr("read back the transmission type"));
    rb.expectValue = type;
    return submitJob(CanJob{0, tr("TPDO%1 %2").arg(canopen::tpdoNumber(channel)).arg(sync ? tr("SYNC mode") : tr("asynchronous mode")),
                         {sdoWriteStep(canopen::tpdoCommIndex(channel), hip::kSubTransmissionType, type, 1, tr("set the transmission type")), rb}});
}

quint64 CanSession::setHeartbeat(int ms)
{
    if (protocol() == CanProtocol::Hec495) {
        const std::optional<uint8_t> n = hec495::heartbeatCode(ms);
        if (!n)
            return refuseJob(tr("the HEC495's heartbeat is 100 ms x (N + 1): %1 to %2 ms (it cannot be turned off)")
                                 .arg(hec495::kMinHeartbeatMs)
                                 .arg(hec495::kMaxHeartbeatMs));
        return hec495Write(hec495::ObjHeartbeat, *n);
    }
    if (protocol() != CanProtocol::CanOpen || ms < 0 || ms > 0xFFFF)
        return refuseJob(tr("the heartbeat needs a CANopen or HEC495 device and 0..65535 ms"));
    CanJobStep rb = sdoReadStep(hip::ObjHeartbeat, 0, tr("read back the heartbeat period"));
    rb.expectValue = uint32_t(ms);
    return submitJob(CanJob{0, tr("heartbeat %1 ms").arg(ms), {sdoWriteStep(hip::ObjHeartbeat, 0, uint32_t(ms), 2, tr("set the heartbeat")), rb}});
}

quint64 CanSession::setNodeId(int newId)
{
    if (newId < 1 || newId > 127)
        return refuseJob(tr("the node ID must be 1..127"));
    CanJobStep follow;
    follow.hasTx = false;
    follow.expect = CanJobStep::Expect::TrafficFrom;
    follow.node = newId;
    follow.followNode = newId;
    follow.timeoutMs = 3000;
    follow.what = tr("traffic from node %1").arg(newId);
    const QString title = tr("node ID %1").arg(newId);
    switch (protocol()) {
    case CanProtocol::J1939: {
        CanJobStep rst = j1939Write(j1939::RegCommand, j1939::CommandReset, tr("reset"));
        return submitJob(CanJob{0, title, {j1939Write(j1939::RegNodeId, uint32_t(newId), tr("set the node ID")),
                                        j1939Write(j1939::RegCommand, j1939::CommandSave, tr("save")), rst, follow}});
    }
    case CanProtocol::CanOpen: {
        const uint16_t obj = m_options.hipnucNodeIdObject;
        return submitJob(CanJob{0, title, {nodeIdObjectProbe(), sdoWriteStep(obj, 0, uint32_t(newId), 4, tr("set the node ID")),
                                        sdoWriteStep(hip::ObjCommand, 0, hip::CommandSave, 4, tr("save")),
                                        sdoWriteStep(hip::ObjCommand, 0, hip::CommandReset, 4, tr("reset")), follow}});
    }
    case CanProtocol::Hec495: {
        // The HEC495 takes the new ID at its next power-up; the session follows once it talks.
        follow.timeoutMs = 60000;
        follow.what = tr("traffic from node %1 (power-cycle the HEC495 now)").arg(newId);
        return submitJob(CanJob{0, title, {hecStep(hec495::ObjNodeId, uint8_t(newId), tr("set the node ID")), follow}});
    }
    case CanProtocol::Auto: break;
    }
    return refuseJob(tr("the protocol is not known yet: choose it or wait for traffic"));
}

quint64 CanSession::setBitrate(int bitrate)
{
    switch (protocol()) {
    case CanProtocol::J1939:
    case CanProtocol::CanOpen: {
        const bool j = protocol() == CanProtocol::J1939;
        const int code = j ? j1939::codeFromBaud(bitrate) : hip::codeFromBaud(bitrate);
        if (code < 0)
            return refuseJob(j ? tr("HiPNUC J1939 modules support 125000, 250000, 500000, 800000 and 1000000 bit/s")
                               : tr("the CANopen object 0x209A takes 125000, 250000, 500000 and 1000000 bit/s "
                                    "(800000 is a J1939 rate only)"));
        const QString title = tr("CAN bit rate %1 (saved; takes effect after a reset: reopen the session at that rate)").arg(bitrate);
        if (j)
            return submitJob(CanJob{0, title, {j1939Write(j1939::RegBaud, uint32_t(code), tr("set the bit rate")),
                                            j1939Write(j1939::RegCommand, j1939::CommandSave, tr("save"))}});
        return submitJob(CanJob{0, title, {sdoWriteStep(hip::ObjBaud, 0, uint32_t(code), 4, tr("set the bit rate")),
                                        sdoWriteStep(hip::ObjCommand, 0, hip::CommandSave, 4, tr("save"))}});
    }
    case CanProtocol::Hec495: {
        const int code = hec495::codeFromBaud(bitrate);
        if (code < 0)
            return refuseJob(tr("the HEC495 supports 10000 to 500000 bit/s (see its manual's table)"));
        return submitJob(CanJob{0, tr("CAN bit rate %1 (takes effect after a power cycle: reopen the session at that rate)").arg(bitrate),
                             {hecStep(hec495::ObjBaud, uint8_t(code), tr("set the bit rate"))}});
    }
    case CanProtocol::Auto: break;
    }
    return refuseJob(tr("the protocol is not known yet: choose it or wait for traffic"));
}

quint64 CanSession::attitudeReset(int mode)
{
    if (protocol() == CanProtocol::J1939) {
        if (mode != 1 && mode != 2 && mode != 3 && mode != 5)
            return refuseJob(tr("attitude reset mode 1, 2, 3 or 5, please"));
        return submitJob(CanJob{0, tr("attitude reset %1").arg(mode), {j1939Write(j1939::RegAttitudeReset, uint32_t(mode), tr("attitude reset"))}});
    }
    if (protocol() == CanProtocol::CanOpen) {
        if (mode != 2 && mode != 5)
            return refuseJob(tr("CANopen zeroing: mode 2 (set zero) or 5 (clear), please"));
        return submitJob(CanJob{0, tr("zero %1").arg(mode), {sdoWriteStep(hip::ObjInclZero, 0, uint32_t(mode), 4, tr("set zero"))}});
    }
    return refuseJob(tr("attitude reset needs a HiPNUC J1939 or CANopen device"));
}

quint64 CanSession::setInclinometerSign(int axis, bool reversed)
{
    if (axis != 0 && axis != 1)
        return refuseJob(tr("the inclinometer axis is X (0) or Y (1)"));
    const QString title = tr("inclinometer %1 %2").arg(axis == 0 ? QStringLiteral("X") : QStringLiteral("Y"),
                                                        reversed ? tr("reversed") : tr("default direction"));
    const uint32_t v = reversed ? 1 : 0;
    if (protocol() == CanProtocol::J1939) { // v1.7.1 7.23: 0x9E / 0x9F, 0 default, 1 reversed
        const uint16_t reg = axis == 0 ? j1939::RegInclSignX : j1939::RegInclSignY;
        CanJobStep rb = j1939Read(reg, tr("read back the inclinometer sign"));
        rb.expectValue = v;
        return submitJob(CanJob{0, title, {j1939Write(reg, v, tr("set the inclinometer sign")), rb}});
    }
    if (protocol() == CanProtocol::CanOpen) { // 0x209E / 0x209F
        const uint16_t index = axis == 0 ? hip::ObjInclSignX : hip::ObjInclSignY;
        CanJobStep rb = sdoReadStep(index, 0, tr("read back the inclinometer sign"));
        rb.expectValue = v;
        return submitJob(CanJob{0, title, {sdoWriteStep(index, 0, v, 4, tr("set the inclinometer sign")), rb}});
    }
    return refuseJob(tr("the inclinometer sign needs a HiPNUC J1939 or CANopen device"));
}

quint64 CanSession::setHec495PdoMode(int mode)
{
    if (protocol() != CanProtocol::Hec495)
        return refuseJob(tr("the PDO mode is an HEC495 setting"));
    // Standard frames: 0 float, 1 fixed point, 3 float 0x180/0x280 only; the extended variant:
    // 0 message one (X), 1 messages one and two (X and Y).
    const bool ok = m_options.hec495Extended ? (mode == 0 || mode == 1) : (mode == 0 || mode == 1 || mode == 3);
    if (!ok)
        return refuseJob(m_options.hec495Extended ? tr("the extended variant's PDO format is 0 (X) or 1 (X and Y)")
                                                  : tr("the PDO mode is 0 (float), 1 (fixed point) or 3 (float, 0x180 "
                                                       "and 0x280 only)"));
    return hec495Write(hec495::ObjPdoMode, uint8_t(mode));
}

quint64 CanSession::setHec495WorkMode(int mode)
{
    if (protocol() != CanProtocol::Hec495 || m_options.hec495Extended)
        return refuseJob(tr("the work mode is an HEC495 setting on standard frames"));
    if (mode != 0x02 && mode != 0x0A)
        return refuseJob(tr("the work mode is 0x02 (pitch, roll, acceleration, rate) or 0x0A (rate at 500 Hz)"));
    return hec495Write(hec495::ObjWorkMode, uint8_t(mode));
}

quint64 CanSession::setAllNodesOutput(bool on)
{
    // CANopen NMT to node 0 (every node); the HEC495 manual's "0x000 01 00 / 02 00" (every node,
    // not saved). No reply: confirmed by the target's PDOs, as setOutputEnabled does.
    if ((protocol() != CanProtocol::CanOpen && protocol() != CanProtocol::Hec495) || m_options.hec495Extended)
        return refuseJob(tr("output on or off for every node needs CANopen or an HEC495 on standard frames (NMT)"));
    CanJobStep send;
    send.tx = canopen::encodeNmt(on ? canopen::NmtStart : canopen::NmtStop, 0);
    send.what = on ? tr("NMT start, every node") : tr("NMT stop, every node");
    return outputJob(send.what, send, on);
}

quint64 CanSession::outputJob(const QString &title, const CanJobStep &action, bool on)
{
    // The action, then the data frames starting (the first one ends the wait) or staying away
    // for kNmtConfirmMs, after kNmtSettleMs for frames already on their way.
    CanJobStep watch;
    watch.hasTx = false;
    watch.what = title;
    watch.timeoutMs = kNmtConfirmMs;
    if (on) {
        watch.expect = CanJobStep::Expect::PdoFrom;
        return submitJob(CanJob{0, title, {action, watch}});
    }
    // Off is confirmed by data that stops, so a session that has not seen the target's data yet
    // (one just opened) first waits for a frame of it, up to kNmtConfirmMs.
    CanJobStep before;
    before.hasTx = false;
    before.what = title;
    before.expect = CanJobStep::Expect::DataSeen;
    before.timeoutMs = kNmtConfirmMs;
    CanJobStep settle;
    settle.hasTx = false;
    settle.what = title;
    settle.pauseMs = kNmtSettleMs;
    watch.expect = CanJobStep::Expect::NoPdoFrom;
    return submitJob(CanJob{0, title, {before, action, settle, watch}});
}

quint64 CanSession::setOutputEnabled(bool on)
{
    const QString title = on ? tr("output on") : tr("output off");
    switch (protocol()) {
    case CanProtocol::J1939:
        // 0x9D is confirmed by its reply, its effect by the data PGNs starting or stopping.
        return outputJob(title, j1939Write(j1939::RegOutputEnable, on ? 1 : 0, tr("output enable")), on);
    case CanProtocol::Hec495: {
        // 0x1083 is answered by the module; its PDOs starting or stopping show it took effect.
        const QString what = hec495::describeObject(hec495::ObjPdoStart, on ? 1 : 0);
        return outputJob(what, hecStep(hec495::ObjPdoStart, on ? 1 : 0, what), on);
    }
    case CanProtocol::CanOpen: {
        // NMT has no reply (CiA 301): the TPDOs starting or stopping confirm it.
        CanJobStep send;
        send.tx = canopen::encodeNmt(on ? canopen::NmtStart : canopen::NmtStop, node());
        send.what = on ? tr("NMT start") : tr("NMT stop");
        return outputJob(send.what, send, on);
    }
    case CanProtocol::Auto: break;
    }
    return refuseJob(tr("the protocol is not known yet: choose it or wait for traffic"));
}

quint64 CanSession::commandJob(uint32_t value, const QString &title, int followNode)
{
    if (protocol() == CanProtocol::J1939) {
        CanJobStep s = j1939Write(j1939::RegCommand, value, title);
        s.followNode = followNode;
        return submitJob(CanJob{0, title, {s}});
    }
    if (protocol() == CanProtocol::CanOpen) {
        CanJobStep s = sdoWriteStep(hip::ObjCommand, 0, value, 4, title);
        s.followNode = followNode;
        return submitJob(CanJob{0, title, {s}});
    }
    return refuseJob(tr("\"%1\" needs a HiPNUC J1939 or CANopen device (the HEC495 saves at once)").arg(title));
}

quint64 CanSession::save() { return commandJob(j1939::CommandSave, tr("save configuration"), -1); }
quint64 CanSession::reset() { return commandJob(j1939::CommandReset, tr("reset"), -1); }
quint64 CanSession::factoryReset()
{
    // Factory defaults bring back the default node ID; the session follows it. On CANopen the
    // firmware decides when: 1.7.1 saves and resets at once (8.28.44.22), 1.6.6 takes them at
    // the next power-up (5.4.1), so the session stays with the node it has until then.
    if (protocol() != CanProtocol::CanOpen)
        return commandJob(j1939::CommandFactory, tr("factory defaults"), canopen::kDefaultNode);
    CanJobStep command = sdoWriteStep(hip::ObjCommand, 0, hip::CommandFactory, 4, tr("factory defaults"));
    command.followNode = canopen::kDefaultNode;
    const CanJobStep probe = firmwareProbe([](std::optional<uint32_t> revision, CanJob &job, size_t at) {
        if (!revision || !hip::isV166Revision(*revision))
            return;
        job.steps[at + 1].followNode = -1;
        job.title += tr(" (firmware 1.6: they take effect at the next power-up)");
    });
    return submitJob(CanJob{0, tr("factory defaults"), {probe, command}});
}

quint64 CanSession::trigger(uint32_t pgn)
{
    if (protocol() != CanProtocol::J1939 || !j1939::isDataPgn(pgn))
        return refuseJob(tr("a one-shot trigger needs a J1939 device and a data PGN"));
    // Confirmed by the requested PGN arriving from the module (the request itself has no reply).
    CanJobStep s;
    s.tx = j1939::encodeReg(j1939::triggerRequest(node(), m_options.hostAddress, pgn));
    s.expect = CanJobStep::Expect::PgnFrom;
    s.pgn = pgn;
    s.timeoutMs = m_options.requestTimeoutMs;
    s.what = tr("trigger PGN %1").arg(QString::number(pgn, 16).toUpper());
    return submitJob(CanJob{0, s.what, {s}});
}

void CanSession::sendSync()
{
    sendFrame(canopen::encodeSync());
}

void CanSession::setSyncPeriod(int ms)
{
    inFamily<CanFamily>([ms](CanFamily &f) { f.setSyncPeriod(ms); });
}

void CanSession::sendNmt(uint8_t command, uint8_t n)
{
    sendFrame(canopen::encodeNmt(canopen::NmtCommand(command), n));
}

void CanSession::sendFrame(const CanFrame &f)
{
    inFamily<CanFamily>([frame = f](CanFamily &family) { family.sendFrame(frame); });
}

void CanSession::scanNodes(int from, int to)
{
    inFamily<CanFamily>([from, to](CanFamily &f) { f.scan(from, to); });
}

void CanSession::cancelScan()
{
    inFamily<CanFamily>([](CanFamily &f) { f.cancelScan(); });
}

} // namespace imudesk::device
