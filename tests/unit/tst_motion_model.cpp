// MotionModel, SensorModel and the attitude conventions of the simulator: Euler
// angles (manual appendix 1, ENU-312), sensor consistency, spin integration, mounting
// (URFR code and v1.6.6 matrix), the NWU world frame and seed reproducibility.
#include "model/mounting.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"
#include "sim/hipnuc_simulator.h"
#include "sim/motion_model.h"
#include "sim/sensor_model.h"
#include "../common/test_main.h"

#include <QTest>

#include <cmath>

using namespace imudesk;
using namespace imudesk::sim;
using protocol::hipnuc::Hi91;

Q_DECLARE_METATYPE(imudesk::sim::Motion)

namespace {

double angleDiff(double a, double b)
{
    double d = std::fmod(a - b, 360.0);
    if (d > 180.0) d -= 360.0;
    if (d < -180.0) d += 360.0;
    return d;
}

double quatDistance(const Eigen::Quaterniond &a, const Eigen::Quaterniond &b)
{
    return std::min((a.coeffs() - b.coeffs()).norm(), (a.coeffs() + b.coeffs()).norm());
}

// Runs a simulator for a while and returns its HI91 frames.
std::vector<Hi91> hi91Frames(HipnucSimulator &sim, int64_t fromUs, int64_t toUs)
{
    sim.advanceTo(fromUs);
    sim.takeOutput();
    sim.advanceTo(toUs);
    const auto bytes = sim.takeOutput();
    protocol::hipnuc::FrameDecoder dec;
    std::vector<Hi91> out;
    for (const auto &payload : dec.feed(bytes.data(), bytes.size())) {
        Hi91 h;
        if (protocol::hipnuc::decodeHi91(payload.data(), payload.size(), h))
            out.push_back(h);
    }
    return out;
}

void command(HipnucSimulator &sim, const std::string &text, int64_t waitUs = 50000)
{
    sim.receive(text + "\r\n");
    sim.advanceTo(sim.nowUs() + waitUs);
    sim.takeOutput();
}

// Saves, reboots (a new mounting takes effect there) and returns the next 300 ms of HI91.
std::vector<Hi91> framesAfterReboot(HipnucSimulator &sim)
{
    command(sim, "SAVECONFIG");
    command(sim, "REBOOT", 400000);
    return hi91Frames(sim, sim.nowUs(), sim.nowUs() + 300000);
}

Eigen::Quaterniond quatOf(const Hi91 &h)
{
    return Eigen::Quaterniond(h.quat[0], h.quat[1], h.quat[2], h.quat[3]);
}

Eigen::Vector3d vec(const std::array<float, 3> &a)
{
    return {a[0], a[1], a[2]};
}

} // namespace

class TestMotionModel : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void eulerGoldenVectors_data();
    void eulerGoldenVectors();
    void eulerRoundTrip_data();
    void eulerRoundTrip();
    void staticAttitude();
    void accelerationIsGravity_data();
    void accelerationIsGravity();
    void sensorsAgreeWithAttitude_data();
    void sensorsAgreeWithAttitude();
    void rateMatchesQuaternionDerivative_data();
    void rateMatchesQuaternionDerivative();
    void spinGyroIntegratesToAngle_data();
    void spinGyroIntegratesToAngle();
    void tumbleRatesAndCoverage();
    void biasAndIronFromSeed();
    void sameSeedSameOutput();
    void outputEulerMatchesQuaternion_data();
    void outputEulerMatchesQuaternion();
    void mountingCode240();
    void mountingLegacyMatrixMatchesCode();
    void mountingLegacyYDownAsNamed();
    void worldFrameNwu();
};

