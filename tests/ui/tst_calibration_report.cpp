// The calibration report (ui/calibration/calibration_report): a real MagCalibrator fit of synthetic
// samples with a known hard and soft iron, written as PDF; the document holds the verdict,
// the field strength and the hard iron; the sphere picture is a real drawing; a warned or
// failed run carries the manual's troubleshooting (v1.7.1 9.31); an unwritable path and an
// empty one come back as errors. Offscreen.
#include "calib/mag_calibrator.h"
#include "calibration/calibration_report.h"
#include "../common/test_main.h"

#include <QFile>
#include <QJsonObject>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTextDocument>

#include <Eigen/Core>

#include <cmath>
#include <random>

using namespace imudesk;

namespace {

// Field directions spread over the sphere (Fibonacci lattice), distorted by a soft iron
// and shifted by a hard iron, with 0.3 uT noise.
std::vector<Eigen::Vector3d> sphereSamples(int n, const Eigen::Vector3d &hardIron, double fieldUt, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, 0.3);
    Eigen::Matrix3d distortion;
    distortion << 1.05, 0.02, 0.0, 0.02, 0.97, 0.01, 0.0, 0.01, 1.0;
    std::vector<Eigen::Vector3d> out;
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double z = 1.0 - 2.0 * (i + 0.5) / n;
        const double r = std::sqrt(1.0 - z * z);
        const Eigen::Vector3d d(r * std::cos(golden * i), r * std::sin(golden * i), z);
        out.push_back(distortion * (fieldUt * d) + hardIron + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
    }
    return out;
}

calib::SampleTable tableOf(const std::vector<Eigen::Vector3d> &mags)
{
    calib::SampleTable t;
    t.columns = {QStringLiteral("mag_x"), QStringLiteral("mag_y"), QStringLiteral("mag_z")};
    for (const auto &m : mags)
        t.rows.push_back({m.x(), m.y(), m.z()});
    return t;
}

calib::CalibrationRecord recordOf(const calib::MagCalResult &r, int samples)
{
    calib::CalibrationRecord rec;
    rec.kind = QStringLiteral("magnetometer");
    rec.time = QDateTime(QDate(2026, 11, 21), QTime(10, 30), Qt::UTC);
    rec.deviceSerial = QStringLiteral("SN4711");
    rec.product = QStringLiteral("HI14R3");
    rec.firmware = QStringLiteral("1.7.1");
    rec.result = r.toJson();
    rec.sampleCount = samples;
    return rec;
}

// Pixels of the picture that differ from its top-left (background) pixel.
int pixelsOffBackground(const QImage &image)
{
    const QRgb background = image.pixel(0, 0);
    int n = 0;
    for (int y = 0; y < image.height(); y += 2)
        for (int x = 0; x < image.width(); x += 2)
            n += image.pixel(x, y) != background;
    return n;
}

} // namespace

