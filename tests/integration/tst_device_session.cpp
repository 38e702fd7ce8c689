// DeviceSession against the simulator on a real pseudo-terminal (QSerialPort path):
// baud detection, identity, streaming, every documented command, ERR and timeouts,
// errors for missing ports, and the unplug case.
#include "device/device_session.h"
#include "sim/hipnuc_simulator.h"
#include "sim/pty_simulator.h"

#include <QSignalSpy>
#include <QTest>

using namespace imudesk;
using device::DeviceSession;
using device::SessionState;
using protocol::hipnuc::AsciiReply;
using Status = AsciiReply::Status;

Q_DECLARE_METATYPE(Status)

namespace {

sim::SimOptions options(const char *firmware = "1.7.1", int baud = 115200, const char *model = "HI14")
{
    sim::SimOptions o;
    o.model = model;
    o.firmware = firmware;
    o.baud = baud;
    o.motion = sim::Motion::Static;
    o.seed = 42;
    return o;
}

bool waitConnected(DeviceSession &s, int timeoutMs = 15000)
{
    QElapsedTimer t;
    t.start();
    while (s.state() != SessionState::Connected && t.elapsed() < timeoutMs) {
        if (s.state() == SessionState::Failed)
            return false;
        QTest::qWait(10);
    }
    return s.state() == SessionState::Connected;
}

AsciiReply send(DeviceSession &s, const QString &cmd, int timeoutMs = 800)
{
    QSignalSpy spy(&s, &DeviceSession::commandFinished);
    const quint64 id = s.sendCommand(cmd, timeoutMs);
    for (int waited = 0; waited < timeoutMs + 3000; waited += 10) {
        for (const auto &args : spy)
            if (args.at(0).toULongLong() == id)
                return args.at(1).value<AsciiReply>();
        QTest::qWait(10);
    }
    AsciiReply r;
    r.status = Status::Pending;
    return r;
}

} // namespace

class TstDeviceSession : public QObject {
    Q_OBJECT
    std::map<QString, std::pair<std::unique_ptr<sim::PtySimulator>, std::unique_ptr<DeviceSession>>> m_open;
private Q_SLOTS:
    void cleanupTestCase()
    {
        for (auto &[fw, slot] : m_open) {
            slot.second.reset(); // the session closes its port before the simulator goes
            slot.first.reset();
        }
        m_open.clear();
    }

    void detectsNonDefaultBaud()
    {
        sim::PtySimulator simulator(options("1.7.1", 460800));
        QString error;
        QVERIFY2(simulator.start(&error), qPrintable(error));
        DeviceSession session;
        QSignalSpy identity(&session, &DeviceSession::identityChanged);
        QSignalSpy baud(&session, &DeviceSession::baudDetected);
        session.open(simulator.devicePath(), 0);
        QVERIFY(waitConnected(session));
        QCOMPARE(baud.size(), 1);
        QCOMPARE(baud.at(0).at(0).toInt(), 460800);
        QTRY_COMPARE(identity.size(), 1);
        const auto id = identity.at(0).at(0).value<model::DeviceIdentity>();
        QCOMPARE(id.productName, std::string("HI14R3"));
        QCOMPARE(id.firmware->toString(), std::string("1.7.1"));
        QVERIFY(!id.serial.empty());
        // Streaming HI91 at 100 Hz arrives as samples.
        const auto before = session.store().totalAppended();
        QTest::qWait(1000);
        const auto got = session.store().totalAppended() - before;
        QVERIFY2(got >= 80 && got <= 120, qPrintable(QString::number(got)));
        const auto s = session.store().latest();
        QVERIFY(s);
        QCOMPARE(s->source, std::string("HI91"));
        QVERIFY(qAbs(std::sqrt(s->acc.x * s->acc.x + s->acc.y * s->acc.y + s->acc.z * s->acc.z) - 1.0) < 0.05);
    }

    void statsReportRateAndLoad()
    {
        sim::PtySimulator simulator(options());
        QVERIFY(simulator.start(nullptr));
        DeviceSession session;
        device::SessionStats last;
        connect(&session, &DeviceSession::statsUpdated, this, [&](const device::SessionStats &s) { last = s; });
        session.open(simulator.devicePath(), 115200);
        QVERIFY(waitConnected(session));
        QTest::qWait(1600);
        QVERIFY(last.framesByType.count("HI91"));
        const double rate = last.rateByType["HI91"];
        QVERIFY2(rate > 80 && rate < 120, qPrintable(QString::number(rate)));
        // 82-byte frames at 100 Hz on 115200 baud: about 71 % of the line.
        QVERIFY2(last.linkLoad > 0.55 && last.linkLoad < 0.9, qPrintable(QString::number(last.linkLoad)));
        QCOMPARE(last.crcErrors, uint64_t(0));
    }

