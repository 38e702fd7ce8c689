// imudesk-cli calibrate against simulated modules on pseudo-terminals: the gyro scale run on a
// simulated turntable (START, the turn followed, STOP once still, the device's OK), a STOP
// the device refuses, the magnetometer calibration's progress and a module without a
// magnetometer, auto level and heading reset with their checks, and the HEC495's clear.
#include "../common/cli_run.h"
#include "../common/test_main.h"
#include "sim/hec495_simulator.h"
#include "sim/hipnuc_simulator.h"
#include "sim/pty_simulator.h"

#include <QTest>

#include <memory>

using namespace imudesk;

namespace {

std::unique_ptr<sim::PtySimulator> serve(sim::Motion motion, const char *model = "HI14", const char *firmware = "1.7.1")
{
    sim::SimOptions o;
    o.model = model;
    o.firmware = firmware;
    o.motion = motion;
    o.seed = 9;
    o.gyroScaleError = 0.005;
    auto pty = std::make_unique<sim::PtySimulator>(o);
    QString error;
    if (!pty->start(&error))
        qFatal("pty: %s", qPrintable(error));
    return pty;
}

test::CliResult calibrate(const sim::PtySimulator &pty, const QStringList &args, int timeoutMs = 60000)
{
    return test::runCli(QStringList{"calibrate", pty.devicePath()} + args + QStringList{"--baud", "115200", "--json"},
                        timeoutMs);
}

} // namespace

class TstCliCalibrate : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void gyroScaleOnTurntable()
    {
        // Still for 3 s, 720 deg at 45 deg/s, still: the CLI starts USRCAL while still, follows
        // the turn and stops once the module rests; the simulated device says OK.
        auto pty = serve(sim::Motion::Turntable);
        const auto r = calibrate(*pty, {"gyro-scale", "--angle", "720", "--timeout", "60"});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        const QJsonObject j = r.json();
        QCOMPARE(j.value("action").toString(), QStringLiteral("gyro-scale"));
        QCOMPARE(j.value("verdict").toString(), QStringLiteral("pass"));
        QVERIFY2(std::abs(j.value("turned_deg").toDouble() - 720) < 5, qPrintable(r.out));
        // The simulated gyro reads 0.5 % high: ImuDesk's own estimate sees it.
        QVERIFY2(std::abs(j.value("scale_error_pct_estimate").toDouble() - 0.5) < 0.15, qPrintable(r.out));
        QVERIFY2(r.err.contains(QStringLiteral("CONFIG USRCAL START 720")), qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("of 720 deg")), qPrintable(r.err)); // progress on stderr
    }

    void gyroScaleStoppedShortIsRefused()
    {
        // Asked for 1800 deg, stopped when the time given is up, halfway through the turntable's
        // 720: the device answers ERR (not within 5 deg of 1800).
        auto pty = serve(sim::Motion::Turntable);
        const auto r = calibrate(*pty, {"gyro-scale", "--angle", "1800", "--timeout", "12"});
        QCOMPARE(r.code, 1);
        QCOMPARE(r.json().value("verdict").toString(), QStringLiteral("fail"));
        QVERIFY2(r.json().value("message").toString().contains(QStringLiteral("1800")), qPrintable(r.out));
        // Usage errors: outside the manual's range.
        QCOMPARE(calibrate(*pty, {"gyro-scale", "--angle", "700"}).code, 2);
        QCOMPARE(calibrate(*pty, {"fly"}).code, 2);
    }

    void magnetometerProgressAndRefusal()
    {
        // A tumbling module: STAT 1 with growing PROGRESS on stderr until the time given runs out
        // (8 s: the CLI starts, connects and starts MCAL within it even on a loaded machine).
        auto pty = serve(sim::Motion::Tumble);
        auto r = calibrate(*pty, {"mag", "--timeout", "8"});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("mag: STAT 1")), qPrintable(r.err));
        QVERIFY(r.json().value("progress").toInt() > 0);
        QCOMPARE(r.json().value("verdict").toString(), QStringLiteral("fail"));
        QCOMPARE(r.json().value("heading_check").toString(), QStringLiteral("not run")); // after a failed MCAL
        // A module without a magnetometer refuses MCAL: said, exit code 1.
        auto hi02 = serve(sim::Motion::Tumble, "HI02");
        r = calibrate(*hi02, {"mag", "--timeout", "10"});
        QCOMPARE(r.code, 1);
        QVERIFY2(!r.json().value("message").toString().isEmpty(), qPrintable(r.out));
    }

    // The wizard's heading check (one level turn, the heading following without a jump above
    // 10 deg), also run after "calibrate mag": a module turning level at 30 deg/s passes within
    // the time given; one at rest has turned nothing when the time is up.
    void headingCheck()
    {
        auto spin = serve(sim::Motion::Spin);
        auto r = calibrate(*spin, {"heading-check", "--heading-timeout", "40"});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QCOMPARE(r.json().value("heading_check").toString(), QStringLiteral("pass"));
        QVERIFY2(r.json().value("heading_turned_deg").toDouble() >= 360, qPrintable(r.out));
        QVERIFY2(r.json().value("heading_max_step_deg").toDouble() < 10, qPrintable(r.out));
        QVERIFY2(r.err.contains(QStringLiteral("heading: turned ")), qPrintable(r.err)); // progress on stderr
        auto still = serve(sim::Motion::Static);
        r = calibrate(*still, {"heading-check", "--heading-timeout", "2"});
        QCOMPARE(r.code, 1);
        QCOMPARE(r.json().value("heading_check").toString(), QStringLiteral("fail"));
        QVERIFY2(r.json().value("message").toString().contains(QStringLiteral("cannot judge")), qPrintable(r.out));
        QCOMPARE(calibrate(*still, {"heading-check", "--heading-timeout", "0"}).code, 2);
    }

    void levelAndHeadingReset()
    {
        // The static simulated module lies slightly tilted, within 5 deg: auto level is sent.
        auto pty = serve(sim::Motion::Static);
        auto r = calibrate(*pty, {"level"});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QCOMPARE(r.json().value("command").toString(), QStringLiteral("CONFIG ATT RST 3"));
        r = calibrate(*pty, {"heading-reset"});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QCOMPARE(r.json().value("command").toString(), QStringLiteral("CONFIG ATT RST 1"));
        // A spinning module is not still: nothing is sent, and the message says what to do.
        auto spin = serve(sim::Motion::Spin);
        r = calibrate(*spin, {"level"});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.json().value("message").toString().contains(QStringLiteral("keep it still")), qPrintable(r.out));
        QVERIFY(!r.json().contains("command"));
    }

    void hec495Clear()
    {
        sim::Hec495Options o;
        o.baud = 9600;
        o.calibrated = true;
        sim::PtySimulator pty(std::make_unique<sim::Hec495Simulator>(o));
        QVERIFY(pty.start());
        const auto r = test::runCli({"calibrate", pty.devicePath(), "hec495-clear", "--baud", "9600", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QCOMPARE(r.json().value("verdict").toString(), QStringLiteral("pass"));
        bool cleared = false;
        pty.withSerialDevice([&](sim::SimulatedSerialDevice &d) {
            const auto &hec = dynamic_cast<sim::Hec495Simulator &>(d);
            cleared = !hec.calibrated() && hec.hardIronCorrection().isZero();
        });
        QVERIFY(cleared); // it was calibrated before
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCliCalibrate)
#include "tst_cli_calibrate.moc"
