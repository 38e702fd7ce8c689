// DeviceWorkspace shows any family's link (DeviceLink) in its live views: samples reach the
// charts and the values table, the state reaches the status bar, and what the link needs
// (its simulator) is released when it closes.
#include "../common/ui_families.h"
#include "attitude/attitude_widget.h"
#include "charts/chart_panel.h"
#include "charts/chart_view.h"
#include "workspace/device_workspace.h"
#include "device/device_link.h"
#include "workspace/family_ui.h"
#include "workspace/main_window.h"
#include "workspace/raw_bytes_view.h"
#include "itemmodels/latest_values_model.h"
#include "../common/hipnuc_link.h"
#include "../common/test_main.h"

#include <QApplication>
#include <QDockWidget>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

#include <cmath>

using namespace imudesk;
using device::SessionState;

namespace {

// A link driven by the test: what a HEC495, Modbus or CAN session does, without a port.
class ScriptedLink : public device::DeviceLink {
public:
    using DeviceLink::DeviceLink;
    void close() override
    {
        ++closes;
        setState(SessionState::Closed, QString());
    }
    QString linkKind() const override { return QStringLiteral("Scripted"); }
    void connectNow(const model::DeviceIdentity &id)
    {
        setState(SessionState::Connected, QString());
        Q_EMIT identityChanged(id);
    }
    void push(int from, int count)
    {
        std::vector<model::Sample> batch;
        for (int i = from; i < from + count; ++i) {
            model::Sample s;
            s.fields = model::FieldAcc | model::FieldEuler;
            s.deviceTimeMs = 1000.0 + i * 10;
            s.hostTimeNs = int64_t(i) * 10'000'000;
            s.acc = {0.01 * i, -0.5, 1.0};
            s.roll = 1.0;
            s.pitch = 2.0;
            s.yaw = 123.0 + i;
            batch.push_back(s);
        }
        store().append(batch);
    }
    int closes = 0;
};

} // namespace

