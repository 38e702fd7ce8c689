// imudesk-cli against the CAN simulator over virtualcan, as separate processes: simulate --can,
// can list/read/scan/reg/sdo/sync, JSON output and exit codes. This executable uses its own
// virtualcan TCP port; the simulator process owns the plugin's server.

#include "../common/cli_process.h"
#include "../common/test_main.h"

#include <QCanBus>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>

namespace {
const QString kCli = QString::fromUtf8(IMUDESK_CLI_PATH);

struct Run {
    int code = -1;
    QString out, err;
};

Run cli(const QStringList &args, int timeoutMs = 20000)
{
    QProcess p;
    p.start(kCli, args);
    Run r;
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished();
        r.err = QStringLiteral("timed out");
        return r;
    }
    r.code = p.exitCode();
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}
} // namespace

class TstCliCan : public QObject {
    Q_OBJECT
    QProcess m_sim;
    QString m_iface;

    bool startSim(const QStringList &extra, int port)
    {
        m_iface = QStringLiteral("tcp://127.0.0.1:%1/can0").arg(port);
        return imudesk::test::startCliUntil(
            m_sim, QStringList{QStringLiteral("simulate"), QStringLiteral("--can"), QStringLiteral("virtualcan:") + m_iface} + extra,
            "can: ");
    }
    void stopSim() { imudesk::test::stopCli(m_sim, 3000); }
    QStringList can(const QStringList &rest) const
    {
        return QStringList{QStringLiteral("can"), QStringLiteral("--interface"), m_iface} + rest;
    }

private Q_SLOTS:
    void initTestCase()
    {
        if (!QCanBus::instance()->plugins().contains(QStringLiteral("virtualcan")))
            QSKIP("Qt's virtualcan CAN bus plugin is not installed (package libqt6serialbus6-plugins)");
    }
    void cleanup() { stopSim(); }

    void list()
    {
        const Run r = cli({QStringLiteral("can"), QStringLiteral("list"), QStringLiteral("--json")});
        QCOMPARE(r.code, 0);
        QVERIFY2(r.out.contains(QStringLiteral("{\"plugin\":\"virtualcan\",\"interfaces\":[\"can0\",\"can1\"]}")), qPrintable(r.out));
    }

    void usageErrors()
    {
        QCOMPARE(cli({QStringLiteral("can")}).code, 2);
        QCOMPARE(cli({QStringLiteral("can"), QStringLiteral("--protocol"), QStringLiteral("x"), QStringLiteral("read")}).code, 2);
        QCOMPARE(cli({QStringLiteral("simulate"), QStringLiteral("--can"), QStringLiteral("virtualcan")}).code, 2);
        QCOMPARE(cli({QStringLiteral("simulate"), QStringLiteral("--can"), QStringLiteral("virtualcan:can0"), QStringLiteral("--protocol"),
                      QStringLiteral("modbus")}).code, 2);
    }

