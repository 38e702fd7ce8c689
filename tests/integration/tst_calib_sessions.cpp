// The calibration drivers over a real DeviceSession against the simulated module in this
// process (sim::SimulatedTransport, tests/common/sim_session.h): the gyro scale calibration (CONFIG USRCAL START/STOP, manual v1.7.1
// 4.6.7.11) while the simulated turntable turns two turns, with our own estimate from the
// streamed samples beside the device's OK; the magnetometer calibration (CONFIG MCAL
// START, LOG MCAL STAT) starting and reporting progress; refusals and silence.
#include "../common/session_probes.h"
#include "../common/sim_session.h"
#include "../common/test_main.h"
#include "calib/gyro_cal_session.h"
#include "calib/gyro_scale_run.h"
#include "calib/mag_cal_session.h"
#include "device/device_session.h"

#include <QSignalSpy>
#include <QTest>

using namespace imudesk;
using calib::GyroCalSession;
using device::DeviceSession;
using device::SessionState;
using test::waitConnected;

namespace {

sim::SimOptions options(sim::Motion motion, const char *firmware = "1.7.1", const char *model = "HI14")
{
    sim::SimOptions o;
    o.model = model;
    o.firmware = firmware;
    o.motion = motion;
    o.seed = 9;
    o.gyroScaleError = 0.005;
    return o;
}

double deviceTimeS(DeviceSession &s)
{
    const auto latest = s.store().latest();
    return latest ? latest->deviceTimeMs / 1000.0 : 0.0;
}

} // namespace

class TstCalibSessions : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        qRegisterMetaType<GyroCalSession::State>();
    }

    void gyroScaleOnTurntable()
    {
        test::SimSession sim(options(sim::Motion::Turntable));
        DeviceSession &session = sim.session;
        sim.open(115200);
        QVERIFY(waitConnected(session));
        QTRY_VERIFY(session.store().totalAppended() > 10);
        QVERIFY2(deviceTimeS(session) < sim::MotionModel::kTurntableStillS, "connected before the turntable starts");

        GyroCalSession gyro(session);
        QSignalSpy finished(&gyro, &GyroCalSession::finished);
        QVERIFY(!gyro.start(700));  // outside 720..1800: nothing sent
        QVERIFY(!gyro.stop());      // not running
        QVERIFY(gyro.start(720));
        QTRY_COMPARE(gyro.state(), GyroCalSession::State::Running);

        // Our own estimate from the same stream, with the device's timestamps.
        calib::GyroScaleRun::Options ro;
        ro.legs = 1;
        ro.biasWindowS = 1.0;
        calib::GyroScaleRun run(ro);
        run.start();
        uint64_t seq = 0;
        const double legEnd = sim::MotionModel::kTurntableStillS + sim::MotionModel::turntableLegS();
        (void)imudesk::test::waitFor(
            [&] {
                for (const auto &s : session.store().since(seq, SIZE_MAX, &seq))
                    run.addSample(s.deviceTimeMs, {s.gyr.x, s.gyr.y, s.gyr.z}, {s.acc.x, s.acc.y, s.acc.z});
                return run.state() == calib::GyroScaleRun::State::Finished;
            },
            40000);
        QCOMPARE(run.state(), calib::GyroScaleRun::State::Finished);
        QVERIFY(deviceTimeS(session) >= legEnd);
        QVERIFY(gyro.stop());
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 5000);
        QCOMPARE(finished.at(0).at(0).toBool(), true); // the device's OK: 720 deg turned within 5
        QCOMPARE(gyro.state(), GyroCalSession::State::Succeeded);
        const auto res = run.result();
        QVERIFY2(std::fabs(res.scaleErrorPct - 0.5) < 0.1, qPrintable(res.summary));
        QVERIFY(res.legs.front().stoppedInWindow);
    }

    void gyroStopTooEarlyIsRejected()
    {
        test::SimSession sim(options(sim::Motion::Turntable));
        DeviceSession &session = sim.session;
        sim.open(115200);
        QVERIFY(waitConnected(session));
        GyroCalSession gyro(session);
        QSignalSpy finished(&gyro, &GyroCalSession::finished);
        QVERIFY(gyro.start(1800));
        QTRY_COMPARE(gyro.state(), GyroCalSession::State::Running);
        QVERIFY(gyro.stop());
        QTRY_COMPARE(finished.size(), 1);
        QCOMPARE(finished.at(0).at(0).toBool(), false); // the device's ERR
        QVERIFY(gyro.message().contains(QStringLiteral("1800")));
    }

    void magCalReportsProgress()
    {
        test::SimSession sim(options(sim::Motion::Tumble));
        DeviceSession &session = sim.session;
        sim.open(115200);
        QVERIFY(waitConnected(session));
        calib::MagCalSession mcal(session, calib::MagCalProcedure::Options{200, 180000, 3});
        QSignalSpy progress(&mcal, &calib::MagCalSession::progressChanged);
        mcal.start(calib::MagCalProcedure::Flow::Mcal);
        QVERIFY(mcal.running());
        // STAT=1 with PROGRESS growing while the simulated module tumbles.
        QTRY_VERIFY_WITH_TIMEOUT(mcal.procedure().progress() > 0, 10000);
        QCOMPARE(mcal.procedure().stat(), 1);
        QCOMPARE(mcal.procedure().state(), calib::MagCalProcedure::State::Calibrating);
        QVERIFY(progress.size() >= 2);
        mcal.cancel();
        QVERIFY(!mcal.running());
    }

    void magCalRefusals_data()
    {
        QTest::addColumn<QString>("model");
        QTest::addColumn<QString>("firmware");
        QTest::newRow("no magnetometer (HI02): ERR") << "HI02" << "1.7.1";
        QTest::newRow("firmware 1.6.6: silence") << "HI14" << "1.6.6";
    }
    void magCalRefusals()
    {
        QFETCH(QString, model);
        QFETCH(QString, firmware);
        const std::string m = model.toStdString(), fw = firmware.toStdString();
        test::SimSession sim(options(sim::Motion::Tumble, fw.c_str(), m.c_str()));
        DeviceSession &session = sim.session;
        sim.open(115200);
        QVERIFY(waitConnected(session));
        calib::MagCalSession mcal(session);
        QSignalSpy finished(&mcal, &calib::MagCalSession::finished);
        mcal.start(calib::MagCalProcedure::Flow::Mcal);
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 5000);
        QCOMPARE(finished.at(0).at(0).toBool(), false);
        QVERIFY(!finished.at(0).at(1).toString().isEmpty());
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCalibSessions)
#include "tst_calib_sessions.moc"
