// HipnucSimulator in process, its motion and calibrations: attitude resets and the legacy yaw
// command, the six-axis heading, gyro and magnetometer calibration (MCAL, the v1.6.6 background
// calibration) and the per-module faults (SimFaults).
#include "../common/hipnuc_sim_rig.h"
#include "../common/test_main.h"

using namespace imudesk;
using namespace imudesk::sim;
using namespace imudesk::protocol::hipnuc;
using namespace imudesk::test::hipnuc_sim;
using model::MainStatus;

class TestHipnucSimulatorMotion : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void attitudeResets();
    void legacyYawCommand();
    void sixAxisHeadingStartsAtZero();
    void gyroCalibration_data();
    void gyroCalibration();
    void magCalTumbleCompletes();
    void magCalStaticFails();
    void legacyBackgroundMagCal_data();
    void legacyBackgroundMagCal();
    void faultNoisyGyro();
    void faultMounting();
    void faultMagDisturbance_data();
    void faultMagDisturbance();
    void faultFixtureMagCal();
    void faultsText();
};

// ---------------------------------------------------------------------------------------

void TestHipnucSimulatorMotion::attitudeResets()
{
    Rig rig; // static, 9-axis, yaw 35
    auto last = [&rig] { return rig.run(100000).packets<Hi91>().back(); };
    Hi91 h = last();
    QVERIFY(std::fabs(h.yaw - 35.0f) < 1e-3);
    // RST 1: heading to zero.
    QVERIFY(rig.ok("CONFIG ATT RST 1"));
    h = last();
    QVERIFY(std::fabs(h.yaw) < 1e-3);
    QVERIFY(std::fabs(h.roll - 1.5f) < 1e-3);
    // RST 2: relative level; acc keeps its tilt (only the angles are zeroed).
    const Eigen::Vector3d accBefore = vec(h.acc);
    QVERIFY(rig.ok("CONFIG ATT RST 2"));
    h = last();
    QVERIFY(std::fabs(h.roll) < 1e-3 && std::fabs(h.pitch) < 1e-3);
    QVERIFY(std::fabs(h.yaw) < 1e-3);
    QVERIFY((vec(h.acc) - accBefore).norm() < 0.005);
    // RST 5 clears RST 2.
    QVERIFY(rig.ok("CONFIG ATT RST 5"));
    h = last();
    QVERIFY(std::fabs(h.roll - 1.5f) < 1e-3 && std::fabs(h.pitch + 2.5f) < 1e-3);
    // RST 3: auto level, acc levelled too, permanent (RST 5 does not undo it, it survives a reboot).
    QVERIFY(rig.ok("CONFIG ATT RST 3"));
    h = last();
    QVERIFY(std::fabs(h.roll) < 1e-3 && std::fabs(h.pitch) < 1e-3);
    QVERIFY(std::fabs(h.acc[0]) < 0.005f && std::fabs(h.acc[1]) < 0.005f);
    QVERIFY(rig.ok("CONFIG ATT RST 5"));
    QVERIFY(rig.ok("REBOOT", 400000));
    h = last();
    QVERIFY(std::fabs(h.roll) < 1e-3 && std::fabs(h.pitch) < 1e-3);
    QVERIFY(std::fabs(h.yaw - 35.0f) < 0.1f); // RST 1 was a runtime correction
    // RST 2 is saved with SAVECONFIG.
    Rig saved;
    QVERIFY(saved.ok("CONFIG ATT RST 2"));
    QVERIFY(saved.ok("SAVECONFIG"));
    QVERIFY(saved.ok("REBOOT", 400000));
    const Hi91 s = saved.run(100000).packets<Hi91>().back();
    QVERIFY(std::fabs(s.roll) < 1e-3 && std::fabs(s.pitch) < 1e-3);

    // RST 3 refuses a tilted module.
    Rig tilted(opts("1.7.1", "HI14", Motion::Tumble));
    int64_t t = 0;
    for (; t < 20000000; t += 10000) {
        tilted.sim.advanceTo(t);
        const EulerAngles e = eulerEnu312(tilted.sim.currentAttitude());
        if (std::fabs(e.pitch) > 20 && std::fabs(e.roll) > 20 && std::fabs(e.roll) < 160)
            break;
    }
    QVERIFY(t < 20000000);
    tilted.sim.takeOutput();
    QCOMPARE(QString::fromStdString(outcome(tilted.command("CONFIG ATT RST 3", 10000))), QStringLiteral("ERR"));
}

