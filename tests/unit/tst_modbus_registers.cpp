// Modbus register maps, decoders and write values against the manuals' examples:
// HiPNUC v1.7.1 chapter 6 (6.17 configuration, 6.18 identity, 6.19 sensor data), v1.6.6
// chapter 4 (4.3, 4.4, 4.5) and the HEC495 manual, "Modbus 通讯协议".
#include "protocol/modbus/hipnuc_writes.h"
#include "protocol/modbus/identity_block.h"
#include "protocol/modbus/register_decoder.h"
#include "protocol/modbus/rtu_adu.h"
#include "../common/test_main.h"

#include <QRandomGenerator>
#include <QtTest>

#include <set>

using namespace imudesk::protocol::modbus;
using imudesk::model::ManualEdition;

Q_DECLARE_METATYPE(imudesk::protocol::modbus::WriteRequest)

namespace {

QByteArray hex(const char *text)
{
    return QByteArray::fromHex(QByteArray(text).replace(' ', ""));
}

// v1.7.1 6.19 response as printed: the header declares 0x30 = 48 data bytes, 47 follow.
const char *kPrintedSensorResponse =
    "50 03 30 FF 01 03 B0 06 50 FC C9 FF 7C 00 91 01 D5 FD DB FD 27 00 00 21 FF 00 00 7F F6 FF FD 73 E7 "
    "00 00 00 00 00 10 A6 0D 59 DD 4E 86 A8 06 30 17 82 1E CE";
// The same registers correctly framed: one 00 of the run after Y_L restored (TEMP and PRS are
// zero). The printed CRC 1E CE then matches: only that byte was lost in print.
const char *kCorrectedSensorResponse =
    "50 03 30 FF 01 03 B0 06 50 FC C9 FF 7C 00 91 01 D5 FD DB FD 27 00 00 21 FF 00 00 7F F6 FF FD 73 E7 "
    "00 00 00 00 00 00 10 A6 0D 59 DD 4E 86 A8 06 30 17 82 1E CE";
// v1.7.1 6.18 (45 bytes).
const char *kIdentityResponse171 =
    "50 03 28 48 49 31 34 52 32 4E 2D 34 38 35 2D 30 30 30 00 00 98 00 6B 00 00 00 00 00 00 00 00 00 00 "
    "04 7D 95 5F 8D 2A 17 08 00 00 4D 0C";
// v1.6.6 4.4: the same frame with three bytes missing.
const char *kIdentityResponse166 =
    "50 03 28 48 49 31 34 52 32 4E 2D 34 38 35 2D 30 30 00 00 98 00 6B 00 00 00 00 00 00 00 00 "
    "04 7D 95 5F 8D 2A 17 08 00 00 4D 0C";

RegisterBlock blockOf(const QByteArray &adu, uint16_t start)
{
    const RtuAdu::Parsed p = RtuAdu::parseResponse(adu);
    if (!p.ok())
        return {};
    const auto regs = RtuAdu::readRegisters(p.response());
    return regs ? RegisterBlock(start, *regs) : RegisterBlock();
}

} // namespace