void TestMotionModel::eulerGoldenVectors_data()
{
    QTest::addColumn<double>("w");
    QTest::addColumn<double>("x");
    QTest::addColumn<double>("y");
    QTest::addColumn<double>("z");
    QTest::addColumn<double>("roll");
    QTest::addColumn<double>("pitch");
    QTest::addColumn<double>("yaw");
    QTest::addColumn<double>("tol");
    // The HI91 example frame of both manuals (section 5.11 / 3.5).
    QTest::newRow("manual HI91 example") << -0.485922 << -0.14982 << 0.0380868 << 0.860223 << 13.0519 << 12.1885
                                         << -122.477 << 0.01;
    // 3-1-2 vectors (yaw about Z, pitch about X, roll about Y).
    QTest::newRow("312 (30,20,10)") << 0.943714 << 0.144878 << 0.127679 << 0.268536 << 10.0 << 20.0 << 30.0 << 1e-3;
    QTest::newRow("312 (-135,-45,60)") << 0.129410 << 0.299950 << 0.482963 << -0.812422 << 60.0 << -45.0 << -135.0
                                       << 1e-3;
    QTest::newRow("312 (45,60,22.5)") << 0.747400 << 0.388408 << 0.343758 << 0.415166 << 22.5 << 60.0 << 45.0 << 1e-3;
    QTest::newRow("identity") << 1.0 << 0.0 << 0.0 << 0.0 << 0.0 << 0.0 << 0.0 << 1e-9;
    QTest::newRow("yaw 90 ccw") << std::sqrt(0.5) << 0.0 << 0.0 << std::sqrt(0.5) << 0.0 << 0.0 << 90.0 << 1e-9;
}

void TestMotionModel::eulerGoldenVectors()
{
    QFETCH(double, w);
    QFETCH(double, x);
    QFETCH(double, y);
    QFETCH(double, z);
    QFETCH(double, roll);
    QFETCH(double, pitch);
    QFETCH(double, yaw);
    QFETCH(double, tol);
    const Eigen::Quaterniond q = Eigen::Quaterniond(w, x, y, z).normalized();
    const EulerAngles e = eulerEnu312(q);
    QVERIFY2(std::fabs(e.roll - roll) < tol, qPrintable(QString::number(e.roll)));
    QVERIFY2(std::fabs(e.pitch - pitch) < tol, qPrintable(QString::number(e.pitch)));
    QVERIFY2(std::fabs(angleDiff(e.yaw, yaw)) < tol, qPrintable(QString::number(e.yaw)));
    // And back: the same rotation.
    QVERIFY(quatDistance(quatFromEnu312({roll, pitch, yaw}), q) < 2e-5);
}

void TestMotionModel::eulerRoundTrip_data()
{
    QTest::addColumn<double>("roll");
    QTest::addColumn<double>("pitch");
    QTest::addColumn<double>("yaw");
    QTest::newRow("small") << 1.5 << -2.5 << 35.0;
    QTest::newRow("upside down") << 179.0 << 3.0 << -100.0;
    QTest::newRow("steep") << -120.0 << 85.0 << 170.0;
    QTest::newRow("negative yaw") << 45.0 << -60.0 << -179.0;
}

void TestMotionModel::eulerRoundTrip()
{
    QFETCH(double, roll);
    QFETCH(double, pitch);
    QFETCH(double, yaw);
    const Eigen::Quaterniond q = quatFromEnu312({roll, pitch, yaw});
    QVERIFY(q.w() >= 0);
    // R = Rz(yaw) Rx(pitch) Ry(roll), built independently of the quaternion product.
    const Eigen::Matrix3d r = (Eigen::AngleAxisd(yaw * M_PI / 180, Eigen::Vector3d::UnitZ())
                               * Eigen::AngleAxisd(pitch * M_PI / 180, Eigen::Vector3d::UnitX())
                               * Eigen::AngleAxisd(roll * M_PI / 180, Eigen::Vector3d::UnitY()))
                                  .toRotationMatrix();
    QVERIFY((q.toRotationMatrix() - r).norm() < 1e-12);
    const EulerAngles e = eulerEnu312(q);
    QVERIFY(std::fabs(e.roll - roll) < 1e-9);
    QVERIFY(std::fabs(e.pitch - pitch) < 1e-9);
    QVERIFY(std::fabs(e.yaw - yaw) < 1e-9);
}

