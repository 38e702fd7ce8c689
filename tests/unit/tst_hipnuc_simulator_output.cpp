// HipnucSimulator in process, what it sends: output rates and triggers (ONTIME, ONMARK, sync
// in, PPS), the HI83 map, frame contents decoded with the core codecs, NMEA sentences,
// MAIN_STATUS and what each model sends.
#include "../common/hipnuc_sim_rig.h"
#include "../common/test_main.h"

using namespace imudesk;
using namespace imudesk::sim;
using namespace imudesk::protocol::hipnuc;
using namespace imudesk::test::hipnuc_sim;
using model::MainStatus;

class TestHipnucSimulatorOutput : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void onTimeRates_data();
    void onTimeRates();
    void onMarkOnce();
    void onMarkSyncIn();
    void hi83MapChangesLength_data();
    void hi83MapChangesLength();
    void ppsAlignsTheClockToUtc();
    void hi91Contents();
    void hi81Contents();
    void hi92Contents();
    void nmeaSentences();
    void mainStatus_data();
    void mainStatus();
    void modelGates();
};

// ---------------------------------------------------------------------------------------

void TestHipnucSimulatorOutput::onTimeRates_data()
{
    QTest::addColumn<QString>("firmware");
    QTest::addColumn<int>("baud");
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("message");
    QTest::addColumn<int>("perSecond");
    QTest::newRow("HI91 100 Hz") << "1.7.1" << 115200 << "LOG HI91 ONTIME 0.01" << "HI91" << 100;
    QTest::newRow("HI91 50 Hz") << "1.7.1" << 115200 << "LOG HI91 ONTIME 0.02" << "HI91" << 50;
    QTest::newRow("HI91 1 Hz") << "1.7.1" << 115200 << "LOG HI91 ONTIME 1" << "HI91" << 1;
    QTest::newRow("HI91 500 Hz") << "1.7.1" << 921600 << "LOG HI91 ONTIME 0.002" << "HI91" << 500;
    QTest::newRow("HI91 1 kHz") << "1.7.1" << 921600 << "LOG HI91 ONTIME 0.001" << "HI91" << 1000;
    QTest::newRow("HI81 100 Hz") << "1.7.1" << 115200 << "LOG HI81 ONTIME 0.01" << "HI81" << 100;
    QTest::newRow("HI83 50 Hz") << "1.7.1" << 115200 << "LOG HI83 ONTIME 0.02" << "HI83" << 50;
    QTest::newRow("GGA 10 Hz") << "1.7.1" << 115200 << "LOG GGA ONTIME 0.1" << "GGA" << 10;
    QTest::newRow("RMC 5 Hz") << "1.7.1" << 115200 << "LOG RMC ONTIME 0.2" << "RMC" << 5;
    QTest::newRow("SXT 1 Hz") << "1.7.1" << 115200 << "LOG SXT ONTIME 1" << "SXT" << 1;
    QTest::newRow("HI91 100 Hz 1.6.6") << "1.6.6" << 115200 << "LOG HI91 ONTIME 0.01" << "HI91" << 100;
    QTest::newRow("HI92 20 Hz 1.6.6") << "1.6.6" << 115200 << "LOG HI92 ONTIME 0.05" << "HI92" << 20;
    QTest::newRow("HI92 200 Hz 1.6.6") << "1.6.6" << 115200 << "LOG HI92 ONTIME 0.005" << "HI92" << 200;
}

void TestHipnucSimulatorOutput::onTimeRates()
{
    QFETCH(QString, firmware);
    QFETCH(int, baud);
    QFETCH(QString, command);
    QFETCH(QString, message);
    QFETCH(int, perSecond);
    Rig rig(opts(firmware.toStdString(), "HI14", Motion::Static, baud));
    if (message != "HI91")
        QVERIFY(rig.ok("LOG HI91 ONTIME 0"));
    QVERIFY(rig.ok(command.toStdString()));
    rig.run(300000);
    const Capture c = rig.run(1000000);
    int n = 0;
    Message m{};
    QVERIFY(parseMessage(message.toStdString(), m));
    const uint8_t tags[] = {TagHi91, TagHi92, TagHi81, TagHi83};
    if (size_t(m) < 4)
        n = c.countTag(tags[size_t(m)]);
    else
        n = c.countSentences(message.toStdString());
    QVERIFY2(std::abs(n - perSecond) <= 1, qPrintable(QString::number(n)));
    QCOMPARE(c.frames.size() + c.sentences.size(), size_t(n)); // nothing else is sent
    QCOMPARE(rig.sim.droppedFrames(), uint64_t(0));
    QCOMPARE(c.nmeaErrors, 0);
    // Frames are on the period grid.
    if (message == "HI91") {
        const auto f = c.packets<Hi91>();
        const uint32_t period = uint32_t(1000 / perSecond);
        for (size_t i = 1; i < f.size(); ++i)
            QCOMPARE(f[i].systemTime - f[i - 1].systemTime, period);
    }
}