class TstCalibrationReport : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void writesThePdfOfARealFit_data()
    {
        QTest::addColumn<double>("hx");
        QTest::addColumn<double>("hy");
        QTest::addColumn<double>("hz");
        QTest::addColumn<double>("field");
        QTest::newRow("indoor hard iron") << 12.5 << -7.25 << 3.0 << 49.8;
        QTest::newRow("large offset, weak field") << -31.0 << 18.0 << -22.0 << 28.0;
    }
    void writesThePdfOfARealFit()
    {
        QFETCH(double, hx);
        QFETCH(double, hy);
        QFETCH(double, hz);
        QFETCH(double, field);
        const auto mags = sphereSamples(400, {hx, hy, hz}, field, 11);
        const calib::MagCalResult fit = calib::MagCalibrator().calibrate(mags);
        QVERIFY2(fit.usable(), qPrintable(fit.reason));
        QVERIFY(std::abs(fit.hardIron.x() - hx) < 1.0);

        ui::CalibrationReport report(recordOf(fit, int(mags.size())), tableOf(mags));
        const QString text = report.plainText();
        QVERIFY(text.contains(calib::MagCalResult::verdictText(fit.verdict)));
        QVERIFY(text.contains(QString::number(fit.fieldUt, 'f', 2)));
        for (int i = 0; i < 3; ++i)
            QVERIFY2(text.contains(QString::number(fit.hardIron[i], 'f', 2)), qPrintable(QString::number(fit.hardIron[i], 'f', 2)));
        QVERIFY(text.contains(QStringLiteral("SN4711")));
        QVERIFY(text.contains(QStringLiteral("1.7.1")));
        QVERIFY(text.contains(QStringLiteral("(µT)")));
        QVERIFY(!text.contains(QStringLiteral("uT")));

        // The sphere: before and after, drawn, and in the document as its image resource.
        const QImage sphere = report.sphereImage();
        QVERIFY(!sphere.isNull());
        QCOMPARE(sphere.width(), 2 * ui::CalibrationReport::kSphereSize);
        QVERIFY(pixelsOffBackground(sphere) > 500);
        const QVariant resource = report.document().resource(QTextDocument::ImageResource, ui::CalibrationReport::sphereUrl());
        QVERIFY(!resource.value<QImage>().isNull());
        QVERIFY(report.html().contains(ui::CalibrationReport::sphereUrl().toString()));

        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("report.pdf"));
        QString error;
        QVERIFY2(report.writePdf(path, &error), qPrintable(error));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray pdf = f.readAll();
        QVERIFY(pdf.startsWith("%PDF"));
        QVERIFY(pdf.size() > 2000);
        // Page objects: "/Type /Page" (not "/Pages").
        const QRegularExpression page(QStringLiteral("/Type\\s*/Page(?!s)"));
        QVERIFY(page.globalMatch(QString::fromLatin1(pdf)).hasNext());
        QVERIFY(pdf.contains("/Image") || pdf.contains("/XObject"));
    }

    void troubleshootingOnlyWhenNotPassed_data()
    {
        QTest::addColumn<QString>("verdict");
        QTest::addColumn<bool>("troubleshooting");
        QTest::newRow("pass") << QStringLiteral("pass") << false;
        QTest::newRow("warn") << QStringLiteral("warn") << true;
        QTest::newRow("fail") << QStringLiteral("fail") << true;
    }
    void troubleshootingOnlyWhenNotPassed()
    {
        QFETCH(QString, verdict);
        QFETCH(bool, troubleshooting);
        const auto mags = sphereSamples(300, {5, 5, 5}, 45, 3);
        calib::CalibrationRecord rec = recordOf(calib::MagCalibrator().calibrate(mags), 300);
        rec.result.insert(QStringLiteral("verdict"), verdict);
        ui::CalibrationReport report(rec, tableOf(mags));
        QCOMPARE(report.plainText().contains(QStringLiteral("9.31")), troubleshooting);
        QCOMPARE(report.plainText().contains(QStringLiteral("20-60 µT")), troubleshooting);
    }

    // Issue 32 point 5: the report gives the run's figures as its result states them, in the
    // table and in the sphere's caption and read-out; the caption says what the picture
    // shows (no "Turn the module..." instruction); µT, never "uT". Point 4: the device's own
    // calibration is a section with its own verdict, not mixed into ImuDesk's.
    void figuresOfTheRunAndTheDevicesOwnVerdict_data()
    {
        QTest::addColumn<QString>("deviceVerdict");
        QTest::addColumn<QString>("deviceWord");
        QTest::newRow("device passed") << QStringLiteral("pass") << calib::MagCalResult::verdictText(calib::MagVerdict::Pass);
        QTest::newRow("device failed") << QStringLiteral("fail") << calib::MagCalResult::verdictText(calib::MagVerdict::Fail);
        QTest::newRow("device not run") << QString() << QString();
    }
    void figuresOfTheRunAndTheDevicesOwnVerdict()
    {
        QFETCH(QString, deviceVerdict);
        QFETCH(QString, deviceWord);
        // More samples than the sphere view keeps while samples come in (4000).
        const auto mags = sphereSamples(6000, {9, -4, 15}, 48, 21);
        const calib::MagCalResult fit = calib::MagCalibrator().calibrate(mags);
        QVERIFY2(fit.usable(), qPrintable(fit.reason));
        calib::CalibrationRecord rec = recordOf(fit, int(mags.size()));
        if (!deviceVerdict.isEmpty())
            rec.result.insert(QStringLiteral("device_calibration"),
                              QJsonObject{{QStringLiteral("flow"), QStringLiteral("mcal")},
                                          {QStringLiteral("verdict"), deviceVerdict},
                                          {QStringLiteral("stat"), deviceVerdict == QLatin1String("pass") ? 3 : 4},
                                          {QStringLiteral("progress"), 100},
                                          {QStringLiteral("message"), QStringLiteral("device says so")}});
        ui::CalibrationReport report(rec, tableOf(mags));
        const QString text = report.plainText();
        const QString coverage = QString::number(fit.coveragePct, 'f', 0);
        const QString samples = QString::number(fit.samples);
        const QString heading = QString::number(fit.predictedHeadingErrorDeg, 'f', 2);
        QVERIFY(text.contains(coverage) && text.contains(samples) && text.contains(heading));
        QVERIFY2(report.sphereCaption().contains(samples) && report.sphereCaption().contains(coverage + QStringLiteral(" %")),
                 qPrintable(report.sphereCaption()));
        QVERIFY(text.contains(report.sphereCaption()));
        for (const QString &shown : {text, report.html()}) {
            QVERIFY(!shown.contains(QStringLiteral("uT")));
            QVERIFY(!shown.contains(QStringLiteral("Turn the module")));
        }
        // ImuDesk's verdict stays the report's verdict; the device's is its own section.
        QVERIFY(text.contains(calib::MagCalResult::verdictText(fit.verdict)));
        QCOMPARE(text.contains(QStringLiteral("The device's own calibration")), !deviceVerdict.isEmpty());
        if (!deviceVerdict.isEmpty()) {
            QVERIFY(text.contains(QStringLiteral("Device's verdict: ") + deviceWord));
            QVERIFY(text.contains(QStringLiteral("STAT=")));
            QVERIFY(!text.contains(QStringLiteral("device_calibration"))); // not a raw metric row
        }
    }

    void otherKindsHaveTheirMetricsAndNoSphere()
    {
        calib::CalibrationRecord rec;
        rec.kind = QStringLiteral("gyro_scale");
        rec.time = QDateTime::currentDateTimeUtc();
        rec.result = QJsonObject{{QStringLiteral("target_deg"), 720},
                                 {QStringLiteral("scale_error_pct"), 0.5034},
                                 {QStringLiteral("device_ok"), true},
                                 {QStringLiteral("verdict"), QStringLiteral("pass")},
                                 {QStringLiteral("reason"), QStringLiteral("even turn")}};
        ui::CalibrationReport report(rec, {});
        QVERIFY(report.sphereImage().isNull());
        const QString text = report.plainText();
        QVERIFY(text.contains(QStringLiteral("Target angle (deg)")));
        QVERIFY(text.contains(QStringLiteral("0.503")));
        QVERIFY(text.contains(QStringLiteral("even turn")));
        QVERIFY(!text.contains(QStringLiteral("9.31")));
    }

    void unwritablePathIsAnError_data()
    {
        QTest::addColumn<QString>("path");
        QTest::newRow("missing folder") << QStringLiteral("/nonexistent-imudesk-folder/sub/report.pdf");
        QTest::newRow("proc") << QStringLiteral("/proc/imudesk-report.pdf");
        QTest::newRow("empty") << QString();
    }
    void unwritablePathIsAnError()
    {
        QFETCH(QString, path);
        const auto mags = sphereSamples(300, {1, 2, 3}, 50, 5);
        ui::CalibrationReport report(recordOf(calib::MagCalibrator().calibrate(mags), 300), tableOf(mags));
        QString error;
        QVERIFY(!report.writePdf(path, &error));
        QVERIFY(!error.isEmpty());
        if (!path.isEmpty())
            QVERIFY(!QFile::exists(path));
    }
};

IMUDESK_TEST_MAIN(TstCalibrationReport)
#include "tst_calibration_report.moc"
