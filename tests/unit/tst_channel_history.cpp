// ChannelHistory: bounds (rows, duration, memory), presence, both time axes, device
// clock gaps and restarts, range queries against a linear scan.
#include "plot/channel_catalog.h"
#include "plot/channel_history.h"
#include "../common/test_main.h"

#include <QTest>

#include <bit>
#include <cmath>
#include <random>

using imudesk::model::Sample;
using imudesk::plot::Channel;
using imudesk::plot::ChannelHistory;
using imudesk::plot::IndexRange;
using imudesk::plot::TimeAxis;
namespace model = imudesk::model;

Q_DECLARE_METATYPE(TimeAxis)

namespace {

constexpr uint32_t kImuFields = model::FieldAcc | model::FieldGyr | model::FieldMag | model::FieldEuler |
                                model::FieldQuat | model::FieldPressure | model::FieldTemperature |
                                model::FieldDeviceTime;

Sample makeSample(int64_t hostNs, double deviceMs, double v = 0.0, uint32_t fields = kImuFields)
{
    Sample s;
    s.source = "HI91";
    s.fields = fields;
    s.hostTimeNs = hostNs;
    s.deviceTimeMs = deviceMs;
    s.acc = {v, v + 1, v + 2};
    s.gyr = {v + 3, v + 4, v + 5};
    s.mag = {v + 6, v + 7, v + 8};
    s.roll = v + 9;
    s.pitch = v + 10;
    s.yaw = v + 11;
    s.quat = {v + 12, v + 13, v + 14, v + 15};
    s.pressurePa = v + 16;
    s.temperatureC = v + 17;
    return s;
}

// Regular stream: `count` samples at `rateHz`, device clock starting at deviceStartMs.
void feed(ChannelHistory &h, size_t count, double rateHz, int64_t hostStartNs = 1'000'000'000,
          double deviceStartMs = 5000.0, uint32_t fields = kImuFields)
{
    const double periodMs = 1000.0 / rateHz;
    std::vector<Sample> batch;
    batch.reserve(1000);
    for (size_t i = 0; i < count; ++i) {
        batch.push_back(makeSample(hostStartNs + int64_t(std::llround(double(i) * periodMs * 1e6)),
                                   deviceStartMs + double(i) * periodMs, double(i % 1000), fields));
        if (batch.size() == 1000) {
            h.append(batch);
            batch.clear();
        }
    }
    h.append(batch);
}

IndexRange bruteRange(const ChannelHistory &h, TimeAxis axis, double t0, double t1)
{
    size_t first = h.size(), last = 0;
    for (size_t i = 0; i < h.size(); ++i) {
        const double t = h.time(axis, i);
        if (t >= t0 && t <= t1) {
            first = std::min(first, i);
            last = i + 1;
        }
    }
    if (last == 0)
        return {};
    return {first, last};
}

bool nonDecreasing(const ChannelHistory &h, TimeAxis axis)
{
    for (size_t i = 1; i < h.size(); ++i)
        if (h.time(axis, i) < h.time(axis, i - 1))
            return false;
    return true;
}

} // namespace