void TestHipnucSimulatorOutput::onMarkOnce()
{
    Rig rig;
    QVERIFY(rig.ok("LOG HI91 ONTIME 0"));
    QVERIFY(rig.run(500000).frames.empty());
    rig.sim.receive("LOG HI91 ONMARK ONCE\r\n");
    const uint32_t at = rig.sim.systemTimeMs();
    const Capture c = rig.run(50000);
    QCOMPARE(c.lines, std::vector<std::string>{"OK"});
    QCOMPARE(c.countTag(TagHi91), 1);
    QCOMPARE(c.packets<Hi91>().front().systemTime, at);
    QCOMPARE(rig.sim.runningConfig().message(Message::HI91).mode, HipnucSimulator::MessageSetting::Mode::Off);
    QVERIFY(rig.run(1000000).frames.empty());
    // Other messages too.
    QCOMPARE(rig.send("LOG HI83 ONMARK ONCE").countTag(TagHi83), 1);
    QCOMPARE(rig.send("LOG HI81 ONMARK ONCE").countTag(TagHi81), 1);
    QCOMPARE(rig.send("LOG GGA ONMARK ONCE").countSentences("GGA"), 1);
    QCOMPARE(rig.send("LOG SXT ONMARK ONCE").countSentences("SXT"), 1);
    Rig legacy(opts("1.6.6"));
    QCOMPARE(legacy.send("LOG HI92 ONMARK ONCE").countTag(TagHi92), 1);
}

void TestHipnucSimulatorOutput::onMarkSyncIn()
{
    Rig rig;
    QVERIFY(rig.ok("LOG HI91 ONMARK 1"));
    QCOMPARE(rig.sim.runningConfig().message(Message::HI91).mode, HipnucSimulator::MessageSetting::Mode::OnMark);
    QVERIFY(rig.run(500000).frames.empty()); // no periodic output any more
    std::vector<uint32_t> pulses;
    Capture all;
    for (int i = 0; i < 5; ++i) {
        rig.run(100000 + 7000 * i);
        pulses.push_back(rig.sim.systemTimeMs());
        rig.sim.syncInPulse();
        const Capture c = rig.run(10000);
        all.frames.insert(all.frames.end(), c.frames.begin(), c.frames.end());
    }
    const auto f = all.packets<Hi91>();
    QCOMPARE(f.size(), size_t(5));
    for (size_t i = 0; i < 5; ++i)
        QCOMPARE(f[i].systemTime, pulses[i]);
    // Two messages on the same pulse.
    QVERIFY(rig.ok("LOG HI83 ONMARK 1"));
    rig.sim.syncInPulse();
    const Capture both = rig.run(20000);
    QCOMPARE(both.countTag(TagHi91), 1);
    QCOMPARE(both.countTag(TagHi83), 1);
    // Output disabled: pulses produce nothing.
    QVERIFY(rig.ok("LOG DISABLE"));
    rig.sim.syncInPulse();
    QVERIFY(rig.run(20000).frames.empty());
}

void TestHipnucSimulatorOutput::hi83MapChangesLength_data()
{
    QTest::addColumn<uint>("map");
    QTest::addColumn<int>("payload");
    QTest::newRow("default 0xFF") << 0x000000FFu << 92;
    QTest::newRow("imu+attitude 0x1F") << 0x0000001Fu << 72;
    QTest::newRow("acc only") << 0x00000001u << 20;
    QTest::newRow("time only") << 0x00000020u << 16;
    QTest::newRow("the SDK's bits 0xC00FFFFF") << 0xC00FFFFFu << 236;
    QTest::newRow("everything the manual sizes") << 0xFE0FFFFFu << 348;
}