void TestHipnucSimulatorMotion::legacyYawCommand()
{
    Rig rig(opts("1.6.6"));
    auto yaw = [&rig] { return rig.run(100000).packets<Hi91>().back().yaw; };
    QVERIFY(std::fabs(yaw() - 35.0f) < 1e-3);
    QVERIFY(rig.ok("CONFIG YAW 1 16"));
    QVERIFY(std::fabs(yaw() - 16.0f) < 1e-3);
    QVERIFY(rig.ok("CONFIG YAW 0 1.5"));
    QVERIFY(std::fabs(yaw() - 17.5f) < 1e-3);
    QVERIFY(rig.ok("CONFIG YAW 1 -170"));
    QVERIFY(std::fabs(yaw() + 170.0f) < 1e-3);
    QVERIFY(rig.ok("SAVECONFIG"));
    QVERIFY(rig.ok("REBOOT", 400000));
    QVERIFY(std::fabs(yaw() - 35.0f) < 1e-3); // not saved
}

void TestHipnucSimulatorMotion::sixAxisHeadingStartsAtZero()
{
    Rig rig(opts("1.7.1", "HI14", Motion::Spin));
    QVERIFY(rig.ok("CONFIG ATT MODE 0"));
    const Hi91 before = rig.run(100000).packets<Hi91>().back();
    QVERIFY(before.mainStatus & bit(MainStatus::MagAiding)); // not active until a restart
    QVERIFY(rig.ok("SAVECONFIG"));
    rig.sim.receive("REBOOT\r\n");
    rig.run(300000);
    const auto f = rig.run(500000).packets<Hi91>();
    QVERIFY(!f.empty());
    QCOMPARE(f.front().mainStatus & (bit(MainStatus::MagAiding) | bit(MainStatus::MagDist)), 0);
    // Yaw counts from 0 at the restart and turns at 30 deg/s (counter-clockwise positive).
    for (const Hi91 &h : f)
        QVERIFY2(std::fabs(angleDiff(h.yaw, 30.0 * h.systemTime / 1000.0)) < 0.01, qPrintable(QString::number(h.yaw)));
}

void TestHipnucSimulatorMotion::gyroCalibration_data()
{
    QTest::addColumn<Motion>("motion");
    QTest::addColumn<int>("angle");
    QTest::addColumn<double>("seconds");
    QTest::addColumn<bool>("ok");
    QTest::newRow("720 exact") << Motion::Spin << 720 << 24.0 << true;
    QTest::newRow("720 +4.5 deg") << Motion::Spin << 720 << 24.15 << true;
    QTest::newRow("720 -4.5 deg") << Motion::Spin << 720 << 23.85 << true;
    QTest::newRow("720 +30 deg") << Motion::Spin << 720 << 25.0 << false;
    QTest::newRow("720 -30 deg") << Motion::Spin << 720 << 23.0 << false;
    QTest::newRow("1080") << Motion::Spin << 1080 << 36.0 << true;
    QTest::newRow("1800") << Motion::Spin << 1800 << 60.0 << true;
    QTest::newRow("static") << Motion::Static << 720 << 24.0 << false;
}

void TestHipnucSimulatorMotion::gyroCalibration()
{
    QFETCH(Motion, motion);
    QFETCH(int, angle);
    QFETCH(double, seconds);
    QFETCH(bool, ok);
    Rig rig(opts("1.7.1", "HI14", motion));
    rig.run(1234000);
    rig.sim.receive("CONFIG USRCAL START " + std::to_string(angle) + "\r\n");
    QVERIFY(rig.sim.gyroCalActive());
    const Capture start = rig.run(int64_t(std::llround(seconds * 1e6)));
    QVERIFY(!start.lines.empty() && start.lines.front() == "OK");
    QVERIFY(std::fabs(rig.sim.gyroCalAngleDeg() - (motion == Motion::Spin ? 30.0 * seconds : 0.0)) < 0.5);
    const AsciiReply r = rig.command("CONFIG USRCAL STOP", 10000);
    QCOMPARE(QString::fromStdString(outcome(r)), QString(ok ? "OK" : "ERR"));
    QVERIFY(!rig.sim.gyroCalActive());
    QVERIFY(!rig.ok("CONFIG USRCAL STOP")); // nothing running any more
}

