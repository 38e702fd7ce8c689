#include "twist_align.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>

namespace imudesk::clock {

int countTwists(const TwistSeries &s, double minPeakDps, int64_t fromNs, int64_t toNs)
{
    const size_t n = std::min(s.timeNs.size(), s.gyroDps.size());
    int count = 0;
    bool armed = true;
    for (size_t i = 0; i < n; ++i) {
        if (s.timeNs[i] < fromNs || s.timeNs[i] > toNs || !std::isfinite(s.gyroDps[i]))
            continue;
        const double v = s.gyroDps[i];
        if (armed && v > minPeakDps) {
            ++count;
            armed = false;
        } else if (!armed && v < minPeakDps / 2) {
            armed = true;
        }
    }
    return count;
}

// The helpers' names are in a namespace of their own: core is a unity build, and other files
// of its batch may have helpers of the same names in this namespace.
namespace twist_align_detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Coarse search budget: grid points x lags. Above it the grid is made coarser.
constexpr double kMaxCoarseWork = 2e8;
// A peak of the coarse curve is separate from the best when the curve dips by at least this
// much (in correlation) between them.
constexpr double kSeparatingDip = 0.1;
// Fewest samples a correlation is computed over.
constexpr int64_t kMinPairs = 16;
// The fine search's smoothing kernel: its radius in other's sample spacings, and at most.
constexpr double kSmoothSpacings = 8;
constexpr double kMaxSmoothRadiusNs = 20e6;
// How far apart residuals may be correlated for the uncertainty.
constexpr double kUncertaintyWindowNs = 50e6;

// Finite values at strictly increasing times; times relative to originNs.
struct Samples {
    std::vector<double> t; // ns since originNs
    std::vector<double> v;
    int64_t firstNs = 0, lastNs = 0; // absolute
};

Samples usable(const TwistSeries &s, int64_t originNs)
{
    Samples out;
    const size_t n = std::min(s.timeNs.size(), s.gyroDps.size());
    out.t.reserve(n);
    out.v.reserve(n);
    int64_t last = std::numeric_limits<int64_t>::min();
    for (size_t i = 0; i < n; ++i) {
        if (!std::isfinite(s.gyroDps[i]) || (!out.t.empty() && s.timeNs[i] <= last))
            continue;
        if (out.t.empty())
            out.firstNs = s.timeNs[i];
        last = s.timeNs[i];
        out.t.push_back(double(s.timeNs[i] - originNs));
        out.v.push_back(s.gyroDps[i]);
    }
    out.lastNs = last;
    return out;
}

// Linear interpolation at non-decreasing query times within [t.front(), t.back()].
class Cursor {
public:
    explicit Cursor(const Samples &s) : m_t(s.t), m_v(s.v) {}
    double at(double x, double *slopePerNs = nullptr)
    {
        while (m_j + 2 < m_t.size() && m_t[m_j + 1] <= x)
            ++m_j;
        const double slope = (m_v[m_j + 1] - m_v[m_j]) / (m_t[m_j + 1] - m_t[m_j]);
        if (slopePerNs)
            *slopePerNs = slope;
        return m_v[m_j] + slope * (x - m_t[m_j]);
    }

private:
    const std::vector<double> &m_t;
    const std::vector<double> &m_v;
    size_t m_j = 0;
};

int64_t floorDiv(int64_t a, int64_t b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }
int64_t ceilDiv(int64_t a, int64_t b) { return -floorDiv(-a, b); }

// A series resampled at grid indices [first, first + v.size()), centred on its mean.
struct Grid {
    int64_t first = 0;
    std::vector<double> v;
    std::vector<double> sum, sumSq; // prefix sums, size v.size() + 1
    int64_t last() const { return first + int64_t(v.size()) - 1; }
};

// fromNs, toNs relative to the origin.
Grid resample(const Samples &s, int64_t fromNs, int64_t toNs, int64_t stepNs)
{
    Grid g;
    g.first = ceilDiv(fromNs, stepNs);
    const int64_t last = floorDiv(toNs, stepNs);
    if (last < g.first)
        return g;
    g.v.resize(size_t(last - g.first + 1));
    Cursor c(s);
    double mean = 0;
    for (size_t i = 0; i < g.v.size(); ++i) {
        g.v[i] = c.at(double((g.first + int64_t(i)) * stepNs));
        mean += g.v[i];
    }
    mean /= double(g.v.size());
    g.sum.assign(g.v.size() + 1, 0);
    g.sumSq.assign(g.v.size() + 1, 0);
    for (size_t i = 0; i < g.v.size(); ++i) {
        g.v[i] -= mean;
        g.sum[i + 1] = g.sum[i] + g.v[i];
        g.sumSq[i + 1] = g.sumSq[i] + g.v[i] * g.v[i];
    }
    return g;
}

double pearson(double n, double sx, double sy, double sxx, double syy, double sxy)
{
    const double vx = sxx - sx * sx / n, vy = syy - sy * sy / n;
    if (!(vx > 0) || !(vy > 0))
        return 0;
    return std::clamp((sxy - sx * sy / n) / std::sqrt(vx * vy), -1.0, 1.0);
}

// Correlation of r at grid index k with o at k - m, over the indices both cover.
double gridCorrelation(const Grid &r, const Grid &o, int64_t m)
{
    const int64_t lo = std::max(r.first, o.first + m), hi = std::min(r.last(), o.last() + m);
    const int64_t n = hi - lo + 1;
    if (n < kMinPairs)
        return kNaN;
    const size_t ri = size_t(lo - r.first), oi = size_t(lo - m - o.first), nn = size_t(n);
    const double *a = r.v.data() + ri, *b = o.v.data() + oi;
    // Four sums: the additions do not wait on one another.
    double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    size_t i = 0;
    for (; i + 4 <= nn; i += 4) {
        s0 += a[i] * b[i];
        s1 += a[i + 1] * b[i + 1];
        s2 += a[i + 2] * b[i + 2];
        s3 += a[i + 3] * b[i + 3];
    }
    for (; i < nn; ++i)
        s0 += a[i] * b[i];
    const double sx = r.sum[ri + nn] - r.sum[ri], sxx = r.sumSq[ri + nn] - r.sumSq[ri];
    const double sy = o.sum[oi + nn] - o.sum[oi], syy = o.sumSq[oi + nn] - o.sumSq[oi];
    return pearson(double(n), sx, sy, sxx, syy, (s0 + s1) + (s2 + s3));
}

// The fine search: the reference's own samples [i0, i1) against `other` interpolated at
// their times minus the lag. The set is fixed for the whole search, so the correlation is a
// continuous function of the lag.
struct Fine {
    const Samples &ref;
    const Samples &other;
    size_t i0 = 0, i1 = 0;
    double refMean = 0, otherMean = 0; // centring, for the sums' precision

