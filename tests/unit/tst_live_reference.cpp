// ImuDesk's live reference attitude (verify/live_reference.h, the 3D view's ghost): it waits
// for the module to rest, starts from the module's heading with the tilt of gravity, and then
// shows how far the module's attitude is from its own: near nothing for a good module, the
// tilt offset of one whose roll is off, a growing gap while a late filter is turned.
#include "../common/test_main.h"
#include "../common/verify_rig.h"
#include "verify/live_reference.h"

#include <QTest>

using namespace imudesk;

namespace {

Eigen::Quaterniond quatOf(const model::Sample &s)
{
    return Eigen::Quaterniond(s.quat.w, s.quat.x, s.quat.y, s.quat.z);
}

// Feeds the module's samples; the largest difference while still and while moving, after the start.
struct Run {
    bool started = false;
    double startS = -1, maxStill = 0, maxMoving = 0;
};

Run run(const test::HandTurnedModule &module)
{
    const sim::MotionModel motion(sim::MotionModel::Options{module.seed, sim::Motion::Poses});
    verify::LiveReference ref;
    Run r;
    for (const model::Sample &s : module.hi91Samples()) {
        ref.add(s);
        if (!ref.started())
            continue;
        if (r.startS < 0)
            r.startS = s.deviceTimeMs / 1000;
        const double d = ref.differenceDeg(quatOf(s));
        const double t = s.deviceTimeMs / 1000;
        if (motion.at(t).moving)
            r.maxMoving = std::max(r.maxMoving, d);
        else if (!motion.at(std::max(0.0, t - 0.2)).moving) // a late filter has caught up by then
            r.maxStill = std::max(r.maxStill, d);
    }
    r.started = ref.started();
    return r;
}

} // namespace

class TstLiveReference : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void goodModuleStaysClose()
    {
        test::HandTurnedModule module;
        module.seed = 91;
        const Run r = run(module);
        QVERIFY(r.started);
        QVERIFY2(r.startS >= 0.95 && r.startS < 2.0, qPrintable(QString::number(r.startS))); // after 1 s of rest
        QVERIFY2(r.maxStill < 0.3 && r.maxMoving < 0.5,
                 qPrintable(QStringLiteral("still %1°, moving %2°").arg(r.maxStill).arg(r.maxMoving)));
    }

    void rollOffsetShows()
    {
        test::HandTurnedModule module;
        module.seed = 92;
        module.attitudeBiasDeg = {2.0, 0, 0};
        const Run r = run(module);
        QVERIFY(r.started);
        // The reference takes gravity's tilt: the module's 2° of roll shows (at least at some pose).
        QVERIFY2(r.maxStill > 1.7 && r.maxStill < 2.5, qPrintable(QString::number(r.maxStill)));
    }

    void lateFilterShowsWhileMoving()
    {
        test::HandTurnedModule module;
        module.seed = 93;
        module.lagMs = 100;
        const Run r = run(module);
        QVERIFY(r.started);
        QVERIFY2(r.maxMoving > 10, qPrintable(QString::number(r.maxMoving)));
        QVERIFY2(r.maxStill < 0.5, qPrintable(QString::number(r.maxStill)));
    }

    void neverStillNeverStarts()
    {
        const sim::MotionModel motion(sim::MotionModel::Options{5, sim::Motion::Tumble});
        sim::SensorModel sensors(5);
        verify::LiveReference ref;
        for (int i = 0; i < 400 * 20; ++i) {
            model::Sample s;
            s.source = "HI91";
            s.deviceTimeMs = i * 2.5;
            const auto m = motion.at(i / 400.0);
            const auto reading = sensors.sample(m);
            s.acc = {reading.acc.x(), reading.acc.y(), reading.acc.z()};
            s.gyr = {reading.gyr.x(), reading.gyr.y(), reading.gyr.z()};
            s.quat = {m.q.w(), m.q.x(), m.q.y(), m.q.z()};
            s.fields = model::FieldAcc | model::FieldGyr | model::FieldQuat | model::FieldDeviceTime;
            ref.add(s);
        }
        QVERIFY(!ref.started());
    }
};

IMUDESK_TEST_APPLESS_MAIN(TstLiveReference)
#include "tst_live_reference.moc"
