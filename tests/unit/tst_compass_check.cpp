// The compass check (verify/compass_check.h, issue 55): a compass turned on a level rose to its
// marked bearings; stops matched to the bearings, the worst heading error and the mean offset
// judged with their bounds, a bearing never held is "cannot judge".
#include "../common/test_main.h"
#include "sim/motion_model.h"
#include "verify/compass_check.h"

#include <QTest>

#include <cmath>
#include <random>

using namespace imudesk;

namespace {

// The compass on Motion::Bearings at 10 Hz: its heading the truth plus `offset` and an error of
// `amplitude` that turns with the heading (soft iron), noise 0.1°; level.
std::vector<verify::CompassSample> turned(double offset, double amplitude, double seconds = 45)
{
    const sim::MotionModel motion(sim::MotionModel::Options{1, sim::Motion::Bearings});
    std::mt19937 g(3);
    std::normal_distribution<double> noise(0, 0.1);
    std::vector<verify::CompassSample> out;
    for (int i = 0; i < int(seconds * 10); ++i) {
        const double t = i / 10.0;
        const double truth = -sim::eulerEnu312(motion.at(t).q).yaw;
        double h = truth + offset + amplitude * std::sin(2 * truth * M_PI / 180) + noise(g);
        h = std::fmod(h + 720, 360);
        out.push_back({t, h, 0.02 * noise(g), 0.02 * noise(g)});
    }
    return out;
}

} // namespace

class TstCompassCheck : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void goodCompassPasses()
    {
        const auto r = verify::checkCompass(turned(0, 0.2), verify::CompassCheckOptions{{0, 90, 180, 270}});
        QCOMPARE(r.bearingsHeld, 4);
        QVERIFY2(r.verdict == verify::Verdict::Pass, qPrintable(r.reasons.join(QLatin1Char('\n'))));
        QVERIFY(std::fabs(r.worstHeadingErrDeg.value) < 0.4);
    }

    void offsetAndCurveFound()
    {
        verify::CompassCheckOptions o;
        o.bearingsDeg = {0, 45, 90, 135, 180, 225, 270, 315};
        const auto r = verify::checkCompass(turned(3.0, 1.0), o);
        QCOMPARE(r.bearingsHeld, 8);
        QVERIFY2(std::fabs(r.meanHeadingErrDeg.value - 3.0) < 0.1, qPrintable(QString::number(r.meanHeadingErrDeg.value)));
        // The worst bearing: 45° or 225°, where sin(2h) adds its full degree.
        QVERIFY2(std::fabs(r.worstHeadingErrDeg.value - 4.0) < 0.15, qPrintable(QString::number(r.worstHeadingErrDeg.value)));
        QVERIFY(r.worstBearingDeg == 45 || r.worstBearingDeg == 225);
        QCOMPARE(r.verdict, verify::Verdict::Fail);
        QVERIFY(r.reasons.front().startsWith(QLatin1String("heading error at")));
    }

    void bearingNeverHeldCannotJudge()
    {
        // 14 s: only the first three marks (0, 45, 90) are held.
        const auto r = verify::checkCompass(turned(0, 0, 14), verify::CompassCheckOptions{{0, 90, 180, 270}});
        QCOMPARE(r.verdict, verify::Verdict::CannotJudge);
        QVERIFY(!r.worstHeadingErrDeg.judged);
        QVERIFY2(r.worstHeadingErrDeg.why.contains(QStringLiteral("180°, 270°")), qPrintable(r.worstHeadingErrDeg.why));
    }

    void tiltedRoseWarns()
    {
        auto s = turned(0, 0);
        for (auto &x : s)
            x.pitchDeg += 0.6; // the rose is not level, or the compass tilts
        const auto r = verify::checkCompass(s, verify::CompassCheckOptions{{0, 90, 180, 270}});
        QCOMPARE(r.verdict, verify::Verdict::Warn);
        QVERIFY(std::fabs(r.pitchErrDeg.value - 0.6) < 0.05);
    }
};

IMUDESK_TEST_APPLESS_MAIN(TstCompassCheck)
#include "tst_compass_check.moc"
