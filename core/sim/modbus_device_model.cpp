#include "modbus_device_model.h"

#include "model/mounting.h"
#include "protocol/modbus/hipnuc_writes.h"
#include "protocol/modbus/identity_block.h"
#include "protocol/modbus/register_block.h"

#include <QModbusPdu>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace imudesk::sim {

using protocol::modbus::DeviceKind;
using protocol::modbus::HipnucWrites;
using protocol::modbus::RegisterBlock;
using protocol::modbus::RegisterDef;
using protocol::modbus::RegisterMap;
namespace reg = protocol::modbus::reg;

namespace {

constexpr uint16_t kSensorEnd = reg::kHeavePeriod;                               // 0x51
constexpr uint16_t kIdentityEnd = reg::kIdentityStart + reg::kIdentityCount - 1; // 0x83
constexpr double kLevelLimitDeg = 15.0;

int16_t toI16(double v, double scale)
{
    const double r = std::round(v / scale);
    return int16_t(std::clamp(r, -32768.0, 32767.0));
}

int32_t toI32(double v, double scale)
{
    const double r = std::round(v / scale);
    return int32_t(std::clamp(r, -2147483648.0, 2147483647.0));
}

Eigen::Quaterniond axisQuat(double deg, const Eigen::Vector3d &axis)
{
    return Eigen::Quaterniond(Eigen::AngleAxisd(deg * model::kDegToRad, axis));
}

uint64_t splitmix(uint64_t &x)
{
    uint64_t z = (x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

} // namespace

ModbusDeviceModel::ModbusDeviceModel(ModbusSimOptions options)
    : m_options(std::move(options)),
      m_motion(MotionModel::Options{m_options.seed, m_options.motion}),
      m_sensor(m_options.seed)
{
    const auto fw = model::FirmwareVersion::parse(m_options.firmware);
    m_firmware = fw.value_or(model::FirmwareVersion{1, 7, 1});
    m_edition = m_firmware >= model::FirmwareVersion{1, 7, 1} ? model::ManualEdition::V171 : model::ManualEdition::V166;
    uint64_t state = m_options.seed ^ 0x4D4F44425553ull;
    char buf[20];
    std::snprintf(buf, sizeof buf, "%016llX", static_cast<unsigned long long>(splitmix(state)));
    m_serial = buf;
    m_saved = factory();
    if (m_options.nodeId > 0)
        m_saved.nodeId = m_options.nodeId;
    if (m_options.baud > 0)
        m_saved.baud = m_options.baud;
    m_running = m_saved;
    reset(0);
    m_resets = 0;
}

ModbusDeviceModel::Config ModbusDeviceModel::factory() const
{
    Config c;
    if (m_options.kind == DeviceKind::Hec495) {
        c.nodeId = protocol::modbus::kHec495DefaultId;
        c.baud = 9600;
    }
    return c;
}

std::string ModbusDeviceModel::productName() const
{
    if (m_options.kind == DeviceKind::Hec495)
        return "HEC495";
    return m_options.model + "R3N-485-000";
}

uint16_t ModbusDeviceModel::swVersion() const
{
    return uint16_t(m_firmware.major * 100 + m_firmware.minor * 10 + m_firmware.patch);
}

void ModbusDeviceModel::reset(int64_t nowUs)
{
    m_running = m_saved;
    m_startUs = nowUs;
    m_snapshotUs = -1;
    m_yawRefDeg = m_running.headingMode == 0 ? eulerEnu312(rawAttitudeAt(nowUs)).yaw : 0.0;
    ++m_resets;
}

Eigen::Matrix3d ModbusDeviceModel::userFromSensor() const
{
    const model::Matrix3 m = model::Mounting::userFromSensor(m_running.mountingCode);
    Eigen::Matrix3d r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r(i, j) = m[size_t(i)][size_t(j)];
    return r;
}

Eigen::Quaterniond ModbusDeviceModel::rawAttitudeAt(int64_t nowUs) const
{
    const MotionState ms = m_motion.at(double(nowUs) * 1e-6);
    const Eigen::Quaterniond qus(userFromSensor());
    return canonical(ms.q * qus.conjugate() * m_running.level);
}

Eigen::Quaterniond ModbusDeviceModel::attitudeAt(int64_t nowUs) const
{
    Eigen::Quaterniond q = rawAttitudeAt(nowUs);
    if (m_running.headingMode == 0)
        q = axisQuat(-m_yawRefDeg, Eigen::Vector3d::UnitZ()) * q;
    return canonical(q);
}

void ModbusDeviceModel::refreshSnapshot(int64_t nowUs)
{
    if (m_snapshotUs == nowUs)
        return;
    m_snapshotUs = nowUs;
    const MotionState ms = m_motion.at(double(nowUs) * 1e-6);
    const SensorReading r = m_sensor.sample(ms);
    const Eigen::Matrix3d m = m_running.level.conjugate().toRotationMatrix() * userFromSensor();
    const Eigen::Vector3d acc = m * r.acc, gyr = m * r.gyr, mag = m * r.mag;
    const Eigen::Quaterniond q = attitudeAt(nowUs);
    const EulerAngles e = eulerEnu312(q);

    if (m_options.kind == DeviceKind::Hec495) {
        const double heading = std::fmod(360.0 - e.yaw, 360.0);
        m_hecRegs.clear();
        for (double v : {e.pitch, e.roll, heading}) {
            const auto w = RegisterBlock::wordsF32le(float(v));
            m_hecRegs.insert(m_hecRegs.end(), w.begin(), w.end());
        }
        return;
    }
    const auto &map = RegisterMap::hipnucAll();
    auto scale = [&map](uint16_t a) { return map.find(a)->scale; };
    m_sensorRegs.assign(size_t(kSensorEnd - reg::kSensorStart + 1), 0);
    auto put16 = [this](uint16_t a, int16_t v) { m_sensorRegs[a - reg::kSensorStart] = uint16_t(v); };
    auto put32 = [this](uint16_t a, int32_t v) {
        const auto w = RegisterBlock::wordsI32(v);
        m_sensorRegs[a - reg::kSensorStart] = w[0];
        m_sensorRegs[a - reg::kSensorStart + 1] = w[1];
    };
    for (int i = 0; i < 3; ++i) {
        put16(uint16_t(0x34 + i), toI16(acc[i], scale(0x34)));
        put16(uint16_t(0x37 + i), toI16(gyr[i], scale(0x37)));
        put16(uint16_t(0x3A + i), toI16(mag[i], scale(0x3A)));
    }
    put32(0x3D, toI32(e.roll, scale(0x3D)));
    put32(0x3F, toI32(e.pitch, scale(0x3F)));
    put32(0x41, toI32(e.yaw, scale(0x41)));
    put16(reg::kTemp, toI16(r.temperatureC, scale(reg::kTemp)));
    put32(0x44, toI32(r.pressurePa, scale(0x44)));
    put16(0x46, toI16(q.w(), scale(0x46)));
    put16(0x47, toI16(q.x(), scale(0x47)));
    put16(0x48, toI16(q.y(), scale(0x48)));
    put16(0x49, toI16(q.z(), scale(0x49)));
    put16(0x4A, toI16(e.roll, scale(0x4A)));
    put16(0x4B, toI16(e.pitch, scale(0x4B)));
    // 0x4E HEAVE and 0x51 HEAVE_PERIOD stay 0: the motion model has no heave.
}

std::optional<uint16_t> ModbusDeviceModel::registerAt(uint16_t address, int64_t nowUs)
{
    if (m_options.kind == DeviceKind::Hec495) {
        if (address < reg::kHecAngles || address >= reg::kHecAngles + reg::kHecAngleCount)
            return std::nullopt;
        refreshSnapshot(nowUs);
        return m_hecRegs[address - reg::kHecAngles];
    }
    switch (address) {
    case reg::kBaud: return HipnucWrites::codeForBaud(m_running.baud).value_or(5);
    case reg::kNodeId: return uint16_t(m_running.nodeId);
    case reg::kHeadingMode: return uint16_t(m_running.headingMode);
    default: break;
    }
    if (address >= reg::kSensorStart && address <= kSensorEnd) {
        refreshSnapshot(nowUs);
        return m_sensorRegs[address - reg::kSensorStart];
    }
    if (address >= reg::kIdentityStart && address <= kIdentityEnd) {
        protocol::modbus::IdentityBlock id;
        id.productName = productName();
        id.swVersion = swVersion();
        id.blVersion = 107;
        id.serial = m_serial;
        return id.encode()[address - reg::kIdentityStart];
    }
    return std::nullopt;
}

ModbusDeviceModel::ReadResult ModbusDeviceModel::read(uint16_t start, uint16_t count, int64_t nowUs)
{
    ReadResult r;
    ++m_reads;
    if (count == 0 || count > 125) {
        r.exception = QModbusPdu::IllegalDataValue;
        return r;
    }
    if (m_options.kind == DeviceKind::Hec495 && start == reg::kHecPitchSingle && count == 2) {
        // HEC495 manual: "读取 Pitch(X 轴)倾斜角度" reads (0x0005, 2) and gets the pitch float.
        refreshSnapshot(nowUs);
        r.values = {m_hecRegs[0], m_hecRegs[1]};
        return r;
    }
    if (uint32_t(start) + count > 0x10000) {
        r.exception = QModbusPdu::IllegalDataAddress;
        return r;
    }
    r.values.reserve(count);
    for (uint32_t a = start; a < uint32_t(start) + count; ++a) {
        const auto v = registerAt(uint16_t(a), nowUs);
        if (!v) {
            r.exception = QModbusPdu::IllegalDataAddress;
            r.values.clear();
            return r;
        }
        r.values.push_back(*v);
    }
    return r;
}

ModbusDeviceModel::WriteResult ModbusDeviceModel::write(uint16_t address, uint16_t value, int64_t nowUs)
{
    WriteResult w;
    ++m_writes;
    if (m_options.kind == DeviceKind::Hec495) {
        w.exception = QModbusPdu::IllegalFunction;
        return w;
    }
    const RegisterDef *def = RegisterMap::hipnuc(m_edition).find(address);
    if (!def || !def->writable()) {
        w.exception = QModbusPdu::IllegalDataAddress;
        return w;
    }
    if (!RegisterMap::accepts(*def, value)) {
        w.exception = QModbusPdu::IllegalDataValue;
        return w;
    }
    const Config before = m_running;
    switch (address) {
    case reg::kCtrl:
        if (value == 0x0000) {
            m_saved = m_running;
        } else {
            if (value == 0x0001)
                m_saved = factory();
            reset(nowUs);
            w.effects.reset = true;
        }
        break;
    case reg::kBaud: m_running.baud = *HipnucWrites::baudForCode(value); break;
    case reg::kNodeId: m_running.nodeId = value; break;
    case reg::kHeadingMode:
        if (value == 0 && m_running.headingMode != 0)
            m_yawRefDeg = eulerEnu312(rawAttitudeAt(nowUs)).yaw; // 6-axis: heading 0 from here
        m_running.headingMode = value;
        break;
    case reg::kAutoLevel:
        if (value == 5) {
            m_running.level = Eigen::Quaterniond::Identity();
            m_running.levelled = false;
        } else {
            m_running.level = Eigen::Quaterniond::Identity();
            const EulerAngles e = eulerEnu312(rawAttitudeAt(nowUs));
            const bool upright = std::abs(e.roll) < kLevelLimitDeg;
            const bool inverted = std::abs(e.roll) > 180.0 - kLevelLimitDeg;
            if (std::abs(e.pitch) < kLevelLimitDeg && (upright || inverted)) {
                // q = qz(yaw) qx(pitch) qy(roll): remove qx qy (and keep 180 deg of roll when inverted).
                Eigen::Quaterniond tilt = axisQuat(e.pitch, Eigen::Vector3d::UnitX()) * axisQuat(e.roll, Eigen::Vector3d::UnitY());
                Eigen::Quaterniond c = tilt.conjugate();
                if (inverted)
                    c = c * axisQuat(180.0, Eigen::Vector3d::UnitY());
                m_running.level = c;
                m_running.levelled = true;
            } else {
                m_running.level = before.level; // too far from level: nothing changes
            }
        }
        m_snapshotUs = -1;
        break;
    case reg::kUrfr:
        m_running.mountingCode = *HipnucWrites::mountingCode(m_edition, value);
        m_snapshotUs = -1;
        break;
    default: break;
    }
    if (m_running.nodeId != before.nodeId)
        w.effects.nodeId = m_running.nodeId;
    if (m_running.baud != before.baud)
        w.effects.baud = m_running.baud;
    return w;
}

} // namespace imudesk::sim
