// HipnucSimulator in process, its commands: every command of the v1.7.1 and v1.6.6 manuals with
// its reply (OK / ERR / silence), persistence, resets, baud switching, the bootloader, the UART
// model and a firmware update from 1.6.6. Its output: tst_hipnuc_simulator_output.cpp; its
// motion, calibrations and faults: tst_hipnuc_simulator_motion.cpp.
#include "../common/hipnuc_sim_rig.h"
#include "../common/test_main.h"

using namespace imudesk;
using namespace imudesk::sim;
using namespace imudesk::protocol::hipnuc;
using namespace imudesk::test::hipnuc_sim;
using model::MainStatus;

class TestHipnucSimulator : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void commandReplies_data();
    void commandReplies();
    void replyBytesAreExact();
    void unknownCommandIsSilent();
    void lineEndings();
    void versionReply_data();
    void versionReply();
    void comConfigDefaults_data();
    void comConfigDefaults();
    void comConfigReflectsChanges();
    void saveRebootPersistence();
    void rebootIgnoresInputAndIsSilent();
    void factoryReset();
    void serialConfigSwitchesAfterOk();
    void serialConfigOtherPortAndLegacyList();
    void logDisableStopsFrames();
    void bootloaderPing();
    void uartDropsFramesWhenBaudTooLow();
    void uartNoDropsAtHighBaud();
    void firmwareUpdateFrom166To171();
};

// ---------------------------------------------------------------------------------------

