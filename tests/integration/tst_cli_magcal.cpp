// imudesk-cli magcal as a process: CSV in, the fit's result out (text and --json) with the
// accuracy the data gives, exit codes (0 usable, 1 fail/refused or unreadable input, 2 usage).
#include "../common/cli_run.h"
#include "../common/test_main.h"

#include <Eigen/Geometry>

#include <QJsonArray>
#include <QJsonObject>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <random>

namespace {

using Run = imudesk::test::CliResult;

Run cli(const QStringList &args)
{
    return imudesk::test::runCli(args, 30000);
}

enum class Shape { Sphere, Planar, HalfSphere };

// Truth: hard iron (25, -18, 12) uT, soft iron diag (1.10, 0.92, 1.02) + off-diagonals, |B| 50 uT.
// HalfSphere: only the field directions with a positive body x (the module never turned its
// -X axis towards the field), 0.6 uT noise. (A missing -Z side would matter much less: the
// z offset it leaves uncertain does not turn the heading of a level module.)
QString writeCsv(const QTemporaryDir &dir, const QString &name, Shape shape, const QByteArray &header = "t,mag_x,mag_y,mag_z")
{
    const bool planar = shape == Shape::Planar;
    const double noise = shape == Shape::HalfSphere ? 0.6 : 0.3;
    Eigen::Matrix3d a;
    a << 1.10, 0.04, 0.03, 0.04, 0.92, 0.05, 0.03, 0.05, 1.02;
    const Eigen::Vector3d field(0, 25, -43.30127), b(25, -18, 12);
    std::mt19937_64 g(17);
    std::normal_distribution<double> n;
    QByteArray text = header + "\n";
    for (int i = 0; i < 300; ++i) {
        Eigen::Quaterniond q = planar ? Eigen::Quaterniond(Eigen::AngleAxisd(i * 0.021, Eigen::Vector3d::UnitZ()))
                                      : Eigen::Quaterniond(Eigen::Vector4d(n(g), n(g), n(g), n(g)).normalized());
        if (shape == Shape::HalfSphere && (q.toRotationMatrix().transpose() * field).x() < 0) {
            --i;
            continue;
        }
        const Eigen::Vector3d m = a * (q.toRotationMatrix().transpose() * field) + b + noise * Eigen::Vector3d(n(g), n(g), n(g));
        text += QByteArray::number(i) + "," + QByteArray::number(m.x(), 'f', 4) + "," + QByteArray::number(m.y(), 'f', 4) + ","
            + QByteArray::number(m.z(), 'f', 4) + "\n";
    }
    const QString path = dir.filePath(name);
    QFile f(path);
    f.open(QIODevice::WriteOnly);
    f.write(text);
    return path;
}

} // namespace

