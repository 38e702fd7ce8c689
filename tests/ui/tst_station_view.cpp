// The production station window (issue 22) on a simulated tray of 8 HI14 modules (one with a
// noisy gyro, one mounted on its side, one with firmware 1.6.6, five good ones) running a short
// plan (identify, firmware at least 1.7.1 without an image, static 2 s, attitude 1 s): the three
// faulty modules fail at their own step and their tiles name it, the summary line counts what the
// runner counts, a tile clicked while its module is under test opens the workspace when the test
// has ended, and a finished tile opens it at once. At 1366x768 and 1920x1080, in English and
// Simplified Chinese: the 8 tiles in 4 columns on the small window and more on the large one,
// every tile whole and inside the window, no scroll bar, no label cut short. Errors are reported
// without stopping the window. The plan editor writes an edited number into the JSON and lists a
// value typed outside its range as a problem; it edits a limit's marginal band (plan format 2),
// lists a band not below its limit, and says a version 1 plan is converted.
//
// The tray runs in this process (StationView::setSimulatedTrayInProcess: each module behind a
// sim::SimulatedTransport, its clock kTimeScale times faster than real time), so a loaded host
// cannot starve pseudo-terminals and their simulator threads into "did not answer" or "no
// data" failures (issue 33). The workspace the main window opens for a module still goes
// through a pseudo-terminal, and bench_station measures the tray over pseudo-terminals.
#include "../common/ui_families.h"
#include "../common/layout_checks.h"
#include "../common/station_plans.h"
#include "../common/test_main.h"
#include "sim/pty_simulator.h"
#include "ui/station/plan_editor_dialog.h"
#include "ui/station/station_model.h"
#include "core/station/station_runner.h"
#include "ui/station/station_view.h"
#include "workspace/device_workspace.h"
#include "workspace/language_switcher.h"
#include "workspace/main_window.h"

#include <QAbstractScrollArea>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTextDocumentFragment>
#include <QToolButton>
#include <QUrl>

#include <memory>

using namespace imudesk;
using station::StepKind;
using station::TestPlan;
using station::Verdict;