void TestMotionModel::staticAttitude()
{
    MotionModel m({7, Motion::Static});
    const MotionState a = m.at(0), b = m.at(123.4);
    QVERIFY(quatDistance(a.q, b.q) < 1e-15);
    QCOMPARE(a.rateDps.norm(), 0.0);
    QVERIFY(!a.moving);
    const EulerAngles e = eulerEnu312(a.q);
    QVERIFY(std::fabs(e.roll - MotionModel::kStaticRollDeg) < 1e-9);
    QVERIFY(std::fabs(e.pitch - MotionModel::kStaticPitchDeg) < 1e-9);
    QVERIFY(std::fabs(e.yaw - MotionModel::kStaticYawDeg) < 1e-9);
    // Slightly tilted, not level.
    QVERIFY(std::fabs(e.roll) > 0.5 && std::fabs(e.pitch) > 0.5);
}

void TestMotionModel::accelerationIsGravity_data()
{
    QTest::addColumn<Motion>("motion");
    QTest::addColumn<double>("t");
    for (double t : {0.0, 1.7, 33.3}) {
        QTest::addRow("static %g", t) << Motion::Static << t;
        QTest::addRow("spin %g", t) << Motion::Spin << t;
        QTest::addRow("tumble %g", t) << Motion::Tumble << t;
    }
}

void TestMotionModel::accelerationIsGravity()
{
    QFETCH(Motion, motion);
    QFETCH(double, t);
    MotionModel m({3, motion});
    SensorModel s(3);
    const MotionState st = m.at(t);
    QVERIFY(std::fabs(s.ideal(st).acc.norm() - 1.0) < 1e-12);
    double sum = 0;
    const int n = 200;
    for (int i = 0; i < n; ++i)
        sum += s.sample(st).acc.norm();
    QVERIFY2(std::fabs(sum / n - 1.0) < 0.001, qPrintable(QString::number(sum / n, 'f', 6)));
    // Spin is level: gravity on body Z only.
    if (motion == Motion::Spin)
        QVERIFY((s.ideal(st).acc - Eigen::Vector3d(0, 0, 1)).norm() < 1e-12);
}

void TestMotionModel::sensorsAgreeWithAttitude_data()
{
    accelerationIsGravity_data();
}

void TestMotionModel::sensorsAgreeWithAttitude()
{
    QFETCH(Motion, motion);
    QFETCH(double, t);
    MotionModel m({11, motion});
    SensorModel s(11);
    const MotionState st = m.at(t);
    const SensorReading r = s.ideal(st);
    const Eigen::Matrix3d rot = st.q.toRotationMatrix();
    // acc rotated into ENU is straight up.
    QVERIFY((rot * r.acc - Eigen::Vector3d(0, 0, 1)).norm() < 1e-12);
    // mag without iron effects, rotated into ENU, is the earth field.
    const Eigen::Vector3d clean = s.softIron().inverse() * (r.mag - s.hardIron());
    QVERIFY((rot * clean - SensorModel::fieldNav()).norm() < 1e-9);
    // Hard iron makes the raw field differ from the earth field.
    QVERIFY((rot * r.mag - SensorModel::fieldNav()).norm() > 1.0);
    // gyr = rate + bias.
    QVERIFY((r.gyr - st.rateDps - s.gyroBias()).norm() < 1e-12);
}

void TestMotionModel::rateMatchesQuaternionDerivative_data()
{
    accelerationIsGravity_data();
}

