// imudesk-cli magcal as a process: CSV in, the fit's result out (text and --json) with the
// accuracy the data gives, exit codes (0 usable, 1 fail/refused or unreadable input, 2 usage).
#include "../common/cli_run.h"
#include "../common/test_main.h"
#include "record/capture_exporter.h"
#include "record/capture_source.h"
#include "record/session_manifest.h"
#include "decode/hipnuc_vendor_csv.h"

#include <Eigen/Geometry>

#include <QJsonArray>
#include <QJsonObject>
#include <QDir>
#include <QFile>
#include <QJsonDocument>
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

// The same field as Shape::Sphere (truth above), as the module's HI91 frames in the vendor's
// CSV layout: the frame tag HI91 in a column named HI91, pc_counter from 5000 ms.
QString writeVendorCsv(const QTemporaryDir &dir, const QString &name, int rows = 300)
{
    Eigen::Matrix3d a;
    a << 1.10, 0.04, 0.03, 0.04, 0.92, 0.05, 0.03, 0.05, 1.02;
    const Eigen::Vector3d field(0, 25, -43.30127), b(25, -18, 12);
    std::mt19937_64 g(17);
    std::normal_distribution<double> n;
    std::string text = imudesk::decode::vendor_csv::hi91Header();
    text += '\n';
    for (int i = 0; i < rows; ++i) {
        const Eigen::Quaterniond q(Eigen::Vector4d(n(g), n(g), n(g), n(g)).normalized());
        const Eigen::Vector3d m = a * (q.toRotationMatrix().transpose() * field) + b + 0.3 * Eigen::Vector3d(n(g), n(g), n(g));
        imudesk::protocol::hipnuc::Hi91 h;
        h.temperature = 25;
        h.pressure = 101325;
        h.systemTime = uint32_t(1000 + 10 * i);
        h.acc = {0.01f, -0.02f, 1.0f};
        h.gyr = {0.1f, -0.1f, 0.05f};
        h.mag = {float(m.x()), float(m.y()), float(m.z())};
        imudesk::decode::vendor_csv::appendRow(text, h, 5000.0 + 10 * i);
    }
    const QString path = dir.filePath(name);
    QFile f(path);
    f.open(QIODevice::WriteOnly);
    f.write(text.data(), qint64(text.size()));
    return path;
}

QString writeText(const QTemporaryDir &dir, const QString &name, const QByteArray &text)
{
    const QString path = dir.filePath(name);
    QFile f(path);
    f.open(QIODevice::WriteOnly);
    f.write(text);
    return path;
}

