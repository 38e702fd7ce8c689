// MinMaxDecimator: output bound, spikes survive, exact agreement with a brute-force
// per-column reference on random data (gaps, restarts, missing fields, ties), breaks.
#include "plot/minmax_decimator.h"
#include "../common/test_main.h"

#include <QTest>

#include <cmath>
#include <map>
#include <random>

using imudesk::model::Sample;
using imudesk::plot::Channel;
using imudesk::plot::ChannelHistory;
using imudesk::plot::MinMaxDecimator;
using imudesk::plot::TimeAxis;
namespace model = imudesk::model;

Q_DECLARE_METATYPE(TimeAxis)

namespace {

constexpr uint32_t kFields = model::FieldAcc | model::FieldGyr | model::FieldPressure | model::FieldDeviceTime;

Sample makeSample(int64_t hostNs, double deviceMs, double accX, uint32_t fields = kFields)
{
    Sample s;
    s.fields = fields;
    s.hostTimeNs = hostNs;
    s.deviceTimeMs = deviceMs;
    s.acc = {accX, -accX, 1.0};
    s.gyr = {0.5 * accX, 0.0, 0.0};
    s.pressurePa = 101325.0 + accX;
    return s;
}

// 1 kHz, a sine plus a little deterministic noise; host stamps in 8-sample batches.
void feedSine(ChannelHistory &h, size_t count, uint32_t seed = 1)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, 0.01);
    std::vector<Sample> batch;
    batch.reserve(1000);
    for (size_t i = 0; i < count; ++i) {
        const double t = double(i) / 1000.0;
        batch.push_back(makeSample(int64_t(i / 8) * 8'000'000, 1000.0 + double(i), std::sin(t) + noise(rng)));
        if (batch.size() == 1000) {
            h.append(batch);
            batch.clear();
        }
    }
    h.append(batch);
}

// The specification, written the slow way: group the window's rows by column, then
// emit first/min/max/last per column with the break rule.
QList<QPointF> reference(const ChannelHistory &h, Channel channel, TimeAxis axis, double t0, double t1, int width,
                         bool breaks, double xOffset)
{
    struct Item {
        size_t row;
        double t;
        float v;
        bool breakBefore;
    };
    QList<QPointF> out;
    if (width < 1 || !(t1 > t0))
        return out;
    std::map<int, std::vector<Item>> columns;
    bool pending = false;
    for (size_t i = 0; i < h.size(); ++i) {
        const double t = h.time(axis, i);
        if (t < t0 || t > t1)
            continue;
        pending = pending || (h.flags(i) & ChannelHistory::kBreakFlags);
        if (!h.has(channel, i))
            continue;
        const int c = std::min(int((t - t0) * (double(width) / (t1 - t0))), width - 1);
        columns[c].push_back({i, t, h.value(channel, i), pending && breaks});
        pending = false;
    }
    bool firstColumn = true;
    for (const auto &[c, items] : columns) {
        const Item &first = items.front();
        const Item &last = items.back();
        size_t lo = 0, hi = 0;
        for (size_t k = 1; k < items.size(); ++k) {
            if (items[k].v < items[lo].v)
                lo = k;
            if (items[k].v > items[hi].v)
                hi = k;
        }
        const bool brk = !firstColumn && first.breakBefore;
        if (brk)
            out.append(MinMaxDecimator::breakPoint());
        std::vector<size_t> picks;
        if (!brk || lo == 0 || hi == 0)
            picks.push_back(0);
        picks.push_back(std::min(lo, hi));
        picks.push_back(std::max(lo, hi));
        picks.push_back(items.size() - 1);
        size_t previous = ~size_t(0);
        for (size_t k : picks) {
            if (k == previous)
                continue;
            previous = k;
            out.append(QPointF(items[k].t - xOffset, double(items[k].v)));
        }
        (void)last;
        firstColumn = false;
    }
    return out;
}

