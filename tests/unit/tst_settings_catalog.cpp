// The settings catalog (values, commands, feature table), the URFR mounting choice and
// the output-rate calculator, against the manuals' tables.
#include "protocol/modbus/hipnuc_writes.h"
#include "model/mounting.h"
#include "settings/bandwidth_calculator.h"
#include "settings/device_configuration.h"
#include "settings/mounting_choice.h"
#include "settings/setting_catalog.h"
#include "../common/test_main.h"

#include <QTest>

#include <cmath>

using namespace imudesk;
using namespace imudesk::settings;
using Dir = MountingChoice::Direction;
using protocol::hipnuc::Message;

namespace {
model::DeviceIdentity identity(const char *product, const char *firmware)
{
    model::DeviceIdentity id;
    id.productName = product;
    id.firmware = model::FirmwareVersion::parse(firmware);
    id.serial = "SIM";
    return id;
}

double det(const model::Matrix3 &m)
{
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

QStringList texts(const std::vector<protocol::hipnuc::Command> &commands)
{
    QStringList out;
    for (const auto &c : commands)
        out << QString::fromStdString(c.text);
    return out;
}

QString actionText(const ActionDefinition &a, const QString &argument)
{
    QString error;
    const auto c = SettingCatalog::actionCommand(a, argument, &error);
    return c ? QString::fromStdString(c->text) : QString();
}

bool sameEffect(const protocol::hipnuc::Command &a, const protocol::hipnuc::Command &b)
{
    return a.effect.changesOutput == b.effect.changesOutput && a.effect.thisPort == b.effect.thisPort
        && a.effect.message == b.effect.message && a.effect.periodS == b.effect.periodS;
}
} // namespace

class TstSettingsCatalog : public QObject {
    Q_OBJECT
private Q_SLOTS:
    // Every code of the v1.7.1 table (§4.6.7.6) gives a proper rotation.
    void urfrCodesAreRotations()
    {
        QCOMPARE(int(model::Mounting::validCodes().size()), 24);
        for (int code : model::Mounting::validCodes()) {
            const model::Matrix3 r = model::Mounting::userFromSensor(code);
            for (size_t i = 0; i < 3; ++i)
                for (size_t j = 0; j < 3; ++j) {
                    double dot = 0;
                    for (size_t k = 0; k < 3; ++k)
                        dot += r[i][k] * r[j][k];
                    QCOMPARE(dot, i == j ? 1.0 : 0.0);
                }
            QCOMPARE(det(r), 1.0);
            QVERIFY(model::Mounting::isRotation(model::Mounting::legacyMatrixForCode(code)));
        }
    }