void TestHipnucSimulator::commandReplies_data()
{
    QTest::addColumn<QString>("firmware");
    QTest::addColumn<QString>("model");
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("expected"); // OK, ERR or "-" (no reply)

    auto row = [](const char *fw, const char *model, const char *cmd, const char *expected) {
        QTest::addRow("%s %s: %s", fw, model, cmd) << fw << model << cmd << expected;
    };
    // v1.7.1, chapter 4
    const char *n = "1.7.1", *m = "HI14";
    row(n, m, "REBOOT", "OK");
    row(n, m, "REBOOT BL", "OK");
    row(n, m, "REBOOT NOW", "ERR");
    row(n, m, "SAVECONFIG", "OK");
    row(n, m, "SAVECONFIG ALL", "ERR");
    row(n, m, "FRESET", "OK");
    row(n, m, "FRESET 1", "ERR");
    row(n, m, "SERIALCONFIG 115200", "OK");
    row(n, m, "SERIALCONFIG 4800", "OK");
    row(n, m, "SERIALCONFIG 230400", "OK");
    row(n, m, "SERIALCONFIG 256000", "OK");
    row(n, m, "SERIALCONFIG 921600", "OK");
    row(n, m, "SERIALCONFIG 12345", "ERR");
    row(n, m, "SERIALCONFIG", "ERR");
    row(n, m, "SERIALCONFIG FAST", "ERR");
    row(n, m, "SERIALCONFIG COM1 460800", "OK");
    row(n, m, "SERIALCONFIG COM4 9600", "OK");
    row(n, m, "SERIALCONFIG COM5 9600", "ERR");
    row(n, m, "CONFIG ATT MODE 0", "OK");
    row(n, m, "CONFIG ATT MODE 1", "OK");
    row(n, m, "CONFIG ATT MODE 4", "OK");
    row(n, m, "CONFIG ATT MODE 2", "ERR");
    row(n, m, "CONFIG ATT MODE", "ERR");
    row(n, m, "CONFIG ATT RST 1", "OK");
    row(n, m, "CONFIG ATT RST 2", "OK");
    row(n, m, "CONFIG ATT RST 3", "OK");
    row(n, m, "CONFIG ATT RST 5", "OK");
    row(n, m, "CONFIG ATT RST 4", "ERR");
    row(n, m, "CONFIG ATT FOO 1", "ERR");
    row(n, m, "CONFIG IMU URFR 24", "OK");
    row(n, m, "CONFIG IMU URFR 024", "OK");
    row(n, m, "CONFIG IMU URFR 240", "OK");
    row(n, m, "CONFIG IMU URFR 531", "OK");
    row(n, m, "CONFIG IMU URFR 25", "ERR");
    row(n, m, "CONFIG IMU URFR 999", "ERR");
    row(n, m, "CONFIG IMU URFR=24", "ERR");
    row(n, m, "CONFIG IMU URFR 1,0,0,0,1,0,0,0,1", "ERR");
    row(n, m, "CONFIG IMU COORD 0", "OK");
    row(n, m, "CONFIG IMU COORD 4", "OK");
    row(n, m, "CONFIG IMU COORD 1", "ERR");
    row(n, m, "CONFIG IMU", "ERR");
    row(n, m, "CONFIG PMUX1 IO1", "OK");
    row(n, m, "CONFIG PMUX2 IO1", "OK");
    row(n, m, "CONFIG PMUX3 IO2", "OK");
    row(n, m, "CONFIG PMUX3 IO5", "OK");
    row(n, m, "CONFIG PMUX4 IO1", "ERR");
    row(n, m, "CONFIG PMUX1 IO6", "ERR");
    row(n, m, "CONFIG PMUX1 IO0", "ERR");
    row(n, m, "CONFIG PMUX2 DIV 1", "OK");
    row(n, m, "CONFIG PMUX2 DIV 5", "OK");
    row(n, m, "CONFIG PMUX2 DIV 1000", "OK");
    row(n, m, "CONFIG PMUX2 DIV 0", "ERR");
    row(n, m, "CONFIG PMUX2 DIV 1001", "ERR");
    row(n, m, "CONFIG PMUX1 DIV 5", "ERR");
    row(n, m, "CONFIG MCAL START", "OK");
    row(n, m, "CONFIG MCAL STOP", "ERR");
    row(n, m, "CONFIG USRCAL START 720", "OK");
    row(n, m, "CONFIG USRCAL START 1800", "OK");
    row(n, m, "CONFIG USRCAL START 700", "ERR");
    row(n, m, "CONFIG USRCAL START 1900", "ERR");
    row(n, m, "CONFIG USRCAL STOP", "ERR"); // nothing started
    row(n, m, "LOG ENABLE", "OK");
    row(n, m, "LOG DISABLE", "OK");
    row(n, m, "LOG VERSION", "OK");
    row(n, m, "LOG COMCONFIG", "OK");
    row(n, m, "LOG MCAL STAT", "OK");
    row(n, m, "LOG MCAL", "ERR");
    row(n, m, "LOG", "ERR");
    row(n, m, "LOG HI91 ONTIME 0.01", "OK");
    row(n, m, "LOG HI91 ONTIME 0.05", "OK");
    row(n, m, "LOG HI91 ONTIME 0.001", "OK");
    row(n, m, "LOG HI91 ONTIME 1", "OK");
    row(n, m, "LOG HI91 ONTIME 0", "OK");
    row(n, m, "LOG HI91 ONTIME 0.0005", "ERR");
    row(n, m, "LOG HI91 ONTIME 0.0015", "ERR");
    row(n, m, "LOG HI91 ONTIME 2", "ERR");
    row(n, m, "LOG HI91 ONTIME -1", "ERR");
    row(n, m, "LOG HI91 ONTIME", "ERR");
    row(n, m, "LOG HI91 ONMARK 1", "OK");
    row(n, m, "LOG HI91 ONMARK ONCE", "OK");
    row(n, m, "LOG HI91 ONMARK 2", "ERR");
    row(n, m, "LOG HI81 ONTIME 0.1", "OK");
    row(n, m, "LOG HI83 ONTIME 0.01", "OK");
    row(n, m, "LOG HI83 ONMARK ONCE", "OK");
    row(n, m, "LOG GGA ONTIME 1", "OK");
    row(n, m, "LOG RMC ONTIME 1", "OK");
    row(n, m, "LOG SXT ONTIME 1", "OK");
    row(n, m, "LOG HI83 MAP 0x000000FF", "OK");
    row(n, m, "LOG HI83 MAP 0x0000001F", "OK");
    row(n, m, "LOG HI83 MAP 31", "OK");
    row(n, m, "LOG HI83 MAP 0x00100000", "ERR");
    row(n, m, "LOG HI83 MAP 0", "ERR");
    row(n, m, "LOG HI83 MAP 0xZZ", "ERR");
    row(n, m, "LOG HI91 MAP 0x1F", "ERR");
    row(n, m, "LOG HI92 ONTIME 0.01", "ERR");  // not a v1.7.1 message
    row(n, m, "LOG VTG ONTIME 1", "ERR");      // unknown message
    row(n, m, "LOG COM1 HI91 ONTIME 0.02", "OK");
    row(n, m, "LOG COM2 HI91 ONTIME 0.02", "OK");
    row(n, m, "LOG COM7 HI91 ONTIME 0.02", "ERR");
    row(n, m, "log version", "OK");
    // v1.6.6-only keywords are unknown to 1.7.1: silence.
    row(n, m, "CONFIG YAW 1 16", "-");
    row(n, m, "CONFIG IMU_EN_MCAL 1", "-");
    row(n, m, "LOG MAGCONFIG", "-");
    // Unknown keywords.
    row(n, m, "HELLO", "-");
    row(n, m, "AT+INFO", "-");
    row(n, m, "CONFIG FOO 1", "-");
    row(n, m, "LOG FOO", "-");
    row(n, m, "LOG FOO BAR", "-");

    // v1.6.6, chapter 2 and 8
    n = "1.6.6";
    row(n, m, "REBOOT", "OK");
    row(n, m, "SAVECONFIG", "OK");
    row(n, m, "FRESET", "OK");
    row(n, m, "SERIALCONFIG 9600", "OK");
    row(n, m, "SERIALCONFIG 115200", "OK");
    row(n, m, "SERIALCONFIG 256000", "OK");
    row(n, m, "SERIALCONFIG 460800", "OK");
    row(n, m, "SERIALCONFIG 921600", "OK");
    row(n, m, "SERIALCONFIG 230400", "ERR"); // not in the v1.6.6 list
    row(n, m, "SERIALCONFIG 4800", "ERR");
    row(n, m, "CONFIG ATT MODE 0", "OK");
    row(n, m, "CONFIG ATT MODE 1", "OK");
    row(n, m, "CONFIG ATT MODE 4", "ERR");
    row(n, m, "CONFIG ATT RST 1", "ERR"); // v1.6.6 has 2, 3, 5 (and CONFIG YAW)
    row(n, m, "CONFIG ATT RST 2", "OK");
    row(n, m, "CONFIG ATT RST 3", "OK");
    row(n, m, "CONFIG ATT RST 5", "OK");
    row(n, m, "CONFIG YAW 1 16", "OK");
    row(n, m, "CONFIG YAW 0 1.5", "OK");
    row(n, m, "CONFIG YAW 1 -180", "OK");
    row(n, m, "CONFIG YAW 2 1", "ERR");
    row(n, m, "CONFIG YAW 1 190", "ERR");
    row(n, m, "CONFIG YAW 1", "ERR");
    row(n, m, "CONFIG IMU URFR 1,0,0,0,1,0,0,0,1", "OK");
    row(n, m, "CONFIG IMU URFR 1,0,0,0,0,1,0,-1,0", "OK");
    row(n, m, "CONFIG IMU URFR 0,0,-1,0,1,0,1,0,0", "OK");
    row(n, m, "CONFIG IMU URFR 0.7071068,-0.7071068,0,0.7071068,0.7071068,0,0,0,1", "OK");
    row(n, m, "CONFIG IMU URFR 1,0,0,0,1,0,-1,0", "ERR");    // 8 numbers (as printed in the manual)
    row(n, m, "CONFIG IMU URFR 1,0,0,0,1,0,0,0,-1", "ERR");  // reflection
    row(n, m, "CONFIG IMU URFR 2,0,0,0,1,0,0,0,1", "ERR");
    row(n, m, "CONFIG IMU URFR 24", "ERR");
    row(n, m, "CONFIG PMUX3 IO2", "OK");
    row(n, m, "CONFIG PMUX5 IO9", "OK");
    row(n, m, "CONFIG PMUX6 IO1", "ERR");
    row(n, m, "CONFIG PMUX1 IO10", "ERR");
    row(n, m, "CONFIG PMUX2 DIV 5", "ERR");
    row(n, m, "CONFIG IMU_EN_MCAL 0", "OK");
    row(n, m, "CONFIG IMU_EN_MCAL 1", "OK");
    row(n, m, "CONFIG IMU_EN_MCAL 2", "ERR");
    row(n, m, "CONFIG USRCAL START 720", "OK");
    row(n, m, "CONFIG USRCAL STOP", "ERR");
    row(n, m, "LOG ENABLE", "OK");
    row(n, m, "LOG DISABLE", "OK");
    row(n, m, "LOG VERSION", "OK");
    row(n, m, "LOG COMCONFIG", "OK");
    row(n, m, "LOG MAGCONFIG", "OK");
    row(n, m, "LOG HI91 ONTIME 0.01", "OK");
    row(n, m, "LOG HI92 ONTIME 0.05", "OK");
    row(n, m, "LOG HI92 ONTIME 0.002", "OK");
    row(n, m, "LOG HI91 ONMARK 1", "OK");
    row(n, m, "LOG HI92 ONMARK ONCE", "OK");
    row(n, m, "LOG HI81 ONTIME 0.1", "ERR");
    row(n, m, "LOG HI83 ONTIME 0.1", "ERR");
    row(n, m, "LOG HI83 MAP 0xFF", "ERR");
    row(n, m, "LOG GGA ONTIME 1", "ERR");
    // v1.7.x-only keywords are unknown to 1.6.6: silence.
    row(n, m, "CONFIG IMU COORD 4", "-");
    row(n, m, "CONFIG MCAL START", "-");
    row(n, m, "LOG MCAL STAT", "-");
    row(n, m, "AT+EOUT=0", "-");

    // Model gates (v1.7.1 chapter 3)
    n = "1.7.1";
    row(n, "HI02", "CONFIG ATT MODE 1", "ERR");
    row(n, "HI02", "CONFIG ATT MODE 0", "OK");
    row(n, "HI02", "CONFIG ATT RST 2", "ERR");
    row(n, "HI02", "CONFIG PMUX3 IO2", "ERR");
    row(n, "HI02", "CONFIG MCAL START", "ERR");
    row(n, "HI02", "CONFIG USRCAL START 720", "OK");
    row(n, "HI50", "CONFIG ATT MODE 1", "ERR");
    row(n, "HI50", "CONFIG ATT RST 2", "OK");
    row(n, "HI50", "CONFIG PMUX3 IO2", "ERR");
    row(n, "HI50", "CONFIG MCAL START", "ERR");
    row(n, "HI92", "CONFIG ATT MODE 1", "OK");
    row(n, "HI92", "CONFIG PMUX3 IO2", "ERR");
    row(n, "HI05", "CONFIG PMUX3 IO2", "OK");
    row(n, "CH040", "CONFIG PMUX3 IO2", "OK");
    // MCAL needs >= 1.7.0, which still uses the v1.6.6 command set otherwise.
    row("1.7.0", m, "CONFIG MCAL START", "OK");
    row("1.7.0", m, "LOG MCAL STAT", "OK");
    row("1.7.0", m, "CONFIG YAW 1 10", "OK");
}

