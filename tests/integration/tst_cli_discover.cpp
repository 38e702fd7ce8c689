// imudesk-cli discover (issue 56): the sweep from a terminal, against simulated devices in this
// process (pseudo-terminals; a virtualcan bus whose server is this process's, so the event loop
// runs while the command does): the JSON keys the issue names, and the exit codes: 1 with a
// conflict, 0 when something was found and no conflict, 2 when nothing was.
#include "../common/test_main.h"
#include "../common/test_paths.h"
#include "../common/try_bounds.h"
#include "sim/can_simulator.h"
#include "sim/hec495_simulator.h"
#include "sim/line_devices.h"
#include "sim/pty_simulator.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>

using namespace imudesk;

namespace {

const QString kIface = QStringLiteral("tcp://127.0.0.1:24504/can0");

struct Run {
    int code = -1;
    QJsonObject json;
    QString err;
};

// Runs the command with the event loop turning (the CAN simulators and the bus server live here).
Run discover(const QStringList &args, int timeoutMs = 60000)
{
    QProcess p;
    p.start(QString::fromUtf8(IMUDESK_CLI_PATH), QStringList{QStringLiteral("discover")} + args);
    Run r;
    if (!p.waitForStarted(5000) || !test::waitFor([&] { return p.state() == QProcess::NotRunning; }, timeoutMs)) {
        p.kill();
        p.waitForFinished();
        r.err = QStringLiteral("did not end: ") + QString::fromUtf8(p.readAllStandardError());
        return r;
    }
    r.code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.json = QJsonDocument::fromJson(p.readAllStandardOutput()).object();
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

QJsonObject deviceOn(const QJsonObject &json, const QString &port, int node = -1)
{
    for (const auto &v : json.value(QStringLiteral("devices")).toArray()) {
        const QJsonObject d = v.toObject();
        if (d.value(QStringLiteral("port")).toString() == port
            && (node < 0 || d.value(QStringLiteral("node")).toInt() == node))
            return d;
    }
    return {};
}

} // namespace

class TestCliDiscover : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void conflictExitsOne()
    {
        sim::SimOptions o;
        o.baud = 460800;
        sim::PtySimulator module(o);
        QVERIFY(module.start());
        sim::Hec495Options h;
        h.baud = 4800;
        h.address = 7;
        sim::PtySimulator compass(std::make_unique<sim::Hec495Simulator>(h));
        QVERIFY(compass.start());
        sim::CanSimOptions c;
        c.protocol = protocol::can::CanProtocol::CanOpen;
        c.node = 5;
        sim::CanSimulator first(c);
        c.seed = 9;
        sim::CanSimulator second(c);
        QString error;
        for (sim::CanSimulator *s : {&first, &second})
            if (!s->start(QStringLiteral("virtualcan"), kIface, &error))
                QSKIP(qPrintable(error));
        const QString bus = QStringLiteral("virtualcan:") + kIface;
        const Run r = discover({QStringLiteral("--only-listed"), QStringLiteral("--no-modbus"), QStringLiteral("--ports"),
                                module.devicePath() + QLatin1Char(',') + compass.devicePath(), QStringLiteral("--can"),
                                bus, QStringLiteral("--json"), QStringLiteral("--timeout"), QStringLiteral("40")});
        QVERIFY2(r.code == 1, qPrintable(r.err));
        const QJsonObject m = deviceOn(r.json, module.devicePath());
        QCOMPARE(m.value(QStringLiteral("link")).toString(), QStringLiteral("serial"));
        QCOMPARE(m.value(QStringLiteral("baud")).toInt(), 460800);
        QCOMPARE(m.value(QStringLiteral("family")).toString(), QStringLiteral("hipnuc"));
        QVERIFY(m.value(QStringLiteral("model")).toString().startsWith(QStringLiteral("HI14")));
        QVERIFY(m.value(QStringLiteral("serial")).isString());
        const QJsonObject hec = deviceOn(r.json, compass.devicePath());
        QCOMPARE(hec.value(QStringLiteral("baud")).toInt(), 4800);
        QCOMPARE(hec.value(QStringLiteral("address")).toInt(), 7);
        const QJsonObject node = deviceOn(r.json, bus, 5);
        QCOMPARE(node.value(QStringLiteral("link")).toString(), QStringLiteral("can"));
        QCOMPARE(node.value(QStringLiteral("bitrate")).toInt(), 500000);
        const QJsonArray conflicts = r.json.value(QStringLiteral("conflicts")).toArray();
        QCOMPARE(conflicts.size(), 1);
        QCOMPARE(conflicts.at(0).toObject().value(QStringLiteral("node")).toInt(), 5);
        QVERIFY(conflicts.at(0).toObject().value(QStringLiteral("evidence")).toString().contains(QLatin1String("2 answers")));
        QVERIFY2(r.err.contains(QLatin1String("found hipnuc")), qPrintable(r.err)); // progress on stderr
    }

    void foundExitsZeroNothingExitsTwo()
    {
        sim::SimOptions o;
        o.baud = 115200;
        sim::PtySimulator module(o);
        QVERIFY(module.start());
        sim::PtySimulator silent(std::make_unique<sim::SilentLine>());
        QVERIFY(silent.start());
        Run r = discover({QStringLiteral("--only-listed"), QStringLiteral("--no-modbus"), QStringLiteral("--ports"),
                          module.devicePath(), QStringLiteral("--json")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QCOMPARE(r.json.value(QStringLiteral("devices")).toArray().size(), 1);
        r = discover({QStringLiteral("--only-listed"), QStringLiteral("--no-modbus"), QStringLiteral("--ports"),
                      silent.devicePath(), QStringLiteral("--json")});
        QVERIFY2(r.code == 2, qPrintable(r.err));
        const QJsonArray ports = r.json.value(QStringLiteral("ports")).toArray();
        QCOMPARE(ports.size(), 1);
        QCOMPARE(ports.at(0).toObject().value(QStringLiteral("kind")).toString(), QStringLiteral("silent"));
        // A bus without PLUGIN: is a usage error, said so.
        r = discover({QStringLiteral("--can"), QStringLiteral("can0")});
        QCOMPARE(r.code, 2);
        QVERIFY(r.err.contains(QLatin1String("PLUGIN:INTERFACE")));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TestCliDiscover)
#include "tst_cli_discover.moc"
