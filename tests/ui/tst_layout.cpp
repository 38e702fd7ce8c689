// The window as a person sees it, offscreen on a 1920x1080 screen: for every kind of
// workspace (HiPNUC serial, HEC495, Modbus, J1939, CANopen, replay), at 1366x768 and
// 1920x1080, in English and Simplified Chinese, nothing the user came for is hidden: no
// scroll bar in the chart area, every column of the values table inside its viewport, the
// 3D attitude view at least 300 px at 1920x1080, no label cut short, no widget outside the
// window. The same after restoring a layout saved in a small automation window and one
// saved at another size; a --screenshot run leaves the user's settings alone; the layout
// presets and the bottom panels that open on demand.
#include "../common/ui_families.h"
#include "../common/layout_checks.h"
#include "../common/synthetic_capture.h"
#include "../common/hipnuc_link.h"
#include "../common/test_main.h"
#include "calibration/attitude_reset_wizard.h"
#include "attitude/attitude_widget.h"
#include "device/device_session.h"
#include "device/hec495_session.h"
#include "protocol/hipnuc/ascii_command.h"
#include "protocol/hipnuc/payloads.h"
#include "ui/firmware/firmware_update_dialog.h"
#include "calibration/gyro_scale_wizard.h"
#include "calibration/hec495_calibration_wizard.h"
#include "calibration/mag_calibration_wizard.h"
#include "calibration/mag_sphere_view.h"
#include "charts/chart_panel.h"
#include "charts/comparison_chart.h"
#include "configuration/config_panel.h"
#include "configuration/mounting_picker.h"
#include "configuration/mounting_tile.h"
#include "model/mounting.h"
#include "charts/chart_view.h"
#include "workspace/connection_bar.h"
#include "device/can_session_types.h"
#include "device/modbus_types.h"
#include "workspace/device_workspace.h"
#include "workspace/language_switcher.h"
#include "record/session_manifest.h"
#include "workspace/main_window.h"
#include "workspace/tool_actions.h"
#include "model/main_status.h"
#include "itemmodels/latest_values_model.h"
#include "workspace/status_flags_widget.h"
#include "workspace/window_settings.h"

#include <QAbstractScrollArea>
#include <QAction>
#include <QChartView>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QGraphicsView>
#include <QHeaderView>
#include <QLabel>
#include <QMainWindow>
#include <QImage>
#include <QProcess>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTabBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QWizard>
#include <QTextDocumentFragment>

using namespace imudesk;
using ui::DeviceWorkspace;
using ui::MainWindow;
using test::layout::cutOrOutside;
using test::layout::layoutSettled;
using test::layout::parkedByQt;

