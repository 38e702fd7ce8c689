// The simulated Modbus RTU devices over pseudo-terminals with Qt's own client
// (QModbusRtuSerialClient): registers follow the motion model, the manuals' example frames go
// over the wire byte for byte, writes take effect as on the device, and the client rejects the
// v1.7.1 manual's printed sensor response (6.19, one byte short) while accepting it correctly framed.
#include "protocol/modbus/hipnuc_writes.h"
#include "protocol/modbus/identity_block.h"
#include "protocol/modbus/register_decoder.h"
#include "protocol/modbus/rtu_adu.h"
#include "model/attitude.h"
#include "sim/modbus_simulator.h"
#include "sim/motion_model.h"
#include "../common/test_main.h"

#include <QModbusRtuSerialClient>
#include <QSerialPort>
#include <QSignalSpy>
#include <QtTest>

#include <fcntl.h>
#include <memory>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

using namespace imudesk;
using namespace imudesk::protocol::modbus;
using imudesk::sim::ModbusSimOptions;
using imudesk::sim::ModbusSimulator;

namespace {

QByteArray hex(const char *text)
{
    return QByteArray::fromHex(QByteArray(text).replace(' ', ""));
}

std::unique_ptr<QModbusRtuSerialClient> makeClient(const QString &path, int baud, int timeoutMs = 600)
{
    auto c = std::make_unique<QModbusRtuSerialClient>();
    c->setConnectionParameter(QModbusDevice::SerialPortNameParameter, path);
    c->setConnectionParameter(QModbusDevice::SerialBaudRateParameter, baud);
    c->setConnectionParameter(QModbusDevice::SerialParityParameter, QSerialPort::NoParity);
    c->setConnectionParameter(QModbusDevice::SerialDataBitsParameter, QSerialPort::Data8);
    c->setConnectionParameter(QModbusDevice::SerialStopBitsParameter, QSerialPort::OneStop);
    c->setTimeout(timeoutMs);
    c->setNumberOfRetries(0);
    return c;
}

struct Outcome {
    QModbusDevice::Error error = QModbusDevice::UnknownError;
    QModbusResponse raw;
    QModbusDataUnit unit;
    QList<QModbusDevice::IntermediateError> intermediate;
};

Outcome finish(QModbusReply *reply)
{
    Outcome o;
    if (!reply)
        return o;
    if (!reply->isFinished()) {
        QSignalSpy spy(reply, &QModbusReply::finished);
        spy.wait(3000);
    }
    o.error = reply->error();
    o.raw = reply->rawResult();
    o.unit = reply->result();
    o.intermediate = reply->intermediateErrors();
    reply->deleteLater();
    return o;
}

Outcome readRegs(QModbusRtuSerialClient &c, int id, int start, int count)
{
    return finish(c.sendReadRequest(QModbusDataUnit(QModbusDataUnit::HoldingRegisters, start, quint16(count)), id));
}

Outcome writeReg(QModbusRtuSerialClient &c, int id, int address, int value)
{
    return finish(c.sendWriteRequest(QModbusDataUnit(QModbusDataUnit::HoldingRegisters, address, QList<quint16>{quint16(value)}), id));
}

RegisterBlock blockOf(const Outcome &o)
{
    const QList<quint16> values = o.unit.values();
    return RegisterBlock(uint16_t(o.unit.startAddress()), std::vector<uint16_t>(values.begin(), values.end()));
}

// Client-to-server bytes the bridge carried since the last clear.
QByteArray sentByClient(sim::PtyBridge &b)
{
    QByteArray out;
    for (const auto &c : b.recorded())
        if (c.direction == sim::PtyBridge::Direction::ClientToServer)
            out.append(reinterpret_cast<const char *>(c.bytes.data()), qsizetype(c.bytes.size()));
    return out;
}

} // namespace

