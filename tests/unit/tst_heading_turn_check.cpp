// The heading check after a magnetometer calibration (calib::HeadingTurnCheck, shared by the
// wizard's heading page and `imudesk-cli calibrate mag|heading-check`): a full level turn with
// the heading following smoothly passes; a jump above 10 deg fails at once; steps across +-180
// and 0/360 are small steps; too short a turn is "keep turning".
#include "calib/heading_turn_check.h"
#include "../common/test_main.h"

#include <QTest>

#include <cmath>
#include <limits>

using imudesk::calib::HeadingTurnCheck;

class TstHeadingTurnCheck : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void fullTurnPasses()
    {
        HeadingTurnCheck c;
        // +-180 headings (the HiPNUC yaw), 2 deg a sample, clockwise and across the seam.
        for (int i = 0; i <= 180; ++i)
            c.add(std::remainder(170.0 - 2.0 * i, 360.0));
        QCOMPARE(c.verdict(), HeadingTurnCheck::Verdict::Passed);
        QVERIFY(std::abs(c.turnedDeg() - 360.0) < 1e-9);
        QVERIFY(std::abs(c.maxJumpDeg() - 2.0) < 1e-9);
        QCOMPARE(c.samples(), 181);
    }

    void shortTurnKeepsTurning()
    {
        HeadingTurnCheck c;
        for (int i = 0; i < 100; ++i) // 0..360 headings, 3 deg a sample: 297 deg
            c.add(std::fmod(350.0 + 3.0 * i, 360.0));
        QCOMPARE(c.verdict(), HeadingTurnCheck::Verdict::KeepTurning);
        QVERIFY(std::abs(c.turnedDeg() - 297.0) < 1e-9);
        c.add(std::numeric_limits<double>::quiet_NaN()); // no heading: ignored
        QCOMPARE(c.samples(), 100);
        c.reset();
        QCOMPARE(c.turnedDeg(), 0.0);
        QCOMPARE(c.samples(), 0);
    }

    void jumpFails()
    {
        HeadingTurnCheck c;
        for (int i = 0; i < 200; ++i)
            c.add(2.0 * i + (i == 50 ? 12.0 : 0.0)); // one heading 12 deg off: two steps of 14 and 10
        QCOMPARE(c.verdict(), HeadingTurnCheck::Verdict::Jumped);
        QVERIFY(std::abs(c.maxJumpDeg() - 14.0) < 1e-9);
        QVERIFY(!c.passed());
        HeadingTurnCheck edge;
        edge.add(0);
        edge.add(10.0); // exactly the limit: not a jump
        QCOMPARE(edge.verdict(), HeadingTurnCheck::Verdict::KeepTurning);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstHeadingTurnCheck)
#include "tst_heading_turn_check.moc"
