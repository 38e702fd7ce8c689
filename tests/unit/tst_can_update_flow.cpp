// The CAN firmware update flow against the simulated HiPNUC CANopen module in the same process
// (virtual time): the vendor's happy-path example as golden frames (hipnuc-protocol-notes 4.5),
// the last-segment rule for every tail length, each injected fault followed by a successful second
// run, cancel and resume, images refused before any frame, CRC verification and its fallback.
#include "core/firmware/can_update_flow.h"
#include "protocol/can/sdo.h"
#include "sim/can_sim_device.h"
#include "sim/kboot_bootloader.h"
#include "sim/simulated_can_frame_link.h"
#include "../common/test_main.h"

#include <QTest>

using namespace imudesk;
using firmware::CanUpdateFlow;
using protocol::can::CanFrame;
using protocol::ihex::FirmwareImage;
using sim::CanSimDevice;

namespace {

sim::CanSimOptions canopen(int node = 8)
{
    sim::CanSimOptions o;
    o.protocol = protocol::can::CanProtocol::CanOpen;
    o.node = node;
    return o;
}

FirmwareImage makeImage(const std::string &version, size_t size, uint64_t seed = 7)
{
    FirmwareImage img;
    img.startAddress = 0x8000;
    img.data = sim::KbootBootloader::makeApplication(version, size, seed);
    return img;
}

bool flashHolds(CanSimDevice &d, const FirmwareImage &img)
{
    const auto area = d.bootloader().applicationArea();
    return img.data.size() <= area.size() && std::equal(img.data.begin(), img.data.end(), area.begin());
}

CanUpdateFlow::Result update(CanSimDevice &d, const FirmwareImage &img, CanUpdateFlow::Options o = {},
                             std::vector<CanFrame> *sent = nullptr, CanUpdateFlow::Observer obs = {})
{
    sim::SimulatedCanFrameLink link(d);
    CanUpdateFlow flow(link, o, std::move(obs));
    const auto r = flow.run(img);
    if (sent)
        *sent = link.sent();
    return r;
}

// The frames of the update itself: every request except the SDO reads (identity, CRC).
std::vector<CanFrame> updateFrames(const std::vector<CanFrame> &sent)
{
    std::vector<CanFrame> out;
    for (const CanFrame &f : sent)
        if (f.data[0] != protocol::can::canopen::SdoUploadRequest)
            out.push_back(f);
    return out;
}

} // namespace

