// Allan deviation and the recording analysis: white noise of known density gives the density
// at tau = 1 s within 5 %; a bias random walk shows the +1/2 slope; statistics, output rate,
// interval histogram and frames lost from system_time gaps.
#include "record/allan_deviation.h"
#include "record/sample_analyzer.h"
#include "../common/test_main.h"

#include <QTest>

#include <cmath>
#include <random>

using imudesk::record::AllanDeviation;
using imudesk::record::SampleAnalyzer;
namespace model = imudesk::model;

namespace {

double slope(const std::vector<AllanDeviation::Point> &c, double tau1, double tau2)
{
    double a = 0, b = 0;
    AllanDeviation::at(c, tau1, &a);
    AllanDeviation::at(c, tau2, &b);
    return (std::log(b) - std::log(a)) / (std::log(tau2) - std::log(tau1));
}

} // namespace

class TstAllanDeviation : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void clusters()
    {
        const auto m = AllanDeviation::logSpacedClusters(1000, 10);
        QCOMPARE(m.front(), size_t(1));
        QVERIFY(m.back() <= 499);
        QVERIFY(std::adjacent_find(m.begin(), m.end(), [](size_t a, size_t b) { return b <= a; }) == m.end());
        QVERIFY(AllanDeviation::logSpacedClusters(2, 10).empty());
    }

    void whiteNoiseGivesDensityAtOneSecond_data()
    {
        QTest::addColumn<double>("density"); // units/sqrt(Hz) = units*sqrt(s)
        QTest::addColumn<double>("rateHz");
        QTest::addColumn<int>("seconds");
        QTest::newRow("gyro 0.01 deg/s/rtHz at 100 Hz") << 0.01 << 100.0 << 1800;
        QTest::newRow("gyro 0.005 at 1 kHz") << 0.005 << 1000.0 << 600;
        QTest::newRow("acc 80 ug/rtHz at 400 Hz") << 80e-6 << 400.0 << 900;
    }
    void whiteNoiseGivesDensityAtOneSecond()
    {
        QFETCH(double, density);
        QFETCH(double, rateHz);
        QFETCH(int, seconds);
        // White rate noise of density N: per-sample sigma = N * sqrt(rate).
        std::mt19937_64 rng(42);
        std::normal_distribution<double> noise(0.0, density * std::sqrt(rateHz));
        std::vector<float> y(size_t(rateHz * seconds));
        for (auto &v : y)
            v = float(0.3 + noise(rng)); // a constant bias does not change the deviation
        const auto curve = AllanDeviation::compute(y.data(), y.size(), 1.0 / rateHz);
        const auto s = AllanDeviation::summarize(curve);
        QVERIFY(s.haveOneSecond);
        QVERIFY2(std::abs(s.atOneSecond / density - 1.0) < 0.05,
                 qPrintable(QStringLiteral("sigma(1 s) = %1, density %2").arg(s.atOneSecond).arg(density)));
        // The -1/2 slope of white noise.
        QVERIFY(std::abs(slope(curve, 0.1, 10.0) + 0.5) < 0.05);
    }

    void biasRandomWalkShowsPlusHalfSlope()
    {
        // Rate random walk K: sigma(tau) = K sqrt(tau / 3).
        const double rate = 100, K = 1e-3;
        std::mt19937_64 rng(7);
        std::normal_distribution<double> step(0.0, K * std::sqrt(1.0 / rate));
        std::vector<float> y(size_t(rate * 7200));
        double bias = 0;
        for (auto &v : y) {
            bias += step(rng);
            v = float(bias);
        }
        const auto curve = AllanDeviation::compute(y.data(), y.size(), 1.0 / rate);
        const double k = slope(curve, 10.0, 300.0);
        QVERIFY2(std::abs(k - 0.5) < 0.1, qPrintable(QStringLiteral("slope %1").arg(k)));
        double at30 = 0;
        QVERIFY(AllanDeviation::at(curve, 30.0, &at30));
        QVERIFY2(std::abs(at30 / (K * std::sqrt(30.0 / 3.0)) - 1.0) < 0.3, qPrintable(QString::number(at30)));
    }

    void whiteNoiseWithRandomWalkHasMinimum()
    {
        const double rate = 100;
        std::mt19937_64 rng(9);
        std::normal_distribution<double> white(0.0, 0.01 * std::sqrt(rate)), step(0.0, 1e-4 / std::sqrt(rate));
        std::vector<float> y(size_t(rate * 3600));
        double bias = 0;
        for (auto &v : y) {
            bias += step(rng);
            v = float(white(rng) + bias);
        }
        const auto curve = AllanDeviation::compute(y.data(), y.size(), 1.0 / rate);
        const auto s = AllanDeviation::summarize(curve);
        QVERIFY(s.haveMinimum);
        // N/sqrt(tau) meets K sqrt(tau/3) near tau = sqrt(3) N / K = 173 s.
        QVERIFY2(s.minimumTau > 40 && s.minimumTau < 600, qPrintable(QString::number(s.minimumTau)));
        QCOMPARE(s.biasInstability, s.minimum / 0.664);
    }

    // A column that never changes (a vendor CSV's unused field, or noise below its resolution):
    // no figure at all, and said so, never "nan".
    void constantSignalHasNoNoiseToMeasure()
    {
        const std::vector<float> y(20000, 1.0f);
        const auto s = AllanDeviation::summarize(AllanDeviation::compute(y.data(), y.size(), 0.01));
        QVERIFY(s.flat);
        QVERIFY(!s.haveOneSecond);
        QVERIFY(!s.haveMinimum);
        // A curve that is 0 at one end of the interval around 1 s (a column that changes too
        // seldom for the short clusters): a straight line there, not the logarithm of 0.
        std::vector<AllanDeviation::Point> curve(2);
        curve[0].tau = 0.5;
        curve[0].adev = 0;
        curve[1].tau = 2;
        curve[1].adev = 0.3;
        double v = -1;
        QVERIFY(AllanDeviation::at(curve, 1.0, &v));
        QCOMPARE(v, 0.1);
        const auto t = AllanDeviation::summarize(curve);
        QVERIFY(!t.flat);
        QVERIFY(t.haveOneSecond);
        QCOMPARE(t.atOneSecond, 0.1);
    }

    void recommendedLength()
    {
        QCOMPARE(AllanDeviation::recommendedLength(100.0, 0.1), 5100.0);
        QCOMPARE(AllanDeviation::recommendedLength(10.0, 0.5), 30.0);
    }

    void analyzerStatisticsRateAndGaps()
    {
        SampleAnalyzer a;
        std::mt19937 rng(3);
        std::uniform_int_distribution<int> jitter(0, 9);
        uint32_t t = 1000;
        int added = 0;
        for (int i = 0; i < 5000; ++i) {
            t += 5; // 200 Hz
            if (i >= 3000 && i < 3010)
                continue; // ten frames lost on the link
            model::Sample s;
            s.source = "HI91";
            s.fields = model::FieldAcc | model::FieldGyr | model::FieldDeviceTime | model::FieldTemperature;
            s.deviceTimeMs = t + (jitter(rng) == 0 ? 1 : 0); // occasional 1 ms late stamp
            s.acc = {double(i % 2), 0, 1};
            // A module at rest (a ramp of rates would be a module that moved: no Allan figures).
            s.gyr = {0.5, -0.5, 0.01 * double(i % 5)};
            s.temperatureC = 25;
            a.add(s);
            ++added;
            model::Sample other = s;
            other.source = "HI81"; // another type is left out
            other.acc = {100, 100, 100};
            a.add(other);
        }
        const auto r = a.finish(100.0, 10);
        QCOMPARE(r.source, std::string("HI91"));
        QCOMPARE(r.frames, uint64_t(added));
        QCOMPARE(r.framesLost, uint64_t(10));
        QVERIFY(std::abs(r.rateHz - 200.0) < 0.1);
        const auto &accX = r.channels.front();
        QCOMPARE(accX.name, std::string("acc_x"));
        QCOMPARE(accX.min, 0.0);
        QCOMPARE(accX.max, 1.0);
        QVERIFY(std::abs(accX.mean - 0.5) < 1e-3);
        QVERIFY(std::abs(accX.std - 0.5) < 1e-3);
        QCOMPARE(r.channels.size(), size_t(7)); // acc, gyr, temperature
        // Histogram: most intervals at 5 ms, some at 4 and 6, one gap of 55 ms in the last bin.
        uint64_t total = 0;
        for (const auto &b : r.intervals)
            total += b.count;
        QCOMPARE(total, uint64_t(added - 1));
        QCOMPARE(r.intervals.back().count, uint64_t(1));
        QCOMPARE(r.axes.size(), size_t(6));
        QCOMPARE(r.axes.front().name, std::string("gyr_x"));
        QCOMPARE(r.recommendedLengthS, 5100.0);
        QVERIFY(!r.motion.moved);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstAllanDeviation)
#include "tst_allan_deviation.moc"