void TestHipnucSimulatorOutput::hi83MapChangesLength()
{
    QFETCH(uint, map);
    QFETCH(int, payload);
    QCOMPARE(Hi83::payloadSize(map).value_or(0), size_t(payload));
    Rig rig;
    QVERIFY(rig.ok("LOG HI91 ONTIME 0"));
    char cmd[64];
    std::snprintf(cmd, sizeof cmd, "LOG HI83 MAP 0x%08X", map);
    QVERIFY(rig.ok(cmd));
    QCOMPARE(rig.sim.runningConfig().hi83Map, uint32_t(map));
    QVERIFY(rig.ok("LOG HI83 ONTIME 0.05"));
    rig.run(100000);
    const Capture c = rig.run(500000);
    QCOMPARE(c.frames.size(), size_t(10));
    for (const auto &f : c.frames)
        QCOMPARE(int(f.size()), payload);
    const auto packets = c.packets<Hi83>();
    QCOMPARE(packets.size(), size_t(10));
    const Hi83 &p = packets.back();
    QCOMPARE(p.bitmap, uint32_t(map));
    QCOMPARE(p.insStatus, uint8_t(0));
    const auto has = [&](int b) { return (map >> b) & 1u; };
    if (has(0))
        QVERIFY(std::fabs(vec(p.accB).norm() - 9.8) < 0.05); // m/s^2 = G * 9.8
    if (has(1))
        QVERIFY(vec(p.gyrB).norm() < 0.01); // rad/s: only bias and noise on a static module
    if (has(2))
        QVERIFY(vec(p.magB).norm() > 20.0);
    if (has(3) && has(4)) {
        const EulerAngles e = eulerEnu312(Eigen::Quaterniond(p.quat[0], p.quat[1], p.quat[2], p.quat[3]).normalized());
        QVERIFY(std::fabs(e.roll - p.rpy[0]) < 1e-3);
        QVERIFY(std::fabs(e.pitch - p.rpy[1]) < 1e-3);
        QVERIFY(std::fabs(angleDiff(e.yaw, p.rpy[2])) < 1e-3);
    }
    if (has(5)) {
        QCOMPARE(p.systemTimeUs % 1000, uint64_t(0));
        QCOMPARE(p.systemTimeUs, uint64_t(packets.front().systemTimeUs + 9 * 50000));
        QVERIFY(!p.legacyTime32);
    }
    if (has(6)) {
        QCOMPARE(int(p.utc[0]), 24);
        QCOMPARE(int(p.utc[1]), 11);
        QCOMPARE(int(p.utc[2]), 14);
        QCOMPARE(int(p.utc[3]), 8);
    }
    if (has(7))
        QVERIFY(std::fabs(p.pressure - 100000.0f) < 50.0f);
    if (has(8))
        QVERIFY(std::fabs(p.temperature - 30.0f) < 1.0f);
    if (has(15)) { // the fix of the simulated GGA
        QCOMPARE(int(p.gnssQualityNv[0]), 1);
        QCOMPARE(int(p.gnssQualityNv[1]), 12);
    }
    if (has(25)) { // gravity updates at 100 Hz since power-on, GNSS position at 1 Hz
        QCOMPARE(p.eventCounter[0], uint32_t(p.systemTimeUs / 10000));
        QVERIFY(p.eventCounter[0] > p.eventCounter[2]);
    }
    if (has(28))
        QCOMPARE(p.gnssStd[0], 1.5f);
    if (has(30)) {
        QCOMPARE(p.gnssLonLatMsl[0], 121.458333);
        QCOMPARE(p.gnssLonLatMsl[1], 31.208333);
    }
    // Refused maps (bits 20-24 are reserved, without a size) leave the configuration alone.
    QVERIFY(!rig.ok("LOG HI83 MAP 0x00100000"));
    QCOMPARE(rig.sim.runningConfig().hi83Map, uint32_t(map));
}

