// RegisterTableModel: the register maps as tables, values from blocks (golden: the v1.7.1
// 6.19 registers correctly framed, the 6.18 identity), editing only where writable and legal,
// the reads that cover a map.
#include "itemmodels/register_table_model.h"
#include "protocol/modbus/rtu_adu.h"
#include "../common/test_main.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QtTest>

using imudesk::models::RegisterTableModel;
using namespace imudesk::protocol::modbus;
using imudesk::model::ManualEdition;

namespace {

int rowOf(const RegisterTableModel &m, const char *name)
{
    for (int r = 0; r < m.rowCount(); ++r)
        if (QLatin1String(m.registerAt(r)->name) == QLatin1String(name))
            return r;
    return -1;
}

std::vector<uint16_t> regsOf(const char *hexFrame)
{
    const auto p = RtuAdu::parseResponse(QByteArray::fromHex(QByteArray(hexFrame).replace(' ', "")));
    return p.ok() ? RtuAdu::readRegisters(p.response()).value_or(std::vector<uint16_t>{}) : std::vector<uint16_t>{};
}

} // namespace

class TstRegisterTableModel : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void valuesFromBlocks()
    {
        RegisterTableModel m;
        QAbstractItemModelTester tester(&m, QAbstractItemModelTester::FailureReportingMode::QtTest);
        m.setMap(RegisterMap::hipnuc(ManualEdition::V171));
        QCOMPARE(m.rowCount(), 32);
        const int yaw = rowOf(m, "Y_H");
        QCOMPARE(m.index(yaw, RegisterTableModel::ValueColumn).data().toString(), QStringLiteral("—"));
        QSignalSpy changed(&m, &QAbstractItemModel::dataChanged);
        const auto regs = regsOf("50 03 30 FF 01 03 B0 06 50 FC C9 FF 7C 00 91 01 D5 FD DB FD 27 00 00 21 FF 00 00 7F F6 FF FD "
                                 "73 E7 00 00 00 00 00 00 10 A6 0D 59 DD 4E 86 A8 06 30 17 82 1E CE");
        QCOMPARE(regs.size(), size_t(24));
        m.setBlock(RegisterBlock(0x34, regs));
        QCOMPARE(changed.count(), 1);
        QCOMPARE(m.index(yaw, RegisterTableModel::ValueColumn).data().toString(), QStringLiteral("-166.9370"));
        QCOMPARE(m.index(yaw, RegisterTableModel::RawColumn).data().toString(), QStringLiteral("FFFD 73E7"));
        QCOMPARE(m.index(yaw, RegisterTableModel::AddressColumn).data().toString(), QStringLiteral("0x0041-0x0042"));
        QCOMPARE(m.index(rowOf(m, "ACCX"), RegisterTableModel::ValueColumn).data().toString(), QStringLiteral("-0.12451"));
        QCOMPARE(m.index(rowOf(m, "GYRX"), RegisterTableModel::ValueColumn).data().toString(), QStringLiteral("-50.2318"));
        QCOMPARE(m.index(rowOf(m, "MAGZ"), RegisterTableModel::UnitColumn).data().toString(), QStringLiteral("uT"));

        m.setBlock(RegisterBlock(0x70, regsOf("50 03 28 48 49 31 34 52 32 4E 2D 34 38 35 2D 30 30 30 00 00 98 00 6B 00 00 00 00 00 "
                                               "00 00 00 00 00 04 7D 95 5F 8D 2A 17 08 00 00 4D 0C")));
        QCOMPARE(m.index(rowOf(m, "PNAME"), RegisterTableModel::ValueColumn).data().toString(), QStringLiteral("HI14R2N-485-000"));
        QCOMPARE(m.index(rowOf(m, "SN"), RegisterTableModel::ValueColumn).data().toString(), QStringLiteral("047D955F8D2A1708"));
        QCOMPARE(m.index(rowOf(m, "SW_VERSION"), RegisterTableModel::ValueColumn).data().toString(), QStringLiteral("152"));
        m.clearValues();
        QCOMPARE(m.index(yaw, RegisterTableModel::ValueColumn).data().toString(), QStringLiteral("—"));
    }

    void editing_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("value");
        QTest::addColumn<bool>("accepted");
        QTest::addColumn<int>("written");
        QTest::newRow("baud 9600 code") << "UART1_BAUD" << "1" << true << 1;
        QTest::newRow("baud code 9") << "UART1_BAUD" << "9" << false << -1;
        QTest::newRow("node hex") << "MD_ID" << "0x51" << true << 0x51;
        QTest::newRow("node 0") << "MD_ID" << "0" << false << -1;
        QTest::newRow("ctrl reset") << "CTRL" << "0xFF" << true << 0xFF;
        QTest::newRow("mount 520") << "URFR" << "520" << true << 520;
        QTest::newRow("mount 99") << "URFR" << "99" << false << -1;
        QTest::newRow("read-only ACCX") << "ACCX" << "1" << false << -1;
        QTest::newRow("text") << "MD_ID" << "eighty" << false << -1;
    }
    void editing()
    {
        QFETCH(QString, name);
        QFETCH(QString, value);
        QFETCH(bool, accepted);
        QFETCH(int, written);
        RegisterTableModel m;
        m.setMap(RegisterMap::hipnuc(ManualEdition::V171));
        QSignalSpy writes(&m, &RegisterTableModel::writeRequested);
        QSignalSpy refused(&m, &RegisterTableModel::writeRefused);
        const QModelIndex idx = m.index(rowOf(m, qPrintable(name)), RegisterTableModel::RawColumn);
        QCOMPARE(m.setData(idx, value), accepted);
        if (accepted) {
            QCOMPARE(writes.count(), 1);
            QCOMPARE(writes.at(0).at(1).toInt(), written);
        } else {
            QCOMPARE(writes.count(), 0);
            QCOMPARE(refused.count(), (m.flags(idx) & Qt::ItemIsEditable) ? 1 : 0);
        }
    }

    void readRanges()
    {
        RegisterTableModel m;
        m.setMap(RegisterMap::hipnuc(ManualEdition::V171));
        const QList<RegisterTableModel::Range> expected{{0x04, 3}, {0x34, 30}, {0x70, 19}};
        QCOMPARE(m.readRanges(), expected);
        m.setMap(RegisterMap::hec495());
        QCOMPARE(m.readRanges(), (QList<RegisterTableModel::Range>{{0x04, 6}}));
        QCOMPARE(m.rowCount(), 3);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstRegisterTableModel)
#include "tst_register_table_model.moc"
