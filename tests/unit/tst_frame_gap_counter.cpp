// FrameGapCounter: frames lost from gaps in the device timestamps, with ms rounding
// and jitter, rate changes, device resets and reconfigured output.
#include "device/frame_gap_counter.h"
#include "../common/test_main.h"

#include <QTest>

#include <cmath>
#include <random>
#include <set>

using imudesk::device::FrameGapCounter;

namespace {

const std::string kHi91 = "HI91";

// Feeds frames i = first..last-1 at time(i), skipping the indices in `dropped`.
template <typename TimeFn>
void feed(FrameGapCounter &c, int first, int last, TimeFn time, const std::set<int> &dropped = {},
          const std::string &type = kHi91)
{
    for (int i = first; i < last; ++i)
        if (!dropped.count(i))
            c.add(type, time(i));
}

} // namespace

class TstFrameGapCounter : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void perfectStreamLosesNothing_data()
    {
        QTest::addColumn<double>("period");
        QTest::newRow("1 Hz") << 1000.0;
        QTest::newRow("100 Hz") << 10.0;
        QTest::newRow("200 Hz") << 5.0;
        QTest::newRow("1 kHz") << 1.0;
    }
    void perfectStreamLosesNothing()
    {
        QFETCH(double, period);
        FrameGapCounter c;
        feed(c, 0, 3000, [&](int i) { return 1234.0 + i * period; });
        QCOMPARE(c.lost(), uint64_t(0));
        QCOMPARE(c.resets(), uint64_t(0));
        QCOMPARE(c.rateChanges(kHi91), uint64_t(0));
        QVERIFY(c.period(kHi91).has_value());
        QCOMPARE(*c.period(kHi91), period);
        QCOMPARE(c.lostByType().at(kHi91), uint64_t(0));
    }

    void droppedFramesAreCounted_data()
    {
        QTest::addColumn<double>("period");
        QTest::addColumn<QList<int>>("dropped");
        QTest::addColumn<int>("expected");
        QTest::newRow("100 Hz, 3 in a row") << 10.0 << QList<int>{500, 501, 502} << 3;
        QTest::newRow("100 Hz, 3 apart") << 10.0 << QList<int>{300, 600, 900} << 3;
        QTest::newRow("100 Hz, 1") << 10.0 << QList<int>{777} << 1;
        QTest::newRow("100 Hz, while learning") << 10.0 << QList<int>{5, 6} << 2;
        QTest::newRow("100 Hz, 50 in a row") << 10.0 << [] {
            QList<int> l;
            for (int i = 1000; i < 1050; ++i)
                l << i;
            return l;
        }() << 50;
        QTest::newRow("1 kHz, 3 in a row") << 1.0 << QList<int>{1500, 1501, 1502} << 3;
        QTest::newRow("1 kHz, 4 apart") << 1.0 << QList<int>{400, 800, 1200, 1600} << 4;
        QTest::newRow("1 Hz, 2") << 1000.0 << QList<int>{40, 41} << 2;
    }
    void droppedFramesAreCounted()
    {
        QFETCH(double, period);
        QFETCH(QList<int>, dropped);
        QFETCH(int, expected);
        FrameGapCounter c;
        feed(c, 0, 2000, [&](int i) { return i * period; }, std::set<int>(dropped.begin(), dropped.end()));
        QCOMPARE(c.lost(), uint64_t(expected));
        QCOMPARE(c.lost(kHi91), uint64_t(expected));
        QCOMPARE(c.rateChanges(kHi91), uint64_t(0));
    }

    void kiloHertzWithMsRoundingJitter()
    {
        // 1 kHz stamped with a ms counter that the frame may lag by up to 1 ms: intervals
        // of 0, 1 and 2 ms, as ±1 ms around the period, never drifting.
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> lag(0.0, 0.999);
        std::vector<double> times(20000);
        for (size_t i = 0; i < times.size(); ++i)
            times[i] = std::floor(double(i) + 0.3 + lag(rng));
        FrameGapCounter c;
        for (double t : times)
            c.add(kHi91, t);
        QCOMPARE(c.lost(), uint64_t(0));
        QCOMPARE(c.resets(), uint64_t(0));
        QCOMPARE(*c.period(kHi91), 1.0);

        // The same stream with single frames missing far apart: each one is found.
        FrameGapCounter d;
        for (size_t i = 0; i < times.size(); ++i)
            if (i % 1000 != 500)
                d.add(kHi91, times[i]);
        QCOMPARE(d.lost(), uint64_t(20));
    }

    void hundredHzWithJitter()
    {
        // ±1 ms on every stamp (intervals 8..12 ms).
        std::mt19937 rng(3);
        std::uniform_int_distribution<int> jitter(-1, 1);
        std::vector<double> times(5000);
        for (size_t i = 0; i < times.size(); ++i)
            times[i] = 100.0 + 10.0 * double(i) + jitter(rng);
        FrameGapCounter c;
        for (double t : times)
            c.add(kHi91, t);
        QCOMPARE(c.lost(), uint64_t(0));
        FrameGapCounter d;
        for (size_t i = 0; i < times.size(); ++i)
            if (i != 1000 && i != 2000 && i != 2001 && i != 4000)
                d.add(kHi91, times[i]);
        QCOMPARE(d.lost(), uint64_t(4));
    }

    void fractionalPeriod()
    {
        // 400 Hz: whole-ms stamps alternate 2 and 3 ms; µs stamps (HI83) are exact.
        FrameGapCounter ms;
        feed(ms, 0, 4000, [](int i) { return std::floor(2.5 * i); });
        QCOMPARE(ms.lost(), uint64_t(0));
        QVERIFY(std::abs(*ms.period(kHi91) - 2.5) < 0.01);
        FrameGapCounter us;
        feed(us, 0, 4000, [](int i) { return 0.001 * std::round(2500.0 * i); }, {1000, 2000, 2001});
        QCOMPARE(us.lost(), uint64_t(3));
    }

    void rateChangeIsNotALoss_data()
    {
        QTest::addColumn<double>("before");
        QTest::addColumn<double>("after");
        QTest::newRow("100 -> 200 Hz") << 10.0 << 5.0;
        QTest::newRow("200 -> 100 Hz") << 5.0 << 10.0;
        QTest::newRow("100 -> 50 Hz") << 10.0 << 20.0;
        QTest::newRow("100 -> 25 Hz") << 10.0 << 40.0;
        QTest::newRow("100 -> 91 Hz") << 10.0 << 11.0;
        QTest::newRow("100 -> 111 Hz") << 10.0 << 9.0;
        QTest::newRow("100 Hz -> 1 kHz") << 10.0 << 1.0;
        QTest::newRow("1 kHz -> 100 Hz") << 1.0 << 10.0;
        QTest::newRow("1 kHz -> 500 Hz") << 1.0 << 2.0;
        QTest::newRow("1 -> 10 Hz") << 1000.0 << 100.0;
    }
    void rateChangeIsNotALoss()
    {
        QFETCH(double, before);
        QFETCH(double, after);
        FrameGapCounter c;
        feed(c, 0, 500, [&](int i) { return i * before; });
        const double switchAt = 499 * before;
        feed(c, 1, 1500, [&](int i) { return switchAt + i * after; });
        QCOMPARE(c.lost(), uint64_t(0));
        QCOMPARE(*c.period(kHi91), after);
        QVERIFY(c.rateChanges(kHi91) >= 1);
        // Losses at the new rate are counted again.
        const double restart = switchAt + 1500 * after;
        feed(c, 0, 500, [&](int i) { return restart + i * after; }, {200, 201});
        QCOMPARE(c.lost(), uint64_t(2));
    }

    void deviceResetIsNotALoss()
    {
        FrameGapCounter c;
        feed(c, 0, 800, [](int i) { return 5000.0 + i * 10.0; });
        // REBOOT: silence, then system_time starts again from about 0.
        feed(c, 0, 800, [](int i) { return 300.0 + i * 10.0; });
        QCOMPARE(c.lost(), uint64_t(0));
        QCOMPARE(c.resets(), uint64_t(1));
        // ...even when the new run is at another rate.
        feed(c, 0, 800, [](int i) { return 20.0 + i * 5.0; });
        QCOMPARE(c.lost(), uint64_t(0));
        QCOMPARE(c.resets(), uint64_t(2));
        QCOMPARE(*c.period(kHi91), 5.0);
    }

    void resetTimingForgetsTheGap()
    {
        // LOG DISABLE ... LOG ENABLE: the silence in between is not a loss.
        FrameGapCounter c;
        feed(c, 0, 500, [](int i) { return i * 10.0; });
        c.resetTiming();
        feed(c, 0, 500, [](int i) { return 60000.0 + i * 10.0; });
        QCOMPARE(c.lost(), uint64_t(0));
        // Without it the same silence is 5500 lost frames.
        FrameGapCounter d;
        feed(d, 0, 500, [](int i) { return i * 10.0; });
        feed(d, 0, 500, [](int i) { return 60000.0 + i * 10.0; });
        QCOMPARE(d.lost(), uint64_t(5500));
    }

    void utcAlignmentIsNotALoss()
    {
        // A HI91 stream at 100 Hz whose system_time jumps from ms-since-power-on to the ms of
        // the UTC day when PPS aligns the clock (UTC_UNSYNC clears): the jump is not a loss,
        // and losses on either side still count.
        FrameGapCounter c;
        for (int i = 0; i < 300; ++i)
            if (i != 100)
                c.add(kHi91, i * 10.0, 1);
        const double utc = 8 * 3600000.0 + 3000;
        for (int i = 0; i < 300; ++i)
            if (i != 200)
                c.add(kHi91, utc + i * 10.0, 0);
        QCOMPARE(c.lost(), uint64_t(2));
        QCOMPARE(c.resets(), uint64_t(0));
        // The same stamps without the clock named: the jump counts as millions of frames.
        FrameGapCounter d;
        for (int i = 0; i < 300; ++i)
            d.add(kHi91, i * 10.0);
        for (int i = 0; i < 300; ++i)
            d.add(kHi91, utc + i * 10.0);
        QVERIFY(d.lost() > 2000000);
    }

    void lossJustBeforeResetTimingIsKept()
    {
        FrameGapCounter c;
        feed(c, 0, 500, [](int i) { return i * 10.0; }, {490, 491, 492});
        c.resetTiming();
        QCOMPARE(c.lost(), uint64_t(3));
    }

    void expectedPeriodOnASaturatedLink()
    {
        // 1 kHz configured, the link carries a frame every 7-8 ms: 6-7 of 7-8 are lost,
        // which the timestamps alone would take for a 7.6 ms period.
        FrameGapCounter c;
        c.setExpectedPeriod(kHi91, 1.0);
        std::vector<double> times;
        for (int i = 0; i < 400; ++i)
            times.push_back(std::floor(i * 7.6));
        for (double t : times)
            c.add(kHi91, t);
        const double expected = times.back() - times.front() + 1 - double(times.size());
        QVERIFY2(c.lost() > 0.75 * expected && c.lost() <= expected,
                 qPrintable(QStringLiteral("%1 of %2").arg(c.lost()).arg(expected)));
        QCOMPARE(*c.period(kHi91), 1.0);

        FrameGapCounter learned;
        for (double t : times)
            learned.add(kHi91, t);
        QCOMPARE(learned.lost(), uint64_t(0));

        // Output faster than expected: the expectation was wrong and is dropped.
        FrameGapCounter faster;
        faster.setExpectedPeriod(kHi91, 10.0);
        feed(faster, 0, 1000, [](int i) { return i * 5.0; });
        QCOMPARE(faster.lost(), uint64_t(0));
        QCOMPARE(*faster.period(kHi91), 5.0);
    }

    void irregularOutputIsNotCounted()
    {
        // ONMARK: frames on external pulses at random times.
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> interval(20.0, 700.0);
        FrameGapCounter c;
        double t = 0;
        for (int i = 0; i < 2000; ++i) {
            t += std::round(interval(rng));
            c.add(kHi91, t);
        }
        QCOMPARE(c.lost(), uint64_t(0));
        QVERIFY(!c.period(kHi91).has_value());
    }

    void typesAreIndependent()
    {
        FrameGapCounter c;
        for (int i = 0; i < 2000; ++i) {
            if (i != 1000)
                c.add("HI91", i * 10.0);
            if (i % 10 == 0 && i != 1500)
                c.add("HI81", 1e6 + i * 10.0);
        }
        QCOMPARE(c.lost("HI91"), uint64_t(1));
        QCOMPARE(c.lost("HI81"), uint64_t(1));
        QCOMPARE(c.lost(), uint64_t(2));
        QCOMPARE(*c.period("HI81"), 100.0);
        c.clear();
        QCOMPARE(c.lost(), uint64_t(0));
        QVERIFY(c.lostByType().empty());
    }

    void randomBurstsAreCountedExactly()
    {
        // Periods, stamp jitter and bursts of 1-5 missing frames at random places.
        const double periods[] = {1, 2, 4, 5, 10, 20, 50, 100};
        for (unsigned seed = 1; seed <= 200; ++seed) {
            std::mt19937 rng(seed);
            const double period = periods[rng() % std::size(periods)];
            const int model = int(rng() % 3); // 0 exact, 1 lag up to 1 ms, 2 ±1 ms (period >= 5)
            std::uniform_real_distribution<double> lag(0.0, 0.999);
            std::uniform_int_distribution<int> sym(-1, 1);
            std::set<int> dropped;
            for (int at = 100 + int(rng() % 50); at < 5800; at += 60 + int(rng() % 200)) {
                const int burst = 1 + int(rng() % 5);
                for (int j = 0; j < burst; ++j)
                    dropped.insert(at + j);
            }
            FrameGapCounter c;
            feed(c, 0, 6000, [&](int i) {
                const double t = 50.0 + i * period;
                if (model == 1)
                    return std::floor(t + lag(rng));
                if (model == 2 && period >= 5)
                    return t + sym(rng);
                return t;
            }, dropped);
            QVERIFY2(c.lost() == dropped.size(), qPrintable(QStringLiteral("seed %1 period %2 model %3: %4 lost, %5 dropped")
                                                              .arg(seed).arg(period).arg(model).arg(c.lost()).arg(dropped.size())));
            QVERIFY2(c.rateChanges(kHi91) == 0, qPrintable(QStringLiteral("seed %1 period %2 model %3: %4 rate changes")
                                                              .arg(seed).arg(period).arg(model).arg(c.rateChanges(kHi91))));
        }
    }

    void duplicateStampsDoNotCount()
    {
        FrameGapCounter c;
        feed(c, 0, 1000, [](int i) { return i * 10.0; });
        c.add(kHi91, 9990.0); // the same frame twice
        feed(c, 1000, 2000, [](int i) { return i * 10.0; });
        QCOMPARE(c.lost(), uint64_t(0));
        QCOMPARE(c.resets(), uint64_t(0));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstFrameGapCounter)
#include "tst_frame_gap_counter.moc"
