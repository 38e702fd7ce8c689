// device::LinkOpener, the one way a link is opened (issue 34): a serial port at baud Auto is
// opened once, whatever the family; the detection tells a HiPNUC module from an HEC495 compass
// and its rate, and the family's session carries on over the same open port. In process, with
// a transport that counts its opens, and once over a pseudo-terminal (the real serial path).
#include "../common/test_main.h"
#include "device/device_session.h"
#include "device/hec495_session.h"
#include "links/link_opener.h"
#include "sim/hec495_simulator.h"
#include "sim/hipnuc_serial_device.h"
#include "sim/pty_simulator.h"
#include "sim/simulated_transport.h"

#include <QSignalSpy>
#include <QTest>

#include <algorithm>
#include <atomic>
#include <memory>

using namespace imudesk;
using device::LinkOpener;
using device::LinkRequest;
using device::SessionState;

namespace {

// A simulated serial device that counts how often the link was opened (any thread).
class CountingTransport : public sim::SimulatedTransport {
public:
    CountingTransport(std::unique_ptr<sim::SimulatedSerialDevice> device, std::shared_ptr<std::atomic<int>> opens)
        : sim::SimulatedTransport(std::move(device)), m_opens(std::move(opens))
    {
    }
    bool open(const QString &address, int baud, QString *error) override
    {
        ++*m_opens;
        return sim::SimulatedTransport::open(address, baud, error);
    }

private:
    std::shared_ptr<std::atomic<int>> m_opens;
};

enum class Device { Hipnuc, Hec495Polled, Hec495Streaming };

std::unique_ptr<sim::SimulatedSerialDevice> makeDevice(Device kind, int baud)
{
    if (kind == Device::Hipnuc) {
        sim::SimOptions o;
        o.baud = baud;
        return std::make_unique<sim::HipnucSerialDevice>(o);
    }
    sim::Hec495Options o;
    o.baud = baud;
    o.address = 5;
    o.rateHz = kind == Device::Hec495Streaming ? 20 : 0;
    return std::make_unique<sim::Hec495Simulator>(o);
}

} // namespace

