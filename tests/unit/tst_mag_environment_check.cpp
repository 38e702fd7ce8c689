// The environment checks of the v1.7.1 manual's troubleshooting (9.31): |B| 20..60 uT
// (step 1), |B| varying by more than 10 uT between orientations means spatial
// interference (step 3).
#include "calib/mag_environment_check.h"
#include "../common/test_main.h"

#include <QTest>

using namespace imudesk::calib;
using Eigen::Vector3d;

class TstMagEnvironmentCheck : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void status_data()
    {
        QTest::addColumn<double>("base");
        QTest::addColumn<double>("variation");
        QTest::addColumn<int>("count");
        QTest::addColumn<int>("status");
        QTest::newRow("normal 50 uT") << 50.0 << 2.0 << 20 << int(MagEnvironmentCheck::Status::Ok);
        QTest::newRow("lower edge 20 uT") << 20.5 << 0.5 << 20 << int(MagEnvironmentCheck::Status::Ok);
        QTest::newRow("upper edge 60 uT") << 59.5 << 0.5 << 20 << int(MagEnvironmentCheck::Status::Ok);
        QTest::newRow("too weak 15 uT") << 15.0 << 1.0 << 20 << int(MagEnvironmentCheck::Status::FieldOutOfRange);
        QTest::newRow("too strong 75 uT") << 75.0 << 1.0 << 20 << int(MagEnvironmentCheck::Status::FieldOutOfRange);
        QTest::newRow("spread 12 uT") << 45.0 << 12.0 << 20 << int(MagEnvironmentCheck::Status::SpatialInterference);
        QTest::newRow("spread exactly 10 uT") << 45.0 << 10.0 << 20 << int(MagEnvironmentCheck::Status::Ok);
        QTest::newRow("not enough samples") << 50.0 << 0.0 << 5 << int(MagEnvironmentCheck::Status::NotEnoughData);
    }
    void status()
    {
        QFETCH(double, base);
        QFETCH(double, variation);
        QFETCH(int, count);
        QFETCH(int, status);
        MagEnvironmentCheck c;
        for (int i = 0; i < count; ++i) {
            // |B| from base - v/2 to base + v/2, in varying directions.
            const double b = base - variation / 2 + variation * i / std::max(1, count - 1);
            c.add(Vector3d(std::cos(i), std::sin(i), 0.3 * i).normalized() * b);
        }
        QCOMPARE(int(c.status()), status);
        QVERIFY(!c.advice().isEmpty());
        QVERIFY(std::fabs(c.spreadUt() - (count > 1 ? variation : 0)) < 1e-9);
        c.add(Vector3d(std::nan(""), 0, 0));
        QCOMPARE(c.count(), count);
        c.reset();
        QCOMPARE(c.count(), 0);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstMagEnvironmentCheck)
#include "tst_mag_environment_check.moc"
