// MainWindow offscreen against a simulated HI14 on a pseudo-terminal: live values,
// identity and rates in the status bar, the console, screenshots, run-time language.
#include "../common/ui_families.h"
#include "../common/layout_checks.h"
#include "../common/hipnuc_link.h"
#include "../common/test_main.h"
#include "recording/export_dialog.h"
#include "recording/recording_controls.h"
#include "workspace/family_ui.h"
#include "workspace/connection_bar.h"
#include "workspace/tool_actions.h"
#include "workspace/console_widget.h"
#include "workspace/language_switcher.h"
#include "attitude/attitude_widget.h"
#include "charts/chart_panel.h"
#include "charts/comparison_chart.h"
#include "workspace/help_dialogs.h"
#include "workspace/command_log_widget.h"
#include "workspace/device_workspace.h"
#include "workspace/main_window.h"
#include "itemmodels/latest_values_model.h"
#include "workspace/status_flags_widget.h"
#include "workspace/window_settings.h"
#include "sim/hec495_simulator.h"
#include "sim/pty_simulator.h"

#include <QAction>
#include <QApplication>
#include <QHeaderView>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QDockWidget>
#include <QLineSeries>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>
#include <QTextBrowser>

#include <set>

using imudesk::models::LatestValuesModel;
using imudesk::ui::ConsoleWidget;
using imudesk::ui::LanguageSwitcher;
using imudesk::ui::MainWindow;
using imudesk::ui::PortChoice;
using imudesk::ui::WindowSettings;

namespace {

QString cell(const MainWindow &w, int row, int column = LatestValuesModel::ValueColumn)
{
    return w.valuesView()->model()->index(row, column).data().toString();
}

double hi91Rate(const QString &status)
{
    static const QRegularExpression re(QStringLiteral("HI91 ([0-9]+(?:\\.[0-9]+)?) Hz"));
    const auto m = re.match(status);
    return m.hasMatch() ? m.captured(1).toDouble() : 0.0;
}

// Lines of the console log after the last line equal to `marker`.
QStringList linesAfter(const QString &log, const QString &marker)
{
    const QStringList lines = log.split(QLatin1Char('\n'));
    const qsizetype at = lines.lastIndexOf(marker);
    return at < 0 ? QStringList() : lines.mid(at + 1);
}

int distinctColours(const QImage &image)
{
    std::set<QRgb> colours;
    for (int y = 0; y < image.height(); y += 3)
        for (int x = 0; x < image.width(); x += 3)
            colours.insert(image.pixel(x, y));
    return int(colours.size());
}


QString screenshotPath(const QString &name)
{
    // The build tree, never the sources.
    return QCoreApplication::applicationDirPath() + QLatin1Char('/') + name;
}

} // namespace

