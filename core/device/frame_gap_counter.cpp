#include "frame_gap_counter.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace imudesk::device {

namespace {

// Frames in the last kRateWindow that reveal a rate change.
constexpr int kOffGridFrames = 4;   // off the grid: a period that is not a multiple
constexpr int kRampFrames = 6;      // whole multiples with a ramping deficit: slower output
constexpr int64_t kFasterDrop = 3;  // deficit below its recent maximum: faster output
constexpr double kPhaseGain = 1.0 / 16;

constexpr double kJitter = FrameGapCounter::kJitterMs;

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Mean of the middle half: ignores gaps and the odd short interval.
double trimmedMean(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const size_t from = v.size() / 4, to = v.size() - v.size() / 4;
    double sum = 0;
    for (size_t i = from; i < to; ++i)
        sum += v[i];
    return to > from ? sum / double(to - from) : 0;
}

// Farthest a frame may sit from its slot (the grid follows the stamps' mean phase)
// before it counts as off the grid.
double gridTolerance(double period)
{
    return std::max(1.5 * kJitter, 0.2 * period);
}

// Places the stamps on a grid of `period` (slots counted from the first stamp) and fits
// a line through (slot, stamp): returns the squared residuals, and the slope.
double gridFitCost(const std::vector<double> &times, double period, double *slope)
{
    const size_t n = times.size();
    std::vector<double> slots(n);
    double meanSlot = 0, meanTime = 0;
    for (size_t i = 0; i < n; ++i) {
        slots[i] = double(std::llround((times[i] - times.front()) / period));
        meanSlot += slots[i];
        meanTime += times[i];
    }
    meanSlot /= double(n);
    meanTime /= double(n);
    double sxx = 0, sxy = 0;
    for (size_t i = 0; i < n; ++i) {
        sxx += (slots[i] - meanSlot) * (slots[i] - meanSlot);
        sxy += (slots[i] - meanSlot) * (times[i] - meanTime);
    }
    *slope = sxx > 0 ? sxy / sxx : 0;
    double cost = 0;
    for (size_t i = 0; i < n; ++i) {
        const double r = times[i] - meanTime - *slope * (slots[i] - meanSlot);
        cost += r * r;
    }
    return cost;
}

// Periods this short carry stamp jitter comparable to the period.
bool jitteryPeriod(double period)
{
    return period < 4 * kJitter;
}

} // namespace

uint64_t FrameGapCounter::add(const std::string &type, double t, int timeBase)
{
    auto [it, fresh] = m_tracks.try_emplace(type);
    Track &k = it->second;
    if (fresh)
        m_lostByType.try_emplace(type, 0);
    if (k.havePrev && timeBase != k.timeBase) {
        // The device's clock changed (aligned to UTC): count what held, then learn again.
        const uint64_t n = commitPending(k);
        k.timeBase = timeBase;
        k.prev = t;
        begin(k, t);
        return account(type, k, n);
    }
    if (!k.havePrev) {
        k.havePrev = true;
        k.timeBase = timeBase;
        k.prev = t;
        begin(k, t);
        return 0;
    }
    const double backTolerance = std::max(2 * kJitter, k.locked ? 0.5 * k.period : 0.0);
    if (t < k.prev - backTolerance) {
        // The device restarted (or its counter wrapped): not a loss. Its configuration may
        // have reverted to the saved one, so an expected period no longer holds.
        ++m_resets;
        const uint64_t n = commitPending(k);
        k.expected = 0;
        k.prev = t;
        begin(k, t);
        return account(type, k, n);
    }
    k.prev = std::max(k.prev, t);
    if (k.locked)
        return account(type, k, step(k, t));
    if (k.learnTimes.empty()) {
        begin(k, t);
        return 0;
    }
    k.learnTimes.push_back(t);
    if (int(k.learnTimes.size()) > kLearnDeltas)
        return account(type, k, tryLock(k));
    return 0;
}

uint64_t FrameGapCounter::account(const std::string &type, Track &k, uint64_t n)
{
    if (n) {
        k.lost += n;
        m_lost += n;
        m_lostByType[type] += n;
    }
    return n;
}

void FrameGapCounter::begin(Track &k, double t)
{
    k.locked = false;
    k.history.clear();
    k.learnTimes.clear();
    if (k.expected > 0) {
        lock(k, k.expected, t, jitteryPeriod(k.expected));
        k.snapped = true;
        return;
    }
    k.learnTimes.push_back(t);
}

