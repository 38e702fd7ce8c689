// The calibration history on disk (one folder per device, one per run: record.json and
// samples.csv), listed newest first, and its list model.
#include "calib/calibration_history.h"
#include "calib/mag_cal_result.h"
#include "itemmodels/calibration_history_model.h"
#include "../common/test_main.h"

#include <QAbstractItemModelTester>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace imudesk;
using calib::CalibrationHistory;
using calib::CalibrationRecord;

namespace {
CalibrationRecord record(const char *kind, const QDateTime &t, const char *serial = "0439956980ABCDEF")
{
    CalibrationRecord r;
    r.kind = QLatin1String(kind);
    r.time = t;
    r.deviceSerial = QLatin1String(serial);
    r.product = QStringLiteral("HI14R3");
    r.firmware = QStringLiteral("1.7.1");
    calib::MagCalResult m;
    m.verdict = calib::MagVerdict::Pass;
    m.reason = QStringLiteral("good");
    m.fieldUt = 49.8;
    m.fitErrorPct = 0.62;
    m.coveragePct = 95;
    r.result = m.toJson();
    return r;
}
calib::SampleTable samples(int n)
{
    calib::SampleTable t;
    t.columns = {QStringLiteral("mag_x"), QStringLiteral("mag_y"), QStringLiteral("mag_z")};
    for (int i = 0; i < n; ++i)
        t.rows.push_back({double(i), -double(i), 0.5 * i});
    return t;
}
} // namespace

class TstCalibrationHistory : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void savesAndListsNewestFirst()
    {
        QTemporaryDir dir;
        CalibrationHistory h(dir.path() + QStringLiteral("/cal"));
        const QDateTime t0 = QDateTime(QDate(2026, 3, 1), QTime(10, 0), Qt::UTC);
        CalibrationRecord a = record("magnetometer", t0.addSecs(60));
        CalibrationRecord b = record("gyro_scale", t0);
        CalibrationRecord c = record("magnetometer", t0.addSecs(120));
        CalibrationRecord other = record("magnetometer", t0, "OTHER/../x");
        QString error;
        for (CalibrationRecord *r : {&a, &b, &c, &other})
            QVERIFY2(h.save(*r, samples(5), &error), qPrintable(error));
        QVERIFY(QFile::exists(a.folder + QStringLiteral("/record.json")));
        QVERIFY(QFile::exists(a.folder + QStringLiteral("/samples.csv")));
        // The same second twice: never overwritten.
        CalibrationRecord again = record("magnetometer", t0.addSecs(120));
        QVERIFY(h.save(again, samples(1)));
        QVERIFY(again.folder != c.folder);

        const auto list = h.list(QStringLiteral("0439956980ABCDEF"));
        QCOMPARE(list.size(), 4);
        QCOMPARE(list.at(0).time, t0.addSecs(120));
        QCOMPARE(list.at(3).time, t0);
        QCOMPARE(list.at(3).kind, QStringLiteral("gyro_scale"));
        QCOMPARE(list.at(1).verdict(), QStringLiteral("pass"));
        // Same time: the later folder ("-2") first.
        QCOMPARE(list.at(0).folder, again.folder);
        QCOMPARE(list.at(0).sampleCount, 1);
        QCOMPARE(list.at(1).sampleCount, 5);
        QCOMPARE(h.devices().size(), 2);
        QVERIFY(h.devices().contains(QStringLiteral("OTHERx"))); // reduced to safe characters

        calib::SampleTable back;
        QVERIFY(h.loadSamples(a, back, &error));
        QCOMPARE(back.rows, samples(5).rows);
        QVERIFY(h.remove(a));
        QCOMPARE(h.list(QStringLiteral("0439956980ABCDEF")).size(), 3);
        CalibrationRecord outside = a;
        outside.folder = dir.path();
        QVERIFY(!h.remove(outside)); // only inside the history
    }

    void damagedRecordsAreSkipped()
    {
        QTemporaryDir dir;
        CalibrationHistory h(dir.path());
        CalibrationRecord a = record("magnetometer", QDateTime::currentDateTimeUtc());
        QVERIFY(h.save(a, samples(2)));
        QDir().mkpath(dir.path() + QStringLiteral("/0439956980ABCDEF/broken"));
        QFile f(dir.path() + QStringLiteral("/0439956980ABCDEF/broken/record.json"));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("{ not json");
        f.close();
        QCOMPARE(h.list(QStringLiteral("0439956980ABCDEF")).size(), 1);
        CalibrationRecord noKind;
        QString error;
        QVERIFY(!h.save(noKind, samples(1), &error));
        QVERIFY(!error.isEmpty());
    }

    void model()
    {
        models::CalibrationHistoryModel m;
        QAbstractItemModelTester tester(&m, QAbstractItemModelTester::FailureReportingMode::QtTest);
        const QDateTime t0 = QDateTime(QDate(2026, 3, 1), QTime(10, 0), Qt::UTC);
        QList<CalibrationRecord> recs{record("gyro_scale", t0), record("magnetometer", t0.addSecs(5))};
        recs[0].result = QJsonObject{{QStringLiteral("scale_error_pct"), 0.503}, {QStringLiteral("verdict"), QStringLiteral("pass")}};
        m.setRecords(recs);
        QCOMPARE(m.rowCount(), 2);
        QCOMPARE(m.columnCount(), int(models::CalibrationHistoryModel::ColumnCount));
        QCOMPARE(m.data(m.index(0, models::CalibrationHistoryModel::KindColumn)).toString(), QStringLiteral("Magnetometer"));
        QVERIFY(m.data(m.index(0, models::CalibrationHistoryModel::SummaryColumn)).toString().contains(QStringLiteral("49.8")));
        QVERIFY(m.data(m.index(1, models::CalibrationHistoryModel::SummaryColumn)).toString().contains(QStringLiteral("0.503")));
        QCOMPARE(m.data(m.index(0, 0), models::CalibrationHistoryModel::VerdictRole).toString(), QStringLiteral("pass"));
        QCOMPARE(m.data(m.index(0, models::CalibrationHistoryModel::VerdictColumn)).toString(), QStringLiteral("Pass"));
        QCOMPARE(m.headerData(0, Qt::Horizontal).toString(), QStringLiteral("Time"));
        QTemporaryDir dir;
        CalibrationHistory h(dir.path());
        CalibrationRecord r = record("magnetometer", t0);
        QVERIFY(h.save(r, samples(1)));
        m.load(h, r.deviceSerial);
        QCOMPARE(m.rowCount(), 1);
        QCOMPARE(m.data(m.index(0, 0), models::CalibrationHistoryModel::FolderRole).toString(), r.folder);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCalibrationHistory)
#include "tst_calibration_history.moc"