void TestHipnucSimulator::commandReplies()
{
    QFETCH(QString, firmware);
    QFETCH(QString, model);
    QFETCH(QString, command);
    QFETCH(QString, expected);
    Rig rig(opts(firmware.toStdString(), model.toStdString()));
    rig.run(200000);
    const AsciiReply r = rig.command(command.toStdString(), 200000);
    QCOMPARE(QString::fromStdString(outcome(r)), expected);
    if (expected == "-")
        QVERIFY2(rig.last.lines.empty(), rig.last.lines.empty() ? "" : rig.last.lines.front().c_str()); // not even a stray line
    if (QString::fromStdString(outcome(r)) != expected)
        for (const auto &l : rig.last.lines)
            qWarning("line: %s", l.c_str());
    if (expected == "ERR")
        QCOMPARE(QString::fromStdString(r.errorLine), QStringLiteral("ERR"));
}

void TestHipnucSimulator::replyBytesAreExact()
{
    Rig rig;
    rig.quiet();
    QCOMPARE(QString::fromStdString(rig.send("SAVECONFIG").text()), QStringLiteral("OK\r\n"));
    QCOMPARE(QString::fromStdString(rig.send("CONFIG ATT MODE 7").text()), QStringLiteral("ERR\r\n"));
    QCOMPARE(QString::fromStdString(rig.send("LOG MCAL STAT").text()), QStringLiteral("STAT=0\r\nPROGRESS=0\r\nOK\r\n"));
    const std::string version = rig.send("LOG VERSION").text();
    QCOMPARE(QString::fromStdString(version),
             QString::fromStdString("PNAME=HI14R3\r\nBUILD=Oct 15 2024\r\nUUID=" + rig.sim.uuid()
                                    + "\r\nAPP_VER=171\r\nBL_VER=109\r\nOK\r\n"));
    // ONMARK ONCE while output is disabled: OK first, then exactly one HI91 frame.
    const Capture once = rig.send("LOG HI91 ONMARK ONCE");
    QCOMPARE(once.raw.size(), size_t(4 + 82));
    QCOMPARE(std::string(once.raw.begin(), once.raw.begin() + 4), std::string("OK\r\n"));
    QCOMPARE(once.countTag(TagHi91), 1);
}