namespace {

const QSize kSmall(1366, 768);
const QSize kLarge(1920, 1080);
// The tray's clocks run this much faster than real time: the plan's 3 s of measuring (on the
// modules' clocks, as the runner measures) take under a second.
constexpr double kTimeScale = 4.0;

// The tray's faults (StationView::startSimulatedTray with faults, 8 modules): where each one
// fails, -1 for the good modules.
StepKind expectedFailure(int module, bool *fails)
{
    *fails = true;
    switch (module) {
    case 1: return StepKind::Static;   // noisy gyro
    case 3: return StepKind::Attitude; // on its side
    case 5: return StepKind::Firmware; // 1.6.6, and the plan has no image to update it
    default: break;
    }
    *fails = false;
    return StepKind::Identify;
}

TestPlan shortPlan()
{
    return test::shortTrayPlan(QStringLiteral("short tray test"));
}

QList<int> numbersIn(const QString &text)
{
    QList<int> out;
    static const QRegularExpression number(QStringLiteral("\\d+"));
    for (auto it = number.globalMatch(text); it.hasNext();)
        out << it.next().captured().toInt();
    return out;
}

// The layout test's check, with the tile grid (a scroll area that must not need to scroll)
// and every line of the tiles' multi-line labels checked too.
QStringList cutOrOutside(QWidget &top)
{
    return test::layout::cutOrOutside(top, {true, true});
}

// What a person would call broken in the station window, one line each.
QStringList stationProblems(ui::StationView &view, bool large)
{
    for (int round = 0; round < 3; ++round) {
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
        QCoreApplication::processEvents();
    }
    QStringList problems;
    // No scroll bar: the tiles all in view. (The port list shows whatever ports the machine has
    // and may scroll; the tray's eight fit its two rows.)
    for (const QScrollBar *bar : view.findChildren<QScrollBar *>())
        if (bar->isVisible())
            problems << QStringLiteral("a scroll bar (%1) in %2")
                            .arg(bar->orientation() == Qt::Vertical ? QStringLiteral("vertical")
                                                                    : QStringLiteral("horizontal"),
                                 bar->parentWidget() && bar->parentWidget()->parentWidget()
                                     ? bar->parentWidget()->parentWidget()->objectName()
                                     : QString());
    // Every tile whole: inside the window and the grid's viewport, as high as it asks, none
    // over another.
    const auto *scroll = view.findChild<QScrollArea *>(QStringLiteral("stationTileScroll"));
    if (!scroll || !scroll->isVisible())
        return problems << QStringLiteral("no tile area");
    const QRect viewport(scroll->viewport()->mapTo(&view, QPoint(0, 0)), scroll->viewport()->size());
    QList<QRect> tiles;
    for (int i = 0; i < view.tileCount(); ++i) {
        QWidget *t = view.tile(i);
        const QRect r(t->mapTo(&view, QPoint(0, 0)), t->size());
        if (!t->isVisible() || !view.rect().contains(r) || !viewport.contains(r))
            problems << QStringLiteral("tile %1 not whole in view: %2,%3 %4x%5 (viewport %6x%7)")
                            .arg(i)
                            .arg(r.x())
                            .arg(r.y())
                            .arg(r.width())
                            .arg(r.height())
                            .arg(viewport.width())
                            .arg(viewport.height());
        if (t->height() < t->sizeHint().height())
            problems << QStringLiteral("tile %1 %2 px high, wants %3").arg(i).arg(t->height()).arg(t->sizeHint().height());
        for (const QRect &other : std::as_const(tiles))
            if (other.intersects(r))
                problems << QStringLiteral("tile %1 over another").arg(i);
        tiles << r;
    }
    // 4 columns x 2 rows on a laptop's window, more columns on a large one.
    if (!large && view.tileColumns() != 4)
        problems << QStringLiteral("%1 columns at 1366 px, expected 4").arg(view.tileColumns());
    if (large && view.tileColumns() <= 4)
        problems << QStringLiteral("only %1 columns at 1920 px").arg(view.tileColumns());
    // The window could be that small: its least size fits the screen size.
    const QSize least = view.minimumSizeHint().expandedTo(view.minimumSize());
    const QSize room = large ? kLarge : kSmall;
    if (least.width() > room.width() || least.height() > room.height())
        problems << QStringLiteral("window needs at least %1x%2").arg(least.width()).arg(least.height());
    problems << cutOrOutside(view);
    return problems;
}

QString visibleText(const QWidget *tile, const char *name)
{
    const auto *label = tile->findChild<QLabel *>(QLatin1String(name));
    return label ? label->text() : QString();
}

} // namespace

