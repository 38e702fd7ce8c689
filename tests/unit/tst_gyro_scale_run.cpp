// The gyro Z scale-factor run (manual v1.7.1 4.6.7.11: 720..1800 deg, 20..100 deg/s,
// stop within +-5 deg) and the stillness detector, on synthetic turntable data with a known
// scale error, bias, tilt and timestamp jitter, and on the simulated module's frames.
#include "calib/gyro_scale_run.h"
#include "calib/stillness_detector.h"
#include "protocol/hipnuc/payloads.h"
#include "protocol/stream/stream_demux.h"
#include "sim/hipnuc_simulator.h"
#include "../common/test_main.h"

#include <Eigen/Geometry>

#include <QTest>

#include <random>

using namespace imudesk;
using calib::GyroScaleRun;
using Eigen::Vector3d;

namespace {

struct Profile {
    double scale = 0.005;     // gyro scale error (fraction)
    double biasDps = 0.3;
    double rateDps = 45;      // even part
    double trueDeg = 720;     // what the turntable really turns per leg
    int legs = 2;
    double tiltDeg = 0;       // sensor tilted about x
    double odrHz = 100;
    double jitterMs = 0;      // timestamp jitter (uniform +-)
    bool pauseMidway = false; // stops for 1 s in the middle of the first leg
};

// Angle (deg) and rate of one leg tau seconds in: 1 s ramps, even in between.
std::pair<double, double> leg(double tau, double w, double total)
{
    const double len = 2 + (total - w) / w;
    if (tau <= 0)
        return {0, 0};
    if (tau < 1)
        return {w * tau * tau / 2, w * tau};
    if (tau < len - 1)
        return {w / 2 + w * (tau - 1), w};
    if (tau < len)
        return {total - w * (len - tau) * (len - tau) / 2, w * (len - tau)};
    return {total, 0};
}

GyroScaleRun::Result run(const Profile &p, GyroScaleRun::Options o = {})
{
    o.legs = p.legs;
    GyroScaleRun r(o);
    r.start();
    std::mt19937_64 g(42);
    std::normal_distribution<double> n(0, 0.02);
    std::uniform_real_distribution<double> j(-p.jitterMs, p.jitterMs);
    const double legLen = 2 + (p.trueDeg - p.rateDps) / p.rateDps + (p.pauseMidway ? 1.0 : 0.0);
    const double start2 = 3 + legLen + 3;
    const double end = start2 + legLen + 3;
    const Eigen::Matrix3d tilt = Eigen::AngleAxisd(p.tiltDeg * M_PI / 180, Vector3d::UnitX()).toRotationMatrix();
    for (int k = 0; k < int(end * p.odrHz); ++k) {
        const double t = k / p.odrHz; // true sample instant; the device stamps it (with jitter in the stamp)
        auto legAt = [&](double tau) {
            if (!p.pauseMidway)
                return leg(tau, p.rateDps, p.trueDeg);
            const double half = (legLen - 1) / 2;
            if (tau < half)
                return leg(tau, p.rateDps, p.trueDeg);
            if (tau < half + 1)
                return std::make_pair(leg(half, p.rateDps, p.trueDeg).first, 0.0);
            return leg(tau - 1, p.rateDps, p.trueDeg);
        };
        double rate = -legAt(t - 3).second;
        if (p.legs > 1)
            rate += legAt(t - start2).second;
        const Vector3d body = tilt.transpose() * Vector3d(0, 0, rate);
        const Vector3d gyr = (1 + p.scale) * body + Vector3d::Constant(p.biasDps) + Vector3d(n(g), n(g), n(g));
        const Vector3d acc = tilt.transpose() * Vector3d(0, 0, 1);
        const double stamp = t * 1000 + (p.jitterMs > 0 && k > 0 ? j(g) : 0.0);
        r.addSample(stamp, gyr, acc);
    }
    return r.result();
}

} // namespace