    double correlation(double lagNs) const
    {
        Cursor c(other);
        double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
        for (size_t i = i0; i < i1; ++i) {
            const double x = ref.v[i] - refMean, y = c.at(ref.t[i] - lagNs) - otherMean;
            sx += x;
            sy += y;
            sxx += x * x;
            syy += y * y;
            sxy += x * y;
        }
        return pearson(double(i1 - i0), sx, sy, sxx, syy, sxy);
    }

    // One standard deviation of the lag. reference = a + b * other(t - lag) + e is a least
    // squares fit in (a, b, lag); the lag's variance is that of its score, sum of b * d_i * e_i
    // (d: the part of other's slope that a and b do not explain), over (b^2 * sum d_i^2)^2.
    // The score's variance is taken from the products themselves, with their
    // autocorrelation up to maxLagSamples (Bartlett weights; Newey and West): the residuals
    // are neither independent (the smoothing) nor alike (the modules' responses differ most
    // where the rate changes).
    double sigmaNs(double lagNs, size_t maxLagSamples) const
    {
        const size_t n = i1 - i0;
        if (n < size_t(kMinPairs))
            return kNaN;
        std::vector<double> x(n), y(n), d(n);
        Cursor c(other);
        double mx = 0, my = 0, md = 0;
        for (size_t k = 0; k < n; ++k) {
            y[k] = ref.v[i0 + k];
            x[k] = c.at(ref.t[i0 + k] - lagNs, &d[k]);
            mx += x[k];
            my += y[k];
            md += d[k];
        }
        mx /= double(n);
        my /= double(n);
        md /= double(n);
        double sxx = 0, sxy = 0, sxd = 0;
        for (size_t k = 0; k < n; ++k) {
            sxx += (x[k] - mx) * (x[k] - mx);
            sxy += (x[k] - mx) * (y[k] - my);
            sxd += (x[k] - mx) * (d[k] - md);
        }
        if (!(sxx > 0))
            return kNaN;
        const double b = sxy / sxx, beta = sxd / sxx;
        double sdd = 0;
        std::vector<double> &g = y; // the score's terms, in place
        for (size_t k = 0; k < n; ++k) {
            const double e = (y[k] - my) - b * (x[k] - mx);
            const double dr = (d[k] - md) - beta * (x[k] - mx);
            g[k] = b * dr * e;
            sdd += dr * dr;
        }
        const double info = b * b * sdd;
        if (!(info > 0))
            return kNaN;
        const size_t lags = std::min(maxLagSamples, n / 4);
        double v = 0;
        for (size_t k = 0; k < n; ++k)
            v += g[k] * g[k];
        for (size_t lag = 1; lag <= lags; ++lag) {
            double s = 0;
            for (size_t k = lag; k < n; ++k)
                s += g[k] * g[k - lag];
            v += 2 * (1 - double(lag) / double(lags + 1)) * s;
        }
        return v > 0 ? std::sqrt(v) / info : kNaN;
    }
};

// The median spacing of a series' samples (ns).
double medianSpacing(const Samples &s)
{
    std::vector<double> d(s.t.size() - 1);
    for (size_t i = 1; i < s.t.size(); ++i)
        d[i - 1] = s.t[i] - s.t[i - 1];
    std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(d.size() / 2), d.end());
    return d[d.size() / 2];
}

