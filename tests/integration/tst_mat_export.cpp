// MATLAB .mat export (issue 37 point 4, record/mat_export.h over format/mat/mat_file.h) read back
// by an independent reader, Debian's scipy.io.loadmat (tests/mat/compare_mat.py): a capture of
// mixed frames, every column of every field equal to the tidy CSV export of the same capture
// (SI units: m/s^2, rad/s, T, rad), NaN exactly where a frame lacks the quantity, units,
// column names and the device's identity beside them; a recorded session as one file with a
// struct per device; the CLI; an output that cannot be written.
#include "record/capture_exporter.h"
#include "record/session_exporter.h"
#include "record/session_manifest.h"
#include "../common/cli_run.h"
#include "../common/synthetic_capture.h"
#include "../common/synthetic_session.h"
#include "../common/test_main.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace imudesk;

namespace {

QString python()
{
    // Debian's interpreter, with its python3-scipy (another python3 earlier on PATH may lack it).
    return QFile::exists(QStringLiteral("/usr/bin/python3")) ? QStringLiteral("/usr/bin/python3") : QStringLiteral("python3");
}

QString script()
{
    return QDir::cleanPath(QString::fromUtf8(IMUDESK_TEST_DATA) + QStringLiteral("/../mat/compare_mat.py"));
}

QJsonObject compare(const QString &mat, const QString &variable, const QString &csv, QString *error)
{
    QProcess p;
    p.start(python(), {script(), mat, variable, csv});
    if (!p.waitForFinished(120000)) {
        *error = QStringLiteral("the reader did not finish: %1").arg(p.errorString());
        return {};
    }
    const QByteArray out = p.readAllStandardOutput();
    const QJsonObject o = QJsonDocument::fromJson(out).object();
    if (p.exitCode() != 0 || o.isEmpty() || o.contains(QStringLiteral("error")))
        *error = QString::fromUtf8(out + p.readAllStandardError());
    return o;
}

// Every field within float precision (times: the CSV's 6 decimals) and NaN where the CSV is empty.
void verifyAgainstCsv(const QJsonObject &r, int rows)
{
    QCOMPARE(r.value(QStringLiteral("rows")).toInt(), rows);
    const QJsonObject err = r.value(QStringLiteral("max_rel_error")).toObject();
    const QJsonObject nan = r.value(QStringLiteral("nan_mismatch")).toObject();
    QCOMPARE(err.size(), 13);
    for (auto it = err.begin(); it != err.end(); ++it) {
        QVERIFY2(!it.value().isNull(), qPrintable(it.key() + QStringLiteral(": shape differs")));
        const double limit = it.key().startsWith(QLatin1String("time")) ? 6e-7 : 2e-7;
        QVERIFY2(it.value().toDouble() <= limit, qPrintable(QStringLiteral("%1: %2").arg(it.key()).arg(it.value().toDouble())));
        QCOMPARE(nan.value(it.key()).toInt(), 0);
    }
}

} // namespace

class TstMatExport : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_capture, m_csv;

