// discovery::BenchSweep (issue 56): one sweep finds every device of a bench. Simulated devices
// on pseudo-terminals (the real serial path) at rates and addresses that are not their
// defaults, a silent line, a line of noise, a port another program holds, and a virtualcan bus
// with a J1939 module and two CANopen nodes that share node 5.
#include "../common/test_main.h"
#include "../common/try_bounds.h"
#include "discovery/bench_sweep.h"
#include "sim/can_simulator.h"
#include "sim/hec495_simulator.h"
#include "sim/line_devices.h"
#include "sim/modbus_simulator.h"
#include "sim/pty_simulator.h"

#include <QJsonArray>
#include <QLoggingCategory>
#include <QSerialPort>
#include <QTest>

#include <memory>

using namespace imudesk;
using discovery::BenchSweep;
using discovery::FoundDevice;
using discovery::PortNote;
using discovery::SweepOptions;

namespace {

// This executable's own virtualcan server (tst_can_session explains the port range).
const QString kBus = QStringLiteral("virtualcan:tcp://127.0.0.1:24501/can0");

std::unique_ptr<sim::PtySimulator> startPty(std::unique_ptr<sim::SimulatedSerialDevice> device)
{
    auto p = std::make_unique<sim::PtySimulator>(std::move(device));
    QString error;
    if (!p->start(&error))
        qFatal("pty simulator: %s", qPrintable(error));
    return p;
}

const FoundDevice *findOn(const discovery::SweepResult &r, const QString &port, int node = -2)
{
    for (const auto &d : r.devices)
        if (d.port == port && (node == -2 || d.node == node))
            return &d;
    return nullptr;
}

const PortNote *noteOn(const discovery::SweepResult &r, const QString &port)
{
    for (const auto &n : r.notes)
        if (n.port == port)
            return &n;
    return nullptr;
}

bool sweep(BenchSweep &s, const SweepOptions &o)
{
    s.start(o);
    return test::waitFor([&] { return !s.running(); }, o.budgetMs + 10000);
}

SweepOptions listed(const QStringList &ports, const QStringList &buses = {})
{
    SweepOptions o;
    o.ports = ports;
    o.canBuses = buses;
    o.machinePorts = false;
    o.machineCan = false;
    return o;
}

} // namespace