class TstMainWindow : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setApplicationVersion(QStringLiteral("test"));
    }

    void simulatedHi14()
    {
        MainWindow w(imudesk::test::builtInFamilies());
        QStringList errors;
        w.setErrorPresenter([&errors](const QString &m) { errors << m; });
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.isRefreshing());
        QCOMPARE(cell(w, LatestValuesModel::Roll), LatestValuesModel::missingText());

        imudesk::sim::SimOptions options; // HI14, firmware 1.7.1, HI91 at 100 Hz
        QString error;
        QVERIFY2(w.openLink(imudesk::device::LinkRequest::simulatedHipnuc(options, 0), &error), qPrintable(error));
        QVERIFY(w.isSimulated());

        // Live values through the pty, the session and the 30 Hz view clock.
        QTRY_VERIFY_WITH_TIMEOUT(cell(w, LatestValuesModel::Roll) != LatestValuesModel::missingText(), 5000);
        bool ok = false;
        cell(w, LatestValuesModel::Roll).toDouble(&ok);
        QVERIFY(ok);
        QCOMPARE(cell(w, LatestValuesModel::FrameType), QStringLiteral("HI91"));
        QCOMPARE(cell(w, LatestValuesModel::AccZ, LatestValuesModel::UnitColumn), QStringLiteral("G"));

        // The attitude view and the charts are on screen and follow the device.
        QVERIFY(w.currentWorkspace()->attitudeWidget()->isVisible());
        {
            // On screen, inside the window (not pushed out by the dock layout).
            const auto *a = w.currentWorkspace()->attitudeWidget();
            const QRect r(a->mapTo(&w, QPoint(0, 0)), a->size());
            QVERIFY2(w.rect().contains(r), qPrintable(QStringLiteral("%1,%2").arg(r.x()).arg(r.y())));
            QVERIFY(r.height() >= 150);
        }
        QTRY_VERIFY(w.currentWorkspace()->attitudeWidget()->hasData());
        QVERIFY(w.currentWorkspace()->chartPanel()->isVisible());
        QTRY_VERIFY(w.currentWorkspace()->chartPanel()->history().size() > 20);
        QTRY_VERIFY(w.currentWorkspace()->chartPanel()->refreshCount() > 0);

        // Identity and link counters in the status bar.
        QTRY_VERIFY_WITH_TIMEOUT(w.statusText().contains(QLatin1String("HI14R3")), 5000);
        QVERIFY2(w.statusText().contains(QLatin1String("1.7.1")), qPrintable(w.statusText()));
        QTRY_VERIFY_WITH_TIMEOUT(hi91Rate(w.statusText()) > 0, 5000);
        QVERIFY2(w.statusText().contains(QLatin1String("CRC errors 0")), qPrintable(w.statusText()));
        QVERIFY(w.windowTitle().contains(QLatin1String("HI14R3")));

        // MAIN_STATUS flags (firmware >= 1.7.0): the simulator always sets UTC_UNSYNC (bit 11).
        QTRY_VERIFY_WITH_TIMEOUT(w.statusFlags()->status().has_value(), 3000);
        QVERIFY(*w.statusFlags()->status() & (1u << 11));
        QVERIFY(w.statusFlags()->flagToolTip(11).contains(QLatin1String("UTC")));

        // The console: a known command answers OK, an unknown one times out.
        ConsoleWidget *console = w.console();
        QTRY_VERIFY(console->input()->isEnabled());
        console->submit(QStringLiteral("LOG VERSION"));
        QTRY_VERIFY_WITH_TIMEOUT(linesAfter(console->logText(), QStringLiteral("> LOG VERSION")).contains(QStringLiteral("OK")),
                                 3000);
        const QStringList versionLines = linesAfter(console->logText(), QStringLiteral("> LOG VERSION"));
        QVERIFY2(versionLines.join(QLatin1Char('\n')).contains(QLatin1String("PNAME=HI14R3")),
                 qPrintable(console->logText()));
        console->submit(QStringLiteral("FOO BAR"));
        QTRY_VERIFY_WITH_TIMEOUT(
            linesAfter(console->logText(), QStringLiteral("> FOO BAR")).join(QLatin1Char('\n')).contains(QLatin1String("Timeout:")),
            3000);
        QCOMPARE(console->history(), (QStringList{QStringLiteral("LOG VERSION"), QStringLiteral("FOO BAR")}));
        // The command log lists both, with their outcome, as copyable text; the raw view saw the bytes.
        const QString commandLog = w.currentWorkspace()->commandLog()->allText();
        QVERIFY2(commandLog.contains(QLatin1String("LOG VERSION")) && commandLog.contains(QLatin1String("FOO BAR")),
                 qPrintable(commandLog));
        QVERIFY(imudesk::test::hipnucOf(*w.currentWorkspace())->rawLog().bytesHeld() > 0);

        // The window draws something, in English...
        QTRY_VERIFY2(distinctColours(w.grab().toImage()) > 20, "the window looks blank");
        const QImage shot = w.grab().toImage();
        QVERIFY(!shot.isNull());
        QVERIFY(shot.width() > 400 && shot.height() > 300);
        QVERIFY2(distinctColours(shot) > 20, "the window looks blank");
        QVERIFY(shot.save(screenshotPath(QStringLiteral("main_window_en.png"))));

        // ...and in Simplified Chinese after a run-time language switch.
