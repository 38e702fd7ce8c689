// ExportDialog offscreen: the suggested output name follows the format, an export writes its
// files with the progress bar at 100 %, a time range limits the rows, and Cancel stops a
// running export and removes the partial files.
#include "../common/synthetic_capture.h"
#include "../common/synthetic_session.h"
#include "../common/test_main.h"
#include "../common/layout_checks.h"
#include "recording/export_dialog.h"
#include "workspace/language_switcher.h"

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QStandardItemModel>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace imudesk;
using Format = record::CaptureExporter::Format;
using ui::ExportDialog;

namespace {
int lineCount(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return -1;
    return int(f.readAll().count('\n'));
}
} // namespace

class TstExportDialog : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_small, m_large;

private Q_SLOTS:
    void initTestCase()
    {
        m_small = m_dir.filePath(QStringLiteral("small.imucap"));
        synthetic::CaptureSpec spec;
        spec.frames = 2000;
        QVERIFY(synthetic::writeCapture(m_small, spec) > 0);
        m_large = m_dir.filePath(QStringLiteral("large.imucap"));
        spec.frames = 1'500'000;
        QVERIFY(synthetic::writeCapture(m_large, spec) > 0);
    }

    void suggestsOutputPerFormat()
    {
        ExportDialog d(m_small);
        auto *output = d.findChild<QLineEdit *>(QStringLiteral("output"));
        QCOMPARE(output->text(), m_dir.filePath(QStringLiteral("small.csv")));
        d.setFormat(Format::JsonLines);
        QCOMPARE(output->text(), m_dir.filePath(QStringLiteral("small.jsonl")));
    }

    void exportsWithProgress_data()
    {
        QTest::addColumn<int>("format");
        QTest::addColumn<QString>("file");
        QTest::addColumn<double>("to");
        QTest::addColumn<int>("lines");
        QTest::newRow("vendor csv") << int(Format::VendorCsv) << "out.csv" << -1.0 << 2001; // one frame type: the file named
        QTest::newRow("tidy csv, first second") << int(Format::TidyCsv) << "out.csv" << 1.0 << 1009;
        QTest::newRow("json lines") << int(Format::JsonLines) << "out.csv" << -1.0 << 2000;
    }
    void exportsWithProgress()
    {
        QFETCH(int, format);
        QFETCH(QString, file);
        QFETCH(double, to);
        QFETCH(int, lines);
        ExportDialog d(m_small);
        d.setFormat(Format(format));
        d.setOutput(m_dir.filePath(QStringLiteral("out.csv")));
        d.setRange(0, to);
        QSignalSpy finished(&d, &ExportDialog::exportFinished);
        QTest::mouseClick(d.findChild<QPushButton *>(QStringLiteral("export")), Qt::LeftButton);
        QVERIFY(finished.wait(10000));
        QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(finished.at(0).at(1).toString()));
        QCOMPARE(d.findChild<QProgressBar *>(QStringLiteral("progress"))->value(), 1000);
        QCOMPARE(lineCount(m_dir.filePath(file)), lines);
        QVERIFY(d.findChild<QLabel *>(QStringLiteral("status"))->text().contains(m_dir.filePath(file)));
    }

    // A success leaves nothing to cancel: the button reads Close (and closes), and the folder
    // of what was written is one click away.
    void afterASuccessCloseAndShowFolder()
    {
        ExportDialog d(m_small);
        d.setFormat(Format::JsonLines);
        d.setOutput(m_dir.filePath(QStringLiteral("closing.jsonl")));
        auto *cancel = d.findChild<QPushButton *>(QStringLiteral("cancel"));
        auto *show = d.findChild<QPushButton *>(QStringLiteral("showFolder"));
        QVERIFY(cancel && show);
        QVERIFY(show->isHidden());
        d.show();
        QSignalSpy finished(&d, &ExportDialog::exportFinished);
        d.startExport();
        QVERIFY(finished.wait(10000));
        QVERIFY(finished.at(0).at(0).toBool());
        QCOMPARE(cancel->text(), ui::ExportDialog::tr("Close"));
        QVERIFY(show->isVisible());
        QSignalSpy rejected(&d, &QDialog::rejected);
        QTest::mouseClick(cancel, Qt::LeftButton);
        QCOMPARE(rejected.size(), 1);
        QVERIFY(!d.isVisible());
    }

    // A recorded session (its folder or its session.json) is exported whole from the window, as
    // imudesk-cli export FOLDER does: every device's rows in one file; no range, no vendor CSV.
    void exportsAWholeSession()
    {
        const QString folder = m_dir.filePath(QStringLiteral("session-1"));
        record::SessionManifest manifest;
        QString error;
        QVERIFY2(test::writeTwoDeviceSession(folder, &manifest, &error), qPrintable(error));
        ExportDialog d(QDir(folder).filePath(QStringLiteral("session.json")));
        QVERIFY(d.isSession());
        QCOMPARE(d.capture(), folder);
        auto *output = d.findChild<QLineEdit *>(QStringLiteral("output"));
        QCOMPARE(output->text(), folder + QStringLiteral(".csv"));
        QVERIFY(!d.findChild<QDoubleSpinBox *>(QStringLiteral("from"))->isEnabled());
        auto *format = d.findChild<QComboBox *>(QStringLiteral("format"));
        auto *model = qobject_cast<QStandardItemModel *>(format->model());
        QVERIFY(!model->item(format->findData(int(Format::VendorCsv)))->isEnabled());
        d.setFormat(Format::JsonLines);
        QSignalSpy finished(&d, &ExportDialog::exportFinished);
        QTest::mouseClick(d.findChild<QPushButton *>(QStringLiteral("export")), Qt::LeftButton);
        QVERIFY(finished.wait(20000));
        QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(finished.at(0).at(1).toString()));
        // 1000 samples of A and 1500 of B, a line each.
        QCOMPARE(lineCount(folder + QStringLiteral(".jsonl")), 2500);
        QCOMPARE(d.findChild<QProgressBar *>(QStringLiteral("progress"))->value(), 1000);
    }

    void cancelRemovesPartialFiles()
    {
        ExportDialog d(m_large);
        d.setFormat(Format::TidyCsv);
        const QString out = m_dir.filePath(QStringLiteral("cancelled.csv"));
        d.setOutput(out);
        QSignalSpy finished(&d, &ExportDialog::exportFinished);
        d.startExport();
        QVERIFY(d.isRunning());
        QTest::mouseClick(d.findChild<QPushButton *>(QStringLiteral("cancel")), Qt::LeftButton);
        QVERIFY(finished.wait(20000));
        QCOMPARE(finished.at(0).at(0).toBool(), false);
        QVERIFY(d.lastResult().cancelled);
        QVERIFY(finished.at(0).at(1).toString().contains(QStringLiteral("cancelled")));
        QVERIFY(!QFile::exists(out));
        QVERIFY(!d.isRunning());
    }

    void reportsAMissingCapture()
    {
        ExportDialog d(m_dir.filePath(QStringLiteral("missing.imucap")));
        QSignalSpy finished(&d, &ExportDialog::exportFinished);
        d.startExport();
        QVERIFY(finished.wait(5000));
        QCOMPARE(finished.at(0).at(0).toBool(), false);
        QVERIFY(finished.at(0).at(1).toString().contains(QStringLiteral("missing.imucap")));
    }

    // Every format's name (MCAP's and the vendor layout's are long) in view, nothing cut, in en
    // and zh_CN, at the dialog's own size: it opens so on a 1366x768 screen.
    void fitsInEveryLanguage_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
    }
    void fitsInEveryLanguage()
    {
        QFETCH(QString, language);
        ui::LanguageSwitcher switcher;
        QString error;
        QVERIFY2(switcher.setLanguage(language, QString::fromUtf8(IMUDESK_QM_DIR), &error), qPrintable(error));
        {
            ExportDialog d(m_small);
            d.setFormat(Format::Mcap);
            d.show();
            QVERIFY(QTest::qWaitForWindowExposed(&d));
            QVERIFY(test::layout::layoutSettled(d));
            QVERIFY2(d.width() <= 1366 && d.height() <= 700, qPrintable(QStringLiteral("%1x%2").arg(d.width()).arg(d.height())));
            const QStringList problems = test::layout::cutOrOutside(d);
            QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
            auto *format = d.findChild<QComboBox *>(QStringLiteral("format"));
            // The box is as wide as its longest name, which it shows whole when chosen.
            int widest = 0;
            for (int i = 0; i < format->count(); ++i)
                widest = std::max(widest, format->fontMetrics().horizontalAdvance(format->itemText(i)));
            QVERIFY2(format->width() >= widest, qPrintable(QStringLiteral("%1 < %2").arg(format->width()).arg(widest)));
            QCOMPARE(format->currentData().toInt(), int(Format::Mcap));
            if (const QString shots = qEnvironmentVariable("IMUDESK_TEST_SHOTS"); !shots.isEmpty())
                d.grab().save(QDir(shots).filePath(QStringLiteral("export-mcap-%1.png").arg(language)));
        }
        QVERIFY(switcher.setLanguage(QStringLiteral("en"), QString::fromUtf8(IMUDESK_QM_DIR), &error));
    }
};

IMUDESK_TEST_MAIN(TstExportDialog)
#include "tst_export_dialog.moc"
