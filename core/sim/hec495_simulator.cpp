#include "hec495_simulator.h"

#include "protocol/nmea/nmea_parser.h"
#include "protocol/witlink/all_data_record.h"
#include "protocol/witlink/bcd.h"
#include "protocol/witlink/reply.h"

#include <Eigen/Geometry>

#include <QLoggingCategory>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>

namespace imudesk::sim {

namespace {

Q_LOGGING_CATEGORY(lcHec, "imudesk.core.sim.hec495", QtInfoMsg)

namespace wl = protocol::witlink;

double wrap360(double deg)
{
    double d = std::fmod(deg, 360.0);
    if (d < 0)
        d += 360.0;
    if (d >= 359.995) // what the 0.01 deg BCD would round to 360.00
        d = 0;
    return d;
}

double wrap180(double deg)
{
    const double d = wrap360(deg);
    return d > 180.0 ? d - 360.0 : d;
}

} // namespace

Hec495Simulator::Hec495Simulator(Hec495Options options)
    : m_options(options),
      m_motion(MotionModel::Options{options.seed, options.motion}),
      m_sensor(options.seed)
{
    m_saved.baud = options.baud;
    m_saved.address = options.address;
    m_saved.rateHz = options.rateHz;
    m_saved.content = options.content;
    m_running = m_saved;
    if (options.calibrated) {
        m_calibrated = true;
        m_hardIron = m_sensor.hardIron();
    }
    scheduleOutput(0);
}

void Hec495Simulator::powerCycle()
{
    m_running = m_saved;
    m_powerOnUs = m_nowUs;
    m_calibration.stop();
    m_decoder.reset();
    m_out.clear(); // what was still in the UART is lost
    m_lineFreeUs = double(m_nowUs);
    scheduleOutput(m_nowUs);
    qCDebug(lcHec) << "power cycle at" << m_nowUs << "us";
}

void Hec495Simulator::scheduleOutput(int64_t fromUs)
{
    m_nextOutputUs = m_running.rateHz > 0 ? std::max(fromUs, m_powerOnUs + kQuietAfterPowerOnUs) : -1;
}

MotionState Hec495Simulator::motionAt(int64_t tUs) const
{
    if (m_pose) {
        MotionState s;
        s.q = sim::quatFromEnu312(EulerAngles{m_pose->roll, m_pose->pitch, -m_pose->heading});
        return s;
    }
    return m_motion.at(double(tUs) / 1e6);
}

double Hec495Simulator::trueHeadingAt(int64_t tUs) const
{
    return wrap360(-eulerEnu312(motionAt(tUs).q).yaw);
}

Hec495Calibration::Pose Hec495Simulator::poseAt(int64_t tUs) const
{
    const EulerAngles e = eulerEnu312(motionAt(tUs).q);
    return {wrap360(-e.yaw), e.pitch, e.roll};
}

Hec495Simulator::Reading Hec495Simulator::readingAt(int64_t tUs)
{
    const MotionState s = motionAt(tUs);
    if (m_sampleUs != tUs) {
        m_sample = m_sensor.sample(s);
        m_sampleUs = tUs;
    }
    const EulerAngles e = eulerEnu312(s.q);
    Reading r;
    r.pitch = e.pitch;
    r.roll = e.roll;
    r.acc = m_sample.acc;
    r.gyr = m_sample.gyr;
    r.rawMag = m_sample.mag;
    r.mag = m_calibrated ? Eigen::Vector3d(m_sample.mag - m_hardIron) : m_sample.mag;
    // Tilt compensation: R = Rz(yaw) Rx(pitch) Ry(roll), so Rx Ry m is the field turned by yaw only.
    const Eigen::Matrix3d tilt = (Eigen::AngleAxisd(e.pitch * std::numbers::pi / 180.0, Eigen::Vector3d::UnitX())
                                  * Eigen::AngleAxisd(e.roll * std::numbers::pi / 180.0, Eigen::Vector3d::UnitY()))
                                     .toRotationMatrix();
    const Eigen::Vector3d h = tilt * r.mag;
    r.heading = wrap360(std::atan2(-h.x(), h.y()) * 180.0 / std::numbers::pi + m_running.declination + m_options.headingBiasDeg);
    r.magRoll = std::atan2(r.mag.x(), -r.mag.z()) * 180.0 / std::numbers::pi;
    r.timeMs = uint32_t((tUs - m_powerOnUs) / 1000);
    return r;
}

void Hec495Simulator::receive(const uint8_t *data, size_t n)
{
    if (m_options.echo && n > 0) { // the adapter's echo, ahead of anything the module sends later
        SerialSegment echo;
        echo.baud = m_running.baud;
        echo.bytes.assign(data, data + n);
        echo.chunk = m_nextChunk++;
        echo.chunkStart = echo.chunkEnd = true;
        const auto at = std::upper_bound(m_out.begin(), m_out.end(), m_nowUs,
                                         [](int64_t t, const Timed &x) { return t < x.releaseUs; });
        m_out.insert(at, Timed{m_nowUs, std::move(echo)});
    }
    if (m_options.rs485 && m_lineFreeUs > double(m_nowUs)) {
        ++m_commandsLost; // half duplex: the module is talking and does not hear this
        return;
    }
    // A sender does not pause inside a frame: after a pause an unfinished candidate (noise
    // with a 0x77 in it) is dropped, so it cannot swallow the next command.
    std::vector<wl::Frame> frames;
    if (m_decoder.pendingBytes() > 0 && m_nowUs - m_lastRxUs > kRxIdleUs)
        m_decoder.flushIdle(frames);
    m_lastRxUs = m_nowUs;
    m_decoder.feed(data, n, frames);
    m_decoder.takeSkipped();
    for (const auto &f : frames)
        handle(f);
}

void Hec495Simulator::advanceTo(int64_t nowUs)
{
    for (;;) {
        int64_t next = m_nextTickUs;
        if (m_nextOutputUs >= 0)
            next = std::min(next, m_nextOutputUs);
        if (next > nowUs)
            break;
        m_nowUs = std::max(m_nowUs, next);
        if (next == m_nextOutputUs) {
            emitOutput(next);
            const int64_t period = 1000000 / std::max(1, m_running.rateHz);
            m_nextOutputUs += period;
        } else {
            calibrationTick(next);
            m_nextTickUs += kTickUs;
        }
    }
    m_nowUs = std::max(m_nowUs, nowUs);
}

std::vector<SerialSegment> Hec495Simulator::takeOutputSegments()
{
    std::vector<SerialSegment> out;
    size_t n = 0;
    while (n < m_out.size() && m_out[n].releaseUs <= m_nowUs)
        out.push_back(std::move(m_out[n++].segment));
    m_out.erase(m_out.begin(), m_out.begin() + std::ptrdiff_t(n));
    return out;
}

std::vector<uint8_t> Hec495Simulator::takeOutput()
{
    std::vector<uint8_t> bytes;
    for (auto &s : takeOutputSegments())
        bytes.insert(bytes.end(), s.bytes.begin(), s.bytes.end());
    return bytes;
}

void Hec495Simulator::send(std::vector<uint8_t> bytes, bool data)
{
    if (bytes.empty())
        return;
    const double now = double(m_nowUs);
    const double start = std::max(now, m_lineFreeUs);
    if (data && start - now > double(kMaxBacklogUs)) {
        ++m_dropped; // more than the baud rate can carry
        return;
    }
    m_lineFreeUs = start + double(bytes.size()) * 10e6 / double(m_running.baud);
    if (data)
        ++m_framesQueued;
    SerialSegment s;
    s.baud = m_running.baud;
    s.bytes = std::move(bytes);
    s.chunk = m_nextChunk++;
    s.chunkStart = s.chunkEnd = true;
    s.data = data;
    m_out.push_back(Timed{int64_t(std::ceil(m_lineFreeUs)), std::move(s)});
}

void Hec495Simulator::reply(const wl::Frame &f)
{
    send(wl::encodeFrame(f), false);
}

std::vector<uint8_t> Hec495Simulator::recordFrame(const Reading &r, bool raw) const
{
    wl::AllDataRecord rec;
    rec.pitch = float(r.pitch);
    rec.roll = float(r.roll);
    rec.heading = float(wrap180(r.heading));
    const Eigen::Vector3d m = (raw ? r.rawMag : r.mag) / kFieldUnitUt;
    for (int i = 0; i < 3; ++i) {
        rec.acc[size_t(i)] = float(r.acc[i]);
        rec.mag[size_t(i)] = float(m[i]);
        rec.gyr[size_t(i)] = float(r.gyr[i]);
    }
    rec.magRoll = float(r.magRoll);
    rec.timeMs = r.timeMs;
    return wl::encodeFrame(m_running.address, uint8_t(wl::Command::ReadAll), rec.encode());
}

void Hec495Simulator::emitOutput(int64_t t)
{
    const Reading r = readingAt(t);
    switch (m_running.content) {
    case wl::OutputContent::Default:
        send(wl::encodeFrame(wl::anglesReply(m_running.address, r.pitch, r.roll, r.heading)), true);
        break;
    case wl::OutputContent::Internal:
        send(recordFrame(r, true), true);
        break;
    case wl::OutputContent::AllData:
        send(recordFrame(r, false), true);
        break;
    case wl::OutputContent::Nmea0183: {
        char body[32];
        std::snprintf(body, sizeof body, "HCHDT,%.1f,T", r.heading);
        const std::string s = protocol::nmea::buildSentence(body);
        send(std::vector<uint8_t>(s.begin(), s.end()), true);
        break;
    }
    }
}

void Hec495Simulator::sendPoint(const Eigen::Vector3d &rawMag)
{
    std::array<uint8_t, 15> bytes{};
    for (int i = 0; i < 3; ++i) {
        const float v = float(rawMag[i] / kFieldUnitUt);
        std::memcpy(bytes.data() + 4 * i, &v, 4);
    }
    reply(wl::calibrationPointReply(m_running.address, bytes, uint8_t(m_calibration.points())));
}

void Hec495Simulator::calibrationTick(int64_t t)
{
    if (!m_calibration.active() || m_calibration.method() == wl::CalibrationMethod::Manual)
        return;
    const Reading r = readingAt(t);
    if (m_calibration.offer(poseAt(t), r.rawMag))
        sendPoint(r.rawMag);
}

void Hec495Simulator::handle(const wl::Frame &f)
{
    using C = wl::Command;
    const bool queryAddress = f.command == uint8_t(C::QueryAddress) && f.address == 0x00;
    if (f.address != m_running.address && !queryAddress)
        return; // another module on the bus
    if (!wl::commands::isKnownCommand(f.command))
        return; // silence, as for any command it does not know
    const uint8_t a = m_running.address;
    const auto &d = f.data;
    auto status = [&](uint8_t cmd, bool ok) { reply(wl::statusReply(a, cmd, ok)); };
    const C cmd = C(f.command);
    switch (cmd) {
    case C::ReadPitch:
    case C::ReadRoll:
    case C::ReadHeading: {
        const Reading r = readingAt(m_nowUs);
        const double v = cmd == C::ReadPitch ? r.pitch : (cmd == C::ReadRoll ? r.roll : r.heading);
        reply(wl::angleReply(a, uint8_t(f.command | 0x80), v));
        return;
    }
    case C::ReadAngles: {
        const Reading r = readingAt(m_nowUs);
        reply(wl::anglesReply(a, r.pitch, r.roll, r.heading));
        return;
    }
    case C::ReadAll:
        send(recordFrame(readingAt(m_nowUs), false), false);
        return;
    case C::SetDeclination: {
        const auto v = d.size() == 2 ? wl::decodeDeclination(d.data()) : std::nullopt;
        if (v)
            m_running.declination = *v;
        status(0x86, v.has_value());
        return;
    }
    case C::ReadDeclination: {
        const auto e = wl::encodeDeclination(m_running.declination).value_or(std::array<uint8_t, 2>{});
        reply(wl::Frame{a, 0x87, {e[0], e[1]}});
        return;
    }
    case C::CalibrateAuto12:
    case C::CalibrateManual:
    case C::CalibrateAllOrientation:
    case C::CalibrateSmallTilt12:
    case C::CalibratePlanar:
        m_calibration.start(wl::CalibrationMethod(f.command));
        status(wl::kReplyCalibrationStarted, true);
        return;
    case C::CollectPoint: {
        const Reading r = readingAt(m_nowUs);
        if (m_calibration.collect(r.rawMag))
            sendPoint(r.rawMag);
        return; // no run, or full: nothing to answer with (the reply has no status)
    }
    case C::StopCalibration: {
        const bool was = m_calibration.active();
        m_calibration.stop();
        status(wl::kReplyStopCalibration, was);
        return;
    }
    case C::SaveCalibration: {
        const auto result = m_calibration.finish();
        if (!result) {
            status(0x89, false);
            return;
        }
        m_calibrated = true;
        m_hardIron = result->hardIron;
        m_lastFitError = result->fitError;
        reply(wl::calibrationSavedReply(a, result->fitError, uint8_t(std::min(result->points, 255))));
        return;
    }
    case C::ClearCalibration:
        m_calibrated = false;
        m_hardIron.setZero();
        m_calibration.stop();
        status(0x90, true);
        return;
    case C::SetBaud: {
        const int b = d.size() == 1 ? wl::commands::baudFromCode(d[0]) : -1;
        status(0x8B, b > 0); // at the old rate
        if (b > 0)
            m_running.baud = b;
        return;
    }
    case C::SetOutputRate: {
        const int hz = d.size() == 1 ? wl::commands::rateFromCode(d[0]) : -1;
        if (hz >= 0) {
            m_running.rateHz = hz;
            scheduleOutput(m_nowUs + (hz > 0 ? 1000000 / hz : 0));
        }
        status(0x8C, hz >= 0);
        return;
    }
    case C::SetOutputContent: {
        const bool ok = d.size() == 1 && d[0] <= uint8_t(wl::OutputContent::Nmea0183);
        if (ok)
            m_running.content = wl::OutputContent(d[0]);
        status(0x49, ok);
        return;
    }
    case C::SetAddress:
        if (d.size() != 1) {
            reply(wl::statusReply(wl::kReplySetAddressAddress, 0x8F, false));
            return;
        }
        m_running.address = d[0];
        reply(wl::statusReply(wl::kReplySetAddressAddress, 0x8F, true));
        return;
    case C::QueryAddress:
        reply(wl::Frame{a, 0x1F, {a}});
        return;
    case C::SaveSettings:
        m_saved = m_running;
        status(0x8A, true);
        return;
    case C::FactoryReset: {
        status(0x8E, true);
        m_running = m_saved = factorySettings();
        scheduleOutput(m_nowUs);
        return;
    }
    }
}

} // namespace imudesk::sim
