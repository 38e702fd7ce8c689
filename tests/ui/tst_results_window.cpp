// Tools > Results (ui/results/results_window.h) on a results.sqlite made here with
// ResultsStore::commit: ten modules of one plan (passes, a failure, an ERROR, a marginal pass, two
// attempts of one serial number, a serial number that is an SQL injection) and one of a plan
// whose name is 10 kB long. The search lists them verbatim and filters them (the injection is a
// text like any other), the serial number with two attempts shows both with their steps,
// measurements and files (the PDF opens through the opener), the yield leaves the ERROR out, the
// trend has a point per PASS or FAIL module and the Cpk that ResultsStore::capability gives. A
// file that is no database, a missing file and a server that is not there are said in the
// window, which goes on working; a slow answer made stale by a newer question is dropped. At
// 1366x768 and 1920x1080, in English and Simplified Chinese, every tab fits with nothing cut,
// the long plan name elided. The station's line database dialog stores its fields, and its Test
// connection against a server that never answers says so without freezing the dialog; the
// station's summary words for the upload follow a real uploader.
#include "../common/ui_families.h"
#include "../common/layout_checks.h"
#include "../common/pg_server.h"
#include "../common/result_records.h"
#include "../common/test_main.h"
#include "core/results/results_store.h"
#include "core/results/results_uploader.h"
#include "ui/results/module_history_view.h"
#include "ui/results/module_table_model.h"
#include "ui/results/results_format.h"
#include "core/results/results_query.h"
#include "ui/results/results_window.h"
#include "ui/results/trend_view.h"
#include "ui/results/yield_view.h"
#include "ui/station/line_database_dialog.h"
#include "ui/station/station_tiles.h"
#include "ui/station/station_view.h"
#include "workspace/language_switcher.h"
#include "workspace/main_window.h"

#include <QAbstractItemModelTester>
#include <QApplication>
#include <QChartView>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QScatterSeries>
#include <QScreen>
#include <QScrollBar>
#include <QSettings>
#include <QTabWidget>
#include <QTableView>
#include <QTableWidget>
#include <QTcpServer>
#include <QTextDocumentFragment>
#include <QThread>
#include <QTreeWidget>
#include <QUrl>

#include <atomic>

using namespace imudesk;
using results::ModuleRecord;
using results::Outcome;
using results::ResultsStore;

namespace {

const QSize kSmall(1366, 768);
const QSize kLarge(1920, 1080);
const QString kPlan = QStringLiteral("HI14 incoming");
const QString kGyro = QStringLiteral("gyro_std_x");
const QString kHostile = QStringLiteral("x'); DROP TABLE run;--");

QString plain(const QString &toolTip)
{
    return QTextDocumentFragment::fromHtml(toolTip).toPlainText();
}

results::RunRecord makeRun(const QString &plan, const QString &station)
{
    results::RunRecord r = test::sampleRun(plan);
    r.stationId = station;
    r.imudeskVersion = QStringLiteral("test");
    return r;
}

// A module with an identify step and a static step holding the gyro's noise (limit 0.05, the
// marginal band ending at 0.04) and the temperature (for information); no files.
ModuleRecord makeModule(const results::RunRecord &run, const QString &serial, Outcome outcome, double gyro,
                        const QString &firmware, const QString &slot, int attempt, int minute)
{
    ModuleRecord m = test::sampleModule(run, serial, outcome, firmware, slot, attempt, minute);
    m.serialRaw = serial.toUtf8();
    m.marginal = outcome == Outcome::Pass && gyro > 0.04;
    m.artifacts.clear();
    results::MeasurementRecord &v = m.measurements[0];
    v.value = gyro;
    v.marginalHigh = 0.04;
    v.outcome = gyro > 0.05 ? Outcome::Fail : Outcome::Pass;
    v.marginal = gyro > 0.04 && gyro <= 0.05;
    m.measurements[1].value = 30 + minute * 0.5;
    return m;
}

// The Modules tab's row of a serial number's attempt.
int rowOf(const ui::ModuleTableModel *model, const QString &serial, int attempt = 1)
{
    for (int r = 0; r < model->rowCount(); ++r)
        if (model->module(r)->serial == serial && model->module(r)->attempt == attempt)
            return r;
    return -1;
}

} // namespace