    void everyCommand_data()
    {
        QTest::addColumn<QString>("firmware");
        QTest::addColumn<QString>("command");
        QTest::addColumn<Status>("expected");
        QTest::addColumn<QString>("mustContain"); // a KEY=VALUE or line the reply must include
        const Status ok = Status::Ok, err = Status::Error, silent = Status::Timeout;
        struct Row {
            const char *fw, *cmd;
            Status st;
            const char *contains;
        };
        const Row rows[] = {
            {"1.7.1", "LOG VERSION", ok, "APP_VER=171"},
            {"1.7.1", "LOG COMCONFIG", ok, "HI91=ONTIME 0.01"},
            {"1.7.1", "LOG DISABLE", ok, ""},
            {"1.7.1", "LOG ENABLE", ok, ""},
            {"1.7.1", "LOG HI91 ONTIME 0.02", ok, ""},
            {"1.7.1", "LOG HI91 ONTIME 0", ok, ""},
            {"1.7.1", "LOG HI83 ONTIME 0.1", ok, ""},
            {"1.7.1", "LOG HI83 MAP 0x0000001F", ok, ""},
            {"1.7.1", "LOG HI83 MAP 0x02000000", err, ""},
            {"1.7.1", "LOG HI81 ONTIME 1", ok, ""},
            {"1.7.1", "LOG GGA ONTIME 1", ok, ""},
            {"1.7.1", "LOG RMC ONTIME 1", ok, ""},
            {"1.7.1", "LOG SXT ONTIME 1", ok, ""},
            {"1.7.1", "LOG HI91 ONMARK 1", ok, ""},
            {"1.7.1", "LOG HI91 ONMARK ONCE", ok, ""},
            {"1.7.1", "LOG HI91 ONTIME 5", err, ""},
            {"1.7.1", "LOG HI92 ONTIME 0.01", err, ""},
            {"1.7.1", "LOG MCAL STAT", ok, "STAT=0"},
            {"1.7.1", "CONFIG ATT MODE 0", ok, ""},
            {"1.7.1", "CONFIG ATT MODE 1", ok, ""},
            {"1.7.1", "CONFIG ATT MODE 4", ok, ""},
            {"1.7.1", "CONFIG ATT MODE 7", err, ""},
            {"1.7.1", "CONFIG ATT RST 1", ok, ""},
            {"1.7.1", "CONFIG ATT RST 2", ok, ""},
            {"1.7.1", "CONFIG ATT RST 5", ok, ""},
            {"1.7.1", "CONFIG IMU URFR 240", ok, ""},
            {"1.7.1", "CONFIG IMU URFR 25", err, ""},
            {"1.7.1", "CONFIG IMU COORD 4", ok, ""},
            {"1.7.1", "CONFIG IMU COORD 2", err, ""},
            {"1.7.1", "CONFIG PMUX3 IO2", ok, ""},
            {"1.7.1", "CONFIG PMUX2 DIV 5", ok, ""},
            {"1.7.1", "CONFIG PMUX2 DIV 0", err, ""},
            {"1.7.1", "CONFIG MCAL START", ok, ""},
            {"1.7.1", "CONFIG USRCAL START 300", err, ""},
            {"1.7.1", "CONFIG USRCAL START 720", ok, ""},
            {"1.7.1", "CONFIG USRCAL STOP", err, ""}, // the module did not turn: calibration refused
            {"1.7.1", "SERIALCONFIG COM2 115200", ok, ""},
            {"1.7.1", "SERIALCONFIG 1200", err, ""},
            {"1.7.1", "SAVECONFIG", ok, ""},
            {"1.7.1", "FOO BAR", silent, ""},
            {"1.7.1", "CONFIG YAW 1 16", silent, ""},
            {"1.7.1", "LOG MAGCONFIG", silent, ""},
            {"1.6.6", "LOG VERSION", ok, "APP_VER=166"},
            {"1.6.6", "LOG COMCONFIG", ok, "URFR=1,0,0,0,1,0,0,0,1"},
            {"1.6.6", "LOG HI92 ONTIME 0.05", ok, ""},
            {"1.6.6", "LOG HI83 ONTIME 0.01", err, ""},
            {"1.6.6", "CONFIG YAW 1 16", ok, ""},
            {"1.6.6", "CONFIG YAW 0 1.5", ok, ""},
            {"1.6.6", "CONFIG YAW 1 200", err, ""},
            {"1.6.6", "CONFIG IMU_EN_MCAL 0", ok, ""},
            {"1.6.6", "LOG MAGCONFIG", ok, "MB=0"},
            {"1.6.6", "CONFIG IMU URFR 1,0,0,0,0,1,0,-1,0", ok, ""},
            {"1.6.6", "CONFIG IMU URFR 24", err, ""},
            {"1.6.6", "CONFIG PMUX5 IO9", ok, ""},
            {"1.6.6", "CONFIG MCAL START", silent, ""},
            {"1.6.6", "SERIALCONFIG 19200", err, ""},
        };
        int n = 0;
        for (const auto &r : rows)
            QTest::newRow(qPrintable(QStringLiteral("%1 %2 #%3").arg(r.fw, r.cmd).arg(n++)))
                << QString(r.fw) << QString(r.cmd) << r.st << QString(r.contains);
    }
    void everyCommand()
    {
        QFETCH(QString, firmware);
        QFETCH(QString, command);
        QFETCH(Status, expected);
        QFETCH(QString, mustContain);
        // One simulator and session per firmware, kept across rows.
        auto &slot = m_open[firmware];
        if (!slot.first) {
            slot.first = std::make_unique<sim::PtySimulator>(options(qPrintable(firmware)));
            QVERIFY(slot.first->start(nullptr));
            slot.second = std::make_unique<DeviceSession>();
            slot.second->open(slot.first->devicePath(), 115200);
            QVERIFY(waitConnected(*slot.second));
        }
        const auto r = send(*slot.second, command, expected == Status::Timeout ? 400 : 1000);
        QCOMPARE(r.status, expected);
        if (!mustContain.isEmpty()) {
            bool found = false;
            for (const auto &l : r.lines)
                found = found || QString::fromStdString(l).contains(mustContain);
            QVERIFY2(found, qPrintable(mustContain));
        }
        if (expected == Status::Error)
            QVERIFY(!r.errorLine.empty());
    }