private Q_SLOTS:
    void initTestCase()
    {
        synthetic::CaptureSpec spec;
        spec.frames = 3000;
        spec.mixed = true; // HI81 (a GNSS position) and HI83 beside HI91, and NMEA
        spec.serial = "SN-0042/a";
        m_capture = m_dir.filePath(QStringLiteral("run.imucap"));
        QVERIFY(synthetic::writeCapture(m_capture, spec) > 0);
        record::CaptureExporter::Options o;
        o.format = record::CaptureExporter::Format::TidyCsv;
        o.output = m_csv = m_dir.filePath(QStringLiteral("run.csv"));
        const auto r = record::CaptureExporter::run(m_capture, o);
        QVERIFY2(r.ok, qPrintable(r.error));
    }

    void captureEqualsTheTidyCsv()
    {
        record::CaptureExporter::Options o;
        o.format = record::CaptureExporter::Format::Mat;
        o.output = m_dir.filePath(QStringLiteral("run.mat"));
        const auto r = record::CaptureExporter::run(m_capture, o);
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.files, QStringList{o.output});
        QString error;
        const QJsonObject c = compare(o.output, QStringLiteral("SN_0042_a"), m_csv, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QCOMPARE(c.value(QStringLiteral("variables")).toArray(), QJsonArray{QStringLiteral("SN_0042_a")});
        QFile csv(m_csv);
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const int rows = int(csv.readAll().count('\n')) - 1;
        QVERIFY(rows > 3000); // HI81 and HI83 rows beside the HI91's
        QCOMPARE(qlonglong(r.frames), qlonglong(rows));
        verifyAgainstCsv(c, rows);
        const QJsonObject units = c.value(QStringLiteral("units")).toObject();
        QCOMPARE(units.value(QStringLiteral("acc")).toString(), QStringLiteral("m/s^2"));
        QCOMPARE(units.value(QStringLiteral("gyr")).toString(), QStringLiteral("rad/s"));
        QCOMPARE(units.value(QStringLiteral("mag")).toString(), QStringLiteral("T"));
        QCOMPARE(units.value(QStringLiteral("euler")).toString(), QStringLiteral("rad"));
        QCOMPARE(units.value(QStringLiteral("time_common")).toString(), QStringLiteral("s"));
        QCOMPARE(c.value(QStringLiteral("columns")).toObject().value(QStringLiteral("quat")).toString(), QStringLiteral("w x y z"));
        const QJsonObject info = c.value(QStringLiteral("info")).toObject();
        QCOMPARE(info.value(QStringLiteral("serial")).toString(), QStringLiteral("SN-0042/a"));
        QVERIFY(info.value(QStringLiteral("time_origin_utc")).toString().contains(QLatin1Char('T')));
    }

    // A session of two devices: one file, a struct per device named by its serial number
    // ("SN_" before it: the user guide's s.SN_0042).
    void sessionToOneFile()
    {
        const QString folder = m_dir.filePath(QStringLiteral("session"));
        record::SessionManifest manifest;
        QString error;
        QVERIFY2(test::writeTwoDeviceSession(folder, &manifest, &error), qPrintable(error));
        record::SessionExporter::Options o;
        o.format = record::CaptureExporter::Format::Mat;
        o.output = m_dir.filePath(QStringLiteral("session.mat"));
        const auto r = record::SessionExporter::run(folder, o);
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.samplesByDevice, (std::vector<uint64_t>{1000, 1500}));
        // Read whole by the reader: the structs, their sizes, their devices (the values are the
        // capture test's, above; here the CSV is only the reader's argument).
        const QJsonObject a = compare(o.output, QStringLiteral("SN_AAA1"), m_csv, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QCOMPARE(a.value(QStringLiteral("variables")).toArray(), (QJsonArray{QStringLiteral("SN_AAA1"), QStringLiteral("SN_BBB2")}));
        QCOMPARE(a.value(QStringLiteral("shapes")).toObject().value(QStringLiteral("acc")).toArray(), (QJsonArray{1000, 3}));
        const QJsonObject b = compare(o.output, QStringLiteral("SN_BBB2"), m_csv, &error);
        QCOMPARE(b.value(QStringLiteral("shapes")).toObject().value(QStringLiteral("acc")).toArray(), (QJsonArray{1500, 3}));
        QCOMPARE(b.value(QStringLiteral("info")).toObject().value(QStringLiteral("serial")).toString(), QStringLiteral("BBB2"));
    }

    // The struct's name is the user guide's (s.SN_0042): "SN_" and the serial number, a valid
    // MATLAB name whatever the serial begins with (a module's 16 hex digits were x2181B60A...).
    void structNamedAsTheGuideSays_data()
    {
        QTest::addColumn<QByteArray>("serial");
        QTest::addColumn<QString>("variable");
        QTest::newRow("digits") << QByteArray("0042") << QStringLiteral("SN_0042");
        QTest::newRow("hex uuid") << QByteArray("2181B60A6FDA63DF") << QStringLiteral("SN_2181B60A6FDA63DF");
        QTest::newRow("SN- already") << QByteArray("SN-7") << QStringLiteral("SN_7");
    }
    void structNamedAsTheGuideSays()
    {
        QFETCH(QByteArray, serial);
        QFETCH(QString, variable);
        synthetic::CaptureSpec spec;
        spec.frames = 200;
        spec.serial = serial.toStdString();
        const QString capture = m_dir.filePath(QStringLiteral("named-%1.imucap").arg(QString::fromLatin1(serial)));
        QVERIFY(synthetic::writeCapture(capture, spec) > 0);
        record::CaptureExporter::Options o;
        o.format = record::CaptureExporter::Format::TidyCsv;
        o.output = m_dir.filePath(QStringLiteral("named-%1.csv").arg(QString::fromLatin1(serial)));
        QVERIFY(record::CaptureExporter::run(capture, o).ok);
        const QString csv = o.output;
        o.format = record::CaptureExporter::Format::Mat;
        o.output = m_dir.filePath(QStringLiteral("named-%1.mat").arg(QString::fromLatin1(serial)));
        const auto r = record::CaptureExporter::run(capture, o);
        QVERIFY2(r.ok, qPrintable(r.error));
        QString error;
        const QJsonObject c = compare(o.output, variable, csv, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QCOMPARE(c.value(QStringLiteral("variables")).toArray(), QJsonArray{variable});
    }

    void fromTheCommandLine()
    {
        const QString out = m_dir.filePath(QStringLiteral("cli.mat"));
        const auto r = test::runCli({QStringLiteral("export"), m_capture, QStringLiteral("--format"), QStringLiteral("mat"),
                                     QStringLiteral("-o"), out});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QString error;
        const QJsonObject c = compare(out, QStringLiteral("SN_0042_a"), m_csv, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        // A folder that does not exist: a clear error naming the file, no file left.
        const QString bad = m_dir.filePath(QStringLiteral("no/such/folder/x.mat"));
        const auto failed = test::runCli({QStringLiteral("export"), m_capture, QStringLiteral("--format"), QStringLiteral("mat"),
                                          QStringLiteral("-o"), bad});
        QVERIFY(failed.code != 0);
        QVERIFY2(failed.err.contains(QStringLiteral("x.mat")), qPrintable(failed.err));
        QVERIFY(!QFile::exists(bad));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstMatExport)
#include "tst_mat_export.moc"
