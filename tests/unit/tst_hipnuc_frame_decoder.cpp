// The streaming frame decoder: golden frame, chunking, garbage, corruption, bounds.
#include "../common/golden.h"
#include "../common/test_main.h"
#include "protocol/hipnuc/crc16.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"

#include <QRandomGenerator>
#include <QTest>

using namespace imudesk::protocol::hipnuc;

namespace {

std::vector<uint8_t> payloadOf(uint32_t i)
{
    Hi91 h;
    h.systemTime = i;
    h.acc = {float(i) * 0.001f, 0.5f, 1.0f};
    h.yaw = float(i % 360);
    return encode(h);
}

struct Recorder : FrameDecoder::Sink {
    std::vector<std::vector<uint8_t>> frames;
    std::vector<uint8_t> skipped;
    size_t maxPending = 0;
    void onFrame(const uint8_t *p, size_t n) override { frames.emplace_back(p, p + n); }
    void onSkipped(const uint8_t *p, size_t n) override { skipped.insert(skipped.end(), p, p + n); }
};

// Feeds `stream` to a fresh decoder in the given chunking (0 = whole, 1 = byte by byte, -1 = random).
Recorder decodeWith(const std::vector<uint8_t> &stream, int chunking, FrameDecoder *out = nullptr, quint32 seed = 7)
{
    FrameDecoder d;
    Recorder r;
    QRandomGenerator rng(seed);
    size_t i = 0;
    while (i < stream.size()) {
        size_t n = stream.size() - i;
        if (chunking == 1)
            n = 1;
        else if (chunking < 0)
            n = std::min<size_t>(n, size_t(rng.bounded(1, 300)));
        d.feed(stream.data() + i, n, r);
        r.maxPending = std::max(r.maxPending, d.pendingBytes());
        i += n;
    }
    d.finish(r);
    if (out)
        *out = d;
    return r;
}

} // namespace