class TstCanUpdateFlow : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void goldenVendorExample()
    {
        // hipnuc-protocol-notes 4.5 "Vendor test happy path": node 8, image = 20 bytes A0..B3.
        CanSimDevice d(canopen(8));
        FirmwareImage img;
        img.startAddress = 0x8000;
        for (uint8_t b = 0xA0; b <= 0xB3; ++b)
            img.data.push_back(b);
        std::vector<CanFrame> sent;
        const auto r = update(d, img, {}, &sent);
        QVERIFY2(r.ok, qPrintable(r.message));
        const std::vector<CanFrame> golden{
            CanFrame::fromHex(0x608, false, "23511F0500000000"), CanFrame::fromHex(0x608, false, "23511F0600000000"),
            CanFrame::fromHex(0x608, false, "21511F0114000000"), CanFrame::fromHex(0x608, false, "00A0A1A2A3A4A5A6"),
            CanFrame::fromHex(0x608, false, "10A7A8A9AAABACAD"), CanFrame::fromHex(0x608, false, "05AEAFB0B1B2B300"),
            CanFrame::fromHex(0x608, false, "23511F0900000000"),
        };
        const auto got = updateFrames(sent);
        QCOMPARE(got.size(), golden.size());
        for (size_t i = 0; i < golden.size(); ++i)
            QVERIFY2(got[i] == golden[i], qPrintable(QStringLiteral("frame %1: %2 %3").arg(i).arg(got[i].idText(), got[i].dataText())));
        QVERIFY(flashHolds(d, img));
        QCOMPARE(r.verifyMethod, QStringLiteral("bootloader CRC"));
        QVERIFY(!d.inBootloader());
    }

    void lastSegmentRule_data()
    {
        QTest::addColumn<int>("size");
        QTest::addColumn<int>("lastCs"); // notes 4.5 table: 17 - 2n, with the toggle of that segment
        QTest::newRow("1 byte") << 1 << 0x0F;
        QTest::newRow("2 bytes") << 2 << 0x0D;
        QTest::newRow("3 bytes") << 3 << 0x0B;
        QTest::newRow("4 bytes") << 4 << 0x09;
        QTest::newRow("5 bytes") << 5 << 0x07;
        QTest::newRow("6 bytes") << 6 << 0x05;
        QTest::newRow("7 bytes only") << 7 << 0x03;
        QTest::newRow("8 bytes") << 8 << 0x1F;
        QTest::newRow("14 bytes") << 14 << 0x13;
        QTest::newRow("15 bytes") << 15 << 0x0F;
    }
    void lastSegmentRule()
    {
        QFETCH(int, size);
        QFETCH(int, lastCs);
        CanSimDevice d(canopen());
        const FirmwareImage img = makeImage("1.7.2", size_t(size));
        std::vector<CanFrame> sent;
        const auto r = update(d, img, {}, &sent);
        QVERIFY2(r.ok, qPrintable(r.message));
        const auto frames = updateFrames(sent);
        QVERIFY(frames.size() >= 2);
        QCOMPARE(int(frames[frames.size() - 2].data[0]), lastCs);
        QVERIFY(flashHolds(d, img));
    }

    void happyPathReportsNewVersion()
    {
        CanSimDevice d(canopen());
        const FirmwareImage img = makeImage("1.7.2", 64 * 1024 + 3);
        std::vector<CanUpdateFlow::State> states;
        uint64_t lastDone = 0, total = 0;
        CanUpdateFlow::Observer obs;
        obs.stateChanged = [&](CanUpdateFlow::State s) { states.push_back(s); };
        obs.progress = [&](uint64_t done, uint64_t t, double, double) { lastDone = done, total = t; };
        const auto r = update(d, img, {}, nullptr, obs);
        QVERIFY2(r.ok, qPrintable(r.message));
        QVERIFY(flashHolds(d, img));
        QCOMPARE(lastDone, uint64_t(img.size()));
        QCOMPARE(total, uint64_t(img.size()));
        QVERIFY(r.before && r.before->toString() == "1.7.1");
        QVERIFY(r.after && r.after->toString() == "1.7.2");
        QCOMPARE(r.bootloaderCrc.value_or(0), img.crc32());
        QVERIFY2(r.message.contains(QStringLiteral("verified: bootloader CRC")), qPrintable(r.message));
        QCOMPARE(states.back(), CanUpdateFlow::State::Done);
        QVERIFY(std::find(states.begin(), states.end(), CanUpdateFlow::State::Verifying) != states.end());
        QVERIFY(!r.resumed);
    }

    void faultThenSecondRunSucceeds_data()
    {
        QTest::addColumn<QString>("fault");
        QTest::addColumn<QString>("expect");
        QTest::newRow("abort on segment 50") << "abort" << "general error";
        QTest::newRow("silence on segment 50") << "silent" << "no reply to segment";
        QTest::newRow("wrong toggle on segment 50") << "corrupt" << "toggle";
        QTest::newRow("power loss on segment 50") << "power" << "no reply to segment";
        QTest::newRow("damaged echo on segment 50") << "echo" << "does not echo";
    }
    void faultThenSecondRunSucceeds()
    {
        QFETCH(QString, fault);
        QFETCH(QString, expect);
        CanSimDevice d(canopen());
        auto &f = d.bootloader().faults();
        if (fault == QLatin1String("abort")) f.abortSegment = 50;
        else if (fault == QLatin1String("silent")) f.silentSegment = 50;
        else if (fault == QLatin1String("corrupt")) f.corruptSegment = 50;
        else if (fault == QLatin1String("echo")) f.badEchoSegment = 50;
        else f.powerLossSegment = 50;
        const FirmwareImage img = makeImage("1.7.3", 4000);
        const auto bad = update(d, img);
        QVERIFY(!bad.ok);
        QCOMPARE(bad.failedIn, CanUpdateFlow::State::Downloading);
        QVERIFY2(bad.message.contains(expect) && bad.message.contains(QStringLiteral("run the update again")),
                 qPrintable(bad.message));
        QVERIFY(d.inBootloader());
        QVERIFY(!d.bootloader().downloading()); // our abort (or the restart) ended the transfer
        const auto good = update(d, img);
        QVERIFY2(good.ok, qPrintable(good.message));
        QVERIFY(good.resumed);
        QVERIFY(flashHolds(d, img));
        QCOMPARE(QString::fromStdString(d.firmware()), QStringLiteral("1.7.3"));
    }

    void cancelMidDownloadThenResume()
    {
        CanSimDevice d(canopen());
        const FirmwareImage img = makeImage("1.7.4", 20000);
        sim::SimulatedCanFrameLink link(d);
        CanUpdateFlow *flowPtr = nullptr;
        CanUpdateFlow::Observer obs;
        obs.progress = [&](uint64_t done, uint64_t total, double, double) {
            if (done * 3 > total)
                flowPtr->cancel();
        };
        CanUpdateFlow flow(link, {}, obs);
        flowPtr = &flow;
        const auto r = flow.run(img);
        QCOMPARE(r.finalState, CanUpdateFlow::State::Cancelled);
        QVERIFY2(r.message.contains(QStringLiteral("run the update again")), qPrintable(r.message));
        QVERIFY(d.inBootloader());
        QCOMPARE(d.bootloader().stats().abortsReceived, uint64_t(1));
        QVERIFY(!d.bootloader().applicationValid());
        // The last frame sent is the abort with the named code.
        const CanFrame last = link.sent().back();
        QCOMPARE(int(last.data[0]), 0x80);
        QCOMPARE(protocol::can::u32At(last, 4), CanUpdateFlow::kAbortCancelledByUser);
        const auto again = update(d, img);
        QVERIFY2(again.ok, qPrintable(again.message));
        QVERIFY(again.resumed);
        QVERIFY(flashHolds(d, img));
    }

    void refusedBeforeAnyFrame_data()
    {
        QTest::addColumn<int>("size");
        QTest::addColumn<uint>("start");
        QTest::addColumn<QString>("expect");
        QTest::newRow("empty") << 0 << 0x8000u << "empty";
        QTest::newRow("not at the application start") << 100 << 0x9000u << "writes the application at";
        QTest::newRow("in the bootloader area") << 100 << 0x0u << "writes the application at";
        QTest::newRow("beyond the flash") << (480 * 1024 + 1) << 0x8000u << "beyond the end of the flash";
    }
    void refusedBeforeAnyFrame()
    {
        QFETCH(int, size);
        QFETCH(uint, start);
        QFETCH(QString, expect);
        CanSimDevice d(canopen());
        FirmwareImage img;
        img.startAddress = start;
        img.data.assign(size_t(size), 0x5A);
        CanUpdateFlow::Options o;
        o.layout = firmware::UpdateFlow::FlashLayout{0, 512 * 1024, 0x8000};
        std::vector<CanFrame> sent;
        const auto r = update(d, img, o, &sent);
        QVERIFY(!r.ok);
        QCOMPARE(r.failedIn, CanUpdateFlow::State::Checking);
        QVERIFY2(r.message.contains(expect), qPrintable(r.message));
        QVERIFY(sent.empty());
    }

    void tooLargeForTheBootloader()
    {
        // No layout given: the bootloader refuses the size at the initiate, before erasing.
        CanSimDevice d(canopen());
        FirmwareImage img;
        img.startAddress = 0x8000;
        img.data.assign(480 * 1024 + 8, 0x11);
        const auto r = update(d, img);
        QVERIFY(!r.ok);
        QVERIFY2(r.message.contains(QStringLiteral("refused the download")), qPrintable(r.message));
        QVERIFY(d.bootloader().applicationValid());
    }

    void crcMismatchDetected()
    {
        CanSimDevice d(canopen());
        d.bootloader().faults().flipByteAt = 1234;
        const FirmwareImage img = makeImage("1.7.5", 5000);
        const auto bad = update(d, img);
        QVERIFY(!bad.ok);
        QCOMPARE(bad.failedIn, CanUpdateFlow::State::Verifying);
        QVERIFY2(bad.message.contains(QStringLiteral("verification failed")), qPrintable(bad.message));
        QVERIFY(d.inBootloader()); // not started
        const auto good = update(d, img);
        QVERIFY2(good.ok, qPrintable(good.message));
        QVERIFY(flashHolds(d, img));
    }

    void withoutCrcObjectFallsBack()
    {
        CanSimDevice d(canopen());
        d.bootloader().mutableOptions().crcObject = false;
        const FirmwareImage img = makeImage("1.7.6", 3000);
        const auto r = update(d, img);
        QVERIFY2(r.ok, qPrintable(r.message));
        QCOMPARE(r.verifyMethod, QStringLiteral("application restarted"));
        QVERIFY2(r.message.contains(QStringLiteral("not verified by the bootloader; application restarted with version 1.7.6")),
                 qPrintable(r.message));
        QVERIFY(!r.bootloaderCrc);
    }

    void nothingAnswers()
    {
        CanSimDevice d(canopen(8));
        CanUpdateFlow::Options o;
        o.node = 9;
        std::vector<CanFrame> sent;
        const auto r = update(d, makeImage("1.7.2", 100), o, &sent);
        QVERIFY(!r.ok);
        QCOMPARE(r.failedIn, CanUpdateFlow::State::Identifying);
        QVERIFY2(r.message.contains(QStringLiteral("nothing answered on node 9")), qPrintable(r.message));
        QVERIFY(!d.inBootloader());
    }

    void interruptedNotFinishedWhenRefused()
    {
        CanSimDevice d(canopen());
        d.bootloader().faults().powerLossSegment = 3;
        const FirmwareImage img = makeImage("1.7.2", 1000);
        QVERIFY(!update(d, img).ok);
        CanUpdateFlow::Options o;
        o.finishInterrupted = false;
        const auto r = update(d, img, o);
        QVERIFY(!r.ok);
        QVERIFY(r.resumed);
        QVERIFY2(r.message.contains(QStringLiteral("already in its bootloader")), qPrintable(r.message));
        QVERIFY(update(d, img).ok);
    }

    void unpluggedBusIsAnError()
    {
        CanSimDevice d(canopen());
        sim::SimulatedCanFrameLink link(d);
        link.setUnplugged(true);
        CanUpdateFlow flow(link, {});
        const auto r = flow.run(makeImage("1.7.2", 100));
        QVERIFY(!r.ok);
        QVERIFY2(r.message.contains(QStringLiteral("not connected")), qPrintable(r.message));
        QVERIFY(link.sent().empty());
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCanUpdateFlow)
#include "tst_can_update_flow.moc"