class TestLinkOpener : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void autoOpensThePortOnce_data()
    {
        QTest::addColumn<int>("device");
        QTest::addColumn<int>("baud");
        QTest::addColumn<QString>("family");
        QTest::newRow("HiPNUC streaming at 460800") << int(Device::Hipnuc) << 460800 << QStringLiteral("hipnuc");
        QTest::newRow("HiPNUC at 115200") << int(Device::Hipnuc) << 115200 << QStringLiteral("hipnuc");
        // Question/answer: found by its answer to "query address" (address 5, not 0).
        QTest::newRow("HEC495 polled at 19200") << int(Device::Hec495Polled) << 19200 << QStringLiteral("hec495");
        QTest::newRow("HEC495 streaming at 9600") << int(Device::Hec495Streaming) << 9600 << QStringLiteral("hec495");
    }
    void autoOpensThePortOnce()
    {
        QFETCH(int, device);
        QFETCH(int, baud);
        QFETCH(QString, family);
        auto opens = std::make_shared<std::atomic<int>>(0);
        LinkRequest request = LinkRequest::serial(QStringLiteral("sim:one"), 0);
        request.autoReconnect = false;
        request.transport = [opens, device, baud] {
            return std::make_unique<CountingTransport>(makeDevice(Device(device), baud), opens);
        };
        LinkOpener opener;
        QSignalSpy ready(&opener, &LinkOpener::ready);
        QSignalSpy failed(&opener, &LinkOpener::failed);
        QSignalSpy detecting(&opener, &LinkOpener::detecting);
        opener.open(request);
        QVERIFY(opener.running());
        QTRY_VERIFY_WITH_TIMEOUT(!ready.isEmpty() || !failed.isEmpty(), 20000);
        QVERIFY2(failed.isEmpty(), qPrintable(failed.value(0).value(0).toString()));
        QCOMPARE(opener.request().family, family);
        QCOMPARE(opener.request().baud, baud);
        QVERIFY(!detecting.isEmpty());

        LinkOpener::Opened link = opener.take();
        QVERIFY(link.link && link.start);
        QSignalSpy identity(link.link.get(), &device::DeviceLink::identityChanged);
        QStringList states; // what it went through, said when it fails
        connect(link.link.get(), &device::DeviceLink::stateChanged, this, [&states](SessionState s, const QString &detail) {
            states << QStringLiteral("%1 (%2)").arg(QLatin1String(device::stateName(s)), detail);
        });
        link.start();
        QTRY_VERIFY2_WITH_TIMEOUT(link.link->state() == SessionState::Connected, qPrintable(states.join(QStringLiteral("; "))),
                                  15000);
        QTRY_VERIFY_WITH_TIMEOUT(!identity.isEmpty(), 10000);
        const auto id = identity.last().at(0).value<model::DeviceIdentity>();
        if (family == QLatin1String("hipnuc")) {
            auto *s = qobject_cast<device::DeviceSession *>(link.link.get());
            QVERIFY(s);
            QCOMPARE(QString::fromStdString(id.productName), QStringLiteral("HI14R3"));
        } else {
            auto *s = qobject_cast<device::Hec495Session *>(link.link.get());
            QVERIFY(s);
            QCOMPARE(QString::fromStdString(id.productName), QStringLiteral("HEC495"));
            QCOMPARE(id.busAddress, 5);
            QCOMPARE(s->baud(), baud);
        }
        // Samples flow on the handed-over port, and it was opened exactly once.
        QTRY_VERIFY_WITH_TIMEOUT(link.link->store().size() > 0, 10000);
        QCOMPARE(opens->load(), 1);
    }

    // A module at a rate outside the request: a clear failure that names the rates, one open.
    void nothingAnswering()
    {
        auto opens = std::make_shared<std::atomic<int>>(0);
        LinkRequest request = LinkRequest::serial(QStringLiteral("sim:mute"), 9600);
        request.transport = [opens] {
            return std::make_unique<CountingTransport>(makeDevice(Device::Hipnuc, 921600), opens);
        };
        LinkOpener opener;
        QSignalSpy ready(&opener, &LinkOpener::ready);
        QSignalSpy failed(&opener, &LinkOpener::failed);
        opener.open(request);
        QTRY_VERIFY_WITH_TIMEOUT(!failed.isEmpty(), 10000);
        QVERIFY(ready.isEmpty());
        QVERIFY(!opener.running());
        const QString message = failed.first().at(0).toString();
        QVERIFY2(message.contains(QLatin1String("no device answered")) && message.contains(QLatin1String("9600"))
                     && message.contains(QLatin1String("a HiPNUC module or an HEC495 compass"))
                     && message.contains(QLatin1String("wiring")),
                 qPrintable(message));
        QCOMPARE(opens->load(), 1);
    }

    // Every registered serial family (device::serialFamilies), the same checks: its simulated
    // device, started through the family's own plug-in, is found by the detection at Auto as
    // that family, at a rate the family lists, and the family's session connects and identifies.
    void everySerialFamilyIsFoundByTheDetection_data()
    {
        QTest::addColumn<QString>("family");
        for (const device::SerialFamilyKind *f : device::serialFamilies())
            QTest::newRow(qPrintable(f->id())) << f->id();
    }
    void everySerialFamilyIsFoundByTheDetection()
    {
        QFETCH(QString, family);
        const device::SerialFamilyKind *kind = device::serialFamily(family);
        QVERIFY(kind);
        QVERIFY(!kind->displayName().isEmpty());
        LinkRequest simulated = LinkRequest::simulatedSerial(family, sim::Motion::Static);
        QString error;
        QVERIFY2(kind->startSimulator(simulated, &error), qPrintable(error));
        QVERIFY(simulated.keepAlive);
        LinkOpener opener;
        QSignalSpy ready(&opener, &LinkOpener::ready);
        QSignalSpy failed(&opener, &LinkOpener::failed);
        LinkRequest request = LinkRequest::serial(simulated.address);
        request.autoReconnect = false;
        opener.open(request);
        QTRY_VERIFY_WITH_TIMEOUT(!ready.isEmpty() || !failed.isEmpty(), 30000);
        QVERIFY2(failed.isEmpty(), qPrintable(failed.value(0).value(0).toString()));
        QCOMPARE(opener.request().family, family);
        const std::vector<int> rates = kind->bauds();
        QVERIFY(std::find(rates.begin(), rates.end(), opener.request().baud) != rates.end());
        LinkOpener::Opened link = opener.take();
        QSignalSpy identity(link.link.get(), &device::DeviceLink::identityChanged);
        QStringList states; // what it went through, said when it fails
        connect(link.link.get(), &device::DeviceLink::stateChanged, this, [&states](SessionState s, const QString &detail) {
            states << QStringLiteral("%1 (%2)").arg(QLatin1String(device::stateName(s)), detail);
        });
        link.start();
        QTRY_VERIFY2_WITH_TIMEOUT(link.link->state() == SessionState::Connected, qPrintable(states.join(QStringLiteral("; "))),
                                  15000);
        QTRY_VERIFY_WITH_TIMEOUT(!identity.isEmpty(), 10000);
        link.link.reset();
    }

    // An unknown family's name is refused with the name in the message, and nothing opens.
    void unknownFamilyIsRefused()
    {
        LinkRequest request = LinkRequest::serial(QStringLiteral("/dev/imudesk-no-such-port"), 9600,
                                                  QStringLiteral("no-such-family"));
        QString error;
        const LinkOpener::Opened o = LinkOpener::openNow(request, &error);
        QVERIFY(!o.link);
        QVERIFY2(error.contains(QLatin1String("no-such-family")), qPrintable(error));
    }

    // A port that does not exist: the serial port's own advice, and no link.
    void missingPort()
    {
        LinkOpener opener;
        QSignalSpy failed(&opener, &LinkOpener::failed);
        opener.open(LinkRequest::serial(QStringLiteral("/dev/imudesk-no-such-port"), 0));
        QTRY_VERIFY_WITH_TIMEOUT(!failed.isEmpty(), 10000);
        QVERIFY2(failed.first().at(0).toString().contains(QLatin1String("not found")),
                 qPrintable(failed.first().at(0).toString()));
        QVERIFY(!opener.take().link);
    }

    // Cancelled while it scans: no signal afterwards, and the opener can start again.
    void cancelWhileScanning()
    {
        LinkOpener opener;
        QSignalSpy ready(&opener, &LinkOpener::ready);
        QSignalSpy failed(&opener, &LinkOpener::failed);
        LinkRequest request = LinkRequest::serial(QStringLiteral("sim:late"), 0);
        request.transport = [] { return std::make_unique<sim::SimulatedTransport>(makeDevice(Device::Hec495Polled, 2400)); };
        opener.open(request);
        QTest::qWait(300); // duration under test: the scan is under way, at its first rates
        opener.cancel();
        QVERIFY(!opener.running());
        QTest::qWait(300); // duration under test: nothing may follow the cancel
        QVERIFY(ready.isEmpty() && failed.isEmpty());
    }

    // The real serial path: a simulated module on a pseudo-terminal, found at its rate.
    void overAPseudoTerminal()
    {
        sim::SimOptions o;
        o.baud = 230400;
        sim::PtySimulator simulator(o);
        QString error;
        QVERIFY2(simulator.start(&error), qPrintable(error));
        LinkOpener opener;
        QSignalSpy ready(&opener, &LinkOpener::ready);
        QSignalSpy failed(&opener, &LinkOpener::failed);
        LinkRequest request = LinkRequest::serial(simulator.devicePath(), 0);
        request.autoReconnect = false;
        opener.open(request);
        QTRY_VERIFY_WITH_TIMEOUT(!ready.isEmpty() || !failed.isEmpty(), 20000);
        QVERIFY2(failed.isEmpty(), qPrintable(failed.value(0).value(0).toString()));
        QCOMPARE(opener.request().family, QStringLiteral("hipnuc"));
        QCOMPARE(opener.request().baud, 230400);
        LinkOpener::Opened link = opener.take();
        link.start();
        QTRY_COMPARE_WITH_TIMEOUT(link.link->state(), SessionState::Connected, 15000);
        QTRY_VERIFY_WITH_TIMEOUT(link.link->store().size() > 10, 10000);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TestLinkOpener)
#include "tst_link_opener.moc"