#ifdef IMUDESK_QM_DIR
        const QString englishTitle = w.windowTitle();
        const QString englishHeader = w.valuesView()->model()->headerData(0, Qt::Horizontal).toString();
        const QString englishRoll = cell(w, LatestValuesModel::Roll, LatestValuesModel::QuantityColumn);
        LanguageSwitcher language;
        QVERIFY2(language.setLanguage(QStringLiteral("zh_CN"), QString::fromUtf8(IMUDESK_QM_DIR), &error),
                 qPrintable(error));
        QTRY_VERIFY(w.windowTitle() != englishTitle);
        QVERIFY(w.windowTitle().contains(QLatin1String("HI14R3")));
        QVERIFY(w.valuesView()->model()->headerData(0, Qt::Horizontal).toString() != englishHeader);
        QCOMPARE(cell(w, LatestValuesModel::Roll, LatestValuesModel::QuantityColumn), QStringLiteral("横滚角"));
        QVERIFY(w.valuesView()->horizontalHeader()->model()->headerData(1, Qt::Horizontal).toString()
                != QLatin1String("Value"));
        QVERIFY(imudesk::test::layout::layoutSettled(w)); // the longer texts laid out before the screenshot
        QVERIFY(w.grab().toImage().save(screenshotPath(QStringLiteral("main_window_zh_CN.png"))));

        QVERIFY(language.setLanguage(QStringLiteral("zh_TW"), QString::fromUtf8(IMUDESK_QM_DIR), &error));
        QTRY_COMPARE(cell(w, LatestValuesModel::Roll, LatestValuesModel::QuantityColumn), QStringLiteral("橫滾角"));

        QVERIFY(language.setLanguage(QStringLiteral("en")));
        QTRY_COMPARE(w.windowTitle(), englishTitle);
        QCOMPARE(cell(w, LatestValuesModel::Roll, LatestValuesModel::QuantityColumn), englishRoll);
#else
        qWarning("IMUDESK_QM_DIR is not defined: the language switch is not tested");
