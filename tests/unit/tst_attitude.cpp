// Attitude maths against the HiPNUC manual's appendix 1: the HI91 example frame, simple
// attitudes whose axes are known by hand, round trips on random quaternions for both
// Euler conventions, the ENU <-> NED conversion and the heading.
#include "model/attitude.h"
#include "sim/motion_model.h"
#include "sim/simulator_detail.h"
#include "../common/test_main.h"

#include <QTest>

#include <Eigen/Geometry>

#include <cmath>
#include <random>

using namespace imudesk::model;

namespace {

constexpr double kTolDeg = 1e-9;

Eigen::Quaterniond eig(const Quat &q)
{
    return Eigen::Quaterniond(q.w, q.x, q.y, q.z);
}

Quat axisAngle(double deg, double x, double y, double z)
{
    const Eigen::Quaterniond q(Eigen::AngleAxisd(deg * kDegToRad, Eigen::Vector3d(x, y, z).normalized()));
    return Quat{q.w(), q.x(), q.y(), q.z()};
}

bool near(double a, double b, double tol)
{
    return std::abs(a - b) <= tol;
}

bool nearVec(const Vec3 &a, const Vec3 &b, double tol = 1e-12)
{
    return near(a.x, b.x, tol) && near(a.y, b.y, tol) && near(a.z, b.z, tol);
}

// Difference of two angles in degrees, ignoring whole turns.
double angleDiff(double a, double b)
{
    return std::abs(wrap180(a - b));
}

Quat randomQuat(std::mt19937_64 &rng)
{
    std::normal_distribution<double> n(0.0, 1.0);
    return normalized(Quat{n(rng), n(rng), n(rng), n(rng)});
}

QByteArray describe(const Quat &q)
{
    return QByteArray("q=(") + QByteArray::number(q.w, 'g', 17) + ", " + QByteArray::number(q.x, 'g', 17) + ", "
        + QByteArray::number(q.y, 'g', 17) + ", " + QByteArray::number(q.z, 'g', 17) + ")";
}

QByteArray describe(const Euler &e)
{
    return QByteArray("roll ") + QByteArray::number(e.roll, 'g', 12) + " pitch " + QByteArray::number(e.pitch, 'g', 12)
        + " yaw " + QByteArray::number(e.yaw, 'g', 12);
}

} // namespace

class TestAttitude : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void hi91Example();
    void identity();
    void yaw90();
    void pitch90();
    void rollSign();
    void rotationMatrixMatchesEigen();
    void eulerToQuatMatchesComposition_data();
    void eulerToQuatMatchesComposition();
    void roundTripEnu312();
    void roundTripNed321();
    void gimbalLockStillSameRotation();
    void enuNedRoundTrip();
    void enuNedSamePhysicalAttitude();
    void nwuAgreesWithSimulator();
    void enuNedEulerRelation();
    void yaw30Heading();
    void heading_data();
    void heading();
    void normalisation();
    void wrapping();
    void agreesWithSimulator();
};

void TestAttitude::hi91Example()
{
    // Manual, HI91 example frame: quaternion and the Euler angles the frame reports.
    const Quat q{-0.485922, -0.14982, 0.0380868, 0.860223};
    const Euler e = eulerEnu312(q);
    QVERIFY2(near(e.roll, 13.0519, 1e-3), describe(e));
    QVERIFY2(near(e.pitch, 12.1885, 1e-3), describe(e));
    QVERIFY2(near(e.yaw, -122.477, 1e-3), describe(e));
    QVERIFY(near(headingDeg(q), 122.477, 1e-3));

    // The inverse lands on the same rotation (the frame's w is negative: q and -q).
    const Quat back = quatFromEnu312(e);
    QVERIFY2(angleBetweenDeg(back, q) < 1e-6, describe(back));
    QVERIFY(back.w >= 0);
    QVERIFY(near(std::abs(back.w), std::abs(q.w), 1e-6));

    // Same attitude as NED-321: roll and pitch agree, yaw is mirrored.
    const Euler n = eulerNed321(enuToNed(q));
    QVERIFY2(near(n.roll, 13.0519, 1e-3), describe(n));
    QVERIFY2(near(n.pitch, 12.1885, 1e-3), describe(n));
    QVERIFY2(near(n.yaw, 122.477, 1e-3), describe(n));
}

