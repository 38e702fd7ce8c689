// The module check (core/verify, issue 55): still poses from a hand-turned recording, the
// accelerometer's, the gyro's and the attitude's errors against the truth injected into the
// simulator's sensor model, and the verdict.
#include "../common/verify_rig.h"
#include "sim/hipnuc_simulator.h"
#include "verify/check_steps.h"
#include "verify/local_gravity.h"

#include "../common/test_main.h"

#include <QtTest>

using namespace imudesk;

class TstModuleCheck : public QObject {
    Q_OBJECT

private:
    static verify::CheckOptions simOptions()
    {
        verify::CheckOptions o;
        o.gravityMs2 = model::kGravity; // the simulator's gravity is the module's 1 G
        return o;
    }

private Q_SLOTS:
    void normalGravity_data()
    {
        QTest::addColumn<double>("latitude");
        QTest::addColumn<double>("height");
        QTest::addColumn<double>("expected");
        // WGS 84 (NIMA TR8350.2 table 3.4): the equator's and the poles' normal gravity; 45° and
        // 1000 m with the free-air gradient of about -3.086e-6 s^-2.
        QTest::newRow("equator") << 0.0 << 0.0 << 9.7803253359;
        QTest::newRow("north pole") << 90.0 << 0.0 << 9.8321849378;
        QTest::newRow("south pole") << -90.0 << 0.0 << 9.8321849378;
        QTest::newRow("45 deg") << 45.0 << 0.0 << 9.806199203;
        QTest::newRow("45 deg, 1000 m") << 45.0 << 1000.0 << 9.806199203 - 3.0860e-3;
    }
    void normalGravity()
    {
        QFETCH(double, latitude);
        QFETCH(double, height);
        QFETCH(double, expected);
        QVERIFY2(std::fabs(verify::normalGravity(latitude, height) - expected) < 2e-6,
                 qPrintable(QString::number(verify::normalGravity(latitude, height), 'f', 9)));
    }

    void faultsReadAndWriteBack()
    {
        sim::SimFaults f;
        std::string error;
        QVERIFY(sim::parseSimFaults("acc-bias=12/-5/8, acc-scale=1/0/-0.5, acc-misalignment=0.2/0/-0.1, gyro-scale=0.5, "
                                    "gyro-misalignment=0.1/0/-0.2, attitude-bias=0/0/3, filter-lag=40",
                                    f, &error));
        QCOMPARE(f.accBiasMg, (std::array<double, 3>{12, -5, 8}));
        QCOMPARE(f.accScalePct, (std::array<double, 3>{1, 0, -0.5}));
        QCOMPARE(f.gyroScalePct, (std::array<double, 3>{0.5, 0.5, 0.5}));
        QCOMPARE(f.gyroMisalignmentDeg, (std::array<double, 3>{0.1, 0, -0.2}));
        QCOMPARE(f.attitudeBiasDeg, (std::array<double, 3>{0, 0, 3}));
        QCOMPARE(f.filterLagMs, 40.0);
        sim::SimFaults back;
        QVERIFY(sim::parseSimFaults(sim::simFaultsText(f), back, &error));
        QCOMPARE(back, f);
        const auto e = sim::accErrorOf(f);
        QCOMPARE(e.biasG[0], 0.012);
        QCOMPARE(e.scale[0], 0.01);
        sim::SimFaults g;
        QVERIFY(sim::parseSimFaults("acc-error=20/1", g, &error));
        QCOMPARE(g.accBiasMg, (std::array<double, 3>{20, 20, 20}));
        QCOMPARE(g.accScalePct, (std::array<double, 3>{1, 1, 1}));
        QVERIFY(!sim::parseSimFaults("acc-bias=1/2", g, &error));
        QVERIFY2(QString::fromStdString(error).contains(QLatin1String("acc-bias=X/Y/Z")), error.c_str());
        QVERIFY(!sim::parseSimFaults("filter-lag=-3", g, &error));
    }