void TestHipnucSimulatorMotion::magCalTumbleCompletes()
{
    Rig rig(opts("1.7.1", "HI14", Motion::Tumble));
    rig.run(500000);
    auto stat = [&rig] {
        const AsciiReply r = rig.command("LOG MCAL STAT", 10000);
        return std::make_pair(std::stoi(r.values.at("STAT")), std::stoi(r.values.at("PROGRESS")));
    };
    QCOMPARE(stat(), std::make_pair(0, 0));
    QVERIFY(rig.run(100000).packets<Hi91>().back().mainStatus & bit(MainStatus::MagDist));
    QVERIFY(rig.ok("CONFIG MCAL START", 10000));
    int previous = 0;
    for (int s = 0; s < 4; ++s) {
        rig.run(10000000);
        const auto [st, progress] = stat();
        QCOMPARE(st, 1);
        QVERIFY2(progress > previous && progress < 100, qPrintable(QString::number(progress)));
        previous = progress;
    }
    rig.run(25000000); // 65 s after START
    QCOMPARE(stat(), std::make_pair(3, 100));
    QVERIFY(rig.sim.magCalibrated());
    // MAG_DIST clears; the hard iron is gone from mag.
    const auto f = rig.run(200000).packets<Hi91>();
    QCOMPARE(f.back().mainStatus & bit(MainStatus::MagDist), 0);
    const SensorModel &sm = rig.sim.sensorModel();
    for (const Hi91 &h : f) {
        const double t = (rig.sim.startedAtUs() + int64_t(h.systemTime) * 1000) * 1e-6;
        const Eigen::Vector3d clean = sm.softIron() * (rig.sim.motionModel().at(t).q.toRotationMatrix().transpose()
                                                       * SensorModel::fieldNav());
        QVERIFY((vec(h.mag) - clean).norm() < 1.0);
    }
    // The calibration survives a reboot; STAT is idle again.
    QVERIFY(rig.ok("REBOOT", 400000));
    QCOMPARE(stat(), std::make_pair(0, 0));
    QCOMPARE(rig.run(100000).packets<Hi91>().back().mainStatus & bit(MainStatus::MagDist), 0);
}

void TestHipnucSimulatorMotion::magCalStaticFails()
{
    Rig rig; // static
    QVERIFY(rig.ok("CONFIG MCAL START"));
    rig.run(60000000);
    AsciiReply r = rig.command("LOG MCAL STAT", 10000);
    QCOMPARE(r.values.at("STAT"), std::string("1"));
    QVERIFY(std::stoi(r.values.at("PROGRESS")) < 10);
    rig.run(61000000);
    r = rig.command("LOG MCAL STAT", 10000);
    QCOMPARE(r.values.at("STAT"), std::string("4"));
    QVERIFY(!rig.sim.magCalibrated());
    QVERIFY(rig.run(100000).packets<Hi91>().back().mainStatus & bit(MainStatus::MagDist));
    // A new start resets the progress.
    QVERIFY(rig.ok("CONFIG MCAL START"));
    QCOMPARE(rig.command("LOG MCAL STAT", 10000).values.at("STAT"), std::string("1"));
}

void TestHipnucSimulatorMotion::legacyBackgroundMagCal_data()
{
    QTest::addColumn<Motion>("motion");
    QTest::addColumn<bool>("enabled");
    QTest::addColumn<bool>("calibrates");
    QTest::addColumn<double>("disturbanceUt");
    QTest::newRow("tumble") << Motion::Tumble << true << true << 0.0;
    QTest::newRow("tumble, IMU_EN_MCAL 0") << Motion::Tumble << false << false << 0.0;
    QTest::newRow("static") << Motion::Static << true << false << 0.0;
    QTest::newRow("tumble, magnetic disturbance") << Motion::Tumble << true << false << 40.0;
}

