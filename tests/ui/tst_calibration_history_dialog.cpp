// The calibration history dialog (offscreen) over a temporary history with two devices:
// lists the devices and their runs newest first, shows the selected run's metrics and, for
// a magnetometer run, its samples on the before/after spheres; exports the report (PDF) and
// the samples (CSV); deletes a run's folder, and the device's folder with its last run.
#include "calib/calibration_history.h"
#include "calib/mag_calibrator.h"
#include "calibration/calibration_history_dialog.h"
#include "calibration/mag_sphere_view.h"
#include "itemmodels/calibration_history_model.h"
#include "../common/test_main.h"

#include <QDir>
#include <QFile>
#include <QListWidget>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace imudesk;

namespace {

calib::SampleTable magTable(const Eigen::Vector3d &hardIron)
{
    calib::SampleTable t;
    t.columns = {QStringLiteral("mag_x"), QStringLiteral("mag_y"), QStringLiteral("mag_z")};
    const int n = 360;
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double z = 1.0 - 2.0 * (i + 0.5) / n;
        const double r = std::sqrt(1.0 - z * z);
        const Eigen::Vector3d m = 48.0 * Eigen::Vector3d(r * std::cos(golden * i), r * std::sin(golden * i), z)
            + hardIron + 0.2 * Eigen::Vector3d(std::sin(i * 1.7), std::cos(i * 2.3), std::sin(i * 0.9));
        t.rows.push_back({m.x(), m.y(), m.z()});
    }
    return t;
}

calib::CalibrationRecord record(const QString &kind, const QString &serial, int minute, const QJsonObject &result)
{
    calib::CalibrationRecord r;
    r.kind = kind;
    r.time = QDateTime(QDate(2026, 11, 20), QTime(9, minute), Qt::UTC);
    r.deviceSerial = serial;
    r.product = QStringLiteral("HI14R3");
    r.firmware = QStringLiteral("1.7.1");
    r.result = result;
    return r;
}

} // namespace