    // The hand-turned motion: its rate is the derivative of its attitude, it rests at every
    // pose, and one pose is held too briefly.
    void posesMotionIsConsistent()
    {
        const sim::MotionModel m(sim::MotionModel::Options{7, sim::Motion::Poses});
        const auto holds = m.poseHolds();
        QCOMPARE(int(holds.size()), sim::MotionModel::kPoseCount + 1);
        QCOMPARE(int(std::count_if(holds.begin(), holds.end(), [](const auto &h) { return h.brief; })), 1);
        // Integrate the rate over the whole motion: it must land on each pose.
        Eigen::Quaterniond q = m.at(0).q;
        const double dt = 1e-4;
        size_t next = 1;
        for (double t = 0; t < m.posesEndS() + 0.5 && next < holds.size(); t += dt) {
            const Eigen::Vector3d w = m.at(t + dt / 2).rateDps * (3.141592653589793 / 180.0);
            if (w.norm() > 0)
                q = q * Eigen::Quaterniond(Eigen::AngleAxisd(w.norm() * dt, w.normalized()));
            if (t >= holds[next].fromS + 0.1) {
                QVERIFY2(q.angularDistance(holds[next].q) < 1e-3,
                         qPrintable(QStringLiteral("pose %1: %2 rad off").arg(next).arg(q.angularDistance(holds[next].q))));
                QVERIFY(!m.at(t).moving);
                QCOMPARE(m.at(t).rateDps.norm(), 0.0);
                ++next;
            }
        }
        QCOMPARE(next, holds.size());
    }

    void stillPosesFoundAndBriefOneLeftOut()
    {
        test::HandTurnedModule module;
        module.seed = 3;
        const auto samples = module.record();
        auto poses = verify::findStillPoses(samples, simOptions());
        QCOMPARE(int(poses.size()), sim::MotionModel::kPoseCount); // the brief one is not a pose
        QCOMPARE(verify::groupPoses(poses, 10), sim::MotionModel::kPoseCount);
        const sim::MotionModel motion(sim::MotionModel::Options{3, sim::Motion::Poses});
        size_t k = 0;
        for (const auto &h : motion.poseHolds()) {
            if (h.brief)
                continue;
            // Every interval lies inside its hold.
            QVERIFY2(poses[k].fromS >= h.fromS - 0.01 && poses[k].toS <= h.toS + 0.01,
                     qPrintable(QStringLiteral("pose %1: %2..%3 s, held %4..%5 s")
                                    .arg(k)
                                    .arg(poses[k].fromS)
                                    .arg(poses[k].toS)
                                    .arg(h.fromS)
                                    .arg(h.toS)));
            ++k;
        }
    }

    void injectedErrorsRecovered_data()
    {
        QTest::addColumn<quint64>("seed");
        QTest::newRow("seed 11") << quint64(11);
        QTest::newRow("seed 12") << quint64(12);
        QTest::newRow("seed 13") << quint64(13);
    }
    void injectedErrorsRecovered()
    {
        QFETCH(quint64, seed);
        test::HandTurnedModule module;
        module.seed = seed;
        module.accError.biasG = {0.012, -0.008, 0.020};
        module.accError.scale = {0.004, -0.003, 0.002};
        module.accError.misalignmentRad = {0.2 * M_PI / 180, -0.15 * M_PI / 180, 0.1 * M_PI / 180};
        module.gyroScale = {0.005, -0.003, 0.008};
        module.gyroMisalignment = {0.3 * M_PI / 180, -0.2 * M_PI / 180, 0.25 * M_PI / 180};
        module.attitudeBiasDeg = {0.4, -0.3, 1.5};
        const auto r = verify::checkModule(module.record(), simOptions());
        QCOMPARE(r.distinctPoses, 12);
        QVERIFY(r.accBiasMg.judged && r.accScalePct.judged && r.accMisalignmentDeg.judged);
        Eigen::Vector3d scaleTruth, misTruth;
        verify::accFiguresOf(module.accError.matrix(), scaleTruth, misTruth);
        for (int a = 0; a < 3; ++a) {
            QVERIFY2(std::fabs(r.accBiasMg.value[a] - module.accError.biasG[a] * 1000) < 1.0,
                     qPrintable(QStringLiteral("bias %1: %2 mg").arg(a).arg(r.accBiasMg.value[a])));
            QVERIFY2(std::fabs(r.accScalePct.value[a] - scaleTruth[a]) < 0.05,
                     qPrintable(QStringLiteral("scale %1: %2 %").arg(a).arg(r.accScalePct.value[a])));
            QVERIFY2(std::fabs(r.accMisalignmentAxesDeg[a] - misTruth[a]) < 0.05,
                     qPrintable(QStringLiteral("misalignment %1: %2 deg, true %3").arg(a).arg(r.accMisalignmentAxesDeg[a]).arg(misTruth[a])));
            QVERIFY(r.gyroScalePct.judged);
            QVERIFY2(std::fabs(r.gyroScalePct.value[a] - module.gyroScale[a] * 100) < 0.1,
                     qPrintable(QStringLiteral("gyro scale %1: %2 %").arg(a).arg(r.gyroScalePct.value[a])));
        }
        // The gyro's axes: the same truth as the accelerometer's form gives.
        Eigen::Vector3d gyroScaleTruth, gyroMisTruth;
        sim::SensorModel withErrors(seed);
        withErrors.setGyroScaleErrors(module.gyroScale);
        withErrors.setGyroMisalignment(module.gyroMisalignment);
        verify::accFiguresOf(withErrors.gyroMatrix(), gyroScaleTruth, gyroMisTruth);
        QVERIFY2(r.gyroMisalignmentDeg.judged, qPrintable(r.gyroMisalignmentDeg.why));
        for (int a = 0; a < 3; ++a) {
            QVERIFY2(std::fabs(r.gyroMisalignmentAxesDeg[a] - gyroMisTruth[a]) < 0.05,
                     qPrintable(QStringLiteral("gyro misalignment %1: %2 deg, true %3").arg(a).arg(r.gyroMisalignmentAxesDeg[a]).arg(gyroMisTruth[a])));
            QVERIFY2(std::fabs(r.gyroScalePct.value[a] - gyroScaleTruth[a]) < 0.1,
                     qPrintable(QStringLiteral("gyro scale %1: %2 %, true %3").arg(a).arg(r.gyroScalePct.value[a]).arg(gyroScaleTruth[a])));
        }
        QVERIFY(r.gyroBiasDps.judged);
        const sim::SensorModel sensors(seed);
        QVERIFY((r.gyroBiasDps.value - sensors.gyroBias()).norm() < 0.01);
        QVERIFY2(r.rollErrDeg.judged && std::fabs(r.rollErrDeg.value - 0.4) < 0.05, qPrintable(QString::number(r.rollErrDeg.value)));
        QVERIFY2(r.pitchErrDeg.judged && std::fabs(r.pitchErrDeg.value + 0.3) < 0.05, qPrintable(QString::number(r.pitchErrDeg.value)));
        QVERIFY2(r.headingErrDeg.judged && std::fabs(r.headingErrDeg.value - 1.5) < 0.3,
                 qPrintable(QString::number(r.headingErrDeg.value)));
        QCOMPARE(r.verdict, verify::Verdict::Warn); // heading 1.5°: between pass (1°) and fail (2.5°)
    }

