// One suite over every family plug-in of the session engine (core/device/family_plugin.h), as
// KDE Okteta runs one interface suite over each implementation: whatever the family, a session
// opens and identifies its device, ends an answered request Ok and an unanswered one as a
// timeout within its bound, keeps what it received when the link is lost, and does what the
// capabilities it declares promise (raw bytes are logged, a recording holds the bytes). The
// serial families run in process over sim::SimulatedTransport; the CAN families over Qt's
// virtualcan plugin with the CAN simulator, as on a bus.
//
// A new family joins by adding its case to cases() below: the checks stay the same.
#include "device/can_session.h"
#include "device/device_session.h"
#include "device/hec495_session.h"
#include "device/modbus_session.h"
#include "jobs/thread_sync.h"
#include "protocol/can/j1939_config.h"
#include "protocol/hipnuc/ascii_command.h"
#include "protocol/modbus/register_map.h"
#include "sim/can_simulator.h"
#include "sim/hec495_simulator.h"
#include "sim/hipnuc_serial_device.h"
#include "sim/modbus_serial_device.h"
#include "sim/simulated_transport.h"
#include "../common/test_main.h"
#include "record/recording.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <functional>
#include <memory>

using namespace imudesk;
using device::DeviceLink;
using device::RequestResult;
using device::RequestStatus;
using device::SessionState;