void TestMotionModel::rateMatchesQuaternionDerivative()
{
    QFETCH(Motion, motion);
    QFETCH(double, t);
    MotionModel m({5, motion});
    const double h = 1e-5;
    Eigen::Quaterniond q0 = m.at(t - h).q, q1 = m.at(t + h).q;
    if (q0.coeffs().dot(q1.coeffs()) < 0)
        q1.coeffs() = -q1.coeffs();
    // body rate = 2 * vec(conj(q) * dq/dt)
    const Eigen::Quaterniond mid = m.at(t).q;
    Eigen::Quaterniond dq;
    dq.coeffs() = (q1.coeffs() - q0.coeffs()) / (2 * h);
    if (mid.coeffs().dot(q0.coeffs()) < 0)
        dq.coeffs() = -dq.coeffs();
    const Eigen::Vector3d w = 2.0 * (mid.conjugate() * dq).vec() * 180.0 / M_PI;
    QVERIFY2((w - m.at(t).rateDps).norm() < 1e-4,
             qPrintable(QStringLiteral("%1 %2 %3").arg(w.x()).arg(w.y()).arg(w.z())));
}

void TestMotionModel::spinGyroIntegratesToAngle_data()
{
    QTest::addColumn<double>("seconds");
    QTest::newRow("90 deg") << 3.0;
    QTest::newRow("one turn") << 12.0;
    QTest::newRow("two turns") << 24.0;
}

void TestMotionModel::spinGyroIntegratesToAngle()
{
    QFETCH(double, seconds);
    MotionModel m({9, Motion::Spin});
    SensorModel s(9);
    const double dt = 0.01;
    double angle = 0;
    const int n = int(std::lround(seconds / dt));
    for (int i = 0; i < n; ++i)
        angle += s.sample(m.at((i + 0.5) * dt)).gyr.z() * dt;
    const double expected = MotionModel::kSpinRateDps * seconds;
    // Bias accumulates: remove it, what remains is white noise (0.02 deg/s, sqrt(n) * dt).
    const double unbiased = angle - s.gyroBias().z() * seconds;
    QVERIFY2(std::fabs(unbiased - expected) < 0.05, qPrintable(QString::number(unbiased, 'f', 4)));
    QVERIFY(std::fabs(angle - expected) <= 0.2 * seconds + 0.05);
    // The attitude turned by the same angle about Z (ccw positive yaw).
    const double yaw0 = eulerEnu312(m.at(0).q).yaw, yaw1 = eulerEnu312(m.at(seconds).q).yaw;
    QVERIFY(std::fabs(angleDiff(yaw1 - yaw0, expected)) < 1e-6);
}

void TestMotionModel::tumbleRatesAndCoverage()
{
    MotionModel m({1, Motion::Tumble});
    double maxRate = 0;
    // Octants of the body-frame field direction and of the body Z axis in ENU.
    std::array<bool, 8> fieldOctants{}, zOctants{};
    for (int i = 0; i <= 6000; ++i) {
        const MotionState s = m.at(i * 0.01);
        maxRate = std::max(maxRate, s.rateDps.norm());
        const Eigen::Vector3d d = s.q.toRotationMatrix().transpose() * SensorModel::fieldNav();
        fieldOctants[size_t((d.x() > 0) + 2 * (d.y() > 0) + 4 * (d.z() > 0))] = true;
        const Eigen::Vector3d z = s.q.toRotationMatrix().col(2);
        zOctants[size_t((z.x() > 0) + 2 * (z.y() > 0) + 4 * (z.z() > 0))] = true;
    }
    QVERIFY2(maxRate <= 60.0, qPrintable(QString::number(maxRate)));
    QVERIFY(maxRate > 20.0);
    for (int i = 0; i < 8; ++i) {
        QVERIFY2(fieldOctants[size_t(i)], qPrintable(QStringLiteral("field octant %1 never visited").arg(i)));
        QVERIFY2(zOctants[size_t(i)], qPrintable(QStringLiteral("attitude octant %1 never visited").arg(i)));
    }
}