void TestHipnucSimulator::unknownCommandIsSilent()
{
    Rig rig;
    rig.quiet();
    for (const char *c : {"HELLO", "CONFIG YAW 1 16", "LOG MAGCONFIG", "AT+INFO", "XYZ 1 2 3"}) {
        const Capture cap = rig.send(c, 1000000);
        QVERIFY2(cap.raw.empty(), c);
    }
    // The device still answers afterwards.
    QVERIFY(rig.ok("LOG VERSION"));
}

void TestHipnucSimulator::lineEndings()
{
    Rig rig;
    rig.quiet();
    rig.sim.receive("LOG VERSION\n");
    QVERIFY(rig.run(50000).text().find("APP_VER=171\r\nBL_VER=109\r\nOK\r\n") != std::string::npos);
    // Split over several receive calls.
    rig.sim.receive("SAVE");
    rig.run(10000);
    rig.sim.receive("CONFIG\r");
    QVERIFY(rig.run(10000).raw.empty());
    rig.sim.receive("\n");
    QCOMPARE(QString::fromStdString(rig.run(10000).text()), QStringLiteral("OK\r\n"));
    // Blank lines and extra spaces.
    rig.sim.receive("\r\n\r\n");
    QVERIFY(rig.run(50000).raw.empty());
    QCOMPARE(QString::fromStdString(rig.send("  LOG   HI91  ONTIME   0.02 ").text()), QStringLiteral("OK\r\n"));
    QCOMPARE(rig.sim.runningConfig().message(Message::HI91).periodMs, 20);
    // An over-long line is discarded entirely; the next line works.
    rig.sim.receive(std::string(400, 'A') + "\r\n");
    QVERIFY(rig.run(50000).raw.empty());
    QVERIFY(rig.ok("SAVECONFIG"));
}

void TestHipnucSimulator::versionReply_data()
{
    QTest::addColumn<QString>("firmware");
    QTest::addColumn<QString>("model");
    QTest::addColumn<QString>("appVer");
    QTest::newRow("HI14 1.7.1") << "1.7.1" << "HI14" << "171";
    QTest::newRow("HI14 1.6.6") << "1.6.6" << "HI14" << "166";
    QTest::newRow("CH0x0 1.5.6") << "156" << "CH040" << "156";
    QTest::newRow("HI02 1.7.2") << "v1.7.2" << "HI02" << "172";
    QTest::newRow("HI12R2 1.7.1") << "1.7.1" << "HI12R2" << "171";
}

