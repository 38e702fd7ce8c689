// "Twist to align" (core/clock/twist_align): two modules on one fixture that is turned sharply
// a few times; the offset between their time axes from their gyro magnitudes, against known
// shifts, sampling phases and rates, dropped samples, and the cases it must refuse.
#include "clock/twist_align.h"
#include "../common/test_main.h"

#include <QTest>

#include <cmath>
#include <random>
#include <vector>

using imudesk::clock::alignByTwist;
using imudesk::clock::TwistAlignOptions;
using imudesk::clock::TwistAlignResult;
using imudesk::clock::TwistSeries;

namespace {

constexpr double kPi = 3.14159265358979323846;

// One sharp turn of the fixture about a fixed axis: its rate's magnitude is a Gaussian
// (widthS = 4 sigma) or a raised cosine (widthS from zero to zero).
struct Twist {
    double atS;
    double peakDps;
    double widthS;
    bool gaussian;
    double axis[3]; // need not be unit: normalised when used
};

// The fixture's angular rate (deg/s) at t.
void rate(const std::vector<Twist> &twists, double t, double w[3])
{
    w[0] = w[1] = w[2] = 0;
    for (const Twist &k : twists) {
        double s = 0;
        if (k.gaussian) {
            const double sigma = k.widthS / 4, u = (t - k.atS) / sigma;
            if (std::abs(u) < 8)
                s = k.peakDps * std::exp(-0.5 * u * u);
        } else if (std::abs(t - k.atS) < k.widthS / 2) {
            s = k.peakDps * 0.5 * (1 + std::cos(2 * kPi * (t - k.atS) / k.widthS));
        }
        const double n = std::sqrt(k.axis[0] * k.axis[0] + k.axis[1] * k.axis[1] + k.axis[2] * k.axis[2]);
        for (int i = 0; i < 3; ++i)
            w[i] += s * k.axis[i] / n;
    }
}

// One module: samples at startS + phaseS + i / rateHz (true time) up to endS, each stamped
// shiftMs late; per-axis white noise and bias, a scale error; a fraction dropped at random.
struct Device {
    double rateHz = 1000;
    double phaseS = 0;
    double shiftMs = 0;
    double dropFraction = 0;
    double noiseDps = 0.1;
    double scale = 1;
    double bias[3] = {0.2, -0.15, 0.1};
    double startS = 0, endS = 30;
    uint64_t seed = 1;
};

TwistSeries record(const std::vector<Twist> &twists, const Device &d, const char *name)
{
    TwistSeries s;
    s.name = name;
    std::mt19937_64 rng(d.seed);
    std::normal_distribution<double> noise(0, d.noiseDps);
    std::uniform_real_distribution<double> uniform(0, 1);
    for (int64_t i = 0;; ++i) {
        const double t = d.startS + d.phaseS + double(i) / d.rateHz;
        if (t > d.endS)
            break;
        double w[3];
        rate(twists, t, w);
        double m2 = 0;
        for (int a = 0; a < 3; ++a) {
            const double v = d.scale * w[a] + d.bias[a] + noise(rng);
            m2 += v * v;
        }
        if (uniform(rng) < d.dropFraction)
            continue;
        s.timeNs.push_back(std::llround(t * 1e9 + d.shiftMs * 1e6));
        s.gyroDps.push_back(std::sqrt(m2));
    }
    return s;
}

// Five sharp turns, irregularly spaced, of different heights, widths, shapes and axes.
std::vector<Twist> fiveTwists()
{
    return {{4.1, 250, 0.20, true, {0, 0, 1}},
            {9.7, 380, 0.12, false, {1, 0.2, 0}},
            {13.2, 160, 0.28, true, {0.3, 1, 0.1}},
            {19.8, 300, 0.15, false, {0, 0.5, 1}},
            {24.5, 220, 0.25, true, {1, 1, 1}}};
}

// The centroid (s) of |gyro| above 30 deg/s within ±0.5 s of atS, the times shifted by addNs.
double centroidS(const TwistSeries &s, double atS, double addNs)
{
    double sw = 0, swt = 0;
    for (size_t i = 0; i < s.timeNs.size(); ++i) {
        const double t = (double(s.timeNs[i]) + addNs) * 1e-9;
        if (std::abs(t - atS) < 0.5 && s.gyroDps[i] > 30) {
            sw += s.gyroDps[i] - 30;
            swt += (s.gyroDps[i] - 30) * t;
        }
    }
    return swt / sw;
}

} // namespace