void TestMotionModel::biasAndIronFromSeed()
{
    for (uint64_t seed : {1ull, 2ull, 99ull, 123456789ull}) {
        SensorModel s(seed);
        for (int i = 0; i < 3; ++i) {
            QVERIFY(std::fabs(s.gyroBias()[i]) >= 0.05 && std::fabs(s.gyroBias()[i]) <= 0.2);
            QVERIFY(std::fabs(s.hardIron()[i]) <= 20.0);
        }
        QVERIFY((s.softIron() - s.softIron().transpose()).norm() < 1e-15);
        QVERIFY((s.softIron() - Eigen::Matrix3d::Identity()).norm() < 0.1);
    }
    QVERIFY((SensorModel(1).hardIron() - SensorModel(2).hardIron()).norm() > 1e-6);
}

void TestMotionModel::sameSeedSameOutput()
{
    // Sensor level.
    MotionModel m({21, Motion::Tumble});
    SensorModel a(21), b(21), c(22);
    bool differs = false;
    for (int i = 0; i < 100; ++i) {
        const MotionState st = m.at(i * 0.01);
        const SensorReading ra = a.sample(st), rb = b.sample(st), rc = c.sample(st);
        QCOMPARE(ra.acc, rb.acc);
        QCOMPARE(ra.gyr, rb.gyr);
        QCOMPARE(ra.mag, rb.mag);
        QCOMPARE(ra.pressurePa, rb.pressurePa);
        differs = differs || ra.gyr != rc.gyr;
    }
    QVERIFY(differs);
    // Device level: identical bytes for the same seed, different for another.
    SimOptions o;
    o.motion = Motion::Tumble;
    o.seed = 77;
    HipnucSimulator s1(o), s2(o);
    o.seed = 78;
    HipnucSimulator s3(o);
    for (auto *s : {&s1, &s2, &s3})
        s->advanceTo(1000000);
    const auto b1 = s1.takeOutput(), b2 = s2.takeOutput(), b3 = s3.takeOutput();
    QVERIFY(b1.size() > 8000);
    QVERIFY(b1 == b2);
    QVERIFY(b1 != b3);
}

void TestMotionModel::outputEulerMatchesQuaternion_data()
{
    QTest::addColumn<Motion>("motion");
    QTest::addColumn<QString>("firmware");
    QTest::newRow("static 1.7.1") << Motion::Static << "1.7.1";
    QTest::newRow("spin 1.7.1") << Motion::Spin << "1.7.1";
    QTest::newRow("tumble 1.7.1") << Motion::Tumble << "1.7.1";
    QTest::newRow("tumble 1.6.6") << Motion::Tumble << "1.6.6";
}

void TestMotionModel::outputEulerMatchesQuaternion()
{
    QFETCH(Motion, motion);
    QFETCH(QString, firmware);
    SimOptions o;
    o.motion = motion;
    o.firmware = firmware.toStdString();
    HipnucSimulator sim(o);
    const auto frames = hi91Frames(sim, 100000, 2100000);
    QVERIFY(frames.size() >= 199);
    for (const Hi91 &h : frames) {
        const Eigen::Quaterniond q = quatOf(h);
        QVERIFY(std::fabs(q.norm() - 1.0) < 1e-6);
        const EulerAngles e = eulerEnu312(q.normalized());
        QVERIFY(std::fabs(e.roll - h.roll) < 1e-3 || std::fabs(std::fabs(e.roll - h.roll) - 360.0) < 1e-3);
        QVERIFY(std::fabs(e.pitch - h.pitch) < 1e-3);
        QVERIFY(std::fabs(angleDiff(e.yaw, h.yaw)) < 1e-3);
        // acc (G) rotated by the output attitude points up; |acc| about 1 G.
        const Eigen::Vector3d up = q.normalized().toRotationMatrix() * vec(h.acc);
        QVERIFY2((up - Eigen::Vector3d(0, 0, 1)).norm() < 0.01, qPrintable(QString::number((up - Eigen::Vector3d(0, 0, 1)).norm())));
        QVERIFY(std::fabs(vec(h.acc).norm() - 1.0) < 0.01);
        // The true rate at the frame time (start = 0) plus bias is what the gyro shows.
        const MotionState st = sim.motionModel().at(h.systemTime * 1e-3);
        QVERIFY((vec(h.gyr) - st.rateDps - sim.sensorModel().gyroBias()).norm() < 0.15);
    }
}