class TstModbusRegisters : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void crcCheckValue()
    {
        QCOMPARE(RtuAdu::crc(QByteArray("123456789")), uint16_t(0x4B37));
    }

    void requests_data()
    {
        QTest::addColumn<int>("id");
        QTest::addColumn<int>("start");
        QTest::addColumn<int>("count");
        QTest::addColumn<QByteArray>("expected");
        QTest::newRow("v1.7.1 6.19 sensor block") << 0x50 << 0x34 << 0x18 << hex("50 03 00 34 00 18 09 8F");
        QTest::newRow("v1.7.1 6.18 identity") << 0x50 << 0x70 << 0x14 << hex("50 03 00 70 00 14 49 9F");
        QTest::newRow("HEC495 three angles") << 1 << 0x04 << 6 << hex("01 03 00 04 00 06 84 09");
        QTest::newRow("HEC495 pitch") << 1 << 0x05 << 2 << hex("01 03 00 05 00 02 D4 0A");
        QTest::newRow("HEC495 roll") << 1 << 0x06 << 2 << hex("01 03 00 06 00 02 24 0A");
    }
    void requests()
    {
        QFETCH(int, id);
        QFETCH(int, start);
        QFETCH(int, count);
        QFETCH(QByteArray, expected);
        QCOMPARE(RtuAdu::readRequest(uint8_t(id), uint16_t(start), uint16_t(count)).toHex(' '), expected.toHex(' '));
        const RtuAdu::Parsed p = RtuAdu::parseRequest(expected);
        QVERIFY(p.ok());
        QCOMPARE(int(p.serverAddress), id);
    }

    void printedSensorResponseIsRejected()
    {
        const QByteArray printed = hex(kPrintedSensorResponse);
        QCOMPARE(printed.size(), 52);        // 3 + 47 + 2
        QCOMPARE(uint8_t(printed.at(2)), uint8_t(0x30)); // declares 48
        const RtuAdu::Parsed p = RtuAdu::parseResponse(printed);
        QCOMPARE(p.error, RtuAdu::Error::Incomplete);
        QCOMPARE(p.expectedSize, 53);
        // Read as a complete frame, its last two bytes are no CRC of the rest.
        const uint16_t carried = uint16_t(uint8_t(printed.at(50)) | (uint8_t(printed.at(51)) << 8));
        QVERIFY(RtuAdu::crc(reinterpret_cast<const uint8_t *>(printed.constData()), 50) != carried);
        QVERIFY(!RtuAdu::readRegisters(QModbusResponse(QModbusPdu::ReadHoldingRegisters, printed.mid(2, 48))));
    }

    void correctedSensorResponse_data()
    {
        QTest::addColumn<QString>("quantity");
        QTest::addColumn<double>("value");
        QTest::addColumn<double>("expected");
        const RegisterBlock b = blockOf(hex(kCorrectedSensorResponse), reg::kSensorStart);
        const auto s = RegisterDecoder::hipnucSample(b);
        // v1.7.1 6.19 "数据解析示例" tables.
        QTest::newRow("acc x") << "acc" << s.acc.x << -0.1245;
        QTest::newRow("acc y") << "acc" << s.acc.y << 0.4609;
        QTest::newRow("acc z") << "acc" << s.acc.z << 0.7891;
        QTest::newRow("gyr x") << "gyr" << s.gyr.x << -50.2318;
        QTest::newRow("gyr y") << "gyr" << s.gyr.y << -8.0566;
        QTest::newRow("gyr z") << "gyr" << s.gyr.z << 8.8501;
        QTest::newRow("mag x") << "mag" << s.mag.x << 14.3125;
        QTest::newRow("mag y") << "mag" << s.mag.y << -16.7538;
        QTest::newRow("mag z") << "mag" << s.mag.z << -22.2469;
        QTest::newRow("roll") << "euler" << s.roll << 8.703;
        QTest::newRow("pitch") << "euler" << s.pitch << 32.758;
        QTest::newRow("yaw") << "euler" << s.yaw << -166.937;
    }
    void correctedSensorResponse()
    {
        QFETCH(double, value);
        QFETCH(double, expected);
        QVERIFY2(std::abs(value - expected) < 0.00006, qPrintable(QStringLiteral("%1 vs %2").arg(value).arg(expected)));
    }

    void correctedSensorResponseFrame()
    {
        const QByteArray adu = hex(kCorrectedSensorResponse);
        const RtuAdu::Parsed p = RtuAdu::parseResponse(adu);
        QVERIFY2(p.ok(), RtuAdu::errorName(p.error));
        const auto regs = RtuAdu::readRegisters(p.response());
        QVERIFY(regs);
        QCOMPARE(regs->size(), size_t(24));
        const RegisterBlock b(reg::kSensorStart, *regs);
        QCOMPARE(b.i32(0x41).value(), -166937);
        const auto s = RegisterDecoder::hipnucSample(b);
        using namespace imudesk::model;
        QVERIFY(s.has(FieldAcc) && s.has(FieldGyr) && s.has(FieldMag) && s.has(FieldEuler) && s.has(FieldQuat));
        QVERIFY(s.has(FieldTemperature) && s.has(FieldPressure) && s.has(FieldInclination));
        QVERIFY(!s.has(FieldHeave)); // 0x4E is outside 0x34..0x4B
        QCOMPARE(s.temperatureC, 0.0);
        // Rebuilding the frame from the registers gives the same bytes.
        QCOMPARE(RtuAdu::frame(0x50, RtuAdu::readResponse(*regs)).toHex(' '), adu.toHex(' '));
    }

    void everyPrefixIsIncomplete()
    {
        const QByteArray adu = hex(kCorrectedSensorResponse);
        for (int n = 0; n < adu.size(); ++n)
            QCOMPARE(RtuAdu::parseResponse(adu.left(n)).error, RtuAdu::Error::Incomplete);
        QCOMPARE(RtuAdu::parseResponse(adu + char(0)).error, RtuAdu::Error::TooLong);
    }

    void anyFlippedBitIsRejected()
    {
        const QByteArray adu = hex(kCorrectedSensorResponse);
        auto *rng = QRandomGenerator::global();
        for (int i = 0; i < 500; ++i) {
            QByteArray bad = adu;
            const int at = 3 + int(rng->bounded(adu.size() - 3)); // keep address, function and count
            bad[at] = char(bad[at] ^ (1 << rng->bounded(8)));
            QCOMPARE(RtuAdu::parseResponse(bad).error, RtuAdu::Error::CrcMismatch);
        }
    }

    void identity171()
    {
        const QByteArray adu = hex(kIdentityResponse171);
        QCOMPARE(adu.size(), 45);
        const RegisterBlock b = blockOf(adu, reg::kIdentityStart);
        QCOMPARE(b.size(), size_t(20));
        const auto id = IdentityBlock::decode(b);
        QVERIFY(id);
        QCOMPARE(QString::fromStdString(id->productName), QStringLiteral("HI14R2N-485-000"));
        QCOMPARE(id->swVersion, uint16_t(0x98));
        QCOMPARE(QString::fromStdString(IdentityBlock::versionText(id->swVersion)), QStringLiteral("V1.52"));
        QCOMPARE(QString::fromStdString(IdentityBlock::versionText(id->blVersion)), QStringLiteral("V1.07"));
        QCOMPARE(QString::fromStdString(id->serial), QStringLiteral("047D955F8D2A1708"));
        const auto di = id->toDeviceIdentity();
        QCOMPARE(QString::fromStdString(di.firmware->toString()), QString::fromStdString(
                     imudesk::model::FirmwareVersion{1, 5, 2}.toString()));
        QVERIFY(di.usable());
        // Round trip: the registers rebuilt from the identity are the response's.
        QCOMPARE(id->encode(), b.values());
    }

    void identity166IsTruncated()
    {
        const QByteArray adu = hex(kIdentityResponse166);
        QCOMPARE(adu.size(), 42);
        QVERIFY(!RtuAdu::parseResponse(adu).ok());
    }

    void writes_data()
    {
        QTest::addColumn<WriteRequest>("write");
        QTest::addColumn<QByteArray>("expected");
        using W = HipnucWrites;
        // v1.7.1 6.17.20-22, v1.6.6 4.3.1
        QTest::newRow("save") << W::save() << hex("50 06 00 00 00 00 84 4B");
        QTest::newRow("factory reset") << W::factoryReset() << hex("50 06 00 00 00 01 45 8B");
        QTest::newRow("reset") << W::reset() << hex("50 06 00 00 00 FF C4 0B");
        // 6.17.23 / 4.3.2
        const char *baudFrames[] = {"50 06 00 04 00 00 C5 8A", "50 06 00 04 00 01 04 4A", "50 06 00 04 00 02 44 4B",
                                    "50 06 00 04 00 03 85 8B", "50 06 00 04 00 04 C4 49", "50 06 00 04 00 05 05 89",
                                    "50 06 00 04 00 06 45 88", "50 06 00 04 00 07 84 48", "50 06 00 04 00 08 C4 4C"};
        const int bauds[] = {4800, 9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600};
        for (int i = 0; i < 9; ++i)
            QTest::newRow(qPrintable(QStringLiteral("baud %1").arg(bauds[i]))) << *W::baud(bauds[i]) << hex(baudFrames[i]);
        // 6.17.24 / 4.3.3
        QTest::newRow("node 0x50") << *W::nodeId(0x50) << hex("50 06 00 05 00 50 94 76");
        QTest::newRow("node 0x51") << *W::nodeId(0x51) << hex("50 06 00 05 00 51 55 B6");
        QTest::newRow("node 0x52") << *W::nodeId(0x52) << hex("50 06 00 05 00 52 15 B7");
        QTest::newRow("node 0x53") << *W::nodeId(0x53) << hex("50 06 00 05 00 53 D4 77");
        // 6.17.25 (v1.7.1 codes)
        const auto v171 = ManualEdition::V171, v166 = ManualEdition::V166;
        QTest::newRow("v1.7.1 mount 024") << *W::mounting(v171, 24) << hex("50 06 00 A6 00 18 64 62");
        QTest::newRow("v1.7.1 mount 043") << *W::mounting(v171, 43) << hex("50 06 00 A6 00 2B 24 77");
        QTest::newRow("v1.7.1 mount 052") << *W::mounting(v171, 52) << hex("50 06 00 A6 00 34 65 BF");
        QTest::newRow("v1.7.1 mount 520") << *W::mounting(v171, 520) << hex("50 06 00 A6 02 08 64 CE");
        QTest::newRow("v1.7.1 mount 421") << *W::mounting(v171, 421) << hex("50 06 00 A6 01 A5 A5 83");
        // 4.3.4 (v1.6.6 indices 0-4)
        QTest::newRow("v1.6.6 mount 0") << *W::mounting(v166, 24) << hex("50 06 00 A6 00 00 64 68");
        QTest::newRow("v1.6.6 mount 1") << *W::mounting(v166, 43) << hex("50 06 00 A6 00 01 A5 A8");
        QTest::newRow("v1.6.6 mount 2") << *W::mounting(v166, 52) << hex("50 06 00 A6 00 02 E5 A9");
        QTest::newRow("v1.6.6 mount 3") << *W::mounting(v166, 520) << hex("50 06 00 A6 00 03 24 69");
        QTest::newRow("v1.6.6 mount 4") << *W::mounting(v166, 421) << hex("50 06 00 A6 00 04 65 AB");
        // 6.17.26 / 4.3.5
        QTest::newRow("auto-level on") << W::autoLevel(true) << hex("50 06 00 A5 00 02 15 A9");
        QTest::newRow("auto-level off") << W::autoLevel(false) << hex("50 06 00 A5 00 05 54 6B");
        // 6.17.27 / 4.3.6
        QTest::newRow("6-axis") << W::headingMode(false) << hex("50 06 00 06 00 00 64 4A");
        QTest::newRow("9-axis") << W::headingMode(true) << hex("50 06 00 06 00 01 A5 8A");
    }
    // 0xA5: the register table says 3 (level) and 5 (cancel), the worked example writes 2. What
    // ImuDesk sends is the example; what it tells the user names the value and its source.
    void autoLevelSaysWhatIsSentAndWhy()
    {
        using W = HipnucWrites;
        QCOMPARE(W::autoLevel(true).value, uint16_t(2));
        const QString sent = W::describe(W::autoLevel(true));
        QVERIFY2(sent.contains(QLatin1String("value 2")) && sent.contains(QLatin1String("example"))
                     && sent.contains(QLatin1String("lists 3")),
                 qPrintable(sent));
        QVERIFY(W::describe({reg::kAutoLevel, 3}).contains(QLatin1String("register table")));
        QVERIFY(W::describe(W::autoLevel(false)).contains(QLatin1String("value 5")));
        for (auto edition : {ManualEdition::V171, ManualEdition::V166}) {
            const auto *r = RegisterMap::hipnuc(edition).find(reg::kAutoLevel);
            QVERIFY(r);
            QVERIFY(RegisterMap::accepts(*r, 2) && RegisterMap::accepts(*r, 3));
            const QString d = RegisterMap::describe(*r);
            QVERIFY2(d.contains(QLatin1String("3 levels once")) && d.contains(QLatin1String("example writes 2")),
                     qPrintable(d));
        }
    }

    void writes()
    {
        QFETCH(WriteRequest, write);
        QFETCH(QByteArray, expected);
        QCOMPARE(RtuAdu::writeSingleRequest(0x50, write.address, write.value).toHex(' '), expected.toHex(' '));
        // The value is legal for the register in the edition(s) whose manual prints it.
        const RegisterDef *def171 = RegisterMap::hipnuc(ManualEdition::V171).find(write.address);
        const RegisterDef *def166 = RegisterMap::hipnuc(ManualEdition::V166).find(write.address);
        QVERIFY(def171 && def166);
        QVERIFY(RegisterMap::accepts(*def171, write.value) || RegisterMap::accepts(*def166, write.value));
    }

    void writeRangeChecks()
    {
        QVERIFY(!HipnucWrites::baud(256000));
        QVERIFY(!HipnucWrites::nodeId(0));
        QVERIFY(!HipnucWrites::nodeId(129));
        QVERIFY(!HipnucWrites::mounting(ManualEdition::V166, 531)); // not one of the five v1.6.6 mountings
        QVERIFY(HipnucWrites::mounting(ManualEdition::V171, 531));  // any of the 24 codes on v1.7.1
        QVERIFY(!HipnucWrites::mounting(ManualEdition::V171, 99));
        QCOMPARE(HipnucWrites::mountingCode(ManualEdition::V166, 3).value(), 520);
        QCOMPARE(HipnucWrites::mountingCode(ManualEdition::V171, 0x1A5).value(), 421);
        const RegisterDef *ctrl = RegisterMap::hipnuc(ManualEdition::V171).find(reg::kCtrl);
        QVERIFY(!RegisterMap::accepts(*ctrl, 2));
        const RegisterDef *acc = RegisterMap::hipnuc(ManualEdition::V171).find(0x34);
        QVERIFY(!RegisterMap::accepts(*acc, 0)); // read-only
    }

    void hec495_data()
    {
        QTest::addColumn<QByteArray>("adu");
        QTest::addColumn<int>("start");
        QTest::addColumn<QList<double>>("angles");
        QTest::newRow("three angles") << hex("01 03 0C 00 00 60 40 33 33 A3 C1 9A 99 B2 42 CE 2B") << 0x04
                                      << QList<double>{3.5, -20.4, 89.3};
        QTest::newRow("pitch") << hex("01 03 04 00 00 60 40 D3 C3") << 0x04 << QList<double>{3.5};
        QTest::newRow("roll") << hex("01 03 04 33 33 A3 C1 BC 18") << 0x06 << QList<double>{-20.4};
    }
    void hec495()
    {
        QFETCH(QByteArray, adu);
        QFETCH(int, start);
        QFETCH(QList<double>, angles);
        const RegisterBlock b = blockOf(adu, uint16_t(start));
        QCOMPARE(b.size(), size_t(angles.size() * 2));
        for (int i = 0; i < angles.size(); ++i)
            QVERIFY(std::abs(*b.f32le(uint16_t(start + 2 * i)) - angles[i]) < 1e-5);
        if (angles.size() == 3) {
            const auto s = RegisterDecoder::hec495Sample(b);
            QVERIFY(s.has(imudesk::model::FieldEuler));
            QVERIFY(std::abs(s.pitch - 3.5) < 1e-5);
            QVERIFY(std::abs(s.roll + 20.4) < 1e-5);
            QVERIFY(std::abs(s.headingDeg - 89.3) < 1e-5); // the compass's heading, clockwise
            QVERIFY(std::abs(s.yaw + 89.3) < 1e-5);        // the world frame's yaw (ENU, issue 53 point 7)
            // Encoding the floats back gives the manual's bytes.
            std::vector<uint16_t> regs;
            for (double a : angles) {
                const auto w = RegisterBlock::wordsF32le(float(a));
                regs.insert(regs.end(), w.begin(), w.end());
            }
            QCOMPARE(RtuAdu::frame(1, RtuAdu::readResponse(regs)).toHex(' '), adu.toHex(' '));
        }
    }

    void mapsAreConsistent_data()
    {
        QTest::addColumn<int>("which");
        QTest::newRow("hipnuc v1.7.1") << 0;
        QTest::newRow("hipnuc v1.6.6") << 1;
        QTest::newRow("hec495") << 2;
    }
    void mapsAreConsistent()
    {
        QFETCH(int, which);
        const RegisterMap &m = which == 0 ? RegisterMap::hipnuc(ManualEdition::V171)
            : which == 1                  ? RegisterMap::hipnuc(ManualEdition::V166)
                                          : RegisterMap::hec495();
        std::set<int> used;
        for (const RegisterDef &d : m.registers()) {
            const int expectedWords = (d.type == RegType::I32 || d.type == RegType::F32LE) ? 2
                : d.type == RegType::Ascii                                                ? 8
                : d.type == RegType::Bytes                                                ? 4
                                                                                          : 1;
            QCOMPARE(int(d.words), expectedWords);
            for (int w = 0; w < d.words; ++w)
                QVERIFY2(used.insert(d.address + w).second, d.name); // no overlap
            QVERIFY(m.find(d.address) == &d);
            QVERIFY(m.covering(uint16_t(d.address + d.words - 1)) == &d);
            QVERIFY(!RegisterMap::describe(d).isEmpty());
        }
        if (which < 2) {
            QCOMPARE(m.registers().size(), size_t(32)); // 32 entries in each edition's table (0xA6 from 6.17.25 on v1.7.1)
            QVERIFY(m.find(0x3E) == nullptr && m.covering(0x3E)->address == 0x3D); // R_L
        }
    }

    void i32Words()
    {
        for (int32_t v : {0, 1, -1, 8703, -166937, INT32_MAX, INT32_MIN}) {
            const RegisterBlock b(0x3D, RegisterBlock::wordsI32(v));
            QCOMPARE(b.i32(0x3D).value(), v);
        }
        const RegisterBlock b(0x41, {0xFFFD, 0x73E7});
        QCOMPARE(b.i32(0x41).value(), -166937);
        QVERIFY(!b.i32(0x42));
        QVERIFY(!b.u16(0x40));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstModbusRegisters)
#include "tst_modbus_registers.moc"
