// AnalysisWindow offscreen: analysing a generated capture fills the statistics table, the
// summary (rate, random walk, bias instability, recommended length), the interval histogram
// and the log-log Allan chart; a file that is no recording is reported.
#include "../common/motion_csv.h"
#include "../common/synthetic_capture.h"
#include "../common/test_main.h"
#include "charts/analysis_window.h"
#include "workspace/language_switcher.h"

#include <QAbstractSeries>
#include <QBarSeries>
#include <QChart>
#include <QFile>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QGraphicsTextItem>
#include <QLogValueAxis>
#include <QScopeGuard>
#include <QScreen>
#include <QScrollBar>
#include <QSettings>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <random>

using namespace imudesk;
using ui::AnalysisWindow;

class TstAnalysisWindow : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private Q_SLOTS:
    void analysesACapture()
    {
        const QString path = m_dir.filePath(QStringLiteral("noise.imucap"));
        synthetic::CaptureSpec spec;
        spec.frames = 20000; // 20 s at 1 kHz
        QVERIFY(synthetic::writeCapture(path, spec) > 0);
        AnalysisWindow w;
        QSignalSpy done(&w, &AnalysisWindow::analysisFinished);
        w.analyzeFile(path, 100.0);
        QVERIFY(done.wait(20000));
        QVERIFY2(done.at(0).at(0).toBool(), qPrintable(done.at(0).at(1).toString()));
        QTableWidget *t = w.statsTable();
        QCOMPARE(t->rowCount(), 14);
        QCOMPARE(t->item(0, 0)->text(), QStringLiteral("acc_x"));
        QCOMPARE(t->item(2, 1)->text(), QStringLiteral("G"));
        QVERIFY(std::abs(t->item(2, 2)->text().toDouble() - 1.0) < 0.01); // acc_z mean ~ 1 G
        QVERIFY(w.summaryText().contains(QStringLiteral("output rate 1000.00 Hz")));
        QVERIFY(w.summaryText().contains(QStringLiteral("ARW")));
        QVERIFY(w.summaryText().contains(QStringLiteral("1.4 h"))); // 51 x 100 s
        QCOMPARE(w.histogramChart()->series().size(), 1);
        QVERIFY(qobject_cast<QBarSeries *>(w.histogramChart()->series().front()));
        QCOMPARE(w.allanChart()->series().size(), 6);
        QCOMPARE(w.allanChart()->axes(Qt::Horizontal).size(), 1);
        QVERIFY(qobject_cast<QLogValueAxis *>(w.allanChart()->axes(Qt::Horizontal).front()));
        QVERIFY(qobject_cast<QLogValueAxis *>(w.allanChart()->axes(Qt::Vertical).front()));
        w.resize(1000, 700);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
    }

    // Issue 53: a module that moved gets no Allan figures, and the window says why.
    void allanOnlyOfAStillModule_data()
    {
        QTest::addColumn<int>("motion");
        QTest::addColumn<bool>("moved");
        QTest::newRow("still") << int(motion_csv::Motion::Still) << false;
        QTest::newRow("moved by hand") << int(motion_csv::Motion::ByHand) << true;
    }
    void allanOnlyOfAStillModule()
    {
        QFETCH(int, motion);
        QFETCH(bool, moved);
        const QString path = m_dir.filePath(QStringLiteral("motion-%1.csv").arg(motion));
        QVERIFY(motion_csv::write(path, motion_csv::Motion(motion), 30));
        AnalysisWindow w;
        QSignalSpy done(&w, &AnalysisWindow::analysisFinished);
        w.analyzeFile(path, 10.0);
        QVERIFY(done.wait(20000));
        QVERIFY2(done.at(0).at(0).toBool(), qPrintable(done.at(0).at(1).toString()));
        const QString reason = QStringLiteral("the module moved: Allan deviation needs a still recording");
        QCOMPARE(w.summaryText().contains(reason), moved);
        QCOMPARE(w.summaryText().contains(QStringLiteral("ARW")), !moved);
        QCOMPARE(w.summaryText().contains(QStringLiteral("bias instability")), !moved);
        QCOMPARE(w.allanChart()->series().isEmpty(), moved);
        QCOMPARE(w.allanChart()->title().contains(reason), moved);
        QCOMPARE(w.statsTable()->rowCount(), 14); // the statistics stay
    }

    // A recording too short for τ = 1 s: no Allan figures either, and the window says so.
    void tooShortARecordingIsNotJudged()
    {
        const QString path = m_dir.filePath(QStringLiteral("short.csv"));
        QVERIFY(motion_csv::write(path, motion_csv::Motion::Still, 1.5));
        AnalysisWindow w;
        QSignalSpy done(&w, &AnalysisWindow::analysisFinished);
        w.analyzeFile(path, 10.0);
        QVERIFY(done.wait(20000));
        QVERIFY2(done.at(0).at(0).toBool(), qPrintable(done.at(0).at(1).toString()));
        const QString reason = QStringLiteral("cannot judge: the recording is too short");
        QVERIFY2(w.summaryText().contains(reason), qPrintable(w.summaryText()));
        QVERIFY(!w.summaryText().contains(QStringLiteral("ARW")));
        QVERIFY(w.allanChart()->series().isEmpty());
        QVERIFY(w.allanChart()->title().contains(reason));
        QCOMPARE(w.statsTable()->rowCount(), 14);
    }

    // Issue 53: the charts' text is whole at the size the window opens at on a laptop's screen
    // (the histogram's twenty bin labels side by side and the Allan chart's y title were cut to
    // "..." at 1366x768).
    void chartTextIsWhole_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN"); // taller rows, wider headers
    }

    void chartTextIsWhole()
    {
        QFETCH(QString, language);
        ui::LanguageSwitcher languages;
        QString error;
        QVERIFY2(languages.setLanguage(language, QString::fromUtf8(IMUDESK_QM_DIR), &error), qPrintable(error));
        const auto backToEnglish = qScopeGuard([&] { languages.setLanguage(QStringLiteral("en"), QString::fromUtf8(IMUDESK_QM_DIR)); });
        QSettings().remove(QStringLiteral("analysisWindow"));
        // A vendor CSV whose device clock steps 5 to 15 ms (a module on a busy USB hub): twenty bins.
        const QString path = m_dir.filePath(QStringLiteral("bins.csv"));
        {
            std::mt19937 rng(3);
            std::uniform_int_distribution<int> step(5, 15);
            std::normal_distribution<double> noise;
            std::string text = std::string(decode::vendor_csv::hi91Header()) + '\n';
            uint32_t t = 1000;
            for (int i = 0; i < 2000; ++i) {
                protocol::hipnuc::Hi91 h;
                h.systemTime = t;
                h.acc = {float(-0.026 + 0.0008 * noise(rng)), float(-0.044 + 0.0008 * noise(rng)), float(0.9986 + 0.0008 * noise(rng))};
                h.gyr = {float(0.1 + 0.02 * noise(rng)), float(-0.07 + 0.02 * noise(rng)), float(-0.18 + 0.02 * noise(rng))};
                h.temperature = 30;
                decode::vendor_csv::appendRow(text, h, double(t));
                t += uint32_t(step(rng));
            }
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(text.data(), qint64(text.size()));
        }
        AnalysisWindow w;
        QSignalSpy done(&w, &AnalysisWindow::analysisFinished);
        // The size it opens at on a 1366x768 laptop screen (less a panel of 28 px), charts side by side.
        w.resize(AnalysisWindow::kDefaultSize.boundedTo(QSize(1366, 740) * 95 / 100));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.analyzeFile(path, 100.0);
        QVERIFY(done.wait(20000));
        QVERIFY2(done.at(0).at(0).toBool(), qPrintable(done.at(0).at(1).toString()));
        // The text a chart shows: its title, its axes' titles and tick labels, its legend.
        auto shown = [](QChart *chart) {
            QStringList texts;
            for (QGraphicsItem *item : chart->scene()->items()) {
                QString text;
                if (auto *t = dynamic_cast<QGraphicsTextItem *>(item))
                    text = t->toPlainText();
                else if (auto *t = dynamic_cast<QGraphicsSimpleTextItem *>(item))
                    text = t->text();
                if (!text.isEmpty() && item->isVisible())
                    texts << text;
            }
            return texts;
        };
        // Once the charts have laid their axes out.
        QTRY_VERIFY(shown(w.histogramChart()).size() >= 5 && shown(w.allanChart()).size() >= 5);
        for (QChart *chart : {w.histogramChart(), w.allanChart()})
            for (const QString &text : shown(chart))
                QVERIFY2(!text.contains(QLatin1String("...")) && !text.contains(QChar(0x2026)), qPrintable(text));
        QVERIFY(w.histogramChart()->series().size() == 1);
        // The table beside the charts shows every column whole: no scrolling, no cut number.
        QTableWidget *t = w.statsTable();
        QCOMPARE(t->horizontalScrollBar()->maximum(), 0);
        const QFontMetrics fm(t->font());
        for (int row = 0; row < t->rowCount(); ++row)
            for (int col = 0; col < t->columnCount(); ++col)
                QVERIFY2(fm.horizontalAdvance(t->item(row, col)->text()) + 6 <= t->columnWidth(col),
                         qPrintable(t->item(row, col)->text()));
        w.close();
        QSettings().remove(QStringLiteral("analysisWindow"));
    }

    // It opens big enough to read (within the screen), and as it was last closed.
    void opensReadableAndRemembersItsSize()
    {
        QSettings().remove(QStringLiteral("analysisWindow"));
        {
            AnalysisWindow w;
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            const QSize room = w.screen()->availableGeometry().size();
            QCOMPARE(w.size(), AnalysisWindow::kDefaultSize.boundedTo(room * 95 / 100));
            w.resize(700, 500);
            QTRY_COMPARE(w.size(), QSize(700, 500));
            w.close();
        }
        AnalysisWindow again;
        again.show();
        QVERIFY(QTest::qWaitForWindowExposed(&again));
        QCOMPARE(again.size(), QSize(700, 500));
        again.close();
        QSettings().remove(QStringLiteral("analysisWindow"));
    }

    void reportsOtherFiles()
    {
        const QString path = m_dir.filePath(QStringLiteral("notes.txt"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("not a recording\n");
        f.close();
        AnalysisWindow w;
        QSignalSpy done(&w, &AnalysisWindow::analysisFinished);
        w.analyzeFile(path);
        QVERIFY(done.wait(5000));
        QCOMPARE(done.at(0).at(0).toBool(), false);
        QVERIFY(w.summaryText().contains(QStringLiteral("neither an ImuDesk capture, a vendor CSV")));
    }
};

IMUDESK_TEST_MAIN(TstAnalysisWindow)
#include "tst_analysis_window.moc"
