// imudesk-cli magcal as a process: CSV in, the fit's result out (text and --json), exit
// codes (0 usable, 1 fail/refused or unreadable input, 2 usage).
#include <Eigen/Geometry>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <random>

namespace {

struct Run {
    int code = -1;
    QByteArray out, err;
};

Run cli(const QStringList &args)
{
    QProcess p;
    p.start(QStringLiteral(IMUDESK_CLI_PATH), args);
    p.waitForFinished(30000);
    return {p.exitCode(), p.readAllStandardOutput(), p.readAllStandardError()};
}

// Truth: hard iron (25, -18, 12) uT, soft iron diag (1.10, 0.92, 1.02) + off-diagonals, |B| 50 uT.
QString writeCsv(const QTemporaryDir &dir, const QString &name, bool planar, const QByteArray &header = "t,mag_x,mag_y,mag_z")
{
    Eigen::Matrix3d a;
    a << 1.10, 0.04, 0.03, 0.04, 0.92, 0.05, 0.03, 0.05, 1.02;
    const Eigen::Vector3d field(0, 25, -43.30127), b(25, -18, 12);
    std::mt19937_64 g(17);
    std::normal_distribution<double> n;
    QByteArray text = header + "\n";
    for (int i = 0; i < 300; ++i) {
        Eigen::Quaterniond q = planar ? Eigen::Quaterniond(Eigen::AngleAxisd(i * 0.021, Eigen::Vector3d::UnitZ()))
                                      : Eigen::Quaterniond(Eigen::Vector4d(n(g), n(g), n(g), n(g)).normalized());
        const Eigen::Vector3d m = a * (q.toRotationMatrix().transpose() * field) + b + 0.3 * Eigen::Vector3d(n(g), n(g), n(g));
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
        const Run r = cli({QStringLiteral("magcal"), writeCsv(dir, QStringLiteral("full.csv"), false), QStringLiteral("--json")});
        QCOMPARE(r.code, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
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
        // Text form, same numbers.
        const Run t = cli({QStringLiteral("magcal"), dir.filePath(QStringLiteral("full.csv"))});
        QCOMPARE(t.code, 0);
        QVERIFY(t.out.contains("verdict\tpass"));
        QVERIFY(t.out.contains("hard_iron_ut\t2")); // 25 +- 0.3
    }

    void planarRefusedThenPlanarMode()
    {
        QTemporaryDir dir;
        const QString path = writeCsv(dir, QStringLiteral("planar.csv"), true);
        const Run r = cli({QStringLiteral("magcal"), path, QStringLiteral("--json")});
        QCOMPARE(r.code, 1);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o.value(QStringLiteral("verdict")).toString(), QStringLiteral("refused"));
        QCOMPARE(o.value(QStringLiteral("planar_offered")).toBool(), true);
        const Run p = cli({QStringLiteral("magcal"), path, QStringLiteral("--json"), QStringLiteral("--mode"), QStringLiteral("planar")});
        QCOMPARE(p.code, 0);
        QCOMPARE(QJsonDocument::fromJson(p.out).object().value(QStringLiteral("mode")).toString(), QStringLiteral("planar"));
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
    }
    void errors()
    {
        QFETCH(QStringList, args);
        QFETCH(int, code);
        QFETCH(QString, message);
        const Run r = cli(args);
        QCOMPARE(r.code, code);
        QVERIFY2(QString::fromUtf8(r.err).contains(message), r.err.constData());
    }

    void missingColumnsNamed()
    {
        QTemporaryDir dir;
        const Run r = cli({QStringLiteral("magcal"), writeCsv(dir, QStringLiteral("acc.csv"), false, "t,acc_x,acc_y,acc_z")});
        QCOMPARE(r.code, 1);
        QVERIFY(r.err.contains("mag_x"));
    }
};

QTEST_GUILESS_MAIN(TstCliMagcal)
#include "tst_cli_magcal.moc"
