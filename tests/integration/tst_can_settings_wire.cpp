// The CAN settings on the wire, against devices written here from the manuals alone (no ImuDesk
// codec): a J1939 device (v1.7.1 7.22-7.23: configuration PGN 0xEF00, ADDR u16, CMD 0x03 read /
// 0x06 write, STATUS, VAL u32, all little-endian) and a CANopen slave (CiA 301 expedited SDO:
// upload request 0x40, answers 0x43/0x4B/0x4F with 4/2/1 bytes; download 0x23/0x2B/0x2F, answer
// 0x60) on Qt's virtualcan bus. They check the bytes ImuDesk sends, answer with values of their
// own, and ImuDesk must show those values. This executable uses its own virtualcan TCP port.
#include "device/can_session.h"
#include "links/link_opener.h"
#include "protocol/can/can_setting_catalog.h"
#include "../common/can_result.h"
#include "../common/test_main.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QTest>

#include <chrono>
#include <cstdlib>
#include <map>
#include <set>
#include <memory>

using namespace imudesk;
using device::CanRequestResult;
using device::CanSession;
using protocol::can::CanProtocol;

namespace {

const QString kPlugin = QStringLiteral("virtualcan");
const QString kIface = QStringLiteral("tcp://127.0.0.1:24492/can0");
constexpr uint8_t kNode = 8;
constexpr uint8_t kHost = 0x55;

uint32_t le32(const QByteArray &d, int at)
{
    return uint32_t(uint8_t(d[at])) | uint32_t(uint8_t(d[at + 1])) << 8 | uint32_t(uint8_t(d[at + 2])) << 16
         | uint32_t(uint8_t(d[at + 3])) << 24;
}

QByteArray bytes(std::initializer_list<int> b)
{
    QByteArray out;
    for (int x : b)
        out.append(char(x));
    return out;
}

// The device side, written from the manuals: J1939 registers and CANopen objects it holds,
// every request it saw.
class IndependentDevice : public QObject {
public:
    std::map<uint16_t, uint32_t> registers;                  // J1939
    std::set<uint16_t> keeps;                                // J1939 registers that acknowledge a write but keep their value
    std::map<std::pair<uint16_t, uint8_t>, std::pair<uint32_t, int>> objects; // CANopen: value, size
    QList<QCanBusFrame> seen;