void TestHipnucSimulatorOutput::ppsAlignsTheClockToUtc()
{
    // v1.7.1 manual 2.2.2: a PPS edge with its time message aligns the clock to the UTC
    // second; afterwards UTC_UNSYNC (5.9.13 bit 11) is clear and the HI91 system_time is the
    // ms of the UTC day. 2.2.1: the same pin's edge triggers the ONMARK 1 messages.
    constexpr uint16_t kUnsync = 1u << 11;
    SimOptions o;
    o.ppsInput = true;
    Rig rig(o);
    QVERIFY(rig.ok("LOG HI91 ONTIME 0.1"));
    const auto before = rig.run(500000).packets<Hi91>();
    QVERIFY(!before.empty());
    QVERIFY(!rig.sim.utcSynced());
    QVERIFY(before.back().mainStatus & kUnsync);
    QVERIFY(before.back().systemTime < 1000); // ms since power-on
    const auto after = rig.run(1000000).packets<Hi91>();
    QVERIFY(rig.sim.utcSynced());
    const Hi91 &last = after.back();
    QCOMPARE(last.mainStatus & kUnsync, 0);
    const uint32_t utcMs = uint32_t((HipnucSimulator::kUtcBaseUnixS * 1000 + rig.sim.nowUs() / 1000) % 86400000);
    QVERIFY2(last.systemTime <= utcMs && last.systemTime + 200 >= utcMs,
             qPrintable(QStringLiteral("%1 vs %2").arg(last.systemTime).arg(utcMs)));
    // ONMARK 1 now fires once per PPS edge.
    QVERIFY(rig.ok("LOG HI91 ONTIME 0"));
    QVERIFY(rig.ok("LOG HI83 ONMARK 1"));
    rig.run(1000); // what was queued
    QCOMPARE(rig.run(3000000).countTag(TagHi83), 3);

    // Without a PPS input the clock stays the time since power-on.
    Rig plain;
    QVERIFY(plain.ok("LOG HI91 ONTIME 0.1"));
    const auto free = plain.run(2500000).packets<Hi91>();
    QVERIFY(free.back().mainStatus & kUnsync);
    QVERIFY(free.back().systemTime < 3000);
    QVERIFY(!plain.sim.utcSynced());
}

void TestHipnucSimulatorOutput::hi91Contents()
{
    Rig rig;
    const auto f = rig.run(508000).packets<Hi91>(); // the frame due at 500 ms takes 7.1 ms
    QCOMPARE(f.size(), size_t(50));
    const Hi91 &h = f.back();
    QCOMPARE(h.systemTime, uint32_t(500));
    QCOMPARE(int(h.temperature), 30);
    QVERIFY(std::fabs(h.pressure - 100000.0f) < 50.0f);
    QVERIFY(std::fabs(h.roll - MotionModel::kStaticRollDeg) < 1e-3);
    QVERIFY(std::fabs(h.pitch - MotionModel::kStaticPitchDeg) < 1e-3);
    QVERIFY(std::fabs(h.yaw - MotionModel::kStaticYawDeg) < 1e-3);
    QVERIFY(h.quat[0] >= 0);
    const SensorReading truth = rig.sim.sensorModel().ideal(rig.sim.motionModel().at(0.5));
    QVERIFY((vec(h.acc) - truth.acc).norm() < 0.005);
    QVERIFY((vec(h.gyr) - truth.gyr).norm() < 0.15);
    QVERIFY((vec(h.mag) - truth.mag).norm() < 1.0); // not calibrated yet: hard iron included
    // toSample (core) agrees.
    const model::Sample s = toSample(h);
    QVERIFY(std::fabs(s.acc.z - h.acc[2]) < 1e-6);
}

