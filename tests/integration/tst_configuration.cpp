// Configuration flows against the simulated module, in this process (sim::SimulatedTransport,
// tests/common/sim_session.h; the serial path itself is tst_device_session's): every setting of both
// manuals round-trips (set, save, reboot, read back); unsaved settings are gone after
// REBOOT; FRESET restores the defaults; the safe baud change succeeds, and recovers when
// the module ignores the new rate or switches to another one; ERR and timeouts leave the
// configuration showing what the device holds.
#include "../common/sim_session.h"
#include "../common/test_main.h"
#include "device/device_session.h"
#include "settings/configuration_controller.h"
#include "settings/setting_catalog.h"

#include <QSignalSpy>
#include <QTest>

#include <memory>

using namespace imudesk;
using settings::ConfigurationController;
using Outcome = ConfigurationController::Outcome;
using Change = ConfigurationController::Change;

namespace {

struct Bench {
    test::SimSession sim;
    device::DeviceSession &session = sim.session;
    ConfigurationController controller{session};

    explicit Bench(const char *firmware = "1.7.1", const char *model = "HI14", int baud = 115200)
        : sim(options(firmware, model, baud))
    {
    }
    static sim::SimOptions options(const char *firmware, const char *model, int baud)
    {
        sim::SimOptions o;
        o.firmware = firmware;
        o.model = model;
        o.baud = baud;
        o.seed = 7;
        return o;
    }
    bool start(int baud = 115200)
    {
        session.setAutoReconnect(false);
        QSignalSpy identified(&session, &device::DeviceSession::identityQueryFinished);
        sim.open(baud);
        if (!identified.wait(5000))
            return false;
        return read();
    }
    bool read()
    {
        QSignalSpy done(&controller, &ConfigurationController::readFinished);
        controller.readAll();
        return (!done.isEmpty() || done.wait(10000)) && done.first().at(0).toBool();
    }
    ConfigurationController::ApplyReport apply(const std::vector<Change> &changes)
    {
        QSignalSpy done(&controller, &ConfigurationController::applyFinished);
        controller.apply(changes);
        if (done.isEmpty() && !done.wait(30000))
            return {false, {}, QStringLiteral("no applyFinished")};
        return done.first().at(0).value<ConfigurationController::ApplyReport>();
    }
    bool action(const QString &key, const QString &arg = QString(), QString *detail = nullptr)
    {
        QSignalSpy done(&controller, &ConfigurationController::actionFinished);
        controller.runAction(key, arg);
        if (done.isEmpty() && !done.wait(30000))
            return false;
        if (detail)
            *detail = done.first().at(2).toString();
        return done.first().at(1).toBool();
    }
    QString value(const char *key) const
    {
        return controller.configuration().value(QLatin1String(key)).value_or(QStringLiteral("<none>"));
    }
    int deviceBaud() { return sim.deviceBaud(); }
};

QString describe(const ConfigurationController::ApplyReport &r)
{
    QStringList s{r.error};
    for (const auto &c : r.results)
        s << QStringLiteral("%1=%2 -> %3 (%4) %5")
                 .arg(c.key, c.requested, c.deviceValue, ConfigurationController::outcomeName(c.outcome), c.detail);
    return s.join(QLatin1String("; "));
}

} // namespace

