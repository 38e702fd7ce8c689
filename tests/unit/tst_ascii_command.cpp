// Command builders: every command of both manuals, with their ranges.
#include "model/mounting.h"
#include "protocol/hipnuc/ascii_command.h"
#include "../common/test_main.h"

#include <QTest>

using namespace imudesk::protocol::hipnuc;
using imudesk::model::Mounting;

Q_DECLARE_METATYPE(Command)

class TstAsciiCommand : public QObject {
    Q_OBJECT
private Q_SLOTS:
    // The output effect a command carries (the lost-frame counter follows it): from the typed
    // builders, and read from the words of text a user typed.
    void outputEffect_data()
    {
        QTest::addColumn<Command>("cmd");
        QTest::addColumn<bool>("changes");
        QTest::addColumn<bool>("thisPort");
        QTest::addColumn<QString>("message");
        QTest::addColumn<double>("period");
        namespace c = commands;
        QTest::newRow("builder ontime") << c::logOnTime(Message::HI91, 0.01) << true << true << "HI91" << 0.01;
        QTest::newRow("builder onmark") << c::logOnMark(Message::HI83, true) << true << true << "HI83" << -1.0;
        QTest::newRow("builder map") << c::logHi83Map(0x1) << true << true << "HI83" << -1.0;
        QTest::newRow("builder reboot") << c::reboot() << true << true << "" << -1.0;
        QTest::newRow("builder serial") << c::serialConfig(921600) << true << true << "" << -1.0;
        QTest::newRow("builder version") << c::logVersion() << false << true << "" << -1.0;
        QTest::newRow("builder save") << c::saveConfig() << false << true << "" << -1.0;
        QTest::newRow("typed ontime") << c::typed("  log hi92 ontime 0.005 ") << true << true << "HI92" << 0.005;
        QTest::newRow("typed other port") << c::typed("LOG COM2 HI91 ONTIME 0.1") << true << false << "HI91" << 0.1;
        QTest::newRow("typed disable") << c::typed("LOG DISABLE") << true << true << "" << -1.0;
        QTest::newRow("typed query") << c::typed("LOG MCAL STAT") << false << true << "" << -1.0;
        QTest::newRow("typed freset") << c::typed("freset") << true << true << "" << -1.0;
        QTest::newRow("typed config") << c::typed("CONFIG ATT MODE 1") << false << true << "" << -1.0;
        QTest::newRow("typed bad period") << c::typed("LOG HI91 ONTIME 0,01") << true << true << "HI91" << -1.0;
    }
    void outputEffect()
    {
        QFETCH(Command, cmd);
        QFETCH(bool, changes);
        QFETCH(bool, thisPort);
        QFETCH(QString, message);
        QFETCH(double, period);
        QVERIFY(cmd.ok());
        QCOMPARE(cmd.effect.changesOutput, changes);
        QCOMPARE(cmd.effect.thisPort, thisPort);
        QCOMPARE(QString::fromStdString(cmd.effect.message), message);
        QCOMPARE(cmd.effect.periodS, period);
    }
    void typedKeepsTheText()
    {
        QCOMPARE(QString::fromStdString(commands::typed("  log hi92 ontime 0.005 \r\n").text),
                 QStringLiteral("log hi92 ontime 0.005"));
    }

