// imudesk-cli config end to end against simulators on pseudo-terminals: show, set with
// verification, save and reboot, refused values, the bandwidth warning, actions,
// export / diff / apply of a profile to several devices with a per-device report.
#include "../common/cli_run.h"
#include "../common/test_main.h"
#include "settings/config_profile.h"
#include "sim/pty_simulator.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace imudesk;

namespace {

using Result = imudesk::test::CliResult;

Result run(const QStringList &args, int timeoutMs = 60000)
{
    return imudesk::test::runCli(args, timeoutMs);
}

std::unique_ptr<sim::PtySimulator> simulator(uint64_t seed, const char *firmware = "1.7.1",
                                             sim::SimFaults::ComConfigStyle comConfig = sim::SimFaults::ComConfigStyle::KeyValue)
{
    sim::SimOptions o;
    o.seed = seed;
    o.firmware = firmware;
    o.faults.comConfigStyle = comConfig;
    auto s = std::make_unique<sim::PtySimulator>(o);
    QString error;
    if (!s->start(&error))
        qWarning() << error;
    return s;
}

sim::HipnucSimulator::Config saved(sim::PtySimulator &s)
{
    sim::HipnucSimulator::Config c;
    s.withDevice([&c](sim::HipnucSimulator &d) { c = d.savedConfig(); });
    return c;
}

} // namespace