void TestAttitude::identity()
{
    const Quat q;
    QCOMPARE(eulerEnu312(q), Euler{});
    QCOMPARE(eulerNed321(q), Euler{});
    QCOMPARE(headingDeg(q), 0.0);
    const Matrix3 c = rotationMatrix(q);
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k)
            QCOMPARE(c[r][k], r == k ? 1.0 : 0.0);
    QCOMPARE(quatFromEnu312(Euler{}), Quat{});
    QCOMPARE(quatFromNed321(Euler{}), Quat{});
    // Flat module, forward to north: FRD->NED is the identity too.
    QVERIFY(angleBetweenDeg(enuToNed(q), Quat{}) < 1e-12);
    QVERIFY(angleBetweenDeg(nedToEnu(q), Quat{}) < 1e-12);
}

void TestAttitude::yaw90()
{
    // 90 deg about Up: counter-clockwise seen from above, the nose turns from north to west.
    const Quat q = axisAngle(90, 0, 0, 1);
    const Euler e = eulerEnu312(q);
    QVERIFY2(near(e.yaw, 90, kTolDeg) && near(e.pitch, 0, kTolDeg) && near(e.roll, 0, kTolDeg), describe(e));
    QVERIFY(nearVec(rotate(q, Vec3{1, 0, 0}), Vec3{0, 1, 0}));  // right -> north
    QVERIFY(nearVec(rotate(q, Vec3{0, 1, 0}), Vec3{-1, 0, 0})); // forward -> west
    QVERIFY(near(headingDeg(q), 270, kTolDeg));
    const Euler n = eulerNed321(enuToNed(q));
    QVERIFY2(near(n.yaw, -90, kTolDeg) && near(n.pitch, 0, kTolDeg) && near(n.roll, 0, kTolDeg), describe(n));
    QVERIFY(angleBetweenDeg(quatFromEnu312(Euler{0, 0, 90}), q) < 1e-12);
}

void TestAttitude::pitch90()
{
    // 90 deg about body x (right): the nose (body y) points up.
    const Quat q = axisAngle(90, 1, 0, 0);
    const Euler e = eulerEnu312(q);
    QVERIFY2(near(e.pitch, 90, 1e-6), describe(e));
    QVERIFY(nearVec(rotate(q, Vec3{0, 1, 0}), Vec3{0, 0, 1}));
    QVERIFY(nearVec(rotate(q, Vec3{0, 0, 1}), Vec3{0, -1, 0})); // top now faces south
    const Euler n = eulerNed321(enuToNed(q));
    QVERIFY2(near(n.pitch, 90, 1e-6), describe(n));
    const Quat back = quatFromEnu312(e);
    QVERIFY(angleBetweenDeg(back, q) < 1e-6);

    // Nose down is negative pitch in both conventions.
    const Quat down = axisAngle(-20, 1, 0, 0);
    QVERIFY(near(eulerEnu312(down).pitch, -20, kTolDeg));
    QVERIFY(near(eulerNed321(enuToNed(down)).pitch, -20, kTolDeg));
}

void TestAttitude::rollSign()
{
    // Positive roll about the forward axis: the right side goes down in both conventions.
    const Quat q = quatFromEnu312(Euler{30, 0, 0});
    const Vec3 right = rotate(q, Vec3{1, 0, 0});
    QVERIFY(right.z < -0.49 && right.z > -0.51);
    QVERIFY(near(eulerEnu312(q).roll, 30, kTolDeg));
    QVERIFY(near(eulerNed321(enuToNed(q)).roll, 30, kTolDeg));
    const Quat qn = quatFromNed321(Euler{30, 0, 0});
    const Vec3 rightNed = rotate(qn, Vec3{0, 1, 0}); // body y = right in FRD
    QVERIFY(near(rightNed.z, 0.5, 1e-12));            // NED z = down: right side down
}

