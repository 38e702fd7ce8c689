// The magnetometer calibration: fits against synthetic data with known truth, the
// coverage/planarity gates, verdicts, determinism and the JSON form.
// Truth as in calibration-notes.md §3 (|B| 50 uT, inclination 60, hard iron (25,-18,12)).
#include "calib/ellipse_fit.h"
#include "calib/ellipsoid_fit.h"
#include "calib/mag_calibrator.h"
#include "calib/sphere_coverage.h"

#include <Eigen/Geometry>

#include <QJsonDocument>
#include <QTest>

#include <cstring>
#include <random>

using namespace imudesk::calib;
using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;

namespace {

enum class Shape { Full, Hemisphere, Cap25, Planar, Few };

struct Truth {
    Vector3d field{0.0, 25.0, -43.30127018922193};
    Vector3d hardIron{25.0, -18.0, 12.0};
    Matrix3d a = (Matrix3d() << 1.10, 0.04, 0.03, 0.04, 0.92, 0.05, 0.03, 0.05, 1.02).finished();
};

std::vector<Vector3d> generate(Shape shape, uint64_t seed, double noise, double scale = 1.0, double spikes = 0)
{
    const Truth t;
    std::mt19937_64 g(seed);
    std::normal_distribution<double> n;
    std::uniform_real_distribution<double> u(0, 1);
    const int count = shape == Shape::Few ? 20 : 300;
    std::vector<Vector3d> out;
    const Vector3d axis = Vector3d(0.3, -0.5, 0.8).normalized();
    while (int(out.size()) < count) {
        Quaterniond q;
        if (shape == Shape::Planar) {
            q = Quaterniond(Eigen::AngleAxisd(u(g) * 2 * M_PI, Vector3d::UnitZ()));
        } else {
            q = Quaterniond(Eigen::Vector4d(n(g), n(g), n(g), n(g)).normalized());
            const double d = (q.toRotationMatrix().transpose() * t.field.normalized()).dot(axis);
            if ((shape == Shape::Hemisphere && d < 0) || (shape == Shape::Cap25 && d < 0.5))
                continue;
        }
        Vector3d m = scale * (t.a * (q.toRotationMatrix().transpose() * t.field)) + t.hardIron
            + noise * Vector3d(n(g), n(g), n(g));
        if (spikes > 0 && u(g) < spikes)
            m += Vector3d(20, 0, 0);
        out.push_back(m);
    }
    return out;
}

} // namespace