    bool start(QString *error)
    {
        m_bus.reset(QCanBus::instance()->createDevice(kPlugin, kIface, error));
        if (!m_bus)
            return false;
        connect(m_bus.get(), &QCanBusDevice::framesReceived, this, [this] {
            while (m_bus->framesAvailable())
                answer(m_bus->readFrame());
        });
        return m_bus->connectDevice();
    }

private:
    void answer(const QCanBusFrame &f)
    {
        const QByteArray d = f.payload();
        if (f.hasExtendedFrameFormat() && (f.frameId() & 0x03FFFF00u) == (0x00EF0000u | uint32_t(kNode) << 8) && d.size() == 8) {
            seen << f;
            const uint8_t sa = uint8_t(f.frameId() & 0xFF);
            const uint16_t addr = uint16_t(uint8_t(d[0]) | uint8_t(d[1]) << 8);
            const uint8_t cmd = uint8_t(d[2]);
            if (cmd == 0x06 && addr == 0x0096) {
                // 7.23: no reply; the module sends the requested data frame once (here only the
                // acceleration's, 0x0CFF34[SA]).
                if (le32(d, 4) == 0xFF34)
                    m_bus->writeFrame(QCanBusFrame(0x0CFF3400u | kNode, bytes({0, 0, 0, 0, 0x10, 0x27, 0, 0})));
                return;
            }
            if (cmd == 0x06 && !keeps.count(addr))
                registers[addr] = le32(d, 4);
            const auto it = registers.find(addr);
            const uint32_t v = it == registers.end() ? 0 : it->second;
            QByteArray r = d.left(3);
            r.append(char(it == registers.end() ? 1 : 0)); // STATUS
            for (int i = 0; i < 4; ++i)
                r.append(char(v >> (8 * i)));
            // Priority 3, PGN 0xEF00 to the requester: 0x0CEF[DA][SA].
            m_bus->writeFrame(QCanBusFrame(0x0CEF0000u | uint32_t(sa) << 8 | kNode, r));
            return;
        }
        if (!f.hasExtendedFrameFormat() && f.frameId() == 0x600u + kNode && d.size() == 8) {
            seen << f;
            const uint16_t index = uint16_t(uint8_t(d[1]) | uint8_t(d[2]) << 8);
            const uint8_t sub = uint8_t(d[3]);
            const uint8_t ccs = uint8_t(d[0]);
            QByteArray r = d.left(4);
            if (ccs == 0x40) {
                const auto it = objects.find({index, sub});
                if (it == objects.end()) {
                    r[0] = char(0x80);
                    r += bytes({0x00, 0x00, 0x02, 0x06}); // abort 0x06020000: no such object
                } else {
                    const auto [value, size] = it->second;
                    r[0] = char(size == 1 ? 0x4F : size == 2 ? 0x4B : 0x43);
                    for (int i = 0; i < 4; ++i)
                        r.append(char(i < size ? value >> (8 * i) : 0));
                }
            } else if (ccs == 0x2F || ccs == 0x2B || ccs == 0x23) {
                const int size = ccs == 0x2F ? 1 : ccs == 0x2B ? 2 : 4;
                uint32_t v = le32(d, 4);
                if (size < 4)
                    v &= (1u << (8 * size)) - 1;
                objects[{index, sub}] = {v, size};
                r[0] = char(0x60);
                r += bytes({0, 0, 0, 0});
            } else {
                return;
            }
            m_bus->writeFrame(QCanBusFrame(0x580u + kNode, r));
        }
    }

    std::unique_ptr<QCanBusDevice> m_bus;
};

std::unique_ptr<CanSession> openSession(CanProtocol protocol)
{
    auto s = std::make_unique<CanSession>();
    device::CanSessionOptions o;
    o.plugin = kPlugin;
    o.interfaceName = kIface;
    o.protocol = protocol;
    o.node = kNode;
    o.hostAddress = kHost;
    s->open(o);
    if (!test::waitFor([&] { return s->state() == device::SessionState::Connected; }, 5000))
        return nullptr;
    return s;
}

protocol::can::CanSetting setting(CanProtocol p, const char *name)
{
    return *protocol::can::findCanSetting(p, QLatin1String(name));
}

} // namespace

class TstCanSettingsWire : public QObject {
    Q_OBJECT
    IndependentDevice m_device;

private Q_SLOTS:
    void initTestCase()
    {
        if (!QCanBus::instance()->plugins().contains(kPlugin))
            QSKIP("Qt's virtualcan CAN bus plugin is not installed (package libqt6serialbus6-plugins)");
        QString error;
        QVERIFY2(m_device.start(&error), qPrintable(error));
    }