void TestAttitude::rotationMatrixMatchesEigen()
{
    std::mt19937_64 rng(7);
    for (int i = 0; i < 500; ++i) {
        const Quat q = randomQuat(rng);
        const Matrix3 c = rotationMatrix(q);
        const Eigen::Matrix3d m = eig(q).toRotationMatrix();
        for (int r = 0; r < 3; ++r)
            for (int k = 0; k < 3; ++k)
                QVERIFY2(near(c[r][k], m(r, k), 1e-12), describe(q));
        // Columns are the body axes in navigation coordinates.
        const Vec3 y = rotate(q, Vec3{0, 1, 0});
        QVERIFY(nearVec(y, Vec3{c[0][1], c[1][1], c[2][1]}));
    }
    // An unnormalised quaternion gives the same matrix as the normalised one.
    const Matrix3 a = rotationMatrix(Quat{2, 0, 0, 2});
    const Matrix3 b = rotationMatrix(axisAngle(90, 0, 0, 1));
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k)
            QVERIFY(near(a[r][k], b[r][k], 1e-12));
}

void TestAttitude::eulerToQuatMatchesComposition_data()
{
    QTest::addColumn<double>("roll");
    QTest::addColumn<double>("pitch");
    QTest::addColumn<double>("yaw");
    QTest::newRow("zero") << 0.0 << 0.0 << 0.0;
    QTest::newRow("roll") << 25.0 << 0.0 << 0.0;
    QTest::newRow("pitch") << 0.0 << -40.0 << 0.0;
    QTest::newRow("yaw") << 0.0 << 0.0 << 135.0;
    QTest::newRow("mixed") << 13.0 << 12.0 << -122.0;
    QTest::newRow("large") << -170.0 << 80.0 << 179.0;
}

void TestAttitude::eulerToQuatMatchesComposition()
{
    QFETCH(double, roll);
    QFETCH(double, pitch);
    QFETCH(double, yaw);
    // ENU 3-1-2: Rz(yaw) * Rx(pitch) * Ry(roll).
    const Quat enu = multiply(multiply(axisAngle(yaw, 0, 0, 1), axisAngle(pitch, 1, 0, 0)), axisAngle(roll, 0, 1, 0));
    QVERIFY(angleBetweenDeg(quatFromEnu312(Euler{roll, pitch, yaw}), enu) < 1e-9);
    // NED 3-2-1: Rz(yaw) * Ry(pitch) * Rx(roll).
    const Quat ned = multiply(multiply(axisAngle(yaw, 0, 0, 1), axisAngle(pitch, 0, 1, 0)), axisAngle(roll, 1, 0, 0));
    QVERIFY(angleBetweenDeg(quatFromNed321(Euler{roll, pitch, yaw}), ned) < 1e-9);
}

void TestAttitude::roundTripEnu312()
{
    std::mt19937_64 rng(312);
    int tested = 0;
    for (int i = 0; i < 2000; ++i) {
        const Quat q = randomQuat(rng);
        const Euler e = eulerEnu312(q);
        if (std::abs(e.pitch) > 85)
            continue; // near gimbal lock: see gimbalLockStillSameRotation
        ++tested;
        const Quat back = quatFromEnu312(e);
        QVERIFY2(angleBetweenDeg(back, q) < 1e-9, describe(q));
        // Up to sign: the components match those of q or of -q.
        const double s = (back.w * q.w + back.x * q.x + back.y * q.y + back.z * q.z) < 0 ? -1.0 : 1.0;
        QVERIFY(near(back.w, s * q.w, 1e-12) && near(back.x, s * q.x, 1e-12) && near(back.y, s * q.y, 1e-12)
                && near(back.z, s * q.z, 1e-12));
        QVERIFY(back.w >= 0);
        const Euler e2 = eulerEnu312(back);
        QVERIFY2(angleDiff(e2.roll, e.roll) < 1e-8 && near(e2.pitch, e.pitch, 1e-8) && angleDiff(e2.yaw, e.yaw) < 1e-8,
                 describe(e));
        QVERIFY(e.roll >= -180 && e.roll <= 180 && e.yaw >= -180 && e.yaw <= 180);
    }
    QVERIFY(tested > 1500);
}

