// imudesk-cli modbus against `imudesk-cli simulate --pty --modbus`: info, read (decoded and raw),
// verified writes that change the node ID and baud, scan, the HEC495, exit codes and messages.
#include "../common/cli_run.h"
#include "../common/test_main.h"
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>

#include <csignal>
#include <memory>

namespace {

using Result = imudesk::test::CliResult;

Result run(const QStringList &args, int timeoutMs = 60000)
{
    return imudesk::test::runCli(args, timeoutMs);
}

QJsonObject json(const QString &line)
{
    return QJsonDocument::fromJson(line.trimmed().toUtf8()).object();
}

// Starts a simulator process and returns its pty path.
QString startSimulator(QProcess &sim, const QStringList &extra)
{
    sim.start(QString::fromUtf8(IMUDESK_CLI_PATH), QStringList{"simulate", "--pty", "--modbus"} + extra);
    if (!sim.waitForStarted())
        return {};
    for (int i = 0; i < 100 && !sim.canReadLine(); ++i)
        sim.waitForReadyRead(100);
    const QString first = QString::fromUtf8(sim.readLine()).trimmed();
    return first.startsWith(QStringLiteral("pty: /dev/")) ? first.mid(5) : QString();
}

void stopSimulator(QProcess &sim)
{
    if (sim.state() == QProcess::NotRunning)
        return;
    ::kill(pid_t(sim.processId()), SIGTERM);
    if (!sim.waitForFinished(5000)) {
        sim.kill();
        sim.waitForFinished();
    }
}

} // namespace

class TstModbusCli : public QObject {
    Q_OBJECT
    QProcess m_sim;
    QString m_pty;

private Q_SLOTS:
    void initTestCase()
    {
        m_pty = startSimulator(m_sim, {"--motion", "spin"});
        QVERIFY2(!m_pty.isEmpty(), "the simulator did not print its pty");
        QTRY_VERIFY(m_sim.canReadLine() || m_sim.waitForReadyRead(10));
        const QString second = QString::fromUtf8(m_sim.readLine()).trimmed();
        QCOMPARE(second, QStringLiteral("modbus: node 80, 115200 baud, 8N1"));
    }

    void cleanupTestCase() { stopSimulator(m_sim); }

    void info()
    {
        const Result r = run({"modbus", m_pty, "info", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject o = json(r.out);
        QCOMPARE(o.value("product").toString(), QStringLiteral("HI14R3N-485-000"));
        QCOMPARE(o.value("software").toString(), QStringLiteral("V1.71"));
        QCOMPARE(o.value("md_id").toInt(), 80);
        QCOMPARE(o.value("uart1_baud").toInt(), 115200);
        QCOMPARE(o.value("serial").toString().size(), 16);
    }

    void readDecoded()
    {
        const Result r = run({"modbus", m_pty, "read", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject o = json(r.out);
        QCOMPARE(o.value("type").toString(), QStringLiteral("MODBUS"));
        QVERIFY(std::abs(o.value("gyr").toArray().at(2).toDouble() - 30.0) < 1.0); // spin
        QVERIFY(std::abs(o.value("acc").toArray().at(2).toDouble() - 1.0) < 0.05);
    }

    void readRaw()
    {
        const Result r = run({"modbus", m_pty, "read", "PNAME", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonArray a = QJsonDocument::fromJson(r.out.trimmed().toUtf8()).array();
        QCOMPARE(a.size(), 8);
        QCOMPARE(a.at(0).toObject().value("value").toString(), QStringLiteral("HI14R3N-485-000"));
        const Result t = run({"modbus", m_pty, "read", "0x10"});
        QCOMPARE(t.code, 1);
        QVERIFY2(t.err.contains(QStringLiteral("ILLEGAL DATA ADDRESS")), qPrintable(t.err));
    }

    void usageErrors_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("no action") << QStringList{"modbus", "/dev/null"};
        QTest::newRow("bad action") << QStringList{"modbus", "/dev/null", "dance"};
        QTest::newRow("bad id") << QStringList{"modbus", "/dev/null", "--id", "300", "info"};
        QTest::newRow("write without value") << QStringList{"modbus", "/dev/null", "write", "MD_ID"};
        QTest::newRow("bad parity") << QStringList{"modbus", "/dev/null", "--parity", "mark", "info"};
    }
    void usageErrors()
    {
        QFETCH(QStringList, args);
        QCOMPARE(run(args).code, 2);
    }

    void writeIdAndBaudThenScan()
    {
        Result r = run({"modbus", m_pty, "write", "MD_ID", "85"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("Read back: 85")), qPrintable(r.out));
        r = run({"modbus", m_pty, "--id", "85", "write", "UART1_BAUD", "9600"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        r = run({"modbus", m_pty, "--id", "85", "--baud", "9600", "info", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QCOMPARE(json(r.out).value("md_id").toInt(), 85);
        QCOMPARE(json(r.out).value("uart1_baud").toInt(), 9600);
        // The old address and rate no longer answer.
        r = run({"modbus", m_pty, "--timeout", "200", "info"});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("No reply from node 80")), qPrintable(r.err));
        // A scan over two rates finds it at its new place. The probe timeout is set: the default
        // one (a few frame times) is for a bench PC, and this test also runs beside seven others.
        r = run({"modbus", m_pty, "scan", "--from", "83", "--to", "86", "--all-bauds", "--timeout", "400", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject hit = json(r.out.split(QLatin1Char('\n')).first());
        QCOMPARE(hit.value("node").toInt(), 85);
        QCOMPARE(hit.value("baud").toInt(), 9600);
        QVERIFY(hit.value("identified").toBool());
        // Refused locally: 129 is no node ID (v1.7.1 6.16: 1-128).
        r = run({"modbus", m_pty, "--id", "85", "--baud", "9600", "write", "MD_ID", "129"});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("MD_ID")), qPrintable(r.err));
        // Reset without saving: back to 80 at 115200.
        r = run({"modbus", m_pty, "--id", "85", "--baud", "9600", "write", "CTRL", "0xFF"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QTRY_COMPARE_WITH_TIMEOUT(run({"modbus", m_pty, "info"}).code, 0, 5000);
    }

    void hec495()
    {
        QProcess sim;
        const QString pty = startSimulator(sim, {"--device", "hec495", "--id", "7"});
        QVERIFY(!pty.isEmpty());
        Result r = run({"modbus", pty, "--device", "hec495", "--id", "7", "read", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QCOMPARE(json(r.out).value("type").toString(), QStringLiteral("HEC495"));
        r = run({"modbus", pty, "--device", "hec495", "--id", "7", "read", "PITCH"});
        QVERIFY2(r.code == 0 && r.out.contains(QStringLiteral("PITCH = -2.5")), qPrintable(r.out + r.err));
        stopSimulator(sim);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstModbusCli)
#include "tst_modbus_cli.moc"
