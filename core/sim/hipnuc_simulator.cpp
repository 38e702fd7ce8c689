#include "hipnuc_simulator.h"

#include "model/main_status.h"
#include "model/sample.h"
#include "protocol/hipnuc/crc16.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/nmea/nmea_parser.h"

#include <QLoggingCategory>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "simulator_detail.h"

Q_LOGGING_CATEGORY(imudesk::sim::detail::lcSim, "imudesk.core.sim", QtInfoMsg)

namespace imudesk::sim {

using namespace detail;

const char *stateName(HipnucSimulator::State s)
{
    switch (s) {
    case HipnucSimulator::State::App: return "app";
    case HipnucSimulator::State::Rebooting: return "rebooting";
    case HipnucSimulator::State::Bootloader: return "bootloader";
    }
    return "?";
}

// ---------------------------------------------------------------------------------------
// Coverage of field directions for the magnetometer calibration progress

void HipnucSimulator::Coverage::reset()
{
    cells.fill(false);
    visited = 0;
    samples = 0;
    meanUt = 0;
    sumSquaresUt = 0;
}

void HipnucSimulator::Coverage::add(const Eigen::Vector3d &d, double fieldUt)
{
    ++samples;
    const double delta = fieldUt - meanUt;
    meanUt += delta / samples;
    sumSquaresUt += delta * (fieldUt - meanUt);

    constexpr int kBands = 6, kSectors = kMagCalCells / kBands;
    const int band = std::clamp(int(std::floor((d.z() + 1.0) * 0.5 * kBands)), 0, kBands - 1);
    const double az = std::atan2(d.y(), d.x()); // -pi..pi
    const int sector = std::clamp(int(std::floor((az + std::numbers::pi) / (2 * std::numbers::pi) * kSectors)), 0, kSectors - 1);
    bool &cell = cells[size_t(band * kSectors + sector)];
    if (!cell) {
        cell = true;
        ++visited;
    }
}

int HipnucSimulator::Coverage::progress() const
{
    return std::min(100, visited * 100 / kMagCalCellsNeeded);
}

double HipnucSimulator::Coverage::spreadUt() const
{
    return samples > 0 ? std::sqrt(sumSquaresUt / samples) : 0.0;
}

// ---------------------------------------------------------------------------------------
// Construction, identity, gates

HipnucSimulator::HipnucSimulator(SimOptions options)
    : m_options(std::move(options)),
      // The rotation fixture holds the module still except during an MCAL (moduleStateAt).
      m_motion(MotionModel::Options{m_options.seed, m_options.faults.magCalFixture ? Motion::Static : m_options.motion}),
      m_fixtureMotion(MotionModel::Options{m_options.seed, Motion::Tumble}),
      m_sensor(m_options.seed)
{
    auto fw = model::FirmwareVersion::parse(m_options.firmware);
    if (!fw) {
        qCWarning(lcSim) << "unparsable firmware version" << m_options.firmware.c_str() << "- simulating 1.7.1";
        fw = model::FirmwareVersion{1, 7, 1};
    }
    m_firmware = *fw;
    const auto &gs = m_options.faults.gyroScalePct;
    m_sensor.setGyroScaleErrors(Eigen::Vector3d::Constant(m_options.gyroScaleError)
                                + Eigen::Vector3d(gs[0], gs[1], gs[2]) * 0.01);
    m_sensor.setAccError(accErrorOf(m_options.faults));
    const auto &gm = m_options.faults.gyroMisalignmentDeg;
    m_sensor.setGyroMisalignment(Eigen::Vector3d(gm[0], gm[1], gm[2]) * (std::numbers::pi / 180.0));
    m_sensor.setGyroNoiseFactor(m_options.faults.gyroNoiseFactor);
    const auto &mount = m_options.faults.mountingErrorDeg;
    m_mounted = mount != std::array<double, 3>{0, 0, 0};
    m_mounting = quatFromEnu312({mount[0], mount[1], mount[2]});
    m_edition = m_firmware >= model::FirmwareVersion{1, 7, 1} ? ManualEdition::V171 : ManualEdition::V166;
    m_family = model::familyOfProduct(m_options.model);
    char buf[20];
    std::snprintf(buf, sizeof buf, "%016llX", static_cast<unsigned long long>(mix(m_options.seed ^ 0x0439956980000000ull)));
    m_uuid = m_options.serial.empty() ? std::string(buf) : m_options.serial;

    m_saved = factoryConfig();
    if (m_options.baud > 0)
        m_saved.baud = m_options.baud;
    m_running = m_saved;
    m_bootloader.installApplication(KbootBootloader::makeApplication(m_firmware.toString(), kInitialAppSize,
                                                                     m_options.seed));
    startApp(0);
}

bool HipnucSimulator::hasMagnetometer() const
{
    return m_family != model::ProductFamily::HI02 && m_family != model::ProductFamily::HI50;
}

bool HipnucSimulator::hasPmux() const
{
    return m_family != model::ProductFamily::HI02 && m_family != model::ProductFamily::HI50
        && m_family != model::ProductFamily::HI7x_9x;
}

bool HipnucSimulator::supportsMessage(Message m) const
{
    if (m_edition == ManualEdition::V171)
        return std::find(std::begin(kMessages171), std::end(kMessages171), m) != std::end(kMessages171);
    return std::find(std::begin(kMessages166), std::end(kMessages166), m) != std::end(kMessages166);
}

bool HipnucSimulator::supportsBaud(int baud) const
{
    return protocol::hipnuc::commands::isSupportedBaud(baud, m_edition);
}

HipnucSimulator::Config HipnucSimulator::factoryConfig() const
{
    Config c;
    c.baud = 115200;
    for (auto &m : c.messages)
        m = MessageSetting{};
    c.message(Message::HI91) = onTime(10);
    c.hi83Map = Hi83::kDefaultMap;
    c.attMode = hasMagnetometer() ? 1 : 0;
    c.urfrCode = model::Mounting::kDefaultCode;
    c.urfrMatrix = model::Mounting::identity();
    c.coord = 0;
    c.pmux = {1, 2, 5, 0, 0};
    c.pmux2Div = 1;
    c.backgroundMagCal = true;
    c.relativeLevel = {1, 0, 0, 0};
    return c;
}

std::string HipnucSimulator::productName() const
{
    const std::string &m = m_options.model;
    const size_t r = m.find_last_of('R');
    if (r != std::string::npos && r >= 4 && r + 1 < m.size()
        && std::all_of(m.begin() + long(r) + 1, m.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return m;
    return m + "R3";
}

uint32_t HipnucSimulator::systemTimeMs() const
{
    if (m_utcSyncedAtUs >= 0) // aligned by PPS: the ms of the UTC day (v1.7.1 manual 2.2.2)
        return uint32_t((kUtcBaseUnixS * 1000 + m_nowUs / 1000) % 86400000);
    return uint32_t((m_nowUs - m_startUs) / 1000);
}

// ---------------------------------------------------------------------------------------
// Time

void HipnucSimulator::startApp(int64_t t)
{
    if (!m_bootloader.applicationValid()) {
        m_baud = m_saved.baud;
        enterBootloader(t);
        return;
    }
    if (const auto v = m_bootloader.applicationVersion()) {
        if (const auto fw = model::FirmwareVersion::parse(*v)) {
            m_firmware = *fw;
            m_edition = m_firmware >= model::FirmwareVersion{1, 7, 1} ? ManualEdition::V171 : ManualEdition::V166;
        }
    }
    m_state = State::App;
    m_startUs = t;
    m_running = m_saved;
    m_active = m_saved;
    m_baud = m_saved.baud;
    m_logEnabled = true;
    m_yawOffsetDeg = 0;
    m_mcalStat = 0;
    m_mcalProgress = 0;
    m_mcalCoverage.reset();
    m_bgCoverage.reset();
    m_usrcalActive = false;
    m_utcSyncedAtUs = -1;
    m_line.clear();
    m_lineOverflow = false;
    m_sampleUs = -1;
    for (size_t i = 0; i < kMessageCount; ++i)
        scheduleMessage(i, t);
    if (m_active.attMode != 1) {
        // 6-axis modes have no absolute heading: it starts at zero.
        m_yawOffsetDeg = -eulerEnu312(attitudeAt(t, false)).yaw;
    }
    qCDebug(lcSim) << "started" << productName().c_str() << m_firmware.toString().c_str() << "at" << t << "us, baud"
                   << m_baud;
}

void HipnucSimulator::beginReset(State after, int64_t delayUs)
{
    m_state = State::Rebooting;
    m_afterReset = after;
    m_resetDoneUs = m_nowUs + delayUs;
    m_usrcalActive = false;
    m_line.clear();
}

void HipnucSimulator::enterBootloader(int64_t t)
{
    m_state = State::Bootloader;
    m_bootloader.start(m_baud, t);
    qCDebug(lcSim) << "bootloader at" << t << "us, baud" << m_baud;
}

void HipnucSimulator::runBootloader(int64_t t)
{
    const auto request = m_bootloader.runUntil(t);
    for (auto &packet : m_bootloader.takeOutput())
        enqueue(std::move(packet), false);
    switch (request) {
    case KbootBootloader::Request::None: break;
    case KbootBootloader::Request::Reset:
        m_baud = m_saved.baud;
        beginReset(State::App, kRebootUs);
        break;
    case KbootBootloader::Request::PowerLoss:
        dropUnsent(t);
        m_baud = m_saved.baud;
        beginReset(State::App, kPowerOffUs);
        break;
    }
}

void HipnucSimulator::powerCycle()
{
    dropUnsent(m_nowUs);
    startApp(m_nowUs);
}

void HipnucSimulator::scheduleMessage(size_t i, int64_t t)
{
    const MessageSetting &s = m_running.messages[i];
    if (s.mode != MessageSetting::Mode::OnTime || s.periodMs <= 0) {
        m_nextDueUs[i] = kNever;
        return;
    }
    // Due on the grid of the period, counted from the start (a 1 kHz base tick).
    const int64_t p = int64_t(s.periodMs) * 1000;
    const int64_t k = (t - m_startUs) / p + 1;
    m_nextDueUs[i] = m_startUs + k * p;
}

int64_t HipnucSimulator::nextEventUs() const
{
    int64_t n = m_nextTickUs;
    if (m_state == State::Rebooting)
        n = std::min(n, m_resetDoneUs);
    if (m_state == State::Bootloader)
        n = std::min(n, m_bootloader.nextEventUs());
    if (m_state == State::App)
        for (size_t i = 0; i < kMessageCount; ++i)
            if (m_running.messages[i].mode == MessageSetting::Mode::OnTime)
                n = std::min(n, m_nextDueUs[i]);
    return n;
}

void HipnucSimulator::advanceTo(int64_t nowUs)
{
    if (nowUs > m_nowUs) {
        for (;;) {
            const int64_t next = nextEventUs();
            if (next > nowUs)
                break;
            m_nowUs = std::max(m_nowUs, next);
            runEventsAt(m_nowUs);
        }
        m_nowUs = nowUs;
    }
    drainTo(m_nowUs);
}

void HipnucSimulator::runEventsAt(int64_t t)
{
    if (m_state == State::Rebooting && t >= m_resetDoneUs) {
        dropUnsent(t);
        if (m_afterReset == State::App)
            startApp(t);
        else
            enterBootloader(t);
    }
    if (m_state == State::Bootloader)
        runBootloader(t);
    while (t >= m_nextTickUs) {
        tick(m_nextTickUs);
        m_nextTickUs += kTickUs;
    }
    if (m_state != State::App)
        return;
    for (size_t i = 0; i < kMessageCount; ++i) {
        const MessageSetting &s = m_running.messages[i];
        if (s.mode != MessageSetting::Mode::OnTime)
            continue;
        while (m_nextDueUs[i] <= t) {
            if (m_logEnabled)
                emitMessage(Message(i), t);
            m_nextDueUs[i] += int64_t(s.periodMs) * 1000;
        }
    }
}

void HipnucSimulator::integrateGyroCal(int64_t t)
{
    if (!m_usrcalActive || t <= m_usrcalLastUs)
        return;
    const double rate = moduleStateAt(t).rateDps.z();
    m_usrcalAngle += 0.5 * (m_usrcalLastRate + rate) * double(t - m_usrcalLastUs) * 1e-6;
    m_usrcalLastUs = t;
    m_usrcalLastRate = rate;
}

void HipnucSimulator::tick(int64_t t)
{
    if (m_state != State::App)
        return;
    integrateGyroCal(t);
    // A PPS rising edge at each whole UTC second (kUtcBase is a whole second).
    if (m_options.ppsInput && t / 1000000 != (t - kTickUs) / 1000000) {
        if (m_utcSyncedAtUs < 0) {
            m_utcSyncedAtUs = t;
            qCDebug(lcSim) << "UTC aligned by PPS at" << t << "us";
        }
        syncInPulse();
    }

    const MotionState ms = moduleStateAt(t);
    const Eigen::Vector3d dir = (ms.q.toRotationMatrix().transpose() * SensorModel::fieldNav()).normalized();
    auto field = [&] { return fittedFieldUt(t, ms); }; // only while a calibration collects
    auto calibrated = [this] {
        m_magCalibrated = true;
        const Eigen::Vector3d h = m_sensor.hardIron();
        for (int i = 0; i < 3; ++i)
            m_magBias[i] = std::round(h[i] * 100.0) / 100.0;
    };

    if (m_mcalStat == 1) {
        m_mcalCoverage.add(dir, field());
        m_mcalProgress = std::max(m_mcalProgress, m_mcalCoverage.progress());
        if (m_mcalProgress >= 100) {
            m_mcalStat = 2;
            m_mcalVerifyUntilUs = t + kMagCalVerifyUs;
        } else if (t - m_mcalStartUs >= kMagCalTimeoutUs) {
            m_mcalStat = 4;
            qCDebug(lcSim) << "MCAL failed at progress" << m_mcalProgress;
        }
    } else if (m_mcalStat == 2 && t >= m_mcalVerifyUntilUs) {
        // The fit does not explain a field that changed while it was collected.
        const double spread = m_mcalCoverage.spreadUt();
        if (spread <= kMagCalMaxSpreadUt) {
            m_mcalStat = 3;
            calibrated();
        } else {
            m_mcalStat = 4;
            qCDebug(lcSim) << "MCAL failed verification: field magnitudes spread" << spread << "uT";
        }
    }

    // v1.6.6: background calibration while in 9-axis mode with IMU_EN_MCAL 1.
    if (m_edition == ManualEdition::V166 && hasMagnetometer() && !m_magCalibrated && m_running.backgroundMagCal
        && m_active.attMode == 1) {
        m_bgCoverage.add(dir, field());
        if (m_bgCoverage.progress() >= 100) {
            if (m_bgCoverage.spreadUt() <= kMagCalMaxSpreadUt) {
                calibrated();
                qCDebug(lcSim) << "background magnetometer calibration done at" << t << "us";
            } else {
                qCDebug(lcSim) << "background magnetometer calibration rejected, spread" << m_bgCoverage.spreadUt()
                               << "uT: collecting again";
                m_bgCoverage.reset();
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// The module's body and what its sensors measure

MotionState HipnucSimulator::moduleStateAt(int64_t t) const
{
    // t is the module's own time; what moves it moves in true time (sim_clock.h).
    MotionState s = m_motion.at(double(m_options.clock.trueUs(t) + m_options.motionEpochUs) * 1e-6);
    if (m_options.faults.magCalFixture && m_mcalStat == 1 && t >= m_mcalStartUs)
        s = m_fixtureMotion.at(double(t - m_mcalStartUs) * 1e-6);
    if (m_mounted) {
        // v_body = R_m v_module: the attitude gains R_m, the rate is seen in the module's axes.
        s.q = canonical(s.q * m_mounting);
        s.rateDps = m_mounting.conjugate() * s.rateDps;
    }
    return s;
}

Eigen::Vector3d HipnucSimulator::magDisturbanceAt(int64_t t) const
{
    const double a = m_options.faults.magDisturbanceUt;
    if (a == 0)
        return Eigen::Vector3d::Zero();
    const double s = double(t) * 1e-6;
    const double azimuth = 2 * std::numbers::pi * s / kMagDisturbanceTurnS;
    const double elevation = 0.5 * std::numbers::pi * std::sin(2 * std::numbers::pi * s / kMagDisturbanceTiltS);
    return a * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                               std::sin(elevation));
}

Eigen::Vector3d HipnucSimulator::disturbanceInSensor(int64_t t, const MotionState &state) const
{
    if (m_options.faults.magDisturbanceUt == 0)
        return Eigen::Vector3d::Zero();
    return m_sensor.softIron() * (state.q.toRotationMatrix().transpose() * magDisturbanceAt(t));
}

double HipnucSimulator::fittedFieldUt(int64_t t, const MotionState &state) const
{
    // The calibration's fit recovers the hard and soft iron (from noise-free readings here),
    // leaving the field at the sensor: the earth's field plus any disturbance.
    const Eigen::Vector3d mag = m_sensor.ideal(state).mag + disturbanceInSensor(t, state);
    return (m_sensor.softIron().inverse() * (mag - m_sensor.hardIron())).norm();
}

// ---------------------------------------------------------------------------------------
// Output data

Eigen::Matrix3d HipnucSimulator::userFromSensor() const
{
    Eigen::Matrix3d r;
    if (m_edition == ManualEdition::V171)
        r = toEigen(model::Mounting::userFromSensor(m_active.urfrCode));
    else
        r = toEigen(m_active.urfrMatrix); // X_U = C X_B, as the manual's named examples mean it (mounting.cpp)
    // A v1.6.6 matrix is only a rotation to 1e-3: keep the output exactly orthonormal.
    return Eigen::Quaterniond(r).normalized().toRotationMatrix();
}

Eigen::Matrix3d HipnucSimulator::levelMatrix() const
{
    return m_level.toRotationMatrix();
}

Eigen::Quaterniond HipnucSimulator::attitudeAt(int64_t t, bool withYawOffset) const
{
    const MotionState ms = moduleStateAt(t);
    const Eigen::Quaterniond qus(userFromSensor());
    // R_nav<-user = R_nav<-sensor * R_user<-sensor^T
    Eigen::Quaterniond q = ms.q * qus.conjugate();
    const auto &r = m_running.relativeLevel;
    const Eigen::Quaterniond rel(r[0], r[1], r[2], r[3]);
    q = q * rel.conjugate() * m_level.conjugate();
    if (m_active.coord == 4)
        q = enuToNwu() * q;
    if (withYawOffset)
        q = qAxis(m_yawOffsetDeg, Eigen::Vector3d::UnitZ()) * q;
    return canonical(q);
}

uint16_t HipnucSimulator::mainStatusAt(int64_t t) const
{
    if (m_firmware < model::FirmwareVersion{1, 7, 0})
        return 0; // reserved before 1.7.0
    uint16_t s = m_utcSyncedAtUs >= 0 && t >= m_utcSyncedAtUs ? 0 : uint16_t(1u << MainStatus::UtcUnsync);
    if (m_active.attMode == 1)
        s |= uint16_t(1u << MainStatus::MagAiding);
    if (m_motion.motion() == Motion::Static && !moduleStateAt(t).moving) // a fixture may turn it
        s |= uint16_t(1u << MainStatus::Static);
    if (t - m_startUs < kWbConvUs)
        s |= uint16_t(1u << MainStatus::WbConv);
    if (m_active.attMode == 1 && (!m_magCalibrated || m_options.faults.magDisturbanceUt != 0))
        s |= uint16_t(1u << MainStatus::MagDist);
    return s;
}

HipnucSimulator::Snapshot HipnucSimulator::snapshotAt(int64_t t)
{
    if (m_sampleUs != t) {
        const MotionState state = moduleStateAt(t);
        m_sample = m_sensor.sample(state);
        m_sample.mag += disturbanceInSensor(t, state);
        m_sampleUs = t;
    }
    Snapshot s;
    s.tUs = t;
    s.systemTimeUs = uint64_t(t - m_startUs);
    s.systemTimeMs = m_utcSyncedAtUs >= 0 && t >= m_utcSyncedAtUs ? uint32_t((kUtcBaseUnixS * 1000 + t / 1000) % 86400000)
                                                                  : uint32_t((t - m_startUs) / 1000);
    const Eigen::Matrix3d m = levelMatrix() * userFromSensor();
    const Eigen::Vector3d mag = m_magCalibrated ? Eigen::Vector3d(m_sample.mag - m_magBias) : m_sample.mag;
    s.acc = m * m_sample.acc;
    s.gyr = m * m_sample.gyr;
    s.mag = m * mag;
    // The attitude the module's filter reports: late by filterLagMs, off by attitudeBiasDeg.
    s.q = attitudeAt(t - int64_t(std::llround(m_options.faults.filterLagMs * 1000)), true);
    s.euler = eulerEnu312(s.q);
    if (const auto &b = m_options.faults.attitudeBiasDeg; b != std::array<double, 3>{0, 0, 0}) {
        s.euler.roll += b[0];
        s.euler.pitch += b[1];
        s.euler.yaw -= b[2]; // heading clockwise, yaw counter-clockwise
        s.q = canonical(sim::quatFromEnu312(s.euler));
        s.euler = eulerEnu312(s.q);
    }
    s.pressurePa = m_sample.pressurePa;
    s.temperatureC = m_sample.temperatureC;
    s.mainStatus = mainStatusAt(t);
    return s;
}

std::string HipnucSimulator::utcFields(int64_t t, int &year, int &month, int &day, int &hour, int &minute, int &ms) const
{
    const int64_t totalMs = kUtcBaseUnixS * 1000 + t / 1000;
    const int64_t days = totalMs / 86400000;
    const int64_t msOfDay = totalMs % 86400000;
    civilFromDays(days, year, month, day);
    hour = int(msOfDay / 3600000);
    minute = int(msOfDay / 60000 % 60);
    ms = int(msOfDay % 60000); // second * 1000 + ms
    char buf[16];
    std::snprintf(buf, sizeof buf, "%02d%02d%02d.%02d", hour, minute, ms / 1000, (ms % 1000) / 10);
    return buf;
}

std::vector<uint8_t> HipnucSimulator::buildMessage(Message m, const Snapshot &s) const
{
    const double radPerDeg = kDeg;
    const double g = model::kGravity;
    int year = 0, month = 0, day = 0, hour = 0, minute = 0, msOfMinute = 0;
    const std::string hhmmss = utcFields(s.tUs, year, month, day, hour, minute, msOfMinute);
    const int8_t temperature = int8_t(std::clamp(std::lround(s.temperatureC), -128L, 127L));
    const int16_t pressure16 = clamp16(s.pressurePa - 100000.0);
    double heading = -s.euler.yaw; // clockwise from north, 0..360
    if (heading < 0)
        heading += 360.0;

    switch (m) {
    case Message::HI91: {
        Hi91 p;
        p.mainStatus = s.mainStatus;
        p.temperature = temperature;
        p.pressure = float(s.pressurePa);
        p.systemTime = s.systemTimeMs;
        for (int i = 0; i < 3; ++i) {
            p.acc[size_t(i)] = float(s.acc[i]);
            p.gyr[size_t(i)] = float(s.gyr[i]);
            p.mag[size_t(i)] = float(s.mag[i]);
        }
        p.roll = float(s.euler.roll);
        p.pitch = float(s.euler.pitch);
        p.yaw = float(s.euler.yaw);
        p.quat = {float(s.q.w()), float(s.q.x()), float(s.q.y()), float(s.q.z())};
        return protocol::hipnuc::buildFrame(protocol::hipnuc::encode(p));
    }
    case Message::HI92: {
        Hi92 p;
        p.status = 0;
        p.temperature = temperature;
        p.pressure = pressure16;
        for (int i = 0; i < 3; ++i) {
            p.gyr[size_t(i)] = clamp16(s.gyr[i] * radPerDeg / 0.001);
            p.acc[size_t(i)] = clamp16(s.acc[i] * g / 0.0048828);
            p.mag[size_t(i)] = clamp16(s.mag[i] / 0.030517);
        }
        p.roll = round32(s.euler.roll * 1000.0);
        p.pitch = round32(s.euler.pitch * 1000.0);
        p.yaw = round32(s.euler.yaw * 1000.0);
        p.quat = {clamp16(s.q.w() * 1e4), clamp16(s.q.x() * 1e4), clamp16(s.q.y() * 1e4), clamp16(s.q.z() * 1e4)};
        return protocol::hipnuc::buildFrame(protocol::hipnuc::encode(p));
    }
    case Message::HI81: {
        Hi81 p;
        p.mainStatus = s.mainStatus;
        p.insStatus = 0;
        for (int i = 0; i < 3; ++i) {
            p.gyr[size_t(i)] = clamp16(s.gyr[i] * radPerDeg / 0.001);
            p.acc[size_t(i)] = clamp16(s.acc[i] * g / 0.0048828);
            p.mag[size_t(i)] = clamp16(s.mag[i] / 0.030517);
        }
        p.pressure = pressure16;
        p.temperature = temperature;
        p.utcYear = uint8_t(year - 2000);
        p.utcMonth = uint8_t(month);
        p.utcDay = uint8_t(day);
        p.utcHour = uint8_t(hour);
        p.utcMinute = uint8_t(minute);
        p.utcMs = uint16_t(msOfMinute);
        p.roll = clamp16(s.euler.roll * 100.0);
        p.pitch = clamp16(s.euler.pitch * 100.0);
        p.yaw = uint16_t(std::lround(heading * 100.0) % 36000);
        p.quat = {clamp16(s.q.w() * 1e4), clamp16(s.q.x() * 1e4), clamp16(s.q.y() * 1e4), clamp16(s.q.z() * 1e4)};
        return protocol::hipnuc::buildFrame(protocol::hipnuc::encode(p));
    }
    case Message::HI83: {
        Hi83 p;
        p.mainStatus = s.mainStatus;
        p.insStatus = 0;
        p.bitmap = m_running.hi83Map;
        for (int i = 0; i < 3; ++i) {
            p.accB[size_t(i)] = float(s.acc[i] * g);
            p.gyrB[size_t(i)] = float(s.gyr[i] * radPerDeg);
            p.magB[size_t(i)] = float(s.mag[i]);
        }
        p.rpy = {float(s.euler.roll), float(s.euler.pitch), float(s.euler.yaw)};
        p.quat = {float(s.q.w()), float(s.q.x()), float(s.q.y()), float(s.q.z())};
        p.systemTimeUs = s.systemTimeUs;
        p.utc = {uint8_t(year - 2000), uint8_t(month), uint8_t(day), uint8_t(hour), uint8_t(minute),
                 uint8_t(msOfMinute & 0xFF), uint8_t(msOfMinute >> 8), 0};
        p.pressure = float(s.pressurePa);
        p.temperature = float(s.temperatureC);
        p.inclination = {float(s.euler.pitch), float(s.euler.roll), 0.0f};
        // The position and fix of the simulated GGA/SXT (a module at rest in Shanghai).
        p.insLonLatMsl = {121.458333, 31.208333, 40.0};
        p.gnssLonLatMsl = p.insLonLatMsl;
        p.gnssQualityNv = {1, 12, 0, 0};
        const Eigen::Vector3d accNav = s.q * (s.acc * g) - Eigen::Vector3d(0, 0, g);
        p.accEnu = {float(accNav.x()), float(accNav.y()), float(accNav.z())};
        p.nodeInfo = {8, 0, 0, 0};
        // Bits 25-29: the filter's measurement updates (gravity and magnetometer at 100 and
        // 50 Hz, GNSS position and velocity at 1 Hz since power-on), its bias estimates
        // (none at rest) and the GNSS accuracy of a single-point fix; no second antenna.
        const uint64_t t = s.systemTimeUs;
        p.eventCounter = {uint32_t(t / 10000), uint32_t(t / 20000), uint32_t(t / 1000000), uint32_t(t / 1000000)};
        p.gnssStd = {1.5f, 0.05f, 0.0f};
        p.insStatus = 0;
        return protocol::hipnuc::buildFrame(protocol::hipnuc::encode(p));
    }
    case Message::GGA: {
        const std::string body = "GPGGA," + hhmmss + ",3112.5000,N,12127.5000,E,1,12,0.8,40.000,M,0.000,M,,";
        const std::string s1 = protocol::nmea::buildSentence(body);
        return {s1.begin(), s1.end()};
    }
    case Message::RMC: {
        char buf[128];
        std::snprintf(buf, sizeof buf, "GPRMC,%s,A,3112.5000,N,12127.5000,E,0.0,%.1f,%02d%02d%02d,0.0,E,A", hhmmss.c_str(),
                      heading, day, month, year % 100);
        const std::string s1 = protocol::nmea::buildSentence(buf);
        return {s1.begin(), s1.end()};
    }
    case Message::SXT: {
        // date-time, lon, lat, alt, heading, pitch, track, speed, roll, solq, solq_heading,
        // nv, nv_heading, gyr x y z (deg/s), vel E N U, ins_stat, ant_stat. Kept below the
        // 120 characters protocol::nmea accepts.
        char buf[160];
        std::snprintf(buf, sizeof buf,
                      "GPSXT,%04d%02d%02d%s,121.458333,31.208333,40.0,%.2f,%.2f,0,0,%.2f,1,0,12,0,%.1f,%.1f,%.1f,0,0,0,0,0",
                      year, month, day, hhmmss.c_str(), heading, s.euler.pitch, s.euler.roll, s.gyr.x(), s.gyr.y(),
                      s.gyr.z());
        const std::string s1 = protocol::nmea::buildSentence(buf);
        return {s1.begin(), s1.end()};
    }
    }
    return {};
}

void HipnucSimulator::emitMessage(Message m, int64_t t)
{
    if (!supportsMessage(m))
        return;
    // A binary frame that cannot fit is dropped before it is built (a saturated link at
    // 1 kHz would otherwise synthesise every frame only to throw it away).
    size_t size = 0;
    switch (m) {
    case Message::HI91: size = Hi91::kSize; break;
    case Message::HI92: size = Hi92::kSize; break;
    case Message::HI81: size = Hi81::kSize; break;
    case Message::HI83: size = Hi83::payloadSize(m_running.hi83Map).value_or(0); break;
    default: break;
    }
    if (size > 0) {
        drainTo(m_nowUs);
        if (m_txQueued + size + protocol::hipnuc::FrameDecoder::kHeaderSize > kTxBufferSize) {
            ++m_dropped;
            return;
        }
    }
    const Snapshot s = snapshotAt(t);
    enqueue(buildMessage(m, s), true);
}

// ---------------------------------------------------------------------------------------
// UART

bool HipnucSimulator::enqueue(std::vector<uint8_t> bytes, bool data)
{
    if (bytes.empty())
        return true;
    drainTo(m_nowUs);
    if (data && m_txQueued + bytes.size() > kTxBufferSize) {
        ++m_dropped;
        return false;
    }
    if (data)
        ++m_framesQueued;
    Chunk c;
    c.baud = m_baud;
    c.byteUs = 1e7 / double(m_baud); // 10 bits per byte (8N1)
    c.startUs = std::max(double(m_nowUs), m_lineFreeUs);
    c.id = m_nextChunkId++;
    c.data = data;
    m_lineFreeUs = c.startUs + double(bytes.size()) * c.byteUs;
    m_txQueued += bytes.size();
    c.bytes = std::move(bytes);
    m_tx.push_back(std::move(c));
    return true;
}

void HipnucSimulator::enqueueText(const std::string &text)
{
    enqueue(std::vector<uint8_t>(text.begin(), text.end()), false);
}

void HipnucSimulator::drainTo(int64_t t)
{
    while (!m_tx.empty()) {
        Chunk &c = m_tx.front();
        const size_t n = c.bytes.size();
        const double elapsed = double(t) - c.startUs;
        size_t k = 0;
        if (elapsed > 0)
            k = std::min(n, size_t(std::floor(elapsed / c.byteUs + 1e-9)));
        if (k > c.sent) {
            const bool start = c.sent == 0;
            if (!start && !m_out.empty() && m_out.back().chunk == c.id) {
                m_out.back().bytes.insert(m_out.back().bytes.end(), c.bytes.begin() + long(c.sent), c.bytes.begin() + long(k));
                m_out.back().chunkEnd = k == n;
            } else {
                OutputSegment seg;
                seg.baud = c.baud;
                seg.bytes.assign(c.bytes.begin() + long(c.sent), c.bytes.begin() + long(k));
                seg.chunk = c.id;
                seg.chunkStart = start;
                seg.chunkEnd = k == n;
                seg.data = c.data;
                m_out.push_back(std::move(seg));
            }
            m_txQueued -= k - c.sent;
            c.sent = k;
        }
        if (c.sent < n)
            break; // later chunks start after this one ends
        m_tx.pop_front();
    }
}

void HipnucSimulator::dropUnsent(int64_t t)
{
    drainTo(t);
    m_tx.clear();
    m_txQueued = 0;
    m_lineFreeUs = double(t);
}

std::vector<HipnucSimulator::OutputSegment> HipnucSimulator::takeOutputSegments()
{
    drainTo(m_nowUs);
    std::vector<OutputSegment> out;
    out.swap(m_out);
    return out;
}

std::vector<uint8_t> HipnucSimulator::takeOutput()
{
    std::vector<uint8_t> out;
    for (auto &seg : takeOutputSegments())
        out.insert(out.end(), seg.bytes.begin(), seg.bytes.end());
    return out;
}

} // namespace imudesk::sim