void TestAttitude::roundTripNed321()
{
    std::mt19937_64 rng(321);
    int tested = 0;
    for (int i = 0; i < 2000; ++i) {
        const Quat q = randomQuat(rng);
        const Euler e = eulerNed321(q);
        if (std::abs(e.pitch) > 85)
            continue;
        ++tested;
        const Quat back = quatFromNed321(e);
        QVERIFY2(angleBetweenDeg(back, q) < 1e-9, describe(q));
        const double s = (back.w * q.w + back.x * q.x + back.y * q.y + back.z * q.z) < 0 ? -1.0 : 1.0;
        QVERIFY(near(back.w, s * q.w, 1e-12) && near(back.x, s * q.x, 1e-12) && near(back.y, s * q.y, 1e-12)
                && near(back.z, s * q.z, 1e-12));
        const Euler e2 = eulerNed321(back);
        QVERIFY2(angleDiff(e2.roll, e.roll) < 1e-8 && near(e2.pitch, e.pitch, 1e-8) && angleDiff(e2.yaw, e.yaw) < 1e-8,
                 describe(e));
    }
    QVERIFY(tested > 1500);
}

void TestAttitude::gimbalLockStillSameRotation()
{
    // At pitch +-90 the split between roll and yaw is arbitrary but the rotation is kept.
    for (const double pitch : {90.0, -90.0, 89.999, -89.9999999, 89.99999999}) {
        const Quat enu = quatFromEnu312(Euler{20, pitch, 35});
        const Euler e = eulerEnu312(enu);
        QVERIFY(near(e.pitch, pitch, 1e-5));
        QVERIFY2(angleBetweenDeg(quatFromEnu312(e), enu) < 1e-5, describe(e));
        const Quat ned = quatFromNed321(Euler{20, pitch, 35});
        const Euler n = eulerNed321(ned);
        QVERIFY(near(n.pitch, pitch, 1e-5));
        QVERIFY2(angleBetweenDeg(quatFromNed321(n), ned) < 1e-5, describe(n));
        // The conversion keeps the relation between the conventions at lock too.
        const Euler m = eulerNed321(enuToNed(enu));
        QVERIFY2(angleBetweenDeg(quatFromNed321(m), enuToNed(enu)) < 1e-5, describe(m));
        QVERIFY2(angleDiff(m.yaw - m.roll * (pitch > 0 ? 1 : -1), -(e.yaw + e.roll * (pitch > 0 ? 1 : -1))) < 1e-4,
                 describe(e) + " / " + describe(m));
    }
    // Nose straight up from north: heading stays 0 (the nose's bearing before the pitch).
    QVERIFY(angleDiff(headingDeg(axisAngle(90, 1, 0, 0)), 0) < 1e-9);
    QVERIFY(angleDiff(headingDeg(quatFromEnu312(Euler{0, 90, -60})), 60) < 1e-9);
}

void TestAttitude::enuNedRoundTrip()
{
    std::mt19937_64 rng(42);
    for (int i = 0; i < 500; ++i) {
        const Quat q = randomQuat(rng);
        const Quat ned = enuToNed(q);
        QVERIFY(near(quatNorm(ned), 1, 1e-12));
        QVERIFY(near(std::abs(ned.w), std::abs(q.w), 1e-12)); // conjugation keeps the angle
        QVERIFY2(angleBetweenDeg(nedToEnu(ned), q) < 1e-9, describe(q));
        QVERIFY2(angleBetweenDeg(enuToNed(nedToEnu(q)), q) < 1e-9, describe(q));
    }
}

void TestAttitude::enuNedSamePhysicalAttitude()
{
    // Every body axis must point the same physical way in both descriptions.
    // ENU coords (e, n, u) <-> NED coords (n, e, -u); RFU body (r, f, u) <-> FRD body (f, r, -u).
    std::mt19937_64 rng(43);
    for (int i = 0; i < 200; ++i) {
        const Quat qe = randomQuat(rng);
        const Quat qn = enuToNed(qe);
        const Vec3 fwdEnu = rotate(qe, Vec3{0, 1, 0}), fwdNed = rotate(qn, Vec3{1, 0, 0});
        const Vec3 rightEnu = rotate(qe, Vec3{1, 0, 0}), rightNed = rotate(qn, Vec3{0, 1, 0});
        const Vec3 upEnu = rotate(qe, Vec3{0, 0, 1}), downNed = rotate(qn, Vec3{0, 0, 1});
        QVERIFY(nearVec(fwdNed, Vec3{fwdEnu.y, fwdEnu.x, -fwdEnu.z}));
        QVERIFY(nearVec(rightNed, Vec3{rightEnu.y, rightEnu.x, -rightEnu.z}));
        QVERIFY(nearVec(downNed, Vec3{-upEnu.y, -upEnu.x, upEnu.z}));
    }
}