// The series smoothed in time: at each sample, the value at that time of a straight line
// fitted with the weights (1 - (dt / radius)^2)^2. A line rather than a weighted mean: where
// samples are missing on one side, a mean would lean the value towards the other side's,
// which on a slope is a shift in time.
Samples smoothed(const Samples &s, double radiusNs)
{
    Samples out = s;
    size_t lo = 0;
    for (size_t i = 0; i < s.t.size(); ++i) {
        while (s.t[lo] <= s.t[i] - radiusNs)
            ++lo;
        double sw = 0, st = 0, stt = 0, sv = 0, stv = 0;
        for (size_t j = lo; j < s.t.size() && s.t[j] < s.t[i] + radiusNs; ++j) {
            const double u = (s.t[j] - s.t[i]) / radiusNs, w = (1 - u * u) * (1 - u * u);
            sw += w;
            st += w * u;
            stt += w * u * u;
            sv += w * s.v[j];
            stv += w * u * s.v[j];
        }
        const double det = sw * stt - st * st;
        // The line's value at u = 0; the mean when the points cannot carry a line.
        out.v[i] = det > 1e-9 * sw * sw ? (sv * stt - stv * st) / det : sv / sw;
    }
    return out;
}

std::string fixed(double v, int decimals)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

std::string deviceName(const TwistSeries &s, const char *fallback) { return s.name.empty() ? fallback : s.name; }

std::string timesPhrase(int n) { return n == 1 ? "once" : std::to_string(n) + " times"; }

std::string turnsFound(int n)
{
    if (n == 0)
        return "No sharp turn found";
    return "Only " + std::to_string(n) + (n == 1 ? " sharp turn found" : " sharp turns found");
}