void TestHipnucSimulatorOutput::hi81Contents()
{
    Rig rig(opts("1.7.1", "HI14", Motion::Static, 921600)); // HI91 + HI81 at 100 Hz exceed 115200
    QVERIFY(rig.ok("LOG HI81 ONTIME 0.01"));
    rig.run(100000);
    const Capture c = rig.run(200000);
    const auto f81 = c.packets<Hi81>();
    const auto f91 = c.packets<Hi91>();
    QVERIFY(f81.size() >= 19 && !f91.empty());
    const Hi81 &p = f81.back();
    const Hi91 &h = f91.back();
    QCOMPARE(p.mainStatus, h.mainStatus);
    QCOMPARE(p.insStatus, uint8_t(0));
    QCOMPARE(p.lat, 0);
    QCOMPARE(p.lon, 0);
    QCOMPARE(p.velEnu, (std::array<int16_t, 3>{0, 0, 0}));
    QVERIFY(std::abs(p.roll - int(std::lround(h.roll * 100))) <= 1);
    QVERIFY(std::abs(p.pitch - int(std::lround(h.pitch * 100))) <= 1);
    // Heading: clockwise from north = 360 - yaw.
    QVERIFY(std::abs(int(p.yaw) - int(std::lround((360.0 - MotionModel::kStaticYawDeg) * 100))) <= 1);
    const model::Sample s = toSample(protocol::hipnuc::Packet(p));
    QVERIFY(std::fabs(angleDiff(s.yaw, h.yaw)) < 0.02);
    QVERIFY(std::fabs(std::sqrt(s.acc.x * s.acc.x + s.acc.y * s.acc.y + s.acc.z * s.acc.z) - 1.0) < 0.01);
    QVERIFY(std::fabs(s.pressurePa - 100000.0) < 50.0);
    QCOMPARE(int(p.utcYear), 24);
    QCOMPARE(int(p.utcMonth), 11);
    QCOMPARE(int(p.utcDay), 14);
    QCOMPARE(int(p.utcHour), 8);
}

void TestHipnucSimulatorOutput::hi92Contents()
{
    Rig rig(opts("1.6.6", "HI14", Motion::Spin, 921600)); // HI91 + HI92 at 100 Hz exceed 115200
    QVERIFY(rig.ok("LOG HI92 ONTIME 0.01"));
    rig.run(100000);
    const Capture c = rig.run(300000);
    const auto f92 = c.packets<Hi92>();
    const auto f91 = c.packets<Hi91>();
    QVERIFY(f92.size() >= 29 && f91.size() >= 29);
    const Hi92 &p = f92.back();
    const Hi91 &h = f91.back(); // same instant: both are due on the 10 ms grid
    QCOMPARE(p.status, uint16_t(0));
    QCOMPARE(h.mainStatus, uint16_t(0)); // reserved before 1.7.0
    QVERIFY(std::abs(p.yaw - int(std::lround(h.yaw * 1000))) <= 1);
    QVERIFY(std::abs(p.roll - int(std::lround(h.roll * 1000))) <= 1);
    QVERIFY(std::abs(p.quat[3] - int(std::lround(h.quat[3] * 1e4))) <= 1);
    const model::Sample s = toSample(protocol::hipnuc::Packet(p));
    QVERIFY(std::fabs(s.acc.z - h.acc[2]) < 0.002);
    QVERIFY(std::fabs(s.gyr.z - h.gyr[2]) < 0.06); // 0.001 rad/s steps
    QVERIFY(std::fabs(s.gyr.z - 30.0) < 0.5);
    QVERIFY(std::fabs(s.mag.y - h.mag[1]) < 0.05);
    QVERIFY(std::abs(p.pressure) < 50);
}

void TestHipnucSimulatorOutput::nmeaSentences()
{
    Rig rig;
    QVERIFY(rig.ok("LOG HI91 ONTIME 0"));
    QVERIFY(rig.ok("LOG GGA ONTIME 1"));
    QVERIFY(rig.ok("LOG RMC ONTIME 1"));
    QVERIFY(rig.ok("LOG SXT ONTIME 1"));
    rig.run(800000); // now at about 1.2 s
    const Capture c = rig.run(1000000);
    QCOMPARE(c.nmeaErrors, 0);
    QCOMPARE(c.countSentences("GGA"), 1);
    QCOMPARE(c.countSentences("RMC"), 1);
    QCOMPARE(c.countSentences("SXT"), 1);
    for (const auto &s : c.sentences) {
        if (s.type == "GGA") {
            QVERIFY(s.gga);
            QVERIFY(std::fabs(*s.gga->latitudeDeg - 31.2083333) < 1e-6);
            QVERIFY(std::fabs(*s.gga->longitudeDeg - 121.4583333) < 1e-6);
            QCOMPARE(s.gga->time->hour, 8);
            QCOMPARE(s.gga->time->minute, 0);
            QCOMPARE(s.gga->time->second, 2.0); // due at 2 s of simulation time
        } else if (s.type == "RMC") {
            QVERIFY(s.rmc && s.rmc->valid);
            QCOMPARE(s.rmc->date->year, 2024);
            QCOMPARE(s.rmc->date->month, 11);
            QCOMPARE(s.rmc->date->day, 14);
            QVERIFY(std::fabs(*s.rmc->courseDeg - (360.0 - MotionModel::kStaticYawDeg)) < 0.06);
        } else {
            QCOMPARE(s.talker, std::string("GP"));
            QCOMPARE(s.fields.size(), size_t(21));
            QCOMPARE(s.fields[0], std::string("20241114080002.00"));
            QCOMPARE(std::stod(s.fields[1]), 121.458333);
            QVERIFY(std::fabs(std::stod(s.fields[5]) - MotionModel::kStaticPitchDeg) < 0.01);
        }
    }
}

