#include "clock_model.h"

#include <cmath>
#include <vector>

namespace imudesk::clock {

ClockModel::ClockModel() : ClockModel(Options{}) {}

ClockModel::ClockModel(Options options) : m_o(options)
{
    if (m_o.binNs <= 0)
        m_o.binNs = 1;
}

void ClockModel::reset()
{
    m_started = false;
    m_binHasPoint = false;
    m_minima.clear();
    m_lineY0 = m_lineSlope = 0;
    m_fit = ClockFit{};
    m_delaySum = 0;
    m_delayCount = 0;
}

void ClockModel::add(int64_t deviceNs, int64_t hostNs)
{
    if (!m_started) {
        m_started = true;
        m_originNs = deviceNs;
        m_binStartNs = deviceNs;
    }
    if (deviceNs >= m_binStartNs + m_o.binNs) {
        closeBin();
        const int64_t rel = deviceNs - m_originNs;
        m_binStartNs = m_originNs + (rel - rel % m_o.binNs);
    }
    const Point p{double(deviceNs - m_originNs), double(hostNs - deviceNs)};
    if (!m_binHasPoint || p.y < m_binMin.y) {
        m_binMin = p;
        m_binHasPoint = true;
        if (m_minima.empty()) { // no line yet: the least delay seen so far, no skew
            m_lineY0 = p.y;
            m_lineSlope = 0;
        }
    }
    // The delay above the line: how long the transport held this sample beyond the least.
    const double delay = p.y - lineAt(p.x);
    if (m_fit.valid && delay >= 0) {
        m_delaySum += delay;
        ++m_delayCount;
        m_fit.meanDelayNs = m_delaySum / double(m_delayCount);
    }
}

void ClockModel::closeBin()
{
    if (!m_binHasPoint)
        return;
    m_minima.push_back(m_binMin);
    m_binHasPoint = false;
    while (m_minima.size() > 1 && m_minima.back().x - m_minima.front().x > double(m_o.windowNs))
        m_minima.pop_front();
    refit();
}

void ClockModel::refit()
{
    // Lower convex hull of the minima (x increasing): a monotone chain keeping left turns.
    std::vector<Point> hull;
    hull.reserve(m_minima.size());
    for (const Point &p : m_minima) {
        while (hull.size() >= 2) {
            const Point &a = hull[hull.size() - 2], &b = hull.back();
            const double cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
            if (cross > 0)
                break;
            hull.pop_back();
        }
        hull.push_back(p);
    }
    // The line: the hull's longest edge, below every minimum. Olson's edge under the mean is
    // the least total distance for delays that are independent; a serial adapter's are not:
    // the phase of the samples against its latency timer slides with the drift, so the floor
    // is reached once a cycle (every 25 s at 40 ppm and 1 kHz) and the newest hull vertex is
    // often above it. Its edges are short; the edge between two visits of the floor is long.
    if (hull.size() == 1) {
        m_lineSlope = 0;
        m_lineY0 = hull.front().y;
    } else {
        size_t best = 0;
        for (size_t i = 1; i + 1 < hull.size(); ++i)
            if (hull[i + 1].x - hull[i].x > hull[best + 1].x - hull[best].x)
                best = i;
        const Point &a = hull[best], &b = hull[best + 1];
        m_lineSlope = (b.y - a.y) / (b.x - a.x);
        m_lineY0 = a.y - m_lineSlope * a.x;
    }
    double sq = 0;
    for (const Point &p : m_minima) {
        const double r = p.y - lineAt(p.x);
        sq += r * r;
    }
    m_fit.bins = int(m_minima.size());
    m_fit.spanS = (m_minima.back().x - m_minima.front().x) / 1e9;
    m_fit.skew = m_lineSlope;
    m_fit.offsetNs = m_lineY0 - m_lineSlope * double(m_originNs);
    m_fit.jitterNs = std::sqrt(sq / double(m_minima.size()));
    m_fit.valid = m_fit.bins >= m_o.minBins && m_fit.spanS >= m_o.minSpanS;
}

std::optional<int64_t> ClockModel::toHost(int64_t deviceNs) const
{
    if (!m_started)
        return std::nullopt;
    return deviceNs + int64_t(std::llround(lineAt(double(deviceNs - m_originNs)))) - m_o.knownDelayNs;
}

ClockModel::State ClockModel::state() const
{
    if (!m_started)
        return State::FreeRunning;
    return m_fit.valid ? State::Aligned : State::Uncertain;
}

} // namespace imudesk::clock