    void serialConfigSwitchesBaud()
    {
        sim::PtySimulator simulator(options());
        QVERIFY(simulator.start(nullptr));
        DeviceSession session;
        session.open(simulator.devicePath(), 115200);
        QVERIFY(waitConnected(session));
        QCOMPARE(send(session, QStringLiteral("SERIALCONFIG 921600")).status, Status::Ok);
        // At the old rate the device is now unreadable.
        QCOMPARE(send(session, QStringLiteral("LOG VERSION"), 500).status, Status::Timeout);
        session.setHostBaud(921600);
        const auto r = send(session, QStringLiteral("LOG VERSION"));
        QCOMPARE(r.status, Status::Ok);
    }

    void settingsSurviveRebootOnlyWhenSaved()
    {
        sim::PtySimulator simulator(options());
        QVERIFY(simulator.start(nullptr));
        DeviceSession session;
        session.open(simulator.devicePath(), 115200);
        QVERIFY(waitConnected(session));
        auto comconfig = [&](const char *key) {
            const auto r = send(session, QStringLiteral("LOG COMCONFIG"));
            const auto it = r.values.find(key);
            return it == r.values.end() ? QString() : QString::fromStdString(it->second);
        };
        QCOMPARE(send(session, QStringLiteral("CONFIG ATT MODE 0")).status, Status::Ok);
        QCOMPARE(comconfig("ATT_MODE"), QStringLiteral("0"));
        QCOMPARE(send(session, QStringLiteral("REBOOT")).status, Status::Ok);
        QTest::qWait(600);
        QCOMPARE(comconfig("ATT_MODE"), QStringLiteral("1")); // not saved: lost
        QCOMPARE(send(session, QStringLiteral("CONFIG ATT MODE 0")).status, Status::Ok);
        QCOMPARE(send(session, QStringLiteral("SAVECONFIG")).status, Status::Ok);
        QCOMPARE(send(session, QStringLiteral("REBOOT")).status, Status::Ok);
        QTest::qWait(600);
        QCOMPARE(comconfig("ATT_MODE"), QStringLiteral("0")); // saved: kept
        QCOMPARE(send(session, QStringLiteral("FRESET")).status, Status::Ok);
        QTest::qWait(600);
        QCOMPARE(comconfig("ATT_MODE"), QStringLiteral("1")); // factory default
    }

