// HEC495 calibration methods (HEC495 manual, "校准方法"): the pose tables of the automatic
// 12-point and 12-point small-tilt methods, the planar targets, collection from the 0x66
// valid-point count, and the FitErr rule (> 10: calibrate again).
#include "calib/compass_pose_tracker.h"
#include "../common/test_main.h"

#include <QTest>

using namespace imudesk::calib;

class TstCompassPoseTracker : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void tables_data()
    {
        QTest::addColumn<int>("method");
        QTest::addColumn<int>("row");
        QTest::addColumn<double>("heading");
        QTest::addColumn<double>("pitchMin");
        QTest::addColumn<double>("pitchMax");
        QTest::addColumn<double>("rollMin");
        QTest::addColumn<double>("rollMax");
        const int a12 = int(CompassCalMethod::Auto12), st = int(CompassCalMethod::Auto12SmallTilt);
        // Rows copied from the manual's tables (采样点序号 / Heading / Pitch / Roll).
        QTest::newRow("auto12 #1") << a12 << 1 << 0.0 << -5.0 << 5.0 << 30.0 << 40.0;
        QTest::newRow("auto12 #2") << a12 << 2 << 90.0 << -5.0 << 5.0 << -40.0 << -30.0;
        QTest::newRow("auto12 #5") << a12 << 5 << 30.0 << 45.0 << 90.0 << 30.0 << 40.0;
        QTest::newRow("auto12 #8") << a12 << 8 << 300.0 << 45.0 << 90.0 << -40.0 << -30.0;
        QTest::newRow("auto12 #9") << a12 << 9 << 60.0 << -90.0 << -45.0 << 30.0 << 40.0;
        QTest::newRow("auto12 #12") << a12 << 12 << 330.0 << -90.0 << -45.0 << -40.0 << -30.0;
        QTest::newRow("small tilt #3") << st << 3 << 180.0 << -5.0 << 5.0 << -5.0 << 5.0;
        QTest::newRow("small tilt #7") << st << 7 << 210.0 << 45.0 << 90.0 << -5.0 << 5.0;
        QTest::newRow("small tilt #11") << st << 11 << 240.0 << -90.0 << -45.0 << -5.0 << 5.0;
        QTest::newRow("planar #4") << int(CompassCalMethod::Planar) << 4 << 90.0 << -2.0 << 2.0 << -2.0 << 2.0;
    }
    void tables()
    {
        QFETCH(int, method);
        QFETCH(int, row);
        QFETCH(double, heading);
        QFETCH(double, pitchMin);
        QFETCH(double, pitchMax);
        QFETCH(double, rollMin);
        QFETCH(double, rollMax);
        const auto t = CompassPoseTracker::targets(CompassCalMethod(method));
        QCOMPARE(int(t.size()), 12);
        const PoseTarget &p = t[size_t(row - 1)];
        QCOMPARE(p.number, row);
        QCOMPARE(p.headingDeg, heading);
        QCOMPARE(p.pitchMinDeg, pitchMin);
        QCOMPARE(p.pitchMaxDeg, pitchMax);
        QCOMPARE(p.rollMinDeg, rollMin);
        QCOMPARE(p.rollMaxDeg, rollMax);
    }

    void methods()
    {
        QVERIFY(CompassPoseTracker::targets(CompassCalMethod::Manual).empty());
        QVERIFY(CompassPoseTracker::targets(CompassCalMethod::AutoAllOrientation).empty());
        QCOMPARE(CompassPoseTracker::maxPoints(CompassCalMethod::AutoAllOrientation), 96);
        QCOMPARE(CompassPoseTracker::maxPoints(CompassCalMethod::Planar), 12);
        QCOMPARE(CompassPoseTracker::minPoints(CompassCalMethod::Manual), 12);
        // The start commands: 77 04 00 63/65/08/64/60.
        QCOMPARE(CompassPoseTracker::startCommandCode(CompassCalMethod::Auto12), uint8_t(0x63));
        QCOMPARE(CompassPoseTracker::startCommandCode(CompassCalMethod::Manual), uint8_t(0x65));
        QCOMPARE(CompassPoseTracker::startCommandCode(CompassCalMethod::AutoAllOrientation), uint8_t(0x08));
        QCOMPARE(CompassPoseTracker::startCommandCode(CompassCalMethod::Auto12SmallTilt), uint8_t(0x64));
        QCOMPARE(CompassPoseTracker::startCommandCode(CompassCalMethod::Planar), uint8_t(0x60));
        QVERIFY(CompassPoseTracker::fitErrAcceptable(10));
        QVERIFY(!CompassPoseTracker::fitErrAcceptable(10.5));
        for (auto m : {CompassCalMethod::Auto12, CompassCalMethod::Manual, CompassCalMethod::AutoAllOrientation,
                       CompassCalMethod::Auto12SmallTilt, CompassCalMethod::Planar}) {
            QVERIFY(!CompassPoseTracker::methodName(m).isEmpty());
            QVERIFY(!CompassPoseTracker::instructions(m).isEmpty());
        }
    }

    void collectsAsTheDeviceCounts()
    {
        CompassPoseTracker t(CompassCalMethod::Auto12);
        QCOMPARE(t.updatePose(95, 2, -35), 1);     // near target #2 (heading within 15, in range)
        QCOMPARE(t.setValidPoints(1), 1);          // the 0x66 reply: point collected here
        QVERIFY(t.collected(1));
        QCOMPARE(t.setValidPoints(1), -1);         // the same count again: nothing new
        QCOMPARE(t.updatePose(200, 2, 35), -1);    // between targets
        QCOMPARE(t.setValidPoints(2), -1);         // counted, but at no target
        QCOMPARE(t.validPoints(), 2);
        QCOMPARE(t.collectedCount(), 1);
        QCOMPARE(t.updatePose(359, 60, 33), -1);   // pitch 60: #5..#8, but none at heading 0
        QCOMPARE(t.updatePose(40, 60, 33), 4);     // #5: heading 30, pitch > 45, roll 30..40
    }

    void everyTargetReachable()
    {
        for (auto m : {CompassCalMethod::Auto12, CompassCalMethod::Auto12SmallTilt, CompassCalMethod::Planar}) {
            CompassPoseTracker t(m);
            int count = 0;
            for (const PoseTarget &p : t.poseTargets()) {
                const double pitch = (p.pitchMinDeg + p.pitchMaxDeg) / 2, roll = (p.rollMinDeg + p.rollMaxDeg) / 2;
                QCOMPARE(t.updatePose(p.headingDeg + 5, pitch, roll), p.number - 1);
                QCOMPARE(t.setValidPoints(++count), p.number - 1);
            }
            QCOMPARE(t.collectedCount(), 12);
            QCOMPARE(t.progressPct(), 100.0);
            QVERIFY(t.readyToSave());
            QVERIFY(t.nextHint().contains(QStringLiteral("12")));
            // The device starting over (count back to 0) clears the display.
            t.setValidPoints(0);
            QCOMPARE(t.collectedCount(), 0);
        }
    }

    void headingWrapsAround()
    {
        CompassPoseTracker t(CompassCalMethod::Planar);
        QCOMPARE(t.updatePose(352, 0.5, -0.5), 0);  // 8 deg from 0
        QCOMPARE(t.updatePose(0, 5, 0), 0);          // pitch 5: within 2 deg + the 5 deg margin
        QCOMPARE(t.updatePose(0, 8, 0), -1);         // pitch 8: not level
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCompassPoseTracker)
#include "tst_compass_pose_tracker.moc"