TwistAlignResult align(const TwistSeries &reference, const TwistSeries &other, const TwistAlignOptions &o)
{
    TwistAlignResult res;
    const std::string refName = deviceName(reference, "the reference device");
    const std::string otherName = deviceName(other, "the other device");
    const int64_t maxLag = std::max<int64_t>(0, o.maxLagNs);
    const int minTwists = std::max(1, o.minTwists);
    const std::string turnAdvice = "turn the fixture sharply at least " + timesPhrase(minTwists) + ".";

    if (reference.timeNs.size() != reference.gyroDps.size() || other.timeNs.size() != other.gyroDps.size()) {
        res.whyNot = "The recorded data are inconsistent (times and values differ in number).";
        return res;
    }
    if (reference.timeNs.empty() || other.timeNs.empty()) {
        res.whyNot = "Nothing was recorded from " + (reference.timeNs.empty() ? refName : otherName) + ".";
        return res;
    }
    // Times relative to the reference's first sample: host times since an epoch are too large
    // for a double to hold to the ns.
    const int64_t origin = reference.timeNs.front();
    const Samples ref = usable(reference, origin), oth = usable(other, origin);
    if (ref.t.size() < 2 || oth.t.size() < 2) {
        res.whyNot = "Too few samples were recorded from " + (ref.t.size() < 2 ? refName : otherName) + ".";
        return res;
    }

    // Overlap on the unshifted time axes.
    const int64_t overlap = std::min(ref.lastNs, oth.lastNs) - std::max(ref.firstNs, oth.firstNs);
    const std::string needed = fixed(double(o.minOverlapNs) * 1e-9, 0);
    if (overlap <= 0) {
        res.whyNot = "The two recordings do not overlap in time; record at least " + needed +
                     " s with both devices while turning the fixture.";
        return res;
    }
    if (overlap < o.minOverlapNs) {
        res.whyNot = "The two recordings share only " + fixed(double(overlap) * 1e-9, 1) + " s; record at least " +
                     needed + " s with both devices while turning the fixture.";
        return res;
    }

    // Twists that can have a partner: within the other recording's span widened by maxLag.
    res.twistsReference = countTwists(reference, o.minPeakDps, std::max(ref.firstNs, oth.firstNs - maxLag),
                                      std::min(ref.lastNs, oth.lastNs + maxLag));
    res.twistsOther = countTwists(other, o.minPeakDps, std::max(oth.firstNs, ref.firstNs - maxLag),
                                  std::min(oth.lastNs, ref.lastNs + maxLag));
    const bool fewRef = res.twistsReference < minTwists, fewOther = res.twistsOther < minTwists;
    if (fewRef && fewOther) {
        res.whyNot = "Too few sharp turns found (" + refName + ": " + std::to_string(res.twistsReference) + ", " +
                     otherName + ": " + std::to_string(res.twistsOther) + "); with both modules on it, " + turnAdvice;
        return res;
    }
    if (fewRef || fewOther) {
        res.whyNot = turnsFound(fewRef ? res.twistsReference : res.twistsOther) + " on " +
                     (fewRef ? refName : otherName) + "; " + turnAdvice;
        return res;
    }

    // Coarse search: both series on one uniform grid (times relative to the origin).
    const int64_t refFrom = std::max(ref.firstNs, oth.firstNs - maxLag) - origin;
    const int64_t refTo = std::min(ref.lastNs, oth.lastNs + maxLag) - origin;
    const int64_t othFrom = std::max(oth.firstNs, ref.firstNs - maxLag) - origin;
    const int64_t othTo = std::min(oth.lastNs, ref.lastNs + maxLag) - origin;
    int64_t grid = std::max<int64_t>(1, o.gridNs);
    {
        const double points = double(refTo - refFrom) / double(grid) + 1;
        const double lags = 2.0 * double(maxLag / grid) + 1;
        if (points * lags > kMaxCoarseWork)
            grid = int64_t(double(grid) * std::ceil(std::sqrt(points * lags / kMaxCoarseWork)));
    }
    res.coarseGridNs = grid;
    const Grid gr = resample(ref, refFrom, refTo, grid), go = resample(oth, othFrom, othTo, grid);
    const int64_t M = maxLag / grid;
    std::vector<double> curve(size_t(2 * M + 1), kNaN);
    int64_t best = -1;
    if (!gr.v.empty() && !go.v.empty()) {
        for (int64_t m = -M; m <= M; ++m) {
            const double c = gridCorrelation(gr, go, m);
            curve[size_t(m + M)] = c;
            if (std::isfinite(c) && (best < 0 || c > curve[size_t(best)]))
                best = m + M;
        }
    }
    const size_t stride = (curve.size() + 1000) / 1001;
    for (size_t i = 0; i < curve.size(); i += stride)
        if (std::isfinite(curve[i]))
            res.curve.emplace_back(double((int64_t(i) - M) * grid) * 1e-6, curve[i]);
    if (best < 0) {
        res.whyNot = "The two recordings share too little time to compare; record at least " + needed +
                     " s with both devices while turning the fixture.";
        return res;
    }

    // The best peak separate from the best: walking away from the best on each side, a local
    // maximum counts once the curve has dipped below it by kSeparatingDip on the way.
    const double bestC = curve[size_t(best)];
    int64_t second = -1;
    for (int dir : {-1, 1}) {
        double dip = bestC;
        for (int64_t i = best + dir; i >= 0 && i < int64_t(curve.size()); i += dir) {
            const double c = curve[size_t(i)];
            if (!std::isfinite(c))
                continue;
            dip = std::min(dip, c);
            const double before = i - dir >= 0 && i - dir < int64_t(curve.size()) ? curve[size_t(i - dir)] : kNaN;
            const double after = i + dir >= 0 && i + dir < int64_t(curve.size()) ? curve[size_t(i + dir)] : kNaN;
            const bool localMax = !(before > c) && !(after >= c);
            if (localMax && c - dip >= kSeparatingDip && (second < 0 || c > curve[size_t(second)]))
                second = i;
        }
    }
    if (second >= 0) {
        res.secondPeakNs = double((second - M) * grid);
        res.secondPeakCorrelation = curve[size_t(second)];
    }

    // Fine search within ±2 grid steps of the coarse peak, on the reference's own samples
    // whose partners stay inside `other` over that whole range. Both series are smoothed
    // first, by one kernel a few of other's sample spacings wide: interpolated white noise is
    // weaker between samples than at them, which pulls an unsmoothed peak towards lags that
    // put the reference's times between other's samples (with equal rates, 4-9 µs at
    // 0.1 deg/s of noise, ~100 µs at 1 deg/s); correlated noise barely changes there.
    const double coarseLag = double((best - M) * grid), window = 2.0 * double(grid);
    const double radius = std::min(kSmoothSpacings * medianSpacing(oth), kMaxSmoothRadiusNs);
    const Samples refSmooth = smoothed(ref, radius), othSmooth = smoothed(oth, radius);
    Fine fine{refSmooth, othSmooth};
    {
        const double lo = oth.t.front() + coarseLag + window, hi = oth.t.back() + coarseLag - window;
        fine.i0 = size_t(std::lower_bound(ref.t.begin(), ref.t.end(), lo) - ref.t.begin());
        fine.i1 = size_t(std::upper_bound(ref.t.begin(), ref.t.end(), hi) - ref.t.begin());
        if (fine.i1 < fine.i0 + size_t(kMinPairs)) {
            res.whyNot = "The two recordings share too little time to compare; record at least " + needed +
                         " s with both devices while turning the fixture.";
            return res;
        }
        for (size_t i = fine.i0; i < fine.i1; ++i)
            fine.refMean += refSmooth.v[i];
        fine.refMean /= double(fine.i1 - fine.i0);
        for (double v : othSmooth.v)
            fine.otherMean += v;
        fine.otherMean /= double(othSmooth.v.size());
    }
    // A scan of 17 lags, then golden sections around the best of them.
    constexpr int kScan = 8;
    const double scanStep = window / kScan;
    double bestLag = coarseLag, bestFine = -2;
    for (int k = -kScan; k <= kScan; ++k) {
        const double lag = coarseLag + k * scanStep, c = fine.correlation(lag);
        if (c > bestFine) {
            bestFine = c;
            bestLag = lag;
        }
    }
    double a = std::max(bestLag - scanStep, coarseLag - window), b = std::min(bestLag + scanStep, coarseLag + window);
    const double invPhi = (std::sqrt(5.0) - 1) / 2;
    const double tol = std::max(1.0, o.fineToleranceNs);
    double x1 = b - invPhi * (b - a), x2 = a + invPhi * (b - a);
    double f1 = fine.correlation(x1), f2 = fine.correlation(x2);
    while (b - a > tol) {
        if (f1 >= f2) {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - invPhi * (b - a);
            f1 = fine.correlation(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + invPhi * (b - a);
            f2 = fine.correlation(x2);
        }
    }
    double lag = (a + b) / 2, c = fine.correlation(lag);
    if (bestFine > c) { // the scan's point was better (a function that is not unimodal there)
        lag = bestLag;
        c = bestFine;
    }
    res.offsetNs = lag;
    res.correlation = c;
    // The residuals' autocorrelation is summed over at most kUncertaintyWindowNs.
    const double sigma = fine.sigmaNs(lag, size_t(kUncertaintyWindowNs / medianSpacing(ref)) + 1);
    res.uncertaintyNs = std::max(std::isfinite(sigma) ? sigma : 0.0, tol / 2);

    if (c < o.minCorrelation) {
        res.whyNot = "The two devices did not see the same motion (correlation " + fixed(c, 2) + ", at least " +
                     fixed(o.minCorrelation, 2) +
                     " needed): fix both modules firmly on the same fixture and turn it sharply a few times.";
        return res;
    }
    if (M > 0 && (best == 0 || best == 2 * M)) {
        res.whyNot = "The best match is at the edge of the searched range (±" + fixed(double(maxLag) * 1e-6, 0) +
                     " ms): the two devices' clocks may differ by more than that.";
        return res;
    }
    if (second >= 0 && res.secondPeakCorrelation >= o.ambiguityRatio * bestC) {
        res.whyNot = "The match is ambiguous: shifts of " + fixed(double(coarseLag) * 1e-6, 1) + " ms and " +
                     fixed(res.secondPeakNs * 1e-6, 1) +
                     " ms fit almost equally well, the turns were too regular. Turn the fixture sharply a few "
                     "times at irregular intervals.";
        return res;
    }
    res.ok = true;
    return res;
}

} // namespace
} // namespace twist_align_detail

TwistAlignResult alignByTwist(const TwistSeries &reference, const TwistSeries &other, const TwistAlignOptions &o)
{
    return twist_align_detail::align(reference, other, o);
}

} // namespace imudesk::clock