    void logDisableStopsSamples()
    {
        sim::PtySimulator simulator(options());
        QVERIFY(simulator.start(nullptr));
        DeviceSession session;
        session.open(simulator.devicePath(), 115200);
        QVERIFY(waitConnected(session));
        QCOMPARE(send(session, QStringLiteral("LOG DISABLE")).status, Status::Ok);
        QTest::qWait(100);
        const auto before = session.store().totalAppended();
        QTest::qWait(500);
        QCOMPARE(session.store().totalAppended(), before);
        QCOMPARE(send(session, QStringLiteral("LOG HI91 ONMARK ONCE")).status, Status::Ok);
        QTRY_COMPARE(session.store().totalAppended(), before + 1);
        QCOMPARE(send(session, QStringLiteral("LOG ENABLE")).status, Status::Ok);
        QTRY_VERIFY(session.store().totalAppended() > before + 20);
    }

    void rebootIntoBootloader()
    {
        sim::PtySimulator simulator(options());
        QVERIFY(simulator.start(nullptr));
        DeviceSession session;
        session.open(simulator.devicePath(), 115200);
        QVERIFY(waitConnected(session));
        QCOMPARE(send(session, QStringLiteral("REBOOT BL")).status, Status::Ok);
        QTest::qWait(100);
        const auto before = session.store().totalAppended();
        // The bootloader ignores ASCII and sends nothing.
        QCOMPARE(send(session, QStringLiteral("LOG VERSION"), 400).status, Status::Timeout);
        QCOMPARE(session.store().totalAppended(), before);
        simulator.withDevice([](sim::HipnucSimulator &d) { d.powerCycle(); });
        QTRY_VERIFY(session.store().totalAppended() > before);
    }

    void unplugKeepsDataAndReports()
    {
        auto simulator = std::make_unique<sim::PtySimulator>(options());
        QVERIFY(simulator->start(nullptr));
        DeviceSession session;
        QSignalSpy errors(&session, &DeviceSession::errorOccurred);
        session.open(simulator->devicePath(), 115200);
        QVERIFY(waitConnected(session));
        QTRY_VERIFY(session.store().totalAppended() > 10);
        simulator.reset(); // the device disappears
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), SessionState::Disconnected, 5000);
        QVERIFY(errors.size() >= 1);
        QVERIFY(errors.at(0).at(0).toString().contains(QStringLiteral("lost")));
        const auto kept = session.store().totalAppended();
        QVERIFY(kept > 10);
        QVERIFY(session.store().latest().has_value());
        QCOMPARE(send(session, QStringLiteral("LOG VERSION")).status, Status::NotSent);
    }

    void missingPortIsReported()
    {
        DeviceSession session;
        QSignalSpy errors(&session, &DeviceSession::errorOccurred);
        session.open(QStringLiteral("/dev/imudesk-no-such-port"), 115200);
        QTRY_COMPARE(errors.size(), 1);
        QCOMPARE(session.state(), SessionState::Failed);
        QVERIFY(errors.at(0).at(0).toString().contains(QStringLiteral("not found")));
        // A command on a closed link is reported, not lost.
        QCOMPARE(send(session, QStringLiteral("LOG VERSION")).status, Status::NotSent);
    }

    void nothingAnswersAtAnyBaud()
    {
        // A silent device (bootloader: no output, ASCII ignored) fails detection with advice.
        sim::PtySimulator simulator(options());
        QVERIFY(simulator.start(nullptr));
        simulator.withDevice([](sim::HipnucSimulator &d) { d.receive(std::string_view("REBOOT BL\r\n")); });
        QTest::qWait(200);
        DeviceSession session;
        QSignalSpy errors(&session, &DeviceSession::errorOccurred);
        session.open(simulator.devicePath(), 0);
        QTRY_VERIFY_WITH_TIMEOUT(errors.size() == 1, 20000);
        QCOMPARE(session.state(), SessionState::Failed);
        QVERIFY(errors.at(0).at(0).toString().contains(QStringLiteral("No HiPNUC device")));
    }
};

QTEST_GUILESS_MAIN(TstDeviceSession)
#include "tst_device_session.moc"
