// CanConfigPanel offscreen on a real CanSession and the CAN simulator over virtualcan: the
// controls follow the detected protocol, Apply writes and the log shows the confirmation,
// Send SYNC makes a SYNC-mode TPDO answer, the node scan shows progress and its result.
#include "bus/can_config_panel.h"
#include "bus/can_settings_table.h"
#include "device/can_session.h"
#include "sim/can_simulator.h"
#include "../common/test_main.h"

#include <QApplication>
#include <QCanBus>
#include <QCheckBox>
#include <QComboBox>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>

using namespace imudesk;

namespace {

// A simulated CAN device on its own virtualcan interface and the session the panel shows.
struct Bus {
    explicit Bus(const sim::CanSimOptions &o) : simulator(o) {}
    // Starts the simulator, then opens the session (given protocol, node) shown in panel.
    bool start(const QString &iface, ui::CanConfigPanel &panel, protocol::can::CanProtocol protocol, int node = -1)
    {
        QString err;
        if (!simulator.start(QStringLiteral("virtualcan"), iface, &err)) {
            qWarning() << err;
            return false;
        }
        device::CanSessionOptions so;
        so.interfaceName = iface;
        so.protocol = protocol;
        so.node = node;
        // The simulated module answers from this (the GUI) thread: on a loaded machine a repaint
        // can hold an answer past the default second. What a timeout does is tested elsewhere.
        so.requestTimeoutMs = 3000;
        panel.setSession(&session);
        session.open(so);
        return true;
    }
    sim::CanSimulator simulator;
    device::CanSession session;
};

sim::CanSimOptions simOptions(protocol::can::CanProtocol protocol, bool hec495)
{
    sim::CanSimOptions o;
    o.protocol = protocol;
    o.hec495 = hec495;
    return o;
}

} // namespace