uint64_t FrameGapCounter::tryLock(Track &k)
{
    const std::vector<double> times = k.learnTimes;
    const size_t n = times.size() - 1;
    std::vector<double> deltas(n);
    for (size_t i = 0; i < n; ++i)
        deltas[i] = times[i + 1] - times[i];
    const double rough = trimmedMean(deltas);
    auto slide = [&k] {
        k.learnTimes.erase(k.learnTimes.begin());
        return uint64_t(0);
    };
    if (!(rough > 0))
        return slide();
    const double tolerance = std::max(2 * kJitter, 0.25 * rough); // two stamps' jitter
    size_t fit = 0, gaps = 0;
    int64_t missing = 0;
    double spread = 0;
    for (double d : deltas) {
        const int64_t m = std::max<int64_t>(1, std::llround(d / rough));
        const double off = std::abs(d - double(m) * rough);
        if (off > tolerance)
            continue;
        ++fit;
        spread = std::max(spread, off);
        if (m >= 2 && d > rough + tolerance) {
            ++gaps;
            missing += m - 1;
        }
    }
    // Irregular output (ONMARK, bursts, a rate change inside the window): slide on.
    if (fit * 4 < n * 3 || gaps * 4 > n)
        return slide();
    // How many slots the window spans: jitter can pass for a gap (or hide one), so each
    // count from "no gaps" to "every gap seen" is tried, and the one whose grid fits the
    // stamps best wins (the fewer slots on a tie). Its least-squares slope is the period.
    const double span = times.back() - times.front();
    double period = 0, bestCost = 0;
    for (int64_t slots = int64_t(n); slots <= int64_t(n) + missing; ++slots) {
        double slope = 0;
        const double cost = gridFitCost(times, span / double(slots), &slope);
        if (slope > 0 && (period == 0 || cost < 0.9 * bestCost)) {
            period = slope;
            bestCost = cost;
        }
    }
    if (!(period > 0))
        return slide();
    bool snapped = false;
    const double snapTolerance = std::max(0.1, 2 * kJitter / double(n));
    const double whole = std::round(period);
    if (whole >= 1 && std::abs(period - whole) <= snapTolerance) {
        period = whole;
        snapped = true;
    }
    // Anchor the grid at the window's median phase, not at one frame's jittered stamp
    // (twice: slots counted from an outlier would be off by one).
    auto medianPhase = [&](double reference) {
        std::vector<double> phases;
        phases.reserve(times.size());
        for (double t : times)
            phases.push_back(t - double(std::llround((t - reference) / period)) * period);
        return median(phases);
    };
    const double phase = medianPhase(medianPhase(times.front()));
    const double origin = phase + double(std::llround((times.front() - phase) / period)) * period;
    lock(k, period, origin, jitteryPeriod(period) || spread > 0.2 * period);
    k.snapped = snapped;
    // Count the window itself (losses while learning are losses too).
    uint64_t lost = 0;
    for (size_t i = 1; i < times.size(); ++i) {
        if (k.locked)
            lost += step(k, times[i]);
        else
            k.learnTimes.push_back(times[i]);
    }
    return lost;
}

void FrameGapCounter::lock(Track &k, double period, double origin, bool jittery)
{
    k.locked = true;
    k.snapped = false;
    k.period = period;
    k.origin = origin;
    k.slots = 0;
    k.frames = 0;
    k.minRef = 0;
    k.medRef = 0;
    k.confirm = jittery ? kConfirmFramesJittery : kConfirmFrames;
    k.calibrating = jittery && k.expected <= 0;
    k.learnTimes.clear();
    k.history.clear();
    k.history.push_back(Step{0, 1, false}); // the origin frame
}

