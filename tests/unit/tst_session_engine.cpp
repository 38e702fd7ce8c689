// The session engine (core/device/session_engine.h) with its serial families, driven in
// the same process through sim::SimulatedTransport: no pseudo-terminal, no simulator thread.
// What the pty tests check end to end (tests/integration/tst_device_session.cpp,
// tst_hec495_session.cpp) stays there; these check the engine's own rules.
#include "device/device_session.h"
#include "device/hec495_session.h"
#include "device/modbus_session.h"
#include "jobs/thread_sync.h"
#include "protocol/modbus/register_map.h"
#include "protocol/hipnuc/ascii_command.h"
#include "sim/hec495_simulator.h"
#include "sim/hipnuc_serial_device.h"
#include "sim/modbus_serial_device.h"
#include "sim/simulated_transport.h"
#include "../common/test_main.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>

using namespace imudesk;
using device::SessionState;
namespace hp = protocol::hipnuc;

namespace {

sim::SimulatedTransport *hipnucLink(int baud)
{
    sim::SimOptions o;
    o.baud = baud;
    return new sim::SimulatedTransport(std::make_unique<sim::HipnucSerialDevice>(o));
}

} // namespace

class TstSessionEngine : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        qRegisterMetaType<device::SessionState>();
        qRegisterMetaType<device::SessionStats>();
        qRegisterMetaType<model::DeviceIdentity>();
    }

    // Auto-detection walks the rates until LOG VERSION answers; counters restart there.
    void hipnucDetectsTheRate()
    {
        device::DeviceSession s(nullptr, std::unique_ptr<io::Transport>(hipnucLink(460800)));
        QSignalSpy detected(&s, &device::DeviceSession::baudDetected);
        QSignalSpy identity(&s, &device::DeviceSession::identityChanged);
        s.open(QStringLiteral("sim:HI14"), 0);
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Connected, 15000);
        QCOMPARE(detected.count(), 1);
        QCOMPARE(detected.at(0).at(0).toInt(), 460800);
        QVERIFY(identity.count() >= 1);
        QCOMPARE(QString::fromStdString(identity.last().at(0).value<model::DeviceIdentity>().productName)
                     .left(4),
                 QStringLiteral("HI14"));
        QTRY_VERIFY(s.store().size() > 10); // the module streams HI91 by default
    }

    // A typed command goes out as its text and its reply comes back by id; refused
    // arguments never reach the line; an unknown command times out with the engine's rule.
    void requestsByIdAndRefusals()
    {
        device::DeviceSession s(nullptr, std::unique_ptr<io::Transport>(hipnucLink(115200)));
        s.open(QStringLiteral("sim:HI14"), 115200);
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Connected, 5000);
        QSignalSpy finished(&s, &device::DeviceSession::commandFinished);
        const quint64 id = s.sendCommand(hp::commands::logOnTime(hp::Message::HI91, 0.02));
        QVERIFY(id > 0);
        QTRY_VERIFY(!finished.isEmpty());
        QCOMPARE(finished.last().at(0).toULongLong(), id);
        QVERIFY(finished.last().at(1).value<hp::AsciiReply>().ok());

        QString why;
        QCOMPARE(s.sendCommand(hp::commands::logOnTime(hp::Message::HI91, 5.0), 1000, &why), quint64(0));
        QVERIFY(!why.isEmpty());

        finished.clear();
        const quint64 unknown = s.sendText(QStringLiteral("NO SUCH COMMAND"), 200);
        QTRY_VERIFY(!finished.isEmpty());
        QCOMPARE(finished.last().at(0).toULongLong(), unknown);
        const auto reply = finished.last().at(1).value<hp::AsciiReply>();
        QCOMPARE(reply.status, hp::AsciiReply::Status::Timeout);
        QVERIFY(QString::fromStdString(reply.errorLine).contains(QStringLiteral("200 ms")));
    }

    // NMEA between binary frames reaches the values: a GGA's position, fix and time sit in the
    // store beside HI91's attitude (issue 21, point 1), while the frames keep flowing.
    void nmeaBesideBinaryFrames()
    {
        device::DeviceSession s(nullptr, std::unique_ptr<io::Transport>(hipnucLink(115200)));
        QSignalSpy sentences(&s, &device::DeviceSession::nmeaReceived);
        s.open(QStringLiteral("sim:HI14"), 115200);
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Connected, 5000);
        QSignalSpy finished(&s, &device::DeviceSession::commandFinished);
        s.sendCommand(hp::commands::logOnTime(hp::Message::GGA, 0.2));
        QTRY_VERIFY(!finished.isEmpty());
        QVERIFY(finished.last().at(1).value<hp::AsciiReply>().ok());
        QTRY_VERIFY_WITH_TIMEOUT(sentences.count() >= 2, 3000);
        const uint64_t before = s.store().totalAppended();
        QTRY_VERIFY(s.store().totalAppended() > before + 20); // HI91 goes on
        const auto v = s.store().latestPerField();
        QVERIFY(v && v->has(model::FieldPosition) && v->has(model::FieldGnss) && v->has(model::FieldQuat));
        // The simulator's GGA: 3112.5000 N, 12127.5000 E, 40 m, single fix, 12 satellites.
        QVERIFY(std::abs(v->latitudeDeg - (31 + 12.5 / 60)) < 1e-9);
        QVERIFY(std::abs(v->longitudeDeg - (121 + 27.5 / 60)) < 1e-9);
        QCOMPARE(v->altitudeM, 40.0);
        QCOMPARE(v->gnssQuality, 1);
        QCOMPARE(v->gnssSatellites, 12);
        QVERIFY(v->utcTimeOfDayS >= 0);
    }

    // The link fails (a pulled cable): queued requests end NotSent, the session waits, and
    // reopens when the device is back, with samples and counters kept.
    void reconnectsAfterUnplug()
    {
        auto *link = hipnucLink(115200);
        device::DeviceSession s(nullptr, std::unique_ptr<io::Transport>(link));
        QSignalSpy reconnected(&s, &device::Session::reconnected);
        QSignalSpy stats(&s, &device::DeviceSession::statsUpdated);
        s.open(QStringLiteral("sim:HI14"), 115200);
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Connected, 5000);
        QTRY_VERIFY(s.store().size() > 50);
        const size_t before = s.store().size();

        jobs::callAndWait(link, [link] { link->unplug(); });
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Reconnecting, 2000);
        QCOMPARE(s.sendCommand(hp::commands::logVersion()) > 0, true); // ends NotSent, nothing hangs
        QTest::qWait(700); // duration under test: away past a reopen poll (Reconnector::kPollMs, 500 ms)
        QVERIFY(s.store().size() >= before);

        jobs::callAndWait(link, [link] { link->replug(); });
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Connected, 3000);
        QCOMPARE(reconnected.count(), 1);
        QTRY_VERIFY(s.store().size() > before + 50);
        QTRY_VERIFY(!stats.isEmpty() && stats.last().at(0).value<device::SessionStats>().reconnects == 1);
    }

    // The HEC495 on the same engine: identified by "read all", a typed write confirmed.
    void hec495OnTheSameEngine()
    {
        sim::Hec495Options o;
        o.baud = 19200;
        device::Hec495Session s(nullptr, std::make_unique<sim::SimulatedTransport>(
                                              std::make_unique<sim::Hec495Simulator>(o)));
        QSignalSpy baud(&s, &device::Hec495Session::baudChanged);
        s.open(QStringLiteral("sim:HEC495"), 0, 0);
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Connected, 15000);
        QCOMPARE(baud.last().at(0).toInt(), 19200);
        QCOMPARE(s.linkKind(), QStringLiteral("HEC495 serial"));

        QSignalSpy finished(&s, &device::Hec495Session::commandFinished);
        const quint64 id = s.setDeclination(-4.5);
        QTRY_VERIFY(!finished.isEmpty());
        QCOMPARE(finished.last().at(0).toULongLong(), id);
        QVERIFY2(finished.last().at(1).value<device::Hec495Result>().ok(),
                 qPrintable(finished.last().at(1).value<device::Hec495Result>().message));
        QTRY_VERIFY(s.store().size() > 3); // polled in question/answer mode
    }

    // Modbus RTU framed by the engine's family on a 2-wire bus that echoes every request: a
    // reply with a broken CRC is counted and the request goes again; a verified write (whose
    // reply repeats its request) reads back; a baud write makes the host follow after the
    // reply, and polling carries on at the new rate.
    void modbusOnTheSameEngine()
    {
        namespace reg = protocol::modbus::reg;
        auto device = std::make_unique<sim::ModbusSerialDevice>();
        device->setEcho(true);
        device->corruptReplies(1); // the identity read's first answer
        auto *link = new sim::SimulatedTransport(std::move(device));
        device::ModbusSession s(nullptr, std::unique_ptr<io::Transport>(link));
        QSignalSpy stats(&s, &device::ModbusSession::statsUpdated);
        QSignalSpy writes(&s, &device::ModbusSession::writeFinished);
        QSignalSpy bauds(&s, &device::ModbusSession::baudChanged);
        device::ModbusOptions o;
        o.port = QStringLiteral("sim:modbus");
        o.pollHz = 20;
        s.open(o);
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Connected, 5000);
        QCOMPARE(s.linkKind(), QStringLiteral("HiPNUC Modbus"));
        QTRY_VERIFY(s.store().size() > 5);
        QCOMPARE(QString::fromStdString(s.store().latest()->source), QStringLiteral("MODBUS"));
        QTRY_VERIFY(!stats.isEmpty() && stats.last().at(0).value<device::SessionStats>().crcErrors == 1);

        const auto reply = [&writes](quint64 id) {
            for (int round = 0; round < 50; ++round) {
                for (const auto &args : writes)
                    if (args.at(0).value<device::ModbusRegisterReply>().id == id)
                        return args.at(0).value<device::ModbusRegisterReply>();
                writes.wait(100);
            }
            return device::ModbusRegisterReply{};
        };
        auto r = reply(s.writeRegister(reg::kHeadingMode, 0));
        QVERIFY2(r.ok && r.message.contains(QStringLiteral("Read back")), qPrintable(r.message));

        r = reply(s.writeRegister(reg::kBaud, 1)); // 9600
        QVERIFY2(r.ok && r.message.contains(QStringLiteral("Read back")), qPrintable(r.message));
        QCOMPARE(bauds.last().at(0).toInt(), 9600);
        int deviceBaud = 0;
        jobs::callAndWait(link, [link, &deviceBaud] { deviceBaud = link->device().baud(); });
        QCOMPARE(deviceBaud, 9600);
        const quint64 n = s.store().totalAppended();
        QTRY_VERIFY_WITH_TIMEOUT(s.store().totalAppended() >= n + 3, 3000);
        QCOMPARE(s.state(), SessionState::Connected);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstSessionEngine)
#include "tst_session_engine.moc"