namespace {

const QSize kSmall(1366, 768);
const QSize kLarge(1920, 1080);

bool laptopScreen()
{
    return qEnvironmentVariableIntValue("IMUDESK_LAYOUT_LAPTOP") == 1;
}

enum class Kind { Serial, Hec495, Modbus, J1939, CanOpen, Replay, SerialGnss, SerialIns, SessionReplay };
const char *kindName(Kind k)
{
    static const char *const names[] = {"HiPNUC serial", "HEC495", "Modbus", "J1939", "CANopen", "replay",
                                                 "HiPNUC serial with NMEA", "HiPNUC serial with every HI83 field",
                                                 "session replay"};
    return names[int(k)];
}

// What a person would call broken in this window, one line each.
QStringList layoutProblems(MainWindow &w, bool large)
{
    QStringList problems;
    // Layouts catch up with a label's new text on a posted event: let them, as the screen would.
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    DeviceWorkspace *ws = w.currentWorkspace();
    // The charts fill their area without any scroll bar, each chart inside it.
    ui::ChartPanel *charts = ws->chartPanel();
    for (const QScrollBar *bar : charts->findChildren<QScrollBar *>())
        if (bar->isVisible())
            problems << QStringLiteral("a scroll bar in the chart area");
    int chartsShown = 0;
    for (int k = 0; k < ui::kChartKindCount; ++k) {
        const ui::ChartView *chart = charts->chart(ui::ChartKind(k));
        if (chart->isHidden())
            continue;
        ++chartsShown;
        const QRect r(chart->mapTo(charts->chartArea(), QPoint(0, 0)), chart->size());
        if (!charts->chartArea()->rect().contains(r) || chart->height() < ui::ChartView::kMinimumChartHeight)
            problems << QStringLiteral("chart %1 cut: %2x%3").arg(k).arg(chart->width()).arg(chart->height());
    }
    if (chartsShown == 0)
        problems << QStringLiteral("no chart shown");
    // The values table: every column inside the viewport.
    const QTableView *values = ws->valuesView();
    if (values->isVisible() && !parkedByQt(values)) {
        int columns = 0;
        for (int c = 0; c < values->model()->columnCount(); ++c)
            columns += values->columnWidth(c);
        // The last column stretches: it only has to fit its contents.
        if (values->horizontalScrollBar()->isVisible() || values->horizontalHeader()->sectionViewportPosition(2) < 0
            || values->horizontalHeader()->sectionViewportPosition(2) + 20 > values->viewport()->width())
            problems << QStringLiteral("values table columns (%1 px) wider than its viewport (%2 px)")
                            .arg(columns)
                            .arg(values->viewport()->width());
        if (values->verticalScrollBar()->isVisible())
            problems << QStringLiteral("values table scrolls: %1 px for %2 px of rows")
                            .arg(values->viewport()->height())
                            .arg(values->verticalHeader()->length());
        if (values->width() < ws->valuesTableWidth())
            problems << QStringLiteral("values table %1 px, needs %2").arg(values->width()).arg(ws->valuesTableWidth());
    } else if (ws->preset() == DeviceWorkspace::LayoutPreset::Monitor
               || ws->preset() == DeviceWorkspace::LayoutPreset::Analyse) {
        problems << QStringLiteral("values table not shown");
    }
    // The 3D attitude: a real size on a large screen, its read-out beside the model. The values
    // come first: a module that adds INS or GNSS rows (29 rows in Chinese) leaves it about 290 px.
    const ui::AttitudeWidget *attitude = ws->attitudeWidget();
    if (attitude->isVisible()) {
        if (large && std::min(attitude->width(), attitude->height()) < 280)
            problems << QStringLiteral("attitude view %1x%2 (< 280)").arg(attitude->width()).arg(attitude->height());
        if (attitude->readoutRect().intersects(attitude->sceneRect()))
            problems << QStringLiteral("attitude read-out over the model");
    }
    // The settings table: no column behind a horizontal scroll bar.
    const QTableView *settings = ws->configPanel() ? ws->configPanel()->table() : nullptr;
    if (settings && settings->isVisible() && !parkedByQt(settings) && settings->horizontalScrollBar()->isVisible())
        problems << QStringLiteral("settings table scrolls sideways");
    // The window fits its screen (a column of docks too tall makes it grow past the bottom).
    const QSize screen = w.screen()->availableGeometry().size();
    if (w.width() > screen.width() || w.height() > screen.height())
        problems << QStringLiteral("window %1x%2 larger than the screen %3x%4")
                        .arg(w.width())
                        .arg(w.height())
                        .arg(screen.width())
                        .arg(screen.height());
    // ... and could fit it when not maximised: a window whose least size is taller than the
    // screen grows past the bottom as soon as it is restored (a CAN settings form in Chinese).
    // The small size stands for a laptop's whole screen.
    const QSize room = large ? screen : kSmall.boundedTo(screen);
    const QSize least = w.minimumSizeHint().expandedTo(w.minimumSize());
    if (least.width() > room.width() || least.height() > room.height())
        problems << QStringLiteral("window needs at least %1x%2, the screen has %3x%4")
                        .arg(least.width())
                        .arg(least.height())
                        .arg(room.width())
                        .arg(room.height());
    // No label cut short, no widget outside the window.
    problems << cutOrOutside(w);
    return problems;
}

void showAt(MainWindow &w, const QSize &size)
{
    if (size == w.screen()->geometry().size()) {
        w.showMaximized();
    } else {
        w.resize(size);
        w.show();
    }
}


} // namespace