void TestHipnucSimulator::versionReply()
{
    QFETCH(QString, firmware);
    QFETCH(QString, model);
    QFETCH(QString, appVer);
    Rig rig(opts(firmware.toStdString(), model.toStdString()));
    const AsciiReply r = rig.command("LOG VERSION");
    QVERIFY(r.ok());
    QCOMPARE(r.lines.size(), size_t(5));
    QCOMPARE(QString::fromStdString(r.values.at("PNAME")), model.contains('R') ? model : model + "R3");
    QCOMPARE(QString::fromStdString(r.values.at("BUILD")), QStringLiteral("Oct 15 2024"));
    QCOMPARE(QString::fromStdString(r.values.at("APP_VER")), appVer);
    QCOMPARE(QString::fromStdString(r.values.at("BL_VER")), QStringLiteral("109"));
    const std::string uuid = r.values.at("UUID");
    QCOMPARE(uuid.size(), size_t(16));
    for (char c : uuid)
        QVERIFY((c >= '0' && c <= '9') || (c >= 'A' && c <= 'F'));
    const auto id = model::DeviceIdentity::fromKeyValues(r.values);
    QVERIFY(id.usable());
    QCOMPARE(QStringLiteral("%1%2%3").arg(id.firmware->major).arg(id.firmware->minor).arg(id.firmware->patch), appVer);
    QCOMPARE(id.family(), model::familyOfProduct(model.toStdString()));
    // The UUID follows the seed.
    SimOptions o = opts(firmware.toStdString(), model.toStdString());
    QCOMPARE(HipnucSimulator(o).uuid(), uuid);
    o.seed = 2;
    QVERIFY(HipnucSimulator(o).uuid() != uuid);
}

void TestHipnucSimulator::comConfigDefaults_data()
{
    QTest::addColumn<QString>("firmware");
    QTest::addColumn<QString>("model");
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("HI14 1.7.1") << "1.7.1" << "HI14"
                                << QStringList{"BAUD=115200",    "LOG=ENABLE",   "HI91=ONTIME 0.01", "HI81=OFF",
                                               "HI83=OFF",       "GGA=OFF",      "RMC=OFF",          "SXT=OFF",
                                               "HI83_MAP=0x000000FF", "ATT_MODE=1", "URFR=24",       "COORD=0",
                                               "PMUX1=IO1",      "PMUX2=IO2",    "PMUX3=IO5",        "PMUX2_DIV=1"};
    QTest::newRow("HI14 1.6.6") << "1.6.6" << "HI14"
                                << QStringList{"BAUD=115200", "LOG=ENABLE", "HI91=ONTIME 0.01", "HI92=OFF", "ATT_MODE=1",
                                               "URFR=1,0,0,0,1,0,0,0,1", "PMUX1=IO1", "PMUX2=IO2", "PMUX3=IO5",
                                               "IMU_EN_MCAL=1"};
    QTest::newRow("HI02 1.7.1") << "1.7.1" << "HI02"
                                << QStringList{"BAUD=115200", "LOG=ENABLE", "HI91=ONTIME 0.01", "HI81=OFF", "HI83=OFF",
                                               "GGA=OFF", "RMC=OFF", "SXT=OFF", "HI83_MAP=0x000000FF", "ATT_MODE=0",
                                               "URFR=24", "COORD=0"};
}

void TestHipnucSimulator::comConfigDefaults()
{
    QFETCH(QString, firmware);
    QFETCH(QString, model);
    QFETCH(QStringList, expected);
    Rig rig(opts(firmware.toStdString(), model.toStdString()));
    const AsciiReply r = rig.command("LOG COMCONFIG");
    QVERIFY(r.ok());
    QStringList got;
    for (const auto &l : r.lines)
        got << QString::fromStdString(l);
    QCOMPARE(got, expected);
}

void TestHipnucSimulator::comConfigReflectsChanges()
{
    Rig rig(opts("1.7.1", "HI14", Motion::Static, 921600)); // 200 Hz HI91 needs more than 115200
    for (const char *c : {"LOG HI91 ONTIME 0.005", "LOG HI83 ONMARK 1", "LOG GGA ONTIME 1", "LOG HI83 MAP 0x1F",
                          "CONFIG ATT MODE 0", "CONFIG IMU URFR 531", "CONFIG IMU COORD 4", "CONFIG PMUX3 IO2",
                          "CONFIG PMUX2 DIV 20", "LOG DISABLE"})
        QVERIFY2(rig.ok(c), c);
    const AsciiReply r = rig.command("LOG COMCONFIG");
    QVERIFY(r.ok());
    const std::map<std::string, std::string> want = {
        {"BAUD", "921600"}, {"LOG", "DISABLE"}, {"HI91", "ONTIME 0.005"}, {"HI83", "ONMARK 1"}, {"GGA", "ONTIME 1"},
        {"HI83_MAP", "0x0000001F"}, {"ATT_MODE", "0"}, {"URFR", "531"}, {"COORD", "4"}, {"PMUX3", "IO2"},
        {"PMUX2_DIV", "20"}, {"HI81", "OFF"}};
    for (const auto &[k, v] : want)
        QCOMPARE(QString::fromStdString(r.values.at(k)), QString::fromStdString(v));
    // v1.6.6 matrix form
    Rig legacy(opts("1.6.6"));
    QVERIFY(legacy.ok("CONFIG IMU URFR 1,0,0,0,0,1,0,-1,0"));
    QVERIFY(legacy.ok("CONFIG IMU_EN_MCAL 0"));
    const AsciiReply l = legacy.command("LOG COMCONFIG");
    QCOMPARE(QString::fromStdString(l.values.at("URFR")), QStringLiteral("1,0,0,0,0,1,0,-1,0"));
    QCOMPARE(QString::fromStdString(l.values.at("IMU_EN_MCAL")), QStringLiteral("0"));
}

