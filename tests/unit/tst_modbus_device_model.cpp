// The simulated Modbus device's register rules without a bus: what reads and writes answer
// (v1.7.1 6.16 / v1.6.6 4.2 register tables), what writes change, what survives a reset.
#include "protocol/modbus/identity_block.h"
#include "protocol/modbus/register_decoder.h"
#include "sim/modbus_device_model.h"
#include "../common/test_main.h"

#include <QModbusPdu>
#include <QtTest>

using namespace imudesk;
using namespace imudesk::protocol::modbus;
using imudesk::sim::ModbusDeviceModel;
using imudesk::sim::ModbusSimOptions;

namespace {

model::Sample sensors(ModbusDeviceModel &d, int64_t t)
{
    const auto r = d.read(reg::kSensorStart, reg::kSensorCount, t);
    return RegisterDecoder::hipnucSample(RegisterBlock(reg::kSensorStart, r.values));
}

} // namespace

class TstModbusDeviceModel : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void reads_data()
    {
        QTest::addColumn<int>("start");
        QTest::addColumn<int>("count");
        QTest::addColumn<int>("exception");
        QTest::newRow("config block") << 0x04 << 3 << 0;
        QTest::newRow("sensor block") << 0x34 << 24 << 0;
        QTest::newRow("with ship motion") << 0x34 << 30 << 0;
        QTest::newRow("identity as in 6.18") << 0x70 << 20 << 0;
        QTest::newRow("CTRL is write-only") << 0x00 << 1 << int(QModbusPdu::IllegalDataAddress);
        QTest::newRow("URFR is write-only") << 0xA6 << 1 << int(QModbusPdu::IllegalDataAddress);
        QTest::newRow("unmapped") << 0x20 << 2 << int(QModbusPdu::IllegalDataAddress);
        QTest::newRow("runs past the block") << 0x50 << 4 << int(QModbusPdu::IllegalDataAddress);
        QTest::newRow("count 0") << 0x34 << 0 << int(QModbusPdu::IllegalDataValue);
        QTest::newRow("count 126") << 0x34 << 126 << int(QModbusPdu::IllegalDataValue);
    }
    void reads()
    {
        QFETCH(int, start);
        QFETCH(int, count);
        QFETCH(int, exception);
        ModbusDeviceModel d;
        const auto r = d.read(uint16_t(start), uint16_t(count), 1000);
        QCOMPARE(r.exception, exception);
        QCOMPARE(int(r.values.size()), exception ? 0 : count);
    }

    void identity()
    {
        ModbusSimOptions o;
        o.model = "HI12";
        o.firmware = "1.6.6";
        o.seed = 9;
        ModbusDeviceModel d(o);
        QCOMPARE(d.edition(), model::ManualEdition::V166);
        const auto r = d.read(reg::kIdentityStart, reg::kIdentityCount, 0);
        const auto id = IdentityBlock::decode(RegisterBlock(reg::kIdentityStart, r.values));
        QVERIFY(id);
        QCOMPARE(QString::fromStdString(id->productName), QStringLiteral("HI12R3N-485-000"));
        QCOMPARE(id->swVersion, uint16_t(166));
        QCOMPARE(QString::fromStdString(id->serial), QString::fromStdString(d.serial()));
    }

    void writeRules_data()
    {
        QTest::addColumn<QString>("firmware");
        QTest::addColumn<int>("address");
        QTest::addColumn<int>("value");
        QTest::addColumn<int>("exception");
        QTest::addColumn<int>("mounting");
        QTest::newRow("1.7.1 URFR 0x208") << "1.7.1" << 0xA6 << 0x208 << 0 << 520;
        QTest::newRow("1.7.1 URFR index 3 is no code") << "1.7.1" << 0xA6 << 3 << int(QModbusPdu::IllegalDataValue) << 24;
        QTest::newRow("1.6.6 URFR 3") << "1.6.6" << 0xA6 << 3 << 0 << 520;
        QTest::newRow("1.6.6 URFR 0x18") << "1.6.6" << 0xA6 << 0x18 << int(QModbusPdu::IllegalDataValue) << 24;
        QTest::newRow("baud code 9") << "1.7.1" << 0x04 << 9 << int(QModbusPdu::IllegalDataValue) << 24;
        QTest::newRow("node 0") << "1.7.1" << 0x05 << 0 << int(QModbusPdu::IllegalDataValue) << 24;
        QTest::newRow("CTRL 2") << "1.7.1" << 0x00 << 2 << int(QModbusPdu::IllegalDataValue) << 24;
        QTest::newRow("level 4") << "1.7.1" << 0xA5 << 4 << int(QModbusPdu::IllegalDataValue) << 24;
        QTest::newRow("read-only ACCX") << "1.7.1" << 0x34 << 0 << int(QModbusPdu::IllegalDataAddress) << 24;
    }
    void writeRules()
    {
        QFETCH(QString, firmware);
        QFETCH(int, address);
        QFETCH(int, value);
        QFETCH(int, exception);
        QFETCH(int, mounting);
        ModbusSimOptions o;
        o.firmware = firmware.toStdString();
        ModbusDeviceModel d(o);
        QCOMPARE(d.write(uint16_t(address), uint16_t(value), 0).exception, exception);
        QCOMPARE(d.running().mountingCode, mounting);
    }

    void effectsAndSaving()
    {
        ModbusDeviceModel d;
        auto w = d.write(reg::kNodeId, 85, 0);
        QCOMPARE(w.effects.nodeId.value_or(0), 85);
        QVERIFY(!w.effects.baud);
        w = d.write(reg::kBaud, 8, 0);
        QCOMPARE(w.effects.baud.value_or(0), 921600);
        // Not saved: a reset brings back node 80 at 115200, and says so.
        w = d.write(reg::kCtrl, 0xFF, 1000);
        QVERIFY(w.effects.reset);
        QCOMPARE(w.effects.nodeId.value_or(0), 80);
        QCOMPARE(w.effects.baud.value_or(0), 115200);
        // Saved: it survives; factory settings undo it.
        d.write(reg::kNodeId, 85, 2000);
        d.write(reg::kCtrl, 0, 2000);
        w = d.write(reg::kCtrl, 0xFF, 3000);
        QVERIFY(!w.effects.nodeId);
        QCOMPARE(d.running().nodeId, 85);
        w = d.write(reg::kCtrl, 1, 4000);
        QCOMPARE(w.effects.nodeId.value_or(0), 80);
        QCOMPARE(d.saved().nodeId, 80);
    }

    void levelUprightAndInverted()
    {
        ModbusDeviceModel d;
        // Upright: the static attitude (roll 1.5, pitch -2.5) levels to 0/0.
        QCOMPARE(d.write(reg::kAutoLevel, 3, 0).exception, 0);
        auto s = sensors(d, 10);
        QVERIFY(std::abs(s.roll) < 0.002 && std::abs(s.pitch) < 0.002);
        QCOMPARE(d.write(reg::kAutoLevel, 5, 0).exception, 0);
        // Mounted upside down (code 035: 180 deg about X): levels to 0/180.
        QCOMPARE(d.write(reg::kUrfr, 35, 0).exception, 0);
        s = sensors(d, 20);
        QVERIFY2(std::abs(std::abs(s.roll) - 180.0) > 0.5 && std::abs(std::abs(s.roll) - 180.0) < 15.0,
                 qPrintable(QString::number(s.roll)));
        QVERIFY(s.acc.z < -0.9);
        QCOMPARE(d.write(reg::kAutoLevel, 2, 0).exception, 0);
        s = sensors(d, 30);
        QVERIFY2(std::abs(s.pitch) < 0.002 && std::abs(std::abs(s.roll) - 180.0) < 0.002,
                 qPrintable(QStringLiteral("%1 %2").arg(s.roll).arg(s.pitch)));
    }

    void sixAxisHeadingStartsAtZero()
    {
        ModbusSimOptions o;
        o.motion = sim::Motion::Spin;
        ModbusDeviceModel d(o);
        QVERIFY(std::abs(sensors(d, 0).yaw) > 1.0);
        QCOMPARE(d.write(reg::kHeadingMode, 0, 500000).exception, 0);
        QVERIFY(std::abs(sensors(d, 500000).yaw) < 0.01);
        // One second later the spin (30 deg/s) has turned the relative heading by 30 deg.
        QVERIFY(std::abs(std::abs(sensors(d, 1500000).yaw) - 30.0) < 0.1);
    }

    void hec495()
    {
        ModbusSimOptions o;
        o.kind = DeviceKind::Hec495;
        ModbusDeviceModel d(o);
        QCOMPARE(d.running().nodeId, 1);
        QCOMPARE(d.running().baud, 9600);
        const auto block = d.read(reg::kHecAngles, reg::kHecAngleCount, 0);
        QCOMPARE(block.exception, 0);
        const auto pitchOnly = d.read(reg::kHecPitchSingle, 2, 0);
        QCOMPARE(pitchOnly.values, std::vector<uint16_t>(block.values.begin(), block.values.begin() + 2));
        QCOMPARE(d.read(0x70, 1, 0).exception, int(QModbusPdu::IllegalDataAddress));
        QCOMPARE(d.write(0x04, 1, 0).exception, int(QModbusPdu::IllegalFunction));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstModbusDeviceModel)
#include "tst_modbus_device_model.moc"