class TstGyroScaleRun : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void estimates_data()
    {
        QTest::addColumn<double>("scale");
        QTest::addColumn<double>("bias");
        QTest::addColumn<double>("rate");
        QTest::addColumn<double>("trueDeg");
        QTest::addColumn<int>("legs");
        QTest::addColumn<double>("tilt");
        QTest::addColumn<double>("jitter");
        QTest::addColumn<bool>("pause");
        QTest::addColumn<double>("expectedPct");
        QTest::addColumn<double>("tolerancePct");
        QTest::addColumn<bool>("acceptable");
        QTest::newRow("there and back, 0.5 %") << 0.005 << 0.3 << 45.0 << 720.0 << 2 << 0.0 << 0.0 << false << 0.5 << 0.01 << true;
        QTest::newRow("one leg, -0.3 %, no bias") << -0.003 << 0.0 << 45.0 << 720.0 << 1 << 0.0 << 0.0 << false << -0.3 << 0.01 << true;
        QTest::newRow("5 turns at 90 deg/s") << 0.002 << 0.3 << 90.0 << 1800.0 << 2 << 0.0 << 0.0 << false << 0.2 << 0.01 << true;
        QTest::newRow("timestamp jitter 2 ms") << 0.005 << 0.3 << 45.0 << 720.0 << 2 << 0.0 << 2.0 << false << 0.5 << 0.02 << true;
        QTest::newRow("tilted 2 deg: projected on gravity") << 0.005 << 0.3 << 45.0 << 720.0 << 2 << 2.0 << 0.0 << false << 0.5 << 0.01 << true;
        QTest::newRow("tilted 5 deg: flagged") << 0.005 << 0.3 << 45.0 << 720.0 << 2 << 5.0 << 0.0 << false << 0.5 << 0.01 << false;
        QTest::newRow("stopped 20 deg short") << 0.0 << 0.1 << 45.0 << 700.0 << 2 << 0.0 << 0.0 << false << -2.78 << 0.02 << false;
        QTest::newRow("too slow (10 deg/s)") << 0.005 << 0.1 << 10.0 << 720.0 << 2 << 0.0 << 0.0 << false << 0.5 << 0.02 << false;
        QTest::newRow("pause in the middle") << 0.005 << 0.1 << 45.0 << 720.0 << 2 << 0.0 << 0.0 << true << 0.5 << 0.02 << false;
    }
    void estimates()
    {
        QFETCH(double, scale);
        QFETCH(double, bias);
        QFETCH(double, rate);
        QFETCH(double, trueDeg);
        QFETCH(int, legs);
        QFETCH(double, tilt);
        QFETCH(double, jitter);
        QFETCH(bool, pause);
        QFETCH(double, expectedPct);
        QFETCH(double, tolerancePct);
        QFETCH(bool, acceptable);
        Profile p;
        p.scale = scale;
        p.biasDps = bias;
        p.rateDps = rate;
        p.trueDeg = trueDeg;
        p.legs = legs;
        p.tiltDeg = tilt;
        p.jitterMs = jitter;
        p.pauseMidway = pause;
        GyroScaleRun::Options o;
        o.targetDeg = trueDeg > 1000 ? 1800 : 720;
        const GyroScaleRun::Result r = run(p, o);
        QVERIFY(r.complete);
        QCOMPARE(int(r.legs.size()), legs);
        QVERIFY2(std::fabs(r.scaleErrorPct - expectedPct) <= tolerancePct, qPrintable(QString::number(r.scaleErrorPct, 'f', 4)));
        QCOMPARE(r.acceptable, acceptable);
        QVERIFY(!r.summary.isEmpty());
        QVERIFY(std::fabs(r.odrHz - 100) < 1);
        QVERIFY(std::fabs(r.axisTiltDeg - tilt) < 0.2);
    }

    void guidanceFollowsTheRun()
    {
        GyroScaleRun r;
        QCOMPARE(r.state(), GyroScaleRun::State::Idle);
        QVERIFY(!r.guidance().isEmpty());
        r.start();
        double t = 0;
        auto feed = [&](double rate, double secs) {
            for (int i = 0; i < int(secs * 100); ++i, t += 10)
                r.addSample(t, Vector3d(0, 0, rate), Vector3d(0, 0, 1));
        };
        feed(0, 1);
        QCOMPARE(r.state(), GyroScaleRun::State::MeasuringBias);
        feed(0, 2);
        QCOMPARE(r.state(), GyroScaleRun::State::WaitingForTurn);
        feed(40, 9);
        QCOMPARE(r.state(), GyroScaleRun::State::Turning);
        QVERIFY(r.rateInBand());
        QVERIFY(std::fabs(r.currentAngleDeg() - 360) < 1);
        QVERIFY(std::fabs(r.turns() - 1) < 0.01);
        QVERIFY(!r.inStopWindow());
        feed(40, 8.95);
        QVERIFY(r.inStopWindow()); // 718 of 720
        feed(0, 1);
        QCOMPARE(r.state(), GyroScaleRun::State::WaitingForTurn);
        QCOMPARE(r.legIndex(), 1);
        QVERIFY(r.guidance().contains(QStringLiteral("back")));
        // Repeated timestamps are ignored, non-finite samples too.
        const int before = r.legIndex();
        r.addSample(t - 10, Vector3d(0, 0, 500), Vector3d(0, 0, 1));
        r.addSample(t + 10, Vector3d(std::nan(""), 0, 0), Vector3d(0, 0, 1));
        QCOMPARE(r.legIndex(), before);
        QCOMPARE(r.state(), GyroScaleRun::State::WaitingForTurn);
    }

    void stillness_data()
    {
        QTest::addColumn<double>("gyroNoise");
        QTest::addColumn<double>("accNoise");
        QTest::addColumn<double>("rate");
        QTest::addColumn<bool>("still");
        QTest::newRow("at rest") << 0.05 << 0.001 << 0.0 << true;
        QTest::newRow("shaking gyro") << 1.0 << 0.001 << 0.0 << false;
        QTest::newRow("vibration (acc)") << 0.05 << 0.02 << 0.0 << false;
        QTest::newRow("steady turn") << 0.05 << 0.001 << 30.0 << false;
    }
    void stillness()
    {
        QFETCH(double, gyroNoise);
        QFETCH(double, accNoise);
        QFETCH(double, rate);
        QFETCH(bool, still);
        calib::StillnessDetector d;
        std::mt19937_64 g(1);
        std::normal_distribution<double> n;
        for (int i = 0; i < 50; ++i)
            d.add(i * 10.0, Vector3d(n(g), n(g), n(g)) * gyroNoise, Vector3d(0, 0, 1));
        QVERIFY(!d.isStill()); // half a window is not enough
        for (int i = 50; i < 300; ++i)
            d.add(i * 10.0, Vector3d(0, 0, rate) + Vector3d(n(g), n(g), n(g)) * gyroNoise,
                  Vector3d(0, 0, 1) + Vector3d(n(g), n(g), n(g)) * accNoise);
        QCOMPARE(d.isStill(), still);
        QVERIFY(d.windowFull());
        if (still) {
            QVERIFY(d.stillForS() >= 1.5);
            QVERIFY(d.meanAcc().z() > 0.99);
        } else {
            QCOMPARE(d.stillForS(), 0.0);
        }
        // Time going back (device restart) starts over.
        d.add(5.0, Vector3d::Zero(), Vector3d(0, 0, 1));
        QVERIFY(!d.isStill());
        QVERIFY(!d.windowFull());
    }

    void simulatedTurntable()
    {
        // The simulated module on its turntable (two turns each way) with a 0.5 % gyro scale
        // error: HI91 frames through the stream decoder, device timestamps (system_time).
        sim::SimOptions o;
        o.motion = sim::Motion::Turntable;
        o.gyroScaleError = 0.005;
        o.seed = 3;
        sim::HipnucSimulator device(o);
        protocol::StreamDemux demux;
        GyroScaleRun r;
        r.start();
        for (int64_t t = 0; t < 50000000 && r.state() != GyroScaleRun::State::Finished; t += 50000) {
            device.advanceTo(t);
            const auto bytes = device.takeOutput();
            for (const auto &e : demux.feed(bytes.data(), bytes.size())) {
                protocol::hipnuc::Hi91 f;
                if (e.kind == protocol::StreamEvent::Kind::Frame && protocol::hipnuc::decodeHi91(e.payload.data(), e.payload.size(), f))
                    r.addSample(f.systemTime, Vector3d(f.gyr[0], f.gyr[1], f.gyr[2]), Vector3d(f.acc[0], f.acc[1], f.acc[2]));
            }
        }
        const auto res = r.result();
        QVERIFY(res.complete);
        QVERIFY(res.acceptable);
        QVERIFY2(std::fabs(res.scaleErrorPct - 0.5) < 0.06, qPrintable(QString::number(res.scaleErrorPct)));
        QVERIFY(res.legs[0].angleDeg < 0); // clockwise first
        QVERIFY(res.legs[1].angleDeg > 0);
        QVERIFY(std::fabs(res.legs[0].meanRateDps - 45 * 1.005) < 0.5);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstGyroScaleRun)
#include "tst_gyro_scale_run.moc"