void TestMotionModel::mountingCode240()
{
    // The module lies (almost) flat: sensor Z up. Configured URFR 240 = user X is sensor +Y,
    // user Y is sensor +Z, user Z is sensor +X; the table: "IMU X up, IMU Y right, IMU Z forward".
    HipnucSimulator sim(SimOptions{});
    const auto before = hi91Frames(sim, 100000, 600000);
    QVERIFY(!before.empty());
    command(sim, "CONFIG IMU URFR 240");
    // Not active before a reset.
    const auto pending = hi91Frames(sim, sim.nowUs(), sim.nowUs() + 200000);
    QVERIFY(!pending.empty());
    QVERIFY(pending.back().acc[2] > 0.99f);
    command(sim, "SAVECONFIG");
    command(sim, "REBOOT", 400000);
    QCOMPARE(sim.activeConfig().urfrCode, 240);
    const auto after = hi91Frames(sim, sim.nowUs(), sim.nowUs() + 500000);
    QVERIFY(after.size() >= 45);
    const SensorReading truth = sim.sensorModel().ideal(sim.motionModel().at(0));
    for (const Hi91 &h : after) {
        const Eigen::Vector3d acc = vec(h.acc), gyr = vec(h.gyr);
        QVERIFY(std::fabs(acc.x() - truth.acc.y()) < 0.01);
        QVERIFY(std::fabs(acc.y() - truth.acc.z()) < 0.01);
        QVERIFY(std::fabs(acc.z() - truth.acc.x()) < 0.01);
        QVERIFY(std::fabs(gyr.x() - truth.gyr.y()) < 0.1);
        QVERIFY(std::fabs(gyr.y() - truth.gyr.z()) < 0.1);
        QVERIFY(std::fabs(gyr.z() - truth.gyr.x()) < 0.1);
        // Gravity is now on user Y ("IMU Z points forward" while the module lies flat: nose up).
        QVERIFY(acc.y() > 0.99);
        // Still consistent: the attitude rotates acc up.
        const Eigen::Vector3d up = quatOf(h).normalized().toRotationMatrix() * acc;
        QVERIFY((up - Eigen::Vector3d(0, 0, 1)).norm() < 0.01);
        // The sensor X axis, seen in the user frame, is user Z ("IMU X up").
        const Eigen::Vector3d sensorXInUser = quatOf(h).normalized().toRotationMatrix().transpose()
            * (sim.motionModel().at(0).q.toRotationMatrix() * Eigen::Vector3d::UnitX());
        QVERIFY((sensorXInUser - Eigen::Vector3d(0, 0, 1)).norm() < 1e-4);
    }
}

void TestMotionModel::mountingLegacyMatrixMatchesCode()
{
    // v1.6.6: the same mounting given as its matrix C (the code's user-from-sensor matrix, as the
    // manual's named examples print it: model/mounting.cpp).
    SimOptions o171;
    SimOptions o166;
    o166.firmware = "1.6.6";
    HipnucSimulator a(o171), b(o166);
    command(a, "CONFIG IMU URFR 531");
    const model::Matrix3 c = model::Mounting::legacyMatrixForCode(531);
    std::string text = "CONFIG IMU URFR ";
    for (size_t i = 0; i < 9; ++i)
        text += (i ? "," : "") + std::to_string(int(c[i / 3][i % 3]));
    command(b, text);
    QCOMPARE(b.runningConfig().urfrMatrix, c);
    const auto fa = framesAfterReboot(a);
    const auto fb = framesAfterReboot(b);
    QVERIFY(!fa.empty() && !fb.empty());
    const Hi91 &x = fa.back(), &y = fb.back();
    QVERIFY((vec(x.acc) - vec(y.acc)).norm() < 0.01);
    QVERIFY((vec(x.mag) - vec(y.mag)).norm() < 1.0);
    QVERIFY(quatDistance(quatOf(x), quatOf(y)) < 1e-5);
    // 531: user X = sensor -Z, user Y = sensor -Y, user Z = sensor -X ("IMU X down, Y back, Z left"):
    // with the module flat, gravity is on user -X.
    QVERIFY(x.acc[0] < -0.99f);
}