    void valid_data()
    {
        QTest::addColumn<Command>("cmd");
        QTest::addColumn<QString>("text");
        namespace c = commands;
        QTest::newRow("reboot") << c::reboot() << "REBOOT";
        QTest::newRow("reboot bl") << c::rebootBootloader() << "REBOOT BL";
        QTest::newRow("save") << c::saveConfig() << "SAVECONFIG";
        QTest::newRow("freset") << c::factoryReset() << "FRESET";
        QTest::newRow("serial") << c::serialConfig(921600) << "SERIALCONFIG 921600";
        QTest::newRow("serial v1.6.6") << c::serialConfig(256000, imudesk::model::ManualEdition::V166)
                                       << "SERIALCONFIG 256000";
        QTest::newRow("serial com2") << c::serialConfig(2, 256000) << "SERIALCONFIG COM2 256000";
        QTest::newRow("vru") << c::attMode(0) << "CONFIG ATT MODE 0";
        QTest::newRow("ahrs") << c::attMode(1) << "CONFIG ATT MODE 1";
        QTest::newRow("humanoid") << c::attMode(4) << "CONFIG ATT MODE 4";
        QTest::newRow("heading rst") << c::attReset(1) << "CONFIG ATT RST 1";
        QTest::newRow("rel zero") << c::attReset(2) << "CONFIG ATT RST 2";
        QTest::newRow("auto level") << c::attReset(3) << "CONFIG ATT RST 3";
        QTest::newRow("cancel level") << c::attReset(5) << "CONFIG ATT RST 5";
        QTest::newRow("urfr 24") << c::imuUrfr(24) << "CONFIG IMU URFR 24";
        QTest::newRow("urfr 531") << c::imuUrfr(531) << "CONFIG IMU URFR 531";
        QTest::newRow("urfr matrix") << c::imuUrfrMatrix(Mounting::identity()) << "CONFIG IMU URFR 1,0,0,0,1,0,0,0,1";
        QTest::newRow("urfr matrix x-90")
            << c::imuUrfrMatrix({{{1, 0, 0}, {0, 0, 1}, {0, -1, 0}}}) << "CONFIG IMU URFR 1,0,0,0,0,1,0,-1,0";
        QTest::newRow("coord enu") << c::imuCoord(0) << "CONFIG IMU COORD 0";
        QTest::newRow("coord nwu") << c::imuCoord(4) << "CONFIG IMU COORD 4";
        QTest::newRow("pmux") << c::pmux(3, 2) << "CONFIG PMUX3 IO2";
        QTest::newRow("pmux legacy") << c::pmux(5, 9, true) << "CONFIG PMUX5 IO9";
        QTest::newRow("div") << c::pmux2Div(5) << "CONFIG PMUX2 DIV 5";
        QTest::newRow("mcal") << c::magCalStart() << "CONFIG MCAL START";
        QTest::newRow("usrcal") << c::gyroCalStart(720) << "CONFIG USRCAL START 720";
        QTest::newRow("usrcal stop") << c::gyroCalStop() << "CONFIG USRCAL STOP";
        QTest::newRow("yaw abs") << c::setYaw(1, 16) << "CONFIG YAW 1 16";
        QTest::newRow("yaw rel") << c::setYaw(0, 1.5) << "CONFIG YAW 0 1.5";
        QTest::newRow("en mcal") << c::enableBackgroundMagCal(false) << "CONFIG IMU_EN_MCAL 0";
        QTest::newRow("log enable") << c::logEnable() << "LOG ENABLE";
        QTest::newRow("log disable") << c::logDisable() << "LOG DISABLE";
        QTest::newRow("version") << c::logVersion() << "LOG VERSION";
        QTest::newRow("comconfig") << c::logComConfig() << "LOG COMCONFIG";
        QTest::newRow("magconfig") << c::logMagConfig() << "LOG MAGCONFIG";
        QTest::newRow("mcal stat") << c::logMagCalStatus() << "LOG MCAL STAT";
        QTest::newRow("ontime 100Hz") << c::logOnTime(Message::HI91, 0.01) << "LOG HI91 ONTIME 0.01";
        QTest::newRow("ontime 1kHz") << c::logOnTime(Message::HI83, 0.001) << "LOG HI83 ONTIME 0.001";
        QTest::newRow("ontime off") << c::logOnTime(Message::GGA, 0) << "LOG GGA ONTIME 0";
        QTest::newRow("ontime 1Hz") << c::logOnTime(Message::SXT, 1) << "LOG SXT ONTIME 1";
        QTest::newRow("ontime 20Hz") << c::logOnTime(Message::HI92, 0.05) << "LOG HI92 ONTIME 0.05";
        QTest::newRow("onmark") << c::logOnMark(Message::HI91, false) << "LOG HI91 ONMARK 1";
        QTest::newRow("onmark once") << c::logOnMark(Message::RMC, true) << "LOG RMC ONMARK ONCE";
        QTest::newRow("hi83 map") << c::logHi83Map(0xFF) << "LOG HI83 MAP 0x000000FF";
    }
    void valid()
    {
        QFETCH(Command, cmd);
        QFETCH(QString, text);
        QVERIFY2(cmd.ok(), cmd.error.c_str());
        QCOMPARE(QString::fromStdString(cmd.text), text);
        QCOMPARE(QString::fromStdString(cmd.wire()), text + "\r\n");
    }