void TestAttitude::enuNedEulerRelation()
{
    // Both sequences turn about (vertical, right, forward): roll and pitch agree, yaw flips.
    std::mt19937_64 rng(44);
    for (int i = 0; i < 1000; ++i) {
        const Quat q = randomQuat(rng);
        const Euler e = eulerEnu312(q);
        if (std::abs(e.pitch) > 85)
            continue;
        const Euler n = eulerNed321(enuToNed(q));
        QVERIFY2(angleDiff(n.roll, e.roll) < 1e-8, describe(e) + " / " + describe(n));
        QVERIFY2(near(n.pitch, e.pitch, 1e-8), describe(e) + " / " + describe(n));
        QVERIFY2(angleDiff(n.yaw, -e.yaw) < 1e-8, describe(e) + " / " + describe(n));
        QVERIFY(angleDiff(headingDeg(q), n.yaw) < 1e-8);
    }
}

void TestAttitude::yaw30Heading()
{
    // A pure 30 deg ENU yaw turns the nose 30 deg left of north (counter-clockwise seen from
    // above): heading 330, NED yaw -30.
    const Quat q = quatFromEnu312(Euler{0, 0, 30});
    QVERIFY(angleBetweenDeg(q, axisAngle(30, 0, 0, 1)) < 1e-12);
    QVERIFY2(near(headingDeg(q), 330, 1e-9), QByteArray::number(headingDeg(q)));
    const Vec3 fwd = rotate(q, Vec3{0, 1, 0});
    QVERIFY(fwd.x < 0 && fwd.y > 0); // west of north
    const Euler n = eulerNed321(enuToNed(q));
    QVERIFY2(near(n.yaw, -30, 1e-9) && near(n.roll, 0, 1e-9) && near(n.pitch, 0, 1e-9), describe(n));
    // And the other way: NED yaw +30 (clockwise) is heading 30, ENU yaw -30.
    const Quat qn = quatFromNed321(Euler{0, 0, 30});
    QVERIFY(near(headingDeg(nedToEnu(qn)), 30, 1e-9));
    QVERIFY(near(eulerEnu312(nedToEnu(qn)).yaw, -30, 1e-9));
}

void TestAttitude::heading_data()
{
    QTest::addColumn<double>("roll");
    QTest::addColumn<double>("pitch");
    QTest::addColumn<double>("yaw");
    QTest::addColumn<double>("heading");
    QTest::newRow("north") << 0.0 << 0.0 << 0.0 << 0.0;
    QTest::newRow("west") << 0.0 << 0.0 << 90.0 << 270.0;
    QTest::newRow("south") << 0.0 << 0.0 << 180.0 << 180.0;
    QTest::newRow("east") << 0.0 << 0.0 << -90.0 << 90.0;
    QTest::newRow("tilted east") << 40.0 << -30.0 << -90.0 << 90.0;
    QTest::newRow("rolled keeps heading") << 170.0 << 10.0 << -45.0 << 45.0;
}

void TestAttitude::heading()
{
    QFETCH(double, roll);
    QFETCH(double, pitch);
    QFETCH(double, yaw);
    QFETCH(double, heading);
    const double h = headingDeg(quatFromEnu312(Euler{roll, pitch, yaw}));
    QVERIFY2(angleDiff(h, heading) < 1e-9, QByteArray::number(h));
    QVERIFY(h >= 0 && h < 360);
}

