// ModbusScanDialog offscreen against a simulated HiPNUC at node 83: progress to the end, the
// device listed with its identity, Use emits its node and baud; Cancel stops a full scan.
#include "device/modbus_session.h"
#include "bus/modbus_scan_dialog.h"
#include "sim/modbus_simulator.h"
#include "../common/test_main.h"

#include <QApplication>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>

using namespace imudesk;
using imudesk::ui::ModbusScanDialog;

class TstModbusScanDialog : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void scanListsTheDeviceAndCancels()
    {
        sim::ModbusSimOptions so;
        so.nodeId = 83;
        sim::ModbusSimulator simulator(so);
        QVERIFY(simulator.start());
        device::ModbusSession session;
        device::ModbusOptions o;
        o.port = simulator.devicePath();
        o.identify = false;
        o.pollHz = 0;
        session.open(o);
        QTRY_COMPARE(session.state(), device::SessionState::Connected);

        ModbusScanDialog dialog(&session);
        dialog.show();
        dialog.setRange(80, 86);
        QVERIFY(dialog.startButton()->isEnabled());
        QTest::mouseClick(dialog.startButton(), Qt::LeftButton);
        QVERIFY(dialog.isScanning());
        QVERIFY(!dialog.startButton()->isEnabled() && dialog.cancelButton()->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(!dialog.isScanning(), 15000);
        QCOMPARE(dialog.progressBar()->maximum(), 7);
        QCOMPARE(dialog.progressBar()->value(), 7);
        QCOMPARE(dialog.results()->rowCount(), 1);
        QCOMPARE(dialog.results()->item(0, 0)->text(), QStringLiteral("83"));
        QCOMPARE(dialog.results()->item(0, 1)->text(), QStringLiteral("115200"));
        QVERIFY(dialog.results()->item(0, 2)->text().startsWith(QStringLiteral("HI14R3N-485-000")));
        QSignalSpy chosen(&dialog, &ModbusScanDialog::deviceChosen);
        dialog.results()->selectRow(0);
        Q_EMIT dialog.results()->cellDoubleClicked(0, 0);
        QCOMPARE(chosen.count(), 1);
        QCOMPARE(chosen.at(0).at(0).toInt(), 83);

        dialog.setRange(1, 247);
        dialog.start();
        QTRY_VERIFY(dialog.progressBar()->value() >= 3);
        QTest::mouseClick(dialog.cancelButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog.isScanning(), 5000);
        QVERIFY(dialog.progressBar()->value() < 247);
        QVERIFY(dialog.statusText().contains(QStringLiteral("Cancelled")));
    }
};

IMUDESK_TEST_MAIN(TstModbusScanDialog)
#include "tst_modbus_scan_dialog.moc"