    // v1.7.1 §4.6.7.6, the 24 rows: "IMU X 指右, IMU Y 指前, IMU Z 指上 -> URFR 24" ...
    void manualTable_data()
    {
        QTest::addColumn<int>("code");
        QTest::addColumn<int>("x");
        QTest::addColumn<int>("y");
        QTest::addColumn<int>("z");
        const struct {
            int code;
            Dir x, y, z;
        } rows[] = {
            {24, Dir::Right, Dir::Forward, Dir::Up},     {35, Dir::Right, Dir::Back, Dir::Down},
            {43, Dir::Right, Dir::Down, Dir::Forward},   {52, Dir::Right, Dir::Up, Dir::Back},
            {125, Dir::Left, Dir::Forward, Dir::Down},   {134, Dir::Left, Dir::Back, Dir::Up},
            {142, Dir::Left, Dir::Up, Dir::Forward},     {153, Dir::Left, Dir::Down, Dir::Back},
            {205, Dir::Forward, Dir::Right, Dir::Down},  {214, Dir::Back, Dir::Right, Dir::Up},
            {240, Dir::Up, Dir::Right, Dir::Forward},    {251, Dir::Down, Dir::Right, Dir::Back},
            {304, Dir::Forward, Dir::Left, Dir::Up},     {315, Dir::Back, Dir::Left, Dir::Down},
            {341, Dir::Down, Dir::Left, Dir::Forward},   {350, Dir::Up, Dir::Left, Dir::Back},
            {402, Dir::Forward, Dir::Up, Dir::Right},    {413, Dir::Back, Dir::Down, Dir::Right},
            {421, Dir::Down, Dir::Forward, Dir::Right},  {430, Dir::Up, Dir::Back, Dir::Right},
            {503, Dir::Forward, Dir::Down, Dir::Left},   {512, Dir::Back, Dir::Up, Dir::Left},
            {520, Dir::Up, Dir::Forward, Dir::Left},     {531, Dir::Down, Dir::Back, Dir::Left},
        };
        for (const auto &r : rows)
            QTest::newRow(qPrintable(QString::number(r.code))) << r.code << int(r.x) << int(r.y) << int(r.z);
    }
    void manualTable()
    {
        QFETCH(int, code);
        QFETCH(int, x);
        QFETCH(int, y);
        QFETCH(int, z);
        const auto axes = MountingChoice::axesOfCode(code);
        QCOMPARE(int(axes.x), x);
        QCOMPARE(int(axes.y), y);
        QCOMPARE(int(axes.z), z);
        QString error;
        QCOMPARE(MountingChoice::codeFor(Dir(x), Dir(y), std::nullopt, &error), std::optional<int>(code));
        QCOMPARE(MountingChoice::codeFor(Dir(x), Dir(y), Dir(z), &error), std::optional<int>(code));
        QVERIFY(MountingChoice::description(code).contains(MountingChoice::directionName(Dir(z))));
    }

    void pickerRefusesLeftHanded()
    {
        QString error;
        // X right, Y forward: Z must be up; down is the mirror image.
        QVERIFY(!MountingChoice::codeFor(Dir::Right, Dir::Forward, Dir::Down, &error));
        QVERIFY(error.contains(QLatin1String("left-handed")));
        QVERIFY(!MountingChoice::codeFor(Dir::Up, Dir::Down, std::nullopt, &error));
        QVERIFY(!MountingChoice::codeFor(Dir::Left, Dir::Left, std::nullopt, &error));
        // Left-handed three-digit codes are not URFR codes at all.
        QVERIFY(!model::Mounting::isValidCode(25));
        QVERIFY(!SettingCatalog::normalize(*SettingCatalog::find(QStringLiteral("IMU.URFR")), QStringLiteral("025"),
                                           nullptr, &error));
    }

    // One table for both paths of a v1.6.6 module, by the manuals' names (mounting.cpp):
    // v1.6.6 2.2.4's named URFR examples (printed with 8 numbers, completed by the worked
    // example's rule), v1.6.6 4.2's register 0xA6 values, v1.7.1 4.6.7.6's codes.
    void legacyMountingsByName_data()
    {
        QTest::addColumn<int>("modbusValue");
        QTest::addColumn<QString>("matrix");
        QTest::addColumn<int>("code");
        QTest::newRow("horizontal") << 0 << "1,0,0,0,1,0,0,0,1" << 24;
        QTest::newRow("Y down (X -90 deg)") << 1 << "1,0,0,0,0,1,0,-1,0" << 43;
        QTest::newRow("Y up (X +90 deg)") << 2 << "1,0,0,0,0,-1,0,1,0" << 52;
        QTest::newRow("X up (Y +90 deg)") << 3 << "0,0,-1,0,1,0,1,0,0" << 520;
        QTest::newRow("X down (Y -90 deg)") << 4 << "0,0,1,0,1,0,-1,0,0" << 421;
    }
    void legacyMountingsByName()
    {
        QFETCH(int, modbusValue);
        QFETCH(QString, matrix);
        QFETCH(int, code);
        namespace mb = protocol::modbus;
        // Modbus: the value and the code it means, both ways.
        QCOMPARE(mb::HipnucWrites::mountingCode(model::ManualEdition::V166, uint16_t(modbusValue)),
                 std::optional<int>(code));
        QCOMPARE(mb::HipnucWrites::mounting(model::ManualEdition::V166, code)->value, uint16_t(modbusValue));
        // ASCII: the command for the code, and the code a read-back matrix shows.
        QCOMPARE(MountingChoice::legacyMatrixText(code), matrix);
        const auto v166 = identity("HI14R3", "1.6.6");
        QString error;
        const auto cmds = SettingCatalog::commands(*SettingCatalog::find(QStringLiteral("IMU.URFR")),
                                                   QString::number(code), v166, &error);
        QCOMPARE(texts(cmds), QStringList{QStringLiteral("CONFIG IMU URFR ") + matrix});
        const auto cfg = DeviceConfiguration::fromComConfig(v166, {{"URFR", matrix.toStdString()}});
        QCOMPARE(cfg.value(QStringLiteral("IMU.URFR")), std::optional<QString>(QString::number(code)));
    }