    void canopenSession()
    {
        QVERIFY(startSim({QStringLiteral("--protocol"), QStringLiteral("canopen"), QStringLiteral("--motion"), QStringLiteral("tumble")}, 35483));
        // 8.28.45.24: TPDO1 period 50 ms, read back.
        Run r = cli(can({QStringLiteral("sdo"), QStringLiteral("write"), QStringLiteral("0x1800"), QStringLiteral("5"), QStringLiteral("50"),
                         QStringLiteral("--size"), QStringLiteral("2")}));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        r = cli(can({QStringLiteral("sdo"), QStringLiteral("read"), QStringLiteral("0x1800"), QStringLiteral("5"), QStringLiteral("--json")}));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QCOMPARE(QJsonDocument::fromJson(r.out.toUtf8()).object().value(QStringLiteral("value")).toInt(), 50);
        // An object the module does not have: the abort, exit 1.
        r = cli(can({QStringLiteral("sdo"), QStringLiteral("read"), QStringLiteral("0x2123"), QStringLiteral("0")}));
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("does not exist")), qPrintable(r.err));
        // Samples as JSON Lines.
        r = cli(can({QStringLiteral("read"), QStringLiteral("--duration"), QStringLiteral("0.6"), QStringLiteral("--json")}));
        QCOMPARE(r.code, 0);
        const QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QVERIFY(lines.size() > 20);
        const QJsonObject o = QJsonDocument::fromJson(lines.last().toUtf8()).object();
        QVERIFY2(o.contains(QStringLiteral("acc")) && o.contains(QStringLiteral("quat")), qPrintable(lines.last()));
        // Active scan finds node 8.
        r = cli(can({QStringLiteral("scan"), QStringLiteral("--active"), QStringLiteral("--duration"), QStringLiteral("0.3"), QStringLiteral("--json")}));
        QCOMPARE(r.code, 0);
        QVERIFY2(r.out.contains(QStringLiteral("\"node\":8")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("{\"sdo_scan\":[8]}")), qPrintable(r.out));
        // SYNC frames.
        r = cli(can({QStringLiteral("--protocol"), QStringLiteral("canopen"), QStringLiteral("sync"), QStringLiteral("--count"), QStringLiteral("3")}));
        QCOMPARE(r.code, 0);
        QVERIFY(r.out.startsWith(QStringLiteral("SYNC sent: 3")));
    }

    void j1939Session()
    {
        QVERIFY(startSim({QStringLiteral("--protocol"), QStringLiteral("j1939"), QStringLiteral("--node"), QStringLiteral("9")}, 35484));
        Run r = cli(can({QStringLiteral("--node"), QStringLiteral("9"), QStringLiteral("reg"), QStringLiteral("write"), QStringLiteral("0x0137"),
                         QStringLiteral("100")}));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        r = cli(can({QStringLiteral("--node"), QStringLiteral("9"), QStringLiteral("reg"), QStringLiteral("read"), QStringLiteral("0x0137")}));
        QVERIFY2(r.code == 0 && r.out.startsWith(QStringLiteral("register 0x0137: 100")), qPrintable(r.out + r.err));
        r = cli(can({QStringLiteral("--node"), QStringLiteral("9"), QStringLiteral("reg"), QStringLiteral("write"), QStringLiteral("0x0137"),
                     QStringLiteral("4")}));
        QCOMPARE(r.code, 1);
        r = cli(can({QStringLiteral("read"), QStringLiteral("--duration"), QStringLiteral("0.5")}));
        QCOMPARE(r.code, 0);
        QVERIFY2(r.out.contains(QStringLiteral("protocol: j1939")), qPrintable(r.out));
        QVERIFY(r.out.contains(QStringLiteral("node 9")));
        // Typed settings: the inclinometer's X direction reversed (0x9E), read back.
        r = cli(can({QStringLiteral("--protocol"), QStringLiteral("j1939"), QStringLiteral("--node"), QStringLiteral("9"),
                     QStringLiteral("set"), QStringLiteral("incl-sign-x"), QStringLiteral("1")}));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        r = cli(can({QStringLiteral("--node"), QStringLiteral("9"), QStringLiteral("reg"), QStringLiteral("read"), QStringLiteral("0x009E")}));
        QVERIFY2(r.code == 0 && r.out.startsWith(QStringLiteral("register 0x009e: 1")), qPrintable(r.out + r.err));
        // Settings the protocol does not have, and bad values: refused with the reason.
        r = cli(can({QStringLiteral("--protocol"), QStringLiteral("j1939"), QStringLiteral("--node"), QStringLiteral("9"),
                     QStringLiteral("set"), QStringLiteral("work-mode"), QStringLiteral("2")}));
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("HEC495")), qPrintable(r.err));
        QCOMPARE(cli(can({QStringLiteral("--protocol"), QStringLiteral("j1939"), QStringLiteral("set"), QStringLiteral("incl-sign-x"),
                          QStringLiteral("2")})).code, 2);
        QCOMPARE(cli(can({QStringLiteral("set"), QStringLiteral("incl-sign-x"), QStringLiteral("1")})).code, 2); // no protocol
    }

    void hec495Session()
    {
        QVERIFY(startSim({QStringLiteral("--protocol"), QStringLiteral("canopen"), QStringLiteral("--device"), QStringLiteral("hec495")}, 35485));
        Run r = cli(can({QStringLiteral("--protocol"), QStringLiteral("hec495"), QStringLiteral("sdo"), QStringLiteral("write"),
                         QStringLiteral("0x6200"), QStringLiteral("0"), QStringLiteral("6")}));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        r = cli(can({QStringLiteral("scan"), QStringLiteral("--duration"), QStringLiteral("1.2")}));
        QVERIFY2(r.out.contains(QStringLiteral("node 5 (hec495, data)")), qPrintable(r.out));
        // PDO and work modes as typed settings; every node off and on again (NMT to node 0),
        // confirmed by the PDOs stopping and starting.
        const QStringList hec = {QStringLiteral("--protocol"), QStringLiteral("hec495")};
        r = cli(can(hec + QStringList{QStringLiteral("set"), QStringLiteral("pdo-mode"), QStringLiteral("1")}));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        r = cli(can(hec + QStringList{QStringLiteral("set"), QStringLiteral("work-mode"), QStringLiteral("0x0A")}));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        r = cli(can(hec + QStringList{QStringLiteral("set"), QStringLiteral("pdo-mode"), QStringLiteral("2")}));
        QCOMPARE(r.code, 1);
        r = cli(can(hec + QStringList{QStringLiteral("output"), QStringLiteral("off"), QStringLiteral("--all")}));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        r = cli(can(hec + QStringList{QStringLiteral("output"), QStringLiteral("on"), QStringLiteral("--all")}));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        // The extended variant has no NMT for every node: said.
        r = cli(can(hec + QStringList{QStringLiteral("--extended"), QStringLiteral("output"), QStringLiteral("off"), QStringLiteral("--all")}));
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("standard frames")), qPrintable(r.err));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCliCan)
#include "tst_cli_can.moc"