void TestAttitude::normalisation()
{
    const Quat q{2, 0, 0, 2};
    const Quat n = normalized(q);
    QVERIFY(near(n.w, std::sqrt(0.5), 1e-15) && near(n.z, std::sqrt(0.5), 1e-15));
    QVERIFY(near(eulerEnu312(q).yaw, 90, kTolDeg));
    QCOMPARE(normalized(Quat{0, 0, 0, 0}), Quat{});
    QCOMPARE(normalized(Quat{std::nan(""), 0, 0, 1}), Quat{});
    QCOMPARE(normalized(Quat{INFINITY, 0, 0, 1}), Quat{});
    QVERIFY(!isUsableQuat(Quat{0, 0, 0, 0}));
    QVERIFY(isUsableQuat(Quat{0, 0, 0, 1}));
    const Quat c = canonical(Quat{-0.5, 0.5, -0.5, 0.5});
    QCOMPARE(c, (Quat{0.5, -0.5, 0.5, -0.5}));
    QVERIFY(angleBetweenDeg(Quat{-1, 0, 0, 0}, Quat{}) < 1e-12);
    QVERIFY(near(angleBetweenDeg(axisAngle(10, 1, 2, 3), axisAngle(-20, 1, 2, 3)), 30, 1e-9));
}

void TestAttitude::wrapping()
{
    QCOMPARE(wrap360(-30), 330.0);
    QCOMPARE(wrap360(360), 0.0);
    QCOMPARE(wrap360(725), 5.0);
    QCOMPARE(wrap360(-0.0), 0.0);
    QVERIFY(!std::signbit(wrap360(-0.0)));
    QVERIFY(wrap360(-1e-17) < 360.0);
    QCOMPARE(wrap180(190), -170.0);
    QCOMPARE(wrap180(180), -180.0);
    QCOMPARE(wrap180(-181), 179.0);
    QCOMPARE(wrap180(0), 0.0);
}

void TestAttitude::agreesWithSimulator()
{
    // The simulator's own ENU-312 helpers (core/sim/motion_model.h) use the same formulas.
    std::mt19937_64 rng(99);
    for (int i = 0; i < 300; ++i) {
        const Quat q = randomQuat(rng);
        const Euler e = eulerEnu312(q);
        if (std::abs(e.pitch) > 85)
            continue;
        const imudesk::sim::EulerAngles s = imudesk::sim::eulerEnu312(eig(q));
        QVERIFY(angleDiff(s.roll, e.roll) < 1e-9 && near(s.pitch, e.pitch, 1e-9) && angleDiff(s.yaw, e.yaw) < 1e-9);
        const Eigen::Quaterniond back = imudesk::sim::quatFromEnu312(imudesk::sim::EulerAngles{e.roll, e.pitch, e.yaw});
        QVERIFY(angleBetweenDeg(Quat{back.w(), back.x(), back.y(), back.z()}, quatFromEnu312(e)) < 1e-9);
    }
}

// v1.7.1 4.6.7.10 COORD 4: the simulator rotates its ENU attitude into NWU (N = ENU y,
// W = -ENU x); nwuToEnu undoes exactly that, enuToNwu is its inverse, and the module's
// forward axis (body y) at NWU identity points west: heading 270.
void TestAttitude::nwuAgreesWithSimulator()
{
    std::mt19937_64 rng(7);
    for (int i = 0; i < 300; ++i) {
        const Quat q = randomQuat(rng);
        const Eigen::Quaterniond simNwu = imudesk::sim::detail::enuToNwu() * eig(q);
        const Quat fromSim{simNwu.w(), simNwu.x(), simNwu.y(), simNwu.z()};
        QVERIFY2(angleBetweenDeg(nwuToEnu(fromSim), q) < 1e-9, describe(q));
        QVERIFY2(angleBetweenDeg(enuToNwu(q), fromSim) < 1e-9, describe(q));
    }
    QVERIFY(near(headingDeg(nwuToEnu(Quat{})), 270, 1e-9));
    // ENU yaw 35 is NWU yaw -55 (the same 3-1-2 formulas in the other frame).
    QVERIFY(near(eulerEnu312(enuToNwu(quatFromEnu312(Euler{0, 0, 35}))).yaw, -55, 1e-9));
}

IMUDESK_TEST_APPLESS_MAIN(TestAttitude)
#include "tst_attitude.moc"