class TstCalibrationHistoryDialog : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void listsShowsExportsAndDeletes()
    {
        QTemporaryDir dir;
        const calib::CalibrationHistory history(dir.path());
        const calib::SampleTable mags = magTable({9.5, -4.0, 2.5});
        std::vector<Eigen::Vector3d> v;
        QVERIFY(calib::SampleCsv::magnetometer(mags, v));
        const calib::MagCalResult fit = calib::MagCalibrator().calibrate(v);
        QVERIFY2(fit.usable(), qPrintable(fit.reason));

        calib::CalibrationRecord magRun = record(QStringLiteral("magnetometer"), QStringLiteral("SN-A"), 10, fit.toJson());
        QVERIFY(history.save(magRun, mags));
        calib::SampleTable gyro;
        gyro.columns = {QStringLiteral("time_ms"), QStringLiteral("gyr_z")};
        gyro.rows = {{0, 0.1}, {10, 30.2}, {20, 30.4}};
        calib::CalibrationRecord gyroRun = record(QStringLiteral("gyro_scale"), QStringLiteral("SN-A"), 40,
                                                  {{QStringLiteral("target_deg"), 1080},
                                                   {QStringLiteral("scale_error_pct"), -0.4213},
                                                   {QStringLiteral("verdict"), QStringLiteral("warn")},
                                                   {QStringLiteral("reason"), QStringLiteral("uneven")}});
        QVERIFY(history.save(gyroRun, gyro));
        calib::CalibrationRecord otherRun = record(QStringLiteral("attitude_reset"), QStringLiteral("SN-B"), 5,
                                                   {{QStringLiteral("variant"), 3},
                                                    {QStringLiteral("verdict"), QStringLiteral("pass")}});
        QVERIFY(history.save(otherRun, gyro));

        ui::CalibrationHistoryDialog dialog(dir.path());
        dialog.show();
        QCOMPARE(dialog.deviceList()->count(), 2);
        QVERIFY(dialog.selectDevice(QStringLiteral("SN-A")));
        QVERIFY(!dialog.selectDevice(QStringLiteral("SN-Z")));
        QCOMPARE(dialog.currentDevice(), QStringLiteral("SN-A"));
        QCOMPARE(dialog.model()->rowCount(), 2);
        // Newest first: the gyro run (09:40) above the magnetometer run (09:10), and selected.
        QCOMPARE(dialog.model()->record(0).kind, QStringLiteral("gyro_scale"));
        QVERIFY(dialog.currentRecord());
        QCOMPARE(dialog.currentRecord()->kind, QStringLiteral("gyro_scale"));
        QVERIFY(dialog.detailsText().contains(QStringLiteral("Target angle (deg)")));
        QVERIFY(dialog.detailsText().contains(QStringLiteral("-0.421")));
        QVERIFY(!dialog.beforeView()->isVisibleTo(&dialog));

        QVERIFY(dialog.selectRun(1));
        QCOMPARE(dialog.currentRecord()->kind, QStringLiteral("magnetometer"));
        const QString details = dialog.detailsText();
        QVERIFY2(details.contains(QString::number(fit.fieldUt, 'f', 2)), qPrintable(details));
        QVERIFY(details.contains(QString::number(fit.hardIron.x(), 'f', 2)));
        QVERIFY(details.contains(QStringLiteral("Fit error (%)")));
        QVERIFY(dialog.beforeView()->isVisibleTo(&dialog));
        QCOMPARE(dialog.beforeView()->sampleCount(), mags.rows.size());
        QCOMPARE(dialog.afterView()->sampleCount(), mags.rows.size());

        QTemporaryDir exports; // outside the history
        const QString pdfPath = exports.filePath(QStringLiteral("out/report.pdf"));
        QString error;
        QVERIFY(!dialog.exportReport(pdfPath, &error)); // the folder "out" does not exist
        QVERIFY(!error.isEmpty());
        QVERIFY(QDir(exports.path()).mkdir(QStringLiteral("out")));
        QVERIFY2(dialog.exportReport(pdfPath, &error), qPrintable(error));
        QFile pdf(pdfPath);
        QVERIFY(pdf.open(QIODevice::ReadOnly));
        QVERIFY(pdf.read(4) == "%PDF");

        const QString csvPath = exports.filePath(QStringLiteral("out/samples.csv"));
        QVERIFY2(dialog.exportSamples(csvPath, &error), qPrintable(error));
        QFile csv(csvPath);
        QVERIFY(csv.open(QIODevice::ReadOnly));
        calib::SampleTable back;
        QVERIFY(calib::SampleCsv::parse(csv.readAll(), back));
        QCOMPARE(back.rows.size(), mags.rows.size());

        const QString magFolder = dialog.currentRecord()->folder;
        QVERIFY(QFileInfo::exists(magFolder));
        QVERIFY(dialog.removeSelected(&error));
        QVERIFY(!QFileInfo::exists(magFolder));
        QCOMPARE(dialog.model()->rowCount(), 1);
        QCOMPARE(dialog.currentRecord()->kind, QStringLiteral("gyro_scale"));

        // The last run of a device takes the device's folder with it.
        QVERIFY(dialog.selectDevice(QStringLiteral("SN-B")));
        QCOMPARE(dialog.model()->rowCount(), 1);
        QVERIFY(dialog.removeSelected(&error));
        QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("SN-B"))));
        QCOMPARE(dialog.deviceList()->count(), 1);
        QCOMPARE(history.devices(), QStringList{QStringLiteral("SN-A")});
    }

    void emptyHistorySaysWhereRunsGo()
    {
        QTemporaryDir dir;
        ui::CalibrationHistoryDialog dialog(dir.path());
        QCOMPARE(dialog.deviceList()->count(), 0);
        QVERIFY(!dialog.currentRecord());
        QVERIFY(dialog.detailsText().contains(QStringLiteral("No calibration runs yet")));
        QString error;
        QVERIFY(!dialog.exportReport(dir.filePath(QStringLiteral("r.pdf")), &error));
        QVERIFY(!dialog.removeSelected(&error));
    }
};

IMUDESK_TEST_MAIN(TstCalibrationHistoryDialog)
#include "tst_calibration_history_dialog.moc"
