// SettingsTableModel: every setting a row, unavailable rows greyed out (feature table,
// firmware edition), pending values validated and dropped once the device holds them.
#include "itemmodels/settings_table_model.h"
#include "settings/setting_catalog.h"
#include "../common/test_main.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QTest>

using namespace imudesk;
using models::SettingsTableModel;

namespace {
settings::DeviceConfiguration config(const char *product, const char *firmware,
                                     std::map<std::string, std::string> comconfig)
{
    model::DeviceIdentity id;
    id.productName = product;
    id.firmware = model::FirmwareVersion::parse(firmware);
    id.serial = "SIM";
    return settings::DeviceConfiguration::fromComConfig(id, comconfig);
}
} // namespace

class TstSettingsTableModel : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void tester()
    {
        SettingsTableModel m;
        QAbstractItemModelTester t(&m, QAbstractItemModelTester::FailureReportingMode::QtTest);
        QCOMPARE(m.rowCount(), int(settings::SettingCatalog::settings().size()));
        // Before a read nothing can be edited.
        QVERIFY(!m.setPending(QStringLiteral("ATT.MODE"), QStringLiteral("0")));
        QVERIFY(!m.lastError().isEmpty());
        m.setConfiguration(config("HI14R3", "1.7.1", {{"ATT_MODE", "1"}, {"URFR", "24"}}));
        QVERIFY(m.setPending(QStringLiteral("IMU.URFR"), QStringLiteral("205")));
        m.setConfiguration(config("HI14R3", "1.7.1", {{"ATT_MODE", "1"}, {"URFR", "205"}}));
        QVERIFY(m.pendingChanges().empty());
    }

    void greyedOut_data()
    {
        QTest::addColumn<QString>("product");
        QTest::addColumn<QString>("firmware");
        QTest::addColumn<QString>("key");
        QTest::addColumn<bool>("enabled");
        QTest::newRow("PMUX on HI14") << "HI14R3" << "1.7.1" << "PMUX1" << true;
        QTest::newRow("PMUX on HI02") << "HI02" << "1.7.1" << "PMUX1" << false;
        QTest::newRow("PMUX on HI92") << "HI92" << "1.7.1" << "PMUX2.DIV" << false;
        QTest::newRow("COORD on 1.6.6") << "HI14R3" << "1.6.6" << "IMU.COORD" << false;
        QTest::newRow("HI92 msg on 1.6.6") << "HI14R3" << "1.6.6" << "LOG.HI92" << true;
        QTest::newRow("HI92 msg on 1.7.1") << "HI14R3" << "1.7.1" << "LOG.HI92" << false;
        QTest::newRow("IMU_EN_MCAL on HI50") << "HI50" << "1.6.6" << "IMU_EN_MCAL" << false;
    }
    void greyedOut()
    {
        QFETCH(QString, product);
        QFETCH(QString, firmware);
        QFETCH(QString, key);
        QFETCH(bool, enabled);
        SettingsTableModel m;
        m.setConfiguration(config(qPrintable(product), qPrintable(firmware), {}));
        const int row = m.rowOfKey(key);
        QVERIFY(row >= 0);
        const QModelIndex idx = m.index(row, SettingsTableModel::NewColumn);
        QCOMPARE(bool(m.flags(idx) & Qt::ItemIsEnabled), enabled);
        QCOMPARE(m.data(idx, SettingsTableModel::AvailableRole).toBool(), enabled);
        if (!enabled) {
            QVERIFY(!m.setData(idx, QStringLiteral("1")));
            QVERIFY(!m.lastError().isEmpty());
            QVERIFY(m.data(idx, Qt::ToolTipRole).toString().contains(m.lastError()));
        }
    }

    void editing()
    {
        SettingsTableModel m;
        m.setConfiguration(config("HI14R3", "1.7.1", {{"ATT_MODE", "1"}, {"HI91", "ONTIME 0.01"}, {"BAUD", "115200"}}));
        QSignalSpy pending(&m, &SettingsTableModel::pendingChanged);
        const QModelIndex mode = m.index(m.rowOfKey(QStringLiteral("ATT.MODE")), SettingsTableModel::NewColumn);
        QVERIFY(!m.setData(mode, QStringLiteral("3")));
        QVERIFY(m.lastError().contains(QLatin1String("ATT.MODE")));
        QVERIFY(m.setData(mode, QStringLiteral("0")));
        QVERIFY(m.setData(m.index(m.rowOfKey(QStringLiteral("LOG.HI91")), SettingsTableModel::NewColumn),
                          QStringLiteral("ONTIME 0.005")));
        QVERIFY(m.setData(m.index(m.rowOfKey(QStringLiteral("SERIAL.BAUD")), SettingsTableModel::NewColumn),
                          QStringLiteral("115200"))); // same as the device: nothing pending
        QCOMPARE(pending.count(), 3);
        const auto changes = m.pendingChanges();
        QCOMPARE(int(changes.size()), 2);
        QCOMPARE(changes[0].key, QStringLiteral("LOG.HI91"));
        QCOMPARE(changes[0].value, QStringLiteral("0.005"));
        QCOMPARE(changes[1].key, QStringLiteral("ATT.MODE"));
        QVERIFY(m.data(mode, SettingsTableModel::PendingRole).toBool());
        QCOMPARE(m.data(mode, SettingsTableModel::ChoicesRole).toStringList(),
                 (QStringList{QStringLiteral("0"), QStringLiteral("1"), QStringLiteral("4")}));
        QVERIFY(m.data(m.index(mode.row(), SettingsTableModel::DeviceColumn)).toString().contains(QLatin1String("AHRS")));
        m.clearPending();
        QVERIFY(m.pendingChanges().empty());
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstSettingsTableModel)
#include "tst_settings_table_model.moc"