class TstFrameDecoder : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void crcCheckValue()
    {
        const char *s = "123456789";
        QCOMPARE(crc16(reinterpret_cast<const uint8_t *>(s), 9), uint16_t(0x31C3));
        QCOMPARE(crc16UpdateBitwise(0, reinterpret_cast<const uint8_t *>(s), 9), uint16_t(0x31C3));
    }

    void crcFastEqualsBitwise()
    {
        QRandomGenerator rng(1);
        for (int len = 0; len < 300; ++len) {
            std::vector<uint8_t> v(static_cast<size_t>(len));
            for (auto &b : v)
                b = uint8_t(rng.bounded(256));
            const uint16_t init = uint16_t(rng.bounded(65536));
            QCOMPARE(crc16Update(init, v.data(), v.size()), crc16UpdateBitwise(init, v.data(), v.size()));
        }
    }

    void manualFrameCrc()
    {
        const auto f = golden::bytes(golden::hi91Frame());
        QCOMPARE(f.size(), size_t(82));
        QCOMPARE(frameCrc(f.data(), f.data() + 6, 76), uint16_t(0xBB14));
        // The encoder rebuilds the manual's frame byte for byte.
        QCOMPARE(buildFrame(f.data() + 6, 76), f);
    }

    void manualFrameAnyChunking_data()
    {
        QTest::addColumn<int>("chunking");
        QTest::newRow("whole") << 0;
        QTest::newRow("byte-by-byte") << 1;
        QTest::newRow("random") << -1;
    }
    void manualFrameAnyChunking()
    {
        QFETCH(int, chunking);
        const auto f = golden::bytes(golden::hi91Frame());
        std::vector<uint8_t> stream;
        for (int i = 0; i < 5; ++i)
            stream.insert(stream.end(), f.begin(), f.end());
        FrameDecoder d;
        const auto r = decodeWith(stream, chunking, &d);
        QCOMPARE(r.frames.size(), size_t(5));
        QCOMPARE(d.counters().frames, uint64_t(5));
        QCOMPARE(d.counters().perTag[0x91], uint64_t(5));
        QCOMPARE(d.counters().crcErrors, uint64_t(0));
        QCOMPARE(d.counters().bytesSkipped, uint64_t(0));
        QVERIFY(r.skipped.empty());
    }

    // Every intact frame survives garbage, truncated frames, false syncs and CRC damage.
    void noIntactFrameLost_data()
    {
        QTest::addColumn<int>("chunking");
        QTest::addColumn<quint32>("seed");
        for (quint32 seed : {1u, 2u, 3u}) {
            QTest::newRow(qPrintable(QStringLiteral("whole-%1").arg(seed))) << 0 << seed;
            QTest::newRow(qPrintable(QStringLiteral("bytes-%1").arg(seed))) << 1 << seed;
            QTest::newRow(qPrintable(QStringLiteral("random-%1").arg(seed))) << -1 << seed;
        }
    }
    void noIntactFrameLost()
    {
        QFETCH(int, chunking);
        QFETCH(quint32, seed);
        QRandomGenerator rng(seed);
        std::vector<uint8_t> stream;
        std::vector<std::vector<uint8_t>> intact;
        for (uint32_t i = 0; i < 400; ++i) {
            const auto payload = payloadOf(i);
            auto frame = buildFrame(payload);
            switch (rng.bounded(8)) {
            case 0: { // flipped payload byte -> CRC error
                frame[6 + rng.bounded(76)] ^= uint8_t(1 + rng.bounded(255));
                break;
            }
            case 1: // truncated: a following frame starts inside it
                frame.resize(6 + rng.bounded(76));
                break;
            case 2: { // a false sync with a plausible length
                const uint8_t fake[] = {0x5A, 0xA5, uint8_t(rng.bounded(1, 250)), 0x00, 0x12, 0x34};
                stream.insert(stream.end(), std::begin(fake), std::end(fake));
                intact.push_back(payload);
                break;
            }
            case 3: { // garbage with lone sync bytes and a bad length
                const uint8_t junk[] = {0x5A, 0x00, 0x5A, 0x5A, 0xA5, 0xFF, 0xFF, 'O', 'K'};
                stream.insert(stream.end(), std::begin(junk), std::end(junk));
                intact.push_back(payload);
                break;
            }
            default:
                intact.push_back(payload);
            }
            stream.insert(stream.end(), frame.begin(), frame.end());
            for (uint32_t g = rng.bounded(6); g > 0; --g)
                stream.push_back(uint8_t(rng.bounded(256)));
        }
        FrameDecoder d;
        const auto r = decodeWith(stream, chunking, &d, seed);
        QVERIFY2(r.maxPending < 512, "decoder kept more than one unfinished frame");
        // Random garbage may by chance hold a valid frame; every intact one must be there, in order.
        size_t k = 0;
        for (const auto &f : r.frames)
            if (k < intact.size() && f == intact[k])
                ++k;
        QCOMPARE(k, intact.size());
        QVERIFY(d.counters().crcErrors + d.counters().lengthErrors > 0);
        // Every byte is either in a frame or skipped.
        uint64_t inFrames = 0;
        for (const auto &f : r.frames)
            inFrames += f.size() + 6;
        QCOMPARE(inFrames + d.counters().bytesSkipped, uint64_t(stream.size()));
        QCOMPARE(r.skipped.size(), size_t(d.counters().bytesSkipped));
    }

    void lengthLimits()
    {
        // LEN 1-4096 (v1.7.1 manual 5.7): length 0 and 4097 are refused and counted; 4096 is
        // accepted (the vendor's SDK stopped at 506).
        std::vector<uint8_t> zero = {0x5A, 0xA5, 0x00, 0x00, 0x00, 0x00};
        std::vector<uint8_t> big = {0x5A, 0xA5, 0x01, 0x10, 0x00, 0x00};
        std::vector<uint8_t> ok(4096, 0x11);
        ok[0] = 0x91;
        auto okFrame = buildFrame(ok);
        std::vector<uint8_t> stream = zero;
        stream.insert(stream.end(), big.begin(), big.end());
        stream.insert(stream.end(), okFrame.begin(), okFrame.end());
        FrameDecoder d;
        const auto r = decodeWith(stream, 0, &d);
        QCOMPARE(r.frames.size(), size_t(1));
        QCOMPARE(r.frames[0].size(), size_t(4096));
        QCOMPARE(d.counters().lengthErrors, uint64_t(2));
        QCOMPARE(d.counters().bytesSkipped, uint64_t(12));
    }

    void payloadEndingInSyncByte()
    {
        // A payload whose last byte is 0x5A followed by a frame must not confuse the scanner.
        Hi91 h;
        std::vector<uint8_t> p = encode(h);
        p.back() = 0x5A;
        auto f1 = buildFrame(p);
        auto f2 = buildFrame(payloadOf(3));
        std::vector<uint8_t> stream = f1;
        stream.insert(stream.end(), f2.begin(), f2.end());
        const auto r = decodeWith(stream, 1);
        QCOMPARE(r.frames.size(), size_t(2));
    }

    void frameInsideUnfinishedTail()
    {
        // A truncated frame whose announced length runs past the end of the stream
        // still gives up the complete frame inside it when the stream ends.
        auto f = buildFrame(payloadOf(9));
        std::vector<uint8_t> stream = {0x5A, 0xA5, 0xF0, 0x01, 0x00, 0x00};
        stream.insert(stream.end(), f.begin(), f.end());
        FrameDecoder d;
        Recorder r;
        d.feed(stream.data(), stream.size(), r);
        QVERIFY(r.frames.empty()); // still waiting for 496 bytes
        d.finish(r);
        QCOMPARE(r.frames.size(), size_t(1));
        QCOMPARE(r.skipped.size(), size_t(6));
        QCOMPARE(d.pendingBytes(), size_t(0));
    }

    void boundedMemoryOnEndlessGarbage()
    {
        FrameDecoder d;
        Recorder r;
        std::vector<uint8_t> junk(4096, 0x5A);
        for (int i = 0; i < 100; ++i) {
            d.feed(junk.data(), junk.size(), r);
            QVERIFY(d.pendingBytes() <= 1);
        }
        QCOMPARE(d.counters().bytesSkipped + d.pendingBytes(), uint64_t(409600));
        QVERIFY(r.frames.empty());
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstFrameDecoder)
#include "tst_hipnuc_frame_decoder.moc"