    void normalizeAndCommands_data()
    {
        QTest::addColumn<QString>("firmware");
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("input");
        QTest::addColumn<QString>("canonical");
        QTest::addColumn<QString>("command");
        auto row = [](const char *name, const char *fw, const char *k, const char *in, const char *canon,
                      const char *cmd) {
            QTest::newRow(name) << fw << k << in << canon << cmd;
        };
        row("urfr", "1.7.1", "IMU.URFR", "205", "205", "CONFIG IMU URFR 205");
        row("urfr 024", "1.7.1", "IMU.URFR", "024", "24", "CONFIG IMU URFR 24");
        row("mode", "1.7.1", "ATT.MODE", "1", "1", "CONFIG ATT MODE 1");
        row("mode 4", "1.7.1", "ATT.MODE", "4", "4", "CONFIG ATT MODE 4");
        row("coord", "1.7.1", "IMU.COORD", "4", "4", "CONFIG IMU COORD 4");
        row("div", "1.7.1", "PMUX2.DIV", "5", "5", "CONFIG PMUX2 DIV 5");
        row("pmux", "1.7.1", "PMUX3", "IO2", "IO2", "CONFIG PMUX3 IO2");
        row("pmux digit", "1.7.1", "pmux1", "3", "IO3", "CONFIG PMUX1 IO3");
        row("hi91", "1.7.1", "LOG.HI91", "0.01", "0.01", "LOG HI91 ONTIME 0.01");
        row("hi91 ontime", "1.7.1", "LOG.HI91", "ONTIME 0.005", "0.005", "LOG HI91 ONTIME 0.005");
        row("hi91 off", "1.7.1", "LOG.HI91", "0", "OFF", "LOG HI91 ONTIME 0");
        row("gga onmark", "1.7.1", "LOG.GGA", "onmark", "ONMARK", "LOG GGA ONMARK 1");
        row("map", "1.7.1", "LOG.HI83.MAP", "0x1f", "0x0000001F", "LOG HI83 MAP 0x0000001F");
        row("baud", "1.7.1", "SERIAL.BAUD", "921600", "921600", "SERIALCONFIG 921600");
        row("log", "1.7.1", "LOG", "disable", "DISABLE", "LOG DISABLE");
        row("hi92 166", "1.6.6", "LOG.HI92", "0.05", "0.05", "LOG HI92 ONTIME 0.05");
        row("mcal 166", "1.6.6", "IMU_EN_MCAL", "0", "0", "CONFIG IMU_EN_MCAL 0");
        row("urfr 166", "1.6.6", "IMU.URFR", "24", "24", "CONFIG IMU URFR 1,0,0,0,1,0,0,0,1");
        row("pmux 166", "1.6.6", "PMUX2", "IO9", "IO9", "CONFIG PMUX2 IO9");
        row("baud 166", "1.6.6", "SERIAL.BAUD", "256000", "256000", "SERIALCONFIG 256000");
    }
    void normalizeAndCommands()
    {
        QFETCH(QString, firmware);
        QFETCH(QString, key);
        QFETCH(QString, input);
        QFETCH(QString, canonical);
        QFETCH(QString, command);
        const auto id = identity("HI14R3", qPrintable(firmware));
        const SettingDefinition *d = SettingCatalog::find(key);
        QVERIFY(d);
        QString error;
        const auto v = SettingCatalog::normalize(*d, input, &id, &error);
        QVERIFY2(v, qPrintable(error));
        QCOMPARE(*v, canonical);
        const auto cmds = SettingCatalog::commands(*d, *v, id, &error);
        QCOMPARE(texts(cmds), QStringList{command});
        // Built by the typed builders with the output effect the device gives the words.
        QVERIFY(sameEffect(cmds.front(), protocol::hipnuc::commands::typed(command.toStdString())));
        // The canonical form is a fixed point.
        QCOMPARE(SettingCatalog::normalize(*d, *v, &id, &error), v);
    }