    // J1939: the read request is 0x0CEF[08][55] 9A 00 03 00 ..; the device's 3 is 250 kbit/s
    // (7.23: 0:1000K 1:800K 2:500K 3:250K 4:125K), its 20 ms the acceleration PGN's interval.
    void j1939ReadsWhatTheDeviceHolds()
    {
        m_device.registers = {{0x009A, 3}, {0x0134, 20}, {0x009E, 1}};
        m_device.seen.clear();
        auto s = openSession(CanProtocol::J1939);
        QVERIFY(s);
        CanRequestResult r = test::waitCanResult(*s, s->readSetting(setting(CanProtocol::J1939, "bitrate")));
        QVERIFY2(r.ok, qPrintable(r.message));
        QCOMPARE(setting(CanProtocol::J1939, "bitrate").show(r.value), QStringLiteral("250000"));
        QVERIFY(!m_device.seen.isEmpty());
        const QCanBusFrame req = m_device.seen.first();
        QCOMPARE(req.frameId(), 0x0CEF0855u);
        QCOMPARE(req.payload().left(4), bytes({0x9A, 0x00, 0x03, 0x00}));
        r = test::waitCanResult(*s, s->readSetting(setting(CanProtocol::J1939, "interval-ff34")));
        QVERIFY2(r.ok, qPrintable(r.message));
        QCOMPARE(r.value, 20u);
        r = test::waitCanResult(*s, s->readSetting(setting(CanProtocol::J1939, "incl-sign-x")));
        QCOMPARE(setting(CanProtocol::J1939, "incl-sign-x").show(r.value), QStringLiteral("reversed"));
        // A write: 0x0CEF0855 37 01 06 00 64 00 00 00 (the manual's example), then read back.
        m_device.seen.clear();
        r = test::waitCanResult(*s, s->writeSetting(setting(CanProtocol::J1939, "interval-ff37"), 100));
        QVERIFY2(r.ok, qPrintable(r.message));
        QVERIFY(m_device.seen.size() >= 2);
        QCOMPARE(m_device.seen[0].payload(), bytes({0x37, 0x01, 0x06, 0x00, 0x64, 0x00, 0x00, 0x00}));
        QCOMPARE(uint8_t(m_device.seen[1].payload()[2]), uint8_t(0x03)); // the read-back
        QCOMPARE(m_device.registers[0x0137], 100u);
    }

    // CANopen: SDO uploads 40 17 10 00 / 40 9A 20 00 / 40 00 18 05 to 0x608; the device's
    // values are shown (0x209A code 4 = 125 kbit/s, 8.28.44.23).
    void canopenUploadsWhatTheDeviceHolds()
    {
        m_device.objects = {{{0x1017, 0}, {250, 2}}, {{0x209A, 0}, {4, 4}}, {{0x1800, 5}, {40, 2}}, {{0x1800, 2}, {1, 1}}};
        m_device.seen.clear();
        auto s = openSession(CanProtocol::CanOpen);
        QVERIFY(s);
        CanRequestResult r = test::waitCanResult(*s, s->readSetting(setting(CanProtocol::CanOpen, "heartbeat")));
        QVERIFY2(r.ok, qPrintable(r.message));
        QCOMPARE(r.value, 250u);
        QCOMPARE(m_device.seen.first().frameId(), 0x608u);
        QCOMPARE(m_device.seen.first().payload(), bytes({0x40, 0x17, 0x10, 0x00, 0, 0, 0, 0}));
        r = test::waitCanResult(*s, s->readSetting(setting(CanProtocol::CanOpen, "bitrate")));
        QVERIFY2(r.ok, qPrintable(r.message));
        QCOMPARE(setting(CanProtocol::CanOpen, "bitrate").show(r.value), QStringLiteral("125000"));
        r = test::waitCanResult(*s, s->readSetting(setting(CanProtocol::CanOpen, "tpdo1-period")));
        QCOMPARE(r.value, 40u);
        r = test::waitCanResult(*s, s->readSetting(setting(CanProtocol::CanOpen, "tpdo1-mode")));
        QCOMPARE(setting(CanProtocol::CanOpen, "tpdo1-mode").show(r.value), QStringLiteral("on each SYNC"));
        // An object the device does not have: its abort, not a value.
        r = test::waitCanResult(*s, s->readSetting(setting(CanProtocol::CanOpen, "incl-sign-x")));
        QVERIFY(!r.ok);
        // A write (2B 17 10 00 2C 01 = 300 ms), read back.
        m_device.seen.clear();
        r = test::waitCanResult(*s, s->writeSetting(setting(CanProtocol::CanOpen, "heartbeat"), 300));
        QVERIFY2(r.ok, qPrintable(r.message));
        QCOMPARE(m_device.seen.first().payload(), bytes({0x2B, 0x17, 0x10, 0x00, 0x2C, 0x01, 0x00, 0x00}));
        QVERIFY(r.message.contains(QLatin1String("verified by reading it back")));
    }