// A session export's tidy CSV: a device column first, two devices interleaved; B's rows are the
// vendor CSV's field (as tidy columns, with empty cells elsewhere), A's a constant field.
QString writeSessionCsv(const QTemporaryDir &dir, const QString &tidyPath)
{
    QFile in(tidyPath);
    in.open(QIODevice::ReadOnly);
    const QList<QByteArray> lines = in.readAll().split('\n');
    QByteArray text = "device," + lines.at(0) + "\n";
    const int cells = int(lines.at(0).count(',')) + 1;
    const int magX = int(lines.at(0).split(',').indexOf("mag_x_uT"));
    for (int i = 1; i < lines.size(); ++i) {
        if (lines.at(i).isEmpty())
            continue;
        QList<QByteArray> other(cells);
        other[magX] = "10";
        other[magX + 1] = "20";
        other[magX + 2] = "30";
        text += "A," + other.join(',') + "\n";
        text += "B," + lines.at(i) + "\n";
    }
    return writeText(dir, QStringLiteral("session.csv"), text);
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

    // Issue 53: every file ImuDesk writes or imports that carries a magnetometer, with only the
    // columns it needs read (the vendor CSV's frame tag and the tidy CSV's empty cells were
    // refused as "not a number"; captures and sessions were not taken at all).
    void everyFileImuDeskWrites_data()
    {
        QTest::addColumn<QString>("what");
        QTest::addColumn<QString>("device");
        QTest::addColumn<QString>("kind"); // as the CLI reports what it read
        QTest::newRow("vendor CSV") << QStringLiteral("vendor") << QString() << QStringLiteral("CSV");
        QTest::newRow("capture (imported vendor CSV)") << QStringLiteral("capture") << QString() << QStringLiteral("capture");
        QTest::newRow("tidy CSV export") << QStringLiteral("tidy") << QString() << QStringLiteral("CSV");
        QTest::newRow("JSON Lines export") << QStringLiteral("jsonl") << QString() << QStringLiteral("JSON Lines");
        QTest::newRow("vendor CSV export") << QStringLiteral("vendor-export") << QString() << QStringLiteral("CSV");
        QTest::newRow("recorded session, one device") << QStringLiteral("session1") << QString() << QStringLiteral("session");
        QTest::newRow("recorded session, --device B") << QStringLiteral("session2") << QStringLiteral("B") << QStringLiteral("session");
        QTest::newRow("a session's member capture") << QStringLiteral("member") << QString() << QStringLiteral("capture");
        QTest::newRow("session export CSV, --device B") << QStringLiteral("session-csv") << QStringLiteral("B") << QStringLiteral("CSV");
    }
    void everyFileImuDeskWrites()
    {
        QFETCH(QString, what);
        QFETCH(QString, device);
        QFETCH(QString, kind);
        using namespace imudesk::record;
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString vendor = writeVendorCsv(dir, QStringLiteral("vendor.csv"));
        const QString capture = dir.filePath(QStringLiteral("run.imucap"));
        const auto converted = CaptureSource::convert(vendor, capture);
        QVERIFY2(converted.ok, qPrintable(converted.error));
        auto exported = [&](CaptureExporter::Format format, const QString &name) {
            CaptureExporter::Options o;
            o.format = format;
            o.output = dir.filePath(name);
            const auto r = CaptureExporter::run(capture, o);
            return r.ok ? o.output : QString();
        };
        auto session = [&](const QString &folder, const QStringList &names) {
            SessionManifest m;
            for (const QString &n : names) {
                SessionManifest::Device d;
                d.name = n;
                d.file = n + QStringLiteral(".imucap");
                d.linkKind = QStringLiteral("HiPNUC serial");
                QDir().mkpath(dir.filePath(folder));
                QFile::copy(capture, QDir(dir.filePath(folder)).filePath(d.file));
                m.devices.push_back(d);
            }
            QString error;
            return m.save(dir.filePath(folder), &error) ? dir.filePath(folder) : QString();
        };
        QString path;
        if (what == QLatin1String("vendor"))
            path = vendor;
        else if (what == QLatin1String("capture"))
            path = capture;
        else if (what == QLatin1String("tidy"))
            path = exported(CaptureExporter::Format::TidyCsv, QStringLiteral("tidy.csv"));
        else if (what == QLatin1String("jsonl"))
            path = exported(CaptureExporter::Format::JsonLines, QStringLiteral("run.jsonl"));
        else if (what == QLatin1String("vendor-export"))
            path = exported(CaptureExporter::Format::VendorCsv, QStringLiteral("again.csv"));
        else if (what == QLatin1String("session1"))
            path = session(QStringLiteral("s1"), {QStringLiteral("A")});
        else if (what == QLatin1String("session2"))
            path = session(QStringLiteral("s2"), {QStringLiteral("A"), QStringLiteral("B")});
        else if (what == QLatin1String("member"))
            path = QDir(session(QStringLiteral("s3"), {QStringLiteral("A"), QStringLiteral("B")})).filePath(QStringLiteral("B.imucap"));
        else if (what == QLatin1String("session-csv"))
            path = writeSessionCsv(dir, exported(CaptureExporter::Format::TidyCsv, QStringLiteral("tidy.csv")));
        QVERIFY2(!path.isEmpty(), qPrintable(what));

        QStringList args{QStringLiteral("magcal"), path, QStringLiteral("--json")};
        if (!device.isEmpty())
            args << QStringLiteral("--device") << device;
        const Run r = cli(args);
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral(": %1").arg(kind)) && r.err.contains(QStringLiteral("300 magnetometer samples")),
                 qPrintable(r.err));
        const QJsonObject o = r.json();
        QCOMPARE(o.value(QStringLiteral("verdict")).toString(), QStringLiteral("pass"));
        QCOMPARE(o.value(QStringLiteral("samples")).toInt(), 300);
        const QJsonArray hi = o.value(QStringLiteral("hard_iron")).toArray();
        QVERIFY2(std::fabs(hi.at(0).toDouble() - 25) < 0.3 && std::fabs(hi.at(1).toDouble() + 18) < 0.3
                     && std::fabs(hi.at(2).toDouble() - 12) < 0.3,
                 qPrintable(QJsonDocument(hi).toJson(QJsonDocument::Compact)));
    }

    // What is still refused, with the line and the column (or what to do) named.
    void unreadableMagnetometer_data()
    {
        QTest::addColumn<QByteArray>("text"); // empty: a two-device session without --device
        QTest::addColumn<QString>("message");
        QTest::newRow("vendor CSV, a bad mag_y") << QByteArray("HI91,pc_counter,mag_x,mag_y,mag_z\nHI91,0,1,2,3\nHI91,10,1,x,3\n")
                                                << QStringLiteral("line 3, column mag_y: 'x' is not a number");
        QTest::newRow("tidy CSV, one mag cell empty")
            << QByteArray("time_s,frame_tag,mag_x_uT,mag_y_uT,mag_z_uT,lat_deg\n0,145,1,2,3,\n0.01,145,1,,3,\n")
            << QStringLiteral("line 3, column mag_y_uT: '' is not a number");
        QTest::newRow("no magnetometer column") << QByteArray("HI91,pc_counter,acc_x,acc_y,acc_z\nHI91,0,1,2,3\n")
                                               << QStringLiteral("line 1: the column mag_x or mag_x_uT is missing");
        QTest::newRow("JSON Lines, mag not three numbers") << QByteArray("{\"type\":\"HI91\",\"mag\":[1,2]}\n")
                                                          << QStringLiteral("line 1, key mag");
        QTest::newRow("session export without --device") << QByteArray("device,mag_x_uT,mag_y_uT,mag_z_uT\nA,1,2,3\nB,1,2,3\n")
                                                        << QStringLiteral("--device NAME");
    }
    void unreadableMagnetometer()
    {
        QFETCH(QByteArray, text);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const Run r = cli({QStringLiteral("magcal"), writeText(dir, QStringLiteral("in.txt"), text)});
        QCOMPARE(r.code, 1);
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