void TestHipnucSimulator::saveRebootPersistence()
{
    Rig rig;
    QVERIFY(rig.ok("LOG HI91 ONTIME 0.02"));
    QVERIFY(rig.ok("CONFIG ATT MODE 0"));
    QVERIFY(rig.ok("CONFIG IMU URFR 240"));
    QVERIFY(rig.ok("SAVECONFIG"));
    QCOMPARE(rig.sim.savedConfig(), rig.sim.runningConfig());
    // Unsaved changes.
    QVERIFY(rig.ok("LOG HI91 ONTIME 0.05"));
    QVERIFY(rig.ok("CONFIG IMU COORD 4"));
    QVERIFY(rig.ok("LOG DISABLE"));
    QVERIFY(!(rig.sim.savedConfig() == rig.sim.runningConfig()));
    const HipnucSimulator::Config saved = rig.sim.savedConfig();

    QVERIFY(rig.ok("REBOOT", 350000));
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::App);
    QCOMPARE(rig.sim.runningConfig(), saved);
    QCOMPARE(rig.sim.activeConfig(), saved);
    QVERIFY(rig.sim.logEnabled()); // LOG DISABLE is not saved
    QCOMPARE(rig.sim.runningConfig().message(Message::HI91).periodMs, 20);
    QCOMPARE(rig.sim.runningConfig().coord, 0);
    QCOMPARE(rig.sim.runningConfig().urfrCode, 240);
    QCOMPARE(rig.sim.runningConfig().attMode, 0);
    // Output restarts at the saved 50 Hz with system_time from the restart.
    rig.run(200000);
    const Capture c = rig.run(1000000);
    QVERIFY(std::abs(c.countTag(TagHi91) - 50) <= 1);
    const auto frames = c.packets<Hi91>();
    QVERIFY(frames.front().systemTime < 1300);
    QCOMPARE(frames.back().systemTime - frames.front().systemTime, uint32_t(20 * (frames.size() - 1)));
    QCOMPARE(frames.back().mainStatus & bit(MainStatus::MagAiding), 0); // mode 0 now active
}

void TestHipnucSimulator::rebootIgnoresInputAndIsSilent()
{
    Rig rig;
    rig.run(108000); // the frame due at 100 ms is out
    rig.sim.receive("REBOOT\r\n");
    const Capture ok = rig.run(2000);
    QCOMPARE(QString::fromStdString(ok.text()), QStringLiteral("OK\r\n"));
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::Rebooting);
    rig.sim.receive("LOG VERSION\r\n"); // lost: the MCU is resetting
    const Capture during = rig.run(280000);
    QVERIFY(during.raw.empty());
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::Rebooting);
    rig.run(30000);
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::App);
    const Capture after = rig.run(500000);
    QVERIFY(after.lines.empty()); // the LOG VERSION sent during the reset got no reply
    QVERIFY(after.countTag(TagHi91) >= 49);
    QVERIFY(rig.sim.systemTimeMs() >= 500 && rig.sim.systemTimeMs() < 600);
}

void TestHipnucSimulator::factoryReset()
{
    Rig rig;
    QVERIFY(rig.ok("LOG HI91 ONTIME 0.05"));
    QVERIFY(rig.ok("LOG HI83 ONTIME 0.1"));
    QVERIFY(rig.ok("CONFIG ATT MODE 0"));
    QVERIFY(rig.ok("CONFIG PMUX2 DIV 7"));
    QVERIFY(rig.ok("CONFIG ATT RST 3"));
    QVERIFY(rig.ok("SERIALCONFIG 460800"));
    QVERIFY(rig.ok("SAVECONFIG"));
    QVERIFY(rig.ok("REBOOT", 400000));
    QCOMPARE(rig.sim.baud(), 460800);
    QCOMPARE(rig.sim.runningConfig().attMode, 0);

    QVERIFY(rig.ok("FRESET", 10000));
    QCOMPARE(rig.sim.savedConfig(), rig.sim.factoryConfig());
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::Rebooting);
    rig.run(400000);
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::App);
    QCOMPARE(rig.sim.runningConfig(), rig.sim.factoryConfig());
    QCOMPARE(rig.sim.baud(), 115200);
    const auto &f = rig.sim.factoryConfig();
    QCOMPARE(f.message(Message::HI91).periodMs, 10);
    QCOMPARE(f.message(Message::HI83).mode, HipnucSimulator::MessageSetting::Mode::Off);
    QCOMPARE(f.attMode, 1);
    QCOMPARE(f.urfrCode, 24);
    QCOMPARE(f.coord, 0);
    QCOMPARE(f.pmux2Div, 1);
    QCOMPARE(f.hi83Map, 0xFFu);
    QCOMPARE(f.pmux[0], 1);
    QCOMPARE(f.pmux[1], 2);
    QCOMPARE(f.pmux[2], 5);
    rig.run(200000);
    const Capture c = rig.run(1000000);
    QVERIFY(std::abs(c.countTag(TagHi91) - 100) <= 1);
    QCOMPARE(c.countTag(TagHi83), 0);
    // The level correction (ATT RST 3) is gone: the static tilt is back.
    const auto frames = c.packets<Hi91>();
    QVERIFY(std::fabs(frames.back().roll - MotionModel::kStaticRollDeg) < 0.01);
    // HI02 factory mode is 6-axis.
    Rig hi02(opts("1.7.1", "HI02"));
    QCOMPARE(hi02.sim.factoryConfig().attMode, 0);
}

