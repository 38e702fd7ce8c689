// The simulators' clocks and links (core/sim/sim_clock.h, issue 36 point 6) and the pairing of
// triggered frames (core/clock/trigger_pairing.h, point 5): what the accuracy figures of
// bench_sync rest on, checked against values worked out by hand.
#include "clock/serial_frame_clocks.h"
#include "clock/trigger_pairing.h"
#include "sim/sim_clock.h"
#include "../common/test_main.h"

#include <QTest>

#include <vector>

using imudesk::clock::TriggerPairing;
using imudesk::sim::AdapterBatcher;
using imudesk::sim::AdapterLatency;
using imudesk::sim::ClockError;

class TstSimClock : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void clockErrorBothWays()
    {
        ClockError c{1000, 40, -1, 0};
        // 100 s of true time: 100 s + 4 ms (+40 ppm) + 1 ms offset on the device.
        QCOMPARE(c.deviceUs(100'000'000), int64_t(100'005'000));
        QCOMPARE(c.trueUs(100'005'000), int64_t(100'000'000));
        ClockError slow{0, -25, -1, 0};
        QCOMPARE(slow.deviceUs(1'000'000'000), int64_t(999'975'000));
        // A step of +5 ms at 30 s: the device's time jumps, and back again maps each side.
        ClockError step{0, 0, 30, 5000};
        QCOMPARE(step.deviceUs(29'999'999), int64_t(29'999'999));
        QCOMPARE(step.deviceUs(30'000'000), int64_t(30'005'000));
        QCOMPARE(step.trueUs(30'005'000), int64_t(30'000'000));
        QCOMPARE(step.trueUs(29'000'000), int64_t(29'000'000));
        QVERIFY(ClockError{}.isIdeal() && !c.isIdeal());
    }

    void adapterReleasesWhenItsTimerRunsOut()
    {
        // A 16 ms timer at phase 3 ms: expiries at 3, 19, 35 ms ...
        AdapterBatcher a(AdapterLatency{16, 0, 0, 0, 3000, 1});
        const uint8_t bytes[4] = {1, 2, 3, 4};
        a.push(bytes, 2, 4000);   // after the 3 ms expiry: held until 19 ms
        a.push(bytes + 2, 2, 18'000);
        QVERIFY(a.take(18'999).empty());
        auto r = a.take(19'000);
        QCOMPARE(int(r.size()), 1);
        QCOMPARE(r[0].hostUs, int64_t(19'000));
        QCOMPARE(int(r[0].bytes.size()), 4);
        QCOMPARE(r[0].bytes[3], uint8_t(4));
        // Bytes that come after an expiry wait for the next one.
        a.push(bytes, 1, 19'500);
        QVERIFY(a.take(34'999).empty());
        QCOMPARE(a.take(35'000).front().hostUs, int64_t(35'000));
    }

    void adapterSendsAFullPacketAtOnceAndAddsItsDelays()
    {
        AdapterBatcher a(AdapterLatency{16, 4, 250, 0, 0, 1});
        const uint8_t bytes[6] = {1, 2, 3, 4, 5, 6};
        a.push(bytes, 6, 1000); // one full packet of 4 at once (+250 us), 2 bytes held for the timer
        auto r = a.take(1250);
        QCOMPARE(int(r.size()), 1);
        QCOMPARE(int(r[0].bytes.size()), 4);
        QCOMPARE(r[0].hostUs, int64_t(1250));
        QCOMPARE(int(a.held()), 2);
        r = a.take(16'250);
        QCOMPARE(int(r.size()), 1);
        QCOMPARE(r[0].hostUs, int64_t(16'250));
        // Jitter never reorders what the host reads.
        AdapterBatcher j(AdapterLatency{1, 0, 0, 900, 0, 7});
        int64_t last = 0;
        for (int64_t t = 0; t < 200'000; t += 100) {
            j.push(bytes, 1, t);
            for (const auto &rel : j.take(t)) {
                QVERIFY(rel.hostUs >= last);
                last = rel.hostUs;
            }
        }
        QVERIFY(last > 190'000);
    }

    // A read that ended inside a frame bounds that frame's sampling instant, but only the frame
    // it can have begun: not one completed long after (an outage, a damaged candidate held).
    void aStaleCutIsNoBound()
    {
        using imudesk::clock::SerialFrameClocks;
        auto common = [](bool stale) {
            SerialFrameClocks c;
            c.setBaud(115200); // 82-byte frames: 7.1 ms on the wire
            const int64_t wire = 82LL * 10'000'000'000 / 115200;
            int64_t last = 0;
            for (int k = 0; k < 400; ++k) { // 100 Hz, each frame read 2 ms after its last byte
                const int64_t host = 1'000'000'000 + int64_t(k) * 10'000'000 + wire + 2'000'000;
                if (k == 399) // the last read before frame 399 held 40 bytes of something
                    c.endRead(40, stale ? host - 3'000'000'000 : host - 2'000'000 - wire + 40LL * 10'000'000'000 / 115200);
                c.beginFrame(82, host);
                last = c.commonTime("HI91", double(k) * 10, host, 0);
                c.endRead(0, host);
            }
            return last;
        };
        const int64_t truth = 1'000'000'000 + 399LL * 10'000'000;
        // A fitting cut: the frame's start read off its first 40 bytes (within the ms rounding).
        QVERIFY2(std::abs(common(false) - truth) < 2'100'000, qPrintable(QString::number(common(false) - truth)));
        // A cut 3 s old is ignored: the same common time as without it, not 3 s early.
        QVERIFY2(std::abs(common(true) - truth) < 2'100'000, qPrintable(QString::number(common(true) - truth)));
    }

    void triggeredFramesArePairedByTheirPulse()
    {
        // Pulses every 10 ms. Device 0 sees pulses 0..99 but loses pulse 40's frame; device 1
        // starts at pulse 3 and its clock runs 25 ppm slow; device 2 never aligns.
        const int64_t period = 10'000'000;
        TriggerPairing pairing(period);
        for (int k = 0; k < 100; ++k) {
            if (k == 40)
                continue;
            const int64_t t = 5'000'000'000 + int64_t(k) * period; // the pulse on the host clock
            pairing.add(0, int64_t(k) * period + 777, t + 150'000, k >= 10);
        }
        for (int k = 3; k < 100; ++k) {
            const int64_t t = 5'000'000'000 + int64_t(k) * period;
            pairing.add(1, int64_t(double(k) * period * (1 - 25e-6)) + 123'000'000, t - 300'000, k >= 12);
        }
        pairing.add(2, 1, 0, false);
        const auto a = pairing.indices(0), b = pairing.indices(1), c = pairing.indices(2);
        QCOMPARE(int(a.size()), 99);
        QCOMPARE(int(b.size()), 97);
        QVERIFY(a[0] && b[0]);
        // Device 1's first frame is pulse 3 of device 0's count; after device 0's lost frame
        // its indices skip 40 instead of shifting.
        QCOMPARE(*b[0] - *a[0], int64_t(3));
        QCOMPARE(*a[40] - *a[0], int64_t(41));
        QCOMPARE(*b[96] - *a[0], int64_t(99));
        QVERIFY(!c.front().has_value());
        const TriggerPairing::Summary s = pairing.summary();
        QCOMPARE(s.devices, 3);
        QCOMPARE(s.unindexed, int64_t(1));
        QCOMPARE(s.pulses, int64_t(100));
        QCOMPARE(s.framesPaired, int64_t(96 + 96)); // pulses 3..99 but 40, on both
    }
};

IMUDESK_TEST_APPLESS_MAIN(TstSimClock)
#include "tst_sim_clock.moc"