class TstModbusSimulator : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void sensorBlockFollowsTheMotionModel()
    {
        ModbusSimOptions o;
        o.motion = sim::Motion::Static;
        ModbusSimulator simulator(o);
        QString error;
        QVERIFY2(simulator.start(&error), qPrintable(error));
        auto c = makeClient(simulator.devicePath(), 115200);
        QVERIFY(c->connectDevice());
        simulator.bridge().clearRecord();
        const Outcome r = readRegs(*c, 80, reg::kSensorStart, reg::kSensorCount);
        QCOMPARE(r.error, QModbusDevice::NoError);
        // v1.7.1 6.19: the request on the wire is the manual's.
        QCOMPARE(sentByClient(simulator.bridge()).toHex(' '), hex("50 03 00 34 00 18 09 8F").toHex(' '));
        const auto s = RegisterDecoder::hipnucSample(blockOf(r));
        QVERIFY(s.has(model::FieldAcc) && s.has(model::FieldEuler) && s.has(model::FieldQuat));
        const double g = std::sqrt(s.acc.x * s.acc.x + s.acc.y * s.acc.y + s.acc.z * s.acc.z);
        QVERIFY2(std::abs(g - 1.0) < 0.01, qPrintable(QString::number(g)));
        QVERIFY(std::abs(s.roll - sim::MotionModel::kStaticRollDeg) < 0.01);
        QVERIFY(std::abs(s.pitch - sim::MotionModel::kStaticPitchDeg) < 0.01);
        QVERIFY(std::abs(s.yaw - sim::MotionModel::kStaticYawDeg) < 0.01);
        const double qn = s.quat.w * s.quat.w + s.quat.x * s.quat.x + s.quat.y * s.quat.y + s.quat.z * s.quat.z;
        QVERIFY(std::abs(qn - 1.0) < 0.001);
        QVERIFY(s.temperatureC > 20 && s.pressurePa > 90000);

        const Outcome id = readRegs(*c, 80, reg::kIdentityStart, reg::kIdentityCount);
        QCOMPARE(id.error, QModbusDevice::NoError);
        const auto ident = IdentityBlock::decode(blockOf(id));
        QVERIFY(ident);
        QCOMPARE(QString::fromStdString(ident->productName), QStringLiteral("HI14R3N-485-000"));
        QCOMPARE(ident->swVersion, uint16_t(171));
    }

    void exceptions_data()
    {
        QTest::addColumn<int>("start");
        QTest::addColumn<int>("count");
        QTest::addColumn<int>("exception");
        QTest::newRow("unmapped") << 0x10 << 1 << int(QModbusPdu::IllegalDataAddress);
        QTest::newRow("write-only CTRL") << 0x00 << 1 << int(QModbusPdu::IllegalDataAddress);
        QTest::newRow("too many") << 0x34 << 126 << int(QModbusPdu::IllegalDataValue);
    }
    void exceptions()
    {
        QFETCH(int, start);
        QFETCH(int, count);
        QFETCH(int, exception);
        ModbusSimulator simulator;
        QVERIFY(simulator.start());
        auto c = makeClient(simulator.devicePath(), 115200);
        QVERIFY(c->connectDevice());
        const Outcome r = readRegs(*c, 80, start, count);
        QCOMPARE(r.error, QModbusDevice::ProtocolError);
        QVERIFY(r.raw.isException());
        QCOMPARE(int(r.raw.exceptionCode()), exception);
    }

    void writeExamplesOnTheWire_data()
    {
        QTest::addColumn<int>("address");
        QTest::addColumn<int>("value");
        QTest::addColumn<QByteArray>("frame");
        // v1.7.1 6.17 (the firmware simulated here is 1.7.1)
        QTest::newRow("save") << 0x00 << 0x0000 << hex("50 06 00 00 00 00 84 4B");
        QTest::newRow("6-axis") << 0x06 << 0 << hex("50 06 00 06 00 00 64 4A");
        QTest::newRow("9-axis") << 0x06 << 1 << hex("50 06 00 06 00 01 A5 8A");
        QTest::newRow("mount 043") << 0xA6 << 0x2B << hex("50 06 00 A6 00 2B 24 77");
        QTest::newRow("mount 520") << 0xA6 << 0x208 << hex("50 06 00 A6 02 08 64 CE");
        QTest::newRow("auto-level") << 0xA5 << 2 << hex("50 06 00 A5 00 02 15 A9");
        QTest::newRow("auto-level off") << 0xA5 << 5 << hex("50 06 00 A5 00 05 54 6B");
        QTest::newRow("node 0x50") << 0x05 << 0x50 << hex("50 06 00 05 00 50 94 76");
        QTest::newRow("baud 115200") << 0x04 << 5 << hex("50 06 00 04 00 05 05 89");
    }
    void writeExamplesOnTheWire()
    {
        QFETCH(int, address);
        QFETCH(int, value);
        QFETCH(QByteArray, frame);
        ModbusSimulator simulator;
        QVERIFY(simulator.start());
        auto c = makeClient(simulator.devicePath(), 115200);
        QVERIFY(c->connectDevice());
        simulator.bridge().clearRecord();
        const Outcome r = writeReg(*c, 80, address, value);
        QCOMPARE(r.error, QModbusDevice::NoError);
        QCOMPARE(sentByClient(simulator.bridge()).toHex(' '), frame.toHex(' '));
        // The reply echoes the request.
        QByteArray reply;
        for (const auto &ch : simulator.bridge().recorded())
            if (ch.direction == sim::PtyBridge::Direction::ServerToClient)
                reply.append(reinterpret_cast<const char *>(ch.bytes.data()), qsizetype(ch.bytes.size()));
        QCOMPARE(reply.toHex(' '), frame.toHex(' '));
    }

    void mountingAndLevelTakeEffect()
    {
        ModbusSimulator simulator;
        QVERIFY(simulator.start());
        auto c = makeClient(simulator.devicePath(), 115200);
        QVERIFY(c->connectDevice());
        // Level: the static attitude is 1.5/-2.5 deg, within 15 deg: pitch and roll read 0.
        QCOMPARE(writeReg(*c, 80, reg::kAutoLevel, 2).error, QModbusDevice::NoError);
        auto s = RegisterDecoder::hipnucSample(blockOf(readRegs(*c, 80, reg::kSensorStart, reg::kSensorCount)));
        QVERIFY2(std::abs(s.roll) < 0.01 && std::abs(s.pitch) < 0.01, qPrintable(QStringLiteral("%1 %2").arg(s.roll).arg(s.pitch)));
        QVERIFY(std::abs(s.acc.z - 1.0) < 0.01);
        QCOMPARE(writeReg(*c, 80, reg::kAutoLevel, 5).error, QModbusDevice::NoError);
        s = RegisterDecoder::hipnucSample(blockOf(readRegs(*c, 80, reg::kSensorStart, reg::kSensorCount)));
        QVERIFY(std::abs(s.roll - sim::MotionModel::kStaticRollDeg) < 0.01);
        // Mounting 043 (Y axis down, X axis -90 deg): gravity moves from Z to Y.
        QCOMPARE(writeReg(*c, 80, reg::kUrfr, 43).error, QModbusDevice::NoError);
        s = RegisterDecoder::hipnucSample(blockOf(readRegs(*c, 80, reg::kSensorStart, reg::kSensorCount)));
        QVERIFY2(std::abs(std::abs(s.acc.y) - 1.0) < 0.06 && std::abs(s.acc.z) < 0.1,
                 qPrintable(QStringLiteral("%1 %2 %3").arg(s.acc.x).arg(s.acc.y).arg(s.acc.z)));
        // A value outside the table is refused and changes nothing.
        const Outcome bad = writeReg(*c, 80, reg::kUrfr, 99);
        QCOMPARE(int(bad.raw.exceptionCode()), int(QModbusPdu::IllegalDataValue));
        int code = 0;
        simulator.withDevice([&code](sim::ModbusDeviceModel &d) { code = d.running().mountingCode; });
        QCOMPARE(code, 43);
    }

    void nodeIdAndBaudChange()
    {
        ModbusSimulator simulator;
        QVERIFY(simulator.start());
        auto c = makeClient(simulator.devicePath(), 115200);
        QVERIFY(c->connectDevice());
        // v1.7.1 6.17.24: 50 06 00 05 00 51 -> the module answers at 0x51 from now on.
        QCOMPARE(writeReg(*c, 80, reg::kNodeId, 0x51).error, QModbusDevice::NoError);
        QTRY_COMPARE(simulator.nodeId(), 0x51);
        QCOMPARE(readRegs(*c, 80, reg::kNodeId, 1).error, QModbusDevice::TimeoutError);
        Outcome r = readRegs(*c, 0x51, reg::kNodeId, 1);
        QCOMPARE(r.error, QModbusDevice::NoError);
        QCOMPARE(int(r.unit.value(0)), 0x51);
        // 6.17.23: 9600; the reply still comes at 115200, then the line switches.
        QCOMPARE(writeReg(*c, 0x51, reg::kBaud, 1).error, QModbusDevice::NoError);
        QTRY_COMPARE(simulator.baud(), 9600);
        QCOMPARE(readRegs(*c, 0x51, reg::kBaud, 1).error, QModbusDevice::TimeoutError);
        c->disconnectDevice();
        c = makeClient(simulator.devicePath(), 9600, 500);
        QVERIFY(c->connectDevice());
        r = readRegs(*c, 0x51, reg::kBaud, 1);
        QCOMPARE(r.error, QModbusDevice::NoError);
        QCOMPARE(int(r.unit.value(0)), 1);
        QVERIFY(simulator.bridge().stats().garbled > 0);
        // Not saved: a reset (CTRL 0xFF) returns to 80 at 115200.
        QCOMPARE(writeReg(*c, 0x51, reg::kCtrl, 0xFF).error, QModbusDevice::NoError);
        QTRY_COMPARE(simulator.nodeId(), 80);
        QTRY_COMPARE(simulator.baud(), 115200);
    }

    void savedSettingsSurviveReset()
    {
        ModbusSimulator simulator;
        QVERIFY(simulator.start());
        auto c = makeClient(simulator.devicePath(), 115200);
        QVERIFY(c->connectDevice());
        QCOMPARE(writeReg(*c, 80, reg::kHeadingMode, 0).error, QModbusDevice::NoError);
        QCOMPARE(writeReg(*c, 80, reg::kCtrl, 0x0000).error, QModbusDevice::NoError); // save
        QCOMPARE(writeReg(*c, 80, reg::kCtrl, 0x00FF).error, QModbusDevice::NoError); // reset
        Outcome r = readRegs(*c, 80, reg::kHeadingMode, 1);
        QCOMPARE(int(r.unit.value(0)), 0);
        // 6-axis: heading starts at 0.
        const auto s = RegisterDecoder::hipnucSample(blockOf(readRegs(*c, 80, reg::kSensorStart, reg::kSensorCount)));
        QVERIFY2(std::abs(s.yaw) < 0.01, qPrintable(QString::number(s.yaw)));
        // Factory reset: 9-axis again.
        QCOMPARE(writeReg(*c, 80, reg::kCtrl, 0x0001).error, QModbusDevice::NoError);
        r = readRegs(*c, 80, reg::kHeadingMode, 1);
        QCOMPARE(int(r.unit.value(0)), 1);
    }

    void hec495()
    {
        ModbusSimOptions o;
        o.kind = DeviceKind::Hec495;
        ModbusSimulator simulator(o);
        QVERIFY(simulator.start());
        QCOMPARE(simulator.nodeId(), 1);
        auto c = makeClient(simulator.devicePath(), 9600, 500);
        QVERIFY(c->connectDevice());
        simulator.bridge().clearRecord();
        const Outcome r = readRegs(*c, 1, reg::kHecAngles, reg::kHecAngleCount);
        QCOMPARE(r.error, QModbusDevice::NoError);
        QCOMPARE(sentByClient(simulator.bridge()).toHex(' '), hex("01 03 00 04 00 06 84 09").toHex(' '));
        const auto s = RegisterDecoder::hec495Sample(blockOf(r));
        QVERIFY(std::abs(s.pitch - sim::MotionModel::kStaticPitchDeg) < 0.01);
        QVERIFY(std::abs(s.roll - sim::MotionModel::kStaticRollDeg) < 0.01);
        // The registers hold the clockwise heading (0..360); the sample keeps the device's one
        // convention, ±180, as its other links.
        QVERIFY(std::abs(*blockOf(r).f32le(0x08) - (360.0 - sim::MotionModel::kStaticYawDeg)) < 0.01);
        QVERIFY(std::abs(s.headingDeg - model::wrap360(360.0 - sim::MotionModel::kStaticYawDeg)) < 0.01);
        QVERIFY(std::abs(s.yaw - model::wrap180(sim::MotionModel::kStaticYawDeg)) < 0.01); // ENU, as every device
        // The manual's single-pitch request (0x0005, 2) answers the pitch float.
        const Outcome p = readRegs(*c, 1, reg::kHecPitchSingle, 2);
        QCOMPARE(p.error, QModbusDevice::NoError);
        QVERIFY(std::abs(*RegisterBlock(0, {p.unit.value(0), p.unit.value(1)}).f32le(0) - s.pitch) < 0.05);
        QCOMPARE(int(writeReg(*c, 1, 0x04, 0).raw.exceptionCode()), int(QModbusPdu::IllegalFunction));
    }

    // v1.7.1 6.19: the printed response (47 data bytes for 48 declared) is never accepted by the
    // client; the same registers correctly framed are, and decode to the printed values.
    void clientRejectsPrintedResponse()
    {
        int master = -1, slave = -1;
        char name[128] = {};
        QCOMPARE(::openpty(&master, &slave, name, nullptr, nullptr), 0);
        termios t{};
        ::tcgetattr(slave, &t);
        ::cfmakeraw(&t);
        ::tcsetattr(slave, TCSANOW, &t);
        auto c = makeClient(QString::fromLocal8Bit(name), 115200, 300);
        QVERIFY(c->connectDevice());
        // Reads the 8-byte request from the master, then writes the answer.
        auto answer = [master](const QByteArray &bytes) {
            QByteArray request;
            QTRY_VERIFY_WITH_TIMEOUT(([&request, master] {
                                         char buf[64];
                                         const ssize_t n = ::read(master, buf, sizeof buf);
                                         if (n > 0)
                                             request.append(buf, qsizetype(n));
                                         return request.size() >= 8;
                                     }()),
                                     3000);
            QCOMPARE(request.toHex(' '), hex("50 03 00 34 00 18 09 8F").toHex(' '));
            QCOMPARE(::write(master, bytes.constData(), size_t(bytes.size())), ssize_t(bytes.size()));
        };
        const QByteArray printed = hex("50 03 30 FF 01 03 B0 06 50 FC C9 FF 7C 00 91 01 D5 FD DB FD 27 00 00 21 FF 00 00 7F F6 FF FD "
                                       "73 E7 00 00 00 00 00 10 A6 0D 59 DD 4E 86 A8 06 30 17 82 1E CE");
        ::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK);
        QModbusReply *reply = c->sendReadRequest(QModbusDataUnit(QModbusDataUnit::HoldingRegisters, 0x34, 0x18), 0x50);
        QVERIFY(reply);
        answer(printed);
        Outcome o = finish(reply);
        QCOMPARE(o.error, QModbusDevice::TimeoutError); // it waits for the 53rd byte, then gives up

        QByteArray corrected = printed;
        corrected.insert(33, char(0));
        reply = c->sendReadRequest(QModbusDataUnit(QModbusDataUnit::HoldingRegisters, 0x34, 0x18), 0x50);
        answer(corrected);
        o = finish(reply);
        QCOMPARE(o.error, QModbusDevice::NoError);
        const auto s = RegisterDecoder::hipnucSample(blockOf(o));
        QVERIFY(std::abs(s.acc.x + 0.1245) < 1e-4 && std::abs(s.gyr.x + 50.2318) < 1e-4);
        QVERIFY(std::abs(s.mag.z + 22.2469) < 1e-4 && std::abs(s.yaw + 166.937) < 1e-6);
        c->disconnectDevice();
        ::close(master);
        ::close(slave);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstModbusSimulator)
#include "tst_modbus_simulator.moc"