class TstCanConfigPanel : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        if (!QCanBus::instance()->plugins().contains(QStringLiteral("virtualcan")))
            QSKIP("Qt's virtualcan CAN bus plugin is not installed (package libqt6serialbus6-plugins)");
    }

    void canopenPanel()
    {
        const QString iface = QStringLiteral("tcp://127.0.0.1:24487/can0");
        sim::CanSimOptions o;
        o.protocol = protocol::can::CanProtocol::CanOpen;
        sim::CanSimulator simulator(o);
        QString err;
        QVERIFY2(simulator.start(QStringLiteral("virtualcan"), iface, &err), qPrintable(err));
        device::CanSession session;
        device::CanSessionOptions so;
        so.interfaceName = iface;
        ui::CanConfigPanel panel;
        panel.resize(600, 500);
        panel.show();
        QVERIFY(!panel.applyPeriodButton()->isEnabled());
        panel.setSession(&session);
        session.open(so);
        QTRY_COMPARE(session.protocol(), protocol::can::CanProtocol::CanOpen);
        QTRY_COMPARE(panel.outputChoice()->count(), 6);
        QVERIFY(panel.applyPeriodButton()->isEnabled());
        QVERIFY(panel.syncModeCheck()->isEnabled());
        QTRY_COMPARE(panel.nodeSpin()->value(), 8);

        // TPDO2 every 50 ms: confirmed by read-back.
        QSignalSpy done(&panel, &ui::CanConfigPanel::requestDone);
        panel.outputChoice()->setCurrentIndex(1);
        panel.periodSpin()->setValue(50);
        panel.applyPeriodButton()->click();
        QTRY_COMPARE(done.size(), 1);
        QVERIFY2(done.at(0).at(0).toBool(), qPrintable(done.at(0).at(1).toString()));
        QCOMPARE(simulator.device().hipnuc().tpdoPeriodMs[1], uint16_t(50));
        QVERIFY(panel.log()->toPlainText().contains(QStringLiteral("confirmed")));

        // SYNC mode for TPDO1, then Send SYNC brings one 0x188.
        panel.outputChoice()->setCurrentIndex(0);
        panel.syncModeCheck()->click();
        QTRY_COMPARE(done.size(), 2);
        QVERIFY(done.at(1).at(0).toBool());
        QCOMPARE(simulator.device().hipnuc().tpdoType[0], uint8_t(1));
        QSignalSpy frames(&session, &device::CanSession::framesSeen);
        panel.sendSyncButton()->click();
        QTRY_VERIFY([&] {
            for (const auto &args : frames)
                for (const auto &e : args.at(0).value<device::CanFrameEvents>())
                    if (!e.transmitted && e.frame.id == 0x188)
                        return true;
            return false;
        }());

        // Scan: progress to 127 and node 8 in the log.
        panel.scanButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(panel.log()->toPlainText().contains(QStringLiteral("Scan finished; nodes answering SDO: 8")), 5000);
        QCOMPARE(panel.scanProgressBar()->value(), 127);
        QVERIFY(panel.scanButton()->isEnabled());

        // Heartbeat 100 ms: confirmed by read-back.
        panel.heartbeatSpin()->setValue(100);
        QPushButton *applyHeartbeat = nullptr;
        for (auto *b : panel.findChildren<QPushButton *>())
            if (b->text() == QStringLiteral("Apply") && b->parentWidget() == panel.heartbeatSpin()->parentWidget())
                applyHeartbeat = b;
        QVERIFY(applyHeartbeat);
        applyHeartbeat->click();
        QTRY_COMPARE(done.size(), 3);
        QVERIFY(done.at(2).at(0).toBool());
        QCOMPARE(simulator.device().hipnuc().heartbeatMs, uint16_t(100));

        // The rows follow the protocol: CANopen has the inclinometer and NMT for every node,
        // not the J1939 trigger nor the HEC495 modes.
        QVERIFY(panel.applyInclButton()->isEnabled());
        QVERIFY(panel.allOffButton()->isEnabled());
        QVERIFY(!panel.triggerButton()->isEnabled());
        QVERIFY(!panel.applyModesButton()->isEnabled());
        // Inclinometer X reversed, Y default: two writes, each read back.
        panel.inclXReversedCheck()->setChecked(true);
        panel.applyInclButton()->click();
        QTRY_COMPARE(done.size(), 5);
        QVERIFY(done.at(3).at(0).toBool() && done.at(4).at(0).toBool());
        QCOMPARE(simulator.device().hipnuc().inclSignX, 1u);
        QCOMPARE(simulator.device().hipnuc().inclSignY, 0u);
        panel.setSession(nullptr);
        QVERIFY(!panel.applyPeriodButton()->isEnabled());
    }

    void hec495Panel()
    {
        // An HEC495 on standard frames: its PDO and work modes, every node on/off; on the
        // extended variant the work mode and NMT are not there, and its PDO formats are two.
        const QString iface = QStringLiteral("tcp://127.0.0.1:24487/can1");
        sim::CanSimOptions o;
        o.protocol = protocol::can::CanProtocol::CanOpen;
        o.hec495 = true;
        sim::CanSimulator simulator(o);
        QString err;
        QVERIFY2(simulator.start(QStringLiteral("virtualcan"), iface, &err), qPrintable(err));
        device::CanSession session;
        device::CanSessionOptions so;
        so.interfaceName = iface;
        so.protocol = protocol::can::CanProtocol::Hec495;
        ui::CanConfigPanel panel;
        panel.resize(600, 500);
        panel.show();
        panel.setSession(&session);
        session.open(so);
        QTRY_COMPARE(session.state(), device::SessionState::Connected);
        QTRY_VERIFY_WITH_TIMEOUT(session.store().totalAppended() > 0, 5000); // the simulator is on the bus
        QVERIFY(panel.applyModesButton()->isEnabled());
        QVERIFY(panel.workModeChoice()->isEnabled());
        QCOMPARE(panel.pdoModeChoice()->count(), 3);
        QVERIFY(panel.allOnButton()->isEnabled());
        QVERIFY(!panel.applyInclButton()->isEnabled());
        QSignalSpy done(&panel, &ui::CanConfigPanel::requestDone);
        panel.pdoModeChoice()->setCurrentIndex(panel.pdoModeChoice()->findData(1));
        panel.workModeChoice()->setCurrentIndex(panel.workModeChoice()->findData(0x0A));
        panel.applyModesButton()->click();
        QTRY_COMPARE(done.size(), 2);
        for (const auto &d : done)
            QVERIFY2(d.at(0).toBool(), qPrintable(d.at(1).toString()));
        QCOMPARE(simulator.device().hec().pdoMode, 1u);
        QCOMPARE(simulator.device().hec().workMode, 0x0Au);

        panel.setSession(nullptr);
        session.close();
        QTRY_COMPARE(session.state(), device::SessionState::Closed);
        so.hec495Extended = true;
        session.open(so);
        panel.setSession(&session);
        QTRY_COMPARE(session.state(), device::SessionState::Connected);
        QCOMPARE(panel.pdoModeChoice()->count(), 2);
        QVERIFY(!panel.workModeChoice()->isEnabled());
        QVERIFY(!panel.allOnButton()->isEnabled());
        panel.setSession(nullptr);
    }

    // The settings page reads before it writes (issue 35): the module's values as soon as the
    // protocol is known, a changed value written and read back ("verified"), a value the module
    // does not keep marked with what it holds, and the HEC495's settings "not readable".
    void settingsPageReadsBeforeItWrites()
    {
        ui::CanConfigPanel panel;
        panel.resize(700, 600);
        panel.show();
        ui::CanSettingsTable *table = panel.settingsTable();
        Bus bus(simOptions(protocol::can::CanProtocol::J1939, false));
        QVERIFY(bus.start(QStringLiteral("tcp://127.0.0.1:24487/can2"), panel, protocol::can::CanProtocol::J1939, 8));
        sim::CanSimulator &simulator = bus.simulator;
        // Read first: every row shows what the simulated module holds (v1.7.1 defaults).
        QTRY_COMPARE(table->moduleText(QStringLiteral("bitrate")), QStringLiteral("500000"));
        QTRY_COMPARE(table->moduleText(QStringLiteral("interval-ff37")), QStringLiteral("100"));
        QTRY_COMPARE(table->moduleText(QStringLiteral("node-id")), QStringLiteral("8"));
        QTRY_VERIFY(table->writeButton() && !table->busy());
        QVERIFY(!table->writeButton()->isEnabled()); // nothing changed yet
        // A new value: written, read back, verified; the module holds it.
        QVERIFY(table->setNewValue(QStringLiteral("interval-ff37"), QStringLiteral("50")));
        QVERIFY(table->setNewValue(QStringLiteral("bitrate"), QStringLiteral("250000")));
        QVERIFY(table->writeButton()->isEnabled());
        QSignalSpy idle(table, &ui::CanSettingsTable::idle);
        table->writeButton()->click();
        QTRY_VERIFY(idle.size() >= 1 && !table->busy());
        QCOMPARE(table->statusText(QStringLiteral("interval-ff37")), QStringLiteral("verified"));
        QCOMPARE(table->statusText(QStringLiteral("bitrate")), QStringLiteral("verified"));
        QCOMPARE(table->moduleText(QStringLiteral("bitrate")), QStringLiteral("250000"));
        QCOMPARE(simulator.device().hipnuc().pgnIntervalMs.at(0xFF37), 50u);
        QCOMPARE(simulator.device().hipnuc().baudCode, 3u);
        // FF5A (CAN FD frame 0): the module without CAN FD refuses it, and the row says so
        // instead of "verified".
        QVERIFY(table->setNewValue(QStringLiteral("interval-ff5a"), QStringLiteral("20")));
        table->writeButton()->click();
        QTRY_VERIFY(!table->statusText(QStringLiteral("interval-ff5a")).isEmpty()
                    && table->statusText(QStringLiteral("interval-ff5a")) != QStringLiteral("writing…"));
        QVERIFY2(table->statusText(QStringLiteral("interval-ff5a")).startsWith(QStringLiteral("not confirmed")),
                 qPrintable(table->statusText(QStringLiteral("interval-ff5a"))));
        panel.setSession(nullptr);
    }

    void settingsPageSaysWhatCannotBeRead()
    {
        ui::CanConfigPanel panel;
        panel.show();
        ui::CanSettingsTable *table = panel.settingsTable();
        Bus bus(simOptions(protocol::can::CanProtocol::CanOpen, true));
        QVERIFY(bus.start(QStringLiteral("tcp://127.0.0.1:24487/can3"), panel, protocol::can::CanProtocol::Hec495));
        sim::CanSimulator &simulator = bus.simulator;
        QTRY_COMPARE(table->moduleText(QStringLiteral("pdo-mode")), QStringLiteral("not readable"));
        QVERIFY(!table->readButton()->isEnabled());
        QVERIFY(table->setNewValue(QStringLiteral("pdo-rate"), QStringLiteral("100 Hz")));
        table->writeButton()->click();
        QTRY_VERIFY(table->statusText(QStringLiteral("pdo-rate")).startsWith(QStringLiteral("confirmed by its reply")));
        QCOMPARE(simulator.device().hec().rateCode, 6u);
        panel.setSession(nullptr);
    }
};

IMUDESK_TEST_MAIN(TstCanConfigPanel)
#include "tst_can_config_panel.moc"
