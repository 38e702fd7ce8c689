// The station's PDF report of one module (ui/reports/station_report.h): it names the module,
// the verdict, the failing step with the values outside their limits and every step with its
// values; the PDF is written whole or not at all (an unwritable folder gives a message and no
// file). IMUDESK_REPORT_PNG=FILE also saves the first page as a picture, to look at.
#include "reports/station_report.h"
#include "../common/test_main.h"

#include <QAbstractTextDocumentLayout>
#include <QFile>
#include <QImage>
#include <QPainter>
#include <QTemporaryDir>
#include <QTest>
#include <QTextDocument>

using namespace imudesk;
using station::Verdict;

namespace {
station::ModuleResult failedModule()
{
    station::TestPlan plan = station::TestPlan::example();
    station::ModuleResult m = station::ModuleResult::pending(QStringLiteral("/dev/ttyUSB3"), plan);
    m.serial = QStringLiteral("3B3F4C95B9D2358B");
    m.product = QStringLiteral("HI14R3");
    m.firmware = QStringLiteral("1.6.6");
    m.firmwareAfter = QStringLiteral("1.7.1");
    m.verdict = Verdict::Fail;
    m.started = QDateTime(QDate(2026, 11, 27), QTime(8, 0), Qt::UTC);
    m.finished = m.started.addSecs(75);
    m.steps[0].verdict = Verdict::Pass;
    m.steps[0].detail = QStringLiteral("HI14R3, firmware 1.6.6, serial 3B3F4C95B9D2358B");
    m.steps[1].verdict = Verdict::Pass;
    m.steps[1].detail = QStringLiteral("updated from 1.6.6 to 1.7.1 and verified");
    m.steps[1].values.push_back({QStringLiteral("write_seconds"), 1.48, QStringLiteral("s"), QString(), true});
    m.steps[2].verdict = Verdict::Pass;
    m.steps[3].verdict = Verdict::Fail;
    m.steps[3].detail = QStringLiteral("502 samples; values outside the limits are marked");
    m.steps[3].values.push_back({QStringLiteral("gyro_std_x"), 0.4087, QStringLiteral("°/s"), QStringLiteral("≤ 0.05"), false});
    m.steps[3].values.push_back({QStringLiteral("gyro_bias_x"), 0.098, QStringLiteral("°/s"), QStringLiteral("|x| ≤ 0.5"), true});
    for (size_t i = 4; i < m.steps.size(); ++i)
        m.steps[i].verdict = Verdict::Skipped;
    return m;
}
} // namespace

class TestStationReport : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void namesWhatFailed();
    void writesPdfOrSaysWhy();
    void marginalPassSaysSo();
};

// A module whose every step passed, one value inside its marginal band: the verdict reads
// "pass (marginal)" and the value "marginal", the others "within".
void TestStationReport::marginalPassSaysSo()
{
    auto m = failedModule();
    m.verdict = Verdict::Pass;
    m.steps[3].verdict = Verdict::Pass;
    m.steps[3].detail = QStringLiteral("502 samples within every limit; marginal: gyro_std_x");
    m.steps[3].values.clear();
    station::Measurement noisy{QStringLiteral("gyro_std_x"), 0.045, QStringLiteral("°/s"), QStringLiteral("≤ 0.05 (marginal > 0.04)"),
                               true, QStringLiteral("LE"), 0.05};
    noisy.marginalHigh = 0.04;
    noisy.marginal = true;
    m.steps[3].values.push_back(noisy);
    m.steps[3].values.push_back({QStringLiteral("gyro_bias_x"), 0.098, QStringLiteral("°/s"), QStringLiteral("|x| ≤ 0.5"), true});
    QVERIFY(m.marginal());
    QTextDocument doc;
    doc.setHtml(ui::StationReport::html(m, station::TestPlan::example()));
    const QString text = doc.toPlainText();
    for (const char *want : {"pass (marginal)", "≤ 0.05 (marginal > 0.04)", "marginal", "within"})
        QVERIFY2(text.contains(QString::fromUtf8(want)), want);
    QVERIFY(!text.contains(QStringLiteral("outside")));
    QVERIFY(!text.contains(QStringLiteral("Failed at")));
}

void TestStationReport::namesWhatFailed()
{
    const auto m = failedModule();
    const QString html = ui::StationReport::html(m, station::TestPlan::example());
    QTextDocument doc;
    doc.setHtml(html);
    const QString text = doc.toPlainText();
    for (const char *want : {"3B3F4C95B9D2358B", "HI14R3", "1.6.6, updated to 1.7.1", "HI14 incoming test", "fail",
                             "Failed at Static noise and bias: gyro_std_x 0.4087 °/s (≤ 0.05)", "outside", "within",
                             "11. Record evidence skipped", "2026-11-27 08:01:15"})
        QVERIFY2(text.contains(QString::fromUtf8(want)), want);
    if (const QByteArray png = qgetenv("IMUDESK_REPORT_PNG"); !png.isEmpty()) {
        doc.setTextWidth(800);
        QImage image(800, int(doc.size().height()), QImage::Format_RGB32);
        image.fill(Qt::white);
        QPainter p(&image);
        doc.drawContents(&p);
        p.end();
        image.save(QString::fromLocal8Bit(png));
    }
}

void TestStationReport::writesPdfOrSaysWhy()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("r.pdf"));
    QString error;
    QVERIFY2(ui::writeStationReport(failedModule(), station::TestPlan::example(), path, &error), qPrintable(error));
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QVERIFY(f.read(4) == "%PDF");
    QVERIFY(f.size() > 5000);
    const QString bad = dir.filePath(QStringLiteral("missing/sub/r.pdf"));
    QVERIFY(!ui::writeStationReport(failedModule(), station::TestPlan::example(), bad, &error));
    QVERIFY2(error.contains(QStringLiteral("Cannot write the report")), qPrintable(error));
    QVERIFY(!QFile::exists(bad));
}

IMUDESK_TEST_MAIN(TestStationReport)
#include "tst_station_report.moc"