class TstCliConfig : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void showJson()
    {
        auto s = simulator(1);
        const auto r = run({"config", s->devicePath(), "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
        const QJsonObject settings = o.value(QStringLiteral("settings")).toObject();
        QCOMPARE(settings.value(QStringLiteral("ATT.MODE")).toString(), QStringLiteral("1"));
        QCOMPARE(settings.value(QStringLiteral("IMU.URFR")).toString(), QStringLiteral("24"));
        QCOMPARE(settings.value(QStringLiteral("LOG.HI91")).toString(), QStringLiteral("0.01"));
        QVERIFY(o.value(QStringLiteral("unavailable")).toObject().contains(QStringLiteral("IMU_EN_MCAL")));
        QCOMPARE(o.value(QStringLiteral("device")).toObject().value(QStringLiteral("product")).toString(),
                 QStringLiteral("HI14R3"));
    }

    void setSaveReboot()
    {
        auto s = simulator(2);
        const auto r = run({"config", s->devicePath(), "set", "IMU.URFR=205", "ATT.MODE=0", "PMUX2.DIV=5",
                            "LOG.HI91=0.02", "IMU.COORD=4", "--save", "--reboot"});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QVERIFY(r.out.contains(QLatin1String("> CONFIG IMU URFR 205")));
        QVERIFY(r.out.contains(QLatin1String("> SAVECONFIG")));
        QVERIFY(r.out.contains(QLatin1String("IMU.URFR=205\tverified")));
        const auto c = saved(*s);
        QCOMPARE(c.urfrCode, 205);
        QCOMPARE(c.attMode, 0);
        QCOMPARE(c.pmux2Div, 5);
        QCOMPARE(c.coord, 4);
        QCOMPARE(c.message(protocol::hipnuc::Message::HI91).periodMs, 20);
    }

    // The manual prints no format for LOG COMCONFIG's reply (v1.7.1 4.6.8.14) but URFR=<CODE>.
    // A module that answers in another KEY : value layout (lower case, three a line) is read
    // all the same; one whose reply ImuDesk cannot read gets "could not be read back" (exit 3),
    // never "not taken" (exit 1), and the reply is shown.
    void readBackOfAnotherFormat()
    {
        auto spaced = simulator(5, "1.7.1", sim::SimFaults::ComConfigStyle::Spaced);
        auto r = run({"config", spaced->devicePath(), "set", "IMU.URFR=205", "ATT.MODE=0"});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.contains(QLatin1String("IMU.URFR=205\tverified")), qPrintable(r.out));
        QVERIFY(r.out.contains(QLatin1String("ATT.MODE=0\tverified")));

        auto unlabelled = simulator(6, "1.7.1", sim::SimFaults::ComConfigStyle::Unlabelled);
        r = run({"config", unlabelled->devicePath(), "set", "IMU.URFR=205"});
        QCOMPARE(r.code, 3);
        QVERIFY2(r.out.contains(QLatin1String("IMU.URFR=205\tcould not be read back")), qPrintable(r.out));
        QVERIFY2(!r.out.contains(QLatin1String("not taken")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QLatin1String("the reply was: 115200 ENABLE")), qPrintable(r.out)); // the raw reply
        // The module did take it (its running configuration says so).
        sim::HipnucSimulator::Config running;
        unlabelled->withDevice([&running](sim::HipnucSimulator &d) { running = d.runningConfig(); });
        QCOMPARE(running.urfrCode, 205);
    }

    void legacyFirmware()
    {
        auto s = simulator(3, "1.6.6");
        const auto r = run({"config", s->devicePath(), "set", "IMU.URFR=43", "IMU_EN_MCAL=0", "LOG.HI92=0.05", "--save"});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QVERIFY(r.out.contains(QLatin1String("> CONFIG IMU URFR 1,0,0,0,0,1,0,-1,0")));
        const auto c = saved(*s);
        QCOMPARE(c.urfrMatrix, (model::Matrix3{{{1, 0, 0}, {0, 0, 1}, {0, -1, 0}}}));
        QVERIFY(!c.backgroundMagCal);
        const auto y = run({"config", s->devicePath(), "action", "YAW=1,16"});
        QVERIFY2(y.code == 0, qPrintable(y.err));
        const auto rst1 = run({"config", s->devicePath(), "action", "ATT.RST=1"});
        QCOMPARE(rst1.code, 1); // not on firmware below 1.7.1
        QVERIFY(rst1.err.contains(QLatin1String("1.7.0")));
    }

    void refused_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("why");
        QTest::newRow("mode 7") << QStringList{"ATT.MODE=7"} << "ATT.MODE";
        QTest::newRow("left-handed") << QStringList{"IMU.URFR=025"} << "24 right-handed";
        QTest::newRow("unknown key") << QStringList{"IMU.FOO=1"} << "unknown setting";
        QTest::newRow("not kv") << QStringList{"ATT.MODE"} << "KEY=VALUE";
        QTest::newRow("1.6.6 only") << QStringList{"IMU_EN_MCAL=0"} << "1.7.1";
    }
    void refused()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, why);
        auto s = simulator(4);
        const auto before = saved(*s);
        const auto r = run(QStringList{"config", s->devicePath(), "set"} + args);
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains(why), qPrintable(r.err));
        QVERIFY(!r.out.contains(QLatin1String("> ")));
        sim::HipnucSimulator::Config running;
        s->withDevice([&running](sim::HipnucSimulator &d) { running = d.runningConfig(); });
        QCOMPARE(running, before);
    }

    void bandwidthWarningAndDryRun()
    {
        auto s = simulator(5);
        const auto r = run({"config", s->devicePath(), "set", "LOG.HI91=0.002", "--dry-run"});
        QCOMPARE(r.code, 0);
        QVERIFY2(r.err.contains(QLatin1String("frames will be lost")), qPrintable(r.err));
        QVERIFY(r.out.contains(QLatin1String("> LOG HI91 ONTIME 0.002")));
        QVERIFY(r.out.contains(QLatin1String("imudesk-cli config")));
        sim::HipnucSimulator::Config running;
        s->withDevice([&running](sim::HipnucSimulator &d) { running = d.runningConfig(); });
        QCOMPARE(running.message(protocol::hipnuc::Message::HI91).periodMs, 10);
    }

    void baudChange()
    {
        auto s = simulator(6);
        const auto r = run({"config", s->devicePath(), "set", "SERIAL.BAUD=921600", "--save"});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        int baud = 0;
        s->withDevice([&baud](sim::HipnucSimulator &d) { baud = d.baud(); });
        QCOMPARE(baud, 921600);
        const auto show = run({"config", s->devicePath()});
        QVERIFY2(show.code == 0, qPrintable(show.err));
        QVERIFY(show.out.contains(QLatin1String("SERIAL.BAUD=921600")));
    }

    void profileBatch()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("line.json"));
        auto master = simulator(7);
        QCOMPARE(run({"config", master->devicePath(), "set", "IMU.URFR=531", "LOG.HI91=0.005", "SERIAL.BAUD=460800",
                      "PMUX3=IO2"})
                     .code,
                 0);
        const auto exported = run({"config", master->devicePath(), "export", path});
        QVERIFY2(exported.code == 0, qPrintable(exported.err));
        QString error;
        const auto profile = settings::ConfigProfile::load(path, &error);
        QVERIFY2(profile, qPrintable(error));
        QCOMPARE(profile->settings.at(QStringLiteral("IMU.URFR")), QStringLiteral("531"));

        auto a = simulator(8);
        auto b = simulator(9);
        const auto diff = run({"config", a->devicePath(), "diff", path});
        QCOMPARE(diff.code, 1);
        QVERIFY(diff.out.contains(QLatin1String("IMU.URFR\tprofile 531\tdevice 24")));
        const auto applied = run({"config", a->devicePath() + QLatin1Char(',') + b->devicePath(), "apply", path, "--save"});
        QVERIFY2(applied.code == 0, qPrintable(applied.out + applied.err));
        const QStringList lines = applied.out.trimmed().split(QLatin1Char('\n'));
        QCOMPARE(lines.size(), 2);
        for (int i = 0; i < 2; ++i) {
            sim::PtySimulator &s = i == 0 ? *a : *b;
            std::string uuid;
            s.withDevice([&uuid](sim::HipnucSimulator &d) { uuid = d.uuid(); });
            QVERIFY2(lines[i].startsWith(s.devicePath() + QLatin1Char('\t') + QString::fromStdString(uuid)),
                     qPrintable(lines[i]));
            QVERIFY(lines[i].contains(QLatin1String("\tOK\t4 changed")));
            const auto c = saved(s);
            QCOMPARE(c.urfrCode, 531);
            QCOMPARE(c.baud, 460800);
            QCOMPARE(c.pmux[2], 2);
        }
        const auto same = run({"config", b->devicePath(), "diff", path});
        QCOMPARE(same.code, 0);
        // A port with nothing behind it is reported and the others still done.
        const auto partial = run({"config", QStringLiteral("/dev/does-not-exist,") + a->devicePath(), "apply", path},
                                 90000);
        QCOMPARE(partial.code, 1);
        QVERIFY(partial.out.contains(QLatin1String("/dev/does-not-exist\t-\t-\tFAILED")));
        QVERIFY(partial.out.contains(a->devicePath() + QLatin1Char('\t')));
        QVERIFY(partial.err.contains(QLatin1String("1 of 2 devices failed")));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCliConfig)
#include "tst_cli_config.moc"