    void refused_data()
    {
        QTest::addColumn<QString>("product");
        QTest::addColumn<QString>("firmware");
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("value");
        auto row = [](const char *name, const char *p, const char *fw, const char *k, const char *v) {
            QTest::newRow(name) << p << fw << k << v;
        };
        row("mode 4 on 1.6.6", "HI14R3", "1.6.6", "ATT.MODE", "4");
        row("AHRS on HI02", "HI02", "1.7.1", "ATT.MODE", "1");
        row("PMUX on HI50", "HI50", "1.7.1", "PMUX1", "IO1");
        row("PMUX on HI9x", "HI92", "1.7.1", "PMUX2.DIV", "5");
        row("IO6 on 1.7.1", "HI14R3", "1.7.1", "PMUX1", "IO6");
        row("coord on 1.6.6", "HI14R3", "1.6.6", "IMU.COORD", "0");
        row("coord 2", "HI14R3", "1.7.1", "IMU.COORD", "2");
        row("HI92 on 1.7.1", "HI14R3", "1.7.1", "LOG.HI92", "0.01");
        row("HI81 on 1.6.6", "HI14R3", "1.6.6", "LOG.HI81", "0.01");
        row("period 2 s", "HI14R3", "1.7.1", "LOG.HI91", "2");
        row("period 0.0015", "HI14R3", "1.7.1", "LOG.HI91", "0.0015");
        row("div 0", "HI14R3", "1.7.1", "PMUX2.DIV", "0");
        row("div 1001", "HI14R3", "1.7.1", "PMUX2.DIV", "1001");
        row("baud 230400 on 1.6.6", "HI14R3", "1.6.6", "SERIAL.BAUD", "230400");
        row("baud 1000", "HI14R3", "1.7.1", "SERIAL.BAUD", "1000");
        row("matrix on 1.7.1", "HI14R3", "1.7.1", "IMU.URFR", "0.6,0.8,0,-0.8,0.6,0,0,0,1");
        row("reflection", "HI14R3", "1.6.6", "IMU.URFR", "1,0,0,0,1,0,0,0,-1");
        row("mcal on HI50", "HI50", "1.6.6", "IMU_EN_MCAL", "1");
        row("mcal on 1.7.1", "HI14R3", "1.7.1", "IMU_EN_MCAL", "1");
        row("map 0", "HI14R3", "1.7.1", "LOG.HI83.MAP", "0");
    }
    void refused()
    {
        QFETCH(QString, product);
        QFETCH(QString, firmware);
        QFETCH(QString, key);
        QFETCH(QString, value);
        const auto id = identity(qPrintable(product), qPrintable(firmware));
        const SettingDefinition *d = SettingCatalog::find(key);
        QVERIFY(d);
        QString error;
        QVERIFY(SettingCatalog::commands(*d, value, id, &error).empty());
        QVERIFY(!error.isEmpty());
    }