    void goodModulePasses()
    {
        test::HandTurnedModule module;
        module.seed = 21;
        const auto r = verify::checkModule(module.record(), simOptions());
        QVERIFY2(r.verdict == verify::Verdict::Pass, qPrintable(r.reasons.join(QLatin1Char('\n'))));
    }

    void wrongModulesNeverPass_data()
    {
        QTest::addColumn<QString>("fault");
        QTest::newRow("heading 3 deg") << QStringLiteral("heading");
        QTest::newRow("acc scale 1 %") << QStringLiteral("scale");
    }
    void wrongModulesNeverPass()
    {
        QFETCH(QString, fault);
        test::HandTurnedModule module;
        module.seed = 31;
        if (fault == QLatin1String("heading"))
            module.attitudeBiasDeg = {0, 0, 3};
        else
            module.accError.scale = {0.01, 0.01, 0.01};
        const auto r = verify::checkModule(module.record(), simOptions());
        QCOMPARE(r.verdict, verify::Verdict::Fail);
        QVERIFY(r.reasons.front().contains(fault == QLatin1String("heading") ? QLatin1String("heading error")
                                                                              : QLatin1String("accelerometer scale error")));
    }

    // The attitude while moving: a module whose filter is 40 ms late shows that lag against the
    // reference filter, a good one none and a small error.
    void attitudeWhileMovingAndItsLag_data()
    {
        QTest::addColumn<double>("lagMs");
        QTest::newRow("no lag") << 0.0;
        QTest::newRow("40 ms") << 40.0;
        QTest::newRow("120 ms") << 120.0;
    }
    void attitudeWhileMovingAndItsLag()
    {
        QFETCH(double, lagMs);
        test::HandTurnedModule module;
        module.seed = 71;
        module.lagMs = lagMs;
        const auto r = verify::checkModule(module.record(), simOptions());
        QVERIFY2(r.dynamicLagMs.judged, qPrintable(r.dynamicLagMs.why));
        QVERIFY2(std::fabs(r.dynamicLagMs.value - lagMs) < 3.0,
                 qPrintable(QStringLiteral("lag %1 ms, sigma %2").arg(r.dynamicLagMs.value).arg(r.dynamicLagMs.sigma)));
        QVERIFY(r.dynamicRmsDeg.judged);
        if (lagMs == 0)
            QVERIFY2(r.dynamicRmsDeg.value < 0.2 && r.dynamicMaxDeg.value < 1.0,
                     qPrintable(QStringLiteral("RMS %1, max %2").arg(r.dynamicRmsDeg.value).arg(r.dynamicMaxDeg.value)));
        else
            QVERIFY2(r.dynamicRmsDeg.value > 1.0, qPrintable(QString::number(r.dynamicRmsDeg.value)));
        // A late attitude is far off while a hand turns the module (hundreds of degrees a second).
        QCOMPARE(r.verdict, lagMs > 0 ? verify::Verdict::Fail : verify::Verdict::Pass);
    }