bool samePoints(const QList<QPointF> &a, const QList<QPointF> &b, QString *why)
{
    if (a.size() != b.size()) {
        *why = QStringLiteral("size %1 != %2").arg(a.size()).arg(b.size());
        return false;
    }
    for (qsizetype i = 0; i < a.size(); ++i) {
        const bool ba = MinMaxDecimator::isBreak(a[i]), bb = MinMaxDecimator::isBreak(b[i]);
        if (ba != bb || (!ba && (a[i].x() != b[i].x() || a[i].y() != b[i].y()))) {
            *why = QStringLiteral("point %1: (%2, %3) != (%4, %5)")
                       .arg(i)
                       .arg(a[i].x(), 0, 'g', 17)
                       .arg(a[i].y())
                       .arg(b[i].x(), 0, 'g', 17)
                       .arg(b[i].y());
            return false;
        }
    }
    return true;
}

int breakCount(const QList<QPointF> &points)
{
    return int(std::count_if(points.begin(), points.end(), MinMaxDecimator::isBreak));
}

} // namespace

class TstMinMaxDecimator : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void spikeSurvives_data()
    {
        QTest::addColumn<size_t>("spikeRow");
        QTest::addColumn<double>("spike");
        QTest::addColumn<int>("width");
        QTest::newRow("middle, up, 1000 px") << size_t(300000) << 50.0 << 1000;
        QTest::newRow("first row, down, 1000 px") << size_t(0) << -50.0 << 1000;
        QTest::newRow("last row, up, 1000 px") << size_t(599999) << 50.0 << 1000;
        QTest::newRow("odd row, down, 317 px") << size_t(123457) << -3.0 << 317;
        QTest::newRow("1 px") << size_t(444444) << 9.0 << 1;
    }
    void spikeSurvives()
    {
        QFETCH(size_t, spikeRow);
        QFETCH(double, spike);
        QFETCH(int, width);
        // 600 000 rows at 1 kHz (10 min) with a single-sample spike.
        ChannelHistory h;
        std::vector<Sample> batch;
        batch.reserve(1000);
        for (size_t i = 0; i < 600000; ++i) {
            const double v = i == spikeRow ? spike : std::sin(double(i) / 1000.0);
            batch.push_back(makeSample(int64_t(i) * 1'000'000, double(i), v));
            if (batch.size() == 1000) {
                h.append(batch);
                batch.clear();
            }
        }
        QCOMPARE(h.size(), size_t(600000));
        MinMaxDecimator d;
        QList<QPointF> out;
        // The charts' mode, min and max only: at most 2 points per column, the spike still there.
        d.setExtremaOnly(true);
        d.decimate(h, Channel::AccX, TimeAxis::Device, h.oldestTime(TimeAxis::Device), h.newestTime(TimeAxis::Device),
                   width, out);
        QVERIFY2(out.size() <= 2 * width, qPrintable(QString::number(out.size())));
        QVERIFY(std::any_of(out.begin(), out.end(), [&](const QPointF &p) {
            return p.y() == double(float(spike)) && p.x() == h.deviceTime(spikeRow);
        }));
        d.setExtremaOnly(false);
        const auto result = d.decimate(h, Channel::AccX, TimeAxis::Device, h.oldestTime(TimeAxis::Device),
                                       h.newestTime(TimeAxis::Device), width, out);
        QCOMPARE(result.rows, size_t(600000));
        QVERIFY2(size_t(out.size()) <= MinMaxDecimator::maxPoints(width), qPrintable(QString::number(out.size())));
        const double spikeTime = h.deviceTime(spikeRow);
        const bool found = std::any_of(out.begin(), out.end(), [&](const QPointF &p) {
            return p.y() == double(float(spike)) && p.x() == spikeTime;
        });
        QVERIFY(found);
        QCOMPARE(spike > 0 ? result.yMax : result.yMin, double(float(spike)));
        // The other sign's extreme is the sine's.
        QVERIFY(std::abs(spike > 0 ? result.yMin : result.yMax) <= 1.0);
        QCOMPARE(breakCount(out), 0);
    }

    void matchesReference_data()
    {
        QTest::addColumn<uint32_t>("seed");
        QTest::addColumn<int>("rows");
        QTest::addColumn<int>("width");
        QTest::addColumn<double>("gapChance");
        QTest::addColumn<double>("missingChance");
        QTest::addColumn<bool>("ties");
        QTest::addColumn<TimeAxis>("axis");
        QTest::addColumn<double>("from");   // window as fractions of the history's span
        QTest::addColumn<double>("to");
        QTest::addColumn<bool>("breaks");
        QTest::newRow("dense, device") << 1u << 50000 << 640 << 0.0005 << 0.0 << false << TimeAxis::Device << 0.0 << 1.0 << true;
        QTest::newRow("dense, host") << 2u << 50000 << 640 << 0.0005 << 0.0 << false << TimeAxis::Host << 0.0 << 1.0 << true;
        QTest::newRow("ties") << 3u << 20000 << 500 << 0.001 << 0.1 << true << TimeAxis::Device << 0.1 << 0.9 << true;
        QTest::newRow("sparse: more px than rows") << 4u << 300 << 1000 << 0.02 << 0.2 << false << TimeAxis::Device << 0.0 << 1.0 << true;
        QTest::newRow("gap in every column") << 5u << 40000 << 200 << 0.05 << 0.0 << false << TimeAxis::Device << 0.0 << 1.0 << true;
        QTest::newRow("many missing") << 6u << 30000 << 333 << 0.01 << 0.7 << true << TimeAxis::Host << 0.25 << 0.5 << true;
        QTest::newRow("breaks off") << 7u << 30000 << 400 << 0.01 << 0.3 << false << TimeAxis::Device << 0.0 << 1.0 << false;
        QTest::newRow("narrow window") << 8u << 30000 << 800 << 0.01 << 0.1 << false << TimeAxis::Device << 0.5 << 0.52 << true;
        QTest::newRow("1 px") << 9u << 5000 << 1 << 0.01 << 0.1 << true << TimeAxis::Device << 0.0 << 1.0 << true;
    }
    void matchesReference()
    {
        QFETCH(uint32_t, seed);
        QFETCH(int, rows);
        QFETCH(int, width);
        QFETCH(double, gapChance);
        QFETCH(double, missingChance);
        QFETCH(bool, ties);
        QFETCH(TimeAxis, axis);
        QFETCH(double, from);
        QFETCH(double, to);
        QFETCH(bool, breaks);

        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        std::uniform_int_distribution<int> small(-3, 3);
        std::uniform_int_distribution<int> batchSize(1, 16);
        // A ring smaller than the data, so the window wraps in storage.
        ChannelHistory h(600.0, size_t(rows) * 3 / 4);
        int64_t hostNs = 0;
        double deviceMs = 5000.0;
        int pendingInBatch = 0;
        for (int i = 0; i < rows; ++i) {
            if (pendingInBatch-- <= 0) {
                pendingInBatch = batchSize(rng);
                hostNs += int64_t(pendingInBatch) * 1'000'000 + int64_t(unit(rng) * 300'000);
            }
            deviceMs += 1.0;
            if (unit(rng) < gapChance)
                deviceMs += 5.0 + 200.0 * unit(rng);
            if (unit(rng) < gapChance / 10)
                deviceMs = 10.0 * unit(rng); // restart
            uint32_t fields = kFields;
            if (unit(rng) < missingChance)
                fields &= ~uint32_t(model::FieldAcc);
            const double v = ties ? double(small(rng)) : unit(rng) * 2.0 - 1.0;
            h.append(makeSample(hostNs, deviceMs, v, fields));
        }
        const double span = h.newestTime(axis) - h.oldestTime(axis);
        const double t0 = h.oldestTime(axis) + from * span;
        const double t1 = h.oldestTime(axis) + to * span;
        const double xOffset = axis == TimeAxis::Device ? h.deviceTimeOffset() : 0.0;

        MinMaxDecimator d;
        d.setBreakAtGaps(breaks);
        QList<QPointF> out;
        const auto result = d.decimate(h, Channel::AccX, axis, t0, t1, width, out, xOffset);
        const QList<QPointF> want = reference(h, Channel::AccX, axis, t0, t1, width, breaks, xOffset);
        QString why;
        QVERIFY2(samePoints(out, want, &why), qPrintable(why));
        QVERIFY(size_t(out.size()) <= MinMaxDecimator::maxPoints(width));
        QCOMPARE(result.breaks, size_t(breakCount(out)));
        if (!breaks)
            QCOMPARE(result.breaks, size_t(0));
        else if (gapChance >= 0.01 && width >= 200)
            QVERIFY(result.breaks > 0);
        // Every non-break point is a stored row of the window.
        for (const QPointF &p : out) {
            if (MinMaxDecimator::isBreak(p))
                continue;
            QVERIFY(p.x() + xOffset >= t0 - 1e-9 && p.x() + xOffset <= t1 + 1e-9);
        }
    }

    void gapsAndRestartsBreakTheLine_data()
    {
        QTest::addColumn<bool>("restart"); // else a 200 ms gap
        QTest::addColumn<TimeAxis>("axis");
        QTest::newRow("gap, device axis") << false << TimeAxis::Device;
        QTest::newRow("gap, host axis") << false << TimeAxis::Host;
        QTest::newRow("restart, device axis") << true << TimeAxis::Device;
        QTest::newRow("restart, host axis") << true << TimeAxis::Host;
    }
    void gapsAndRestartsBreakTheLine()
    {
        QFETCH(bool, restart);
        QFETCH(TimeAxis, axis);
        ChannelHistory h;
        for (int i = 0; i < 2000; ++i) {
            double deviceMs = 70000.0 + i;
            if (i >= 1000)
                deviceMs = restart ? double(i - 1000) : deviceMs + 200.0;
            // The host clock keeps going; 1 ms per sample.
            h.append(makeSample(int64_t(i) * 1'000'000, deviceMs, std::sin(i / 50.0)));
        }
        MinMaxDecimator d;
        QList<QPointF> out;
        const double t0 = h.oldestTime(axis), t1 = h.newestTime(axis);
        d.decimate(h, Channel::AccX, axis, t0, t1, 1000, out);
        QCOMPARE(breakCount(out), 1);
        const qsizetype at = std::find_if(out.begin(), out.end(), MinMaxDecimator::isBreak) - out.begin();
        QVERIFY(at > 0 && at + 1 < out.size());
        QCOMPARE(out[at - 1].x(), h.time(axis, 999));
        QCOMPARE(out[at + 1].x(), h.time(axis, 1000));
        if (!restart && axis == TimeAxis::Device)
            QVERIFY(out[at + 1].x() - out[at - 1].x() > 0.2); // the gap is kept on the device axis

        // The same data with breaks off: one line.
        d.setBreakAtGaps(false);
        d.decimate(h, Channel::AccX, axis, t0, t1, 1000, out);
        QCOMPARE(breakCount(out), 0);
    }

    void gapOnRowWithoutTheChannel()
    {
        // The row right after the gap lacks pressure; the break still comes before the next pressure row.
        ChannelHistory h;
        for (int i = 0; i < 200; ++i) {
            const double deviceMs = i < 100 ? i : i + 500.0;
            const uint32_t fields = i == 100 ? (kFields & ~uint32_t(model::FieldPressure)) : kFields;
            h.append(makeSample(int64_t(i) * 1'000'000, deviceMs, 0.0, fields));
        }
        QVERIFY(h.flags(100) & ChannelHistory::FlagGap);
        QVERIFY(!h.has(Channel::Pressure, 100));
        MinMaxDecimator d;
        QList<QPointF> out;
        d.decimate(h, Channel::Pressure, TimeAxis::Device, h.oldestTime(TimeAxis::Device),
                   h.newestTime(TimeAxis::Device), 600, out);
        QCOMPARE(breakCount(out), 1);
    }

    void boundHoldsWithAGapInEveryColumn()
    {
        // Bursts of 20 rows (19 ms) every 219 ms: nearly every column holds a full burst (>= 4
        // rows) and starts after a gap, and still gets at most 4 points.
        ChannelHistory h;
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        double deviceMs = 0;
        for (int i = 0; i < 20000; ++i) {
            deviceMs += (i % 20 == 0) ? 201.0 : 1.0;
            h.append(makeSample(int64_t(i) * 1'000'000, deviceMs, unit(rng)));
        }
        MinMaxDecimator d;
        QList<QPointF> out;
        const double t0 = h.oldestTime(TimeAxis::Device), t1 = h.newestTime(TimeAxis::Device);
        const int width = int((t1 - t0) / (0.219 * 0.95)); // columns drift across the bursts
        d.decimate(h, Channel::AccX, TimeAxis::Device, t0, t1, width, out);
        QVERIFY2(size_t(out.size()) <= MinMaxDecimator::maxPoints(width),
                 qPrintable(QStringLiteral("%1 > 4 x %2").arg(out.size()).arg(width)));
        QVERIFY(breakCount(out) > width / 2);
    }

    void missingChannelGivesNothing()
    {
        ChannelHistory h;
        const uint32_t noBaro = kFields & ~uint32_t(model::FieldPressure);
        for (int i = 0; i < 100; ++i)
            h.append(makeSample(int64_t(i) * 1'000'000, i, 1.0, noBaro));
        MinMaxDecimator d;
        QList<QPointF> out{QPointF(1, 1)};
        const auto r = d.decimate(h, Channel::Pressure, TimeAxis::Host, 0.0, 1.0, 100, out);
        QVERIFY(out.isEmpty());
        QCOMPARE(r.rows, size_t(0));
        QCOMPARE(d.decimate(h, Channel::MagX, TimeAxis::Host, 0.0, 1.0, 100, out).rows, size_t(0));
    }

    void degenerateRequests()
    {
        ChannelHistory h;
        feedSine(h, 1000);
        MinMaxDecimator d;
        QList<QPointF> out;
        QCOMPARE(d.decimate(h, Channel::AccX, TimeAxis::Host, 0.0, 1.0, 0, out).rows, size_t(0));
        QCOMPARE(d.decimate(h, Channel::AccX, TimeAxis::Host, 1.0, 1.0, 100, out).rows, size_t(0));
        QCOMPARE(d.decimate(h, Channel::AccX, TimeAxis::Host, 2.0, 1.0, 100, out).rows, size_t(0));
        QCOMPARE(d.decimate(h, Channel::AccX, TimeAxis::Host, 50.0, 60.0, 100, out).rows, size_t(0));
        QCOMPARE(d.decimate(h, Channel::AccX, TimeAxis::Host, qQNaN(), 1.0, 100, out).rows, size_t(0));
        QVERIFY(out.isEmpty());
        ChannelHistory empty;
        QCOMPARE(d.decimate(empty, Channel::AccX, TimeAxis::Device, 0.0, 1.0, 100, out).rows, size_t(0));
    }

    void fewRowsAreKeptAsTheyAre()
    {
        // Fewer rows than pixels: every row comes out once, in order, shifted by xOffset.
        ChannelHistory h;
        for (int i = 0; i < 50; ++i)
            h.append(makeSample(int64_t(i) * 10'000'000, 1000.0 + 10.0 * i, double(i)));
        MinMaxDecimator d;
        QList<QPointF> out;
        d.decimate(h, Channel::GyrX, TimeAxis::Device, 1.0, 1.49, 1000, out, 1.0);
        QCOMPARE(out.size(), qsizetype(50));
        for (int i = 0; i < 50; ++i) {
            QCOMPARE(out[i].x(), 1.0 + 0.01 * i - 1.0);
            QCOMPARE(out[i].y(), 0.5 * i);
        }
    }

    void reusesTheOutputBuffer()
    {
        ChannelHistory h;
        feedSine(h, 20000);
        MinMaxDecimator d;
        QList<QPointF> out;
        d.decimate(h, Channel::AccX, TimeAxis::Host, 0.0, 20.0, 500, out);
        QVERIFY(out.capacity() >= 2000);
        const QPointF *data = out.constData();
        const qsizetype capacity = out.capacity();
        for (int k = 0; k < 5; ++k) {
            d.decimate(h, Channel::AccX, TimeAxis::Host, 0.5 * k, 10.0 + 0.5 * k, 500, out);
            QCOMPARE(out.constData(), data);
            QCOMPARE(out.capacity(), capacity);
        }
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstMinMaxDecimator)
#include "tst_minmax_decimator.moc"
