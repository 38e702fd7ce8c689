// The simulated CAN device without a bus: J1939 configuration, CANopen SDO/SYNC/NMT and the
// HEC495 SDO writes answer as the manuals describe; periodic output follows the settings.
#include "model/attitude.h"
#include "protocol/can/canopen.h"
#include "protocol/can/hec495_can.h"
#include "protocol/can/hipnuc_canopen_objects.h"
#include "protocol/can/j1939.h"
#include "protocol/can/j1939_config.h"
#include "protocol/can/sdo.h"
#include "sim/can_sim_device.h"
#include "sim/hec495_simulator.h"
#include "../common/test_main.h"

#include <QTest>

#include <cmath>

using namespace imudesk::protocol::can;
using imudesk::sim::CanSimDevice;
using imudesk::sim::CanSimOptions;
using imudesk::sim::Hec495Options;
using imudesk::sim::Hec495Simulator;
using imudesk::sim::Motion;
namespace model = imudesk::model;

namespace {
// Frames with this id sent between t0 and t1 (s), polling every ms.
int countBetween(CanSimDevice &d, uint32_t id, double t0, double t1)
{
    int n = 0;
    for (double t = t0; t < t1; t += 0.001)
        for (const auto &f : d.poll(t))
            n += f.id == id ? 1 : 0;
    return n;
}
// Window edges may hold one frame more or less.
bool about(int n, int expected) { return n >= expected - 1 && n <= expected + 1; }
CanSimOptions opts(CanProtocol p, bool hec = false)
{
    CanSimOptions o;
    o.protocol = p;
    o.hec495 = hec;
    return o;
}
} // namespace

