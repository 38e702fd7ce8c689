// RegisterBrowser offscreen against the simulated Modbus HiPNUC: live values in the table,
// an edit of a writable register goes to the device and is read back, refused values are
// explained, and the raw request line reads and writes registers.
#include "device/modbus_session.h"
#include "bus/register_browser.h"
#include "sim/modbus_simulator.h"
#include "../common/test_main.h"

#include <QAbstractItemModelTester>
#include <QApplication>
#include <QTableView>
#include <QTest>

using namespace imudesk;
using imudesk::models::RegisterTableModel;
using imudesk::ui::RegisterBrowser;

namespace {

int rowOf(RegisterTableModel *m, const char *name)
{
    for (int r = 0; r < m->rowCount(); ++r)
        if (QLatin1String(m->registerAt(r)->name) == QLatin1String(name))
            return r;
    return -1;
}

QString cell(RegisterTableModel *m, const char *name, int column)
{
    return m->index(rowOf(m, name), column).data().toString();
}

} // namespace

class TstRegisterBrowser : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void liveValuesEditsAndRawRequests()
    {
        sim::ModbusSimulator simulator;
        QVERIFY(simulator.start());
        device::ModbusSession session;
        device::ModbusOptions o;
        o.port = simulator.devicePath();
        o.pollHz = 0;
        o.timeoutMs = 600;
        session.open(o);
        RegisterBrowser browser(&session);
        QAbstractItemModelTester tester(browser.model(), QAbstractItemModelTester::FailureReportingMode::QtTest);
        browser.setRefreshInterval(100);
        browser.resize(900, 600);
        browser.show();
        QTRY_COMPARE(session.state(), device::SessionState::Connected);
        auto *m = browser.model();
        QTRY_COMPARE_WITH_TIMEOUT(cell(m, "PNAME", RegisterTableModel::ValueColumn), QStringLiteral("HI14R3N-485-000"), 5000);
        QTRY_COMPARE(cell(m, "MD_ID", RegisterTableModel::ValueColumn), QStringLiteral("80"));
        QVERIFY(cell(m, "ACCZ", RegisterTableModel::ValueColumn).toDouble() > 0.9);

        // Edit HEADING_MODE to 0 through the model, as the view's editor would.
        QVERIFY(m->setData(m->index(rowOf(m, "HEADING_MODE"), RegisterTableModel::RawColumn), 0));
        QTRY_VERIFY_WITH_TIMEOUT(browser.statusText().contains(QStringLiteral("Read back")), 5000);
        QTRY_COMPARE(cell(m, "HEADING_MODE", RegisterTableModel::ValueColumn), QStringLiteral("0"));
        int mode = -1;
        simulator.withDevice([&mode](sim::ModbusDeviceModel &d) { mode = d.running().headingMode; });
        QCOMPARE(mode, 0);

        // A value outside the table is refused with the reason, nothing is sent.
        QVERIFY(!m->setData(m->index(rowOf(m, "UART1_BAUD"), RegisterTableModel::RawColumn), 12));
        QVERIFY(browser.statusText().contains(QStringLiteral("UART1_BAUD")));

        // Raw line: a register outside the map gets the device's exception, then a read that works.
        browser.sendRawRequest(3, 0x10, 1);
        QTRY_VERIFY(browser.rawResultText().contains(QStringLiteral("ILLEGAL DATA ADDRESS")));
        browser.sendRawRequest(3, 0x05, 1);
        QTRY_VERIFY(browser.rawResultText().contains(QStringLiteral("03 @0x0005: 0050")));
        browser.sendRawRequest(6, 0xA5, 2);
        QTRY_VERIFY(browser.rawResultText().contains(QStringLiteral("06 @0x00a5")));
    }
};

IMUDESK_TEST_MAIN(TstRegisterBrowser)
#include "tst_register_browser.moc"