    // Waved about with no still pose: nothing is judged, and the reason says what to do.
    void noStillPoseCannotJudge()
    {
        const sim::MotionModel motion(sim::MotionModel::Options{5, sim::Motion::Tumble});
        sim::SensorModel sensors(5);
        std::vector<verify::MotionSample> samples;
        for (int i = 0; i < 400 * 30; ++i) {
            verify::MotionSample s;
            s.tS = i / 400.0;
            const auto r = sensors.sample(motion.at(s.tS));
            s.acc = r.acc;
            s.gyr = r.gyr;
            samples.push_back(s);
        }
        const auto r = verify::checkModule(samples, simOptions());
        QCOMPARE(r.verdict, verify::Verdict::CannotJudge);
        QCOMPARE(int(r.poses.size()), 0);
        QVERIFY(!r.accBiasMg.judged && !r.gyroBiasDps.judged && !r.headingErrDeg.judged);
        QVERIFY2(r.reasons.front().contains(QLatin1String("no still pose: hold the module still for 3 s")),
                 qPrintable(r.reasons.front()));
    }

    // Too few poses: the accelerometer and the attitude are not judged (no number), the gyro's
    // bias is; a verdict needs the accelerometer and the tilt, so there is none.
    void fewPosesJudgeOnlyTheGyroBias()
    {
        test::HandTurnedModule module;
        module.seed = 41;
        auto samples = module.record();
        const sim::MotionModel motion(sim::MotionModel::Options{41, sim::Motion::Poses});
        const double cut = motion.poseHolds()[4].toS; // poses 0..4 and nothing after
        samples.erase(std::find_if(samples.begin(), samples.end(), [cut](const auto &s) { return s.tS > cut; }),
                      samples.end());
        const auto r = verify::checkModule(samples, simOptions());
        QCOMPARE(r.distinctPoses, 5);
        QVERIFY(!r.accBiasMg.judged);
        QVERIFY2(r.accBiasMg.why.contains(QLatin1String("5 distinct still poses, 9 needed")), qPrintable(r.accBiasMg.why));
        QVERIFY(!r.rollErrDeg.judged && !r.headingErrDeg.judged);
        QVERIFY(r.gyroBiasDps.judged);
        QCOMPARE(r.verdict, verify::Verdict::CannotJudge);
    }

    // A magnetometer whose hard iron was never calibrated: ImuDesk removes it from the poses
    // and says so; a pose beside a magnet is set aside.
    void hardIronRemovedAndDisturbedPoseSetAside()
    {
        test::HandTurnedModule module;
        module.seed = 51;
        auto samples = module.record();
        for (auto &s : samples)
            s.mag += Eigen::Vector3d(15, -10, 12); // a hard iron never calibrated
        const sim::MotionModel motion(sim::MotionModel::Options{51, sim::Motion::Poses});
        const auto hold = motion.poseHolds()[0]; // lying flat
        for (auto &s : samples)
            if (s.tS >= hold.fromS && s.tS <= hold.toS)
                s.mag += Eigen::Vector3d(15, -10, 5); // a magnet beside the first pose
        const auto r = verify::checkModule(samples, simOptions());
        QVERIFY(r.hardIronRemoved);
        QVERIFY(r.reasons.join(QLatin1Char('\n')).contains(QLatin1String("hard iron")));
        int setAside = 0;
        for (const auto &p : r.poses)
            setAside += p.tiltUsed && !p.headingUsed;
        QVERIFY2(setAside >= 1, qPrintable(r.reasons.join(QLatin1Char('\n'))));
        QVERIFY2(r.headingErrDeg.judged, qPrintable(r.headingErrDeg.why + QLatin1Char('\n') + r.reasons.join(QLatin1Char('\n'))));
        QVERIFY2(std::fabs(r.headingErrDeg.value) < 0.3, qPrintable(QString::number(r.headingErrDeg.value)));
    }
};

IMUDESK_TEST_APPLESS_MAIN(TstModuleCheck)
#include "tst_module_check.moc"
