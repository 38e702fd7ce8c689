// The heading check after a magnetometer calibration (issue 53 point 4): a level turn without a
// jump passes; a tilted module (the tumbling demo, whose Euler yaw swings near 90 deg of pitch)
// is told to keep the module level, never to calibrate again; a jump in a disturbed field is not
// the calibration's; a jump while level in a steady field is; a slow output turning fast is not
// a jump when the gyro turned as much.
#include "calib/heading_check.h"
#include "model/sample.h"
#include "../common/test_main.h"

#include <QTest>

#include <cmath>

using imudesk::calib::HeadingCheck;
using imudesk::model::Sample;
namespace model = imudesk::model;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// A sample at t seconds: Euler angles, the gyro about the vertical (deg/s) and a field of 50 µT
// turning with the heading (already corrected).
Sample sample(double t, double roll, double pitch, double yaw, double rateZ, double field = 50.0)
{
    Sample s;
    s.source = "HI91";
    s.fields = model::FieldEuler | model::FieldGyr | model::FieldMag | model::FieldDeviceTime;
    s.deviceTimeMs = t * 1e3;
    s.hostTimeNs = int64_t(t * 1e9);
    s.roll = roll;
    s.pitch = pitch;
    s.yaw = std::remainder(yaw, 360.0);
    s.gyr = {0.0, 0.0, rateZ};
    const double h = std::sqrt(field * field * 0.25), v = std::sqrt(field * field * 0.75);
    s.mag = {h * std::sin(yaw * kDeg), h * std::cos(yaw * kDeg), -v};
    return s;
}

} // namespace

class TstHeadingCheck : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void levelTurnPasses()
    {
        HeadingCheck c;
        c.setFieldCorrection(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
        for (int i = 0; i <= 1300; ++i) // 100 Hz, 30 deg/s: 390 deg
            c.add(sample(i / 100.0, 1.0, -2.0, 30.0 * i / 100.0, 30.0));
        QCOMPARE(c.status(), HeadingCheck::Status::Passed);
        QVERIFY(c.levelTurnDeg() >= HeadingCheck::kFullTurnDeg);
        QVERIFY(c.largestJudgedStepDeg() < 1.0);
        QVERIFY(c.advice().startsWith(QStringLiteral("Passed")));
    }

    void partOfATurnSaysKeepTurning()
    {
        HeadingCheck c;
        for (int i = 0; i <= 300; ++i)
            c.add(sample(i / 100.0, 0.0, 0.0, 30.0 * i / 100.0, 30.0));
        QCOMPARE(c.status(), HeadingCheck::Status::TurnMore);
        QVERIFY2(c.advice().contains(QStringLiteral("90 of 360")), qPrintable(c.advice()));
    }

    // The demo's case: tumbling through 90 deg of pitch, where the yaw swings by tens of degrees
    // from one sample to the next. Not level: nothing is judged, and the check says so.
    void tumblingIsToldToKeepLevel()
    {
        HeadingCheck c;
        c.setFieldCorrection(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
        for (int i = 0; i <= 2000; ++i) {
            const double t = i / 100.0;
            const double pitch = 89.0 * std::sin(0.5 * t);
            const double yaw = 20.0 * t + (std::abs(pitch) > 80.0 ? 40.0 * (i % 3) : 0.0); // swings near the pole
            c.add(sample(t, 30.0 * std::sin(0.3 * t), pitch, yaw, 0.0));
        }
        QVERIFY(c.unjudgedJumps() > 0);
        QVERIFY(c.status() != HeadingCheck::Status::Jumps);
        QVERIFY(c.largestTiltDeg() > 60.0);
        // Ends tilted: the advice is to keep the module level.
        c.add(sample(20.01, 0.0, 40.0, 0.0, 0.0));
        QCOMPARE(c.status(), HeadingCheck::Status::Tilted);
        QVERIFY2(c.advice().startsWith(QStringLiteral("Keep the module level while you turn it")), qPrintable(c.advice()));
        QVERIFY(!c.advice().contains(QStringLiteral("alibrate again")));
    }

    void jumpWhileLevelInASteadyFieldFails()
    {
        HeadingCheck c;
        c.setFieldCorrection(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
        for (int i = 0; i <= 1300; ++i) {
            const double yaw = 30.0 * i / 100.0 + (i >= 500 ? 25.0 : 0.0); // a 25 deg step at 5 s
            c.add(sample(i / 100.0, 0.0, 0.0, yaw, 30.0));
        }
        QCOMPARE(c.status(), HeadingCheck::Status::Jumps);
        QVERIFY(std::abs(c.largestJudgedStepDeg() - 25.0) < 0.5);
        QVERIFY2(c.advice().contains(QStringLiteral("Calibrate again")), qPrintable(c.advice()));
    }

    // A magnet passes: |B| rises by 40 % and the heading steps. The field is disturbed, so the
    // step is not the calibration's; the check says why it cannot judge.
    void jumpInADisturbedFieldIsNotJudged()
    {
        HeadingCheck c;
        c.setFieldCorrection(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
        for (int i = 0; i <= 600; ++i) {
            const bool magnet = i >= 300;
            c.add(sample(i / 100.0, 0.0, 0.0, 30.0 * i / 100.0 + (magnet ? 30.0 : 0.0), 30.0, magnet ? 70.0 : 50.0));
        }
        QCOMPARE(c.status(), HeadingCheck::Status::FieldDisturbed);
        QCOMPARE(c.unjudgedJumps(), 1);
        QVERIFY(c.largestJudgedStepDeg() < 1.0);
        QVERIFY(std::abs(c.fieldChangePct() - 40.0) < 1.0);
        QVERIFY2(c.advice().contains(QStringLiteral("cannot judge")), qPrintable(c.advice()));
        // Without a correction the field is not judged: the step counts.
        HeadingCheck raw;
        for (int i = 0; i <= 600; ++i) {
            const bool magnet = i >= 300;
            raw.add(sample(i / 100.0, 0.0, 0.0, 30.0 * i / 100.0 + (magnet ? 30.0 : 0.0), 30.0, magnet ? 70.0 : 50.0));
        }
        QCOMPARE(raw.status(), HeadingCheck::Status::Jumps);
    }

    // 5 Hz output, turned at 100 deg/s: 20 deg a sample, all of it turned by the gyro.
    void slowOutputTurningFastIsNoJump()
    {
        HeadingCheck c;
        for (int i = 0; i <= 25; ++i)
            c.add(sample(i / 5.0, 0.0, 0.0, 100.0 * i / 5.0, 100.0));
        QCOMPARE(c.status(), HeadingCheck::Status::Passed);
        // Without the gyro the same steps are jumps.
        HeadingCheck noGyro;
        for (int i = 0; i <= 25; ++i) {
            Sample s = sample(i / 5.0, 0.0, 0.0, 100.0 * i / 5.0, 100.0);
            s.fields &= ~uint32_t(model::FieldGyr);
            noGyro.add(s);
        }
        QCOMPARE(noGyro.status(), HeadingCheck::Status::Jumps);
    }
};

IMUDESK_TEST_MAIN(TstHeadingCheck)
#include "tst_heading_check.moc"