class TstStationView : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    ui::LanguageSwitcher m_language;
    std::unique_ptr<ui::StationView> m_view;
    QStringList m_errors;

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCOMPARE(QGuiApplication::primaryScreen()->geometry().size(), kLarge);
        QString error;
        QVERIFY2(m_language.setLanguage(QStringLiteral("en"), QString::fromUtf8(IMUDESK_QM_DIR), &error),
                 qPrintable(error));
        m_view = std::make_unique<ui::StationView>();
        m_view->setRemembering(false);
        m_view->setErrorPresenter([this](const QString &message) { m_errors << message; });
        m_view->setReportFolder(m_dir.filePath(QStringLiteral("reports")));
        m_view->setSimulatedTrayInProcess(true, kTimeScale);
        QVERIFY2(m_view->startSimulatedTray(ui::StationView::kDemoTraySize, true, &error), qPrintable(error));
        QCOMPARE(m_view->simulatedPorts().size(), 8);
        QCOMPARE(m_view->checkedPorts(), m_view->simulatedPorts());
        m_view->setPlan(shortPlan(), QString());
        m_view->resize(kSmall);
        m_view->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
    }

    void cleanupTestCase()
    {
        m_view.reset(); // the runner's sessions close, then the simulated modules stop
    }

    void runsTheTray()
    {
        QSignalSpy opened(m_view.get(), &ui::StationView::openWorkspaceRequested);
        QElapsedTimer clock;
        clock.start();
        auto *startButton = m_view->findChild<QPushButton *>(QStringLiteral("startStation"));
        QVERIFY(startButton && startButton->isEnabled());
        startButton->click();
        QVERIFY(m_view->running());
        QCOMPARE(m_view->tileCount(), 8);
        QVERIFY(m_view->findChild<QPushButton *>(QStringLiteral("cancelStation"))->isEnabled());
        QVERIFY(!startButton->isEnabled());
        const station::StationRunner *runner = m_view->runner();
        QVERIFY(runner);

        // A tile clicked while its module is under test: no workspace yet, the summary says it waits.
        QTest::mouseClick(m_view->tile(0), Qt::LeftButton);
        QCOMPARE(opened.count(), 0);
        QVERIFY2(m_view->summaryText().contains(runner->module(0).port), qPrintable(m_view->summaryText()));

        // The tiles follow the run: a module is seen running on the view's clock.
        QTRY_VERIFY_WITH_TIMEOUT(visibleText(m_view->tile(2), "verdict") == station::verdictText(Verdict::Running),
                                 5000);

        QTRY_VERIFY_WITH_TIMEOUT(!m_view->running(), 120000);
        const qint64 runMs = clock.elapsed();
        // The waiting workspace opens once the port is free.
        QTRY_COMPARE_WITH_TIMEOUT(opened.count(), 1, 3000);
        QCOMPARE(opened.at(0).at(0).toString(), runner->module(0).port);
        QCOMPARE(opened.at(0).at(1).toInt(), ui::StationView::kSimulatedBaud);
        QVERIFY2(!m_view->summaryText().contains(QLatin1String("workspace")), qPrintable(m_view->summaryText()));

        // Verdicts: the three faults fail at their step, the others pass; each tile says so.
        for (int i = 0; i < 8; ++i) {
            const station::ModuleResult &r = runner->module(i);
            bool fails = false;
            const StepKind kind = expectedFailure(i, &fails);
            QTRY_COMPARE_WITH_TIMEOUT(visibleText(m_view->tile(i), "verdict"), station::verdictText(r.verdict), 1000);
            if (!fails) {
                QVERIFY2(r.verdict == Verdict::Pass, qPrintable(QStringLiteral("module %1: %2").arg(i).arg(r.failureSummary())));
                QCOMPARE(visibleText(m_view->tile(i), "failure"), QString());
                QCOMPARE(m_view->tile(i)->findChild<QProgressBar *>()->value(), 1000);
                continue;
            }
            QVERIFY2(r.verdict == Verdict::Fail, qPrintable(QStringLiteral("module %1 passed").arg(i)));
            QCOMPARE(r.steps[size_t(r.failedStep())].kind, kind);
            // The failing step named on the tile as it is seen, and its values in the failure line.
            const QString title = TestPlan::title(kind);
            QVERIFY2(visibleText(m_view->tile(i), "step").contains(title),
                     qPrintable(QStringLiteral("module %1 shows \"%2\"").arg(i).arg(visibleText(m_view->tile(i), "step"))));
            const auto *failure = m_view->tile(i)->findChild<QLabel *>(QStringLiteral("failure"));
            QVERIFY(!failure->text().isEmpty());
            // Shown whole (wrapped onto its lines) or elided with the whole text in the tooltip.
            const QString full = failure->toolTip().isEmpty() ? QString(failure->text()).replace(u'\n', u' ')
                                                              : failure->toolTip();
            QCOMPARE(full, r.failureSummary());
            QVERIFY(full.startsWith(title));
            // The step the plan turns off is not blamed on the failure.
            QVERIFY2(m_view->tile(i)->toolTip().contains(QStringLiteral("Save configuration: skipped (disabled in the plan)")),
                     qPrintable(m_view->tile(i)->toolTip()));
            // The tile's tooltip lists the values with their units.
            if (kind == StepKind::Static)
                QVERIFY2(m_view->tile(i)->toolTip().contains(QStringLiteral("°/s")), qPrintable(m_view->tile(i)->toolTip()));
        }

        // The summary line counts what the runner counts.
        const station::StationRunner::Summary s = runner->summary();
        QCOMPARE(s.passed, 5);
        QCOMPARE(s.failed, 3);
        QTRY_COMPARE_WITH_TIMEOUT(numbersIn(m_view->summaryText()).mid(0, 4),
                                  (QList<int>{s.passed, s.failed, s.running, s.waiting}), 1000);
        QVERIFY(m_view->findChild<QPushButton *>(QStringLiteral("rerunFailed"))->isEnabled());
        QVERIFY(!m_view->findChild<QPushButton *>(QStringLiteral("cancelStation"))->isEnabled());

        // The run folder: a report per module, no error shown.
        QVERIFY2(m_errors.isEmpty(), qPrintable(m_errors.join(QLatin1Char('\n'))));
        const QStringList pdfs = QDir(runner->runFolder()).entryList({QStringLiteral("*.pdf")}, QDir::Files);
        QCOMPARE(pdfs.size(), 8);
        qInfo("8 modules tested in %.1f s", double(runMs) / 1000.0);
    }

    void layout_data() { test::layout::addSizesAndLanguages({kSmall, kLarge}); }

    void layout()
    {
        QFETCH(QSize, size);
        QFETCH(QString, language);
        QVERIFY2(m_view->tileCount() == 8, "runsTheTray runs first");
        QString error;
        QVERIFY2(m_language.setLanguage(language, QString::fromUtf8(IMUDESK_QM_DIR), &error), qPrintable(error));
        m_view->resize(size);
        QTRY_COMPARE(m_view->size(), size);
        // A new language brings a new font: the nested layouts take a few rounds to follow it,
        // as they would between two frames on a screen. What is left after the bound is reported below.
        QStringList problems;
        const auto fits = [&] {
            problems = stationProblems(*m_view, size == kLarge);
            return problems.isEmpty();
        };
        (void)imudesk::test::waitFor(fits, 5000);
        // The failing tiles still name their step.
        for (int i = 0; i < 8; ++i) {
            const station::ModuleResult &r = m_view->runner()->module(i);
            if (r.failedStep() >= 0)
                QVERIFY2(visibleText(m_view->tile(i), "step").contains(r.steps[size_t(r.failedStep())].title),
                         qPrintable(visibleText(m_view->tile(i), "step")));
        }
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
        if (const QString shots = qEnvironmentVariable("IMUDESK_LAYOUT_SHOTS"); !shots.isEmpty())
            m_view->grab().save(QDir(shots).filePath(
                QStringLiteral("station-%1x%2-%3.png").arg(size.width()).arg(size.height()).arg(language)));
        QVERIFY(m_language.setLanguage(QStringLiteral("en"), QString::fromUtf8(IMUDESK_QM_DIR), &error));
    }

    void finishedTileOpensItsWorkspace()
    {
        QSignalSpy opened(m_view.get(), &ui::StationView::openWorkspaceRequested);
        QTest::mouseClick(m_view->tile(2), Qt::LeftButton);
        QCOMPARE(opened.count(), 1);
        QCOMPARE(opened.at(0).at(0).toString(), m_view->runner()->module(2).port);
        QCOMPARE(opened.at(0).at(1).toInt(), ui::StationView::kSimulatedBaud);
        // The keyboard too: Enter on a focused tile.
        m_view->tile(5)->setFocus();
        QTest::keyClick(m_view->tile(5), Qt::Key_Return);
        QCOMPARE(opened.count(), 2);
        QCOMPARE(opened.at(1).at(0).toString(), m_view->runner()->module(5).port);
    }

    // A finished tile's Report button opens that module's PDF, "Open run folder" the run's
    // folder (both through the opener: the desktop's viewers in the application).
    void finishedTileOpensItsReport()
    {
        QList<QUrl> opened;
        m_view->setUrlOpener([&opened](const QUrl &url) {
            opened << url;
            return true;
        });
        const station::StationRunner *runner = m_view->runner();
        QVERIFY(runner && !m_view->running());
        auto *report = m_view->tile(3)->findChild<QToolButton *>(QStringLiteral("openReport"));
        QVERIFY(report);
        QVERIFY(report->isVisible());
        QVERIFY(report->toolTip().contains(QDir::toNativeSeparators(runner->module(3).reportPath)));
        QVERIFY(report->focusPolicy() & Qt::TabFocus);
        // Inside its tile, not over the verdict.
        QVERIFY(m_view->tile(3)->rect().contains(QRect(report->mapTo(m_view->tile(3), QPoint(0, 0)), report->size())));
        QSignalSpy workspace(m_view.get(), &ui::StationView::openWorkspaceRequested);
        QTest::mouseClick(report, Qt::LeftButton);
        QCOMPARE(opened.size(), 1);
        QCOMPARE(opened.at(0), QUrl::fromLocalFile(runner->module(3).reportPath));
        QVERIFY(opened.at(0).toLocalFile().endsWith(QStringLiteral(".pdf")));
        QVERIFY(QFile::exists(opened.at(0).toLocalFile()));
        QCOMPARE(workspace.count(), 0); // the report, not the workspace
        // The keyboard: Space on the focused button.
        report->setFocus();
        QTest::keyClick(report, Qt::Key_Space);
        QCOMPARE(opened.size(), 2);

        auto *folder = m_view->findChild<QPushButton *>(QStringLiteral("openRunFolder"));
        QVERIFY(folder && folder->isEnabled() && !folder->toolTip().isEmpty());
        folder->click();
        QCOMPARE(opened.size(), 3);
        QCOMPARE(opened.at(2), QUrl::fromLocalFile(runner->runFolder()));
        // Its shortcut too.
        m_view->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_view.get()));
        QTest::keyClick(m_view.get(), Qt::Key_O, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(opened.size(), 4);

        // No viewer for PDFs on this computer: said, not silently ignored.
        const int errors = int(m_errors.size());
        m_view->setUrlOpener([](const QUrl &) { return false; });
        QVERIFY(!m_view->openReport(3));
        QCOMPARE(m_errors.size(), errors + 1);
        QVERIFY2(m_errors.last().contains(QFileInfo(runner->module(3).reportPath).fileName()), qPrintable(m_errors.last()));
        m_errors.clear();
        m_view->setUrlOpener({});
    }

    // Tools > Production station (Ctrl+Shift+P) opens one station window; a module's workspace
    // it asks for opens in the main window's free tab.
    void mainWindowOpensTheStation()
    {
        // A simulated module on a pseudo-terminal for the workspace (the tray's in-process
        // ports are names only the station's runner opens); it outlives the window.
        sim::SimOptions o;
        o.model = "HI14";
        o.baud = ui::StationView::kSimulatedBaud;
        sim::PtySimulator module(o);
        QString error;
        QVERIFY2(module.start(&error), qPrintable(error));
        ui::MainWindow window(imudesk::test::builtInFamilies());
        window.setErrorPresenter([](const QString &) {});
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        auto *action = window.findChild<QAction *>(QStringLiteral("stationAction"));
        QVERIFY(action);
        QCOMPARE(action->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
        QVERIFY(!action->text().isEmpty());
        action->trigger();
        QPointer<ui::StationView> station = window.station();
        QVERIFY(station);
        QVERIFY(station->isVisible());
        QVERIFY(station->isWindow());
        action->trigger(); // raised, not a second one
        QCOMPARE(window.station(), station.data());
        QCOMPARE(window.findChildren<ui::StationView *>().size(), 1);
        station->setRemembering(false);
        const QString port = module.devicePath(); // free: no test runs on it
        Q_EMIT station->openWorkspaceRequested(port, ui::StationView::kSimulatedBaud);
        QCOMPARE(window.currentWorkspace()->target(), port);
        QTRY_VERIFY_WITH_TIMEOUT(window.currentWorkspace()->state() == device::SessionState::Connected, 10000);
        // Closing the station window ends it.
        station->close();
        QTRY_VERIFY(!station);
        QVERIFY(!window.station());
    }

    void errorsDoNotStopTheWindow()
    {
        m_errors.clear();
        // A plan that does not load: said, and the plan in use stays.
        const QString broken = m_dir.filePath(QStringLiteral("broken-plan.json"));
        QFile f(broken);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(R"({"format": "imudesk-station-plan", "version": 1, "steps": [{"step": "static", "seconds": 9000}]})");
        f.close();
        QVERIFY(!m_view->openPlan(broken));
        QCOMPARE(m_errors.size(), 1);
        QVERIFY2(m_errors.first().contains(QStringLiteral("broken-plan.json")), qPrintable(m_errors.first()));
        QCOMPARE(m_view->plan().name, shortPlan().name);
        // A report folder that cannot be made (a file is in the way): said, nothing starts.
        const QString blocker = m_dir.filePath(QStringLiteral("not-a-folder"));
        QFile block(blocker);
        QVERIFY(block.open(QIODevice::WriteOnly));
        block.close();
        const QString before = m_view->reportFolder();
        m_view->setReportFolder(QDir(blocker).filePath(QStringLiteral("reports")));
        const station::StationRunner *previous = m_view->runner();
        QVERIFY(!m_view->start());
        QCOMPARE(m_errors.size(), 2);
        QVERIFY2(m_errors.at(1).contains(QStringLiteral("not-a-folder")), qPrintable(m_errors.at(1)));
        QCOMPARE(m_view->runner(), previous);
        QVERIFY(m_view->isVisible());
        m_view->setReportFolder(before);
    }

    // A folder typed into the Reports field is the one kept (Return) and the one the next run uses.
    void typedReportFolderIsUsed()
    {
        auto *field = m_view->findChild<QLineEdit *>(QStringLiteral("reportFolder"));
        QVERIFY(field);
        const QString before = m_view->reportFolder();
        const QString typed = m_dir.filePath(QStringLiteral("typed-reports"));
        field->setFocus();
        field->selectAll();
        QTest::keyClicks(field, QDir::toNativeSeparators(typed));
        QCOMPARE(m_view->reportFolder(), typed); // before Return: what the field says
        QTest::keyClick(field, Qt::Key_Return);
        QCOMPARE(m_view->settings().reportFolder, typed);
        m_view->setReportFolder(before);
        QCOMPARE(m_view->settings().reportFolder, before);
    }

    void planEditorWritesAnEditedNumber()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("plan.json"));
        QString error;
        QVERIFY2(shortPlan().save(path, &error), qPrintable(error));
        const auto loaded = TestPlan::load(path, &error);
        QVERIFY2(loaded, qPrintable(error));
        ui::PlanEditorDialog editor(*loaded, path);
        editor.show();
        QVERIFY(QTest::qWaitForWindowExposed(&editor));
        editor.selectStep(2); // static
        auto *seconds = qobject_cast<QDoubleSpinBox *>(editor.field(QStringLiteral("seconds")));
        QVERIFY(seconds);
        // Nothing cut in the editor either.
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
        QCoreApplication::processEvents();
        QVERIFY2(cutOrOutside(editor).isEmpty(), qPrintable(cutOrOutside(editor).join(QLatin1Char('\n'))));
        if (const QString shots = qEnvironmentVariable("IMUDESK_LAYOUT_SHOTS"); !shots.isEmpty())
            editor.grab().save(QDir(shots).filePath(QStringLiteral("station-plan-editor.png")));
        // The catalogue's unit, range and tooltip.
        QCOMPARE(seconds->suffix(), QStringLiteral(" s"));
        QCOMPARE(seconds->minimum(), 1.0);
        QCOMPARE(seconds->maximum(), 600.0);
        QVERIFY2(seconds->toolTip().contains(QStringLiteral("600 s")), qPrintable(seconds->toolTip()));
        auto *gyro = qobject_cast<QDoubleSpinBox *>(editor.field(QStringLiteral("gyro_std_max_dps")));
        QVERIFY(gyro);
        QCOMPARE(gyro->suffix(), QStringLiteral(" °/s"));
        seconds->selectAll();
        QTest::keyClicks(seconds, QStringLiteral("7"));
        QCOMPARE(seconds->value(), 7.0);
        QVERIFY(editor.isModified());
        QVERIFY(editor.windowTitle().endsWith(QLatin1Char('*')));
        QSignalSpy saved(&editor, &ui::PlanEditorDialog::saved);
        editor.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&editor));
        QTest::keyClick(&editor, Qt::Key_S, Qt::ControlModifier); // Ctrl+S
        QCOMPARE(saved.count(), 1);
        QVERIFY(!editor.isModified());
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QJsonArray steps = QJsonDocument::fromJson(f.readAll()).object().value(QStringLiteral("steps")).toArray();
        QCOMPARE(steps.at(2).toObject().value(QStringLiteral("step")).toString(), QStringLiteral("static"));
        QCOMPARE(steps.at(2).toObject().value(QStringLiteral("seconds")).toDouble(), 7.0);
        // The saved plan is the one announced, and it loads.
        QCOMPARE(saved.at(0).at(1).toString(), QFileInfo(path).absoluteFilePath());
        QVERIFY(TestPlan::load(path, &error));
    }

    void planEditorListsAValueOutOfRange()
    {
        ui::PlanEditorDialog editor(shortPlan(), QString());
        editor.show();
        QVERIFY(QTest::qWaitForWindowExposed(&editor));
        auto *problems = editor.findChild<QLabel *>(QStringLiteral("planProblems"));
        QVERIFY(problems);
        QVERIFY2(editor.problems().isEmpty(), qPrintable(editor.problems().join(QLatin1Char('\n'))));
        editor.selectStep(2);
        auto *seconds = qobject_cast<QDoubleSpinBox *>(editor.field(QStringLiteral("seconds")));
        QVERIFY(seconds);
        // 0 s is below the least duration (1 s): listed while it is typed.
        seconds->selectAll();
        QTest::keyClicks(seconds, QStringLiteral("0"));
        QCOMPARE(editor.problems().size(), 1);
        QVERIFY2(problems->text().contains(QStringLiteral("seconds")) && problems->text().contains(QStringLiteral("step 3")),
                 qPrintable(problems->text()));
        // Back within the range: the problem goes.
        seconds->selectAll();
        QTest::keyClicks(seconds, QStringLiteral("3"));
        QVERIFY2(editor.problems().isEmpty(), qPrintable(editor.problems().join(QLatin1Char('\n'))));
        QCOMPARE(editor.plan().steps[2].number("seconds"), 3.0);
        // A text out of its form: a firmware version that is none.
        editor.selectStep(0);
        auto *lowest = qobject_cast<QLineEdit *>(editor.field(QStringLiteral("firmware_min")));
        QVERIFY(lowest);
        lowest->selectAll();
        QTest::keyClicks(lowest, QStringLiteral("abc"));
        QVERIFY2(problems->text().contains(QStringLiteral("firmware_min")), qPrintable(problems->text()));
        // A step switched off in the list is off in the plan; Down moves the selected step.
        auto *list = editor.findChild<QListWidget *>(QStringLiteral("planSteps"));
        QVERIFY(list);
        list->item(3)->setCheckState(Qt::Unchecked);
        QVERIFY(!editor.plan().steps[3].enabled);
        editor.findChild<QPushButton *>(QStringLiteral("stepDown"))->click();
        QCOMPARE(editor.plan().steps[1].kind, StepKind::Identify);
        QCOMPARE(editor.currentStep(), 1);
    }

    void planEditorEditsAMarginalBand()
    {
        // A version 1 plan: the editor says it is converted, and everything still fits.
        QString error;
        const auto loaded = TestPlan::fromJson(R"({"format": "imudesk-station-plan", "version": 1, "name": "old plan",
                                                   "steps": [{"step": "identify"},
                                                             {"step": "static", "gyro_std_max_dps": 0.05}]})",
                                               &error);
        QVERIFY2(loaded, qPrintable(error));
        ui::PlanEditorDialog editor(*loaded, QString());
        editor.show();
        QVERIFY(QTest::qWaitForWindowExposed(&editor));
        auto *note = editor.findChild<QLabel *>(QStringLiteral("conversionNote"));
        QVERIFY(note);
        QVERIFY(note->isVisible());
        QVERIFY2(note->text().contains(QStringLiteral("version 1")), qPrintable(note->text()));
        editor.selectStep(1); // static
        auto *limit = qobject_cast<QDoubleSpinBox *>(editor.field(QStringLiteral("gyro_std_max_dps")));
        auto *check = editor.findChild<QCheckBox *>(QStringLiteral("marginalBand_gyro_std_max_dps"));
        auto *band = editor.findChild<QDoubleSpinBox *>(QStringLiteral("marginal_gyro_std_max_dps"));
        QVERIFY(limit && check && band);
        QVERIFY(!check->isChecked());
        QVERIFY(!band->isEnabled());
        QCOMPARE(band->suffix(), QStringLiteral(" °/s"));
        QVERIFY2(band->toolTip().contains(QStringLiteral("marginal"))
                     && band->toolTip().contains(QStringLiteral("°/s")),
                 qPrintable(band->toolTip()));
        // A parameter that is no limit has no band.
        QVERIFY(!editor.findChild<QDoubleSpinBox *>(QStringLiteral("marginal_seconds")));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
        QCoreApplication::processEvents();
        QVERIFY2(cutOrOutside(editor).isEmpty(), qPrintable(cutOrOutside(editor).join(QLatin1Char('\n'))));
        const QSize frame = editor.frameGeometry().size();
        QVERIFY2(frame.width() <= kSmall.width() && frame.height() <= kSmall.height(),
                 qPrintable(QStringLiteral("%1x%2").arg(frame.width()).arg(frame.height())));
        if (const QString shots = qEnvironmentVariable("IMUDESK_LAYOUT_SHOTS"); !shots.isEmpty())
            editor.grab().save(QDir(shots).filePath(QStringLiteral("station-plan-editor-band.png")));

        // Checked: a band below the limit at once; then one typed.
        check->click();
        QVERIFY(band->isEnabled());
        QVERIFY(editor.isModified());
        QCOMPARE(editor.plan().steps[1].marginalOf("gyro_std_max_dps").value_or(-1), 0.04);
        band->selectAll();
        QTest::keyClicks(band, QStringLiteral("0.03"));
        QCOMPARE(editor.plan().steps[1].marginalOf("gyro_std_max_dps").value_or(-1), 0.03);
        QVERIFY2(editor.problems().isEmpty(), qPrintable(editor.problems().join(QLatin1Char('\n'))));
        const QJsonObject written = QJsonDocument::fromJson(editor.plan().toJson())
                                        .object()
                                        .value(QStringLiteral("steps"))
                                        .toArray()
                                        .at(1)
                                        .toObject()
                                        .value(QStringLiteral("gyro_std_max_dps"))
                                        .toObject();
        QCOMPARE(written.value(QStringLiteral("high")).toDouble(), 0.05);
        QCOMPARE(written.value(QStringLiteral("marginal_high")).toDouble(), 0.03);

        // A band at or above the limit is a problem naming the step and the limit, whichever moved.
        auto *problems = editor.findChild<QLabel *>(QStringLiteral("planProblems"));
        QVERIFY(problems);
        band->selectAll();
        QTest::keyClicks(band, QStringLiteral("0.06"));
        QCOMPARE(editor.problems().size(), 1);
        QVERIFY2(problems->text().contains(QStringLiteral("step 2 (static)"))
                     && problems->text().contains(QStringLiteral("gyro_std_max_dps"))
                     && problems->text().contains(QStringLiteral("not below the limit")),
                 qPrintable(problems->text()));
        band->selectAll();
        QTest::keyClicks(band, QStringLiteral("0.03"));
        QVERIFY2(editor.problems().isEmpty(), qPrintable(editor.problems().join(QLatin1Char('\n'))));
        limit->selectAll();
        QTest::keyClicks(limit, QStringLiteral("0.02"));
        QCOMPARE(editor.problems().size(), 1);
        // Unchecked: no band, and no problem with it.
        check->click();
        QVERIFY(!band->isEnabled());
        QVERIFY(!editor.plan().steps[1].marginalOf("gyro_std_max_dps"));
        QVERIFY2(editor.problems().isEmpty(), qPrintable(editor.problems().join(QLatin1Char('\n'))));

        // Saved in version 2 with the band: the note goes, and the band comes back.
        check->click();
        band->selectAll();
        QTest::keyClicks(band, QStringLiteral("0.015"));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("plan.json"));
        QVERIFY(editor.saveTo(path));
        QVERIFY(!note->isVisible());
        const auto saved = TestPlan::load(path, &error);
        QVERIFY2(saved, qPrintable(error));
        QCOMPARE(saved->loadedVersion, 2);
        QCOMPARE(saved->steps[1].number("gyro_std_max_dps"), 0.02);
        QCOMPARE(saved->steps[1].marginalOf("gyro_std_max_dps").value_or(-1), 0.015);
    }
};

static int testMain(int argc, char **argv)
{
    return test::layout::runOnOffscreenScreen<TstStationView>(argc, argv, kLarge, QStringLiteral("tst_station_view"));
}

IMUDESK_TEST_CUSTOM_MAIN(testMain)

#include "tst_station_view.moc"