uint64_t FrameGapCounter::step(Track &k, double t)
{
    const double predicted = k.origin + double(k.slots) * k.period;
    const int64_t m = std::llround((t - predicted) / k.period);
    k.slots += m;
    ++k.frames;
    const double residual = t - (predicted + double(m) * k.period);
    const int64_t deficit = k.slots - k.frames;
    k.history.push_back(Step{deficit, m, std::abs(residual) > gridTolerance(k.period)});
    k.origin += residual * kPhaseGain; // follow the stamps' mean phase
    while (int(k.history.size()) > kConfirmFramesJittery)
        k.history.pop_front();
    // A learned period that is not whole ms is refined over the whole grid, gently: one
    // frame's stamp must not drag the grid along.
    if (!k.snapped && k.slots >= kLearnDeltas)
        k.period += ((t - k.origin) / double(k.slots) - k.period) * kPhaseGain;

    // A rate change is learned again, and what it looked like is not a loss.
    const int size = int(k.history.size());
    int64_t highest = deficit;
    for (int i = std::max(0, size - kConfirmFramesJittery); i < size; ++i)
        highest = std::max(highest, k.history[size_t(i)].deficit);
    bool faster = highest - deficit >= kFasterDrop;
    bool changed = faster;
    if (!changed && size > kRateWindow) {
        int offGrid = 0, multiples = 0;
        for (int i = size - kRateWindow; i < size; ++i) {
            offGrid += k.history[size_t(i)].offGrid ? 1 : 0;
            multiples += k.history[size_t(i)].slots >= 2 ? 1 : 0;
        }
        const int64_t rise = deficit - k.history[size_t(size - 1 - kRateWindow)].deficit;
        changed = offGrid >= kOffGridFrames || (k.expected <= 0 && multiples >= kRampFrames && rise >= kRampFrames);
    }
    if (changed) {
        k.expected = 0; // output does not follow the expected period
        ++k.rateChanges;
        begin(k, t);
        return 0;
    }

    // Commit a deficit once both its minimum and its median over the confirmation
    // window have risen: jitter moves one of them, a loss moves both.
    if (size < k.confirm)
        return 0;
    std::array<int64_t, kConfirmFramesJittery> window; // no allocation per frame
    for (int i = 0; i < k.confirm; ++i)
        window[size_t(i)] = k.history[size_t(size - k.confirm + i)].deficit;
    std::sort(window.begin(), window.begin() + k.confirm);
    const int64_t low = window.front();
    const int64_t mid = window[size_t(k.confirm - 1) / 2];
    if (k.calibrating) {
        // Stamps that flicker (the deficit steps back now and then) set the references
        // from this first window; steady ones keep the grid's own (0): a loss inside the
        // window still counts.
        k.calibrating = false;
        bool flicker = false;
        for (int i = size - k.confirm + 1; i < size; ++i)
            flicker = flicker || k.history[size_t(i)].deficit < k.history[size_t(i - 1)].deficit;
        if (flicker) {
            // The origin frame itself flickered (deficit 0 is one of the values): a
            // loss inside this window shows as values above the flicker.
            k.minRef = std::min<int64_t>(low, 0);
            std::vector<int64_t> before; // the frames before any loss in the window
            for (int i = size - k.confirm; i < size && k.history[size_t(i)].deficit <= k.minRef + 1; ++i)
                before.push_back(k.history[size_t(i)].deficit);
            std::sort(before.begin(), before.end());
            k.medRef = before.empty() ? k.minRef : before[(before.size() - 1) / 2];
            const int64_t rise = std::min(low - k.minRef, mid - k.medRef);
            if (rise <= 0)
                return 0;
            k.minRef += rise;
            k.medRef += rise;
            return uint64_t(rise);
        }
    }
    const int64_t rise = std::min(low - k.minRef, mid - k.medRef);
    if (rise > 0) {
        k.minRef += rise;
        k.medRef += rise;
        return uint64_t(rise);
    }
    // More frames than slots (a duplicate, a slightly fast clock): the grid moved.
    const int64_t fall = std::max(low - k.minRef, mid - k.medRef);
    if (fall < 0) {
        k.minRef += fall;
        k.medRef += fall;
    }
    return 0;
}

uint64_t FrameGapCounter::commitPending(Track &k)
{
    // Before the timing is forgotten: a deficit that held for the last few frames of a
    // steady stream is a loss; with jittery stamps only a full window tells.
    if (!k.locked || k.confirm != kConfirmFrames)
        return 0;
    const int size = int(k.history.size());
    constexpr int kMinFrames = 3;
    if (size < kMinFrames)
        return 0;
    int64_t low = k.history.back().deficit;
    for (int i = size - kMinFrames; i < size; ++i)
        low = std::min(low, k.history[size_t(i)].deficit);
    if (low <= k.minRef)
        return 0;
    const int64_t rise = low - k.minRef;
    k.minRef += rise;
    k.medRef += rise;
    return uint64_t(rise);
}

void FrameGapCounter::resetTiming()
{
    for (auto &[type, k] : m_tracks)
        resetTiming(type);
}

void FrameGapCounter::resetTiming(const std::string &type)
{
    const auto it = m_tracks.find(type);
    if (it == m_tracks.end())
        return;
    Track &k = it->second;
    account(type, k, commitPending(k));
    k.locked = false;
    k.learnTimes.clear(); // the next frame starts a new grid
    k.history.clear();
}

void FrameGapCounter::setExpectedPeriod(const std::string &type, double periodMs)
{
    auto [it, fresh] = m_tracks.try_emplace(type);
    if (fresh)
        m_lostByType.try_emplace(type, 0);
    Track &k = it->second;
    k.expected = periodMs > 0 ? periodMs : 0;
    account(type, k, commitPending(k));
    k.locked = false;
    k.learnTimes.clear();
    k.history.clear();
}

void FrameGapCounter::clear()
{
    m_tracks.clear();
    m_lostByType.clear();
    m_lost = 0;
    m_resets = 0;
}

uint64_t FrameGapCounter::lost(const std::string &type) const
{
    const auto it = m_lostByType.find(type);
    return it == m_lostByType.end() ? 0 : it->second;
}

uint64_t FrameGapCounter::rateChanges(const std::string &type) const
{
    const auto it = m_tracks.find(type);
    return it == m_tracks.end() ? 0 : it->second.rateChanges;
}

std::optional<double> FrameGapCounter::period(const std::string &type) const
{
    const auto it = m_tracks.find(type);
    if (it == m_tracks.end())
        return std::nullopt;
    if (it->second.locked)
        return it->second.period;
    if (it->second.expected > 0)
        return it->second.expected;
    return std::nullopt;
}

} // namespace imudesk::device
