// Reply parsing: OK, ERR, KEY=VALUE, echo, LOG VERSION identity.
#include "model/device_identity.h"
#include "protocol/hipnuc/ascii_reply.h"
#include "../common/test_main.h"

#include <QTest>

using namespace imudesk::protocol::hipnuc;
using imudesk::model::DeviceIdentity;
using imudesk::model::FirmwareVersion;
using imudesk::model::ManualEdition;

class TstAsciiReply : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void logVersionIdentity()
    {
        ReplyCollector c("LOG VERSION");
        for (const char *l : {"LOG VERSION", "PNAME=HI14R3", "BUILD=Oct 15 2024", "UUID=043995698D6E1708",
                              "APP_VER=156", "BL_VER=109"})
            QVERIFY(!c.addLine(l));
        QVERIFY(c.addLine("OK"));
        const auto r = c.take();
        QCOMPARE(r.status, AsciiReply::Status::Ok);
        QCOMPARE(r.lines.size(), size_t(5)); // echo dropped
        const auto id = DeviceIdentity::fromKeyValues(r.values);
        QCOMPARE(id.productName, std::string("HI14R3"));
        QCOMPARE(id.serial, std::string("043995698D6E1708"));
        QCOMPARE(id.firmware->toString(), std::string("1.5.6"));
        QCOMPARE(id.bootloader->toString(), std::string("1.0.9"));
        QCOMPARE(id.build, std::string("Oct 15 2024"));
        QVERIFY(id.usable());
        QCOMPARE(id.edition(), ManualEdition::V166);
        QVERIFY(!id.hasMainStatus());
        QCOMPARE(imudesk::model::familyName(id.family()), "CH0x0/HI04/12/13/14");
    }

    void aliases()
    {
        const auto id = DeviceIdentity::fromKeyValues({{"PNAME", "HI50"}, {"SW_VERSION", "1.7.1"}, {"SN", "X1"},
                                                      {"BL_VERSION", "110"}});
        QCOMPARE(id.firmware->toString(), std::string("1.7.1"));
        QCOMPARE(id.serial, std::string("X1"));
        QCOMPARE(id.edition(), ManualEdition::V171);
        QVERIFY(id.hasMainStatus());
        QVERIFY(!id.hasMagnetometer());
    }

    void classify_data()
    {
        QTest::addColumn<QString>("line");
        QTest::addColumn<int>("kind");
        QTest::newRow("ok") << "OK" << int(LineKind::Ok);
        QTest::newRow("ok spaces") << "  OK \r" << int(LineKind::Ok);
        QTest::newRow("err") << "ERR" << int(LineKind::Error);
        QTest::newRow("err code") << "ERR 3" << int(LineKind::Error);
        QTest::newRow("error colon") << "Error: bad arg" << int(LineKind::Error);
        QTest::newRow("fail") << "FAIL" << int(LineKind::Error);
        QTest::newRow("errata is info") << "ERRATA=1" << int(LineKind::Info);
        QTest::newRow("okay is info") << "OKAY" << int(LineKind::Info);
        QTest::newRow("kv") << "STAT=1" << int(LineKind::Info);
    }
    void classify()
    {
        QFETCH(QString, line);
        QFETCH(int, kind);
        QCOMPARE(int(classifyLine(line.toStdString())), kind);
    }

    void errorReply()
    {
        ReplyCollector c("CONFIG USRCAL STOP");
        QVERIFY(c.addLine("ERR"));
        QCOMPARE(c.reply().status, AsciiReply::Status::Refused);
        QCOMPARE(c.reply().errorLine, std::string("ERR"));
        // Lines after completion are ignored.
        QVERIFY(c.addLine("OK"));
        QCOMPARE(c.reply().status, AsciiReply::Status::Refused);
    }

    void mcalStat()
    {
        ReplyCollector c("LOG MCAL STAT");
        c.addLine("STAT=1");
        c.addLine("PROGRESS=8");
        QVERIFY(c.addLine("OK"));
        QCOMPARE(c.reply().values.at("STAT"), std::string("1"));
        QCOMPARE(c.reply().values.at("PROGRESS"), std::string("8"));
    }

    void keyValue()
    {
        const auto pairs = imudesk::protocol::hipnuc::keyValuePairs(" MB=14.14, -2.08, -8.75 ");
        QCOMPARE(pairs.size(), size_t(1));
        QCOMPARE(pairs.front().first, std::string("MB"));
        QCOMPARE(pairs.front().second, std::string("14.14, -2.08, -8.75"));
        QVERIFY(imudesk::protocol::hipnuc::keyValuePairs("=5").empty());
        QVERIFY(imudesk::protocol::hipnuc::keyValuePairs("no equals").empty());
    }

    // LOG COMCONFIG read tolerantly (issue 35): the manual prints no format but URFR=<CODE>.
    void keyValuePairs_data()
    {
        QTest::addColumn<QString>("line");
        QTest::addColumn<QString>("pairs"); // "KEY=VALUE|KEY=VALUE"
        QTest::newRow("ImuDesk's lines") << "ATT_MODE=1" << "ATT_MODE=1";
        QTest::newRow("blanks around =") << "  URFR = 24 " << "URFR=24";
        QTest::newRow("lower case") << "att_mode=0" << "ATT_MODE=0";
        QTest::newRow("matrix keeps its commas") << "URFR=1,0,0,0,1,0,0,0,1" << "URFR=1,0,0,0,1,0,0,0,1";
        QTest::newRow("a value of words") << "HI91=ONTIME 0.01" << "HI91=ONTIME 0.01";
        QTest::newRow("three on a line") << "BAUD=115200; LOG=ENABLE; HI91=ONTIME 0.01"
                                         << "BAUD=115200|LOG=ENABLE|HI91=ONTIME 0.01";
        QTest::newRow("blank separated") << "ATT_MODE=1 COORD=0" << "ATT_MODE=1|COORD=0";
        QTest::newRow("colon") << "att_mode : 1; coord : 4" << "ATT_MODE=1|COORD=4";
        QTest::newRow("words before a colon") << "Att mode: 1" << "ATT_MODE=1";
        QTest::newRow("dashes and dots") << "IMU.URFR=205" << "IMU.URFR=205";
        QTest::newRow("a sentence") << "configuration follows" << "";
        QTest::newRow("values alone") << "115200 ENABLE ONTIME 0.01 OFF" << "";
        QTest::newRow("text before the key") << "the baud is BAUD=9600" << "";
    }
    void keyValuePairs()
    {
        QFETCH(QString, line);
        QFETCH(QString, pairs);
        QStringList got;
        for (const auto &[k, v] : imudesk::protocol::hipnuc::keyValuePairs(line.toStdString()))
            got << QString::fromStdString(k + "=" + v);
        QCOMPARE(got.join(QLatin1Char('|')), pairs);
    }

    void versions_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("parsed");
        QTest::newRow("3 digits") << "171" << "1.7.1";
        QTest::newRow("dotted") << "1.6.6" << "1.6.6";
        QTest::newRow("v prefix") << "v1.7.0" << "1.7.0";
        QTest::newRow("two parts") << "1.7" << "1.7.0";
        QTest::newRow("garbage") << "abc" << "";
        QTest::newRow("4 digits") << "1712" << "";
        QTest::newRow("empty") << "" << "";
        QTest::newRow("trailing dot") << "1.7." << "";
    }
    void versions()
    {
        QFETCH(QString, text);
        QFETCH(QString, parsed);
        const auto v = FirmwareVersion::parse(text.toStdString());
        QCOMPARE(v ? QString::fromStdString(v->toString()) : QString(), parsed);
        QVERIFY((FirmwareVersion{1, 5, 5} < FirmwareVersion{1, 7, 1}));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstAsciiReply)
#include "tst_ascii_reply.moc"