class TestBenchSweep : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        // The simulated Modbus server hears every probe at a wrong rate as a broken frame.
        QLoggingCategory::setFilterRules(QStringLiteral("qt.modbus*=false\nqt.canbus*=false"));
    }

    // The serial families at rates that are not their defaults, an HEC495 at address 7, and the
    // three ways a port shows nothing: silent, noise, busy. No Modbus here (the next test).
    void serialPortsAndWhyNothingAnswered()
    {
        sim::SimOptions hipnuc;
        hipnuc.baud = 460800;
        auto module = std::make_unique<sim::PtySimulator>(hipnuc);
        QVERIFY(module->start());
        sim::Hec495Options hec;
        hec.baud = 4800;
        hec.address = 7;
        auto compass = startPty(std::make_unique<sim::Hec495Simulator>(hec));
        auto silent = startPty(std::make_unique<sim::SilentLine>());
        auto noise = startPty(std::make_unique<sim::NoiseLine>(115200, 3000, 7));
        auto held = startPty(std::make_unique<sim::SilentLine>());
        QSerialPort other; // another program holds this one
        other.setPortName(held->devicePath());
        QVERIFY(other.open(QIODevice::ReadWrite));

        SweepOptions o = listed({module->devicePath(), compass->devicePath(), silent->devicePath(),
                                 noise->devicePath(), held->devicePath()});
        o.modbus = false;
        o.budgetMs = 40000;
        BenchSweep s;
        QVERIFY(sweep(s, o));
        const auto &r = s.result();
        qInfo().noquote() << r.textLines().join(QLatin1Char('\n'));

        const FoundDevice *m = findOn(r, module->devicePath());
        QVERIFY(m);
        QCOMPARE(m->family, QStringLiteral("hipnuc"));
        QCOMPARE(m->baud, 460800);
        QVERIFY2(m->model.startsWith(QStringLiteral("HI14")), qPrintable(m->model));
        QVERIFY(!m->firmware.isEmpty());
        QVERIFY(!m->serial.isEmpty());

        const FoundDevice *c = findOn(r, compass->devicePath());
        QVERIFY(c);
        QCOMPARE(c->family, QStringLiteral("hec495"));
        QCOMPARE(c->baud, 4800);
        QCOMPARE(c->address, 7);
        QCOMPARE(c->model, QStringLiteral("HEC495"));

        QVERIFY(!findOn(r, silent->devicePath()));
        QVERIFY(noteOn(r, silent->devicePath()));
        QCOMPARE(noteOn(r, silent->devicePath())->kind, PortNote::Kind::Silent);
        QVERIFY(noteOn(r, noise->devicePath()));
        QCOMPARE(noteOn(r, noise->devicePath())->kind, PortNote::Kind::Garbage);
        QVERIFY(noteOn(r, held->devicePath()));
        QCOMPARE(noteOn(r, held->devicePath())->kind, PortNote::Kind::Busy);
        QVERIFY(r.conflicts.isEmpty());
        QCOMPARE(r.exitCode(), 0);
        QVERIFY(!r.cancelled);
        // Nothing stays open: every port can be opened again at once.
        for (const QString &port : {module->devicePath(), compass->devicePath(), noise->devicePath()}) {
            QSerialPort again;
            again.setPortName(port);
            QVERIFY2(again.open(QIODevice::ReadWrite), qPrintable(port));
        }
        // The sweep wrote no setting: the module still runs at its rate, the compass at its address.
        int saved = 0, running = 0;
        module->withDevice([&](sim::HipnucSimulator &d) {
            saved = d.savedConfig().baud;
            running = d.baud();
        });
        QCOMPARE(saved, 460800);
        QCOMPARE(running, 460800);
    }

    // Modbus RTU lines: a HiPNUC module at 38400 with id 17 and an HEC495 at 19200 with id 9
    // (both found in the full pass, after the likely ids); neither answers the serial families'
    // queries.
    void modbusLinesAtTheirRateAndId()
    {
        sim::ModbusSimOptions a;
        a.nodeId = 17;
        a.baud = 38400;
        sim::ModbusSimulator module(a);
        QVERIFY(module.start());
        sim::ModbusSimOptions b;
        b.kind = protocol::modbus::DeviceKind::Hec495;
        b.nodeId = 9;
        b.baud = 19200;
        sim::ModbusSimulator compass(b);
        QVERIFY(compass.start());

        SweepOptions o = listed({module.devicePath(), compass.devicePath()});
        o.budgetMs = 60000;
        BenchSweep s;
        QVERIFY(sweep(s, o));
        const auto &r = s.result();
        qInfo().noquote() << r.textLines().join(QLatin1Char('\n'));
        const FoundDevice *m = findOn(r, module.devicePath());
        QVERIFY(m);
        QCOMPARE(m->link, FoundDevice::Link::Modbus);
        QCOMPARE(m->baud, 38400);
        QCOMPARE(m->address, 17);
        QCOMPARE(m->family, QStringLiteral("hipnuc-modbus"));
        QVERIFY(m->model.startsWith(QStringLiteral("HI14")));
        const FoundDevice *c = findOn(r, compass.devicePath());
        QVERIFY(c);
        QCOMPARE(c->baud, 19200);
        QCOMPARE(c->address, 9);
        QCOMPARE(c->family, QStringLiteral("hec495-modbus"));
        QCOMPARE(r.exitCode(), 0);
        QCOMPARE(module.nodeId(), 17); // nothing written
        QCOMPARE(module.baud(), 38400);
    }

    // A CAN bus: a J1939 module at address 12, an HEC495 at node 9 and two CANopen nodes that
    // both took node 5; the two answers to one SDO read are the conflict's evidence.
    void canNodesAndAConflict()
    {
        sim::CanSimOptions j;
        j.protocol = protocol::can::CanProtocol::J1939;
        j.node = 12;
        sim::CanSimulator j1939(j);
        sim::CanSimOptions c;
        c.protocol = protocol::can::CanProtocol::CanOpen;
        c.node = 5;
        c.seed = 1;
        sim::CanSimulator first(c);
        c.seed = 2;
        c.firmware = "1.6.6";
        sim::CanSimulator second(c);
        sim::CanSimOptions h;
        h.protocol = protocol::can::CanProtocol::CanOpen;
        h.hec495 = true;
        h.node = 9;
        sim::CanSimulator compass(h);
        const QString iface = kBus.mid(kBus.indexOf(QLatin1Char(':')) + 1);
        QString error;
        for (sim::CanSimulator *x : {&j1939, &first, &second, &compass})
            if (!x->start(QStringLiteral("virtualcan"), iface, &error))
                QSKIP(qPrintable(QStringLiteral("virtualcan: ") + error));

        SweepOptions o = listed({}, {kBus});
        o.budgetMs = 20000;
        BenchSweep s;
        QVERIFY(sweep(s, o));
        const auto &r = s.result();
        qInfo().noquote() << r.textLines().join(QLatin1Char('\n'));
        const FoundDevice *m = findOn(r, kBus, 12);
        QVERIFY(m);
        QCOMPARE(m->family, QStringLiteral("j1939"));
        QCOMPARE(m->firmware, QStringLiteral("1.7.1"));
        QCOMPARE(m->bitrate, 500000); // its own setting: virtualcan has no bit rate
        QVERIFY(!m->bitrateWhy.isEmpty());
        const FoundDevice *n5 = findOn(r, kBus, 5);
        QVERIFY(n5);
        QCOMPARE(n5->family, QStringLiteral("canopen"));
        QCOMPARE(r.conflicts.size(), 1);
        QCOMPARE(r.conflicts.front().address, 5);
        QVERIFY2(r.conflicts.front().evidence.contains(QStringLiteral("different contents")),
                 qPrintable(r.conflicts.front().evidence)); // 1.7.1 and 1.6.6 in 0x1018:3
        QCOMPARE(r.exitCode(), 1);
        const QJsonObject json = r.toJson();
        QCOMPARE(json.value(QStringLiteral("conflicts")).toArray().size(), 1);
        QCOMPARE(json.value(QStringLiteral("devices")).toArray().size(), 3);
        const FoundDevice *hec = findOn(r, kBus, 9);
        QVERIFY(hec);
        QCOMPARE(hec->family, QStringLiteral("hec495-can"));
        QCOMPARE(hec->bitrate, 0); // neither the bus nor the compass tells it
        QVERIFY(!hec->bitrateWhy.isEmpty());
    }

    // Cancelled at once: nothing found, every port closed, and said so.
    void cancelClosesEverything()
    {
        auto silent = startPty(std::make_unique<sim::SilentLine>());
        BenchSweep s;
        bool detecting = false; // the detection has the port open and tries a rate
        connect(&s, &BenchSweep::progress, this, [&](int, int, const QString &, const QString &detail) {
            detecting = detecting || detail.contains(QLatin1String("baud"));
        });
        s.start(listed({silent->devicePath()}));
        QVERIFY(test::waitFor([&] { return detecting; }, 5000));
        s.cancel();
        QVERIFY(!s.running());
        QVERIFY(s.result().cancelled);
        QCOMPARE(s.result().exitCode(), 2);
        QSerialPort again;
        again.setPortName(silent->devicePath());
        QVERIFY(again.open(QIODevice::ReadWrite));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TestBenchSweep)
#include "tst_bench_sweep.moc"
