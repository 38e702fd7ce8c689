// imudesk-cli against the simulated HEC495 on a pseudo-terminal: "simulate --device hec495",
// "probe" telling an HEC495 from a HiPNUC module, and every "hec495" action, including a
// planar calibration run.
#include "../common/cli_run.h"
#include "../common/test_main.h"
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>

#include <csignal>

namespace {

using Result = imudesk::test::CliResult;

Result run(const QStringList &args, int timeoutMs = 60000)
{
    return imudesk::test::runCli(args, timeoutMs);
}

// Starts "imudesk-cli simulate --pty ..." and returns the pty path.
QString startSimulator(QProcess &sim, const QStringList &args)
{
    sim.start(QString::fromUtf8(IMUDESK_CLI_PATH), QStringList{"simulate", "--pty"} + args);
    if (!sim.waitForStarted())
        return {};
    for (int i = 0; i < 100 && !sim.canReadLine(); ++i)
        sim.waitForReadyRead(100);
    const QString first = QString::fromUtf8(sim.readLine()).trimmed();
    return first.startsWith(QStringLiteral("pty: /dev/")) ? first.mid(5) : QString();
}

void stopSimulator(QProcess &sim)
{
    ::kill(pid_t(sim.processId()), SIGTERM);
    sim.waitForFinished(5000);
}

} // namespace

class TstHec495Cli : public QObject {
    Q_OBJECT
    QProcess m_sim;
    QString m_pty;

private Q_SLOTS:
    void initTestCase()
    {
        m_pty = startSimulator(m_sim, {"--device", "hec495", "--motion", "spin", "--seed", "4"});
        QVERIFY(!m_pty.isEmpty());
    }

    void cleanupTestCase()
    {
        stopSimulator(m_sim);
        QCOMPARE(m_sim.exitStatus(), QProcess::NormalExit);
        QCOMPARE(m_sim.exitCode(), 0);
    }