class TstConfiguration : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void roundTrip_data()
    {
        QTest::addColumn<QString>("firmware");
        QTest::addColumn<QString>("model");
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("value");
        auto row = [](const char *fw, const char *m, const char *k, const char *v) {
            QTest::newRow(qPrintable(QStringLiteral("%1 %2 %3=%4").arg(QLatin1String(fw), QLatin1String(m),
                                                                        QLatin1String(k), QLatin1String(v))))
                << fw << m << k << v;
        };
        row("1.7.1", "HI14", "LOG.HI91", "0.02");
        row("1.7.1", "HI14", "LOG.HI81", "0.1");
        row("1.7.1", "HI14", "LOG.HI83", "ONMARK");
        row("1.7.1", "HI14", "LOG.GGA", "1");
        row("1.7.1", "HI14", "LOG.RMC", "0.5");
        row("1.7.1", "HI14", "LOG.SXT", "0.2");
        row("1.7.1", "HI14", "LOG.HI83.MAP", "0x0000001F");
        row("1.7.1", "HI14", "ATT.MODE", "0");
        row("1.7.1", "HI14", "ATT.MODE", "4");
        row("1.7.1", "HI14", "IMU.URFR", "205");
        row("1.7.1", "HI14", "IMU.URFR", "531");
        row("1.7.1", "HI14", "IMU.COORD", "4");
        row("1.7.1", "HI14", "PMUX1", "IO3");
        row("1.7.1", "HI14", "PMUX2", "IO4");
        row("1.7.1", "HI14", "PMUX3", "IO2");
        row("1.7.1", "HI14", "PMUX2.DIV", "5");
        row("1.7.1", "HI92", "ATT.MODE", "0");
        row("1.7.1", "HI50", "IMU.URFR", "43");
        row("1.6.6", "HI14", "LOG.HI91", "ONMARK");
        row("1.6.6", "HI14", "LOG.HI92", "0.05");
        row("1.6.6", "HI14", "ATT.MODE", "0");
        row("1.6.6", "HI14", "IMU.URFR", "52");
        row("1.6.6", "HI14", "IMU.URFR", "0.6,0.8,0,-0.8,0.6,0,0,0,1");
        row("1.6.6", "HI14", "PMUX2", "IO9");
        row("1.6.6", "HI14", "IMU_EN_MCAL", "0");
    }
    void roundTrip()
    {
        QFETCH(QString, firmware);
        QFETCH(QString, model);
        QFETCH(QString, key);
        QFETCH(QString, value);
        Bench b(qPrintable(firmware), qPrintable(model));
        QVERIFY(b.start());
        QVERIFY(b.value(qPrintable(key)) != value); // a real change
        const auto report = b.apply({{key, value}});
        QVERIFY2(report.ok, qPrintable(describe(report)));
        QCOMPARE(report.results.front().outcome, Outcome::Verified);
        QVERIFY(b.action(QStringLiteral("SAVECONFIG")));
        QVERIFY(b.action(QStringLiteral("REBOOT")));
        QCOMPARE(b.value(qPrintable(key)), value);
    }

    void unsavedGoneAfterReboot()
    {
        Bench b;
        QVERIFY(b.start());
        const auto report = b.apply({{QStringLiteral("ATT.MODE"), QStringLiteral("0")},
                                     {QStringLiteral("LOG.HI91"), QStringLiteral("0.02")},
                                     {QStringLiteral("LOG"), QStringLiteral("DISABLE")}});
        QVERIFY2(report.ok, qPrintable(describe(report)));
        QCOMPARE(b.value("ATT.MODE"), QStringLiteral("0"));
        QCOMPARE(b.value("LOG"), QStringLiteral("DISABLE"));
        QVERIFY(b.action(QStringLiteral("REBOOT")));
        QCOMPARE(b.value("ATT.MODE"), QStringLiteral("1"));
        QCOMPARE(b.value("LOG.HI91"), QStringLiteral("0.01"));
        QCOMPARE(b.value("LOG"), QStringLiteral("ENABLE"));
    }

    void factoryResetRestoresDefaults()
    {
        Bench b;
        QVERIFY(b.start());
        const auto before = b.controller.configuration().values;
        auto report = b.apply({{QStringLiteral("IMU.URFR"), QStringLiteral("205")},
                               {QStringLiteral("LOG.HI91"), QStringLiteral("0.005")},
                               {QStringLiteral("PMUX2.DIV"), QStringLiteral("10")},
                               {QStringLiteral("SERIAL.BAUD"), QStringLiteral("460800")}});
        QVERIFY2(report.ok, qPrintable(describe(report)));
        QVERIFY(b.action(QStringLiteral("SAVECONFIG")));
        QVERIFY(b.action(QStringLiteral("REBOOT")));
        QCOMPARE(b.value("SERIAL.BAUD"), QStringLiteral("460800"));
        QCOMPARE(b.deviceBaud(), 460800);
        QString detail;
        QVERIFY2(b.action(QStringLiteral("FRESET"), QString(), &detail), qPrintable(detail));
        QCOMPARE(b.deviceBaud(), 115200);
        QCOMPARE(b.controller.configuration().values, before);
    }

    void baudChange()
    {
        Bench b;
        QVERIFY(b.start());
        const auto report = b.apply({{QStringLiteral("SERIAL.BAUD"), QStringLiteral("921600")}});
        QVERIFY2(report.ok, qPrintable(describe(report)));
        QCOMPARE(b.deviceBaud(), 921600);
        QCOMPARE(b.value("SERIAL.BAUD"), QStringLiteral("921600"));
        QVERIFY(b.action(QStringLiteral("SAVECONFIG")));
        QVERIFY(b.action(QStringLiteral("REBOOT")));
        QCOMPARE(b.value("SERIAL.BAUD"), QStringLiteral("921600"));
        // Not saved: back at the saved rate after a reboot, and the session finds it there.
        QVERIFY(b.apply({{QStringLiteral("SERIAL.BAUD"), QStringLiteral("230400")}}).ok);
        QCOMPARE(b.deviceBaud(), 230400);
        QVERIFY(b.action(QStringLiteral("REBOOT")));
        QCOMPARE(b.deviceBaud(), 921600);
        QCOMPARE(b.value("SERIAL.BAUD"), QStringLiteral("921600"));
    }

    // The module says OK but keeps its old rate: the session goes back to it.
    void baudChangeIgnored()
    {
        Bench b;
        QVERIFY(b.start());
        b.sim.withDevice([](sim::HipnucSimulator &d) { d.setBaudChangeOverride(-1); });
        const auto report = b.apply({{QStringLiteral("SERIAL.BAUD"), QStringLiteral("460800")}});
        QVERIFY(!report.ok);
        QVERIFY(report.results.front().outcome != Outcome::Verified);
        QVERIFY(report.results.front().detail.contains(QLatin1String("115200")));
        QCOMPARE(b.deviceBaud(), 115200);
        QVERIFY(b.read()); // still reachable
    }

    // The module goes to a rate nobody asked for: found again by auto-detection.
    void baudChangeRecoversByDetection()
    {
        Bench b;
        QVERIFY(b.start());
        b.sim.withDevice([](sim::HipnucSimulator &d) { d.setBaudChangeOverride(38400); });
        QSignalSpy detected(&b.session, &device::DeviceSession::baudDetected);
        const auto report = b.apply({{QStringLiteral("SERIAL.BAUD"), QStringLiteral("921600")}});
        QVERIFY(!report.ok);
        QCOMPARE(report.results.front().outcome, Outcome::Refused);
        QVERIFY(!detected.isEmpty());
        QCOMPARE(detected.last().at(0).toInt(), 38400);
        QVERIFY(b.read());
        QCOMPARE(b.controller.identity().productName, std::string("HI14R3"));
    }

    // ERR stops the flow; the configuration is read again and shows the device's state.
    void errLeavesTrueState()
    {
        Bench b;
        QVERIFY(b.start());
        b.sim.withDevice([](sim::HipnucSimulator &d) { d.setRefusedCommand("CONFIG IMU COORD"); });
        QSignalSpy changed(&b.controller, &ConfigurationController::configurationChanged);
        const auto report = b.apply({{QStringLiteral("ATT.MODE"), QStringLiteral("0")},
                                     {QStringLiteral("IMU.COORD"), QStringLiteral("4")},
                                     {QStringLiteral("IMU.URFR"), QStringLiteral("205")}});
        QVERIFY(!report.ok);
        QCOMPARE(int(report.results.size()), 3);
        QCOMPARE(report.results[0].outcome, Outcome::Verified);
        QCOMPARE(report.results[1].outcome, Outcome::Refused);
        QCOMPARE(report.results[2].outcome, Outcome::NotSent);
        QVERIFY(!changed.isEmpty());
        int mode = -1, coord = -1, urfr = -1;
        b.sim.withDevice([&](sim::HipnucSimulator &d) {
            mode = d.runningConfig().attMode;
            coord = d.runningConfig().coord;
            urfr = d.runningConfig().urfrCode;
        });
        QCOMPARE(b.value("ATT.MODE"), QString::number(mode));
        QCOMPARE(b.value("IMU.COORD"), QString::number(coord));
        QCOMPARE(b.value("IMU.URFR"), QString::number(urfr));
        QCOMPARE(report.results[1].deviceValue, QStringLiteral("0"));
    }

    // No reply at all (the module sits in its bootloader): nothing is claimed, the last
    // values read stay, and the report says why.
    void timeoutLeavesTrueState()
    {
        Bench b;
        QVERIFY(b.start());
        const auto before = b.controller.configuration().values;
        QSignalSpy bl(&b.session, &device::DeviceSession::commandFinished);
        b.session.sendText(QStringLiteral("REBOOT BL"));
        QVERIFY(bl.wait(3000));
        QTRY_COMPARE(b.sim.deviceState(), sim::HipnucSimulator::State::Bootloader);
        const auto report = b.apply({{QStringLiteral("ATT.MODE"), QStringLiteral("0")}});
        QVERIFY(!report.ok);
        QCOMPARE(report.results.front().outcome, Outcome::Timeout);
        QVERIFY(!report.error.isEmpty());
        QCOMPARE(b.controller.configuration().values, before);
        int mode = -1;
        b.sim.withDevice([&](sim::HipnucSimulator &d) {
            d.powerCycle();
            mode = d.runningConfig().attMode;
        });
        QCOMPARE(b.value("ATT.MODE"), QString::number(mode));
        QVERIFY(b.read());
    }

    void refusedBeforeSending()
    {
        Bench b("1.6.6");
        QVERIFY(b.start());
        QSignalSpy sent(&b.controller, &ConfigurationController::commandSent);
        const auto report = b.apply({{QStringLiteral("IMU.COORD"), QStringLiteral("4")},
                                     {QStringLiteral("ATT.MODE"), QStringLiteral("4")}});
        QVERIFY(!report.ok);
        QVERIFY2(report.error.contains(QLatin1String("IMU.COORD")), qPrintable(report.error));
        QVERIFY(report.error.contains(QLatin1String("ATT.MODE")));
        QCOMPARE(sent.count(), 0);
        QString detail;
        QVERIFY(!b.action(QStringLiteral("ATT.RST.1"), QString(), &detail));
        QCOMPARE(sent.count(), 0);
        QVERIFY2(b.action(QStringLiteral("YAW"), QStringLiteral("1,16"), &detail), qPrintable(detail));
        QVERIFY2(b.action(QStringLiteral("ATT.RST.3"), QString(), &detail), qPrintable(detail));
    }

    void pendingCommandsAndCliLine()
    {
        Bench b;
        QVERIFY(b.start());
        const std::vector<Change> changes = {{QStringLiteral("serial.baud"), QStringLiteral("921600")},
                                             {QStringLiteral("IMU.URFR"), QStringLiteral("024")},
                                             {QStringLiteral("LOG.HI91"), QStringLiteral("ONTIME 0.005")}};
        const auto plan = b.controller.plan(changes);
        QVERIFY(plan.ok());
        QCOMPARE(int(plan.commands.size()), 3);
        QCOMPARE(QString::fromStdString(plan.commands[0].command.text), QStringLiteral("CONFIG IMU URFR 24"));
        QCOMPARE(QString::fromStdString(plan.commands[1].command.text), QStringLiteral("LOG HI91 ONTIME 0.005"));
        QCOMPARE(QString::fromStdString(plan.commands[2].command.text), QStringLiteral("SERIALCONFIG 921600"));
        QCOMPARE(ConfigurationController::cliLine(QStringLiteral("/dev/ttyUSB0"), plan.changes, true, false),
                 QStringLiteral("imudesk-cli config /dev/ttyUSB0 set IMU.URFR=24 LOG.HI91=0.005 SERIAL.BAUD=921600 "
                                "--save"));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstConfiguration)
#include "tst_configuration.moc"