class TstLayout : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_capture;
    QString m_session; // a session folder of two devices, both m_capture's recording
    ui::LanguageSwitcher m_language;

    bool connectKind(MainWindow &w, Kind kind, QString *error)
    {
        switch (kind) {
        case Kind::Serial: {
            sim::SimOptions options;
            options.model = "HI14";
            options.firmware = "1.7.1";
            options.motion = sim::Motion::Tumble;
            return w.openLink(imudesk::device::LinkRequest::simulatedHipnuc(options, 0), error);
        }
        case Kind::SerialGnss: { // HI91 with NMEA GGA and RMC beside it: eight more rows
            sim::SimOptions options;
            options.model = "HI14";
            options.firmware = "1.7.1";
            if (!w.openLink(imudesk::device::LinkRequest::simulatedHipnuc(options, 115200), error))
                return false;
            DeviceWorkspace *ws = w.currentWorkspace();
            if (!imudesk::test::waitFor([ws] { return ws->link().state() == device::SessionState::Connected; }, 5000))
                return false;
            test::hipnucOf(*ws)->sendCommand(protocol::hipnuc::commands::logOnTime(protocol::hipnuc::Message::GGA, 0.2));
            test::hipnucOf(*ws)->sendCommand(protocol::hipnuc::commands::logOnTime(protocol::hipnuc::Message::RMC, 0.2));
            return imudesk::test::waitFor(
                [ws] { return !ws->valuesView()->isRowHidden(models::LatestValuesModel::UtcTime); }, 5000);
        }
        case Kind::SerialIns: { // HI91 beside an HI83 with every field the manual sizes: the details tab
            sim::SimOptions options;
            options.model = "HI14";
            options.firmware = "1.7.1";
            options.ppsInput = true;
            if (!w.openLink(imudesk::device::LinkRequest::simulatedHipnuc(options, 115200), error))
                return false;
            DeviceWorkspace *ws = w.currentWorkspace();
            if (!imudesk::test::waitFor([ws] { return ws->link().state() == device::SessionState::Connected; }, 5000))
                return false;
            namespace hpc = protocol::hipnuc::commands;
            test::hipnucOf(*ws)->sendCommand(hpc::logHi83Map(protocol::hipnuc::Hi83::kSupportedMask));
            test::hipnucOf(*ws)->sendCommand(hpc::logOnTime(protocol::hipnuc::Message::HI83, 0.05));
            return imudesk::test::waitFor([ws] { return !ws->detailsDock()->isHidden(); }, 5000);
        }
        case Kind::Hec495: return w.connectSimulated(imudesk::ui::PortChoice::simulated(QStringLiteral("HEC495"), QString()), 0, error);
        case Kind::Modbus: {
            device::LinkRequest request = device::LinkRequest::modbusDevice({});
            request.simulate = true;
            return w.openLink(request, error);
        }
        case Kind::J1939:
        case Kind::CanOpen: {
            device::CanSessionOptions o;
            o.protocol = kind == Kind::J1939 ? protocol::can::CanProtocol::J1939 : protocol::can::CanProtocol::CanOpen;
            device::LinkRequest request = device::LinkRequest::canBus(o);
            request.simulate = true;
            return w.openLink(request, error);
        }
        case Kind::Replay: {
            // The capture plays once it is open: runKind() waits for its data on the views.
            return w.openLink(device::LinkRequest::capture(m_capture), error);
        }
        case Kind::SessionReplay: {
            // Two devices of a recorded session: two replay tabs, linked (the label beside the
            // controls); the last one is in view.
            if (!w.tools()->openCapture(m_session)) {
                *error = QStringLiteral("the session did not open");
                return false;
            }
            return true;
        }
        }
        return false;
    }

    // Connects, waits for data on the views, returns the problems.
    QStringList runKind(Kind kind, const QSize &size, const ui::WindowSettings &settings = {})
    {
        MainWindow w(imudesk::test::builtInFamilies(), settings);
        w.setErrorPresenter([](const QString &) {});
        showAt(w, size);
        if (!QTest::qWaitForWindowExposed(&w))
            return {QStringLiteral("window not exposed")};
        QString error;
        if (!connectKind(w, kind, &error))
            return {QStringLiteral("could not connect: ") + error};
        DeviceWorkspace *ws = w.currentWorkspace();
        if (!imudesk::test::waitFor([ws] { return ws->link().store().totalAppended() > 20; }, 15000))
            return {QStringLiteral("no data from the %1 link").arg(QLatin1String(kindName(kind)))};
        // The views follow the data on their clock (the values at most ten times a second), the
        // layouts follow the views: a refresh of the values with this data, then the layouts.
        QSignalSpy valuesShown(ws->valuesView()->model(), &QAbstractItemModel::dataChanged);
        if (!valuesShown.wait(5000))
            return {QStringLiteral("the values table never showed the %1 link's data").arg(QLatin1String(kindName(kind)))};
        if (!layoutSettled(w))
            return {QStringLiteral("the layout did not settle")};
        QStringList problems = layoutProblems(w, size.width() >= kLarge.width());
        // The bar names what this tab is connected to.
        if (w.connectionBar()->shownTarget() != ws->target())
            problems << QStringLiteral("connection bar shows \"%1\", the tab is \"%2\"")
                            .arg(w.connectionBar()->shownTarget(), ws->target());
        // The values table lists what this link sends: a compass has no quaternion.
        if (ws->valuesView()->isRowHidden(models::LatestValuesModel::QuatW) != (kind == Kind::Hec495))
            problems << QStringLiteral("quaternion row shown: %1").arg(!ws->valuesView()->isRowHidden(
                            models::LatestValuesModel::QuatW));
        // Only the panels the link supports.
        const bool serial = kind == Kind::Serial || kind == Kind::SerialGnss || kind == Kind::SerialIns;
        if (ws->dockActions().contains(ws->consoleDock()->toggleViewAction()) != serial)
            problems << QStringLiteral("console offered: %1").arg(!serial);
        // The CAN configuration in front: it gets the column's height (the 3D view becomes a tab),
        // every row in view; back to the values, the 3D view returns below them when there is room.
        if (kind == Kind::J1939 || kind == Kind::CanOpen) {
            QDockWidget *can = nullptr;
            for (QDockWidget *d : ws->linkDocks())
                if (d->objectName() == QLatin1String("canConfigDock"))
                    can = d;
            const auto *area = can ? qobject_cast<const QScrollArea *>(can->widget()) : nullptr;
            if (!area) {
                problems << QStringLiteral("no CAN configuration dock");
            } else {
                can->raise();
                if (!layoutSettled(w))
                    problems << QStringLiteral("the layout did not settle with the CAN configuration in front");
                if (area->verticalScrollBar()->isVisible())
                    problems << QStringLiteral("CAN configuration scrolls: %1 px for %2 px")
                                    .arg(area->viewport()->height())
                                    .arg(area->widget()->minimumSizeHint().height());
                ws->valuesDock()->raise();
                if (!layoutSettled(w))
                    problems << QStringLiteral("the layout did not settle with the values in front");
                problems << layoutProblems(w, size.width() >= kLarge.width());
            }
        }
        // Every HI83 field: the values keep their rows in view, the details are a tab beside them,
        // all twenty rows and their three-number texts in full.
        if (kind == Kind::SerialIns) {
            if (!ws->tabifiedDockWidgets(ws->valuesDock()).contains(ws->detailsDock()))
                problems << QStringLiteral("the HI83 details are not a tab beside the values");
            int rows = 0;
            for (int r = 0; r < ws->detailsView()->model()->rowCount(); ++r)
                rows += ws->detailsView()->isRowHidden(r) ? 0 : 1;
            if (rows != 20) // 15 HI83 extras, heave, surge, sway, inclination X and Y
                problems << QStringLiteral("%1 detail rows, 20 expected").arg(rows);
            ws->detailsDock()->raise();
            if (!layoutSettled(w))
                problems << QStringLiteral("the layout did not settle with the HI83 details in front");
            const QTableView *details = ws->detailsView();
            if (!details->isVisible() || details->verticalScrollBar()->isVisible())
                problems << QStringLiteral("HI83 details hidden or scrolled: %1 px for %2 px of rows")
                                .arg(details->viewport()->height())
                                .arg(details->verticalHeader()->length());
            const QFontMetrics fm = details->fontMetrics();
            for (int r = 0; r < details->model()->rowCount(); ++r)
                for (int c = 0; c < details->model()->columnCount() && !details->isRowHidden(r); ++c) {
                    const QString text = details->model()->index(r, c).data().toString();
                    if (fm.horizontalAdvance(text) > details->columnWidth(c))
                        problems << QStringLiteral("HI83 detail \"%1\" cut (%2 px in %3)")
                                        .arg(text)
                                        .arg(fm.horizontalAdvance(text))
                                        .arg(details->columnWidth(c));
                }
            if (details->horizontalHeader()->length() > details->viewport()->width())
                problems << QStringLiteral("HI83 details %1 px wide in %2").arg(details->horizontalHeader()->length()).arg(
                    details->viewport()->width());
            ws->valuesDock()->raise();
        }
        w.disconnectDevice();
        return problems;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QCOMPARE(QGuiApplication::primaryScreen()->geometry().size(), laptopScreen() ? kSmall : kLarge);
        m_capture = m_dir.filePath(QStringLiteral("ten_seconds.imucap"));
        synthetic::CaptureSpec spec;
        spec.frames = 10000;
        QVERIFY(synthetic::writeCapture(m_capture, spec) > 0);
        m_session = m_dir.filePath(QStringLiteral("session"));
        QVERIFY(QDir().mkpath(m_session));
        record::SessionManifest manifest;
        for (const QString &name : {QStringLiteral("A"), QStringLiteral("B")}) {
            QVERIFY(QFile::copy(m_capture, QDir(m_session).filePath(name + QStringLiteral(".imucap"))));
            record::SessionManifest::Device d;
            d.name = name;
            d.linkKind = QStringLiteral("HiPNUC serial");
            d.file = name + QStringLiteral(".imucap");
            manifest.devices.push_back(d);
        }
        QString error;
        QVERIFY2(manifest.save(m_session, &error), qPrintable(error));
    }

    void everyWorkspaceKind_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<QSize>("size");
        QTest::addColumn<QString>("language");
        for (const QString &lang : {QStringLiteral("en"), QStringLiteral("zh_CN")})
            for (const QSize &size : {kSmall, kLarge})
                for (int k = 0; k <= int(Kind::SessionReplay); ++k)
                    QTest::addRow("%s %dx%d %s", kindName(Kind(k)), size.width(), size.height(), qPrintable(lang))
                        << k << size << lang;
    }

    void everyWorkspaceKind()
    {
        QFETCH(int, kind);
        QFETCH(QSize, size);
        QFETCH(QString, language);
        QString error;
        QVERIFY2(m_language.setLanguage(language, QString::fromUtf8(IMUDESK_QM_DIR), &error), qPrintable(error));
        const QStringList problems = runKind(Kind(kind), size);
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    }

    void restoredLayoutsAreRepaired()
    {
        QString error;
        QVERIFY(m_language.setLanguage(QStringLiteral("en"), QString::fromUtf8(IMUDESK_QM_DIR), &error));
        // What a screenshot run on the offscreen platform's 800x600 screen saved before:
        // a small window with the right column squeezed.
        ui::WindowSettings small;
        {
            MainWindow w(imudesk::test::builtInFamilies());
            w.resize(800, 600);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            DeviceWorkspace *ws = w.currentWorkspace();
            ws->resizeDocks({ws->valuesDock()}, {120}, Qt::Horizontal);
            ws->resizeDocks({ws->attitudeDock()}, {60}, Qt::Vertical);
            QCoreApplication::processEvents();
            small = w.windowSettings();
        }
        for (const QSize &size : {kSmall, kLarge}) {
            const QStringList problems = runKind(Kind::Serial, size, small);
            QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
        }
        // A layout saved at 1920x1080, opened at 1366x768, and the other way round.
        ui::WindowSettings large;
        {
            MainWindow w(imudesk::test::builtInFamilies());
            w.showMaximized();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QCoreApplication::processEvents();
            large = w.windowSettings();
        }
        QStringList problems = runKind(Kind::Serial, kSmall, large);
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
        ui::WindowSettings fromSmall;
        {
            MainWindow w(imudesk::test::builtInFamilies());
            w.resize(kSmall);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QCoreApplication::processEvents();
            fromSmall = w.windowSettings();
        }
        problems = runKind(Kind::Serial, kLarge, fromSmall);
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));

        // A window saved larger than this screen fits on it.
        ui::WindowSettings huge;
        {
            MainWindow w(imudesk::test::builtInFamilies());
            w.setGeometry(QRect(QPoint(400, 300), QSize(2560, 1600)));
            huge = w.windowSettings();
        }
        MainWindow fitted(imudesk::test::builtInFamilies(), huge);
        const QRect avail = fitted.screen()->availableGeometry();
        QVERIFY2(avail.contains(fitted.geometry()) || fitted.isMaximized(),
                 qPrintable(QStringLiteral("%1,%2 %3x%4").arg(fitted.x()).arg(fitted.y()).arg(fitted.width()).arg(
                     fitted.height())));
    }

    void screenshotRunLeavesSettingsAlone()
    {
        // The GUI itself, as docs/WINDOW.md runs it: --screenshot must not write the user's layout.
        QTemporaryDir config;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), config.path());
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        env.remove(QStringLiteral("IMUDESK_NO_SAVE_LAYOUT"));
        QProcess gui;
        gui.setProcessEnvironment(env);
        const QString shot = m_dir.filePath(QStringLiteral("shot.png"));
        gui.start(QString::fromUtf8(IMUDESK_GUI_PATH),
                  {QStringLiteral("--demo"), QStringLiteral("--screenshot"), shot, QStringLiteral("--after"),
                   QStringLiteral("1")});
        QVERIFY(gui.waitForFinished(60000));
        QCOMPARE(gui.exitCode(), 0);
        QVERIFY(QFile::exists(shot));
        const QString file = config.filePath(QStringLiteral("ImuDesk/ImuDesk.conf"));
        if (QFile::exists(file)) {
            QSettings written(file, QSettings::IniFormat);
            QVERIFY2(!written.contains(QLatin1String(ui::WindowSettings::kStateKey))
                         && !written.contains(QLatin1String(ui::WindowSettings::kWorkspaceStateKey))
                         && !written.contains(QLatin1String(ui::WindowSettings::kGeometryKey)),
                     qPrintable(written.allKeys().join(QLatin1Char(' '))));
        }
    }

    // Fresh settings on this 1920x1080 screen (1366x768 with IMUDESK_LAYOUT_LAPTOP): the GUI
    // opens maximised, not at 1280x860 in the middle of a larger screen (issue 53 point 17d).
    void freshSettingsOpenMaximised()
    {
        QTemporaryDir config;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment(); // this screen's platform
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), config.path());
        QProcess gui;
        gui.setProcessEnvironment(env);
        const QString shot = m_dir.filePath(QStringLiteral("fresh.png"));
        gui.start(QString::fromUtf8(IMUDESK_GUI_PATH),
                  {QStringLiteral("--demo"), QStringLiteral("--screenshot"), shot, QStringLiteral("--after"),
                   QStringLiteral("1")});
        QVERIFY(gui.waitForFinished(60000));
        QCOMPARE(gui.exitCode(), 0);
        const QImage image(shot);
        const QSize screen = laptopScreen() ? kSmall : kLarge;
        // Maximised: the whole screen but the platform's frame (the offscreen one's is 2 px).
        QVERIFY2(image.width() >= screen.width() - 16 && image.height() >= screen.height() - 16,
                 qPrintable(QStringLiteral("%1x%2 on %3x%4").arg(image.width()).arg(image.height()).arg(screen.width()).arg(
                     screen.height())));
        // A saved geometry is kept: the window restored from it is not maximised.
        ui::WindowSettings saved;
        {
            MainWindow w(imudesk::test::builtInFamilies());
            w.resize(1000, 700);
            saved = w.windowSettings();
        }
        MainWindow restored(imudesk::test::builtInFamilies(), saved);
        restored.showAsSaved();
        QVERIFY(QTest::qWaitForWindowExposed(&restored));
        QVERIFY(!restored.isMaximized());
        QCOMPARE(restored.width(), 1000); // its height: at least what its layout needs
        MainWindow fresh(imudesk::test::builtInFamilies());
        fresh.showAsSaved();
        QVERIFY(QTest::qWaitForWindowExposed(&fresh));
        QVERIFY(fresh.isMaximized());
    }

    // The mounting picker (issue 53 point 17e): on this screen (1920x1080, or 1366x768 with
    // IMUDESK_LAYOUT_LAPTOP), in English and Chinese, all 24 pictures in sight at once, each at
    // least the size at which it reads, none cut by the dialog or its scroll area.
    void mountingPicker_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
    }
    void mountingPicker()
    {
        QFETCH(QString, language);
        QString error;
        QVERIFY2(m_language.setLanguage(language, QString::fromUtf8(IMUDESK_QM_DIR), &error), qPrintable(error));
        ui::MountingPicker picker(205, false);
        picker.show();
        QVERIFY(QTest::qWaitForWindowExposed(&picker));
        QVERIFY(layoutSettled(picker));
        const QRect avail = picker.screen()->availableGeometry();
        QVERIFY2(avail.contains(picker.frameGeometry()) || avail.contains(picker.geometry()),
                 qPrintable(QStringLiteral("%1x%2").arg(picker.width()).arg(picker.height())));
        const QWidget *viewport = picker.tileArea()->viewport();
        QStringList problems = cutOrOutside(picker);
        for (int code : model::Mounting::validCodes()) {
            const ui::MountingTile *tile = picker.tile(code);
            QVERIFY(tile);
            const QRect inView(tile->mapTo(viewport, QPoint(0, 0)), tile->size());
            if (tile->width() < 120 || tile->height() < 110 || tile->width() < tile->readableSize().width()
                || tile->height() < tile->readableSize().height())
                problems << QStringLiteral("URFR %1: %2x%3 px").arg(code).arg(tile->width()).arg(tile->height());
            if (!viewport->rect().contains(inView))
                problems << QStringLiteral("URFR %1 cut by the scroll area").arg(code);
        }
        // IMUDESK_LAYOUT_SHOTS=DIR: the picker as a PNG there (scripts/screenshots.sh).
        if (const QString shots = qEnvironmentVariable("IMUDESK_LAYOUT_SHOTS"); !shots.isEmpty())
            picker.grab().save(QDir(shots).filePath(QStringLiteral("mounting-picker-%1x%2-%3.png")
                                                        .arg(avail.width())
                                                        .arg(avail.height())
                                                        .arg(language)));
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    }

    void presetsAndPanelsOnDemand()
    {
        QString error;
        QVERIFY(m_language.setLanguage(QStringLiteral("en"), QString::fromUtf8(IMUDESK_QM_DIR), &error));
        MainWindow w(imudesk::test::builtInFamilies());
        w.setErrorPresenter([](const QString &) {});
        showAt(w, kSmall);
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        DeviceWorkspace *ws = w.currentWorkspace();
        // The panels below the charts start closed.
        for (QDockWidget *dock : {ws->consoleDock(), ws->rawBytesDock(), ws->commandLogDock(), ws->recordingDock()})
            QVERIFY2(dock->isHidden(), qPrintable(dock->objectName()));
        QVERIFY(!ws->attitudeDock()->isHidden());
        sim::SimOptions options;
        options.motion = sim::Motion::Static;
        QVERIFY2(w.openLink(imudesk::device::LinkRequest::simulatedHipnuc(options, 0), &error), qPrintable(error));
        QTRY_VERIFY_WITH_TIMEOUT(ws->state() == device::SessionState::Connected, 15000);
        // An ERR reply opens the console, where the user sees it.
        ws->sendConsoleCommand(QStringLiteral("NO SUCH COMMAND"));
        QTRY_VERIFY_WITH_TIMEOUT(!ws->consoleDock()->isHidden(), 5000);

        // Every preset keeps the layout whole at 1366x768; each shows what its task needs.
        const auto presetAction = [&w](DeviceWorkspace::LayoutPreset p) {
            return w.findChild<QAction *>(QStringLiteral("layoutPreset_") + DeviceWorkspace::presetKey(p));
        };
        for (int i = 0; i < DeviceWorkspace::kPresetCount; ++i) {
            const auto preset = DeviceWorkspace::LayoutPreset(i);
            QAction *action = presetAction(preset);
            QVERIFY(action);
            action->trigger();
            QCoreApplication::processEvents();
            QCOMPARE(ws->preset(), preset);
            const QStringList problems = layoutProblems(w, false);
            QVERIFY2(problems.isEmpty(), qPrintable(DeviceWorkspace::presetKey(preset) + QLatin1String(": ")
                                                    + problems.join(QLatin1Char('\n'))));
            QCOMPARE(ws->configDock()->isVisible(), preset == DeviceWorkspace::LayoutPreset::Configure);
            QCOMPARE(ws->rawBytesDock()->isVisible(), preset == DeviceWorkspace::LayoutPreset::Analyse);
            QCOMPARE(ws->consoleDock()->isHidden(), preset != DeviceWorkspace::LayoutPreset::Calibrate);
        }
        // Remembered with the window's settings; Reset layout puts a moved dock back.
        QCOMPARE(w.windowSettings().preset, QStringLiteral("analyse"));
        presetAction(DeviceWorkspace::LayoutPreset::Monitor)->trigger();
        ws->attitudeDock()->setFloating(true);
        w.findChild<QAction *>(QStringLiteral("resetLayoutAction"))->trigger();
        QVERIFY(!ws->attitudeDock()->isFloating() && ws->attitudeDock()->isVisible());
        QCOMPARE(w.windowSettings().preset, QStringLiteral("monitor"));
        // Device > Configuration from the Monitor layout: the settings table gets the right
        // column (before: two rows behind the values at 1366x768), and the panel reads the
        // device as it opens.
        presetAction(DeviceWorkspace::LayoutPreset::Monitor)->trigger();
        QVERIFY(ws->configPanel());
        w.findChild<QAction *>(QStringLiteral("configurationAction"))->trigger();
        QCoreApplication::processEvents();
        QVERIFY(ws->configDock()->isVisible());
        QTRY_VERIFY_WITH_TIMEOUT(ws->configPanel()->controller().identity().usable(), 15000);
        QTRY_VERIFY_WITH_TIMEOUT(!ws->configPanel()->controller().busy(), 15000);
        {
            const QTableView *table = ws->configPanel()->table();
            const int rows = table->viewport()->height() / std::max(1, table->verticalHeader()->defaultSectionSize());
            QVERIFY2(rows >= 10, qPrintable(QStringLiteral("%1 rows of the settings table in view").arg(rows)));
            const QStringList problems = layoutProblems(w, false);
            QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
        }
        // View > Compare devices on a laptop screen: the window stays inside the screen (it
        // grew to 878 px on 768 before) and the comparison is whole.
        if (laptopScreen()) {
            presetAction(DeviceWorkspace::LayoutPreset::Monitor)->trigger();
            w.findChild<QAction *>(QStringLiteral("compareDevicesAction"))->trigger();
            QCoreApplication::processEvents();
            QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
            QVERIFY(w.comparisonDock()->isVisible());
            const QRect avail = w.screen()->availableGeometry();
            QVERIFY2(w.height() <= avail.height() && w.minimumSizeHint().height() <= avail.height(),
                     qPrintable(QStringLiteral("window %1 px, least %2, screen %3")
                                    .arg(w.height())
                                    .arg(w.minimumSizeHint().height())
                                    .arg(avail.height())));
            const QWidget *chart = w.comparisonChart()->chartView();
            const QRect onScreen(chart->mapToGlobal(QPoint(0, 0)), chart->size());
            QVERIFY2(avail.contains(onScreen) && chart->height() >= ui::ComparisonChart::kMinimumChartHeight,
                     qPrintable(QStringLiteral("comparison %1,%2 %3x%4")
                                    .arg(onScreen.x()).arg(onScreen.y()).arg(onScreen.width()).arg(onScreen.height())));
            QStringList problems = layoutProblems(w, false);
            if (w.comparisonDock()->isFloating())
                problems << cutOrOutside(*w.comparisonDock());
            QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
            w.findChild<QAction *>(QStringLiteral("compareDevicesAction"))->trigger();
        }
        // A recording opens its panel.
        w.disconnectDevice();
    }

    // Every wizard page and the firmware-update dialog as a work place: at the size it takes on
    // a 1366x768 and a 1920x1080 screen, in English and Chinese, no text cut, nothing outside;
    // the magnetometer sphere >= 400 px on the small screen. With IMUDESK_LAYOUT_SHOTS=DIR
    // each page is also saved there as a PNG (scripts/screenshots.sh).
    void wizardPages_data()
    {
        QTest::addColumn<QSize>("screen");
        QTest::addColumn<QString>("language");
        for (const QString &lang : {QStringLiteral("en"), QStringLiteral("zh_CN")})
            for (const QSize &size : {kSmall, kLarge})
                QTest::addRow("%dx%d %s", size.width(), size.height(), qPrintable(lang)) << size << lang;
    }

    void wizardPages()
    {
        QFETCH(QSize, screen);
        QFETCH(QString, language);
        QString error;
        QVERIFY2(m_language.setLanguage(language, QString::fromUtf8(IMUDESK_QM_DIR), &error), qPrintable(error));
        // What fitWorkPlace() gives on that screen (this test's screen is 1920x1080).
        const QSize room(screen.width() * 94 / 100, screen.height() * 94 / 100 - 30);
        const QString shots = qEnvironmentVariable("IMUDESK_LAYOUT_SHOTS");
        const auto check = [&](QWidget &window, const QString &name) {
            window.resize(window.size().boundedTo(room));
            QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
            QCoreApplication::processEvents();
            QStringList problems = cutOrOutside(window);
            if (!shots.isEmpty())
                window.grab().save(QDir(shots).filePath(QStringLiteral("%1-%2x%3-%4.png")
                                                            .arg(name)
                                                            .arg(screen.width())
                                                            .arg(screen.height())
                                                            .arg(language)));
            return problems.isEmpty() ? QString() : name + QLatin1String(": ") + problems.join(QLatin1Char('\n'));
        };
        const auto everyPage = [&](QWizard &wizard, const QString &name) {
            QStringList problems;
            wizard.show();
            if (!QTest::qWaitForWindowExposed(&wizard))
                return QStringList{name + QLatin1String(" not exposed")};
            for (int id : wizard.pageIds()) {
                wizard.setStartId(id);
                wizard.restart();
                const QString p = check(wizard, QStringLiteral("%1-page%2").arg(name).arg(id));
                if (!p.isEmpty())
                    problems << p;
            }
            return problems;
        };
        QStringList problems;
        device::DeviceSession session;
        {
            ui::MagCalibrationWizard mag(session, model::FirmwareVersion{1, 7, 1});
            problems << everyPage(mag, QStringLiteral("wizard-magnetometer"));
            mag.setStartId(ui::MagCalibrationWizard::RotationPage);
            mag.restart();
            check(mag, QStringLiteral("wizard-magnetometer-rotation"));
            const int sphere = std::min(mag.sphere()->width(), mag.sphere()->height());
            if (sphere < (screen == kSmall ? 400 : 500))
                problems << QStringLiteral("magnetometer sphere %1 px").arg(sphere);
        }
        {
            ui::GyroScaleWizard gyro(session);
            problems << everyPage(gyro, QStringLiteral("wizard-gyro-scale"));
        }
        {
            ui::AttitudeResetWizard reset(session);
            problems << everyPage(reset, QStringLiteral("wizard-attitude-reset"));
        }
        {
            device::Hec495Session compass;
            ui::Hec495CalibrationWizard hec(compass);
            problems << everyPage(hec, QStringLiteral("wizard-hec495"));
        }
        {
            model::DeviceIdentity id;
            id.productName = "HI14R3";
            id.firmware = model::FirmwareVersion{1, 7, 1};
            ui::FirmwareUpdateDialog update(QStringLiteral("/dev/ttyUSB0"), 115200, id);
            update.setDemoImageOffered(true);
            update.show();
            QVERIFY(QTest::qWaitForWindowExposed(&update));
            const QString p = check(update, QStringLiteral("firmware-update"));
            if (!p.isEmpty())
                problems << p;
        }
        problems.removeAll(QString());
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    }

    void statusFlagsColouredByMeaning()
    {
        QString error;
        QVERIFY(m_language.setLanguage(QStringLiteral("en"), QString::fromUtf8(IMUDESK_QM_DIR), &error));
        ui::StatusFlagsWidget flags;
        flags.setStatus(quint16((1u << model::MainStatus::MagDist) | (1u << model::MainStatus::MagAiding)
                                | (1u << model::MainStatus::Static)));
        const auto style = [&flags](const char *name) {
            return flags.findChild<QLabel *>(QStringLiteral("flag_") + QLatin1String(name))->styleSheet();
        };
        // A warning, good news and information each look different; a clear flag is grey.
        QVERIFY(style("MAG_DIST") != style("MAG_AIDING"));
        QVERIFY(style("MAG_DIST") != style("STATIC"));
        QVERIFY(style("MAG_AIDING") != style("STATIC"));
        QVERIFY(style("ATT_CONV") != style("MAG_DIST"));
        QVERIFY(flags.flagToolTip(model::MainStatus::MagDist).contains(QLatin1String("warning")));
        QVERIFY(flags.flagToolTip(model::MainStatus::MagDist).contains(QLatin1String("disturb")));
        // Each tooltip names its source; bit 9 is reserved in the manual and says so.
        QVERIFY(flags.flagToolTip(model::MainStatus::MagDist).contains(QLatin1String("manual v1.7.1, 5.9.13")));
        QVERIFY(flags.flagToolTip(model::MainStatus::Static).contains(QLatin1String("SDK")));
        QVERIFY(flags.flagToolTip(model::MainStatus::Static).contains(QLatin1String("reserved")));
    }
};