void TestHipnucSimulatorOutput::mainStatus_data()
{
    QTest::addColumn<QString>("firmware");
    QTest::addColumn<QString>("model");
    QTest::addColumn<Motion>("motion");
    QTest::addColumn<int>("early");
    QTest::addColumn<int>("later");
    const int utc = bit(MainStatus::UtcUnsync), mag = bit(MainStatus::MagAiding), st = bit(MainStatus::Static),
              wb = bit(MainStatus::WbConv), dist = bit(MainStatus::MagDist);
    QTest::newRow("HI14 static") << "1.7.1" << "HI14" << Motion::Static << (utc | mag | st | wb | dist)
                                 << (utc | mag | st | dist);
    QTest::newRow("HI14 spin") << "1.7.1" << "HI14" << Motion::Spin << (utc | mag | wb | dist) << (utc | mag | dist);
    QTest::newRow("HI02 static") << "1.7.1" << "HI02" << Motion::Static << (utc | st | wb) << (utc | st);
    QTest::newRow("HI14 1.7.0") << "1.7.0" << "HI14" << Motion::Static << (utc | mag | st | wb | dist)
                                << (utc | mag | st | dist);
    QTest::newRow("HI14 1.6.6") << "1.6.6" << "HI14" << Motion::Static << 0 << 0;
}

void TestHipnucSimulatorOutput::mainStatus()
{
    QFETCH(QString, firmware);
    QFETCH(QString, model);
    QFETCH(Motion, motion);
    QFETCH(int, early);
    QFETCH(int, later);
    Rig rig(opts(firmware.toStdString(), model.toStdString(), motion));
    const auto a = rig.run(1000000).packets<Hi91>();
    QCOMPARE(int(a.back().mainStatus), early);
    rig.run(2500000);
    const auto b = rig.run(500000).packets<Hi91>();
    QCOMPARE(int(b.front().mainStatus), later);
    // WB_CONV returns after a restart.
    rig.sim.powerCycle();
    const auto c = rig.run(500000).packets<Hi91>();
    QCOMPARE(int(c.back().mainStatus), early);
}

void TestHipnucSimulatorOutput::modelGates()
{
    Rig hi02(opts("1.7.1", "HI02"));
    QCOMPARE(hi02.sim.runningConfig().attMode, 0);
    QVERIFY(!hi02.sim.hasMagnetometer());
    QVERIFY(!hi02.sim.hasPmux());
    QCOMPARE(QString::fromStdString(outcome(hi02.command("CONFIG ATT MODE 1"))), QStringLiteral("ERR"));
    QCOMPARE(hi02.sim.runningConfig().attMode, 0);
    const AsciiReply cc = hi02.command("LOG COMCONFIG");
    QVERIFY(cc.values.count("PMUX1") == 0);
    Rig hi50(opts("1.7.1", "HI50"));
    QVERIFY(!hi50.ok("CONFIG ATT MODE 1"));
    QVERIFY(hi50.ok("CONFIG ATT RST 5"));
    Rig hi92(opts("1.7.1", "HI92"));
    QVERIFY(hi92.sim.hasMagnetometer());
    QVERIFY(!hi92.sim.hasPmux());
    QCOMPARE(hi92.sim.family(), model::ProductFamily::HI7x_9x);
}

IMUDESK_TEST_GUILESS_MAIN(TestHipnucSimulatorOutput)
#include "tst_hipnuc_simulator_output.moc"