void TestHipnucSimulator::serialConfigSwitchesAfterOk()
{
    Rig rig;
    rig.run(108000); // between two frames
    rig.sim.takeOutputSegments();
    rig.sim.receive("SERIALCONFIG 460800\r\n");
    QCOMPARE(rig.sim.baud(), 460800); // at once, after the OK was queued
    QCOMPARE(rig.sim.runningConfig().baud, 460800);
    QCOMPARE(rig.sim.savedConfig().baud, 115200);
    rig.sim.advanceTo(rig.sim.nowUs() + 200000);
    const auto segs = rig.sim.takeOutputSegments();
    bool sawOk = false;
    int framesAfter = 0;
    QVERIFY(!segs.empty());
    QVERIFY(!segs.front().data); // nothing was being sent: the OK comes first
    for (const auto &s : segs) {
        if (!s.data) {
            QCOMPARE(std::string(s.bytes.begin(), s.bytes.end()), std::string("OK\r\n"));
            QCOMPARE(s.baud, 115200); // the OK goes out at the old baud
            sawOk = true;
        } else {
            QCOMPARE(s.baud, 460800);
            framesAfter += s.chunkStart;
        }
    }
    QVERIFY(sawOk);
    QVERIFY(framesAfter >= 19);
    // Not saved: a reboot returns to 115200; saved: it stays.
    QVERIFY(rig.ok("REBOOT", 400000));
    QCOMPARE(rig.sim.baud(), 115200);
    QVERIFY(rig.ok("SERIALCONFIG 921600"));
    QVERIFY(rig.ok("SAVECONFIG"));
    QVERIFY(rig.ok("REBOOT", 400000));
    QCOMPARE(rig.sim.baud(), 921600);
    QCOMPARE(rig.sim.savedConfig().baud, 921600);
}

void TestHipnucSimulator::serialConfigOtherPortAndLegacyList()
{
    Rig rig;
    QVERIFY(rig.ok("SERIALCONFIG COM2 9600"));
    QCOMPARE(rig.sim.baud(), 115200);
    QVERIFY(rig.ok("SERIALCONFIG COM1 230400"));
    QCOMPARE(rig.sim.baud(), 230400);
    Rig legacy(opts("1.6.6"));
    QVERIFY(!legacy.ok("SERIALCONFIG 230400"));
    QCOMPARE(legacy.sim.baud(), 115200);
    QVERIFY(legacy.ok("SERIALCONFIG 256000"));
    QCOMPARE(legacy.sim.baud(), 256000);
    // Bytes take 10 bit times: 1 s at 256000 carries at most 25600 bytes: 200 HI91 frames fit.
    QVERIFY(legacy.ok("LOG HI91 ONTIME 0.005"));
    legacy.run(100000);
    const Capture c = legacy.run(1000000);
    QVERIFY(c.raw.size() <= 25600);
    QVERIFY(std::abs(c.countTag(TagHi91) - 200) <= 1);
    QCOMPARE(legacy.sim.droppedFrames(), uint64_t(0));
}

void TestHipnucSimulator::logDisableStopsFrames()
{
    Rig rig;
    QVERIFY(rig.run(500000).countTag(TagHi91) >= 49);
    QVERIFY(rig.ok("LOG DISABLE", 20000));
    QVERIFY(!rig.sim.logEnabled());
    const Capture off = rig.run(1000000);
    QCOMPARE(off.frames.size(), size_t(0));
    QVERIFY(off.raw.empty());
    QVERIFY(rig.ok("LOG ENABLE", 20000));
    QVERIFY(std::abs(rig.run(1000000).countTag(TagHi91) - 100) <= 1);
}

void TestHipnucSimulator::bootloaderPing()
{
    Rig rig;
    rig.run(108000);
    rig.sim.receive("REBOOT BL\r\n");
    const Capture ok = rig.run(5000);
    QCOMPARE(ok.lines, std::vector<std::string>{"OK"});
    rig.run(50000);
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::Bootloader);
    QCOMPARE(rig.sim.baud(), 115200); // the bootloader runs at the application's baud
    // No output, ASCII ignored.
    QVERIFY(rig.run(500000).raw.empty());
    rig.sim.receive("LOG VERSION\r\nREBOOT\r\n");
    QVERIFY(rig.run(500000).raw.empty());
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::Bootloader);
    // KBOOT ping.
    const uint8_t ping[] = {0x5A, 0xA6};
    rig.sim.receive(ping, 2);
    const std::vector<uint8_t> resp = rig.run(10000).raw;
    const std::vector<uint8_t> want = {0x5A, 0xA7, 0x00, 0x00, 0x02, 0x50, 0x00, 0x00, 0xF5, 0x35};
    QCOMPARE(resp, want);
    QCOMPARE(crc16(want.data(), 8), uint16_t(0x35F5));
    // Split across two reads, after garbage.
    rig.sim.receive(ping, 1);
    rig.sim.receive(ping + 1, 1);
    QCOMPARE(rig.run(10000).raw, want);
    // Power cycle: back to the application.
    rig.sim.powerCycle();
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::App);
    QVERIFY(rig.ok("LOG VERSION"));
    QVERIFY(rig.run(200000).countTag(TagHi91) >= 19);
}