void TestHipnucSimulatorMotion::legacyBackgroundMagCal()
{
    QFETCH(Motion, motion);
    QFETCH(bool, enabled);
    QFETCH(bool, calibrates);
    QFETCH(double, disturbanceUt);
    SimFaults faults;
    faults.magDisturbanceUt = disturbanceUt;
    Rig rig(withFaults(faults, opts("1.6.6", "HI14", motion)));
    if (!enabled)
        QVERIFY(rig.ok("CONFIG IMU_EN_MCAL 0", 1000));
    AsciiReply r = rig.command("LOG MAGCONFIG");
    QVERIFY(r.ok());
    QCOMPARE(r.lines, std::vector<std::string>{"MB=0.00, 0.00, 0.00"});
    rig.run(30000000);
    QCOMPARE(rig.command("LOG MAGCONFIG").lines.front(), std::string("MB=0.00, 0.00, 0.00"));
    rig.run(40000000);
    r = rig.command("LOG MAGCONFIG");
    QVERIFY(r.ok());
    if (!calibrates) {
        QCOMPARE(r.lines.front(), std::string("MB=0.00, 0.00, 0.00"));
        return;
    }
    const Eigen::Vector3d h = rig.sim.sensorModel().hardIron();
    char want[96];
    std::snprintf(want, sizeof want, "MB=%.2f, %.2f, %.2f", h.x(), h.y(), h.z());
    QCOMPARE(r.lines.front(), std::string(want));
    // The mag output is calibrated now.
    const auto f = rig.run(100000).packets<Hi91>();
    const double t = (rig.sim.startedAtUs() + int64_t(f.back().systemTime) * 1000) * 1e-6;
    const Eigen::Vector3d clean = rig.sim.sensorModel().softIron()
        * (rig.sim.motionModel().at(t).q.toRotationMatrix().transpose() * SensorModel::fieldNav());
    QVERIFY((vec(f.back().mag) - clean).norm() < 1.0);
}

void TestHipnucSimulatorMotion::faultNoisyGyro()
{
    SimFaults noisy;
    noisy.gyroNoiseFactor = 20;
    Rig clean, bad(withFaults(noisy));
    const auto a = clean.run(3000000).packets<Hi91>();
    const auto b = bad.run(3000000).packets<Hi91>();
    QVERIFY(a.size() >= 299 && b.size() >= 299); // 3 s at 100 Hz

    const double sa = gyroStd(a), sb = gyroStd(b);
    qInfo("gyro std per axis: %.4f deg/s clean, %.4f deg/s noisy", sa, sb);
    QVERIFY2(std::fabs(sa - SensorModel::kGyrNoiseDps) < 0.004, qPrintable(QString::number(sa)));
    QVERIFY2(std::fabs(sb - 20 * SensorModel::kGyrNoiseDps) < 0.08, qPrintable(QString::number(sb)));
    QVERIFY2(sb / sa > 17 && sb / sa < 23, qPrintable(QString::number(sb / sa)));
    // The same bias: only the noise grew.
    QVERIFY((bad.sim.sensorModel().gyroBias() - clean.sim.sensorModel().gyroBias()).norm() < 1e-12);
}