class TstChannelHistory : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void memoryAtFullSize()
    {
        QCOMPARE(ChannelHistory::kBytesPerRow, size_t(108)); // every channel, the compass's four too
        // A module's rows: its 18 channels' columns only (92 B a row).
        ChannelHistory h; // defaults: 10 min, 600 000 rows
        QCOMPARE(h.maxRows(), size_t(600000));
        QCOMPARE(h.maxDuration(), 600.0);
        QVERIFY(h.memoryBytes() < 1'000'000); // grows on demand
        feed(h, 650000, 1000.0);
        QCOMPARE(h.size(), size_t(600000));
        QCOMPARE(h.capacity(), size_t(600000));
        QCOMPARE(h.memoryBytes(), size_t(600000) * 92);
        QVERIFY2(h.memoryBytes() <= 60'000'000, qPrintable(QString::number(h.memoryBytes())));
        QCOMPARE(h.totalAppended(), uint64_t(650000));
        QCOMPARE(h.dropped(), uint64_t(50000));
        // The oldest rows went: row 0 is sample 50 000.
        QCOMPARE(h.hostTime(0), 50.0);
        QCOMPARE(h.deviceTime(0), 5.0 + 50.0);
        QCOMPARE(h.value(Channel::AccX, 0), float(50000 % 1000));
        QCOMPARE(h.value(Channel::Temperature, h.size() - 1), float(649999 % 1000 + 17));
        QVERIFY(nonDecreasing(h, TimeAxis::Host));
        QVERIFY(nonDecreasing(h, TimeAxis::Device));
    }

    void boundedByDuration_data()
    {
        QTest::addColumn<double>("rateHz");
        QTest::addColumn<double>("durationS");
        QTest::addColumn<size_t>("maxRows");
        QTest::newRow("10 Hz, 1 s") << 10.0 << 1.0 << size_t(600000);
        QTest::newRow("100 Hz, 10 s") << 100.0 << 10.0 << size_t(600000);
        QTest::newRow("1 kHz, 30 s") << 1000.0 << 30.0 << size_t(600000);
        QTest::newRow("1 kHz, 30 s, 5000 rows") << 1000.0 << 30.0 << size_t(5000);
        QTest::newRow("2 kHz, 600 s cap") << 2000.0 << 600.0 << size_t(600000);
        QTest::newRow("out of range -> 600 s") << 100.0 << 10000.0 << size_t(10000000);
    }
    void boundedByDuration()
    {
        QFETCH(double, rateHz);
        QFETCH(double, durationS);
        QFETCH(size_t, maxRows);
        ChannelHistory h(durationS, maxRows);
        const double duration = std::min(durationS, ChannelHistory::kMaxDurationS);
        const size_t rows = std::min(maxRows, ChannelHistory::kMaxRows);
        QCOMPARE(h.maxDuration(), duration);
        QCOMPARE(h.maxRows(), rows);
        const size_t count = size_t(std::min(duration * 1.5 * rateHz, 1.3e6));
        feed(h, count, rateHz);
        const double span = h.newestTime(TimeAxis::Host) - h.oldestTime(TimeAxis::Host);
        QVERIFY2(span <= duration + 1e-9, qPrintable(QString::number(span)));
        QVERIFY(h.size() <= rows);
        QVERIFY(h.capacity() <= rows);
        // Full: either the row cap or the duration is what limits it.
        QVERIFY(h.size() == rows || span >= duration - 1.0 / rateHz - 1e-9);
        QCOMPARE(h.totalAppended(), uint64_t(count));
    }

    void presenceMask()
    {
        ChannelHistory h;
        // HI83 without pressure and magnetometer, then a full frame, then one with only Euler angles.
        const uint32_t noBaro = kImuFields & ~uint32_t(model::FieldPressure | model::FieldMag);
        h.append(makeSample(0, 0.0, 1.0, noBaro));
        h.append(makeSample(1'000'000, 1.0, 2.0));
        h.append(makeSample(2'000'000, 2.0, 3.0, model::FieldEuler | model::FieldDeviceTime));
        QCOMPARE(h.size(), size_t(3));
        QVERIFY(!h.has(Channel::Pressure, 0));
        QVERIFY(!h.has(Channel::MagY, 0));
        QVERIFY(std::isnan(h.value(Channel::Pressure, 0)));
        QVERIFY(h.has(Channel::AccX, 0));
        QCOMPARE(h.value(Channel::AccX, 0), 1.0f);
        QVERIFY(h.has(Channel::Pressure, 1));
        QCOMPARE(h.value(Channel::Pressure, 1), 18.0f);
        QVERIFY(h.has(Channel::Yaw, 2));
        QVERIFY(!h.has(Channel::AccX, 2));
        QVERIFY(!h.has(Channel::QuatW, 2));
        // Every channel these samples carry (the compass's relative field and magnetic roll are
        // not among them).
        QCOMPARE(h.presentChannels(), ChannelHistory::kChannelMask & ~(imudesk::plot::channelBit(Channel::MagRelX)
                                                                       | imudesk::plot::channelBit(Channel::MagRelY)
                                                                       | imudesk::plot::channelBit(Channel::MagRelZ)
                                                                       | imudesk::plot::channelBit(Channel::MagRoll)));
        QVERIFY(std::isnan(h.value(Channel::MagRelX, 1)));
        QVERIFY(!h.columnData(Channel::MagRoll)); // never carried: no column

        ChannelHistory onlyImu;
        onlyImu.append(makeSample(0, 0.0, 1.0, model::FieldAcc | model::FieldGyr));
        QCOMPARE(onlyImu.presentChannels(),
                 ChannelHistory::channelsOfField(model::FieldAcc) | ChannelHistory::channelsOfField(model::FieldGyr));
        QCOMPARE(std::popcount(onlyImu.presentChannels()), 6);
        QVERIFY(!(onlyImu.flags(0) & ChannelHistory::FlagDeviceTime));
    }

    void nonFiniteValuesAreAbsent()
    {
        ChannelHistory h;
        Sample s = makeSample(0, 0.0, 1.0);
        s.acc.y = std::nan("");
        s.pressurePa = INFINITY;
        h.append(s);
        QVERIFY(h.has(Channel::AccX, 0));
        QVERIFY(!h.has(Channel::AccY, 0));
        QVERIFY(!h.has(Channel::Pressure, 0));
    }

    void wrapAround()
    {
        ChannelHistory h(600.0, 100);
        feed(h, 250, 100.0);
        QCOMPARE(h.size(), size_t(100));
        const auto runs = h.physicalRuns(0, h.size());
        QCOMPARE(runs[0].end - runs[0].begin + runs[1].end - runs[1].begin, size_t(100));
        QVERIFY(runs[1].end > runs[1].begin); // 250 rows in a 100-row ring: the window wraps
        size_t row = 0;
        for (const auto &run : runs) {
            for (size_t p = run.begin; p < run.end; ++p, ++row) {
                QCOMPARE(h.timeData(TimeAxis::Host)[p], h.hostTime(row));
                QCOMPARE(h.columnData(Channel::GyrZ)[p], h.value(Channel::GyrZ, row));
            }
        }
        for (size_t i = 0; i < h.size(); ++i)
            QCOMPARE(h.value(Channel::AccX, i), float((150 + i) % 1000));
        QVERIFY(nonDecreasing(h, TimeAxis::Host));
    }

    void rangeQueries_data()
    {
        QTest::addColumn<TimeAxis>("axis");
        QTest::addColumn<double>("t0");
        QTest::addColumn<double>("t1");
        QTest::addColumn<size_t>("first");
        QTest::addColumn<size_t>("last");
        // 100 Hz for 10 s: host 0.00 .. 9.99 s, device 5.00 .. 14.99 s.
        QTest::newRow("host all") << TimeAxis::Host << -1.0 << 100.0 << size_t(0) << size_t(1000);
        QTest::newRow("host exact ends") << TimeAxis::Host << 1.0 << 2.0 << size_t(100) << size_t(201);
        QTest::newRow("host between rows") << TimeAxis::Host << 1.005 << 1.035 << size_t(101) << size_t(104);
        QTest::newRow("host before") << TimeAxis::Host << -5.0 << -1.0 << size_t(0) << size_t(0);
        QTest::newRow("host after") << TimeAxis::Host << 10.0 << 11.0 << size_t(1000) << size_t(1000);
        QTest::newRow("host reversed") << TimeAxis::Host << 2.0 << 1.0 << size_t(0) << size_t(0);
        QTest::newRow("device last second") << TimeAxis::Device << 14.0 << 15.0 << size_t(900) << size_t(1000);
        QTest::newRow("device one row") << TimeAxis::Device << 7.0 << 7.0 << size_t(200) << size_t(201);
        QTest::newRow("device before") << TimeAxis::Device << 0.0 << 4.99 << size_t(0) << size_t(0);
    }
    void rangeQueries()
    {
        QFETCH(TimeAxis, axis);
        QFETCH(double, t0);
        QFETCH(double, t1);
        QFETCH(size_t, first);
        QFETCH(size_t, last);
        ChannelHistory h;
        feed(h, 1000, 100.0, 0, 5000.0);
        const IndexRange r = h.range(axis, t0, t1);
        if (first == last) {
            QVERIFY(r.empty());
        } else {
            QCOMPARE(r.first, first);
            QCOMPARE(r.last, last);
        }
        QCOMPARE(r.size(), bruteRange(h, axis, t0, t1).size());
    }

    void randomQueriesMatchScan()
    {
        // Irregular host arrival in batches (equal stamps), a device gap, a reboot and a wrap of the ring.
        ChannelHistory h(600.0, 3000);
        std::mt19937 rng(7);
        std::uniform_int_distribution<int> batchSize(1, 12);
        int64_t hostNs = 0;
        double deviceMs = 100000.0;
        for (int i = 0; i < 5000;) {
            hostNs += int64_t(batchSize(rng)) * 1'000'000;
            const int n = batchSize(rng);
            for (int k = 0; k < n; ++k, ++i) {
                deviceMs += 1.0;
                if (i == 2000)
                    deviceMs += 250.0; // gap
                if (i == 3500)
                    deviceMs = 3.0; // reboot
                h.append(makeSample(hostNs, deviceMs, double(i)));
            }
        }
        QCOMPARE(h.size(), size_t(3000));
        QVERIFY(nonDecreasing(h, TimeAxis::Host));
        QVERIFY(nonDecreasing(h, TimeAxis::Device));
        for (TimeAxis axis : {TimeAxis::Host, TimeAxis::Device}) {
            const double lo = h.oldestTime(axis) - 1.0, hi = h.newestTime(axis) + 1.0;
            std::uniform_real_distribution<double> pick(lo, hi);
            for (int q = 0; q < 2000; ++q) {
                double a = pick(rng), b = pick(rng);
                if (q % 10 == 0)
                    a = b = h.time(axis, size_t(q) % h.size()); // exact hits
                if (a > b)
                    std::swap(a, b);
                const IndexRange got = h.range(axis, a, b);
                const IndexRange want = bruteRange(h, axis, a, b);
                QCOMPARE(got.size(), want.size());
                if (!want.empty())
                    QCOMPARE(got, want);
            }
        }
    }

    void deviceRestartStartsSegment()
    {
        ChannelHistory h;
        // 1 kHz from device time 1000 s, host stamped per sample; the device reboots after 500 samples.
        for (int i = 0; i < 1000; ++i) {
            const double deviceMs = i < 500 ? 1'000'000.0 + i : 20.0 + (i - 500);
            h.append(makeSample(int64_t(i) * 1'000'000, deviceMs, double(i)));
        }
        QCOMPARE(h.segmentCount(), 2);
        QVERIFY(nonDecreasing(h, TimeAxis::Device));
        QVERIFY(h.flags(500) & ChannelHistory::FlagSegmentStart);
        QVERIFY(!(h.flags(500) & ChannelHistory::FlagGap));
        QVERIFY(!(h.flags(499) & ChannelHistory::kBreakFlags));
        // The new segment continues one host step after the last row of the old one...
        QCOMPARE(h.deviceTime(500), h.deviceTime(499) + 0.001);
        // ...and shows the device's own clock once the offset is taken off.
        QCOMPARE(h.deviceTime(999) - h.deviceTimeOffset(), 0.020 + 0.499);
        QCOMPARE(h.deviceTime(0), 1000.0);
        // Queries across the restart still work on the stitched axis.
        const IndexRange r = h.range(TimeAxis::Device, h.deviceTime(490), h.deviceTime(510));
        QCOMPARE(r.first, size_t(490));
        QCOMPARE(r.last, size_t(511));
        QCOMPARE(h.lowerBound(TimeAxis::Device, h.deviceTimeOffset() + 0.0195), size_t(500));
    }

    void twoClocksOneAxis()
    {
        // HI91 at 100 Hz on the UTC day (08:00:00 on, PPS-aligned) interleaved with HI83 at
        // 100 Hz whose system_time_us still counts from power-on: the axis follows HI91 alone,
        // one segment, 10 ms a row pair, and an HI83 row sits between the HI91 rows.
        ChannelHistory h;
        for (int i = 0; i < 400; ++i) {
            Sample a = makeSample(int64_t(i) * 10'000'000, 28'800'000.0 + i * 10.0, double(i));
            Sample b = makeSample(int64_t(i) * 10'000'000 + 5'000'000, 12'000.0 + i * 10.0, double(i));
            b.source = "HI83";
            h.append(std::vector<Sample>{a, b});
        }
        QCOMPARE(h.segmentCount(), 1);
        QVERIFY(nonDecreasing(h, TimeAxis::Device));
        QCOMPARE(h.deviceTime(h.size() - 1) - h.deviceTime(0), 3.99);
        // An HI83 row between two HI91 rows goes where its host time puts it (5 ms after the HI91
        // row before it), not on that row's time.
        QVERIFY(std::abs(h.deviceTime(1) - h.deviceTime(0) - 0.005) < 1e-9);
        QVERIFY(!(h.flags(1) & ChannelHistory::FlagDeviceTime));
        // HI91 stops; after kClockHandOverS of host time HI83's clock takes over (a new segment).
        for (int i = 400; i < 700; ++i) {
            Sample b = makeSample(int64_t(i) * 10'000'000 + 5'000'000, 12'000.0 + i * 10.0, double(i));
            b.source = "HI83";
            h.append(std::vector<Sample>{b});
        }
        QCOMPARE(h.segmentCount(), 2);
        QVERIFY(nonDecreasing(h, TimeAxis::Device));
        QVERIFY(h.flags(h.size() - 1) & ChannelHistory::FlagDeviceTime);
        QCOMPARE(h.deviceTime(h.size() - 1) - h.deviceTimeOffset(), 12.0 + 6.99);

        // A slow type first (HI83 at 20 Hz), then a busy one beside it (HI91 at 100 Hz): the
        // busy one's clock carries the axis after one window, so its rows are not stairs.
        ChannelHistory g;
        for (int i = 0; i < 1000; ++i) {
            const bool hi83 = i % 5 == 0;
            Sample x = makeSample(int64_t(i) * 10'000'000, (hi83 ? 12'000.0 : 28'800'000.0) + i * 10.0, double(i));
            x.source = hi83 ? "HI83" : "HI91";
            g.append(std::vector<Sample>{x});
        }
        QCOMPARE(g.segmentCount(), 2);
        QVERIFY(g.flags(g.size() - 2) & ChannelHistory::FlagDeviceTime); // an HI91 row
        QVERIFY(!(g.flags(g.size() - 5) & ChannelHistory::FlagDeviceTime)); // an HI83 row
    }

    void deviceGapStaysAGap_data()
    {
        QTest::addColumn<double>("rateHz");
        QTest::addColumn<double>("gapMs");
        QTest::addColumn<bool>("flagged");
        QTest::newRow("1 kHz, 100 ms") << 1000.0 << 100.0 << true;
        QTest::newRow("1 kHz, 3 ms (within 5 periods)") << 1000.0 << 3.0 << false;
        QTest::newRow("100 Hz, 1 s") << 100.0 << 1000.0 << true;
        QTest::newRow("400 Hz (2/3 ms steps), 40 ms") << 400.0 << 40.0 << true;
        QTest::newRow("400 Hz (2/3 ms steps), 5 ms") << 400.0 << 5.0 << false;
    }
    void deviceGapStaysAGap()
    {
        QFETCH(double, rateHz);
        QFETCH(double, gapMs);
        QFETCH(bool, flagged);
        ChannelHistory h;
        const double period = 1000.0 / rateHz;
        for (int i = 0; i < 400; ++i) {
            // Device time quantised to whole ms, as HI91 system_time is.
            double deviceMs = std::floor(double(i) * period);
            if (i >= 200)
                deviceMs += gapMs;
            // The host gets the samples in 10 ms batches: no gap on the host clock.
            h.append(makeSample(int64_t(i / 10) * 10'000'000, deviceMs, double(i)));
        }
        QCOMPARE(bool(h.flags(200) & ChannelHistory::FlagGap), flagged);
        for (size_t i = 1; i < h.size(); ++i)
            if (i != 200)
                QVERIFY2(!(h.flags(i) & ChannelHistory::kBreakFlags), qPrintable(QString::number(i)));
        QCOMPARE(h.segmentCount(), 1);
        // The gap is kept on the device axis.
        QCOMPARE(h.deviceTime(200) - h.deviceTime(199),
                 (std::floor(200 * period) + gapMs - std::floor(199 * period)) / 1000.0);
        QVERIFY(std::abs(h.samplePeriod() - period / 1000.0) < 0.0011);
    }

    void hostClockNeverGoesBack()
    {
        ChannelHistory h;
        h.append(makeSample(5'000'000'000, 0.0));
        h.append(makeSample(5'010'000'000, 10.0));
        h.append(makeSample(5'005'000'000, 20.0)); // stamped earlier: clamped
        h.append(makeSample(5'020'000'000, 30.0));
        QCOMPARE(h.hostOriginNs(), int64_t(5'000'000'000));
        QCOMPARE(h.hostTime(0), 0.0);
        QCOMPARE(h.hostTime(2), h.hostTime(1));
        QCOMPARE(h.hostTime(3), 0.020);
        QVERIFY(nonDecreasing(h, TimeAxis::Host));
    }

    void withoutDeviceClock()
    {
        ChannelHistory h;
        const uint32_t fields = kImuFields & ~uint32_t(model::FieldDeviceTime);
        for (int i = 0; i < 10; ++i)
            h.append(makeSample(int64_t(i) * 10'000'000, 0.0, 0.0, fields));
        // The device axis follows the host clock.
        QCOMPARE(h.deviceTime(9), h.hostTime(9));
        QCOMPARE(h.segmentCount(), 1);
        // A device time showing up later starts a segment; rows without one later repeat the last.
        h.append(makeSample(100'000'000, 777.0));
        QCOMPARE(h.segmentCount(), 2);
        QVERIFY(h.flags(10) & ChannelHistory::FlagSegmentStart);
        h.append(makeSample(110'000'000, 0.0, 0.0, fields));
        QCOMPARE(h.deviceTime(11), h.deviceTime(10));
        QVERIFY(nonDecreasing(h, TimeAxis::Device));
    }

    // A device that sends its clock in some frames only and then stops sending them (the
    // HEC495's full records, then angles alone): once the clock is overdue (kOverduePeriods)
    // the host clock carries the device axis on from the clock's last row, so the charts keep
    // moving (issue 53: the rows of a whole second stood at one instant, a step and then a flat
    // stretch in the Euler chart); a device time that comes back after kClockHandOverS starts
    // a new segment.
    void deviceClockFallsSilent()
    {
        ChannelHistory h;
        for (int i = 0; i < 100; ++i) // 1 s of records, device time 5000 ms onwards
            h.append(makeSample(int64_t(i) * 10'000'000, 5000.0 + i * 10.0));
        const double lastClocked = h.newestTime(TimeAxis::Device);
        const uint32_t angles = model::FieldEuler;
        for (int i = 100; i < 400; ++i) // 3 s of angles without a device time
            h.append(makeSample(int64_t(i) * 10'000'000, 0.0, 0.0, angles));
        QVERIFY(nonDecreasing(h, TimeAxis::Device));
        // The rows follow the host clock from the clock's last row (0.99 s): none stands at
        // its time, not even the two before it was overdue; the axis has moved on by the host
        // time since the clock fell silent (0.99 s to 3.99 s).
        QVERIFY(std::abs(h.deviceTime(150) - lastClocked - 0.51) < 1e-9);
        for (int i = 100; i < 400; ++i)
            QVERIFY2(std::abs(h.deviceTime(size_t(i)) - h.deviceTime(size_t(i - 1)) - 0.01) < 1e-9,
                     qPrintable(QStringLiteral("row %1: %2 s after the one before")
                                    .arg(i)
                                    .arg(h.deviceTime(size_t(i)) - h.deviceTime(size_t(i - 1)))));
        QVERIFY2(std::abs(h.newestTime(TimeAxis::Device) - lastClocked - 3.0) < 1e-6,
                 qPrintable(QString::number(h.newestTime(TimeAxis::Device) - lastClocked)));
        QVERIFY(h.deviceTime(399) > h.deviceTime(398));
        QCOMPARE(h.segmentCount(), 1);
        // The clock comes back: a new segment, right after the last row.
        h.append(makeSample(4'000'000'000, 9000.0));
        QCOMPARE(h.segmentCount(), 2);
        QVERIFY(h.flags(400) & ChannelHistory::FlagSegmentStart);
        QVERIFY(h.deviceTime(400) > h.deviceTime(399));
        QVERIFY(h.deviceTime(400) - h.deviceTime(399) < 0.02);
        QVERIFY(nonDecreasing(h, TimeAxis::Device));
    }

    void nearestRow()
    {
        ChannelHistory h;
        h.append(makeSample(0, 0.0, 1.0));
        h.append(makeSample(10'000'000, 10.0, 2.0, model::FieldGyr | model::FieldDeviceTime));
        h.append(makeSample(20'000'000, 20.0, 3.0));
        QCOMPARE(h.nearestRow(TimeAxis::Host, 0.009, Channel::GyrX), 1LL);
        QCOMPARE(h.nearestRow(TimeAxis::Host, 0.009, Channel::AccX), 0LL);
        QCOMPARE(h.nearestRow(TimeAxis::Host, 0.011, Channel::AccX), 2LL);
        QCOMPARE(h.nearestRow(TimeAxis::Host, 5.0, Channel::AccX), 2LL);
        QCOMPARE(h.nearestRow(TimeAxis::Host, 0.0, Channel::Pressure), 0LL);
        QCOMPARE(h.nearestRow(TimeAxis::Host, 0.0, Channel::QuatW, 0), -1LL);
    }

    void clearAndRevision()
    {
        ChannelHistory h;
        const uint64_t r0 = h.revision();
        feed(h, 100, 100.0);
        QVERIFY(h.revision() != r0);
        const uint64_t r1 = h.revision();
        h.append(std::vector<Sample>{});
        QCOMPARE(h.revision(), r1); // nothing appended, nothing to redraw
        const size_t capacity = h.capacity();
        const uint64_t generation = h.generation();
        h.clear();
        QVERIFY(h.revision() != r1);
        QCOMPARE(h.generation(), generation + 1);
        QVERIFY(h.empty());
        QCOMPARE(h.capacity(), capacity);
        QCOMPARE(h.presentChannels(), 0u);
        QCOMPARE(h.segmentCount(), 0);
        feed(h, 10, 100.0, 7'000'000'000, 42.0);
        QCOMPARE(h.hostOriginNs(), int64_t(7'000'000'000));
        QCOMPARE(h.hostTime(0), 0.0);
        QCOMPARE(h.deviceTime(0), 0.042);
    }

    void shrinkingLimits()
    {
        ChannelHistory h;
        feed(h, 5000, 100.0); // 50 s
        h.setLimits(10.0, 600000);
        QVERIFY(h.newestTime(TimeAxis::Host) - h.oldestTime(TimeAxis::Host) <= 10.0);
        h.setLimits(600.0, 100);
        QCOMPARE(h.size(), size_t(100));
        QCOMPARE(h.capacity(), size_t(100));
        QCOMPARE(h.value(Channel::AccX, 99), float(4999 % 1000));
        feed(h, 10, 100.0, 60'000'000'000);
        QCOMPARE(h.size(), size_t(100));
    }

    // The one catalogue: each channel reads its own member of the Sample, needs its own
    // field, belongs to its chart, and is named and coloured once (X red, Y green, Z blue).
    void catalogueReadsEachChannelOnce()
    {
        model::Sample s;
        s.acc = {1, 2, 3};
        s.gyr = {4, 5, 6};
        s.mag = {7, 8, 9};
        s.roll = 10;
        s.pitch = 11;
        s.yaw = 12;
        s.quat = {13, 14, 15, 16};
        s.pressurePa = 17;
        s.temperatureC = 18;
        s.magRelative = {19, 20, 21};
        s.magRollDeg = 22;
        const auto catalog = imudesk::plot::channelCatalog();
        QCOMPARE(int(catalog.size()), imudesk::plot::kChannelCount);
        for (int c = 0; c < imudesk::plot::kChannelCount; ++c) {
            const imudesk::plot::ChannelInfo &i = catalog[size_t(c)];
            QCOMPARE(int(i.channel), c);
            QCOMPARE(i.read(s), double(c + 1));
            QCOMPARE(imudesk::plot::ChannelHistory::channelsOfField(i.field) & imudesk::plot::channelBit(i.channel),
                     imudesk::plot::channelBit(i.channel));
        }
        QCOMPARE(imudesk::plot::channelsOf(imudesk::plot::ChannelGroup::Quaternion),
                 (std::vector<imudesk::plot::Channel>{imudesk::plot::Channel::QuatW, imudesk::plot::Channel::QuatX, imudesk::plot::Channel::QuatY,
                                             imudesk::plot::Channel::QuatZ}));
        QCOMPARE(imudesk::plot::channelName(imudesk::plot::Channel::GyrY), QStringLiteral("Angular velocity Y"));
        QCOMPARE(imudesk::plot::channelName(imudesk::plot::Channel::Yaw), QStringLiteral("Yaw"));
        QCOMPARE(imudesk::plot::channelInfo(imudesk::plot::Channel::MagX).rgb, imudesk::plot::channelInfo(imudesk::plot::Channel::Roll).rgb);
        QVERIFY(imudesk::plot::channelInfo(imudesk::plot::Channel::AccX).rgb != imudesk::plot::channelInfo(imudesk::plot::Channel::AccY).rgb);
        QCOMPARE(imudesk::plot::ChannelHistory::channelsOfField(imudesk::model::FieldEuler | imudesk::model::FieldPressure),
                 imudesk::plot::channelBit(imudesk::plot::Channel::Roll) | imudesk::plot::channelBit(imudesk::plot::Channel::Pitch)
                     | imudesk::plot::channelBit(imudesk::plot::Channel::Yaw) | imudesk::plot::channelBit(imudesk::plot::Channel::Pressure));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstChannelHistory)
#include "tst_channel_history.moc"