class TstCliMagcal : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void fullSphereJson()
    {
        QTemporaryDir dir;
        const Run r = cli({QStringLiteral("magcal"), writeCsv(dir, QStringLiteral("full.csv"), Shape::Sphere), QStringLiteral("--json")});
        QCOMPARE(r.code, 0);
        const QJsonObject o = r.json();
        QCOMPARE(o.value(QStringLiteral("verdict")).toString(), QStringLiteral("pass"));
        const QJsonArray hi = o.value(QStringLiteral("hard_iron")).toArray();
        QCOMPARE(hi.size(), 3);
        QVERIFY(std::fabs(hi.at(0).toDouble() - 25) < 0.3);
        QVERIFY(std::fabs(hi.at(1).toDouble() + 18) < 0.3);
        QVERIFY(std::fabs(hi.at(2).toDouble() - 12) < 0.3);
        const QJsonArray si = o.value(QStringLiteral("soft_iron")).toArray();
        QCOMPARE(si.size(), 3);
        QCOMPARE(si.at(0).toArray().size(), 3);
        QVERIFY(o.value(QStringLiteral("field_ut")).toDouble() > 45);
        QVERIFY(o.value(QStringLiteral("fit_error_pct")).toDouble() < 1.5);
        QVERIFY(o.value(QStringLiteral("coverage_pct")).toDouble() > 80);
        QVERIFY(!o.value(QStringLiteral("reason")).toString().isEmpty());
        // The accuracy the data gives: 300 samples, 0.3 uT noise, the whole sphere.
        const double predicted = o.value(QStringLiteral("predicted_heading_error_deg")).toDouble(-1);
        QVERIFY2(predicted > 0 && predicted < 0.5, qPrintable(QString::number(predicted)));
        const double predicted95 = o.value(QStringLiteral("predicted_heading_error_95_deg")).toDouble(-1);
        QVERIFY2(predicted95 >= predicted && predicted95 < 1.0, qPrintable(QString::number(predicted95)));
        const double hiSigma = o.value(QStringLiteral("hard_iron_sigma_ut")).toDouble(-1);
        QVERIFY2(hiSigma > 0 && hiSigma < 0.15, qPrintable(QString::number(hiSigma)));
        QVERIFY(o.value(QStringLiteral("soft_iron_sigma_pct")).toDouble(-1) > 0);
        // Text form, same numbers.
        const Run t = cli({QStringLiteral("magcal"), dir.filePath(QStringLiteral("full.csv"))});
        QCOMPARE(t.code, 0);
        QVERIFY(t.out.contains("verdict\tpass"));
        QVERIFY(t.out.contains("hard_iron_ut\t2")); // 25 +- 0.3
        QVERIFY(t.out.contains("predicted_heading_error_deg\t0."));
        QVERIFY(t.out.contains("predicted_heading_error_95_deg\t0."));
        QVERIFY(t.out.contains("hard_iron_sigma_ut\t0."));
        QVERIFY(t.out.contains("soft_iron_sigma_pct\t0."));
        // A steeper field leaves less horizontal field: a larger predicted heading error.
        const Run steep = cli({QStringLiteral("magcal"), dir.filePath(QStringLiteral("full.csv")), QStringLiteral("--json"),
                               QStringLiteral("--inclination"), QStringLiteral("75")});
        QVERIFY(steep.json().value(QStringLiteral("predicted_heading_error_deg")).toDouble()
                > 1.5 * predicted);
    }

    void halfSphereRefusedWithTheMissingRotation()
    {
        // Before this was judged by its coverage ("usable with care"); its accuracy refuses it.
        QTemporaryDir dir;
        const Run r = cli({QStringLiteral("magcal"), writeCsv(dir, QStringLiteral("half.csv"), Shape::HalfSphere),
                           QStringLiteral("--json")});
        QCOMPARE(r.code, 1);
        const QJsonObject o = r.json();
        QCOMPARE(o.value(QStringLiteral("verdict")).toString(), QStringLiteral("refused"));
        QVERIFY(o.value(QStringLiteral("predicted_heading_error_deg")).toDouble() > 1.0);
        const QString reason = o.value(QStringLiteral("reason")).toString();
        QVERIFY2(reason.contains(QStringLiteral("-X axis")), qPrintable(reason));
        QCOMPARE(o.value(QStringLiteral("hard_iron_only_offered")).toBool(), true);
    }

    void planarRefusedThenPlanarMode()
    {
        QTemporaryDir dir;
        const QString path = writeCsv(dir, QStringLiteral("planar.csv"), Shape::Planar);
        const Run r = cli({QStringLiteral("magcal"), path, QStringLiteral("--json")});
        QCOMPARE(r.code, 1);
        const QJsonObject o = r.json();
        QCOMPARE(o.value(QStringLiteral("verdict")).toString(), QStringLiteral("refused"));
        QCOMPARE(o.value(QStringLiteral("planar_offered")).toBool(), true);
        const Run p = cli({QStringLiteral("magcal"), path, QStringLiteral("--json"), QStringLiteral("--mode"), QStringLiteral("planar")});
        QCOMPARE(p.code, 0);
        QCOMPARE(p.json().value(QStringLiteral("mode")).toString(), QStringLiteral("planar"));
    }

    void errors_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("code");
        QTest::addColumn<QString>("message");
        QTest::newRow("no file") << QStringList{QStringLiteral("magcal")} << 2 << "exactly one FILE";
        QTest::newRow("missing file") << QStringList{QStringLiteral("magcal"), QStringLiteral("/nonexistent/x.csv")} << 1 << "cannot read";
        QTest::newRow("bad mode") << QStringList{QStringLiteral("magcal"), QStringLiteral("x.csv"), QStringLiteral("--mode"), QStringLiteral("round")} << 2 << "--mode";
        QTest::newRow("bad field") << QStringList{QStringLiteral("magcal"), QStringLiteral("x.csv"), QStringLiteral("--field"), QStringLiteral("-3")} << 2 << "--field";
        QTest::newRow("bad inclination") << QStringList{QStringLiteral("magcal"), QStringLiteral("x.csv"), QStringLiteral("--inclination"), QStringLiteral("90")} << 2 << "--inclination";
    }
    void errors()
    {
        QFETCH(QStringList, args);
        QFETCH(int, code);
        QFETCH(QString, message);
        const Run r = cli(args);
        QCOMPARE(r.code, code);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
    }

    void missingColumnsNamed()
    {
        QTemporaryDir dir;
        const Run r = cli({QStringLiteral("magcal"), writeCsv(dir, QStringLiteral("acc.csv"), Shape::Sphere, "t,acc_x,acc_y,acc_z")});
        QCOMPARE(r.code, 1);
        QVERIFY(r.err.contains("mag_x"));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCliMagcal)
#include "tst_cli_magcal.moc"
