// Configuration profiles: JSON round trip, the loader's refusals, diff against a device.
#include "settings/config_profile.h"
#include "../common/test_main.h"

#include <QTemporaryDir>
#include <QTest>

using namespace imudesk;
using settings::ConfigProfile;

namespace {
settings::DeviceConfiguration deviceWith(const char *product, const char *firmware,
                                     std::map<std::string, std::string> comconfig)
{
    model::DeviceIdentity id;
    id.productName = product;
    id.firmware = model::FirmwareVersion::parse(firmware);
    id.serial = "0123";
    return settings::DeviceConfiguration::fromComConfig(id, comconfig);
}
} // namespace

class TstConfigProfile : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void roundTrip()
    {
        const auto cfg = deviceWith("HI14R3", "1.7.1",
                                {{"BAUD", "921600"}, {"LOG", "DISABLE"}, {"HI91", "ONTIME 0.005"}, {"URFR", "205"},
                                 {"HI83_MAP", "0x0000001F"}, {"PMUX2_DIV", "5"}});
        const auto p = ConfigProfile::fromConfiguration(cfg);
        QCOMPARE(int(p.settings.size()), 5); // LOG ENABLE/DISABLE is not part of a profile
        QCOMPARE(p.product, QStringLiteral("HI14R3"));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("p.json"));
        QString error;
        QVERIFY2(p.save(path, &error), qPrintable(error));
        const auto back = ConfigProfile::load(path, &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->settings, p.settings);
        QCOMPARE(back->serial, QStringLiteral("0123"));
        QVERIFY(back->diff(cfg).empty());
    }

    void refused_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("why");
        QTest::newRow("not json") << QByteArray("{\"format\":") << "not valid JSON";
        QTest::newRow("array") << QByteArray("[]") << "JSON object";
        QTest::newRow("format") << QByteArray(R"({"format":"x","version":1,"settings":{}})") << "imudesk-profile";
        QTest::newRow("version") << QByteArray(R"({"format":"imudesk-profile","version":2,"settings":{}})")
                                 << "version 2";
        QTest::newRow("no settings") << QByteArray(R"({"format":"imudesk-profile","version":1})") << "settings";
        QTest::newRow("unknown key")
            << QByteArray(R"({"format":"imudesk-profile","version":1,"settings":{"IMU.FOO":"1"}})") << "IMU.FOO";
        QTest::newRow("LOG not in profiles")
            << QByteArray(R"({"format":"imudesk-profile","version":1,"settings":{"LOG":"DISABLE"}})") << "LOG";
        QTest::newRow("bad value")
            << QByteArray(R"({"format":"imudesk-profile","version":1,"settings":{"PMUX2.DIV":"5000"}})") << "1 .. 1000";
        QTest::newRow("left-handed")
            << QByteArray(R"({"format":"imudesk-profile","version":1,"settings":{"IMU.URFR":"025"}})") << "URFR";
        QTest::newRow("object value")
            << QByteArray(R"({"format":"imudesk-profile","version":1,"settings":{"ATT.MODE":{}}})") << "string";
        QTest::newRow("too large") << QByteArray(ConfigProfile::kMaxBytes + 1, ' ') << "larger";
    }
    void refused()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, why);
        QString error;
        QVERIFY(!ConfigProfile::fromJson(json, &error));
        QVERIFY2(error.contains(why), qPrintable(error));
    }

    void numbersAccepted()
    {
        QString error;
        const auto p = ConfigProfile::fromJson(
            R"({"format":"imudesk-profile","version":1,"settings":{"LOG.HI91":0.005,"ATT.MODE":4}})", &error);
        QVERIFY2(p, qPrintable(error));
        QCOMPARE(p->settings.at(QStringLiteral("LOG.HI91")), QStringLiteral("0.005"));
    }

    // A profile of a 1.7.1 HI14 against a 1.6.6 HI14 and a 1.7.1 HI92 (no PMUX).
    void diffAcrossModels()
    {
        QString error;
        const auto p = ConfigProfile::fromJson(R"({"format":"imudesk-profile","version":1,"settings":{
            "IMU.URFR":"52","IMU.COORD":"4","PMUX2.DIV":"5","ATT.MODE":"0","LOG.HI91":"0.01"}})",
                                               &error);
        QVERIFY2(p, qPrintable(error));
        const auto old = deviceWith("HI14R3", "1.6.6",
                                {{"URFR", "1,0,0,0,1,0,0,0,1"}, {"ATT_MODE", "1"}, {"HI91", "ONTIME 0.01"}});
        const auto d = p->diff(old);
        QCOMPARE(int(d.size()), 4); // LOG.HI91 is equal
        QCOMPARE(d[0].key, QStringLiteral("ATT.MODE"));
        QCOMPARE(d[1].key, QStringLiteral("IMU.URFR"));
        QCOMPARE(d[1].deviceValue, QStringLiteral("24"));
        QVERIFY(d[1].applicable);
        QVERIFY(!d[2].applicable); // IMU.COORD: not on 1.6.6
        QVERIFY(!d[3].applicable); // PMUX2.DIV: not on 1.6.6
        QCOMPARE(int(p->changesFor(old).size()), 2);
        const auto hi92 = deviceWith("HI92R3", "1.7.1", {{"URFR", "52"}, {"ATT_MODE", "0"}, {"COORD", "4"}});
        const auto d2 = p->diff(hi92);
        QCOMPARE(int(d2.size()), 2);
        QVERIFY(!d2[1].applicable); // PMUX2.DIV on HI9x
        QVERIFY(d2[1].note.contains(QLatin1String("PMUX")));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstConfigProfile)
#include "tst_config_profile.moc"