    // Each action's command comes from its typed builder: the manual's words, and the output
    // effect the device gives them (a reset stops the stream for a while).
    void actionCommands_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("command");
        QTest::addColumn<bool>("changesOutput");
        QTest::newRow("ATT.RST.1") << "ATT.RST.1" << "CONFIG ATT RST 1" << false;
        QTest::newRow("ATT.RST.2") << "ATT.RST.2" << "CONFIG ATT RST 2" << false;
        QTest::newRow("ATT.RST.3") << "ATT.RST.3" << "CONFIG ATT RST 3" << false;
        QTest::newRow("ATT.RST.5") << "ATT.RST.5" << "CONFIG ATT RST 5" << false;
        QTest::newRow("SAVECONFIG") << "SAVECONFIG" << "SAVECONFIG" << false;
        QTest::newRow("REBOOT") << "REBOOT" << "REBOOT" << true;
        QTest::newRow("FRESET") << "FRESET" << "FRESET" << true;
    }
    void actionCommands()
    {
        QFETCH(QString, key);
        QFETCH(QString, command);
        QFETCH(bool, changesOutput);
        const ActionDefinition *a = SettingCatalog::findAction(key);
        QVERIFY(a);
        QString error;
        const auto c = SettingCatalog::actionCommand(*a, QString(), &error);
        QVERIFY2(c && c->ok(), qPrintable(error));
        QCOMPARE(QString::fromStdString(c->text), command);
        QCOMPARE(c->effect.changesOutput, changesOutput);
        QVERIFY(sameEffect(*c, protocol::hipnuc::commands::typed(command.toStdString())));
        // "1" is accepted as "run it"; any other value is refused.
        QVERIFY(SettingCatalog::actionCommand(*a, QStringLiteral("1"), &error));
        QVERIFY(!SettingCatalog::actionCommand(*a, QStringLiteral("2"), &error));
        QVERIFY(error.contains(key));
    }

    void legacyArbitraryMatrix()
    {
        const auto id = identity("HI14R3", "1.6.6");
        const SettingDefinition *d = SettingCatalog::find(QStringLiteral("IMU.URFR"));
        QString error;
        const auto v = SettingCatalog::normalize(*d, QStringLiteral("0.6,0.8,0,-0.8,0.6,0,0,0,1"), &id, &error);
        QVERIFY2(v, qPrintable(error));
        QCOMPARE(texts(SettingCatalog::commands(*d, *v, id, &error)),
                 QStringList{QStringLiteral("CONFIG IMU URFR 0.6,0.8,0,-0.8,0.6,0,0,0,1")});
    }

    void actions()
    {
        const auto v171 = identity("HI14R3", "1.7.1");
        const auto v166 = identity("HI14R3", "1.6.6");
        QString error;
        QVERIFY(SettingCatalog::availability(*SettingCatalog::findAction(QStringLiteral("ATT.RST.1")), v171).available);
        QVERIFY(!SettingCatalog::availability(*SettingCatalog::findAction(QStringLiteral("ATT.RST.1")), v166).available);
        QVERIFY(!SettingCatalog::availability(*SettingCatalog::findAction(QStringLiteral("ATT.RST.3")),
                                              identity("HI02", "1.7.1"))
                     .available);
        QVERIFY(SettingCatalog::conditions(*SettingCatalog::findAction(QStringLiteral("ATT.RST.3"))).contains(
            QLatin1String("5 deg")));
        const auto *yaw = SettingCatalog::findAction(QStringLiteral("YAW"));
        QCOMPARE(actionText(*yaw, QStringLiteral("1,16")), QStringLiteral("CONFIG YAW 1 16"));
        QCOMPARE(actionText(*yaw, QStringLiteral("0,1.5")), QStringLiteral("CONFIG YAW 0 1.5"));
        QVERIFY(!SettingCatalog::actionCommand(*yaw, QStringLiteral("1,200"), &error));
        QVERIFY(!error.isEmpty());
        QVERIFY(SettingCatalog::availability(*yaw, v166).available);
        QVERIFY(!SettingCatalog::availability(*yaw, v171).available);
    }