    // The J1939 one-shot trigger (register 0x96) has no reply: it is confirmed by the requested
    // PGN arriving from the module, and a PGN that does not come is "no answer within N ms".
    void triggerIsConfirmedByThePgn()
    {
        auto s = openSession(CanProtocol::J1939);
        QVERIFY(s);
        m_device.seen.clear();
        CanRequestResult r = test::waitCanResult(*s, s->trigger(0xFF34));
        QVERIFY2(r.ok, qPrintable(r.message));
        QCOMPARE(m_device.seen.first().payload(), bytes({0x96, 0x00, 0x06, 0x00, 0x34, 0xFF, 0x00, 0x00}));
        r = test::waitCanResult(*s, s->trigger(0xFF3A));
        QVERIFY(!r.ok);
        QVERIFY2(r.message.contains(QLatin1String("no answer within 1000 ms")) && r.message.contains(QLatin1String("FF3A")),
                 qPrintable(r.message));
    }

    // A device that acknowledges a write but keeps its value: "read back 0, expected 1", not "done".
    void writeNotTakenIsSaid()
    {
        m_device.registers = {{0x009F, 0}};
        m_device.keeps = {0x009F};
        auto s = openSession(CanProtocol::J1939);
        QVERIFY(s);
        const CanRequestResult r = test::waitCanResult(*s, s->writeSetting(setting(CanProtocol::J1939, "incl-sign-y"), 1));
        m_device.keeps.clear();
        QVERIFY(!r.ok);
        QVERIFY2(r.message.contains(QLatin1String("read back 0, expected 1")), qPrintable(r.message));
    }

    // A CAN FD bus (v1.7.1 7.19.30): the link opened as the window and the CLI open it, with a
    // simulated J1939 module whose CAN FD output is on: its 64-byte FF5A frames arrive as FD
    // frames and are decoded into samples (attitude and temperature among them, 7.21.39).
    void canFdBusCarriesFf5a()
    {
        device::CanSessionOptions o;
        o.plugin = kPlugin;
        o.interfaceName = QStringLiteral("tcp://127.0.0.1:24492/can1");
        o.protocol = CanProtocol::J1939;
        o.canFd = true;
        o.dataBitrate = 4000000;
        device::LinkRequest request = device::LinkRequest::canBus(o);
        request.simulate = true;
        QString error;
        device::LinkOpener::Opened link = device::LinkOpener::openNow(request, &error);
        QVERIFY2(link.link, qPrintable(error));
        auto *session = qobject_cast<CanSession *>(link.link.get());
        QVERIFY(session);
        int fdFrames = 0;
        connect(session, &CanSession::framesSeen, this, [&](const device::CanFrameEvents &ev) {
            for (const auto &e : ev)
                fdFrames += !e.transmitted && e.frame.fd && e.frame.len == 64 && (e.frame.id & 0x00FFFF00u) == 0x00FF5A00u;
        });
        link.start();
        QTRY_VERIFY_WITH_TIMEOUT(fdFrames >= 3, 5000);
        QTRY_VERIFY(session->store().latest().has_value());
        // Stamped on the host clock every session uses (steady_clock), so the values table does
        // not call fresh values hours old.
        const qint64 now = std::chrono::duration_cast<std::chrono::nanoseconds>(
                               std::chrono::steady_clock::now().time_since_epoch())
                               .count();
        QVERIFY(std::llabs(now - session->store().latest()->hostTimeNs) < 5'000'000'000LL);
        link.link.reset();
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCanSettingsWire)
#include "tst_can_settings_wire.moc"
