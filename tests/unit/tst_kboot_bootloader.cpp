// The simulated KBOOT bootloader's flash rules and status codes, driven by the host's
// KbootClient over the in-process link (hipnuc-protocol-notes.md 3.1-3.3).
#include "core/firmware/kboot_client.h"
#include "core/firmware/update_flow.h"
#include "protocol/kboot/status_code.h"
#include "sim/hipnuc_simulator.h"
#include "sim/simulated_byte_link.h"
#include "../common/test_main.h"

#include <QTest>

using namespace imudesk;
using firmware::KbootClient;
using protocol::kboot::PropertyTag;
using sim::HipnucSimulator;

namespace {

void enterBootloader(HipnucSimulator &s, sim::SimulatedByteLink &link)
{
    QString e;
    link.open(115200, &e);
    link.write({'R', 'E', 'B', 'O', 'O', 'T', ' ', 'B', 'L', '\r', '\n'}, &e);
    link.sleepMs(50);
    QCOMPARE(s.state(), HipnucSimulator::State::Bootloader);
}

} // namespace

class TstKbootBootloader : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void properties()
    {
        HipnucSimulator s;
        sim::SimulatedByteLink link(s);
        enterBootloader(s, link);
        KbootClient kb(link);
        QString e;
        protocol::kboot::PingResponse ping;
        QVERIFY2(kb.ping(3, &ping, &e), qPrintable(e));
        QCOMPARE(ping.major, uint8_t(2));
        QCOMPARE(kb.getProperty(PropertyTag::CurrentVersion, &e).value_or(0), 0x4B010400u); // "K1.4.0", notes 3.0
        QCOMPARE(kb.getProperty(PropertyTag::MaxPacketSize, &e).value_or(0), 512u);
        QCOMPARE(kb.getProperty(PropertyTag::FlashSizeInBytes, &e).value_or(0), 512u * 1024u);
        QCOMPARE(kb.getProperty(PropertyTag::FlashSectorSize, &e).value_or(0), 4096u);
        QCOMPARE(kb.getProperty(PropertyTag::BootloaderVersion, &e).value_or(0), 109u);
        QCOMPARE(kb.getProperty(PropertyTag::AppVersion, &e).value_or(0), 171u);
        QVERIFY(!kb.getProperty(PropertyTag(0x22), &e));
        QVERIFY2(e.contains(QStringLiteral("kStatus_UnknownProperty")), qPrintable(e));
    }

    void flashRules_data()
    {
        QTest::addColumn<uint>("address");
        QTest::addColumn<uint>("length");
        QTest::addColumn<QString>("needle");
        QTest::newRow("misaligned address") << 0x8100u << 4096u << QStringLiteral("kStatus_FlashAlignmentError");
        QTest::newRow("misaligned length") << 0x8000u << 100u << QStringLiteral("kStatus_FlashAlignmentError");
        QTest::newRow("bootloader area") << 0x0u << 4096u << QStringLiteral("kStatus_FlashProtectionViolation");
        QTest::newRow("beyond the flash") << 0x7F000u << 8192u << QStringLiteral("kStatus_FlashAddressError");
    }
    void flashRules()
    {
        QFETCH(uint, address);
        QFETCH(uint, length);
        QFETCH(QString, needle);
        HipnucSimulator s;
        sim::SimulatedByteLink link(s);
        enterBootloader(s, link);
        KbootClient kb(link);
        QString e;
        QVERIFY(kb.ping(3, nullptr, &e));
        QVERIFY(!kb.flashEraseRegion(address, length, 1000, &e));
        QVERIFY2(e.contains(needle), qPrintable(e));
        QCOMPARE(s.bootloader().stats().sectorsErased, uint64_t(0));
        QVERIFY(s.bootloader().applicationValid());
    }

    void writeWithoutEraseIsCumulative()
    {
        HipnucSimulator s;
        sim::SimulatedByteLink link(s);
        enterBootloader(s, link);
        KbootClient kb(link);
        QString e;
        QVERIFY(kb.ping(3, nullptr, &e));
        std::vector<uint8_t> data(1024, 0x00);
        data[0] = 0xFF;
        QVERIFY(!kb.writeMemory(0x8000, data.data(), data.size(), 512, {}, &e)); // over the installed application
        QVERIFY2(e.contains(QStringLiteral("kStatusMemoryCumulativeWrite")), qPrintable(e));
        QVERIFY(!s.bootloader().applicationValid());
        QVERIFY(kb.flashEraseRegion(0x8000, 4096, 1000, &e));
        data.assign(1024, 0x5A);
        QVERIFY2(kb.writeMemory(0x8000, data.data(), data.size(), 256, {}, &e), qPrintable(e));
        std::vector<uint8_t> back;
        QVERIFY2(kb.readMemory(0x8000, 1024, back, {}, &e), qPrintable(e));
        QCOMPARE(back, data);
        QVERIFY(s.bootloader().applicationValid());
        QCOMPARE(s.bootloader().flash()[0x8000 + 1024], uint8_t(0xFF));
    }

    void withoutReadMemoryNotVerified()
    {
        HipnucSimulator s;
        s.bootloader().setReadMemoryEnabled(false);
        sim::SimulatedByteLink link(s);
        firmware::UpdateFlow flow(link, firmware::UpdateFlow::Options{});
        protocol::ihex::FirmwareImage img;
        img.startAddress = 0x8000;
        img.data = sim::KbootBootloader::makeApplication("1.7.9", 4096, 3);
        const auto r = flow.run(img);
        QVERIFY(!r.ok);
        QCOMPARE(r.failedIn, firmware::UpdateFlow::State::Verifying);
        QVERIFY2(r.message.contains(QStringLiteral("cannot be verified")), qPrintable(r.message));
        QVERIFY(r.verifyMethod.isEmpty());
        s.advanceTo(s.nowUs() + 1000000);
        QCOMPARE(s.state(), HipnucSimulator::State::Bootloader); // not restarted into an unverified image
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstKbootBootloader)
#include "tst_kboot_bootloader.moc"