namespace {

using Caps = DeviceLink::Capabilities;
using Cap = DeviceLink::Capability;

// virtualcan: a port of this executable's own (the plugin starts one server per process).
const QString kCanPlugin = QStringLiteral("virtualcan");
const QString kCanIface = QStringLiteral("tcp://127.0.0.1:24495/can0"); // 24493 is the CAN update dialog test's

// One family under test: how to make and open its session over a simulated device, two
// requests (one the device answers, one it cannot), and how to break and mend the link.
struct FamilyCase {
    const char *name;
    QString linkKind;
    Caps capabilities;
    bool streams; // samples arrive without asking (else: polled by the session)
    // The session announces who the device is at connect (a CAN module is not asked: J1939
    // and CANopen give the product and firmware only on request, see CanSession).
    bool identifies = true;
    std::function<std::unique_ptr<device::Session>()> make;
    std::function<void(device::Session &)> open;
    std::function<quint64(device::Session &)> answered;
    std::function<quint64(device::Session &)> unanswered;
    int unansweredBoundMs; // the request's own timeout and retries, with room
    // Makes the device stop hearing the host (unanswered) and hear it again.
    std::function<void(bool deaf)> deafen;
    // Pulls the cable and puts it back; null where the link cannot be pulled (a CAN bus).
    std::function<void()> unplug, replug;
    std::shared_ptr<void> keep; // the simulator behind a bus
};

// The serial transports of the cases, kept for the faults (they live in the engine's thread).
struct SerialRig {
    sim::SimulatedTransport *link = nullptr;
};

FamilyCase serialCase(const char *name, const QString &kind, Caps caps, bool streams,
                      std::function<std::unique_ptr<sim::SimulatedSerialDevice>()> device,
                      std::function<std::unique_ptr<device::Session>(std::unique_ptr<io::Transport>)> session)
{
    auto rig = std::make_shared<SerialRig>();
    FamilyCase c;
    c.name = name;
    c.linkKind = kind;
    c.capabilities = caps;
    c.streams = streams;
    c.make = [rig, device, session] {
        auto t = std::make_unique<sim::SimulatedTransport>(device());
        rig->link = t.get();
        return session(std::move(t));
    };
    c.deafen = [rig](bool on) { rig->link->setDeaf(on); };
    c.unplug = [rig] { jobs::callAndWait(rig->link, [l = rig->link] { l->unplug(); }); };
    c.replug = [rig] { jobs::callAndWait(rig->link, [l = rig->link] { l->replug(); }); };
    c.keep = rig;
    return c;
}

std::vector<FamilyCase> cases()
{
    std::vector<FamilyCase> out;
    // HiPNUC serial: ASCII commands and binary frames; the rate found by the engine (baud 0).
    {
        FamilyCase c = serialCase(
            "HiPNUC serial", QStringLiteral("HiPNUC serial"),
            Cap::TextCommands | Cap::Settings | Cap::Recording | Cap::RawBytes, true,
            [] {
                sim::SimOptions o;
                o.baud = 460800;
                return std::make_unique<sim::HipnucSerialDevice>(o);
            },
            [](std::unique_ptr<io::Transport> t) { return std::make_unique<device::DeviceSession>(nullptr, std::move(t)); });
        c.open = [](device::Session &s) { static_cast<device::DeviceSession &>(s).open(QStringLiteral("sim:HI14"), 0); };
        c.answered = [](device::Session &s) {
            return static_cast<device::DeviceSession &>(s).sendCommand(protocol::hipnuc::commands::logVersion());
        };
        c.unanswered = [](device::Session &s) {
            return static_cast<device::DeviceSession &>(s).sendCommand(protocol::hipnuc::commands::logComConfig(), 300);
        };
        c.unansweredBoundMs = 3000;
        out.push_back(std::move(c));
    }
    // The HEC495 compass: Witlink frames, question and answer (polled by the session).
    {
        FamilyCase c = serialCase(
            "HEC495 serial", QStringLiteral("HEC495 serial"), Cap::RawBytes | Cap::Recording, false,
            [] {
                sim::Hec495Options o;
                o.baud = 19200;
                return std::make_unique<sim::Hec495Simulator>(o);
            },
            [](std::unique_ptr<io::Transport> t) { return std::make_unique<device::Hec495Session>(nullptr, std::move(t)); });
        c.open = [](device::Session &s) { static_cast<device::Hec495Session &>(s).open(QStringLiteral("sim:HEC495"), 0, 0); };
        c.answered = [](device::Session &s) { return static_cast<device::Hec495Session &>(s).readDeclination(); };
        c.unanswered = [](device::Session &s) { return static_cast<device::Hec495Session &>(s).readAll(); };
        c.unansweredBoundMs = 5000;
        out.push_back(std::move(c));
    }
    // Modbus RTU registers (HiPNUC's map), polled.
    {
        FamilyCase c = serialCase(
            "Modbus RTU", QStringLiteral("HiPNUC Modbus"), Cap::RawBytes, false,
            [] { return std::make_unique<sim::ModbusSerialDevice>(); },
            [](std::unique_ptr<io::Transport> t) { return std::make_unique<device::ModbusSession>(nullptr, std::move(t)); });
        c.open = [](device::Session &s) {
            device::ModbusOptions o;
            o.port = QStringLiteral("sim:modbus");
            o.pollHz = 20;
            static_cast<device::ModbusSession &>(s).open(o);
        };
        c.answered = [](device::Session &s) {
            return static_cast<device::ModbusSession &>(s).readRegisters(protocol::modbus::reg::kHeadingMode, 1);
        };
        c.unanswered = [](device::Session &s) {
            return static_cast<device::ModbusSession &>(s).readRegisters(protocol::modbus::reg::kHeadingMode, 1);
        };
        c.unansweredBoundMs = 4000;
        out.push_back(std::move(c));
    }
    // CAN, J1939: registers by the manual's read request, data PGNs streamed.
    {
        auto simulator = std::make_shared<std::unique_ptr<sim::CanSimulator>>();
        FamilyCase c;
        c.name = "CAN J1939";
        c.linkKind = QStringLiteral("HiPNUC J1939");
        c.identifies = false;
        c.capabilities = {}; // frames, not a byte stream: the CAN monitor shows them
        c.streams = true;
        c.make = [simulator] {
            sim::CanSimOptions o;
            o.protocol = protocol::can::CanProtocol::J1939;
            *simulator = std::make_unique<sim::CanSimulator>(o);
            QString why;
            if (!(*simulator)->start(kCanPlugin, kCanIface, &why))
                qWarning() << "CAN simulator:" << why;
            return std::make_unique<device::CanSession>();
        };
        c.open = [](device::Session &s) {
            device::CanSessionOptions o;
            o.plugin = kCanPlugin;
            o.interfaceName = kCanIface;
            o.protocol = protocol::can::CanProtocol::J1939;
            static_cast<device::CanSession &>(s).open(o);
        };
        c.answered = [](device::Session &s) {
            return static_cast<device::CanSession &>(s).readRegister(protocol::can::j1939::RegBaud);
        };
        c.unanswered = c.answered;
        c.unansweredBoundMs = 5000;
        // The bus stays; the module goes quiet (as a module whose power is cut).
        c.deafen = [simulator](bool on) {
            if (on)
                (*simulator)->stop();
            else
                (*simulator)->start(kCanPlugin, kCanIface);
        };
        c.keep = simulator;
        out.push_back(std::move(c));
    }
    return out;
}

// Waits for the end of request id (Session::requestEnded, every family's).
std::optional<RequestResult> waitEnded(QSignalSpy &spy, quint64 id, int boundMs)
{
    std::optional<RequestResult> out;
    (void)test::waitFor(
        [&] {
            for (const auto &args : spy)
                if (const auto r = args.at(0).value<RequestResult>(); r.id == id) {
                    out = r;
                    return true;
                }
            return false;
        },
        boundMs);
    return out;
}

} // namespace

