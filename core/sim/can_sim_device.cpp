#include "can_sim_device.h"

#include "kboot_bootloader.h"

#include "model/attitude.h"
#include "model/device_identity.h"
#include "protocol/can/canopen.h"
#include "protocol/can/hec495_can.h"
#include "protocol/can/hipnuc_canopen_objects.h"
#include "protocol/can/j1939.h"
#include "protocol/can/j1939_config.h"
#include "protocol/can/sdo.h"
#include "sim/hec495_simulator.h"

#include <cmath>

namespace imudesk::sim {

using namespace protocol::can;
namespace j = protocol::can::j1939;
namespace co = protocol::can::canopen;
namespace hec = protocol::can::hec495;

namespace {
constexpr uint8_t kStatusOk = 0;
constexpr uint8_t kStatusError = 1;
double wrap180(double a)
{
    while (a > 180.0)
        a -= 360.0;
    while (a <= -180.0)
        a += 360.0;
    return a;
}
} // namespace

CanSimDevice::HipnucConfig CanSimDevice::hipnucDefaults(bool canFd)
{
    HipnucConfig c;
    // v1.6.6 chapter 6: 100 ms default interval; the time PGN once a second.
    for (uint32_t pgn : {j::PgnAcc, j::PgnGyr, j::PgnRollPitch, j::PgnHeading, j::PgnMag, j::PgnQuat})
        c.pgnIntervalMs[pgn] = 100;
    c.pgnIntervalMs[j::PgnTime] = 1000;
    c.pgnIntervalMs[j::PgnIncl] = 0;
    c.pgnIntervalMs[j::PgnCanFd0] = canFd ? 10 : 0;
    return c;
}

namespace {
ModbusSimOptions registerSide(const CanSimOptions &o)
{
    ModbusSimOptions m;
    m.firmware = o.firmware;
    m.motion = o.motion;
    m.seed = o.seed;
    return m;
}
} // namespace

CanSimDevice::CanSimDevice(CanSimOptions options)
    : m_options(std::move(options)), m_motion(MotionModel::Options{m_options.seed, m_options.motion}),
      m_sensor(m_options.seed), m_registers(registerSide(m_options))
{
    m_ram = hipnucDefaults(m_options.canFd);
    if (m_options.node > 0)
        m_ram.node = m_options.node;
    m_flash = m_ram;
    if (m_options.node > 0)
        m_hec.node = m_options.node;
    m_hecFlash = m_hec;
    // The factory application (a small image that carries the firmware version).
    m_boot.installApplication(KbootBootloader::makeApplication(m_options.firmware, 4096, m_options.seed));
    powerCycle(0);
}

int CanSimDevice::node() const
{
    return m_activeNode;
}

int CanSimDevice::bitrate() const
{
    return m_options.hec495 ? hec::baudFromCode(m_activeBaudCode) : j::baudFromCode(m_activeBaudCode);
}

void CanSimDevice::powerCycle(double t)
{
    if (m_options.hec495) {
        m_hec = m_hecFlash;
        m_activeNode = m_hec.node;
        m_activeBaudCode = m_hec.baudCode;
    } else {
        m_ram = m_flash;
        m_activeNode = m_ram.node;
        m_activeBaudCode = m_ram.baudCode;
    }
    m_nmtState = co::StateOperational; // manual 8.25: initial state Operational
    m_inBootloader = !isJ1939() && !m_options.hec495 && !m_boot.applicationValid();
    if (m_inBootloader)
        m_boot.start(uint8_t(m_activeNode), int64_t(t * 1e6));
    m_bootPending = !isJ1939() && !m_options.hec495 && !m_inBootloader;
    m_syncCount = {};
    m_yawOffset = m_rollOffset = m_pitchOffset = 0;
    rescheduleAll(t);
}

model::Sample CanSimDevice::sampleAt(double t)
{
    const MotionState st = m_motion.at(t);
    const SensorReading r = m_sensor.sample(st);
    model::Sample s;
    s.source = "sim";
    s.acc = {r.acc.x(), r.acc.y(), r.acc.z()};
    s.gyr = {r.gyr.x(), r.gyr.y(), r.gyr.z()};
    s.mag = {r.mag.x(), r.mag.y(), r.mag.z()};
    const EulerAngles e = eulerEnu312(st.q);
    s.roll = wrap180(e.roll - m_rollOffset);
    s.pitch = e.pitch - m_pitchOffset;
    s.yaw = wrap180(e.yaw - m_yawOffset);
    const Eigen::Quaterniond q = canonical(quatFromEnu312({s.roll, s.pitch, s.yaw}));
    s.quat = {q.w(), q.x(), q.y(), q.z()};
    s.pressurePa = r.pressurePa;
    s.temperatureC = r.temperatureC;
    s.inclinationX = (m_ram.inclSignX ? -1 : 1) * s.pitch;
    s.inclinationY = (m_ram.inclSignY ? -1 : 1) * s.roll;
    s.deviceTimeMs = std::floor(t * 1000.0);
    s.fields = model::FieldAcc | model::FieldGyr | model::FieldMag | model::FieldEuler | model::FieldQuat
        | model::FieldPressure | model::FieldTemperature | model::FieldInclination | model::FieldDeviceTime;
    return s;
}

model::Sample CanSimDevice::hec495SampleAt(double t)
{
    // The compass's quantities as on its serial side (Hec495Simulator): the heading clockwise
    // from north (+-180 as in the read-all record), the field relative to the horizontal one.
    model::Sample s = sampleAt(t);
    model::setCompassHeading(s, -s.yaw, false);
    s.magRelative = {s.mag.x / Hec495Simulator::kFieldUnitUt, s.mag.y / Hec495Simulator::kFieldUnitUt,
                     s.mag.z / Hec495Simulator::kFieldUnitUt};
    s.fields = (s.fields & ~uint32_t(model::FieldMag)) | model::FieldMagRelative;
    return s;
}

void CanSimDevice::attitudeReset(uint32_t mode, double t)
{
    const EulerAngles e = eulerEnu312(m_motion.at(t).q);
    if (mode == 1)
        m_yawOffset = e.yaw;
    else if (mode == 2 || mode == 3) {
        m_rollOffset = e.roll;
        m_pitchOffset = e.pitch;
    } else if (mode == 5) {
        m_rollOffset = m_pitchOffset = 0;
    }
}

void CanSimDevice::rescheduleAll(double t)
{
    m_nextDueMs.clear();
    (void)t;
}

bool CanSimDevice::due(const std::string &key, double periodMs, double t)
{
    if (periodMs <= 0) {
        m_nextDueMs.erase(key);
        return false;
    }
    const double now = t * 1000.0;
    auto it = m_nextDueMs.find(key);
    if (it == m_nextDueMs.end()) {
        m_nextDueMs[key] = now + periodMs;
        return true;
    }
    if (now + 1e-6 < it->second)
        return false;
    it->second += periodMs;
    if (it->second <= now) // fell behind by more than a period: no burst
        it->second = now + periodMs;
    return true;
}

CanSimDevice::Frame CanSimDevice::tpdoFrame(int channel, double t)
{
    return co::encodeTpdo(channel, uint8_t(m_activeNode), sampleAt(t));
}

std::vector<CanSimDevice::Frame> CanSimDevice::poll(double t)
{
    std::vector<Frame> out;
    if (m_options.hec495) {
        const bool ext = isJ1939();
        // 100 ms * (N + 1) for every N the byte holds (N = 255: 25.6 s); the manual has no "off".
        if (!ext && due("hb", hec::heartbeatPeriodMs(m_hec.heartbeatN), t))
            out.push_back(co::encodeHeartbeat(uint8_t(m_activeNode), m_hec.pdoStarted && m_hec.rateCode ? 0x05 : 0x04));
        double period = hec::rateHzFromCode(m_hec.rateCode) > 0 ? 1000.0 / hec::rateHzFromCode(m_hec.rateCode) : 0;
        const bool gyroOnly = m_hec.workMode == 0x0A;
        if (gyroOnly && !ext)
            period = 2.0; // 500 Hz gyro mode
        if (!m_hec.pdoStarted)
            period = 0;
        if (due("pdo", period, t)) {
            const model::Sample s = hec495SampleAt(t);
            if (ext) {
                out.push_back(hec::encodeExtended(false, s));
                if (m_hecExtFormat2)
                    out.push_back(hec::encodeExtended(true, s));
            } else {
                const bool fixed = m_hec.pdoMode == hec::ModeFixed;
                for (int slot = 0; slot < hec::kPdoCount; ++slot) {
                    if (m_hec.pdoMode == hec::ModeFloatShort && slot > 1)
                        break;
                    if (gyroOnly && slot < 3)
                        continue;
                    out.push_back(hec::encodePdo(slot, uint8_t(m_activeNode), s, fixed));
                }
            }
        }
        return out;
    }
    if (isJ1939()) {
        if (!m_ram.outputEnabled) {
            m_nextDueMs.clear();
            return out;
        }
        for (const auto &[pgn, ms] : m_ram.pgnIntervalMs) {
            if (!due("pgn" + std::to_string(pgn), ms, t))
                continue;
            if (pgn == j::PgnTime) {
                const auto ms64 = int64_t(t * 1000.0);
                // Without GNSS time the module sends its uptime with a zero date (notes 4.2).
                out.push_back(j::encodeTime(uint8_t(m_activeNode), j::UtcTime{2000, 0, 0, int(ms64 / 3600000 % 24),
                                                                          int(ms64 / 60000 % 60), int(ms64 / 1000 % 60),
                                                                          int(ms64 % 1000)}));
            } else {
                out.push_back(j::encodeData(pgn, uint8_t(m_activeNode), sampleAt(t), m_options.firmware != "1.6.6"));
            }
        }
        return out;
    }
    // CANopen
    if (m_inBootloader)
        return pollBootloader(t);
    if (m_bootPending) {
        m_bootPending = false;
        out.push_back(co::encodeHeartbeat(uint8_t(m_activeNode), co::StateBootUp));
    }
    if (due("hb", m_ram.heartbeatMs, t))
        out.push_back(co::encodeHeartbeat(uint8_t(m_activeNode), m_nmtState));
    const bool operational = m_nmtState == co::StateOperational;
    for (int c = 0; c < co::kTpdoCount; ++c) {
        const bool async = m_ram.tpdoType[size_t(c)] >= 0xFE;
        const double period = operational && async ? m_ram.tpdoPeriodMs[size_t(c)] : 0;
        if (due("tpdo" + std::to_string(c), period, t))
            out.push_back(tpdoFrame(c, t));
    }
    return out;
}

std::vector<CanSimDevice::Frame> CanSimDevice::pollBootloader(double t)
{
    const auto tUs = int64_t(t * 1e6);
    std::vector<Frame> out = m_boot.takeDue(tUs);
    switch (m_boot.takeRequest(tUs)) {
    case CanBootloader::Request::StartApplication:
        if (const auto v = m_boot.applicationVersion(); v && model::FirmwareVersion::parse(*v))
            m_options.firmware = *v;
        powerCycle(t); // the application starts: boot-up on the next poll
        break;
    case CanBootloader::Request::PowerLoss:
        powerCycle(t); // no valid application: back in the bootloader
        break;
    case CanBootloader::Request::None: break;
    }
    return out;
}

std::vector<CanSimDevice::Frame> CanSimDevice::handle(const Frame &in, double t)
{
    if (m_options.hec495)
        return handleHec495(in, t);
    if (isJ1939())
        return handleJ1939(in, t);
    return handleCanOpen(in, t);
}

std::vector<CanSimDevice::Frame> CanSimDevice::handleJ1939(const Frame &in, double t)
{
    std::vector<Frame> out;
    const auto req = j::parseReg(in);
    if (!req || (req->da != m_activeNode && req->da != j::kBroadcast) || req->sa == m_activeNode)
        return out;
    j::RegMessage reply{req->sa, uint8_t(m_activeNode), req->addr, req->cmd, kStatusOk, req->value};
    bool resetAfter = false;
    auto ok = [&] { out.push_back(j::encodeReg(reply)); };
    auto bad = [&] {
        reply.status = kStatusError;
        out.push_back(j::encodeReg(reply));
    };
    if (req->cmd == j::CmdRead) {
        uint32_t v = 0;
        bool known = true;
        if (const auto pgn = j::pgnOfIntervalRegister(req->addr))
            v = m_ram.pgnIntervalMs.count(*pgn) ? m_ram.pgnIntervalMs.at(*pgn) : 0;
        else if (req->addr == j::RegBaud) v = m_ram.baudCode;
        else if (req->addr == j::RegNodeId) v = uint32_t(m_ram.node);
        else if (req->addr == j::RegOutputEnable) v = m_ram.outputEnabled ? 1 : 0;
        else if (req->addr == j::RegInclSignX) v = m_ram.inclSignX;
        else if (req->addr == j::RegInclSignY) v = m_ram.inclSignY;
        else if (req->addr == j::RegVersion) {
            const auto fw = model::FirmwareVersion::parse(m_options.firmware);
            v = fw ? uint32_t(fw->major * 100 + fw->minor * 10 + fw->patch) : 0;
        } else {
            // 7.22.41: a register of the Modbus list (a write-only one or an address it does not
            // have: status 1).
            const auto r = m_registers.read(req->addr, 1, int64_t(t * 1e6));
            known = r.exception == 0 && r.values.size() == 1;
            v = known ? r.values[0] : 0;
        }
        reply.value = v;
        known ? ok() : bad();
        return out;
    }
    if (req->cmd != j::CmdWrite) {
        bad();
        return out;
    }
    const uint32_t v = req->value;
    if (const auto pgn = j::pgnOfIntervalRegister(req->addr)) {
        if (!j::validInterval(v) || (*pgn == j::PgnCanFd0 && !m_options.canFd)) {
            bad();
            return out;
        }
        m_ram.pgnIntervalMs[*pgn] = v;
        m_nextDueMs.erase("pgn" + std::to_string(*pgn));
        ok();
        return out;
    }
    switch (req->addr) {
    case j::RegTrigger:
        // No reply: the module sends the data frame at once (7.23).
        if (j::isDataPgn(v) && v != j::PgnTime && (v != j::PgnCanFd0 || m_options.canFd))
            out.push_back(j::encodeData(v, uint8_t(m_activeNode), sampleAt(t)));
        return out;
    case j::RegOutputEnable:
        if (v > 1) return bad(), out;
        m_ram.outputEnabled = v == 1;
        break;
    case j::RegCommand:
        if (v == j::CommandSave) m_flash = m_ram;
        else if (v == j::CommandFactory) {
            m_flash = hipnucDefaults(m_options.canFd);
            resetAfter = true;
        } else if (v == j::CommandReset) resetAfter = true;
        else return bad(), out;
        m_registers.write(protocol::modbus::reg::kCtrl, uint16_t(v), int64_t(t * 1e6)); // the list's registers too
        break;
    case protocol::modbus::reg::kBaud:
    case protocol::modbus::reg::kNodeId:
    case protocol::modbus::reg::kHeadingMode:
    case protocol::modbus::reg::kUrfr:
        // 7.22.41: the Modbus list's writable registers (the serial port's baud and Modbus ID
        // take effect on that port; the J1939 side goes on as it is).
        if (v > 0xFFFF || m_registers.write(uint16_t(req->addr), uint16_t(v), int64_t(t * 1e6)).exception != 0)
            return bad(), out;
        break;
    case j::RegBaud:
        if (v > 4) return bad(), out;
        m_ram.baudCode = v;
        break;
    case j::RegNodeId:
        if (v < 1 || v > 127) return bad(), out;
        m_ram.node = int(v);
        break;
    case j::RegAttitudeReset:
        if (v != 1 && v != 2 && v != 3 && v != 5) return bad(), out;
        attitudeReset(v, t);
        break;
    case j::RegInclSignX:
    case j::RegInclSignY:
        if (v > 1) return bad(), out;
        (req->addr == j::RegInclSignX ? m_ram.inclSignX : m_ram.inclSignY) = v;
        break;
    default: return bad(), out;
    }
    ok();
    if (resetAfter)
        powerCycle(t);
    return out;
}

bool CanSimDevice::writeHipnucObject(uint16_t index, uint8_t sub, uint32_t value, uint32_t *abort, double t, bool *resetAfter)
{
    const uint16_t nodeObj = m_options.firmware == "1.6.6" ? co::hipnuc::ObjNodeIdV166 : co::hipnuc::ObjNodeId;
    if (index >= 0x1800 && index <= 0x1805) {
        const size_t c = index - 0x1800u;
        if (sub == co::hipnuc::kSubEventTimer) {
            if (value > 0xFFFF) return *abort = co::AbortValueHigh, false;
            m_ram.tpdoPeriodMs[c] = uint16_t(value);
            m_nextDueMs.erase("tpdo" + std::to_string(c));
            return true;
        }
        if (sub == co::hipnuc::kSubTransmissionType) {
            if (value == 0 || (value > 240 && value < 0xFE) || value > 0xFF) return *abort = co::AbortValueRange, false;
            m_ram.tpdoType[c] = uint8_t(value);
            m_syncCount[c] = 0;
            m_nextDueMs.erase("tpdo" + std::to_string(c));
            return true;
        }
        return *abort = co::AbortNoSubIndex, false;
    }
    if (sub != 0)
        return *abort = co::AbortNoSubIndex, false;
    if (index == co::hipnuc::ObjCommand) {
        if (value == co::hipnuc::CommandSave) m_flash = m_ram;
        else if (value == co::hipnuc::CommandFactory) {
            // v1.7.1 8.28.44.22: saved and reset at once; v1.6.6 5.4.1: "takes effect after a
            // power-up" (the defaults are saved; the running configuration stays).
            m_flash = hipnucDefaults(m_options.canFd);
            *resetAfter = m_options.firmware != "1.6.6";
        } else if (value == co::hipnuc::CommandReset) *resetAfter = true;
        else return *abort = co::AbortValueRange, false;
        return true;
    }
    if (index == nodeObj) {
        if (value < 1 || value > 127) return *abort = co::AbortValueRange, false;
        m_ram.node = int(value);
        return true;
    }
    if (index == co::hipnuc::ObjBaud) {
        if (co::hipnuc::baudFromCode(value) == 0) return *abort = co::AbortValueRange, false; // 0, 2, 3, 4 only
        m_ram.baudCode = value;
        return true;
    }
    if (index == co::hipnuc::ObjHeartbeat) {
        if (value > 0xFFFF) return *abort = co::AbortValueHigh, false;
        m_ram.heartbeatMs = uint16_t(value);
        m_nextDueMs.erase("hb");
        return true;
    }
    if (index == co::hipnuc::ObjInclSignX || index == co::hipnuc::ObjInclSignY) {
        if (value > 1) return *abort = co::AbortValueRange, false;
        (index == co::hipnuc::ObjInclSignX ? m_ram.inclSignX : m_ram.inclSignY) = value;
        return true;
    }
    if (index == co::hipnuc::ObjInclZero) {
        if (value != 2 && value != 5) return *abort = co::AbortValueRange, false;
        attitudeReset(value, t);
        return true;
    }
    *abort = co::AbortNoObject;
    return false;
}

bool CanSimDevice::readHipnucObject(uint16_t index, uint8_t sub, uint32_t *value, int *size, uint32_t *abort) const
{
    const uint16_t nodeObj = m_options.firmware == "1.6.6" ? co::hipnuc::ObjNodeIdV166 : co::hipnuc::ObjNodeId;
    *size = 4;
    if (index >= 0x1800 && index <= 0x1805) {
        const size_t c = index - 0x1800u;
        if (sub == 1) *value = co::tpdoBase(int(c)) + uint32_t(m_activeNode); // COB-ID
        else if (sub == co::hipnuc::kSubTransmissionType) { *value = m_ram.tpdoType[c]; *size = 1; }
        else if (sub == co::hipnuc::kSubEventTimer) { *value = m_ram.tpdoPeriodMs[c]; *size = 2; }
        else return *abort = co::AbortNoSubIndex, false;
        return true;
    }
    if (sub != 0 && index != 0x1018)
        return *abort = co::AbortNoSubIndex, false;
    if (index == 0x1000) *value = 0;                      // device type: no profile
    else if (index == 0x1018 && sub == 3) {
        // Revision number: ImuDesk's simulator reports the firmware version as major << 16 | minor << 8 | patch
        // (the manuals name no version object; the CAN update reads this one and accepts an abort).
        const auto fw = model::FirmwareVersion::parse(m_options.firmware);
        *value = fw ? uint32_t(fw->major << 16 | fw->minor << 8 | fw->patch) : 0;
    } else if (index == 0x1018) { *value = sub == 0 ? 3 : 0; if (sub > 3) return *abort = co::AbortNoSubIndex, false; }
    else if (index == nodeObj) *value = uint32_t(m_ram.node);
    else if (index == co::hipnuc::ObjBaud) *value = m_ram.baudCode;
    else if (index == co::hipnuc::ObjHeartbeat) { *value = m_ram.heartbeatMs; *size = 2; }
    else if (index == co::hipnuc::ObjInclSignX) *value = m_ram.inclSignX;
    else if (index == co::hipnuc::ObjInclSignY) *value = m_ram.inclSignY;
    else if (index == co::hipnuc::ObjCommand || index == co::hipnuc::ObjInclZero) return *abort = co::AbortWriteOnly, false;
    else return *abort = co::AbortNoObject, false;
    return true;
}

std::vector<CanSimDevice::Frame> CanSimDevice::handleCanOpen(const Frame &in, double t)
{
    std::vector<Frame> out;
    const uint8_t node = uint8_t(m_activeNode);
    if (m_inBootloader) {
        // Only the bootloader's SDOs; its replies come out of poll() when their time has come.
        if (const auto sdo = co::parseSdo(in))
            m_boot.handle(*sdo, in, int64_t(t * 1e6));
        return out;
    }
    if (const auto nmt = co::parseNmt(in)) {
        if (nmt->node != 0 && nmt->node != node)
            return out;
        switch (nmt->command) {
        case co::NmtStart: m_nmtState = co::StateOperational; break;
        case co::NmtStop: m_nmtState = co::StateStopped; break;
        case co::NmtPreOperational: m_nmtState = co::StatePreOperational; break;
        case co::NmtResetNode: powerCycle(t); break;
        case co::NmtResetCommunication:
            m_activeNode = m_ram.node;
            m_nmtState = co::StateOperational;
            m_bootPending = true;
            m_nextDueMs.clear();
            break;
        default: break;
        }
        return out;
    }
    if (co::isSync(in)) {
        if (m_nmtState != co::StateOperational)
            return out;
        for (int c = 0; c < co::kTpdoCount; ++c) {
            const uint8_t type = m_ram.tpdoType[size_t(c)];
            if (type < 1 || type > 240)
                continue;
            if (++m_syncCount[size_t(c)] >= type) {
                m_syncCount[size_t(c)] = 0;
                out.push_back(tpdoFrame(c, t));
            }
        }
        return out;
    }
    const auto sdo = co::parseSdo(in);
    if (!sdo || sdo->fromDevice || sdo->node != node || m_nmtState == co::StateStopped)
        return out;
    uint32_t abort = 0;
    if (sdo->kind == co::SdoKind::DownloadExpedited && sdo->index == 0x1F51 && sdo->sub == 0x05) {
        // Enter the bootloader (notes 4.5 step 1): acknowledged, then the module reboots into it.
        out.push_back(co::sdoWriteReply(node, sdo->index, sdo->sub));
        m_inBootloader = true;
        m_boot.start(node, int64_t(t * 1e6));
        return out;
    }
    if (sdo->kind == co::SdoKind::DownloadExpedited) {
        bool resetAfter = false;
        if (writeHipnucObject(sdo->index, sdo->sub, sdo->value, &abort, t, &resetAfter))
            out.push_back(co::sdoWriteReply(node, sdo->index, sdo->sub));
        else
            out.push_back(co::sdoAbortFrame(node, sdo->index, sdo->sub, abort));
        if (resetAfter)
            powerCycle(t);
    } else if (sdo->kind == co::SdoKind::UploadRequest) {
        uint32_t value = 0;
        int size = 4;
        if (readHipnucObject(sdo->index, sdo->sub, &value, &size, &abort))
            out.push_back(co::sdoReadReply(node, sdo->index, sdo->sub, value, size));
        else
            out.push_back(co::sdoAbortFrame(node, sdo->index, sdo->sub, abort));
    } else if (sdo->kind != co::SdoKind::Abort) {
        out.push_back(co::sdoAbortFrame(node, sdo->index, sdo->sub,
                                        sdo->kind == co::SdoKind::Unknown ? co::AbortCommand : co::AbortUnsupported));
    }
    return out;
}

std::vector<CanSimDevice::Frame> CanSimDevice::handleHec495(const Frame &in, double t)
{
    (void)t;
    std::vector<Frame> out;
    const bool ext = isJ1939();
    if (!ext) {
        if (const auto nmt = co::parseNmt(in)) {
            // 0x000 [01 00] / [02 00]: start / stop PDOs of every node, not saved.
            if (nmt->command == co::NmtStart || nmt->command == co::NmtStop)
                m_hec.pdoStarted = nmt->command == co::NmtStart;
            return out;
        }
    }
    const auto w = hec::parseWrite(in);
    if (!w || w->reply || w->extended != ext || (!ext && w->node != m_activeNode))
        return out;
    const uint8_t node = uint8_t(m_activeNode);
    const uint32_t v = w->value;
    bool okWrite = true;
    switch (w->index) {
    case hec::ObjNodeId:
        okWrite = !ext && v >= 1 && v <= 127;
        if (okWrite) m_hecFlash.node = int(v), m_hec.node = int(v);
        break;
    case hec::ObjBaud:
        okWrite = hec::baudFromCode(v) > 0 && (ext || v != 6);
        if (okWrite) m_hecFlash.baudCode = v, m_hec.baudCode = v;
        break;
    case hec::ObjPdoMode:
        if (ext) {
            okWrite = v <= 1;
            if (okWrite) m_hecExtFormat2 = v == 1;
        } else {
            okWrite = v == 0 || v == 1 || v == 3;
            if (okWrite) m_hec.pdoMode = v, m_hecFlash.pdoMode = v;
        }
        break;
    case hec::ObjHeartbeat:
        okWrite = !ext;
        if (okWrite) m_hec.heartbeatN = v, m_hecFlash.heartbeatN = v, m_nextDueMs.erase("hb");
        break;
    case hec::ObjPdoStart:
        okWrite = v <= 1;
        if (okWrite) m_hec.pdoStarted = v == 1, m_hecFlash.pdoStarted = v == 1;
        break;
    case hec::ObjPdoRate:
        okWrite = v <= 6;
        if (okWrite) m_hec.rateCode = v, m_hecFlash.rateCode = v, m_nextDueMs.erase("pdo");
        break;
    case hec::ObjWorkMode:
        okWrite = !ext && (v == 0x02 || v == 0x0A);
        if (okWrite) m_hec.workMode = v, m_hecFlash.workMode = v, m_nextDueMs.erase("pdo");
        break;
    default: okWrite = false; break;
    }
    if (okWrite)
        out.push_back(hec::writeReply(node, w->index, ext));
    else if (!ext)
        out.push_back(co::sdoAbortFrame(node, w->index, w->sub, co::AbortValueRange));
    return out;
}

} // namespace imudesk::sim
