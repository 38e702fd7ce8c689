// ModbusSession against the simulated Modbus devices: identity, polling into the sample store,
// poll rate bounded by the baud, verified writes, following a new node ID and baud, exception
// and timeout messages, scans by ID and by baud with cancel.
//
// In process by default (sim::ModbusSerialDevice behind sim::SimulatedTransport in the session's
// thread, tests/common/inproc_link.h); connectsAndPolls and verifiedWritesFollowIdAndBaud run
// against the Modbus RTU server on a pseudo-terminal and prove the real serial path (reads,
// writes, a new node ID and a rate change on the port).
#include "../common/inproc_link.h"
#include "../common/test_main.h"
#include "device/modbus_session.h"
#include "protocol/modbus/register_map.h"
#include "sim/modbus_serial_device.h"
#include "sim/modbus_simulator.h"

#include <QSignalSpy>
#include <QtTest>

using namespace imudesk;
using namespace imudesk::device;
using imudesk::protocol::modbus::DeviceKind;
namespace reg = imudesk::protocol::modbus::reg;

namespace {

ModbusOptions optionsFor(const QString &port, double pollHz = 50)
{
    ModbusOptions o;
    o.port = port;
    o.pollHz = pollHz;
    o.timeoutMs = 600; // generous: the test machine is shared
    return o;
}
ModbusOptions optionsFor(const sim::ModbusSimulator &s, double pollHz = 50)
{
    return optionsFor(s.devicePath(), pollHz);
}

// A simulated Modbus device in process and the session that talks to it.
struct Bus {
    test::InProcSession<ModbusSession> in;

    explicit Bus(sim::ModbusSimOptions so = {})
        : in(test::inProcSession<ModbusSession>(std::make_unique<sim::ModbusSerialDevice>(so), QStringLiteral("sim:modbus")))
    {
    }
    ModbusSession &session() { return *in.session; }
    ModbusOptions options(double pollHz = 50) const { return optionsFor(in.port, pollHz); }
    // Bytes the session has put on the line.
    quint64 bytesOnTheLine() const { return in.link->bytesWritten(); }
};

ModbusRegisterReply waitReply(QSignalSpy &spy, quint64 id)
{
    for (int round = 0; round < 50; ++round) {
        for (const auto &args : spy) {
            const auto r = args.at(0).value<ModbusRegisterReply>();
            if (r.id == id)
                return r;
        }
        spy.wait(200);
    }
    return {};
}

} // namespace