void TestHipnucSimulatorMotion::faultMounting()
{
    SimFaults side;
    side.mountingErrorDeg = {90, 0, 0};
    Rig clean(opts("1.7.1", "HI14", Motion::Static, 921600)), bad(withFaults(side, clean.sim.options()));
    for (Rig *r : {&clean, &bad})
        QVERIFY(r->ok("LOG HI81 ONTIME 0.01"));
    const Capture ca = clean.run(500000), cb = bad.run(500000);
    const Hi91 a = ca.packets<Hi91>().back(), b = cb.packets<Hi91>().back();
    QVERIFY2(std::fabs(a.roll - MotionModel::kStaticRollDeg) < 1e-3, qPrintable(QString::number(a.roll)));
    QVERIFY2(std::fabs(b.roll - (MotionModel::kStaticRollDeg + 90)) < 1e-3, qPrintable(QString::number(b.roll)));
    QVERIFY(std::fabs(b.pitch - a.pitch) < 1e-3);
    QVERIFY(std::fabs(angleDiff(b.yaw, a.yaw)) < 1e-3);
    QVERIFY(std::abs(cb.packets<Hi81>().back().roll - int(std::lround(b.roll * 100))) <= 1); // every message
    // What it measures is of the turned body: gravity along its x axis now, and the same field
    // magnitude (soft iron aside) in other axes; acc agrees with the reported attitude.
    QVERIFY2(b.acc[0] < -0.99f && std::fabs(a.acc[2] - 1.0f) < 0.01f, qPrintable(QString::number(b.acc[0])));
    const Eigen::Quaterniond q(b.quat[0], b.quat[1], b.quat[2], b.quat[3]);
    QVERIFY((vec(b.acc) - q.conjugate() * Eigen::Vector3d(0, 0, 1)).norm() < 0.005);
    const Eigen::Vector3d bodyMag = bad.sim.sensorModel().softIron().inverse()
        * (vec(b.mag) - bad.sim.sensorModel().hardIron());
    QVERIFY((bodyMag - q.conjugate() * SensorModel::fieldNav()).norm() < 1.0);
}

void TestHipnucSimulatorMotion::faultMagDisturbance_data()
{
    QTest::addColumn<double>("disturbanceUt");
    QTest::addColumn<int>("stat");
    QTest::newRow("clean fixture") << 0.0 << 3;
    QTest::newRow("motor beside the fixture") << SimFaults::kMagDisturbanceUt << 4;
}

void TestHipnucSimulatorMotion::faultMagDisturbance()
{
    QFETCH(double, disturbanceUt);
    QFETCH(int, stat);
    SimFaults faults;
    faults.magCalFixture = true;
    faults.magDisturbanceUt = disturbanceUt;
    Rig rig(withFaults(faults));
    // At rest, the measured field changes when (and only when) it is disturbed.
    const auto before = rig.run(6000000).packets<Hi91>();
    double lo = 1e9, hi = 0;
    for (const Hi91 &h : before) {
        lo = std::min(lo, vec(h.mag).norm());
        hi = std::max(hi, vec(h.mag).norm());
    }
    QVERIFY2(disturbanceUt > 0 ? hi - lo > 20 : hi - lo < 2, qPrintable(QString::number(hi - lo)));
    QVERIFY(before.back().mainStatus & bit(MainStatus::MagDist));
    // The fixture collects every direction either way; the disturbed one fails its check.
    const McalEnd end = runMagCal(rig);
    QCOMPARE(end.stat, stat);
    QCOMPARE(end.progress, 100);
    QCOMPARE(rig.sim.magCalibrated(), stat == 3);
    const uint16_t status = rig.run(100000).packets<Hi91>().back().mainStatus;
    QCOMPARE(bool(status & bit(MainStatus::MagDist)), stat != 3);
}