    void probeDetectsTheHec495()
    {
        const auto r = run({"probe", m_pty, "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const auto o = r.json();
        QCOMPARE(o.value("family").toString(), QStringLiteral("hec495"));
        QCOMPARE(o.value("product").toString(), QStringLiteral("HEC495"));
        QCOMPARE(o.value("baud").toInt(), 9600);
        QCOMPARE(o.value("address").toInt(), 0);
    }

    void probeTellsHipnucAndOtherAddresses()
    {
        QProcess hipnuc;
        const QString hp = startSimulator(hipnuc, {"--baud", "115200"});
        QVERIFY(!hp.isEmpty());
        auto r = run({"probe", hp, "--json"});
        stopSimulator(hipnuc);
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QCOMPARE(r.json().value("family").toString(), QStringLiteral("hipnuc"));
        QCOMPARE(r.json().value("product").toString(), QStringLiteral("HI14R3"));

        QProcess other;
        const QString op = startSimulator(other, {"--device", "hec495", "--baud", "19200", "--address", "5"});
        QVERIFY(!op.isEmpty());
        r = run({"probe", op, "--json"});
        const auto info = run({"hec495", op, "--address", "5", "info", "--json"});
        stopSimulator(other);
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QCOMPARE(r.json().value("family").toString(), QStringLiteral("hec495"));
        QCOMPARE(r.json().value("baud").toInt(), 19200);
        QCOMPARE(r.json().value("address").toInt(), 5);
        QVERIFY2(info.code == 0, qPrintable(info.err));
        QCOMPARE(info.json().value("baud").toInt(), 19200);
        QCOMPARE(info.json().value("address").toInt(), 5);
    }

    void settings()
    {
        auto r = run({"hec495", m_pty, "--baud", "9600", "declination", "-3.2"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        r = run({"hec495", m_pty, "declination", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QCOMPARE(r.json().value("declination").toDouble(), -3.2);
        r = run({"hec495", m_pty, "content", "all", "--json"});
        QCOMPARE(r.json().value("status").toString(), QStringLiteral("ok"));
        r = run({"hec495", m_pty, "read", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY(qAbs(r.json().value("acc").toArray().at(2).toDouble() - 1.0) < 0.01);
        QVERIFY(qAbs(r.json().value("gyr").toArray().at(2).toDouble() - 30.0) < 1.0); // spin
        // Streaming at 50 Hz: requests still answered.
        r = run({"hec495", m_pty, "rate", "50"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        r = run({"hec495", m_pty, "info", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QCOMPARE(r.json().value("streaming").toBool(), true);
        QVERIFY2(run({"hec495", m_pty, "rate", "0"}).code == 0, "rate 0");
        // NMEA output: the sentences as they come, with their heading (spinning at 30 deg/s).
        QVERIFY2(run({"hec495", m_pty, "content", "nmea"}).code == 0, "content nmea");
        QVERIFY2(run({"hec495", m_pty, "rate", "10"}).code == 0, "rate 10");
        r = run({"hec495", m_pty, "nmea", "--count", "3", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 3);
        double previous = -1;
        for (const QString &line : lines) {
            const QJsonObject o = QJsonDocument::fromJson(line.toUtf8()).object();
            QVERIFY2(o.value("sentence").toString().startsWith(QStringLiteral("$HCHDT,")), qPrintable(line));
            const double h = o.value("heading_true").toDouble(-1);
            QVERIFY2(h >= 0 && h < 360 && h != previous, qPrintable(line));
            previous = h;
        }
        QVERIFY2(run({"hec495", m_pty, "rate", "0"}).code == 0, "rate 0");
        QVERIFY2(run({"hec495", m_pty, "content", "default"}).code == 0, "content default");
        // No NMEA output: said, with what to do.
        r = run({"hec495", m_pty, "nmea"});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("content nmea")), qPrintable(r.err));
        // Invalid values: refused before the wire, and usage errors.
        r = run({"hec495", m_pty, "baud", "38400"});
        QCOMPARE(r.code, 1);
        QVERIFY(r.err.contains(QStringLiteral("115200")));
        QCOMPARE(run({"hec495", m_pty, "fly"}).code, 2);
        QCOMPARE(run({"hec495", m_pty, "rate"}).code, 2);
    }

    void baudChangeThenCalibrate()
    {
        auto r = run({"hec495", m_pty, "baud", "115200", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        // An automatic method asks before it saves: "n" stops it (0x12), nothing saved.
        QProcess asked;
        asked.start(QString::fromUtf8(IMUDESK_CLI_PATH), {"hec495", m_pty, "--baud", "115200", "calibrate", "planar"});
        QVERIFY(asked.waitForStarted());
        QString err;
        for (int i = 0; i < 1200 && !err.contains(QStringLiteral("[y/N]")); ++i) {
            asked.waitForReadyRead(50);
            err += QString::fromUtf8(asked.readAllStandardError());
        }
        QVERIFY2(err.contains(QStringLiteral("points collected. Save this calibration to the compass? [y/N]")), qPrintable(err));
        asked.write("n\n");
        QVERIFY(asked.waitForFinished(10000));
        err += QString::fromUtf8(asked.readAllStandardError());
        QCOMPARE(asked.exitCode(), 1);
        QVERIFY2(err.contains(QStringLiteral("not confirmed")) && err.contains(QStringLiteral("nothing saved")), qPrintable(err));
        QVERIFY(!QString::fromUtf8(asked.readAllStandardOutput()).contains(QStringLiteral("calibration saved")));
        // A script saves with --save, without a question.
        r = run({"hec495", m_pty, "--baud", "115200", "calibrate", "planar", "--save", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY(!r.err.contains(QStringLiteral("[y/N]")));
        const auto o = r.json();
        QCOMPARE(o.value("points").toInt(), 12);
        QVERIFY(o.value("fit_error").toDouble() > 0.0);
        QVERIFY(o.value("fit_error").toDouble() < 10.0);
        r = run({"hec495", m_pty, "--baud", "115200", "reset"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        r = run({"hec495", m_pty, "info", "--json"}); // back to 9600 after the factory reset
        QCOMPARE(r.json().value("baud").toInt(), 9600);
        QCOMPARE(r.json().value("declination").toDouble(), 0.0);
    }

    // 2.1-2.4 single readings.
    void singleAngles()
    {
        auto r = run({"hec495", m_pty, "angle", "heading", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const double h = r.json().value("heading").toDouble(-1);
        QVERIFY2(h >= 0 && h < 360, qPrintable(r.out));
        r = run({"hec495", m_pty, "angle", "all", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.json().contains("pitch") && r.json().contains("roll") && r.json().contains("heading"), qPrintable(r.out));
        r = run({"hec495", m_pty, "angle", "pitch"});
        QVERIFY2(r.code == 0 && r.out.contains(QStringLiteral(" deg")), qPrintable(r.out + r.err));
        QCOMPARE(run({"hec495", m_pty, "angle", "yaw"}).code, 2);
        QCOMPARE(run({"hec495", m_pty, "angle"}).code, 2);
    }

    // The manual method is paced by the operator: one point per Enter, "f" refused before 12
    // points, and nothing saved without a yes or --save; scripts pace it with --auto-interval.
    void manualCalibrationPacedByTheOperator()
    {
        QProcess cli;
        cli.start(QString::fromUtf8(IMUDESK_CLI_PATH), {"hec495", m_pty, "calibrate", "manual"});
        QVERIFY(cli.waitForStarted());
        QString err;
        const auto waitErr = [&](const QString &text) {
            for (int i = 0; i < 200 && !err.contains(text); ++i) {
                cli.waitForReadyRead(50);
                err += QString::fromUtf8(cli.readAllStandardError());
            }
            return err.contains(text);
        };
        QVERIFY2(waitErr(QStringLiteral("point 1: turn the compass")), qPrintable(err));
        QVERIFY(cli.state() == QProcess::Running); // waits for the operator, collects nothing by itself
        for (int n = 1; n <= 5; ++n) {
            cli.write("\n");
            QVERIFY2(waitErr(QStringLiteral("point %1: turn").arg(n + 1)), qPrintable(err));
        }
        cli.write("f\n");
        QVERIFY2(waitErr(QStringLiteral("at least 12 points are needed; 5 so far")), qPrintable(err));
        for (int n = 6; n <= 12; ++n) {
            cli.write("\n");
            QVERIFY2(waitErr(QStringLiteral("point %1: turn").arg(n + 1)), qPrintable(err));
        }
        cli.write("f\n");
        QVERIFY2(waitErr(QStringLiteral("Save this calibration to the compass? [y/N]")), qPrintable(err));
        cli.write("n\n");
        QVERIFY(cli.waitForFinished(10000));
        err += QString::fromUtf8(cli.readAllStandardError());
        const QString out = QString::fromUtf8(cli.readAllStandardOutput());
        QCOMPARE(cli.exitCode(), 1);
        QVERIFY2(err.contains(QStringLiteral("not confirmed")) && err.contains(QStringLiteral("nothing saved")), qPrintable(err));
        QVERIFY2(out.contains(QStringLiteral("point 12")) && !out.contains(QStringLiteral("calibration saved")), qPrintable(out));

        // No operator and no interval: stopped at once, with what to do.
        QProcess noInput;
        noInput.start(QString::fromUtf8(IMUDESK_CLI_PATH), {"hec495", m_pty, "calibrate", "manual"});
        QVERIFY(noInput.waitForStarted());
        noInput.closeWriteChannel();
        QVERIFY(noInput.waitForFinished(20000));
        QCOMPARE(noInput.exitCode(), 1);
        QVERIFY2(QString::fromUtf8(noInput.readAllStandardError()).contains(QStringLiteral("--auto-interval")), "no hint");

        // A script: every 0.2 s, saved because --save says so.
        auto r = run({"hec495", m_pty, "calibrate", "manual", "--auto-interval", "0.2", "--save", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QCOMPARE(r.json().value("points").toInt(), 12);
        QCOMPARE(run({"hec495", m_pty, "calibrate", "planar", "--auto-interval", "1", "--save"}).code, 2);
        QCOMPARE(run({"hec495", m_pty, "info", "--save"}).code, 2);
        QCOMPARE(run({"hec495", m_pty, "calibrate", "manual", "--auto-interval", "0"}).code, 2);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstHec495Cli)
#include "tst_hec495_cli.moc"
