// Device > Connect over CAN…: the bit rates each protocol's manual lists, the device's factory
// rate chosen first (HiPNUC 500 kbit/s, HEC495 250 kbit/s), what the module itself can be
// switched to, and CAN FD with its data-phase rate, into the session's options.
#include "bus/bus_connect_dialog.h"
#include "../common/test_main.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QTest>

using namespace imudesk;
using protocol::can::CanProtocol;

namespace {

QList<int> rates(const QComboBox *c)
{
    QList<int> out;
    for (int i = 0; i < c->count(); ++i)
        if (const int r = c->itemData(i).toInt(); r > 0)
            out << r;
    return out;
}

void choose(QComboBox *protocols, CanProtocol p)
{
    protocols->setCurrentIndex(protocols->findData(int(p)));
}

} // namespace

class TstBusConnectDialog : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void ratesFollowTheProtocol()
    {
        ui::CanConnectDialog dialog;
        // J1939 (v1.7.1 7.20): 125K to 1000K including 800K, 500K by default.
        choose(dialog.protocolCombo(), CanProtocol::J1939);
        QCOMPARE(rates(dialog.bitrateCombo()), (QList<int>{1000000, 800000, 500000, 250000, 125000}));
        QCOMPARE(dialog.bitrateCombo()->currentData().toInt(), 500000);
        QCOMPARE(dialog.options().bitrate, 500000);
        QVERIFY2(dialog.rateHint()->text().contains(QStringLiteral("0x9A")), qPrintable(dialog.rateHint()->text()));
        // CANopen: object 0x209A's four (8.28.44.23), no 800K.
        choose(dialog.protocolCombo(), CanProtocol::CanOpen);
        QCOMPARE(rates(dialog.bitrateCombo()), (QList<int>{1000000, 500000, 250000, 125000}));
        QCOMPARE(dialog.bitrateCombo()->currentData().toInt(), 500000);
        // HEC495: its own list down to 10K, 250K from the factory.
        choose(dialog.protocolCombo(), CanProtocol::Hec495);
        QCOMPARE(rates(dialog.bitrateCombo()), (QList<int>{500000, 250000, 125000, 100000, 50000, 20000, 10000}));
        QCOMPARE(dialog.bitrateCombo()->currentData().toInt(), 250000);
        QVERIFY(dialog.bitrateCombo()->currentText().contains(QStringLiteral("factory")));
        QCOMPARE(dialog.options().bitrate, 250000);
        QVERIFY(dialog.rateHint()->text().contains(QStringLiteral("0x1020")));
        // 30 kbit/s on the extended-frame variant only (the HEC495 manual lists it there).
        dialog.hec495ExtendedCheck()->setChecked(true);
        QVERIFY(rates(dialog.bitrateCombo()).contains(30000));
        QCOMPARE(dialog.bitrateCombo()->currentData().toInt(), 250000);
    }

    void canFdIntoTheOptions()
    {
        ui::CanConnectDialog dialog;
        choose(dialog.protocolCombo(), CanProtocol::J1939);
        QVERIFY(!dialog.options().canFd);
        QCOMPARE(dialog.options().dataBitrate, 0);
        QVERIFY(!dialog.dataBitrateCombo()->isEnabled());
        dialog.fdCheck()->setChecked(true);
        QVERIFY(dialog.dataBitrateCombo()->isEnabled());
        QVERIFY(dialog.options().canFd);
        QCOMPARE(dialog.options().dataBitrate, 4000000); // the manual's "usually 4 Mbps"
    }
};

IMUDESK_TEST_MAIN(TstBusConnectDialog)
#include "tst_bus_connect_dialog.moc"
