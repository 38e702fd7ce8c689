// The serial update flow against the simulated module in the same process (virtual time):
// happy path, each injected fault followed by a successful second attempt, images refused
// before erasing, cancel and resume. The bootloader's first replies are compared with the
// golden packets of hipnuc-protocol-notes.md 3.1/3.5.
#include "core/firmware/update_flow.h"
#include "protocol/hipnuc/ascii_command.h"
#include "protocol/kboot/command.h"
#include "protocol/kboot/packet.h"
#include "sim/hipnuc_simulator.h"
#include "sim/simulated_byte_link.h"
#include "../common/test_main.h"

#include <QTest>

using namespace imudesk;
using firmware::UpdateFlow;
using protocol::ihex::FirmwareImage;
using sim::HipnucSimulator;
using sim::KbootBootloader;

namespace {

FirmwareImage makeImage(const std::string &version, size_t size, uint32_t start = 0x8000, uint64_t seed = 7)
{
    FirmwareImage img;
    img.startAddress = start;
    img.data = KbootBootloader::makeApplication(version, size, seed);
    return img;
}

bool flashHolds(const HipnucSimulator &s, const FirmwareImage &img)
{
    const auto &f = s.bootloader().flash();
    return img.endAddress() <= f.size()
        && std::equal(img.data.begin(), img.data.end(), f.begin() + img.startAddress);
}

UpdateFlow::Result update(HipnucSimulator &s, const FirmwareImage &img, UpdateFlow::Observer obs = {})
{
    sim::SimulatedByteLink link(s);
    UpdateFlow flow(link, UpdateFlow::Options{}, std::move(obs));
    return flow.run(img);
}

std::vector<uint8_t> hex(const char *s)
{
    const QByteArray b = QByteArray::fromHex(s);
    return std::vector<uint8_t>(b.begin(), b.end());
}


// A link on which the first read after each clearInput() brings the tail of a frame first, as
// a pty joined in the middle of a streamed frame does.
class TailAfterClear : public firmware::ByteLink {
public:
    TailAfterClear(firmware::ByteLink &inner, std::vector<uint8_t> tail) : m_inner(inner), m_tail(std::move(tail)) {}
    bool open(int baud, QString *error) override { return m_inner.open(baud, error); }
    void close() override { m_inner.close(); }
    bool isOpen() const override { return m_inner.isOpen(); }
    bool write(const std::vector<uint8_t> &bytes, QString *error) override { return m_inner.write(bytes, error); }
    bool read(std::vector<uint8_t> &out, int timeoutMs, QString *error) override
    {
        if (m_armed) {
            m_armed = false;
            ++m_injected;
            out.insert(out.end(), m_tail.begin(), m_tail.end());
        }
        return m_inner.read(out, timeoutMs, error);
    }
    void clearInput() override
    {
        m_inner.clearInput();
        m_armed = true;
    }
    void sleepMs(int ms) override { m_inner.sleepMs(ms); }
    int64_t nowUs() const override { return m_inner.nowUs(); }
    int injected() const { return m_injected; }

private:
    firmware::ByteLink &m_inner;
    std::vector<uint8_t> m_tail;
    bool m_armed = false;
    int m_injected = 0;
};

} // namespace