class TstFamilyConformance : public QObject {
    Q_OBJECT

    static void addCases()
    {
        QTest::addColumn<int>("index");
        const auto all = cases();
        for (size_t i = 0; i < all.size(); ++i)
            QTest::newRow(all[i].name) << int(i);
    }

private Q_SLOTS:
    void initTestCase()
    {
        qRegisterMetaType<device::SessionState>();
        qRegisterMetaType<device::RequestResult>();
        qRegisterMetaType<model::DeviceIdentity>();
    }

    // Opens, identifies, declares its link and capabilities, and delivers samples.
    void opensAndIdentifies_data() { addCases(); }
    void opensAndIdentifies()
    {
        QFETCH(int, index);
        FamilyCase c = cases()[size_t(index)];
        auto s = c.make();
        QSignalSpy identity(s.get(), &DeviceLink::identityChanged);
        QSignalSpy states(s.get(), &DeviceLink::stateChanged);
        c.open(*s);
        QTRY_COMPARE_WITH_TIMEOUT(s->state(), SessionState::Connected, 15000);
        QCOMPARE(s->linkKind(), c.linkKind);
        QCOMPARE(s->capabilities(), c.capabilities);
        QVERIFY(s->isLive());
        if (c.identifies) {
            QTRY_VERIFY_WITH_TIMEOUT(!identity.isEmpty(), 5000);
            const auto id = identity.last().at(0).value<model::DeviceIdentity>();
            QVERIFY2(!id.productName.empty() || !id.serial.empty(), "an identity with neither product nor serial");
        }
        QTRY_VERIFY_WITH_TIMEOUT(s->store().size() > 3, 5000);
        QVERIFY(s->store().latest()->hostTimeNs > 0);
        // Every state on the way was announced, ending at Connected.
        QCOMPARE(states.last().at(0).value<SessionState>(), SessionState::Connected);
        s->close();
        QTRY_COMPARE(s->state(), SessionState::Closed);
    }