void TestMotionModel::mountingLegacyYDownAsNamed()
{
    // v1.6.6 2.2.4's example "Y軸正方向朝下的垂直安裝" (1 0 0 / 0 0 1 / 0 -1 0) on a v1.6.6
    // module reads as v1.7.1's 043 "IMU Y 指下" and as the Modbus URFR value 1 "Y軸正方向朝下":
    // one mounting, whichever path set it.
    SimOptions o166;
    o166.firmware = "1.6.6";
    HipnucSimulator a(SimOptions{}), b(o166);
    command(a, "CONFIG IMU URFR 43");
    command(b, "CONFIG IMU URFR 1,0,0,0,0,1,0,-1,0");
    const auto fa = framesAfterReboot(a);
    const auto fb = framesAfterReboot(b);
    QVERIFY(!fa.empty() && !fb.empty());
    QVERIFY((vec(fa.back().acc) - vec(fb.back().acc)).norm() < 0.01);
    // 043: user Y = sensor +Z. The module lying flat, gravity's reaction is on user +Y; the
    // transposed matrix (052, Y up) would put it on user -Y.
    QVERIFY(fb.back().acc[1] > 0.99f);
}

void TestMotionModel::worldFrameNwu()
{
    HipnucSimulator sim(SimOptions{}); // static, 9-axis: absolute heading 35 deg (ENU)
    const auto enu = hi91Frames(sim, 100000, 300000);
    QVERIFY(!enu.empty());
    QVERIFY(std::fabs(enu.back().yaw - MotionModel::kStaticYawDeg) < 1e-3);
    command(sim, "CONFIG IMU COORD 4");
    command(sim, "SAVECONFIG");
    command(sim, "REBOOT", 400000);
    const auto nwu = hi91Frames(sim, sim.nowUs(), sim.nowUs() + 200000);
    QVERIFY(!nwu.empty());
    const Hi91 &h = nwu.back();
    // N = ENU y, W = -ENU x: the yaw reference turns by 90 deg.
    QVERIFY2(std::fabs(angleDiff(h.yaw, MotionModel::kStaticYawDeg - 90.0)) < 1e-3, qPrintable(QString::number(h.yaw)));
    QVERIFY(std::fabs(h.roll - enu.back().roll) < 1e-3);
    QVERIFY(std::fabs(h.pitch - enu.back().pitch) < 1e-3);
    // The calibrated field, rotated by the NWU attitude, is (north 28, west 0, up -42) apart from soft iron.
    const Eigen::Vector3d field = quatOf(h).normalized().toRotationMatrix() * vec(h.mag);
    const Eigen::Vector3d hard = quatOf(h).normalized().toRotationMatrix() * sim.sensorModel().hardIron();
    const Eigen::Vector3d earth = field - hard;
    QVERIFY2((earth - Eigen::Vector3d(28, 0, -42)).norm() < 4.0,
             qPrintable(QStringLiteral("%1 %2 %3").arg(earth.x()).arg(earth.y()).arg(earth.z())));
}

IMUDESK_TEST_GUILESS_MAIN(TestMotionModel)
#include "tst_motion_model.moc"