static int testMain(int argc, char **argv)
{
    // A 1920x1080 screen (the offscreen platform's default is 800x600). With
    // IMUDESK_LAYOUT_SCALE=S: a screen of S times the pixels at scale factor S (a 4K monitor at
    // 200 %), the same 1920x1080 in logical pixels.
    const double scale = qEnvironmentVariableIsSet("IMUDESK_LAYOUT_SCALE")
        ? QString::fromLocal8Bit(qgetenv("IMUDESK_LAYOUT_SCALE")).toDouble()
        : 1.0;
    // IMUDESK_LAYOUT_LAPTOP=1: a 1366x768 screen, where the window opens maximised.
    const QSize screen = laptopScreen() ? kSmall : kLarge;
    if (scale < 1.0 || scale > 4.0)
        return 2;
    if (scale != 1.0)
        qputenv("QT_SCALE_FACTOR", QByteArray::number(scale));
    QTemporaryDir dir;
    if (!imudesk::test::layout::useOffscreenScreen(
            dir, QSize(qRound(screen.width() * scale), qRound(screen.height() * scale)), QStringLiteral("layout-test")))
        return 2;
    qputenv("IMUDESK_NO_SAVE_LAYOUT", "1");
    // The wizards keep their runs under the data location: a temporary one, never the user's
    // ~/.local/share (the GUI that screenshotRunLeavesSettingsAlone starts inherits it too).
    QTemporaryDir data;
    if (!data.isValid())
        return 2;
    qputenv("XDG_DATA_HOME", QFile::encodeName(data.path()));
    QApplication app(argc, argv);
    TstLayout test;
    return QTest::qExec(&test, argc, argv);
}

IMUDESK_TEST_CUSTOM_MAIN(testMain)

#include "tst_layout.moc"