class TstUpdateFlow : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void bootloaderGoldenReplies()
    {
        HipnucSimulator s;
        sim::SimulatedByteLink link(s);
        QString e;
        link.open(115200, &e);
        link.write({'R', 'E', 'B', 'O', 'O', 'T', ' ', 'B', 'L', '\r', '\n'}, &e);
        link.sleepMs(50);
        QCOMPARE(s.state(), HipnucSimulator::State::Bootloader);
        link.clearInput();
        link.write(protocol::kboot::encodePing(), &e);
        std::vector<uint8_t> got;
        while (got.size() < 10 && link.read(got, 50, &e) && !got.empty()) {
        }
        QCOMPARE(got, hex("5aa7000002500000f535")); // notes 3.1
        got.clear();
        link.write(hex("5aa40800d8bc070000010b000000"), &e); // notes 3.5 GetProperty 0x0B
        while (got.size() < 20 && link.read(got, 50, &e)) {
            if (s.nowUs() > 10000000)
                break;
        }
        QCOMPARE(got, hex("5aa1" "5aa40c00f9dea70000020000000000020000")); // ACK + notes 3.5 value 512
    }

    void happyPath()
    {
        HipnucSimulator s;
        const auto img = makeImage("1.7.2", 100 * 1024 + 3); // odd size: padded to a word
        std::vector<UpdateFlow::State> states;
        uint64_t lastDone = 0;
        UpdateFlow::Observer obs;
        obs.stateChanged = [&](UpdateFlow::State st) { states.push_back(st); };
        obs.progress = [&](const UpdateFlow::Progress &p) {
            if (p.state == UpdateFlow::State::Writing)
                lastDone = p.done;
        };
        const auto r = update(s, img, obs);
        QVERIFY2(r.ok, qPrintable(r.message));
        QCOMPARE(r.verifyMethod, QStringLiteral("read-back"));
        QVERIFY(flashHolds(s, img));
        QCOMPARE(s.bootloader().flash()[img.endAddress()], uint8_t(0xFF)); // padding
        QCOMPARE(lastDone, uint64_t(100 * 1024 + 4));
        QCOMPARE(s.state(), HipnucSimulator::State::App);
        QCOMPARE(s.firmware().toString(), std::string("1.7.2"));
        QVERIFY(r.before && r.after);
        QCOMPARE(r.before->firmware->toString(), std::string("1.7.1"));
        QCOMPARE(r.after->firmware->toString(), std::string("1.7.2"));
        QCOMPARE(r.device.maxPacketSize, 512u);
        QCOMPARE(r.device.flashSize, 512u * 1024u);
        QCOMPARE(r.device.sectorSize, 4096u);
        QCOMPARE(states.back(), UpdateFlow::State::Done);
        QVERIFY(std::find(states.begin(), states.end(), UpdateFlow::State::Verifying) != states.end());
        QVERIFY(!r.resumed);
    }

    void faults_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<bool>("firstSucceeds");
        QTest::addColumn<QString>("needle");
        QTest::newRow("NAK on packet 5: resent") << 0 << true << QString();
        QTest::newRow("silence on packet 7") << 1 << false << QStringLiteral("did not answer");
        QTest::newRow("corrupted ACK on packet 3") << 2 << false << QStringLiteral("damaged bytes");
        QTest::newRow("power loss on packet 9") << 3 << false << QStringLiteral("did not answer");
    }
    void faults()
    {
        QFETCH(int, kind);
        QFETCH(bool, firstSucceeds);
        QFETCH(QString, needle);
        HipnucSimulator s;
        auto &f = s.bootloader().faults();
        switch (kind) {
        case 0: f.nakDataPacket = 5; break;
        case 1: f.silentDataPacket = 7; break;
        case 2: f.corruptAckDataPacket = 3; break;
        case 3: f.powerLossDataPacket = 9; break;
        }
        const auto img = makeImage("1.7.3", 32 * 1024);
        const auto first = update(s, img);
        QCOMPARE(first.ok, firstSucceeds);
        if (!firstSucceeds) {
            QVERIFY2(first.message.contains(needle), qPrintable(first.message));
            QVERIFY2(first.message.contains(QStringLiteral("run the update again")), qPrintable(first.message));
            QCOMPARE(first.failedIn, UpdateFlow::State::Writing);
            s.advanceTo(s.nowUs() + 1000000);
            QCOMPARE(s.state(), HipnucSimulator::State::Bootloader); // never the broken application
            const auto second = update(s, img);
            QVERIFY2(second.ok, qPrintable(second.message));
            QVERIFY(second.resumed);
        } else {
            QCOMPARE(s.bootloader().stats().naksSent, uint64_t(1));
        }
        QVERIFY(flashHolds(s, img));
        QCOMPARE(s.firmware().toString(), std::string("1.7.3"));
    }

    void refusedBeforeErasing_data()
    {
        QTest::addColumn<uint>("start");
        QTest::addColumn<int>("size");
        QTest::addColumn<QString>("needle");
        QTest::newRow("beyond the flash") << 0x7F000u << 8192 << QStringLiteral("outside the module's flash");
        QTest::newRow("not on a sector") << 0x8100u << 4096 << QStringLiteral("sector boundary");
        QTest::newRow("in the bootloader") << 0x4000u << 4096 << QStringLiteral("PROTECT");
    }
    void refusedBeforeErasing()
    {
        QFETCH(uint, start);
        QFETCH(int, size);
        QFETCH(QString, needle);
        HipnucSimulator s;
        const auto before = s.bootloader().flash();
        const auto r = update(s, makeImage("1.8.0", size_t(size), start));
        QVERIFY(!r.ok);
        QVERIFY2(r.message.contains(needle, Qt::CaseInsensitive), qPrintable(r.message));
        QCOMPARE(s.bootloader().stats().sectorsErased, uint64_t(0));
        QVERIFY(s.bootloader().flash() == before);
        s.advanceTo(s.nowUs() + 1000000);
        QCOMPARE(s.state(), HipnucSimulator::State::App); // given back its application
        QCOMPARE(s.firmware().toString(), std::string("1.7.1"));
    }

    void layoutRefusesBeforeAnyByte()
    {
        HipnucSimulator s;
        sim::SimulatedByteLink link(s);
        UpdateFlow::Options o;
        o.layout = UpdateFlow::FlashLayout{0, 512 * 1024, 0x8000};
        UpdateFlow flow(link, o);
        const auto r = flow.run(makeImage("1.8.0", 4096, 0x80000));
        QVERIFY(!r.ok);
        QVERIFY2(r.message.contains(QStringLiteral("before contacting")), qPrintable(r.message));
        QCOMPARE(link.bytesWritten(), uint64_t(0));
        QVERIFY(!flow.run(FirmwareImage{}).ok);
        QCOMPARE(link.bytesWritten(), uint64_t(0));
    }

    void cancelMidWriteThenResume()
    {
        HipnucSimulator s;
        const auto img = makeImage("1.7.4", 64 * 1024);
        sim::SimulatedByteLink link(s);
        UpdateFlow *flowPtr = nullptr;
        UpdateFlow::Observer obs;
        obs.progress = [&](const UpdateFlow::Progress &p) {
            if (p.state == UpdateFlow::State::Writing && p.done > p.total / 3)
                flowPtr->cancel();
        };
        UpdateFlow flow(link, UpdateFlow::Options{}, obs);
        flowPtr = &flow;
        const auto r = flow.run(img);
        QVERIFY(!r.ok);
        QCOMPARE(r.finalState, UpdateFlow::State::Cancelled);
        QVERIFY2(r.message.contains(QStringLiteral("run the update again")), qPrintable(r.message));
        s.advanceTo(s.nowUs() + 500000);
        QCOMPARE(s.state(), HipnucSimulator::State::Bootloader);
        s.powerCycle(); // even a power cycle keeps it in the bootloader: the application is incomplete
        QCOMPARE(s.state(), HipnucSimulator::State::Bootloader);
        const auto second = update(s, img);
        QVERIFY2(second.ok, qPrintable(second.message));
        QVERIFY(second.resumed);
        QVERIFY(!second.before);
        QVERIFY(flashHolds(s, img));
    }

    void interruptedNotFinishedWhenNotAllowed()
    {
        HipnucSimulator s;
        s.bootloader().faults().powerLossDataPacket = 2;
        const auto img = makeImage("1.7.5", 8192);
        QVERIFY(!update(s, img).ok);
        s.advanceTo(s.nowUs() + 1000000);
        sim::SimulatedByteLink link(s);
        UpdateFlow::Options o;
        o.finishInterrupted = false;
        const auto r = UpdateFlow(link, o).run(img);
        QVERIFY(!r.ok);
        QVERIFY(r.resumed);
        QVERIFY2(r.message.contains(QStringLiteral("already in its bootloader")), qPrintable(r.message));
    }

    // Issue 53: an update at a rate set but not saved (SERIALCONFIG 230400 without SAVECONFIG)
    // wrote and verified the image, then failed: the restarted module answers at its saved
    // 115200. The flow finds it there, says so, and reports the rate to connect at.
    void unsavedRateIsFoundAfterTheRestart()
    {
        HipnucSimulator s;
        sim::SimulatedByteLink link(s);
        QString e;
        QVERIFY(link.open(115200, &e));
        const std::string cmd = protocol::hipnuc::commands::serialConfig(230400).wire();
        QVERIFY(link.write(std::vector<uint8_t>(cmd.begin(), cmd.end()), &e));
        link.sleepMs(100);
        QCOMPARE(s.baud(), 230400);
        link.close();
        UpdateFlow::Options o;
        o.baud = 230400;
        const auto img = makeImage("1.7.5", 8192);
        const auto r = UpdateFlow(link, o).run(img);
        QVERIFY2(r.ok, qPrintable(r.message));
        QCOMPARE(r.afterBaud, 115200);
        QVERIFY2(r.message.contains(QStringLiteral("restarted at 115200 baud")), qPrintable(r.message));
        QVERIFY(r.after && r.after->firmware && r.after->firmware->toString() == "1.7.5");
        QVERIFY(flashHolds(s, img));
        // Without other rates to try, the old answer: not confirmed.
        HipnucSimulator s2;
        sim::SimulatedByteLink link2(s2);
        QVERIFY(link2.open(115200, &e));
        QVERIFY(link2.write(std::vector<uint8_t>(cmd.begin(), cmd.end()), &e));
        link2.sleepMs(100);
        link2.close();
        o.otherBauds.clear();
        const auto r2 = UpdateFlow(link2, o).run(img);
        QVERIFY(!r2.ok);
        QCOMPARE(r2.finalState, UpdateFlow::State::Failed);
        QVERIFY2(r2.message.contains(QStringLiteral("did not answer LOG VERSION")), qPrintable(r2.message));
    }

    // Joined mid-frame, the tail of a binary frame must not spoil the reply to LOG VERSION:
    // the demo's update once failed with "nothing answered" when these bytes, the end of an
    // HI91 frame on the pty, came before the reply's first line and were read as its start.
    void frameTailBeforeTheReplyIsNotPartOfIt()
    {
        HipnucSimulator s;
        sim::SimulatedByteLink inner(s);
        TailAfterClear link(inner, hex("65183f6ecfca3e3678ac3e"));
        const auto r = UpdateFlow(link, UpdateFlow::Options{}).run(makeImage("1.7.5", 4096));
        QVERIFY2(r.ok && r.before, qPrintable(r.message));
        QCOMPARE(QString::fromStdString(r.before->productName), QStringLiteral("HI14R3"));
        QVERIFY(link.injected() > 0);
    }

    void nothingAnswers()
    {
        HipnucSimulator s;
        sim::SimulatedByteLink link(s);
        UpdateFlow::Options o;
        o.baud = 9600; // the module listens at 115200
        const auto r = UpdateFlow(link, o).run(makeImage("1.7.5", 4096));
        QVERIFY(!r.ok);
        QVERIFY2(r.message.contains(QStringLiteral("nothing answered at 9600")), qPrintable(r.message));
        QCOMPARE(s.bootloader().stats().sectorsErased, uint64_t(0));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstUpdateFlow)
#include "tst_update_flow.moc"