class TstTwistAlign : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void recoversTheOffset_data()
    {
        QTest::addColumn<double>("shiftMs");  // B's stamps are this late
        QTest::addColumn<double>("rateA");
        QTest::addColumn<double>("rateB");
        QTest::addColumn<double>("dropB");    // fraction of B's samples lost
        QTest::addColumn<double>("startB");   // B's recording starts (and ends) this much later, s
        QTest::addColumn<double>("noiseDps"); // per axis, both devices
        QTest::addColumn<double>("seconds");  // A's recording
        const double shifts[] = {3.21, -47.3, 180.0};
        for (double shift : shifts) {
            const QByteArray s = QByteArray::number(shift, 'f', 2) + " ms";
            QTest::newRow("1 kHz, " + s) << shift << 1000.0 << 1000.0 << 0.0 << 0.0 << 0.1 << 30.0;
            QTest::newRow("1 kHz, 5 % of B dropped, " + s) << shift << 1000.0 << 1000.0 << 0.05 << 0.0 << 0.1 << 30.0;
            QTest::newRow("B at 400 Hz, " + s) << shift << 1000.0 << 400.0 << 0.0 << 0.0 << 0.1 << 30.0;
        }
        QTest::newRow("A at 400 Hz, -47.30 ms") << -47.3 << 400.0 << 1000.0 << 0.0 << 0.0 << 0.1 << 30.0;
        QTest::newRow("B 3 s later, 5 % dropped, -123.40 ms") << -123.4 << 1000.0 << 1000.0 << 0.05 << 3.0 << 0.1 << 30.0;
        // Ten times the noise: the error grows with it (about 10 µs RMS over seeds).
        QTest::newRow("1 deg/s of noise, -47.30 ms") << -47.3 << 1000.0 << 1000.0 << 0.0 << 0.0 << 1.0 << 30.0;
        // Long enough for the coarse search to take a coarser grid than 0.5 ms.
        QTest::newRow("300 s, -47.30 ms") << -47.3 << 1000.0 << 1000.0 << 0.0 << 0.0 << 0.1 << 300.0;
    }
    void recoversTheOffset()
    {
        QFETCH(double, shiftMs);
        QFETCH(double, rateA);
        QFETCH(double, rateB);
        QFETCH(double, dropB);
        QFETCH(double, startB);
        QFETCH(double, noiseDps);
        QFETCH(double, seconds);
        const auto twists = fiveTwists();
        Device a;
        a.rateHz = rateA;
        a.noiseDps = noiseDps;
        a.endS = seconds;
        a.seed = 11;
        Device b;
        b.rateHz = rateB;
        b.phaseS = 0.37e-3;
        b.shiftMs = shiftMs;
        b.dropFraction = dropB;
        b.noiseDps = noiseDps;
        b.scale = 1.015;
        b.bias[0] = -0.3;
        b.startS += startB;
        b.endS = seconds + startB;
        b.seed = 22;
        const TwistAlignResult r = alignByTwist(record(twists, a, "device A"), record(twists, b, "device B"));
        QVERIFY2(r.ok, r.whyNot.c_str());
        QCOMPARE(r.twistsReference, 5);
        QCOMPARE(r.twistsOther, 5);
        const double errorUs = (r.offsetNs + shiftMs * 1e6) / 1e3;
        qInfo("offset %.4f ms (expected %.4f), error %+.2f us, uncertainty %.2f us, correlation %.5f, grid %lld ns",
              r.offsetNs / 1e6, -shiftMs, errorUs, r.uncertaintyNs / 1e3, r.correlation, (long long)r.coarseGridNs);
        QVERIFY2(std::abs(errorUs) <= 50, qPrintable(QStringLiteral("error %1 us").arg(errorUs)));
        QVERIFY(r.correlation > 0.99);
        QVERIFY(r.uncertaintyNs > 0 && r.uncertaintyNs < 50e3);
        // The uncertainty is not optimistic: the error within 3 of it.
        QVERIFY2(std::abs(errorUs) * 1e3 <= 3 * r.uncertaintyNs, qPrintable(QString::number(r.uncertaintyNs)));
        if (seconds > 100)
            QVERIFY(r.coarseGridNs > TwistAlignOptions{}.gridNs);
    }

    // The offset, added to B's times, makes a twist's centroid fall at A's; the curve's peak
    // is at the offset.
    void offsetPutsOtherOnReference()
    {
        const auto twists = fiveTwists();
        Device a;
        Device b;
        b.phaseS = 0.37e-3;
        b.shiftMs = -47.3;
        b.seed = 5;
        const TwistSeries sa = record(twists, a, "device A"), sb = record(twists, b, "device B");
        const TwistAlignResult r = alignByTwist(sa, sb);
        QVERIFY2(r.ok, r.whyNot.c_str());
        const double ca = centroidS(sa, 9.7, 0);
        const double cb = centroidS(sb, 9.7 - 47.3e-3, 0);
        const double cbOnA = centroidS(sb, 9.7, r.offsetNs);
        QVERIFY2(std::abs(ca - cb - 47.3e-3) < 0.1e-3, qPrintable(QString::number(ca - cb))); // as recorded
        QVERIFY2(std::abs(cbOnA - ca) < 0.05e-3, qPrintable(QString::number(cbOnA - ca)));
        QVERIFY(!r.curve.empty() && r.curve.size() <= 1001);
        auto peak = r.curve.front();
        for (const auto &p : r.curve)
            if (p.second > peak.second)
                peak = p;
        QVERIFY2(std::abs(peak.first - r.offsetNs / 1e6) <= 0.5, qPrintable(QString::number(peak.first)));
        QVERIFY(r.curve.front().first < -249 && r.curve.back().first > 249);
    }

    void refuses_data()
    {
        QTest::addColumn<int>("scenario");
        QTest::addColumn<QString>("says");
        QTest::newRow("no twists") << 0 << QStringLiteral("turn the fixture sharply at least 3 times");
        QTest::newRow("one twist") << 1 << QStringLiteral("turn the fixture sharply at least 3 times");
        QTest::newRow("two twists on B") << 2 << QStringLiteral("Only 2 sharp turns found on device B");
        QTest::newRow("unrelated motions") << 3 << QStringLiteral("did not see the same motion");
        QTest::newRow("periodic twists") << 4 << QStringLiteral("ambiguous");
        QTest::newRow("short overlap") << 5 << QStringLiteral("share only 3.0 s");
        QTest::newRow("offset beyond the range") << 6 << QString();
    }
    void refuses()
    {
        QFETCH(int, scenario);
        QFETCH(QString, says);
        std::vector<Twist> ta = fiveTwists(), tb = ta;
        Device a;
        Device b;
        b.phaseS = 0.37e-3;
        b.shiftMs = 12.5;
        b.seed = 3;
        switch (scenario) {
        case 0:
            ta.clear();
            tb.clear();
            break;
        case 1:
            ta.resize(1);
            tb = ta;
            break;
        case 2:
            tb.resize(2);
            break;
        case 3: // each 1 s or more from every twist of the other
            tb = {{3.0, 250, 0.20, true, {0, 0, 1}},
                  {7.4, 380, 0.12, false, {1, 0, 0}},
                  {15.9, 160, 0.28, true, {0, 1, 0}},
                  {21.3, 300, 0.15, false, {0, 0, 1}},
                  {27.0, 220, 0.25, true, {1, 1, 1}}};
            break;
        case 4: // 30 identical turns, 150 ms apart
            ta.clear();
            for (int i = 0; i < 30; ++i)
                ta.push_back({10 + 0.15 * i, 200, 0.08, true, {0, 0, 1}});
            tb = ta;
            break;
        case 5:
            b.startS = 27;
            b.endS = 40;
            break;
        case 6:
            b.shiftMs = 400;
            break;
        }
        const TwistAlignResult r = alignByTwist(record(ta, a, "device A"), record(tb, b, "device B"));
        qInfo("twists %d/%d, correlation %.3f, second peak %.3f at %.1f ms: %s", r.twistsReference, r.twistsOther,
              r.correlation, r.secondPeakCorrelation, r.secondPeakNs / 1e6, r.whyNot.c_str());
        QVERIFY(!r.ok);
        QVERIFY2(QString::fromStdString(r.whyNot).contains(says), r.whyNot.c_str());
        if (scenario == 1) {
            QCOMPARE(r.twistsReference, 1);
            QCOMPARE(r.twistsOther, 1);
        }
        if (scenario == 3)
            QVERIFY(r.correlation < 0.8);
        if (scenario == 4)
            QVERIFY(r.secondPeakCorrelation >= 0.95 * r.correlation - 0.01);
    }

    // Twists counted once each, however the signal crosses the threshold on the way.
    void countsTwists()
    {
        TwistSeries s;
        const double v[] = {0, 70, 55, 65, 40, 80, 20, 61, 29, 0};
        for (int i = 0; i < 10; ++i) {
            s.timeNs.push_back(i * 1'000'000);
            s.gyroDps.push_back(v[i]);
        }
        QCOMPARE(imudesk::clock::countTwists(s, 60, 0, 10'000'000), 2);
        QCOMPARE(imudesk::clock::countTwists(s, 60, 7'000'000, 10'000'000), 1);
    }
};

IMUDESK_TEST_APPLESS_MAIN(TstTwistAlign)
#include "tst_twist_align.moc"