class TstCanSimDevice : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void j1939DefaultsAndIntervals()
    {
        CanSimDevice d(opts(CanProtocol::J1939));
        QCOMPARE(d.node(), 8);
        QVERIFY(about(countBetween(d, 0x0CFF3708, 0, 1.0), 10)); // 100 ms default
        // 7.23 example: gyro at 100 ms -> reply echoes from 0x0CEF5508.
        const auto r = d.handle(CanFrame::fromHex(0x0CEF0855, true, "3701060014000000"), 1.0); // 20 ms
        QCOMPARE(r.size(), size_t(1));
        QCOMPARE(r[0].id, 0x0CEF5508u);
        QCOMPARE(r[0].payload(), QByteArray::fromHex("3701060014000000"));
        QVERIFY(about(countBetween(d, 0x0CFF3708, 1.0, 2.0), 50));
        // Read back.
        const auto rb = d.handle(j1939::encodeReg(j1939::readRequest(8, 0x55, 0x0137)), 2.0);
        QCOMPARE(rb.size(), size_t(1));
        QCOMPARE(j1939::parseReg(rb[0])->value, 20u);
        // Out of range: status non-zero.
        const auto bad = d.handle(j1939::encodeReg(j1939::intervalRequest(8, 0x55, j1939::PgnGyr, 2)), 2.0);
        QCOMPARE(int(j1939::parseReg(bad[0])->status), 1);
        // Another node's request is ignored.
        QVERIFY(d.handle(j1939::encodeReg(j1939::intervalRequest(9, 0x55, j1939::PgnGyr, 50)), 2.0).empty());
    }

    // 7.22.41: the J1939 registers are the Modbus register list's (6.16), one register in VAL:
    // HEADING_MODE read and written, PNAME as ASCII two characters a register, ACCZ about 1 G
    // at rest, URFR written but not read, a Modbus ID out of 1..128 refused.
    void j1939ModbusListRegisters()
    {
        CanSimDevice d(opts(CanProtocol::J1939));
        d.poll(0);
        const auto ask = [&d](const j1939::RegMessage &m, double t) {
            const auto out = d.handle(j1939::encodeReg(m), t);
            return out.size() == 1 ? j1939::parseReg(out[0]) : std::nullopt;
        };
        auto r = ask(j1939::readRequest(8, 0x55, 0x06), 0.1);
        QVERIFY(r && r->status == 0);
        QCOMPARE(r->value, 1u); // 9-axis from the factory
        r = ask(j1939::writeRequest(8, 0x55, 0x06, 0), 0.2);
        QVERIFY(r && r->status == 0);
        QCOMPARE(ask(j1939::readRequest(8, 0x55, 0x06), 0.3)->value, 0u);
        QByteArray name;
        for (uint16_t a = 0x70; a <= 0x77; ++a) {
            r = ask(j1939::readRequest(8, 0x55, a), 0.4);
            QVERIFY(r && r->status == 0 && r->value <= 0xFFFF);
            name.append(char(r->value >> 8)).append(char(r->value & 0xFF));
        }
        QVERIFY2(name.startsWith("HI14R3N-485"), name.constData());
        r = ask(j1939::readRequest(8, 0x55, 0x36), 0.5);
        QVERIFY(r && r->status == 0);
        const double accZ = int16_t(uint16_t(r->value)) * 0.00048828;
        QVERIFY2(std::abs(accZ - 1.0) < 0.05, qPrintable(QString::number(accZ)));
        QCOMPARE(int(ask(j1939::writeRequest(8, 0x55, 0xA6, 0x18), 0.6)->status), 0);
        QCOMPARE(int(ask(j1939::readRequest(8, 0x55, 0xA6), 0.6)->status), 1);
        QCOMPARE(int(ask(j1939::writeRequest(8, 0x55, 0x05, 200), 0.7)->status), 1);
        QCOMPARE(int(ask(j1939::writeRequest(8, 0x55, 0x34, 1), 0.7)->status), 1); // read only
    }

    void j1939TriggerEnableNode()
    {
        CanSimDevice d(opts(CanProtocol::J1939));
        // 7.23: trigger has no reply, only the data frame.
        const auto tr = d.handle(CanFrame::fromHex(0x0CEF0855, true, "9600060034FF0000"), 0.5);
        QCOMPARE(tr.size(), size_t(1));
        QCOMPARE(tr[0].id, 0x0CFF3408u);
        d.handle(CanFrame::fromHex(0x0CEF0855, true, "9D00060000000000"), 0.5);
        QCOMPARE(countBetween(d, 0x0CFF3408, 0.5, 1.5), 0);
        d.handle(CanFrame::fromHex(0x0CEF0855, true, "9D00060001000000"), 1.5);
        QVERIFY(countBetween(d, 0x0CFF3408, 1.5, 2.5) >= 9);
        // Node ID: takes effect after save + reset.
        d.handle(j1939::encodeReg(j1939::writeRequest(8, 0x55, j1939::RegNodeId, 9)), 3.0);
        QCOMPARE(d.node(), 8);
        d.handle(j1939::encodeReg(j1939::writeRequest(8, 0x55, j1939::RegCommand, j1939::CommandSave)), 3.0);
        d.handle(j1939::encodeReg(j1939::writeRequest(8, 0x55, j1939::RegCommand, j1939::CommandReset)), 3.0);
        QCOMPARE(d.node(), 9);
        QVERIFY(countBetween(d, 0x0CFF3409, 3.0, 4.0) >= 9);
        // Factory defaults: back to node 8.
        d.handle(j1939::encodeReg(j1939::writeRequest(9, 0x55, j1939::RegCommand, j1939::CommandFactory)), 4.0);
        QCOMPARE(d.node(), 8);
    }

    void canopenSdoAndRates()
    {
        CanSimDevice d(opts(CanProtocol::CanOpen));
        const auto boot = d.poll(0);
        QVERIFY(!boot.empty());
        QCOMPARE(boot[0].id, 0x708u); // boot-up
        QCOMPARE(int(boot[0].data[0]), 0);
        QVERIFY(about(countBetween(d, 0x188, 0.001, 1.0), 100));
        // 8.28.45.24: 1800.5 = 100 -> 10 Hz.
        const auto r = d.handle(canopen::hipnuc::setTpdoPeriod(8, 0, 100), 1.0);
        QCOMPARE(r.size(), size_t(1));
        QCOMPARE(r[0].id, 0x588u);
        QCOMPARE(r[0].payload(), QByteArray::fromHex("6000180500000000"));
        QVERIFY(about(countBetween(d, 0x188, 1.0, 2.0), 10));
        const auto rd = d.handle(canopen::sdoRead(8, 0x1800, 5), 2.0);
        QCOMPARE(canopen::parseSdo(rd[0])->value, 100u);
        // Unknown object: abort 0x06020000.
        const auto ab = d.handle(canopen::sdoWrite(8, 0x2123, 0, 1), 2.0);
        QCOMPARE(canopen::parseSdo(ab[0])->kind, canopen::SdoKind::Abort);
        QCOMPARE(canopen::parseSdo(ab[0])->value, uint32_t(canopen::AbortNoObject));
        // 1.7.1 has no 0x20A0.
        QCOMPARE(canopen::parseSdo(d.handle(canopen::hipnuc::setNodeId(8, 9, canopen::hipnuc::ObjNodeIdV166), 2.0)[0])->kind,
                 canopen::SdoKind::Abort);
    }

    void canopenSyncAndNmt()
    {
        CanSimDevice d(opts(CanProtocol::CanOpen));
        d.poll(0);
        d.handle(canopen::hipnuc::setTransmissionType(8, 0, canopen::hipnuc::kTransmissionSync), 0.0);
        QCOMPARE(countBetween(d, 0x188, 0.001, 0.5), 0);
        const auto s = d.handle(canopen::encodeSync(), 0.5);
        QCOMPARE(s.size(), size_t(1));
        QCOMPARE(s[0].id, 0x188u);
        d.handle(canopen::encodeNmt(canopen::NmtStop, 8), 0.5);
        QVERIFY(d.handle(canopen::encodeSync(), 0.6).empty());
        QCOMPARE(countBetween(d, 0x288, 0.6, 1.0), 0);
        d.handle(canopen::encodeNmt(canopen::NmtStart, 0), 1.0);
        QVERIFY(countBetween(d, 0x288, 1.0, 1.5) >= 49);
        // Heartbeat 100 ms.
        d.handle(canopen::hipnuc::setHeartbeat(8, 100), 1.5);
        QVERIFY(about(countBetween(d, 0x708, 1.5, 2.5), 10));
        // v1.6.6: node ID at 0x20A0.
        CanSimOptions o = opts(CanProtocol::CanOpen);
        o.firmware = "1.6.6";
        CanSimDevice old(o);
        QCOMPARE(canopen::parseSdo(old.handle(canopen::hipnuc::setNodeId(8, 9, canopen::hipnuc::ObjNodeIdV166), 0)[0])->kind,
                 canopen::SdoKind::DownloadReply);
    }

    void hec495Standard()
    {
        CanSimDevice d(opts(CanProtocol::CanOpen, true));
        QCOMPARE(d.node(), 5);
        QVERIFY(about(countBetween(d, 0x185, 0, 1.0), 5)); // 5 Hz default
        QVERIFY(about(countBetween(d, 0x705, 1.0, 3.0), 2)); // heartbeat N = 9: 1 s
        const auto r = d.handle(hec495::writeRequest(5, hec495::ObjPdoRate, 6), 2.0);
        QCOMPARE(r[0].payload(), QByteArray::fromHex("6000620000000000"));
        QVERIFY(about(countBetween(d, 0x185, 2.0, 3.0), 100));
        d.handle(hec495::writeRequest(5, hec495::ObjPdoMode, 1), 3.0);
        bool fixedSeen = false;
        for (const auto &f : d.poll(3.1))
            if (f.id == 0x185)
                fixedSeen = hec495::looksFixed(f);
        QVERIFY(fixedSeen);
        // Node change applies after a power cycle (manual: frames from 0x590 afterwards).
        const auto n = d.handle(CanFrame::fromHex(0x605, false, "2210100010000000"), 3.2);
        QCOMPARE(n[0].payload(), QByteArray::fromHex("6010100000000000"));
        QCOMPARE(d.node(), 5);
        d.powerCycle(3.3);
        QCOMPARE(d.node(), 0x10);
        QVERIFY(countBetween(d, 0x190, 3.3, 4.3) > 0);
        d.handle(hec495::stopAll(), 4.3);
        QCOMPARE(countBetween(d, 0x190, 4.4, 5.0), 0);
    }

    // The heartbeat's period after a write of N (manual: 100 ms * (N + 1)), for N = 3 and for
    // N = 255 (25.6 s: the manual has no "off").
    void hec495HeartbeatPeriod()
    {
        CanSimDevice d(opts(CanProtocol::CanOpen, true));
        QVERIFY(about(countBetween(d, 0x705, 0, 3.0), 3)); // N = 9: 1 s
        auto r = d.handle(hec495::writeRequest(5, hec495::ObjHeartbeat, 3), 3.0);
        QCOMPARE(r[0].payload(), QByteArray::fromHex("6017100000000000"));
        QVERIFY(about(countBetween(d, 0x705, 3.0, 7.0), 10)); // 400 ms
        r = d.handle(hec495::writeRequest(5, hec495::ObjHeartbeat, 255), 7.0);
        QCOMPARE(r[0].payload(), QByteArray::fromHex("6017100000000000"));
        QCOMPARE(countBetween(d, 0x705, 7.001, 32.5), 1);  // 25.6 s after the write
        QCOMPARE(countBetween(d, 0x705, 32.5, 58.1), 1);
    }

    // The compass on CAN reports what it reports on serial: the heading clockwise from north (the
    // serial simulator's true heading, +-180 as in the read-all record), the field relative.
    void hec495HeadingAndFieldAsOnSerial()
    {
        CanSimOptions o = opts(CanProtocol::CanOpen, true);
        o.motion = Motion::Spin;
        CanSimDevice d(o);
        Hec495Options so;
        so.motion = Motion::Spin;
        Hec495Simulator serial(so);
        int checked = 0;
        for (double t = 0.2; t < 3.0; t += 0.2) {
            const model::Sample s = d.hec495SampleAt(t);
            double expected = serial.trueHeadingAt(int64_t(t * 1e6));
            if (expected > 180)
                expected -= 360;
            // The heading as its own quantity, and the world frame's yaw its opposite (issue 53 point 7).
            QVERIFY(s.has(model::FieldHeading));
            QVERIFY(std::abs(model::wrap180(s.headingDeg + s.yaw)) < 1e-6);
            double diff = std::abs(model::wrap180(s.headingDeg) - expected);
            diff = std::min(diff, 360 - diff);
            QVERIFY2(diff < 0.01, qPrintable(QStringLiteral("t %1: CAN %2, serial %3").arg(t).arg(s.headingDeg).arg(expected)));
            QVERIFY(s.has(model::FieldMagRelative) && !s.has(model::FieldMag));
            const double horizontal = std::hypot(s.magRelative.x, s.magRelative.y);
            QVERIFY2(horizontal > 0.3 && horizontal < 3, qPrintable(QString::number(horizontal))); // about 1, not uT
            ++checked;
        }
        QCOMPARE(checked, 14);
    }

    void hec495Extended()
    {
        CanSimDevice d(opts(CanProtocol::J1939, true));
        QVERIFY(countBetween(d, hec495::kExtDataXId, 0, 1.0) == 5);
        QCOMPARE(countBetween(d, hec495::kExtDataYId, 1.0, 2.0), 0);
        const auto r = d.handle(hec495::writeRequest(0, hec495::ObjPdoMode, 1, true), 2.0);
        QCOMPARE(r[0].id, hec495::kExtReplyId);
        QVERIFY(about(countBetween(d, hec495::kExtDataYId, 2.0, 3.0), 5));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCanSimDevice)
#include "tst_can_sim_device.moc"