    // A request the device answers ends Ok with the same id; one it cannot answer ends as a
    // timeout within its bound, and the session stays connected.
    void requestsEndByIdWithinTheirBound_data() { addCases(); }
    void requestsEndByIdWithinTheirBound()
    {
        QFETCH(int, index);
        FamilyCase c = cases()[size_t(index)];
        auto s = c.make();
        QSignalSpy ended(s.get(), &device::Session::requestEnded);
        c.open(*s);
        QTRY_COMPARE_WITH_TIMEOUT(s->state(), SessionState::Connected, 15000);
        const quint64 ok = c.answered(*s);
        QVERIFY(ok > 0);
        const auto r = waitEnded(ended, ok, 5000);
        QVERIFY2(r, "the answered request never ended");
        QVERIFY2(r->ok(), qPrintable(QStringLiteral("%1: %2").arg(QLatin1String(model::outcomeName(r->status)),
                                                                      r->message)));

        c.deafen(true);
        QElapsedTimer clock;
        clock.start();
        const quint64 lost = c.unanswered(*s);
        QVERIFY(lost > 0 && lost != ok);
        const auto t = waitEnded(ended, lost, c.unansweredBoundMs + 10000);
        QVERIFY2(t, "the unanswered request never ended");
        QCOMPARE(t->status, RequestStatus::Timeout);
        QVERIFY2(clock.elapsed() < test::tryBound(c.unansweredBoundMs), qPrintable(QString::number(clock.elapsed())));
        QVERIFY(!t->message.isEmpty());
        const uint64_t heard = s->store().totalAppended();
        c.deafen(false);
        if (c.streams) // the module back on the line (a CAN module's first frames after power-up)
            QTRY_VERIFY_WITH_TIMEOUT(s->store().totalAppended() > heard + 2, 5000);
        // Heard again: the next request is answered.
        const auto again = waitEnded(ended, c.answered(*s), 8000);
        QVERIFY2(again && again->ok(), again ? qPrintable(again->message) : "never ended");
    }

    // The link is lost: the session says so, a request then ends (never hangs), every sample
    // already received is kept; when the cable is back, a reconnecting family carries on.
    void lostLinkKeepsWhatWasReceived_data() { addCases(); }
    void lostLinkKeepsWhatWasReceived()
    {
        QFETCH(int, index);
        FamilyCase c = cases()[size_t(index)];
        if (!c.unplug)
            QSKIP("a CAN bus has no cable of the module's own to pull (requestsEndByIdWithinTheirBound silences it)");
        auto s = c.make();
        QSignalSpy ended(s.get(), &device::Session::requestEnded);
        c.open(*s);
        QTRY_COMPARE_WITH_TIMEOUT(s->state(), SessionState::Connected, 15000);
        QTRY_VERIFY_WITH_TIMEOUT(s->store().size() > 5, 5000);
        const uint64_t before = s->store().totalAppended();
        c.unplug();
        QTRY_VERIFY_WITH_TIMEOUT(s->state() == SessionState::Reconnecting || s->state() == SessionState::Disconnected,
                                 3000);
        QVERIFY(s->store().totalAppended() >= before);
        const quint64 id = c.answered(*s);
        const auto r = waitEnded(ended, id, 5000);
        QVERIFY2(r, "a request on a lost link never ended");
        QVERIFY(!r->ok());
        c.replug();
        if (s->state() == SessionState::Reconnecting) {
            QTRY_COMPARE_WITH_TIMEOUT(s->state(), SessionState::Connected, 5000);
            QTRY_VERIFY_WITH_TIMEOUT(s->store().totalAppended() > before + 3, 5000);
        }
    }

    // What the declared capabilities promise: the bytes on the wire are logged (RawBytes), and
    // a recording holds what arrived (Recording).
    void capabilitiesHold_data() { addCases(); }
    void capabilitiesHold()
    {
        QFETCH(int, index);
        FamilyCase c = cases()[size_t(index)];
        auto s = c.make();
        c.open(*s);
        QTRY_COMPARE_WITH_TIMEOUT(s->state(), SessionState::Connected, 15000);
        if (c.capabilities.testFlag(Cap::RawBytes))
            QTRY_VERIFY_WITH_TIMEOUT(s->rawLog().bytesHeld() > 0, 5000);
        if (c.capabilities.testFlag(Cap::Recording)) {
            QTemporaryDir dir;
            const QString path = dir.filePath(QStringLiteral("capture.imcap"));
            QSignalSpy stopped(s.get(), &device::Session::recordingStopped);
            record::startRecording(*s, path);
            const uint64_t from = s->store().totalAppended();
            QTRY_VERIFY_WITH_TIMEOUT(s->store().totalAppended() > from + 5, 5000);
            s->stopRecording();
            QTRY_VERIFY_WITH_TIMEOUT(!stopped.isEmpty(), 5000);
            QCOMPARE(stopped.last().at(0).toString(), QString());
            QVERIFY(QFile(path).size() > 64);
        }
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstFamilyConformance)
#include "tst_family_conformance.moc"