class TstResultsWindow : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_db;
    QString m_longPlan;
    QString m_reports[2]; // the PDFs of SN-B's two attempts
    QString m_failUuid;   // SN-B's first attempt
    ui::LanguageSwitcher m_language;

    // A window reading the test's database, searched.
    std::unique_ptr<ui::ResultsWindow> openWindow(QList<QUrl> *opened = nullptr)
    {
        auto w = std::make_unique<ui::ResultsWindow>();
        w->setRemembering(false);
        if (opened)
            w->setUrlOpener([opened](const QUrl &url) {
                *opened << url;
                return true;
            });
        w->openLocation(m_db);
        return w;
    }

    static bool settle(ui::ResultsWindow &w)
    {
        return test::waitFor([&w] { return !w.busy(); }, 10000);
    }

    static void choosePlan(ui::ResultsWindow &w, const QString &plan)
    {
        auto *combo = w.findChild<QComboBox *>(QStringLiteral("filterPlan"));
        const int at = combo->findData(plan);
        QVERIFY2(at > 0, qPrintable(plan.left(40)));
        combo->setCurrentIndex(at);
        w.search();
        QVERIFY(settle(w));
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_dir.isValid());
        QString error;
        QVERIFY2(m_language.setLanguage(QStringLiteral("en"), QString::fromUtf8(IMUDESK_QM_DIR), &error), qPrintable(error));
        m_db = m_dir.filePath(QLatin1String(ResultsStore::kFileName));
        m_longPlan = QStringLiteral("long plan ") + QString(10 * 1024, QLatin1Char('P'));
        ResultsStore store;
        QVERIFY2(store.open(m_db, &error), qPrintable(error));
        const results::RunRecord run = makeRun(kPlan, QStringLiteral("bench-3"));
        const QString usb0 = QStringLiteral("/dev/ttyUSB0"), usb1 = QStringLiteral("/dev/ttyUSB1"),
                      usb2 = QStringLiteral("/dev/ttyUSB2");
        std::vector<ModuleRecord> modules{
            makeModule(run, QStringLiteral("SN-A"), Outcome::Pass, 0.012, QStringLiteral("1.7.1"), usb0, 1, 0),
            makeModule(run, QStringLiteral("SN-B"), Outcome::Fail, 0.41, QStringLiteral("1.7.1"), usb1, 1, 1),
            makeModule(run, QStringLiteral("SN-C"), Outcome::Error, 0.03, QStringLiteral("1.6.6"), usb2, 1, 2),
            makeModule(run, QStringLiteral("SN-D"), Outcome::Pass, 0.045, QStringLiteral("1.6.6"), usb0, 1, 3),
            makeModule(run, kHostile, Outcome::Pass, 0.015, QStringLiteral("1.7.1"), usb2, 1, 4),
            makeModule(run, QStringLiteral("SN-B"), Outcome::Pass, 0.02, QStringLiteral("1.7.1"), usb1, 2, 5),
        };
        const double more[] = {0.010, 0.014, 0.018, 0.011};
        for (int i = 0; i < 4; ++i)
            modules.push_back(makeModule(run, QStringLiteral("SN-E%1").arg(i), Outcome::Pass, more[i],
                                         QStringLiteral("1.7.1"), usb0, 1, 6 + i));
        // SN-B's two attempts have their PDF reports.
        QDir().mkpath(m_dir.filePath(QStringLiteral("runs")));
        for (int a = 0; a < 2; ++a) {
            m_reports[a] = m_dir.filePath(QStringLiteral("runs/SN-B-attempt%1.pdf").arg(a + 1));
            QFile pdf(m_reports[a]);
            QVERIFY(pdf.open(QIODevice::WriteOnly));
            pdf.write("%PDF-1.4\n% test\n");
            ModuleRecord &m = modules[a == 0 ? 1 : 5];
            m.artifacts.push_back({QStringLiteral("report"), QStringLiteral("application/pdf"), results::fileSha256(m_reports[a]),
                                   m_reports[a]});
        }
        m_failUuid = modules[1].uuid;
        const results::RunRecord other = makeRun(m_longPlan, QStringLiteral("bench-4"));
        modules.push_back(makeModule(other, QStringLiteral("SN-L"), Outcome::Pass, 0.01, QStringLiteral("1.7.1"), usb0, 1, 20));
        QVERIFY2(store.commit(modules, &error), qPrintable(error));
        QCOMPARE(store.moduleCount(), 11);
    }

    void cleanup()
    {
        QString error;
        QVERIFY2(m_language.setLanguage(QStringLiteral("en"), QString::fromUtf8(IMUDESK_QM_DIR), &error), qPrintable(error));
    }

    void searchesAndShowsHistory()
    {
        QList<QUrl> opened;
        auto w = openWindow(&opened);
        w->show();
        QVERIFY(settle(*w));
        QVERIFY2(w->problem().isEmpty(), qPrintable(w->problem()));
        ui::ModuleTableModel *model = w->modulesModel();
        QAbstractItemModelTester tester(model, QAbstractItemModelTester::FailureReportingMode::QtTest);
        QCOMPARE(model->rowCount(), 11);
        QVERIFY(w->findChild<ui::ElidedLabel *>(QStringLiteral("resultsSource"))->fullText().contains(m_db));
        // Newest first; outcomes in words; the injection shown as it is.
        QCOMPARE(model->module(0)->serial, QStringLiteral("SN-L"));
        const auto cell = [model](int row, int column) { return model->index(row, column).data().toString(); };
        QCOMPARE(cell(rowOf(model, QStringLiteral("SN-D")), ui::ModuleTableModel::Outcome), QStringLiteral("PASS (marginal)"));
        QCOMPARE(cell(rowOf(model, QStringLiteral("SN-C")), ui::ModuleTableModel::Outcome), QStringLiteral("ERROR"));
        QCOMPARE(cell(rowOf(model, QStringLiteral("SN-B")), ui::ModuleTableModel::Outcome), QStringLiteral("FAIL"));
        QCOMPARE(cell(rowOf(model, QStringLiteral("SN-B"), 2), ui::ModuleTableModel::Attempt), QStringLiteral("2"));
        QCOMPARE(cell(rowOf(model, kHostile), ui::ModuleTableModel::Serial), kHostile);
        QCOMPARE(model->index(rowOf(model, QStringLiteral("SN-C")), ui::ModuleTableModel::Outcome).data(Qt::ForegroundRole).value<QColor>(),
                 ui::ResultsFormat::outcomeColour(Outcome::Error));
        // The long plan: cut in the cell, whole in the tooltip.
        const QModelIndex longPlan = model->index(0, ui::ModuleTableModel::Plan);
        QVERIFY(longPlan.data().toString().size() <= ui::ResultsFormat::kMaxShownChars);
        QCOMPARE(plain(longPlan.data(Qt::ToolTipRole).toString()), m_longPlan);

        // The filter: a part of the serial number, the injection included (a text, not SQL).
        auto *serial = w->findChild<QLineEdit *>(QStringLiteral("filterSerial"));
        serial->setText(QStringLiteral("DROP TABLE"));
        QTest::keyClick(serial, Qt::Key_Return); // Enter searches
        QTRY_COMPARE(model->rowCount(), 1);
        QVERIFY(settle(*w));
        QCOMPARE(model->module(0)->serial, kHostile);
        serial->setText(QStringLiteral("SN-B"));
        w->search();
        QVERIFY(settle(*w));
        QCOMPARE(model->rowCount(), 2);
        {
            ResultsStore check;
            QString error;
            QVERIFY2(check.open(m_db, &error, false), qPrintable(error));
            QCOMPARE(check.moduleCount(), 11); // the run table is still there
        }

        // The first attempt selected: both attempts below, with their steps and measurements.
        const int first = model->rowOf(m_failUuid);
        QVERIFY(first >= 0);
        w->modulesTable()->selectRow(first);
        ui::ModuleHistoryView *history = w->history();
        QTRY_COMPARE(int(history->attempts().size()), 2);
        QTreeWidget *tree = history->tree();
        QCOMPARE(tree->topLevelItemCount(), 2);
        const char *outcomes[] = {"FAIL", "PASS"};
        const char *values[] = {"0.41", "0.02"};
        for (int a = 0; a < 2; ++a) {
            QTreeWidgetItem *attempt = tree->topLevelItem(a);
            QVERIFY2(attempt->text(ui::ModuleHistoryView::NameColumn).startsWith(QStringLiteral("Attempt %1").arg(a + 1)),
                     qPrintable(attempt->text(0)));
            QCOMPARE(attempt->text(ui::ModuleHistoryView::OutcomeColumn), QLatin1String(outcomes[a]));
            QCOMPARE(attempt->childCount(), 2); // identify, static
            QTreeWidgetItem *step = attempt->child(1);
            QCOMPARE(step->text(ui::ModuleHistoryView::NameColumn), QStringLiteral("Static noise and bias"));
            QCOMPARE(step->childCount(), 2);
            QTreeWidgetItem *gyro = step->child(0);
            QCOMPARE(gyro->text(ui::ModuleHistoryView::NameColumn), kGyro);
            QCOMPARE(gyro->text(ui::ModuleHistoryView::ValueColumn), QLatin1String(values[a]));
            QCOMPARE(gyro->text(ui::ModuleHistoryView::UnitColumn), QStringLiteral("°/s"));
            QCOMPARE(gyro->text(ui::ModuleHistoryView::LimitsColumn), QStringLiteral("≤ 0.05"));
            QCOMPARE(gyro->text(ui::ModuleHistoryView::MarginalColumn), QStringLiteral("≤ 0.04"));
            QCOMPARE(gyro->text(ui::ModuleHistoryView::OutcomeColumn), QLatin1String(outcomes[a]));
            QCOMPARE(step->child(1)->text(ui::ModuleHistoryView::LimitsColumn), QStringLiteral("for information"));
        }
        QCOMPARE(tree->currentItem(), tree->topLevelItem(0)); // the selected attempt

        // Both reports listed; the selected attempt's opens.
        QCOMPARE(history->files()->topLevelItemCount(), 2);
        auto *open = history->findChild<QPushButton *>(QStringLiteral("openArtifact"));
        QVERIFY(open->isEnabled());
        open->click();
        QCOMPARE(opened, QList<QUrl>{QUrl::fromLocalFile(m_reports[0])});
        QVERIFY(w->problem().isEmpty());
    }

    void yieldLeavesErrorsOut()
    {
        auto w = openWindow();
        QVERIFY(settle(*w));
        auto *table = w->yieldView()->table();
        QCOMPARE(table->rowCount(), 0); // no plan chosen: a line says to choose one
        choosePlan(*w, kPlan);
        QCOMPARE(w->modulesModel()->rowCount(), 10);
        ResultsStore store;
        QString error;
        QVERIFY(store.open(m_db, &error, false));
        const ResultsStore::Yield y = store.yield(kPlan, QDateTime(), &error);
        QCOMPARE(y.total.pass, 8);
        QCOMPARE(y.total.fail, 1);
        QCOMPARE(y.total.error, 1);
        QTRY_VERIFY(table->rowCount() > 0);
        // All, firmware 1.6.6 and 1.7.1, three slots.
        QCOMPARE(table->rowCount(), 1 + 2 + 3);
        const auto text = [table](int row, int column) { return table->item(row, column)->text(); };
        QCOMPARE(text(0, ui::YieldView::PassColumn), QStringLiteral("8"));
        QCOMPARE(text(0, ui::YieldView::FailColumn), QStringLiteral("1"));
        QCOMPARE(text(0, ui::YieldView::MarginalColumn), QStringLiteral("1"));
        QCOMPARE(text(0, ui::YieldView::ErrorColumn), QStringLiteral("1"));
        QCOMPARE(text(0, ui::YieldView::AbortedColumn), QStringLiteral("0"));
        // 8 / 9, the ERROR not counted (8 / 10 would be 80.0 %).
        QCOMPARE(text(0, ui::YieldView::YieldColumn), QStringLiteral("88.9 %"));
        QCOMPARE(text(0, ui::YieldView::YieldColumn), ui::YieldView::yieldText(y.total));
        // Firmware 1.6.6: SN-C (ERROR) and SN-D (a marginal pass): 100 %.
        QCOMPARE(text(1, ui::YieldView::GroupColumn), QStringLiteral("Firmware 1.6.6"));
        QCOMPARE(text(1, ui::YieldView::ErrorColumn), QStringLiteral("1"));
        QCOMPARE(text(1, ui::YieldView::YieldColumn), QStringLiteral("100.0 %"));
        QVERIFY(w->findChild<QLabel *>(QStringLiteral("yieldNote"))->text().contains(QStringLiteral("ERROR")));
    }

    void trendMatchesCapability()
    {
        auto w = openWindow();
        QVERIFY(settle(*w));
        choosePlan(*w, kPlan);
        ui::TrendView *trend = w->trendView();
        QTRY_COMPARE(trend->measurement(), kGyro);
        QVERIFY(settle(*w));
        ResultsStore store;
        QString error;
        QVERIFY(store.open(m_db, &error, false));
        const auto points = store.series(kPlan, kGyro, QDateTime(), QDateTime(), &error);
        QCOMPARE(int(points.size()), 9); // the ERROR module left out
        const ResultsStore::Capability c = ResultsStore::capability(points);
        QVERIFY(std::isfinite(c.cpk));
        QCOMPARE(trend->pointCount(), 9);
        QCOMPARE(trend->failureCount(), 1);
        QVERIFY2(trend->statsText().contains(QStringLiteral("n = 9")), qPrintable(trend->statsText()));
        QVERIFY2(trend->statsText().endsWith(QStringLiteral("Cpk = %1").arg(QString::number(c.cpk, 'f', 2))),
                 qPrintable(trend->statsText()));
        QVERIFY(trend->findChild<QLabel *>(QStringLiteral("trendStats"))->toolTip().contains(QStringLiteral("3σ")));
        // A measurement without limits: no Cpk.
        QComboBox *combo = trend->measurementCombo();
        combo->setCurrentIndex(combo->findData(QStringLiteral("temperature")));
        Q_EMIT combo->activated(combo->currentIndex());
        QTRY_VERIFY(trend->statsText().endsWith(QStringLiteral("Cpk = –")));
        QVERIFY(settle(*w));
        QCOMPARE(trend->pointCount(), 9);
    }

    void problemsAreSaidAndTheWindowGoesOn()
    {
        auto w = openWindow();
        w->show();
        QVERIFY(settle(*w));
        // A file that is not a results database.
        const QString junk = m_dir.filePath(QStringLiteral("notes.sqlite"));
        QFile f(junk);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("these are notes, not a database\n");
        f.close();
        w->openLocation(junk, true);
        QTRY_VERIFY(!w->problem().isEmpty());
        QVERIFY2(w->problem().contains(QStringLiteral("Choose another file")), qPrintable(w->problem()));
        QCOMPARE(w->modulesModel()->rowCount(), 0);
        // A file that is not there yet: not created.
        const QString missing = m_dir.filePath(QStringLiteral("elsewhere/results.sqlite"));
        w->openLocation(missing);
        QVERIFY(settle(*w));
        QVERIFY2(w->problem().contains(QStringLiteral("no results")), qPrintable(w->problem()));
        QVERIFY(!QFileInfo::exists(missing));
        // A server that accepts the connection and never answers: the window keeps answering
        // while the read waits for its timeout, then says what to do.
        QTcpServer silent;
        QVERIFY(silent.listen(QHostAddress::LocalHost));
        QElapsedTimer clock;
        clock.start();
        w->openLocation(QStringLiteral("postgresql://station:secret@127.0.0.1:%1/imudesk").arg(silent.serverPort()));
        QVERIFY2(clock.elapsed() < 500, "openLocation waited for the server");
        QVERIFY(w->busy());
        QVERIFY(w->findChild<QProgressBar *>(QStringLiteral("resultsBusy"))->isVisible());
        int ticks = 0;
        QTimer tick;
        connect(&tick, &QTimer::timeout, this, [&ticks] { ++ticks; });
        tick.start(100);
        QTRY_VERIFY_WITH_TIMEOUT(!w->problem().isEmpty(), 20000);
        QVERIFY2(ticks >= 5, qPrintable(QString::number(ticks)));
        QVERIFY2(w->problem().contains(QStringLiteral("line database")), qPrintable(w->problem()));
        QVERIFY(!w->problem().contains(QStringLiteral("secret")));
        QVERIFY(!w->findChild<ui::ElidedLabel *>(QStringLiteral("resultsSource"))->fullText().contains(QStringLiteral("secret")));
        // And back to the good file: the problem goes, the modules come.
        w->openLocation(m_db);
        QVERIFY(settle(*w));
        QVERIFY(w->problem().isEmpty());
        QCOMPARE(w->modulesModel()->rowCount(), 11);
    }

    void staleAnswersAreDropped()
    {
        results::ResultsQuery query;
        QSignalSpy busy(&query, &ui::ResultsQuery::busyChanged);
        QStringList applied;
        // The first is under way when the second comes: its answer is dropped. The third is on
        // another channel and answers.
        std::atomic<bool> started{false};
        query.post(0, [&applied, &started](ResultsStore &) -> std::function<void()> {
            started = true;
            QThread::msleep(300);
            return [&applied] { applied << QStringLiteral("old"); };
        });
        QVERIFY(test::waitFor([&started] { return started.load(); }, 5000));
        query.post(0, [&applied](ResultsStore &) -> std::function<void()> { return [&applied] { applied << QStringLiteral("new"); }; });
        query.post(1, [&applied](ResultsStore &) -> std::function<void()> { return [&applied] { applied << QStringLiteral("other"); }; });
        QCOMPARE(query.outstanding(), 3);
        QTRY_VERIFY(!query.busy());
        QCOMPARE(applied, (QStringList{QStringLiteral("new"), QStringLiteral("other")}));
        QCOMPARE(busy.count(), 2);
        // A job that has not started when a newer one comes is skipped, not run.
        int ran = 0;
        query.post(2, [](ResultsStore &) -> std::function<void()> {
            QThread::msleep(200);
            return {};
        });
        query.post(3, [&ran](ResultsStore &) -> std::function<void()> {
            ++ran;
            return {};
        });
        query.post(3, [&ran](ResultsStore &) -> std::function<void()> {
            ++ran;
            return {};
        });
        QTRY_VERIFY(!query.busy());
        QCOMPARE(ran, 1);
    }

    void layout_data() { test::layout::addSizesAndLanguages({kSmall, kLarge}); }

    void layout()
    {
        QFETCH(QSize, size);
        QFETCH(QString, language);
        QString error;
        QVERIFY2(m_language.setLanguage(language, QString::fromUtf8(IMUDESK_QM_DIR), &error), qPrintable(error));
        auto w = openWindow();
        w->resize(size);
        w->show();
        QVERIFY(QTest::qWaitForWindowExposed(w.get()));
        QVERIFY(settle(*w));
        QTRY_COMPARE(w->size(), size);
        // The window could be that small.
        const QSize least = w->minimumSizeHint().expandedTo(w->minimumSize());
        QVERIFY2(least.width() <= size.width() && least.height() <= size.height(),
                 qPrintable(QStringLiteral("needs at least %1x%2").arg(least.width()).arg(least.height())));
        // SN-B's history below the table, then the yield and the trend of the plan.
        w->modulesTable()->selectRow(rowOf(w->modulesModel(), QStringLiteral("SN-B"), 2));
        QTRY_COMPARE(int(w->history()->attempts().size()), 2);
        const auto fits = [&](const QString &what) {
            QStringList problems;
            (void)test::waitFor(
                [&] {
                    (void)test::layout::layoutSettled(*w);
                    problems = test::layout::cutOrOutside(*w);
                    // Every column of the table in view: no horizontal scrolling.
                    if (w->modulesTable()->isVisible() && w->modulesTable()->horizontalScrollBar()->isVisible())
                        problems << QStringLiteral("the modules table scrolls sideways");
                    return problems.isEmpty();
                },
                5000);
            if (!problems.isEmpty())
                qWarning("%s: %s", qPrintable(what), qPrintable(problems.join(QLatin1Char('\n'))));
            return problems.isEmpty();
        };
        QVERIFY(fits(QStringLiteral("modules")));
        // IMUDESK_TEST_SHOTS: each tab at 1366x768 as a PNG there (the user guide's pictures).
        const QString shots = size == kSmall ? qEnvironmentVariable("IMUDESK_TEST_SHOTS") : QString();
        const auto shoot = [&](const char *name) {
            if (!shots.isEmpty())
                QVERIFY(w->grab().save(QDir(shots).filePath(QStringLiteral("%1-%2.png").arg(QLatin1String(name), language))));
        };
        shoot("results-window");
        choosePlan(*w, kPlan);
        w->tabs()->setCurrentIndex(ui::ResultsWindow::YieldTab);
        QVERIFY(fits(QStringLiteral("yield")));
        shoot("results-yield");
        w->tabs()->setCurrentIndex(ui::ResultsWindow::TrendTab);
        QTRY_COMPARE(w->trendView()->pointCount(), 9);
        QVERIFY(fits(QStringLiteral("trend")));
        shoot("results-trend");
        // The 10 kB plan chosen: the combo box keeps its width, the name whole in its tooltip.
        w->tabs()->setCurrentIndex(ui::ResultsWindow::ModulesTab);
        auto *plan = w->findChild<QComboBox *>(QStringLiteral("filterPlan"));
        const int width = plan->width();
        choosePlan(*w, m_longPlan);
        QVERIFY(test::layout::layoutSettled(*w));
        QCOMPARE(plan->width(), width);
        QCOMPARE(plain(plan->itemData(plan->currentIndex(), Qt::ToolTipRole).toString()), m_longPlan);
        QCOMPARE(w->modulesModel()->rowCount(), 1);
        QCOMPARE(w->size(), size);
        QVERIFY(fits(QStringLiteral("long plan")));
        QVERIFY(m_language.setLanguage(QStringLiteral("en"), QString::fromUtf8(IMUDESK_QM_DIR), &error));
    }

    void openedFromTheMainWindow()
    {
        QSettings().remove(QStringLiteral("station"));
        ui::MainWindow main(imudesk::test::builtInFamilies());
        auto *action = main.findChild<QAction *>(QStringLiteral("resultsAction"));
        QVERIFY(action);
        QCOMPARE(action->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_D));
        action->trigger();
        ui::ResultsWindow *w = main.findChild<ui::ResultsWindow *>();
        QVERIFY(w && w->isVisible());
        QVERIFY(w->isWindow());
        // The station's saved database (nothing saved here: the default report folder's file).
        QCOMPARE(w->location(), station::StationSettings().resultsDatabase());
        action->trigger();
        QCOMPARE(main.findChildren<ui::ResultsWindow *>().size(), 1); // one instance
        QVERIFY(settle(*w));
        w->close();
    }

    void sizeAndPlaceAreRemembered()
    {
        QSettings().remove(QStringLiteral("results"));
        {
            ui::ResultsWindow w;
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            w.resize(1000, 640);
            QTRY_COMPARE(w.size(), QSize(1000, 640));
            w.close();
        }
        QVERIFY(!QSettings().value(QLatin1String(ui::ResultsWindowSettings::kGeometryKey)).toByteArray().isEmpty());
        ui::ResultsWindow again;
        QCOMPARE(again.size(), QSize(1000, 640));
        QSettings().remove(QStringLiteral("results"));
    }

    void lineDatabaseDialogStoresItsFields()
    {
        QSettings().remove(QStringLiteral("station"));
        ui::StationView view;
        view.setErrorPresenter([](const QString &) {});
        auto *button = view.findChild<QPushButton *>(QStringLiteral("lineDatabaseButton"));
        QVERIFY(button);
        button->click();
        auto *dialog = view.findChild<ui::LineDatabaseDialog *>();
        QVERIFY(dialog && dialog->isVisible());
        auto *url = dialog->findChild<QLineEdit *>(QStringLiteral("lineDatabaseUrl"));
        auto *folder = dialog->findChild<QLineEdit *>(QStringLiteral("artifactFolder"));
        auto *ok = dialog->findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
        QVERIFY(url->toolTip().contains(QStringLiteral("~/.pgpass")));
        url->setText(QStringLiteral("not a url"));
        QVERIFY(!ok->isEnabled());
        url->setText(QStringLiteral("postgresql://station:pw@line.example/imudesk"));
        QVERIFY(ok->isEnabled());
        QVERIFY(dialog->findChild<QLabel *>(QStringLiteral("lineDatabaseNote"))->text().contains(QStringLiteral("password")));
        url->setText(QStringLiteral("postgresql://station@line.example/imudesk"));
        folder->setText(m_dir.filePath(QStringLiteral("shared")));
        ok->click();
        QTRY_VERIFY(!dialog->isVisible());
        QCOMPARE(view.settings().lineDatabase, QStringLiteral("postgresql://station@line.example/imudesk"));
        QCOMPARE(view.settings().artifactFolder, m_dir.filePath(QStringLiteral("shared")));
        QSettings saved;
        QCOMPARE(saved.value(QLatin1String(station::StationSettings::kLineDatabaseKey)).toString(),
                 QStringLiteral("postgresql://station@line.example/imudesk"));
        QCOMPARE(saved.value(QLatin1String(station::StationSettings::kArtifactFolderKey)).toString(), m_dir.filePath(QStringLiteral("shared")));
        // What the results window reads now.
        station::StationSettings loaded;
        loaded.load(saved);
        QCOMPARE(loaded.resultsDatabase(), QStringLiteral("postgresql://station@line.example/imudesk"));
        QCOMPARE(ui::ResultsWindow::stationDatabase(), loaded.resultsDatabase());
        saved.remove(QStringLiteral("station"));
    }

    void testConnectionDoesNotFreeze()
    {
        // A server that takes the connection and never answers: the connect timeout (5 s) ends it.
        QTcpServer silent;
        QVERIFY(silent.listen(QHostAddress::LocalHost));
        ui::LineDatabaseDialog dialog(QStringLiteral("postgresql://station@127.0.0.1:%1/imudesk").arg(silent.serverPort()),
                                      QString());
        dialog.show();
        auto *test = dialog.findChild<QPushButton *>(QStringLiteral("testConnection"));
        QVERIFY(test->isEnabled());
        QElapsedTimer clock;
        clock.start();
        test->click();
        QVERIFY2(clock.elapsed() < 500, "the click waited for the server");
        QVERIFY(dialog.testing());
        QVERIFY(!test->isEnabled());
        QVERIFY(dialog.testResult().startsWith(QStringLiteral("Connecting")));
        int ticks = 0;
        QTimer tick;
        connect(&tick, &QTimer::timeout, this, [&ticks] { ++ticks; });
        tick.start(100);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog.testing(), 20000);
        QVERIFY2(ticks >= 5, qPrintable(QString::number(ticks)));
        QVERIFY(!dialog.testResult().isEmpty());
        QVERIFY2(!dialog.testResult().startsWith(QStringLiteral("Connected")), qPrintable(dialog.testResult()));
        QVERIFY(test->isEnabled());
    }

    void testConnectionToARealServer()
    {
        test::PgServer server;
        QString error;
        if (!server.start(&error))
            QSKIP(qPrintable(error));
        ui::LineDatabaseDialog dialog(server.url(), QString());
        dialog.findChild<QPushButton *>(QStringLiteral("testConnection"))->click();
        QTRY_VERIFY_WITH_TIMEOUT(!dialog.testing(), 30000);
        QCOMPARE(dialog.testResult(), QStringLiteral("Connected: schema %1").arg(ResultsStore::kSchemaVersion));
    }

    void uploadStatusFollowsTheUploader()
    {
        ui::LineDatabaseStatus status;
        QCOMPARE(status.text(), QString());
        // An outbox with two modules, and a server: here an SQLite file, which the uploader
        // opens the same way.
        const QString outbox = m_dir.filePath(QStringLiteral("outbox.sqlite"));
        {
            ResultsStore store;
            QString error;
            QVERIFY(store.open(outbox, &error));
            const results::RunRecord run = makeRun(kPlan, QStringLiteral("bench-5"));
            QVERIFY(store.commit({makeModule(run, QStringLiteral("U1"), Outcome::Pass, 0.01, QStringLiteral("1.7.1"), QString(), 1, 0),
                                  makeModule(run, QStringLiteral("U2"), Outcome::Pass, 0.01, QStringLiteral("1.7.1"), QString(), 1, 1)},
                                 &error));
            QCOMPARE(store.pendingCount(), 2);
        }
        {
            results::UploaderOptions o;
            o.outbox = outbox;
            o.server = m_dir.filePath(QStringLiteral("line.sqlite"));
            results::ResultsUploader uploader(o);
            status.follow(&uploader);
            QVERIFY(status.text().contains(QStringLiteral("connecting")));
            uploader.start();
            QTRY_COMPARE(status.text(), QStringLiteral(" · every result uploaded"));
            QVERIFY(status.toolTip().contains(o.server));
        }
        QCOMPARE(status.text(), QString()); // the uploader went with its run
        {
            results::UploaderOptions o;
            o.outbox = outbox;
            o.server = QStringLiteral("postgresql://nobody@127.0.0.1:1/none");
            results::ResultsUploader uploader(o);
            status.follow(&uploader);
            uploader.start();
            QTRY_VERIFY_WITH_TIMEOUT(status.text().startsWith(QStringLiteral(" · upload failing: ")), 15000);
            QVERIFY2(status.toolTip().contains(QStringLiteral("nothing is lost")), qPrintable(status.toolTip()));
        }
    }
};

static int testMain(int argc, char **argv)
{
    return test::layout::runOnOffscreenScreen<TstResultsWindow>(argc, argv, kLarge, QStringLiteral("tst_results_window"));
}

IMUDESK_TEST_CUSTOM_MAIN(testMain)

#include "tst_results_window.moc"