    // A COMCONFIG reply as the simulator prints it (docs/DEVICES_AND_LINKS.md, "The simulator").
    void fromComConfig()
    {
        const std::map<std::string, std::string> kv = {
            {"BAUD", "115200"},   {"LOG", "ENABLE"},   {"HI91", "ONTIME 0.01"}, {"HI81", "OFF"},
            {"HI83", "ONMARK 1"}, {"GGA", "OFF"},      {"RMC", "OFF"},          {"SXT", "ONTIME 1"},
            {"HI83_MAP", "0x000000FF"}, {"ATT_MODE", "1"}, {"URFR", "24"},      {"COORD", "0"},
            {"PMUX1", "IO1"},     {"PMUX2", "IO2"},    {"PMUX3", "IO5"},        {"PMUX2_DIV", "1"},
            {"FUTURE", "42"}};
        const auto c = DeviceConfiguration::fromComConfig(identity("HI14R3", "1.7.1"), kv);
        QCOMPARE(int(c.values.size()), 16);
        QCOMPARE(c.value(QStringLiteral("LOG.HI91")), std::optional<QString>(QStringLiteral("0.01")));
        QCOMPARE(c.value(QStringLiteral("LOG.HI83")), std::optional<QString>(QStringLiteral("ONMARK")));
        QCOMPARE(c.value(QStringLiteral("LOG.SXT")), std::optional<QString>(QStringLiteral("1")));
        QCOMPARE(c.unreadable, QStringList{QStringLiteral("FUTURE=42")});
    }

    // v1.7.1 §5.13 and v1.6.6 §3.7: maximum rates per baud.
    void maxRates_data()
    {
        QTest::addColumn<int>("message");
        QTest::addColumn<int>("baud");
        QTest::addColumn<int>("hz");
        const int bauds[] = {9600, 115200, 230400, 256000, 460800, 921600};
        const int hi91[] = {10, 100, 250, 250, 500, 1000};
        const int hi92[] = {10, 200, 250, 250, 500, 1000};
        for (int i = 0; i < 6; ++i) {
            QTest::newRow(qPrintable(QStringLiteral("HI91 %1").arg(bauds[i]))) << int(Message::HI91) << bauds[i]
                                                                               << hi91[i];
            QTest::newRow(qPrintable(QStringLiteral("HI92 %1").arg(bauds[i]))) << int(Message::HI92) << bauds[i]
                                                                               << hi92[i];
        }
    }
    void maxRates()
    {
        QFETCH(int, message);
        QFETCH(int, baud);
        QFETCH(int, hz);
        QCOMPARE(BandwidthCalculator::maxRateClass(Message(message), baud), hz);
        QVERIFY(BandwidthCalculator::evaluate({{Message(message), double(hz)}}, baud).fits);
    }

    void warnsWhenTheLinkCannotCarryIt()
    {
        QCOMPARE(BandwidthCalculator::frameBytes(Message::HI91), size_t(82));
        // HI91 at 500 Hz on 115200: 41000 bytes/s against 11520.
        const auto r = BandwidthCalculator::evaluate({{Message::HI91, 500.0}}, 115200);
        QVERIFY(!r.fits);
        QCOMPARE(r.bytesPerSecond, 41000.0);
        QCOMPARE(r.capacityBytesPerSecond, 11520.0);
        QVERIFY(r.warning.contains(QLatin1String("460800")));
        // A configuration: HI91 100 Hz and HI83 (default map, 6 + 8 + 12*4 + 16 + 8 + 8 + 4 bytes) 100 Hz.
        DeviceConfiguration c;
        c.values = {{QStringLiteral("SERIAL.BAUD"), QStringLiteral("115200")},
                    {QStringLiteral("LOG.HI91"), QStringLiteral("0.01")},
                    {QStringLiteral("LOG.HI83"), QStringLiteral("0.01")},
                    {QStringLiteral("LOG.GGA"), QStringLiteral("ONMARK")}};
        const auto rc = BandwidthCalculator::evaluate(c);
        QCOMPARE(int(rc.lines.size()), 2);
        QCOMPARE(rc.bytesPerSecond, 8200.0 + 100.0 * double(BandwidthCalculator::frameBytes(Message::HI83)));
        QVERIFY(BandwidthCalculator::evaluate(c, 921600).fits);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstSettingsCatalog)
#include "tst_settings_catalog.moc"