class TstMagCalibrator : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void verdicts_data()
    {
        QTest::addColumn<int>("shape");
        QTest::addColumn<int>("mode");
        QTest::addColumn<double>("noise");
        QTest::addColumn<double>("scale");
        QTest::addColumn<double>("spikes");
        QTest::addColumn<QString>("verdict");
        QTest::addColumn<double>("maxHardIronErr"); // < 0: not checked
        QTest::addColumn<bool>("hardIronOffered");
        QTest::addColumn<bool>("planarOffered");
        const int full = int(MagCalMode::Full3D), hi = int(MagCalMode::HardIronOnly), planar = int(MagCalMode::Planar2D);
        QTest::newRow("full sphere passes") << int(Shape::Full) << full << 0.3 << 1.0 << 0.0 << "pass" << 0.15 << false << false;
        QTest::newRow("3 % spikes still pass") << int(Shape::Full) << full << 0.3 << 1.0 << 0.03 << "pass" << 0.2 << false << false;
        QTest::newRow("10 % spikes: fit holds, warns") << int(Shape::Full) << full << 0.3 << 1.0 << 0.10 << "warn" << 0.3 << false << false;
        QTest::newRow("hemisphere warns on coverage") << int(Shape::Hemisphere) << full << 0.3 << 1.0 << 0.0 << "warn" << 0.8 << false << false;
        QTest::newRow("25 % cap refused, hard iron offered") << int(Shape::Cap25) << full << 0.3 << 1.0 << 0.0 << "refused" << -1.0 << true << false;
        QTest::newRow("planar refused, 2-D offered") << int(Shape::Planar) << full << 0.3 << 1.0 << 0.0 << "refused" << -1.0 << false << true;
        QTest::newRow("too few samples refused") << int(Shape::Few) << full << 0.3 << 1.0 << 0.0 << "refused" << -1.0 << true << false;
        QTest::newRow("planar 2-D fit: level only") << int(Shape::Planar) << planar << 0.3 << 1.0 << 0.0 << "warn" << -1.0 << false << false;
        QTest::newRow("noisy data fails") << int(Shape::Full) << full << 4.0 << 1.0 << 0.0 << "fail" << -1.0 << false << false;
        QTest::newRow("weak field warns (15 uT... x0.36)") << int(Shape::Full) << full << 0.05 << 0.36 << 0.0 << "warn" << 0.2 << false << false;
        QTest::newRow("field of 5 uT fails") << int(Shape::Full) << full << 0.02 << 0.1 << 0.0 << "fail" << -1.0 << false << false;
        QTest::newRow("hard iron only on a cap") << int(Shape::Cap25) << hi << 0.3 << 1.0 << 0.0 << "warn" << -1.0 << false << false;
    }
    void verdicts()
    {
        QFETCH(int, shape);
        QFETCH(int, mode);
        QFETCH(double, noise);
        QFETCH(double, scale);
        QFETCH(double, spikes);
        QFETCH(QString, verdict);
        QFETCH(double, maxHardIronErr);
        QFETCH(bool, hardIronOffered);
        QFETCH(bool, planarOffered);
        const auto samples = generate(Shape(shape), 7, noise, scale, spikes);
        const MagCalResult r = MagCalibrator().calibrate(samples, MagCalMode(mode));
        QCOMPARE(QString::fromLatin1(verdictName(r.verdict)), verdict);
        QVERIFY2(!r.reason.isEmpty(), "every verdict says why");
        QCOMPARE(r.hardIronOnlyOffered, hardIronOffered);
        QCOMPARE(r.planarOffered, planarOffered);
        QCOMPARE(r.samples, int(samples.size()));
        if (maxHardIronErr >= 0)
            QVERIFY2((r.hardIron - Truth().hardIron).norm() <= maxHardIronErr,
                     qPrintable(QStringLiteral("hard iron error %1").arg((r.hardIron - Truth().hardIron).norm())));
    }

    void fullFitRecoversTruthWithoutNoise()
    {
        const auto samples = generate(Shape::Full, 3, 0.0);
        const MagCalResult r = MagCalibrator().calibrate(samples);
        QCOMPARE(r.verdict, MagVerdict::Pass);
        QVERIFY((r.hardIron - Truth().hardIron).norm() < 1e-6);
        const Matrix3d m = r.softIron * Truth().a;
        QVERIFY((m / std::cbrt(m.determinant()) - Matrix3d::Identity()).norm() < 1e-6);
        QVERIFY(std::fabs(r.fieldUt - 50.0 * std::cbrt(Truth().a.determinant())) < 1e-6);
        QVERIFY(r.fitErrorPct < 1e-6);
        QVERIFY(r.coveragePct > 90);
        QVERIFY(r.eigenRatio < 3);
        // The soft iron is symmetric with determinant 1.
        QVERIFY((r.softIron - r.softIron.transpose()).norm() < 1e-12);
        QVERIFY(std::fabs(r.softIron.determinant() - 1.0) < 1e-9);
    }

    void fitErrorMatchesNoise()
    {
        // Fit error floor = sigma / |B| * 100 (notes §3): 0.3 uT per axis on ~50 uT -> ~0.6 %.
        const MagCalResult r = MagCalibrator().calibrate(generate(Shape::Full, 11, 0.3));
        QVERIFY2(r.fitErrorPct > 0.45 && r.fitErrorPct < 0.8, qPrintable(QString::number(r.fitErrorPct)));
        QVERIFY(std::fabs(r.residualRmsUt / r.fieldUt * 100 - r.fitErrorPct) < 1e-9);
    }

    void deterministic()
    {
        const auto samples = generate(Shape::Full, 5, 0.3, 1.0, 0.03);
        const MagCalResult a = MagCalibrator().calibrate(samples);
        const MagCalResult b = MagCalibrator().calibrate(samples);
        QVERIFY(std::memcmp(a.hardIron.data(), b.hardIron.data(), sizeof(double) * 3) == 0);
        QVERIFY(std::memcmp(a.softIron.data(), b.softIron.data(), sizeof(double) * 9) == 0);
        QVERIFY(std::memcmp(&a.fitErrorPct, &b.fitErrorPct, sizeof(double)) == 0);
    }

    void nonFiniteSamplesAreIgnored()
    {
        auto samples = generate(Shape::Full, 9, 0.3);
        const MagCalResult clean = MagCalibrator().calibrate(samples);
        samples.push_back(Vector3d(std::nan(""), 1, 2));
        samples.push_back(Vector3d(1, std::numeric_limits<double>::infinity(), 2));
        const MagCalResult r = MagCalibrator().calibrate(samples);
        QCOMPARE(r.verdict, clean.verdict);
        QVERIFY((r.hardIron - clean.hardIron).norm() < 1e-12);
    }

    void planarFitWithVerticalReference()
    {
        MagCalibrator::Options o;
        const Truth t;
        o.levelVerticalUt = t.field.z(); // the world model's vertical component
        const MagCalResult r = MagCalibrator(o).calibrate(generate(Shape::Planar, 4, 0.0), MagCalMode::Planar2D);
        QCOMPARE(r.mode, MagCalMode::Planar2D);
        QVERIFY(r.zOffsetKnown);
        // The 2-D offset absorbs the z cross terms: b_xy + A[0..1][2] * Z at level.
        const Eigen::Vector2d expected = t.hardIron.head<2>() + t.a.block<2, 1>(0, 2) * t.field.z();
        QVERIFY((r.hardIron.head<2>() - expected).norm() < 1e-6);
        // b_z = mean(mz) - Z: the unobservable z scale (A[2][2] - 1) * Z stays in it, and the
        // A[2][0..1] terms average out only roughly over random headings.
        QVERIFY(std::fabs(r.hardIron.z() - (t.hardIron.z() + (t.a(2, 2) - 1) * t.field.z())) < 0.2);
        QVERIFY(r.coveragePct > 90);
    }

    void jsonRoundTrip()
    {
        const MagCalResult r = MagCalibrator().calibrate(generate(Shape::Full, 2, 0.3));
        const QJsonObject o = r.toJson();
        for (const char *key : {"hard_iron", "soft_iron", "field_ut", "fit_error_pct", "coverage_pct", "verdict", "reason"})
            QVERIFY2(o.contains(QLatin1String(key)), key);
        MagCalResult back;
        QVERIFY(MagCalResult::fromJson(QJsonDocument::fromJson(QJsonDocument(o).toJson()).object(), back));
        QCOMPARE(back.verdict, r.verdict);
        QCOMPARE(back.reason, r.reason);
        QVERIFY((back.hardIron - r.hardIron).norm() < 1e-12);
        QVERIFY((back.softIron - r.softIron).norm() < 1e-12);
        QVERIFY(!MagCalResult::fromJson(QJsonObject(), back));
    }

    void geodesicGrid()
    {
        const auto &cells = SphereCoverage::cells();
        // 80 distinct cells that tile the sphere: every centre falls in its own cell.
        for (int i = 0; i < SphereCoverage::kCells; ++i) {
            QCOMPARE(SphereCoverage::cellOf(cells[size_t(i)].centre), i);
            QVERIFY(std::fabs(cells[size_t(i)].centre.norm() - 1) < 1e-12);
        }
        QCOMPARE(SphereCoverage::cellOf(Vector3d::Zero()), -1);
        SphereCoverage c;
        QCOMPARE(c.percent(), 0.0);
        QVERIFY(!c.missingRotationHint().isEmpty());
        // Only the upper hemisphere: the missing direction points down.
        for (const auto &cell : cells)
            if (cell.centre.z() > 0.2)
                c.add(cell.centre * 3.0);
        QVERIFY(c.percent() > 20 && c.percent() < 60);
        QVERIFY(c.missingDirection().z() < -0.9);
        QVERIFY(c.missingRotationHint().contains(QStringLiteral("-Z")));
        // The hole is the lower hemisphere less a band: its radius is well over 45 degrees.
        QVERIFY2(c.largestGapDeg() > 45 && c.largestGapDeg() < 110, QByteArray::number(c.largestGapDeg()));
        for (const auto &cell : cells)
            c.add(cell.centre);
        QCOMPARE(c.percent(), 100.0);
        QVERIFY(c.missingRotationHint().isEmpty());
        QCOMPARE(c.largestGapDeg(), 0.0);
        // One empty cell: a hole of about a cell's spacing; none covered: the whole sphere.
        SphereCoverage one;
        for (int i = 1; i < SphereCoverage::kCells; ++i)
            one.add(cells[size_t(i)].centre);
        QVERIFY2(one.largestGapDeg() > 10 && one.largestGapDeg() < 35, QByteArray::number(one.largestGapDeg()));
        QCOMPARE(SphereCoverage().largestGapDeg(), 180.0);
    }

    void ellipseFitExact()
    {
        std::vector<Eigen::Vector2d> pts;
        Eigen::Matrix2d a;
        a << 1.2, 0.1, 0.1, 0.8;
        for (int i = 0; i < 36; ++i)
            pts.push_back(a * Eigen::Vector2d(std::cos(i * 0.17453), std::sin(i * 0.17453)) * 20 + Eigen::Vector2d(5, -7));
        const auto e = EllipseFit::fit(pts);
        QVERIFY(e.has_value());
        QVERIFY((e->center - Eigen::Vector2d(5, -7)).norm() < 1e-9);
        for (const auto &p : pts)
            QVERIFY(std::fabs((e->w * (p - e->center)).norm() - 1) < 1e-9);
        QVERIFY(!EllipseFit::fit({pts.begin(), pts.begin() + 3}).has_value());
    }

    void liRejectsDegenerateData()
    {
        std::vector<Vector3d> line;
        for (int i = 0; i < 50; ++i)
            line.emplace_back(i, 2 * i, 3 * i);
        QVERIFY(!EllipsoidFit::algebraicLi(line).has_value());
        QVERIFY(!EllipsoidFit::algebraicLi({}).has_value());
        const MagCalResult r = MagCalibrator().calibrate(line);
        QCOMPARE(r.verdict, MagVerdict::Refused);
    }
};

QTEST_GUILESS_MAIN(TstMagCalibrator)
#include "tst_mag_calibrator.moc"