#endif

        // Hidden windows do not refresh.
        w.hide();
        QVERIFY(!w.isRefreshing());
        w.show();
        QVERIFY(w.isRefreshing());

        // Disconnect: the session closes, then the simulator stops.
        w.disconnectDevice();
        QTRY_COMPARE(w.currentWorkspace()->link().state(), imudesk::device::SessionState::Closed);
        QTRY_VERIFY(!w.isSimulated());
        QVERIFY2(errors.isEmpty(), qPrintable(errors.join(QLatin1Char('\n'))));
    }

    // View > Compare devices with two devices, the second tab in the back: both lines move
    // (before, only the front tab's history grew), and still with an unconnected tab in front.
    void compareDrawsEveryDeviceWhicheverTabIsInFront()
    {
        MainWindow w(imudesk::test::builtInFamilies());
        QStringList errors;
        w.setErrorPresenter([&errors](const QString &m) { errors << m; });
        w.resize(1366, 768);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        imudesk::sim::SimOptions options;
        options.motion = imudesk::sim::Motion::Spin;
        QString error;
        QVERIFY2(w.openLink(imudesk::device::LinkRequest::simulatedHipnuc(options, 0), &error), qPrintable(error));
        w.newWorkspace();
        QVERIFY2(w.connectSimulated(imudesk::ui::PortChoice::simulated(QStringLiteral("HEC495"), QString()), 0, &error), qPrintable(error));
        QCOMPARE(w.workspaceCount(), 2);
        auto *tabs = w.findChild<QTabWidget *>();
        QVERIFY(tabs);
        auto *hi14 = w.workspace(0), *hec = w.workspace(1);
        QTRY_VERIFY_WITH_TIMEOUT(hec->chartPanel()->history().size() > 10, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(hi14->link().store().totalAppended() > 10, 10000);
        w.findChild<QAction *>(QStringLiteral("compareDevicesAction"))->trigger();
        QVERIFY(w.comparisonDock()->isVisible());
        imudesk::ui::ComparisonChart *compare = w.comparisonChart();
        compare->setChannel(imudesk::plot::Channel::Roll);
        QCOMPARE(compare->sources().size(), size_t(2));
        // Two legend names for two devices.
        QVERIFY(compare->series(0)->name() != compare->series(1)->name());
        const auto newestX = [compare](int i) {
            const QList<QPointF> points = compare->series(i)->points();
            return points.isEmpty() ? -1.0 : points.last().x();
        };
        const auto bothMove = [&](const char *when) {
            const uint64_t hecRows = hec->chartPanel()->history().totalAppended();
            const uint64_t hi14Rows = hi14->chartPanel()->history().totalAppended();
            const double x0 = newestX(0), x1 = newestX(1);
            QTRY_VERIFY2_WITH_TIMEOUT(hec->chartPanel()->history().totalAppended() > hecRows + 20, when, 5000);
            QTRY_VERIFY2_WITH_TIMEOUT(hi14->chartPanel()->history().totalAppended() > hi14Rows + 20, when, 5000);
            QTRY_VERIFY2_WITH_TIMEOUT(newestX(0) > x0 + 0.3 && newestX(1) > x1 + 0.3, when, 5000);
        };
        // The compass's tab in the back.
        tabs->setCurrentIndex(0);
        QVERIFY(!hec->isVisible());
        bothMove("second tab in the back");
        // An unconnected tab in front: both devices in the back, still live.
        w.newWorkspace();
        QCOMPARE(tabs->currentIndex(), 2);
        QVERIFY(!hi14->isVisible() && !hec->isVisible());
        bothMove("an unconnected tab in front");
        QVERIFY2(errors.isEmpty(), qPrintable(errors.join(QLatin1Char('\n'))));
    }

    // Two simulated HI14 connected from the connection bar are two devices: each its own serial
    // number, and the comparison tells them apart (before, one serial and one legend name).
    void twoSimulatedModulesAreTwoDevices()
    {
        MainWindow w(imudesk::test::builtInFamilies());
        w.setErrorPresenter([](const QString &) {});
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto *connect = w.findChild<QAction *>(QStringLiteral("connectAction"));
        QVERIFY(connect);
        for (int i = 0; i < 2; ++i) {
            if (i == 1)
                w.newWorkspace();
            w.connectionBar()->selectPort(PortChoice::simulated(QStringLiteral("HI14"), QStringLiteral("1.7.1")));
            QTRY_VERIFY(connect->isEnabled());
            connect->trigger();
            QTRY_VERIFY_WITH_TIMEOUT(w.workspace(i)->identity() && !w.workspace(i)->identity()->serial.empty(), 10000);
        }
        QVERIFY(w.workspace(0)->identity()->serial != w.workspace(1)->identity()->serial);
        QCOMPARE(w.workspace(0)->title(), w.workspace(1)->title());
        const auto &sources = w.comparisonChart()->sources();
        QCOMPARE(sources.size(), size_t(2));
        QVERIFY2(sources[0].first != sources[1].first, qPrintable(sources[0].first));
        QVERIFY(sources[1].first.contains(QString::fromStdString(w.workspace(1)->identity()->serial)));
    }

    // Help has the user guide (the guide's own text) and the keyboard shortcuts (read from the
    // window's actions), beside About.
    void helpMenuGuideAndShortcuts()
    {
        MainWindow w(imudesk::test::builtInFamilies());
        w.setErrorPresenter([](const QString &) {});
        w.show();
        auto *guide = w.findChild<QAction *>(QStringLiteral("userGuideAction"));
        auto *keys = w.findChild<QAction *>(QStringLiteral("shortcutsAction"));
        QVERIFY(guide && keys);
        QCOMPARE(guide->shortcut(), QKeySequence(QKeySequence::HelpContents));
        guide->trigger();
        auto *dialog = w.findChild<imudesk::ui::UserGuideDialog *>();
        QVERIFY(dialog && dialog->isVisible());
        const QString text = dialog->browser()->toPlainText();
        QVERIFY2(text.contains(QLatin1String("Production station")), qPrintable(text.left(200)));
        QVERIFY(text.contains(QLatin1String("Getting started with the simulator")));
        QVERIFY(!text.contains(QLatin1String("![")));
        keys->trigger();
        auto *shortcuts = w.findChild<imudesk::ui::ShortcutsDialog *>();
        QVERIFY(shortcuts && shortcuts->isVisible());
        QMap<QString, QString> rows;
        for (int r = 0; r < shortcuts->table()->rowCount(); ++r)
            rows.insert(shortcuts->table()->item(r, 0)->text(), shortcuts->table()->item(r, 1)->text());
        QCOMPARE(rows.value(QStringLiteral("Connect")), QKeySequence(Qt::CTRL | Qt::Key_K).toString(QKeySequence::NativeText));
        QCOMPARE(rows.value(QStringLiteral("Production station")),
                 QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P).toString(QKeySequence::NativeText));
        QVERIFY(rows.contains(QStringLiteral("User guide")));
        QVERIFY(rows.contains(QStringLiteral("Configuration")));
    }

    void takeOneSampleAndPps()
    {
        // A module with a PPS receiver: its HI91 clock aligns to UTC (the device time reads as
        // a UTC time); with output off, Device > Take one sample brings exactly one HI91.
        MainWindow w(imudesk::test::builtInFamilies());
        QStringList errors;
        w.setErrorPresenter([&errors](const QString &m) { errors << m; });
        w.show();
        imudesk::sim::SimOptions options;
        options.ppsInput = true;
        QString error;
        QVERIFY2(w.openLink(imudesk::device::LinkRequest::simulatedHipnuc(options, 115200), &error), qPrintable(error));
        QTRY_VERIFY_WITH_TIMEOUT(cell(w, LatestValuesModel::DeviceTime).contains(QLatin1Char(':')), 5000);
        auto *take = w.findChild<QAction *>(QStringLiteral("takeSampleAction"));
        QVERIFY(take);
        QTRY_VERIFY(take->isEnabled());
        w.console()->submit(QStringLiteral("LOG DISABLE"));
        QTRY_VERIFY_WITH_TIMEOUT(linesAfter(w.console()->logText(), QStringLiteral("> LOG DISABLE")).contains(QStringLiteral("OK")),
                                 3000);
        // One more round trip: every frame sent before that OK is in the store once its answer
        // is in (the engine stores each chunk's samples before it reads the next).
        w.console()->submit(QStringLiteral("LOG VERSION"));
        QTRY_VERIFY_WITH_TIMEOUT(linesAfter(w.console()->logText(), QStringLiteral("> LOG VERSION")).contains(QStringLiteral("OK")),
                                 3000);
        const quint64 before = w.currentWorkspace()->link().store().totalAppended();
        take->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(
            linesAfter(w.console()->logText(), QStringLiteral("> LOG HI91 ONMARK ONCE")).contains(QStringLiteral("OK")), 3000);
        QTRY_COMPARE_WITH_TIMEOUT(w.currentWorkspace()->link().store().totalAppended(), before + 1, 2000);
        QTest::qWait(300); // duration under test: no second sample in 300 ms
        QCOMPARE(w.currentWorkspace()->link().store().totalAppended(), before + 1);
        QVERIFY2(errors.isEmpty(), qPrintable(errors.join(QLatin1Char('\n'))));
    }

    void simulatedOldFirmware()
    {
        MainWindow w(imudesk::test::builtInFamilies());
        QStringList errors;
        w.setErrorPresenter([&errors](const QString &m) { errors << m; });
        w.show();
        imudesk::sim::SimOptions options;
        options.firmware = "1.6.6";
        options.motion = imudesk::sim::Motion::Spin;
        QString error;
        QVERIFY2(w.openLink(imudesk::device::LinkRequest::simulatedHipnuc(options, 115200), &error), qPrintable(error));
        QTRY_VERIFY_WITH_TIMEOUT(cell(w, LatestValuesModel::Yaw) != LatestValuesModel::missingText(), 5000);
        // Spinning at 30 deg/s: the yaw changes.
        const QString yaw = cell(w, LatestValuesModel::Yaw);
        QTRY_VERIFY_WITH_TIMEOUT(cell(w, LatestValuesModel::Yaw) != yaw, 2000);
        // Device > Send LOG VERSION: logged in the console, and the identity follows the reply.
        auto *version = w.findChild<QAction *>(QStringLiteral("versionAction"));
        QVERIFY(version);
        QTRY_VERIFY(version->isEnabled());
        version->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(linesAfter(w.console()->logText(), QStringLiteral("> LOG VERSION")).contains(QStringLiteral("OK")),
                                 3000);
        QTRY_VERIFY2_WITH_TIMEOUT(w.statusText().contains(QLatin1String("firmware 1.6.6")), qPrintable(w.statusText()),
                                  3000);
        // Firmware 1.6.6 has no MAIN_STATUS: the flags show "not reported", the table "—".
        QTRY_VERIFY(!w.statusFlags()->status().has_value());
        QTRY_COMPARE(cell(w, LatestValuesModel::StatusFlags), LatestValuesModel::missingText());
        QCOMPARE(w.connectionBar()->selectedPort(), PortChoice::simulated(QStringLiteral("HI14"), QStringLiteral("1.6.6")));
        QCOMPARE(w.connectionBar()->selectedBaud(), 115200);
        QVERIFY2(errors.isEmpty(), qPrintable(errors.join(QLatin1Char('\n'))));
    }

    void missingPortReportsWithoutBlocking()
    {
        MainWindow w(imudesk::test::builtInFamilies());
        QStringList errors;
        w.setErrorPresenter([&errors](const QString &m) { errors << m; });
        w.show();
        w.connectPort(QStringLiteral("/dev/imudesk-no-such-port"), 115200);
        QTRY_COMPARE(errors.size(), 1);
        QVERIFY2(errors.first().contains(QLatin1String("was not found")), qPrintable(errors.first()));
        QTRY_COMPARE(w.currentWorkspace()->link().state(), imudesk::device::SessionState::Failed);
        QVERIFY(w.statusText().contains(QLatin1String("/dev/imudesk-no-such-port")));
        QVERIFY(w.console()->logText().contains(QLatin1String("was not found")));
        QVERIFY(w.isRefreshing());
    }

    void errorBoxDoesNotBlock()
    {
        MainWindow w(imudesk::test::builtInFamilies()); // the default presenter: a non-modal message box
        w.show();
        w.connectPort(QStringLiteral("/dev/imudesk-no-such-port"), 115200);
        QMessageBox *box = nullptr;
        QTRY_VERIFY((box = w.findChild<QMessageBox *>()) && box->isVisible());
        QVERIFY(!box->isModal());
        QVERIFY(QApplication::activeModalWidget() == nullptr);
        QVERIFY(box->text().contains(QLatin1String("was not found")));
        QTRY_COMPARE(w.currentWorkspace()->link().state(), imudesk::device::SessionState::Failed);
        // A second error joins the open box instead of stacking another one.
        w.connectPort(QStringLiteral("/dev/imudesk-no-such-port-2"), 115200);
        QTRY_VERIFY(box->text().contains(QLatin1String("imudesk-no-such-port-2")));
        QCOMPARE(w.findChildren<QMessageBox *>().size(), 1);
        QVERIFY(w.isRefreshing());
        box->close();
    }

    // Baud "Auto": the detection belongs to the window. It finds the simulated
    // module and opens the session at the rate found; a window closed while its probe still
    // listens waits for it, and nothing runs after the window is gone.
    void autoBaudProbeIsOwnedByTheWindow()
    {
        imudesk::sim::PtySimulator simulator(imudesk::sim::SimOptions{});
        QString error;
        QVERIFY2(simulator.start(&error), qPrintable(error));
        {
            MainWindow w(imudesk::test::builtInFamilies());
            w.setErrorPresenter([](const QString &) {});
            w.connectPort(simulator.devicePath(), 0);
            QTRY_COMPARE_WITH_TIMEOUT(w.currentWorkspace()->state(), imudesk::device::SessionState::Connected, 20000);
        }
        {
            MainWindow w(imudesk::test::builtInFamilies());
            w.setErrorPresenter([](const QString &) {});
            w.connectPort(simulator.devicePath(), 0); // still probing when the window goes
        }
        QCoreApplication::processEvents(); // a late result would land here, on a dead window
    }

    // Baud "Auto" on a port with an HEC495: the detection hands the port to a compass session,
    // shown with the compass's docks, at the compass's rate and address; nothing found on a
    // port says so once, with what to check.
    void autoBaudFindsTheCompass()
    {
        imudesk::sim::Hec495Options o;
        o.baud = 19200;
        o.address = 7;
        imudesk::sim::PtySimulator simulator(std::make_unique<imudesk::sim::Hec495Simulator>(o));
        QString error;
        QVERIFY2(simulator.start(&error), qPrintable(error));
        MainWindow w(imudesk::test::builtInFamilies());
        QStringList errors;
        w.setErrorPresenter([&errors](const QString &e) { errors << e; });
        w.connectPort(simulator.devicePath(), 0);
        QTRY_COMPARE_WITH_TIMEOUT(w.currentWorkspace()->state(), imudesk::device::SessionState::Connected, 20000);
        imudesk::ui::DeviceWorkspace *ws = w.currentWorkspace();
        QVERIFY(!imudesk::test::hipnucOf(*ws));
        QTRY_VERIFY(ws->identity() && ws->identity()->busAddress == 7);
        QVERIFY(ws->findChild<QDockWidget *>(QStringLiteral("headingDialDock")));
        QCOMPARE(ws->link().linkKind(), QStringLiteral("HEC495 serial"));
        QVERIFY2(errors.isEmpty(), qPrintable(errors.join(u'\n')));
    }

    void connectionBarListsSimulators()
    {
        // The simulated devices are the family plug-ins': none without them.
        imudesk::ui::ConnectionBar bar;
        QVERIFY(!bar.portTexts().contains(QStringLiteral("Simulated HI14 (firmware 1.7.1)")));
        const imudesk::ui::FamilyUiRegistry &families = imudesk::test::builtInFamilies();
        bar.setSimulatedDevices([&families] { return families.simulatedDevices(); });
        const QStringList texts = bar.portTexts();
        QVERIFY(texts.contains(QStringLiteral("Simulated HI14 (firmware 1.7.1)")));
        QVERIFY(texts.contains(QStringLiteral("Simulated HI14 (firmware 1.6.6)")));
        QVERIFY(texts.contains(QStringLiteral("Simulated HEC495 compass")));
        bar.selectPort(PortChoice::serial(QStringLiteral("/dev/pts/99")));
        QCOMPARE(bar.selectedPort(), PortChoice::serial(QStringLiteral("/dev/pts/99")));
        bar.refreshPorts(); // a rescan keeps the choice
        QCOMPARE(bar.selectedPort(), PortChoice::serial(QStringLiteral("/dev/pts/99")));
        QCOMPARE(bar.selectedBaud(), 0);
        bar.selectBaud(921600);
        QCOMPARE(bar.selectedBaud(), 921600);
        QSignalSpy connectSpy(&bar, &imudesk::ui::ConnectionBar::connectRequested);
        QSignalSpy disconnectSpy(&bar, &imudesk::ui::ConnectionBar::disconnectRequested);
        auto *button = bar.findChild<QPushButton *>(QStringLiteral("connectButton"));
        QVERIFY(button);
        button->click();
        bar.show();
        QVERIFY(bar.isScanningPorts()); // a port can be chosen: the list follows the system
        bar.setSessionState(imudesk::device::SessionState::Connected);
        QVERIFY(!bar.isScanningPorts()); // connected: no sysfs scan every two seconds
        button->click();
        QCOMPARE(connectSpy.count(), 1);
        QCOMPARE(disconnectSpy.count(), 1);
        bar.setSessionState(imudesk::device::SessionState::Reconnecting);
        QVERIFY(bar.isScanningPorts()); // a cable pulled: the user may pick another port
        bar.setSessionState(imudesk::device::SessionState::Closed);
        QVERIFY(bar.isScanningPorts());
        bar.hide();
        QVERIFY(!bar.isScanningPorts());
    }

    void consoleHistory()
    {
        ConsoleWidget console;
        QSignalSpy spy(&console, &ConsoleWidget::commandSubmitted);
        QTest::keyClicks(console.input(), QStringLiteral("LOG VERSION"));
        QTest::keyClick(console.input(), Qt::Key_Return);
        console.submit(QStringLiteral("LOG COMCONFIG"));
        QCOMPARE(spy.count(), 2);
        QTest::keyClicks(console.input(), QStringLiteral("draft"));
        QTest::keyClick(console.input(), Qt::Key_Up);
        QCOMPARE(console.input()->text(), QStringLiteral("LOG COMCONFIG"));
        QTest::keyClick(console.input(), Qt::Key_Up);
        QCOMPARE(console.input()->text(), QStringLiteral("LOG VERSION"));
        QTest::keyClick(console.input(), Qt::Key_Up);
        QCOMPARE(console.input()->text(), QStringLiteral("LOG VERSION"));
        QTest::keyClick(console.input(), Qt::Key_Down);
        QTest::keyClick(console.input(), Qt::Key_Down);
        QCOMPARE(console.input()->text(), QStringLiteral("draft"));

        imudesk::device::TextReply err;
        err.status = imudesk::device::TextReply::Status::Refused;
        err.why = QStringLiteral("ERR");
        console.showCommand(7, QStringLiteral("CONFIG ATT MODE 9"));
        console.showReply(7, err);
        QVERIFY(console.logText().endsWith(QLatin1String("ERR: ERR")));
    }

    // Device > Record (Ctrl+R) records at once; File > Export (Ctrl+E) then offers that recording.
    // Before the device is connected, the recording panel says what to press.
    void recordThenExportTheRecording()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        MainWindow w(imudesk::test::builtInFamilies());
        w.setErrorPresenter([](const QString &) {});
        imudesk::ui::Preferences prefs = w.preferences();
        prefs.recordingFolder = dir.path();
        w.setPreferences(prefs);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        imudesk::ui::DeviceWorkspace *ws = w.currentWorkspace();
        imudesk::ui::RecordingControls *controls = ws->recordingControls();
        QAction *record = w.tools()->recordAction();
        QCOMPARE(record->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_R));

        imudesk::sim::SimOptions options;
        QString error;
        QVERIFY2(w.openLink(imudesk::device::LinkRequest::simulatedHipnuc(options, 0), &error), qPrintable(error));
        QTRY_VERIFY_WITH_TIMEOUT(ws->state() == imudesk::device::SessionState::Connected, 10000);
        QTRY_VERIFY(record->isEnabled());
        QSignalSpy stopped(controls, &imudesk::ui::RecordingControls::recordingStopped);
        record->trigger();
        QVERIFY(ws->recordingDock()->isVisible());
        QTRY_VERIFY_WITH_TIMEOUT(controls->isRecording(), 5000);
        const QString path = controls->currentPath();
        QVERIFY2(path.startsWith(dir.path()), qPrintable(path));
        // Ctrl+R again leaves it recording.
        record->trigger();
        QVERIFY(controls->isRecording());
        QTRY_VERIFY_WITH_TIMEOUT(QFileInfo(path).size() > 1000, 5000);
        controls->stopRecording();
        QTRY_COMPARE_WITH_TIMEOUT(stopped.count(), 1, 5000);
        QCOMPARE(w.tools()->lastRecording(), path);

        // Export opens with the recording just made, without asking for a file first.
        w.tools()->exportAction()->trigger();
        auto *exporter = w.findChild<imudesk::ui::ExportDialog *>();
        QVERIFY(exporter);
        QTRY_VERIFY(exporter->isVisible());
        QCOMPARE(exporter->capture(), path);
        QCOMPARE(exporter->findChild<QLineEdit *>(QStringLiteral("capture"))->text(), path);
        QVERIFY(exporter->windowTitle().contains(QFileInfo(path).fileName()));
        exporter->close();

        // Open capture stays offered in the connected tab (the capture opens in a tab of its
        // own), and a capture opened so leaves the device's tab as it was.
        QAction *open = w.findChild<QAction *>(QStringLiteral("openCaptureAction"));
        QVERIFY(open);
        QVERIFY(open->isEnabled());
        QVERIFY(open->statusTip().contains(QStringLiteral("tab of its own")));
        const int before = int(w.allWorkspaces().size());
        QVERIFY(w.tools()->openCapture(path));
        QCOMPARE(int(w.allWorkspaces().size()), before + 1);
        QCOMPARE(ws->state(), imudesk::device::SessionState::Connected);
        QVERIFY(open->isEnabled());
        auto *tabs = w.findChild<QTabWidget *>();
        QVERIFY(tabs);
        tabs->setCurrentIndex(tabs->indexOf(ws));
        QCOMPARE(w.currentWorkspace(), ws);

        // Not connected: Record says what to press instead of opening an idle panel.
        w.disconnectDevice();
        QTRY_VERIFY_WITH_TIMEOUT(ws->state() != imudesk::device::SessionState::Connected, 5000);
        if (record->isEnabled()) {
            record->trigger();
            QVERIFY(!controls->isRecording());
            const QString said = controls->findChild<QLabel *>(QStringLiteral("message"))->text();
            QVERIFY2(said.contains(QStringLiteral("Ctrl+K")) && said.contains(QStringLiteral("Record")), qPrintable(said));
        }
    }

    void windowSettingsRoundTrip()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QSettings store(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
        WindowSettings a;
        a.geometry = QByteArray("geo");
        a.windowState = QByteArray("state");
        a.port = PortChoice::simulated(QStringLiteral("HI14"), QStringLiteral("1.6.6")).key();
        a.baud = 460800;
        a.save(store);
        WindowSettings b;
        b.load(store);
        QCOMPARE(b.geometry, a.geometry);
        QCOMPARE(b.windowState, a.windowState);
        QCOMPARE(b.port, a.port);
        QCOMPARE(b.baud, 460800);
        store.setValue(QString::fromLatin1(WindowSettings::kBaudKey), 12345); // not a HiPNUC rate
        b.load(store);
        QCOMPARE(b.baud, 0);

        MainWindow w(imudesk::test::builtInFamilies(), a);
        QCOMPARE(w.connectionBar()->selectedPort().key(), a.port);
        QCOMPARE(w.windowSettings().baud, 460800);
    }
};

IMUDESK_TEST_MAIN(TstMainWindow)
#include "tst_main_window.moc"