class TstDeviceWorkspace : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void showsAnAttachedLink()
    {
        ui::DeviceWorkspace ws;
        ws.resize(1200, 800);
        ws.show();
        QVERIFY(QTest::qWaitForWindowExposed(&ws));
        auto link = std::make_unique<ScriptedLink>();
        ScriptedLink *raw = link.get();
        auto keepAlive = std::make_shared<int>(7);
        std::weak_ptr<int> watch = keepAlive;
        QVERIFY(ws.attachLink(std::move(link), QStringLiteral("Scripted bus"), std::move(keepAlive)));
        QVERIFY(!test::hipnucOf(ws));
        QCOMPARE(&ws.link(), static_cast<device::DeviceLink *>(raw));
        // A link without capabilities: none of the serial session's panels, no settings panel.
        QVERIFY(!ws.configPanel());
        for (QDockWidget *dock : {ws.consoleDock(), ws.rawBytesDock(), ws.commandLogDock(), ws.recordingDock(),
                                  ws.configDock()}) {
            QVERIFY2(!ws.offersDock(dock), qPrintable(dock->objectName()));
            QVERIFY(!dock->isVisible());
        }

        model::DeviceIdentity id;
        id.productName = "HEC495";
        id.serial = "addr 0";
        raw->connectNow(id);
        QCOMPARE(ws.state(), SessionState::Connected);
        QVERIFY(ws.isBusy());
        QVERIFY(ws.title().contains(QStringLiteral("HEC495")));
        QVERIFY(ws.statusText().contains(QStringLiteral("HEC495")));

        raw->push(0, 200);
        ws.refreshViews();
        QCOMPARE(ws.chartPanel()->history().size(), size_t(200));
        // The values table shows the newest sample (its numbers refresh at most ten times a
        // second, so within kValuesIntervalMs of the view clock).
        const auto *values = ws.valuesModel();
        const auto sawYaw = [values] {
            for (int r = 0; r < values->rowCount(); ++r)
                if (values->index(r, 1).data().toString().startsWith(QStringLiteral("322.0")))
                    return true;
            return false;
        };
        QTRY_VERIFY_WITH_TIMEOUT(sawYaw(), 5 * ui::DeviceWorkspace::kValuesIntervalMs);

        // A second attach while connected is refused; disconnecting closes the link and
        // releases what it needed.
        QVERIFY(!ws.attachLink(std::make_unique<ScriptedLink>(), QStringLiteral("other")));
        ws.disconnectDevice();
        QCOMPARE(raw->closes, 1);
        QCOMPARE(ws.state(), SessionState::Closed);
        QVERIFY(watch.expired());
        // The data stays on screen after the close.
        QCOMPARE(ws.chartPanel()->history().size(), size_t(200));
    }

    // CRC errors and frames lost stand out in the status bar once they are not zero (amber, as
    // a warning flag); statusText() stays plain text.
    void damageCountsHighlighted()
    {
        ui::DeviceWorkspace ws;
        ws.show();
        auto link = std::make_unique<ScriptedLink>();
        ScriptedLink *raw = link.get();
        QVERIFY(ws.attachLink(std::move(link), QStringLiteral("Scripted bus")));
        raw->connectNow(model::DeviceIdentity{});
        auto *label = ws.findChild<QLabel *>(QStringLiteral("statsLabel"));
        QVERIFY(label);
        device::SessionStats stats;
        stats.baud = 115200;
        stats.rateByType["HI91"] = 100.0;
        Q_EMIT raw->statsUpdated(stats);
        QVERIFY2(ws.statusText().contains(QStringLiteral("CRC errors 0 · lost 0")), qPrintable(ws.statusText()));
        QVERIFY(!label->text().contains(QLatin1String("#ef6c00")));
        stats.framesLost = 7;
        Q_EMIT raw->statsUpdated(stats);
        QVERIFY2(ws.statusText().contains(QStringLiteral("CRC errors 0 · lost 7")), qPrintable(ws.statusText()));
        const QString html = label->text();
        const int span = html.indexOf(QLatin1String("#ef6c00"));
        QVERIFY2(span > 0 && html.indexOf(QLatin1String("lost 7"), span) > span
                     && html.indexOf(QLatin1String("CRC errors 0")) < span,
                 qPrintable(html));
        stats.crcErrors = 2;
        Q_EMIT raw->statsUpdated(stats);
        QCOMPARE(label->text().count(QLatin1String("#ef6c00")), 2);
        QVERIFY(!ws.statusText().contains(QLatin1Char('<')));
        ws.disconnectDevice();
    }

    // Bytes that form no frame (issue 53, 2): a note in the tab's status area while it lasts, not
    // a modal error; it goes when frames arrive again, and the console keeps both ends.
    void streamWarningIsANoteThatGoes()
    {
        ui::DeviceWorkspace ws;
        ws.resize(1200, 800);
        ws.show();
        QVERIFY(QTest::qWaitForWindowExposed(&ws));
        auto link = std::make_unique<ScriptedLink>();
        ScriptedLink *raw = link.get();
        QVERIFY(ws.attachLink(std::move(link), QStringLiteral("Scripted bus")));
        raw->connectNow(model::DeviceIdentity{});
        QSignalSpy errors(&ws, &ui::DeviceWorkspace::errorReported);
        auto *note = ws.findChild<QLabel *>(QStringLiteral("streamWarningLabel"));
        QVERIFY(note);
        QVERIFY(!note->isVisible());
        const QString text = QStringLiteral("Bytes keep arriving on Scripted bus but none of them form a frame");
        Q_EMIT raw->streamWarning(text);
        QVERIFY(note->isVisible());
        QCOMPARE(note->text(), text);
        QVERIFY(errors.isEmpty()); // no modal: the main window shows errorReported as one
        Q_EMIT raw->streamWarning(QString());
        QVERIFY(!note->isVisible());
        QVERIFY(errors.isEmpty());
        ws.disconnectDevice();
    }

    // The attitude view's reference (issue 55): asked for from its context menu, it starts once
    // the simulated module has rested 1 s and is drawn beside the module with how far apart
    // they are; taken away again on request.
    void referenceAttitudeBesideTheModule()
    {
        ui::DeviceWorkspace ws;
        ws.resize(1200, 800);
        ws.show();
        QVERIFY(QTest::qWaitForWindowExposed(&ws));
        QString error;
        QVERIFY2(ui::openLinkIn(ws, test::builtInFamilies(), device::LinkRequest::simulatedHipnuc(sim::SimOptions{}, 115200), &error),
                 qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(ws.state(), SessionState::Connected, 15000);
        ui::AttitudeWidget *view = ws.attitudeWidget();
        Q_EMIT view->ghostRequested(true);
        QVERIFY(view->ghostShown());
        QTRY_VERIFY_WITH_TIMEOUT(view->ghostCaption().startsWith(QStringLiteral("Reference ")), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(view->ghostCaption().contains(QStringLiteral("apart")), 10000);
        // The simulated module reports the truth: the reference agrees within a few tenths of a degree.
        const double apart = view->ghostCaption().section(QLatin1Char(' '), 1, 1).chopped(1).toDouble();
        QVERIFY2(apart < 0.5, qPrintable(view->ghostCaption()));
        // The chart of their difference fills on the view's clock.
        QTRY_VERIFY_WITH_TIMEOUT(view->ghostTrace().size() >= 5, 5000);
        for (const QPointF &v : view->ghostTrace())
            QVERIFY(v.y() < 0.5);
        Q_EMIT view->ghostRequested(false);
        QVERIFY(!view->ghostShown());
        QVERIFY(view->ghostTrace().empty());
        ws.disconnectDevice();
        QTRY_COMPARE(ws.state(), SessionState::Closed);
    }

    void simulatedCompassReachesTheViews()
    {
        ui::DeviceWorkspace ws;
        ws.resize(1200, 800);
        ws.show();
        QVERIFY(QTest::qWaitForWindowExposed(&ws));
        QString error;
        const ui::FamilyUiRegistry &families = test::builtInFamilies();
        QVERIFY2(ui::openLinkIn(ws, families, device::LinkRequest::simulatedHec495(sim::Motion::Spin), &error),
                 qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(ws.state(), SessionState::Connected, 15000);
        QTRY_VERIFY_WITH_TIMEOUT(ws.link().store().totalAppended() > 20, 15000);
        QTRY_VERIFY_WITH_TIMEOUT(ws.chartPanel()->history().size() > 20, 5000);
        QVERIFY(ws.valuesModel()->valueText(models::LatestValuesModel::Yaw) != QStringLiteral("\u2014"));
        // The compass sends angles only: the attitude view builds its quaternion from them.
        QVERIFY(ws.attitudeWidget()->hasData());
        // A byte link: its raw bytes are offered and show the Witlink frames (77 ...), both ways;
        // no console or settings, which are HiPNUC serial's.
        QVERIFY(ws.offersDock(ws.rawBytesDock()));
        QVERIFY(!ws.offersDock(ws.consoleDock()) && !ws.offersDock(ws.configDock()));
        ws.openDock(ws.rawBytesDock());
        QTRY_VERIFY_WITH_TIMEOUT((ws.rawBytesView()->refresh(), ws.rawBytesView()->text().contains(QStringLiteral("77 "))),
                                 5000);
        ws.disconnectDevice();
        QTRY_COMPARE(ws.state(), SessionState::Closed);
    }

    // Issue 53 point 6. The simulated compass streams its default content (angles) at 50 Hz
    // after its 3 s quiet window, in which the session polls "read all" (records with
    // acceleration, rate and the module's clock). Its Euler chart runs on smoothly across that
    // change (before: the angles of a whole second stood at the records' last device time, a
    // step and then a flat stretch), and the acceleration and rate charts say why they stay
    // empty, with a switch of the output to all data that fills them.
    void compassChartsAcrossItsOutput()
    {
        ui::DeviceWorkspace ws;
        ws.resize(1200, 800);
        ws.show();
        QVERIFY(QTest::qWaitForWindowExposed(&ws));
        QString error;
        const ui::FamilyUiRegistry &families = test::builtInFamilies();
        QVERIFY2(ui::openLinkIn(ws, families, device::LinkRequest::simulatedHec495(sim::Motion::Spin), &error),
                 qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(ws.state(), SessionState::Connected, 15000);
        const plot::ChannelHistory &h = ws.chartPanel()->history();
        QTRY_VERIFY_WITH_TIMEOUT(!h.empty() && h.newestTime(plot::TimeAxis::Host) > 6.5, 20000);

        // The yaw on the device axis: the compass turns at 30 deg/s, smoothly. No pile of rows at
        // one instant turning through more than kPileDeg (a step: the bug piled a second's rows,
        // about 30 deg, at the records' last time; frames without a clock that a loaded host
        // reads in one go share their arrival, a pile of a few degrees), no stretch of the axis
        // without a row (a flat line: the bug's axis jumped a second), no turn faster than the
        // motion's, but for kJitterDeg: frames without a clock are stamped at their arrival, and a
        // loaded host (the suite beside two builds) reads two frames sent 70 ms apart 6 ms apart
        // (2 deg; seen in CI), far below the bug's 30 deg.
        constexpr double kPileDeg = 12.0;
        constexpr double kJitterDeg = 4.0;
        double pile = 0.0;
        int rows = 0;
        size_t previous = SIZE_MAX;
        for (size_t i = 0; i < h.size(); ++i) {
            if (!h.has(plot::Channel::Yaw, i))
                continue;
            ++rows;
            if (previous != SIZE_MAX) {
                const double dt = h.deviceTime(i) - h.deviceTime(previous);
                double dyaw = double(h.value(plot::Channel::Yaw, i)) - double(h.value(plot::Channel::Yaw, previous));
                dyaw -= 360.0 * std::round(dyaw / 360.0);
                const QString where = QStringLiteral("row %1 at %2 s (host %3 s): %4 s and %5 deg after the one before")
                                          .arg(i)
                                          .arg(h.deviceTime(i))
                                          .arg(h.hostTime(i))
                                          .arg(dt)
                                          .arg(dyaw);
                QVERIFY2(dt >= 0.0 && dt < 0.4, qPrintable(where));
                pile = dt < 1e-6 ? pile + std::abs(dyaw) : 0.0;
                QVERIFY2(pile < kPileDeg, qPrintable(where + QStringLiteral(", %1 deg at this instant").arg(pile)));
                if (dt >= 1e-6)
                    QVERIFY2(std::abs(dyaw) <= kJitterDeg + 120.0 * dt, qPrintable(where));
            }
            previous = i;
        }
        QVERIFY2(rows > 200, qPrintable(QString::number(rows)));

        // Angles only since the quiet window: the acceleration chart says why it is empty and
        // offers the switch.
        ui::ChartView *acc = ws.chartPanel()->chart(ui::ChartKind::Accelerometer);
        QTRY_VERIFY_WITH_TIMEOUT(acc->hasNote(), 5000);
        QVERIFY(acc->isVisible());
        QVERIFY2(acc->noteText().contains(QStringLiteral("carries no acceleration at its current setting")),
                 qPrintable(acc->noteText()));
        QVERIFY(ws.chartPanel()->chart(ui::ChartKind::Gyroscope)->hasNote());
        QVERIFY(!ws.chartPanel()->chart(ui::ChartKind::Euler)->hasNote());
        QVERIFY(acc->noteButton()->isVisible() && acc->noteButton()->isEnabled());
        // One click: the compass outputs all data (0x49 02), acceleration and rate arrive.
        // The relative field is not in the angles' output (only the identification's read-all
        // record had it): its chart is not there, or says why it is empty.
        ui::ChartView *relative = ws.chartPanel()->chart(ui::ChartKind::MagneticRelative);
        QTRY_VERIFY_WITH_TIMEOUT(relative->isVisible() && relative->hasNote(), 5000);
        QVERIFY(relative->noteText().contains(QStringLiteral("no relative magnetic field")));
        QVERIFY(relative->noteButton()->isVisible()); // the same switch as the acceleration's
        const double clicked = h.newestTime(plot::TimeAxis::Host);
        QTest::mouseClick(acc->noteButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(h.channelSeenHost(plot::Channel::AccZ) > clicked, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(!acc->hasNote(), 5000);
        QVERIFY(!ws.chartPanel()->chart(ui::ChartKind::Gyroscope)->hasNote());
        // All data carries the compass's relative field (its own chart, one line per axis) and its
        // magnetic roll (a line on the Euler chart), and the values table has their rows.
        QTRY_VERIFY_WITH_TIMEOUT(h.channelSeenHost(plot::Channel::MagRelX) > clicked, 10000);
        QVERIFY(h.channelSeenHost(plot::Channel::MagRoll) > clicked);
        QTRY_VERIFY_WITH_TIMEOUT(relative->isVisible(), 5000);
        QVERIFY(!relative->hasNote());
        QCOMPARE(ui::ChartView::kindOf(plot::Channel::MagRoll), ui::ChartKind::Euler);
        QVERIFY(ws.valuesModel()->everSeen(models::LatestValuesModel::MagRelZ));
        QVERIFY(!ws.chartPanel()->chart(ui::ChartKind::Magnetometer)->isVisible() ||
                ws.chartPanel()->chart(ui::ChartKind::Magnetometer)->hasNote()); // no µT field: not its magnetometer chart
        ws.disconnectDevice();
        QTRY_COMPARE(ws.state(), SessionState::Closed);
    }

    void mainWindowShowsTheSimulatedCompass()
    {
        ui::MainWindow window(imudesk::test::builtInFamilies());
        window.resize(1280, 860);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QString error;
        QVERIFY2(window.connectSimulated(imudesk::ui::PortChoice::simulated(QStringLiteral("HEC495"), QString()), 0, &error), qPrintable(error));
        ui::DeviceWorkspace *ws = window.currentWorkspace();
        QTRY_COMPARE_WITH_TIMEOUT(ws->state(), SessionState::Connected, 15000);
        QTRY_VERIFY_WITH_TIMEOUT(ws->link().store().totalAppended() > 20, 15000);
        QTRY_VERIFY_WITH_TIMEOUT(ws->chartPanel()->history().size() > 20, 5000);
        QVERIFY(ws->valuesModel()->valueText(models::LatestValuesModel::Yaw) != QStringLiteral("\u2014"));
    }

    void serialSessionReplacesAnAttachedLink()
    {
        ui::DeviceWorkspace ws;
        auto link = std::make_unique<ScriptedLink>();
        link->push(0, 50);
        QVERIFY(ws.attachLink(std::move(link), QStringLiteral("Scripted bus")));
        ws.refreshViews();
        QCOMPARE(ws.chartPanel()->history().size(), size_t(50));
        // Connecting a serial port drops the attached link and starts the views afresh.
        const ui::FamilyUiRegistry &families = test::builtInFamilies();
        QString error;
        QVERIFY2(ui::openLinkIn(ws, families,
                                device::LinkRequest::serial(QStringLiteral("/dev/imudesk-no-such-port"), 115200,
                                                            QStringLiteral("hipnuc")),
                                &error),
                 qPrintable(error));
        QVERIFY(test::hipnucOf(ws));
        QVERIFY(ws.configPanel());
        QVERIFY(ws.offersDock(ws.consoleDock()) && ws.offersDock(ws.configDock()));
        QCOMPARE(ws.chartPanel()->history().size(), size_t(0));
        QTRY_COMPARE(ws.state(), SessionState::Failed);
    }
};

IMUDESK_TEST_MAIN(TstDeviceWorkspace)
#include "tst_device_workspace.moc"