    void refused_data()
    {
        QTest::addColumn<Command>("cmd");
        namespace c = commands;
        QTest::newRow("baud 1200") << c::serialConfig(1200);
        QTest::newRow("v1.6.6 has no 19200")
            << c::serialConfig(19200, imudesk::model::ManualEdition::V166);
        QTest::newRow("com5") << c::serialConfig(5, 115200);
        QTest::newRow("mode 2") << c::attMode(2);
        QTest::newRow("rst 4") << c::attReset(4);
        QTest::newRow("urfr left-handed 25") << c::imuUrfr(25);
        QTest::newRow("urfr 999") << c::imuUrfr(999);
        QTest::newRow("urfr scale") << c::imuUrfrMatrix({{{2, 0, 0}, {0, 1, 0}, {0, 0, 1}}});
        QTest::newRow("urfr mirror") << c::imuUrfrMatrix({{{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}}});
        QTest::newRow("coord 1") << c::imuCoord(1);
        QTest::newRow("pmux4") << c::pmux(4, 1);
        QTest::newRow("io6") << c::pmux(1, 6);
        QTest::newRow("div 0") << c::pmux2Div(0);
        QTest::newRow("div 1001") << c::pmux2Div(1001);
        QTest::newRow("usrcal 700") << c::gyroCalStart(700);
        QTest::newRow("usrcal 1801") << c::gyroCalStart(1801);
        QTest::newRow("yaw 181") << c::setYaw(1, 181);
        QTest::newRow("yaw mode 2") << c::setYaw(2, 0);
        QTest::newRow("period 2 s") << c::logOnTime(Message::HI91, 2);
        QTest::newRow("period 0.0005") << c::logOnTime(Message::HI91, 0.0005);
        QTest::newRow("period 0.0015") << c::logOnTime(Message::HI91, 0.0015);
        QTest::newRow("map bit 20 (reserved)") << c::logHi83Map(1u << 20);
        QTest::newRow("map empty") << c::logHi83Map(0);
    }
    void refused()
    {
        QFETCH(Command, cmd);
        QVERIFY(!cmd.ok());
        QVERIFY(cmd.text.empty());
        QVERIFY(!cmd.error.empty());
    }

    void mountingTable()
    {
        // The manual's table lists exactly these 24 codes.
        const std::vector<int> manual = {24,  35,  43,  52,  125, 134, 142, 153, 205, 214, 240, 251,
                                         304, 315, 341, 350, 402, 413, 421, 430, 503, 512, 520, 531};
        QCOMPARE(Mounting::validCodes(), manual);
        // 240: IMU X up, Y right, Z forward -> user X = sensor +Y ... row 0 is sensor +Y.
        const auto r = Mounting::userFromSensor(240);
        QCOMPARE(r[0][1], 1.0);
        QCOMPARE(r[1][2], 1.0);
        QCOMPARE(r[2][0], 1.0);
        QCOMPARE(Mounting::parseCode("024").value(), 24);
        QVERIFY(!Mounting::parseCode("26"));
        QVERIFY(!Mounting::parseCode("6"));
        for (int code : manual) {
            QVERIFY(Mounting::isRotation(Mounting::legacyMatrixForCode(code)));
            QCOMPARE(Mounting::codeForLegacyMatrix(Mounting::legacyMatrixForCode(code)).value(), code);
        }
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstAsciiCommand)
#include "tst_ascii_command.moc"
