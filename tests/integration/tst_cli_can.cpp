// imudesk-cli against the CAN simulator over virtualcan, as separate processes: simulate --can,
// can list/read/scan/reg/sdo/sync, JSON output and exit codes. This executable uses its own
// virtualcan TCP port; the simulator process owns the plugin's server.

#include "../common/cli_process.h"
#include "../common/cli_run.h"
#include "../common/test_main.h"

#include <QCanBus>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTest>

#include <cmath>

namespace {
using Run = imudesk::test::CliResult;

// Each command's own waits end within 30 s, so a minute is a hang (reported with its stacks).
Run cli(const QStringList &args)
{
    return imudesk::test::runCli(args, 60000);
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
    // Each request may take 4 s to be answered (the default, 1 s, is a real bus's): on a loaded
    // machine, beside sanitizer builds, the simulator process is not always scheduled within 1 s.
    QStringList can(const QStringList &rest) const
    {
        return QStringList{QStringLiteral("can"), QStringLiteral("--interface"), m_iface, QStringLiteral("--timeout"),
                           QStringLiteral("4000")}
               + rest;
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
        const Run t = cli({QStringLiteral("can"), QStringLiteral("--timeout"), QStringLiteral("10"), QStringLiteral("scan")});
        QCOMPARE(t.code, 2);
        QVERIFY2(t.err.contains(QStringLiteral("--timeout needs milliseconds")), qPrintable(t.err));
        QCOMPARE(cli({QStringLiteral("can"), QStringLiteral("--protocol"), QStringLiteral("x"), QStringLiteral("read")}).code, 2);
        QCOMPARE(cli({QStringLiteral("simulate"), QStringLiteral("--can"), QStringLiteral("virtualcan")}).code, 2);
        QCOMPARE(cli({QStringLiteral("simulate"), QStringLiteral("--can"), QStringLiteral("virtualcan:can0"), QStringLiteral("--protocol"),
                      QStringLiteral("modbus")}).code, 2);
    }

    void canopenSession()
    {
        QVERIFY(startSim({QStringLiteral("--protocol"), QStringLiteral("canopen"), QStringLiteral("--motion"), QStringLiteral("tumble")}, 24483));
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
        // Every setting by name (8.28): TPDO periods and transmission types, heartbeat, bit rate,
        // node ID and inclinometer signs, read by SDO upload; a write read back.
        const QStringList co = {QStringLiteral("--protocol"), QStringLiteral("canopen")};
        r = cli(can(co + QStringList{QStringLiteral("config")}));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("tpdo1-period\t50 ms")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("tpdo1-mode\ttimed")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("bitrate\t500000 bit/s\t[1000000, 500000, 250000, 125000]")), qPrintable(r.out));
        r = cli(can(co + QStringList{QStringLiteral("set"), QStringLiteral("heartbeat"), QStringLiteral("100")}));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        r = cli(can(co + QStringList{QStringLiteral("get"), QStringLiteral("heartbeat")}));
        QVERIFY2(r.code == 0 && r.out.trimmed() == QStringLiteral("heartbeat: 100 ms"), qPrintable(r.out + r.err));
        // 800K is J1939's only (0x209A has no code for it).
        QCOMPARE(cli(can(co + QStringList{QStringLiteral("set"), QStringLiteral("bitrate"), QStringLiteral("800000")})).code, 2);
        // SYNC frames.
        r = cli(can({QStringLiteral("--protocol"), QStringLiteral("canopen"), QStringLiteral("sync"), QStringLiteral("--count"), QStringLiteral("3")}));
        QCOMPARE(r.code, 0);
        QVERIFY(r.out.startsWith(QStringLiteral("SYNC sent: 3")));
    }

    void j1939Session()
    {
        QVERIFY(startSim({QStringLiteral("--protocol"), QStringLiteral("j1939"), QStringLiteral("--node"), QStringLiteral("9")}, 24484));
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
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains(QStringLiteral("unknown setting 'work-mode' for j1939")), qPrintable(r.err));
        // Every setting by name (v1.7.1 7.23): the dump shows the module's values, a bit rate in
        // bit/s is written as its code and read back, and shown in bit/s again.
        const QStringList j = {QStringLiteral("--protocol"), QStringLiteral("j1939"), QStringLiteral("--node"), QStringLiteral("9")};
        r = cli(can(j + QStringList{QStringLiteral("config")}));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("interval-ff37\t100 ms\t[5-1000 ms]")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("bitrate\t500000 bit/s")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("incl-sign-x\treversed")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("node-id\t9")), qPrintable(r.out));
        r = cli(can(j + QStringList{QStringLiteral("set"), QStringLiteral("bitrate"), QStringLiteral("250k")}));
        QVERIFY2(r.code == 0 && r.out.contains(QStringLiteral("verified by reading it back")), qPrintable(r.out + r.err));
        r = cli(can({QStringLiteral("--node"), QStringLiteral("9"), QStringLiteral("reg"), QStringLiteral("read"), QStringLiteral("0x009A")}));
        QVERIFY2(r.out.startsWith(QStringLiteral("register 0x009a: 3")), qPrintable(r.out + r.err)); // 7.23: 3 = 250K
        r = cli(can(j + QStringList{QStringLiteral("get"), QStringLiteral("bitrate"), QStringLiteral("--json")}));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject got = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(got.value(QStringLiteral("value")).toString(), QStringLiteral("250000"));
        QCOMPARE(got.value(QStringLiteral("raw")).toInt(), 3);
        QCOMPARE(got.value(QStringLiteral("unit")).toString(), QStringLiteral("bit/s"));
        // Out of the manual's range, or a rate J1939 does not have: refused before anything is sent.
        QCOMPARE(cli(can(j + QStringList{QStringLiteral("set"), QStringLiteral("interval-ff34"), QStringLiteral("3")})).code, 2);
        QCOMPARE(cli(can(j + QStringList{QStringLiteral("set"), QStringLiteral("bitrate"), QStringLiteral("300000")})).code, 2);
        QCOMPARE(cli(can({QStringLiteral("--bitrate"), QStringLiteral("300000"), QStringLiteral("--protocol"),
                          QStringLiteral("j1939"), QStringLiteral("read")})).code, 2);
        QCOMPARE(cli(can(j + QStringList{QStringLiteral("set"), QStringLiteral("version"), QStringLiteral("1")})).code, 2);
        QCOMPARE(cli(can({QStringLiteral("--protocol"), QStringLiteral("j1939"), QStringLiteral("set"), QStringLiteral("incl-sign-x"),
                          QStringLiteral("2")})).code, 2);
        QCOMPARE(cli(can({QStringLiteral("set"), QStringLiteral("incl-sign-x"), QStringLiteral("1")})).code, 2); // no protocol
    }

    // "can --protocol j1939 sync PGN" is confirmed as the session confirms a trigger (v1.7.1
    // 7.23: no reply; the PGN arriving from the module is the answer): with the module's output
    // off, FF34 comes only as the triggers' answers; FF5A, which a module without CAN FD never
    // sends, leaves the trigger unconfirmed and the command exits 1 saying so.
    void j1939SyncConfirmed()
    {
        QVERIFY(startSim({QStringLiteral("--protocol"), QStringLiteral("j1939")}, 24501));
        const QStringList j = {QStringLiteral("--protocol"), QStringLiteral("j1939")};
        Run r = cli(can(j + QStringList{QStringLiteral("output"), QStringLiteral("off")}));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        r = cli(can(j + QStringList{QStringLiteral("sync"), QStringLiteral("0xFF34"), QStringLiteral("--count"), QStringLiteral("2"),
                                    QStringLiteral("--json")}));
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(o.value(QStringLiteral("sent")).toInt(), 2);
        QCOMPARE(o.value(QStringLiteral("confirmed")).toInt(), 2);
        r = cli(can(j + QStringList{QStringLiteral("sync"), QStringLiteral("0xFF5A")}));
        QCOMPARE(r.code, 1);
        QVERIFY2(r.out.contains(QStringLiteral("confirmed by PGN FF5A: 0")), qPrintable(r.out));
        QVERIFY2(r.err.contains(QStringLiteral("1 of 1 triggers of PGN FF5A were not answered by node 8")), qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("sent no PGN FF5A")), qPrintable(r.err));
    }

    // "can set node-id" on a v1.6.6 CANopen module writes 0x20A0 (5.4.1), chosen by the firmware
    // version the module reports; the 1.7.1 object 0x209C is aborted by it.
    void canopenV166NodeId()
    {
        QVERIFY(startSim({QStringLiteral("--protocol"), QStringLiteral("canopen"), QStringLiteral("--firmware"),
                          QStringLiteral("1.6.6")},
                         24502));
        const QStringList co = {QStringLiteral("--protocol"), QStringLiteral("canopen")};
        Run r = cli(can(co + QStringList{QStringLiteral("sdo"), QStringLiteral("write"), QStringLiteral("0x209C"), QStringLiteral("0"),
                                         QStringLiteral("9")}));
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("does not exist")), qPrintable(r.err));
        r = cli(can(co + QStringList{QStringLiteral("set"), QStringLiteral("node-id"), QStringLiteral("9")}));
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.contains(QStringLiteral("object 0x20a0, firmware 1.6.6")), qPrintable(r.out));
        r = cli(can(co + QStringList{QStringLiteral("sdo"), QStringLiteral("read"), QStringLiteral("0x20A0"), QStringLiteral("0")}));
        QVERIFY2(r.code == 0 && r.out.startsWith(QStringLiteral("0x20a0.00: 9")), qPrintable(r.out + r.err));
        r = cli(can(co + QStringList{QStringLiteral("get"), QStringLiteral("node-id")}));
        QVERIFY2(r.code == 0 && r.out.trimmed() == QStringLiteral("node-id: 9"), qPrintable(r.out + r.err));
    }

    // The simulated module has no GNSS time: its FF2F frames carry a zero date and its running
    // time, which is no UTC time of day in the samples (here every 50 ms).
    void j1939TimeWithoutDateIsNotUtc()
    {
        QVERIFY(startSim({QStringLiteral("--protocol"), QStringLiteral("j1939")}, 24503));
        const QStringList j = {QStringLiteral("--protocol"), QStringLiteral("j1939")};
        Run r = cli(can(j + QStringList{QStringLiteral("set"), QStringLiteral("interval-ff2f"), QStringLiteral("50")}));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        r = cli(can(j + QStringList{QStringLiteral("read"), QStringLiteral("--duration"), QStringLiteral("0.5"), QStringLiteral("--json")}));
        QVERIFY2(r.code == 0 && r.out.contains(QStringLiteral("\"acc\"")), qPrintable(r.out + r.err));
        QVERIFY2(!r.out.contains(QStringLiteral("utc_time_s")), qPrintable(r.out.left(2000)));
    }

    // A register read from every node (255) with the host at source address 0x21: one line per
    // node that answered; 254 is J1939's null address, not a host's; CANopen has no broadcast SDO.
    void j1939BroadcastFromSourceAddress()
    {
        QVERIFY(startSim({QStringLiteral("--protocol"), QStringLiteral("j1939")}, 24504));
        const QStringList j = {QStringLiteral("--protocol"), QStringLiteral("j1939")};
        Run r = cli(can(j + QStringList{QStringLiteral("--node"), QStringLiteral("255"), QStringLiteral("--source-address"),
                                        QStringLiteral("0x21"), QStringLiteral("reg"), QStringLiteral("read"), QStringLiteral("0x9C"),
                                        QStringLiteral("--json")}));
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        const QJsonObject answer = QJsonDocument::fromJson(r.out.trimmed().toUtf8()).object();
        QCOMPARE(answer.value(QStringLiteral("node")).toInt(), 8);
        QCOMPARE(answer.value(QStringLiteral("value")).toInt(), 8);
        r = cli(can(j + QStringList{QStringLiteral("--node"), QStringLiteral("255"), QStringLiteral("reg"), QStringLiteral("read"),
                                    QStringLiteral("0x9C")}));
        QVERIFY2(r.code == 0 && r.out.trimmed() == QStringLiteral("register 0x009c node 8: 8 (0x8)"), qPrintable(r.out + r.err));
        QCOMPARE(cli(can(j + QStringList{QStringLiteral("--source-address"), QStringLiteral("254"), QStringLiteral("reg"),
                                         QStringLiteral("read"), QStringLiteral("0x9C")})).code,
                 2);
        QCOMPARE(cli(can({QStringLiteral("--protocol"), QStringLiteral("canopen"), QStringLiteral("--node"), QStringLiteral("255"),
                          QStringLiteral("sdo"), QStringLiteral("read"), QStringLiteral("0x1000"), QStringLiteral("0")})).code,
                 2);
    }

    // 7.22.41: the J1939 registers mapped to the Modbus register list, by the list's names:
    // HEADING_MODE read, written and read back; PNAME (8 registers) as text; ACCZ in G; R_H/R_L
    // as one roll; URFR written (no read: refused with why); a read-only register not written.
    void j1939ModbusListByName()
    {
        QVERIFY(startSim({QStringLiteral("--protocol"), QStringLiteral("j1939")}, 24505));
        const QStringList j = {QStringLiteral("--protocol"), QStringLiteral("j1939")};
        Run r = cli(can(j + QStringList{QStringLiteral("get"), QStringLiteral("heading_mode")}));
        QVERIFY2(r.code == 0 && r.out.trimmed() == QStringLiteral("HEADING_MODE: 9-axis (absolute heading)"), qPrintable(r.out + r.err));
        r = cli(can(j + QStringList{QStringLiteral("set"), QStringLiteral("HEADING_MODE"), QStringLiteral("0")}));
        QVERIFY2(r.code == 0 && r.out.contains(QStringLiteral("verified by reading it back")), qPrintable(r.out + r.err));
        r = cli(can({QStringLiteral("reg"), QStringLiteral("read"), QStringLiteral("0x06")}));
        QVERIFY2(r.code == 0 && r.out.startsWith(QStringLiteral("register 0x0006: 0")), qPrintable(r.out + r.err));
        r = cli(can(j + QStringList{QStringLiteral("get"), QStringLiteral("pname")}));
        QVERIFY2(r.code == 0 && r.out.trimmed() == QStringLiteral("PNAME: HI14R3N-485-000"), qPrintable(r.out + r.err));
        r = cli(can(j + QStringList{QStringLiteral("get"), QStringLiteral("accz"), QStringLiteral("--json")}));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject acc = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(acc.value(QStringLiteral("unit")).toString(), QStringLiteral("G"));
        QVERIFY2(std::abs(acc.value(QStringLiteral("value")).toString().toDouble() - 1.0) < 0.05, qPrintable(r.out));
        r = cli(can(j + QStringList{QStringLiteral("get"), QStringLiteral("r_h")}));
        QVERIFY2(r.code == 0 && r.out.startsWith(QStringLiteral("R_H: ")) && r.out.trimmed().endsWith(QStringLiteral(" deg")),
                 qPrintable(r.out + r.err));
        QVERIFY2(std::abs(r.out.mid(5).section(QLatin1Char(' '), 0, 0).toDouble()) < 10, qPrintable(r.out));
        r = cli(can(j + QStringList{QStringLiteral("set"), QStringLiteral("urfr"), QStringLiteral("0x18")}));
        QVERIFY2(r.code == 0 && r.out.contains(QStringLiteral("confirmed by the module's reply")), qPrintable(r.out + r.err));
        r = cli(can(j + QStringList{QStringLiteral("get"), QStringLiteral("urfr")}));
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("cannot be read")), qPrintable(r.err));
        QCOMPARE(cli(can(j + QStringList{QStringLiteral("set"), QStringLiteral("accx"), QStringLiteral("1")})).code, 2);
        QCOMPARE(cli(can(j + QStringList{QStringLiteral("set"), QStringLiteral("md_id"), QStringLiteral("129")})).code, 2);
        QCOMPARE(cli(can(j + QStringList{QStringLiteral("set"), QStringLiteral("urfr"), QStringLiteral("7")})).code, 2);
        r = cli(can(j + QStringList{QStringLiteral("config")}));
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.contains(QStringLiteral("UART1_BAUD\t115200 bit/s")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("SN\t")), qPrintable(r.out));
    }

    // A J1939 module on a CAN FD bus: its 64-byte FF5A frames reach "can read" as FD frames, the
    // text lines show only what the frames carried, and --fd is refused where no manual has it.
    void j1939CanFd()
    {
        QVERIFY(startSim({QStringLiteral("--protocol"), QStringLiteral("j1939"), QStringLiteral("--fd")}, 24486));
        Run r = cli(can({QStringLiteral("--fd"), QStringLiteral("--data-bitrate"), QStringLiteral("2000000"), QStringLiteral("--protocol"),
                         QStringLiteral("j1939"), QStringLiteral("read"), QStringLiteral("--duration"), QStringLiteral("0.6")}));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QRegularExpression summary(QStringLiteral("frames received: (\\d+) \\(CAN FD: (\\d+)\\)"));
        const auto m = summary.match(r.out);
        QVERIFY2(m.hasMatch(), qPrintable(r.out));
        QVERIFY2(m.captured(2).toInt() >= 20, qPrintable(m.captured(0))); // FF5A every 10 ms
        QVERIFY2(r.out.contains(QStringLiteral(" mag=[")) && r.out.contains(QStringLiteral(" temp=")), qPrintable(r.out));
        // The FF5A interval is a setting of this module (0x015A), 10 ms as simulated.
        r = cli(can({QStringLiteral("--protocol"), QStringLiteral("j1939"), QStringLiteral("reg"), QStringLiteral("read"),
                     QStringLiteral("0x015A")}));
        QVERIFY2(r.code == 0 && r.out.startsWith(QStringLiteral("register 0x015a: 10")), qPrintable(r.out + r.err));
        stopSim();
        QCOMPARE(cli({QStringLiteral("simulate"), QStringLiteral("--can"), QStringLiteral("virtualcan:can0"), QStringLiteral("--protocol"),
                      QStringLiteral("canopen"), QStringLiteral("--fd")}).code, 2);
        QCOMPARE(cli({QStringLiteral("simulate"), QStringLiteral("--pty"), QStringLiteral("--fd")}).code, 2);
    }

    // The module's commands by name (J1939 0x0000 / 0xA5; CANopen has no heading reset): a
    // saved interval survives "action reset", an unsaved one does not.
    void actionsByName()
    {
        QVERIFY(startSim({QStringLiteral("--protocol"), QStringLiteral("j1939")}, 24489));
        const QStringList j = {QStringLiteral("--protocol"), QStringLiteral("j1939")};
        const auto ok = [&](const QStringList &args) {
            const Run r = cli(can(j + args));
            return r.code == 0 ? QString() : r.out + r.err + QString::number(r.code);
        };
        QCOMPARE(ok({QStringLiteral("action"), QStringLiteral("heading-reset")}), QString());
        QCOMPARE(ok({QStringLiteral("set"), QStringLiteral("interval-ff34"), QStringLiteral("50")}), QString());
        QCOMPARE(ok({QStringLiteral("action"), QStringLiteral("save")}), QString());
        QCOMPARE(ok({QStringLiteral("set"), QStringLiteral("interval-ff34"), QStringLiteral("200")}), QString());
        QCOMPARE(ok({QStringLiteral("action"), QStringLiteral("reset")}), QString());
        Run r = cli(can(j + QStringList{QStringLiteral("get"), QStringLiteral("interval-ff34")}));
        QVERIFY2(r.code == 0 && r.out.trimmed() == QStringLiteral("interval-ff34: 50 ms"), qPrintable(r.out + r.err));
        QCOMPARE(ok({QStringLiteral("action"), QStringLiteral("factory")}), QString());
        r = cli(can(j + QStringList{QStringLiteral("get"), QStringLiteral("interval-ff34")}));
        QVERIFY2(r.out.trimmed() == QStringLiteral("interval-ff34: 100 ms"), qPrintable(r.out + r.err));
        QCOMPARE(cli(can(j + QStringList{QStringLiteral("action"), QStringLiteral("fly")})).code, 2);
        r = cli(can({QStringLiteral("--protocol"), QStringLiteral("canopen"), QStringLiteral("action"),
                     QStringLiteral("heading-reset")}));
        QCOMPARE(r.code, 1); // 0x20A5 has set zero and clear only
        QVERIFY2(r.err.contains(QStringLiteral("mode 2")), qPrintable(r.err));
    }

    void hec495Session()
    {
        QVERIFY(startSim({QStringLiteral("--protocol"), QStringLiteral("canopen"), QStringLiteral("--device"), QStringLiteral("hec495")}, 24485));
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
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains(QStringLiteral("pdo-mode takes float, fixed point")), qPrintable(r.err));
        // The HEC495's manual documents writes only: a read is refused with that reason, and the
        // dump says "not readable" instead of a guess.
        r = cli(can(hec + QStringList{QStringLiteral("get"), QStringLiteral("pdo-mode")}));
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("no way to read it back")), qPrintable(r.err));
        r = cli(can(hec + QStringList{QStringLiteral("config"), QStringLiteral("--json")}));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("\"name\":\"pdo-rate\"")) && r.out.contains(QStringLiteral("\"value\":null")),
                 qPrintable(r.out));
        r = cli(can(hec + QStringList{QStringLiteral("set"), QStringLiteral("pdo-rate"), QStringLiteral("50 Hz")}));
        QVERIFY2(r.code == 0 && r.out.contains(QStringLiteral("confirmed by the module's reply")), qPrintable(r.out + r.err));
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