class TstModbusSession : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        qRegisterMetaType<ModbusRegisterReply>();
        qRegisterMetaType<ModbusScanHit>();
    }

    // Over a pseudo-terminal.
    void connectsAndPolls()
    {
        sim::ModbusSimOptions so;
        so.motion = sim::Motion::Spin;
        sim::ModbusSimulator simulator(so);
        QVERIFY(simulator.start());
        ModbusSession session;
        QSignalSpy identity(&session, &ModbusSession::identityChanged);
        QSignalSpy stats(&session, &ModbusSession::statsUpdated);
        session.open(optionsFor(simulator, 50));
        QTRY_COMPARE(session.state(), SessionState::Connected);
        QCOMPARE(identity.count(), 1);
        const auto id = identity.at(0).at(0).value<model::DeviceIdentity>();
        QCOMPARE(QString::fromStdString(id.productName), QStringLiteral("HI14R3N-485-000"));
        QCOMPARE(QString::fromStdString(id.firmware->toString()), QString::fromStdString(model::FirmwareVersion{1, 7, 1}.toString()));
        QCOMPARE(session.linkKind(), QStringLiteral("HiPNUC Modbus"));
        QTRY_VERIFY_WITH_TIMEOUT(session.store().totalAppended() >= 25, 5000);
        const auto samples = session.store().since(0);
        const auto &first = samples.front();
        const auto &last = samples.back();
        QCOMPARE(QString::fromStdString(last.source), QStringLiteral("MODBUS"));
        QVERIFY(last.has(model::FieldAcc) && last.has(model::FieldEuler) && last.has(model::FieldQuat));
        QVERIFY(last.hostTimeNs > first.hostTimeNs);
        // Spin: 30 deg/s about Z, and the registers follow it.
        QVERIFY(std::abs(last.gyr.z - 30.0) < 1.0);
        QVERIFY(std::abs(last.yaw - first.yaw) > 1.0);
        QTRY_VERIFY(!stats.isEmpty());
        const auto st = stats.last().at(0).value<SessionStats>();
        QVERIFY(st.frames >= 2);
        QCOMPARE(st.baud, 115200);
    }

    void pollRateIsBoundedByTheBaud()
    {
        sim::ModbusSimOptions so;
        so.baud = 9600;
        Bus bus(so);
        ModbusSession &session = bus.session();
        QSignalSpy rate(&session, &ModbusSession::pollRateChanged);
        ModbusOptions o = bus.options(1000);
        o.baud = 9600;
        session.open(o);
        QTRY_COMPARE(session.state(), SessionState::Connected);
        QTRY_VERIFY(!rate.isEmpty());
        const double limit = ModbusSession::maxPollRate(9600, reg::kSensorCount);
        QVERIFY(limit > 5 && limit < 15);
        QCOMPARE(rate.last().at(0).toDouble(), limit);
        const quint64 before = session.store().totalAppended();
        QTest::qWait(1500); // duration under test: the poll rate, counted over 1.5 s
        const quint64 polled = session.store().totalAppended() - before;
        QVERIFY2(polled >= 5 && polled <= quint64(1.5 * limit + 2), qPrintable(QString::number(polled)));
    }

    // Over a pseudo-terminal: the port follows the new node ID and rate.
    void verifiedWritesFollowIdAndBaud()
    {
        sim::ModbusSimulator simulator;
        QVERIFY(simulator.start());
        ModbusSession session;
        QSignalSpy writes(&session, &ModbusSession::writeFinished);
        QSignalSpy ids(&session, &ModbusSession::nodeIdChanged);
        QSignalSpy bauds(&session, &ModbusSession::baudChanged);
        session.open(optionsFor(simulator, 20));
        QTRY_COMPARE(session.state(), SessionState::Connected);

        // 6-axis mode, read back.
        auto r = waitReply(writes, session.writeRegister(reg::kHeadingMode, 0));
        QVERIFY2(r.ok, qPrintable(r.message));
        QVERIFY(r.message.contains(QStringLiteral("Read back")));

        // New node ID: the session follows it and reads it back there.
        r = waitReply(writes, session.writeRegister(reg::kNodeId, 0x52));
        QVERIFY2(r.ok, qPrintable(r.message));
        QCOMPARE(ids.last().at(0).toInt(), 0x52);
        QCOMPARE(simulator.nodeId(), 0x52);

        // New baud: the session switches after the reply and reads it back at 9600.
        r = waitReply(writes, session.writeRegister(reg::kBaud, 1));
        QVERIFY2(r.ok, qPrintable(r.message));
        QCOMPARE(bauds.last().at(0).toInt(), 9600);
        QCOMPARE(simulator.baud(), 9600);
        // Polling carries on at the new ID and baud.
        const quint64 n = session.store().totalAppended();
        QTRY_VERIFY_WITH_TIMEOUT(session.store().totalAppended() >= n + 3, 5000);
        QCOMPARE(session.state(), SessionState::Connected);

        // Save, reset: the saved ID and baud stay.
        r = waitReply(writes, session.writeRegister(reg::kCtrl, 0));
        QVERIFY2(r.ok, qPrintable(r.message));
        r = waitReply(writes, session.writeRegister(reg::kCtrl, 0xFF));
        QVERIFY2(r.ok, qPrintable(r.message));
        const quint64 m = session.store().totalAppended();
        QTRY_VERIFY_WITH_TIMEOUT(session.store().totalAppended() >= m + 3, 5000);
        int savedId = 0;
        simulator.withDevice([&savedId](sim::ModbusDeviceModel &d) { savedId = d.saved().nodeId; });
        QCOMPARE(savedId, 0x52);
    }

    void clearMessages()
    {
        Bus bus;
        ModbusSession &session = bus.session();
        QSignalSpy reads(&session, &ModbusSession::registersRead);
        QSignalSpy writes(&session, &ModbusSession::writeFinished);
        session.open(bus.options(0));
        QTRY_COMPARE(session.state(), SessionState::Connected);
        auto r = waitReply(reads, session.readRegisters(0x10, 1));
        QVERIFY(!r.ok);
        QCOMPARE(r.exceptionCode, 2);
        QVERIFY2(r.message.contains(QStringLiteral("ILLEGAL DATA ADDRESS")) && r.message.contains(QStringLiteral("0x0010")),
                 qPrintable(r.message));
        r = waitReply(reads, session.readRegisters(reg::kSensorStart, 24));
        QVERIFY(r.ok);
        QCOMPARE(r.values.size(), 24);
        // Refused before it goes on the bus: code 9 is not in the baud table.
        const quint64 onTheLine = bus.bytesOnTheLine();
        r = waitReply(writes, session.writeRegister(reg::kBaud, 9));
        QVERIFY(!r.ok);
        QVERIFY2(r.message.contains(QStringLiteral("UART1_BAUD")), qPrintable(r.message));
        QCOMPARE(bus.bytesOnTheLine(), onTheLine);
    }

    void wrongNodeTimesOut()
    {
        Bus bus;
        ModbusSession &session = bus.session();
        QSignalSpy errors(&session, &ModbusSession::errorOccurred);
        ModbusOptions o = bus.options();
        o.nodeId = 81;
        session.open(o);
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), SessionState::Failed, 5000);
        QVERIFY(!errors.isEmpty());
        const QString msg = errors.last().at(0).toString();
        QVERIFY2(msg.contains(QStringLiteral("No reply from node 81")) && msg.contains(QStringLiteral("baud")), qPrintable(msg));
    }

    void scanFindsTheNode()
    {
        sim::ModbusSimOptions so;
        so.nodeId = 83;
        Bus bus(so);
        ModbusSession &session = bus.session();
        ModbusOptions o = bus.options(0);
        o.identify = false;
        session.open(o);
        QTRY_COMPARE(session.state(), SessionState::Connected);
        QSignalSpy progress(&session, &ModbusSession::scanProgress);
        QSignalSpy finished(&session, &ModbusSession::scanFinished);
        ModbusScanOptions scan;
        scan.firstId = 78;
        scan.lastId = 88;
        scan.timeoutMs = 250;
        session.scan(scan);
        QVERIFY(finished.wait(10000));
        const auto hits = finished.at(0).at(0).value<QList<ModbusScanHit>>();
        QCOMPARE(finished.at(0).at(1).toBool(), false);
        QCOMPARE(hits.size(), 1);
        QCOMPARE(hits.at(0).nodeId, 83);
        QVERIFY(hits.at(0).identified);
        QCOMPARE(QString::fromStdString(hits.at(0).identity.productName), QStringLiteral("HI14R3N-485-000"));
        QCOMPARE(progress.last().at(0).toInt(), 11);
        QCOMPARE(progress.last().at(1).toInt(), 11);
    }

    void scanAcrossBaudsAndCancel()
    {
        sim::ModbusSimOptions so;
        so.nodeId = 5;
        so.baud = 19200;
        Bus bus(so);
        ModbusSession &session = bus.session();
        ModbusOptions o = bus.options(0);
        o.identify = false;
        session.open(o);
        QTRY_COMPARE(session.state(), SessionState::Connected);
        QSignalSpy finished(&session, &ModbusSession::scanFinished);
        QSignalSpy baud(&session, &ModbusSession::baudChanged);
        ModbusScanOptions scan;
        scan.firstId = 1;
        scan.lastId = 6;
        scan.bauds = {115200, 19200};
        scan.timeoutMs = 250;
        session.scan(scan);
        QVERIFY(finished.wait(15000));
        auto hits = finished.at(0).at(0).value<QList<ModbusScanHit>>();
        QCOMPARE(hits.size(), 1);
        QCOMPARE(hits.at(0).nodeId, 5);
        QCOMPARE(hits.at(0).baud, 19200);

        // Cancel a full scan after a few probes.
        QSignalSpy progress(&session, &ModbusSession::scanProgress);
        finished.clear();
        session.scan(ModbusScanOptions{});
        QTRY_VERIFY(progress.count() >= 4);
        session.cancelScan();
        QVERIFY(finished.wait(5000));
        QCOMPARE(finished.at(0).at(1).toBool(), true);
        QVERIFY(progress.last().at(0).toInt() < 247);
    }

    void hec495Polls()
    {
        sim::ModbusSimOptions so;
        so.kind = DeviceKind::Hec495;
        Bus bus(so);
        ModbusSession &session = bus.session();
        ModbusOptions o = bus.options(5);
        o.kind = DeviceKind::Hec495;
        session.open(o);
        QTRY_COMPARE(session.state(), SessionState::Connected);
        QCOMPARE(session.linkKind(), QStringLiteral("HEC495 Modbus"));
        QTRY_VERIFY_WITH_TIMEOUT(session.store().totalAppended() >= 3, 5000);
        const auto s = *session.store().latest();
        QCOMPARE(QString::fromStdString(s.source), QStringLiteral("HEC495"));
        QVERIFY(std::abs(s.pitch - sim::MotionModel::kStaticPitchDeg) < 0.01);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstModbusSession)
#include "tst_modbus_session.moc"