void TestHipnucSimulatorMotion::faultFixtureMagCal()
{
    SimFaults faults;
    faults.magCalFixture = true;
    Rig rig(withFaults(faults, opts("1.7.1", "HI14", Motion::Spin))); // the fixture holds it still
    const Eigen::Vector3d bias = rig.sim.sensorModel().gyroBias();
    auto atRest = [&](const Hi91 &h) {
        return std::fabs(h.roll - MotionModel::kStaticRollDeg) < 1e-3 && std::fabs(h.pitch - MotionModel::kStaticPitchDeg) < 1e-3
            && std::fabs(angleDiff(h.yaw, MotionModel::kStaticYawDeg)) < 1e-3 && (vec(h.gyr) - bias).norm() < 0.15
            && (h.mainStatus & bit(MainStatus::Static));
    };
    const auto still = rig.run(3500000).packets<Hi91>();
    for (const Hi91 &h : still)
        QVERIFY(atRest(h));
    // START: the fixture turns it.
    QVERIFY(rig.ok("CONFIG MCAL START", 10000));
    const auto turning = rig.run(5000000).packets<Hi91>();
    QVERIFY(!turning.empty());
    int moving = 0;
    for (const Hi91 &h : turning)
        moving += !atRest(h) && (vec(h.gyr) - bias).norm() > 10 && !(h.mainStatus & bit(MainStatus::Static));
    QVERIFY2(moving > int(turning.size()) - 2, qPrintable(QString::number(moving)));
    // Started again (the fixture starts over), it completes on the bench, and the module rests
    // at the static attitude again.
    const McalEnd end = runMagCal(rig);
    QCOMPARE(end.stat, 3);
    QCOMPARE(end.progress, 100);
    qInfo("MCAL on the fixture: %.1f s of simulated time from START to STAT=3", end.seconds);
    QVERIFY(end.seconds > 30 && end.seconds < 70);
    QVERIFY(rig.sim.magCalibrated());
    const auto after = rig.run(1000000).packets<Hi91>();
    QVERIFY(!after.empty());
    for (const Hi91 &h : after) {
        QVERIFY(atRest(h));
        QCOMPARE(h.mainStatus & bit(MainStatus::MagDist), 0);
    }
}

void TestHipnucSimulatorMotion::faultsText()
{
    SimFaults f;
    std::string error;
    QVERIFY(parseSimFaults("", f, &error));
    QVERIFY(f == SimFaults{});
    QCOMPARE(simFaultsText(f), std::string());
    // The short words and their defaults.
    QVERIFY(parseSimFaults(" noisy-gyro, Wrong-Mounting ,mag-disturbance,unplug=2.5,fixture", f, &error));
    QCOMPARE(f.gyroNoiseFactor, 20.0);
    QCOMPARE(f.mountingErrorDeg, (std::array<double, 3>{90, 0, 0}));
    QCOMPARE(f.magDisturbanceUt, 40.0);
    QCOMPARE(f.unplugAtS, 2.5);
    QVERIFY(f.magCalFixture);
    QCOMPARE(simFaultsText(f), std::string("noisy-gyro=20,mounting=90/0/0,mag-disturbance=40,unplug=2.5,fixture"));
    SimFaults back;
    QVERIFY(parseSimFaults(simFaultsText(f), back, &error));
    QVERIFY(back == f);
    // Values, round trip.
    SimFaults g;
    QVERIFY(parseSimFaults("noisy-gyro=3.5,mounting=-10/5.25/180,mag-disturbance=12.5,unplug=0", g, &error));
    QCOMPARE(g.mountingErrorDeg, (std::array<double, 3>{-10, 5.25, 180}));
    QCOMPARE(simFaultsText(g), std::string("noisy-gyro=3.5,mounting=-10/5.25/180,mag-disturbance=12.5,unplug=0"));
    SimFaults g2;
    QVERIFY(parseSimFaults(simFaultsText(g), g2, &error));
    QVERIFY(g2 == g);
    // Refused, with what is accepted; out is left as it was.
    const SimFaults keep = g;
    for (const char *bad : {"wobble", "noisy-gyro,wobble", "mounting=1/2", "mounting=1/2/3/4", "mounting=a/0/0",
                            "mounting", "unplug", "unplug=-1", "noisy-gyro=-2", "noisy-gyro=x", "mag-disturbance=-5",
                            "fixture=1", "wrong-mounting=1", "unplug=inf"}) {
        error.clear();
        QVERIFY2(!parseSimFaults(bad, g, &error), bad);
        QVERIFY2(!error.empty(), bad);
        QVERIFY2(g == keep, bad);
    }
    QVERIFY(!parseSimFaults("noisy-gyro, wobble", g, &error));
    QVERIFY2(error.find("wobble") != std::string::npos && error.find("noisy-gyro") != std::string::npos
                 && error.find("mounting=R/P/Y") != std::string::npos && error.find("unplug=T") != std::string::npos
                 && error.find("fixture") != std::string::npos,
             error.c_str());
}



IMUDESK_TEST_GUILESS_MAIN(TestHipnucSimulatorMotion)
#include "tst_hipnuc_simulator_motion.moc"