void TestHipnucSimulator::uartDropsFramesWhenBaudTooLow()
{
    Rig rig;
    QVERIFY(rig.ok("LOG HI91 ONTIME 0.001", 10000));
    rig.run(1000000);
    QVERIFY(rig.sim.droppedFrames() > 500);
    QVERIFY(rig.sim.txQueuedBytes() <= HipnucSimulator::kTxBufferSize);
    const uint64_t droppedBefore = rig.sim.droppedFrames();
    const Capture c = rig.run(1000000);
    // 115200 baud = 11520 bytes/s = about 140 HI91 frames per second.
    const int n = c.countTag(TagHi91);
    QVERIFY2(n >= 138 && n <= 142, qPrintable(QString::number(n)));
    QVERIFY(c.raw.size() <= 11521);
    QVERIFY(std::abs(int(rig.sim.droppedFrames() - droppedBefore) - (1000 - n)) <= 1);
    // Every frame that went out is intact.
    QCOMPARE(rig.demux.frameCounters().crcErrors, uint64_t(0));
    const auto f = c.packets<Hi91>();
    for (size_t i = 1; i < f.size(); ++i)
        QVERIFY(f[i].systemTime > f[i - 1].systemTime);
    // Replies still get through.
    QVERIFY(rig.ok("LOG VERSION", 500000));
}

void TestHipnucSimulator::uartNoDropsAtHighBaud()
{
    Rig rig(opts("1.7.1", "HI14", Motion::Static, 921600));
    QVERIFY(rig.ok("LOG HI91 ONTIME 0.001", 10000));
    rig.run(500000);
    const Capture c = rig.run(1000000);
    QVERIFY(std::abs(c.countTag(TagHi91) - 1000) <= 1);
    QCOMPARE(rig.sim.droppedFrames(), uint64_t(0));
}

// An old module updated over KBOOT becomes the new firmware: its LOG VERSION and its command set.
void TestHipnucSimulator::firmwareUpdateFrom166To171()
{
    Rig rig(opts("1.6.6"));
    AsciiReply v = rig.command("LOG VERSION");
    QVERIFY(v.ok());
    QCOMPARE(v.values.at("APP_VER"), std::string("166"));
    QCOMPARE(outcome(rig.command("CONFIG IMU COORD 4")), std::string("-")); // not on 1.6.6
    protocol::ihex::FirmwareImage img;
    img.startAddress = 0x8000;
    img.data = KbootBootloader::makeApplication("1.7.1", 72 * 1024, 5);
    sim::SimulatedByteLink link(rig.sim);
    firmware::UpdateFlow flow(link, firmware::UpdateFlow::Options{}, {});
    const auto r = flow.run(img);
    QVERIFY2(r.ok, qPrintable(r.message));
    QVERIFY(r.before && r.after);
    QCOMPARE(r.before->firmware->toString(), std::string("1.6.6"));
    QCOMPARE(r.after->firmware->toString(), std::string("1.7.1"));
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::App);
    QCOMPARE(rig.sim.firmware().toString(), std::string("1.7.1"));
    QCOMPARE(rig.sim.edition(), model::ManualEdition::V171);
    rig.run(100000);
    rig.collect();
    v = rig.command("LOG VERSION");
    QVERIFY(v.ok());
    QCOMPARE(v.values.at("APP_VER"), std::string("171"));
    // The v1.7.1 command set, and none of the v1.6.6 words.
    QCOMPARE(outcome(rig.command("CONFIG IMU COORD 4")), std::string("OK"));
    QCOMPARE(outcome(rig.command("LOG HI81 ONTIME 0.1")), std::string("OK"));
    QCOMPARE(outcome(rig.command("LOG MCAL STAT")), std::string("OK"));
    QCOMPARE(outcome(rig.command("LOG HI92 ONTIME 0.1")), std::string("ERR"));
    QCOMPARE(outcome(rig.command("CONFIG IMU_EN_MCAL 1")), std::string("-"));
    QCOMPARE(outcome(rig.command("LOG MAGCONFIG")), std::string("-"));
    // It stays 1.7.1 after a power cycle (taken with the line idle: no frame cut in half).
    rig.quiet();
    rig.sim.powerCycle();
    v = rig.command("LOG VERSION");
    QVERIFY(v.ok());
    QCOMPARE(v.values.at("APP_VER"), std::string("171"));
}

IMUDESK_TEST_GUILESS_MAIN(TestHipnucSimulator)
#include "tst_hipnuc_simulator.moc"
