#include "axis_scaling.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace imudesk::plot {

double AxisScaling::timeTickInterval(double spanS, int maxTicks)
{
    static constexpr std::array<double, 15> kSteps = {0.1, 0.2, 0.25, 0.5, 1, 2, 5, 10, 15, 30, 60, 120, 300, 600, 1200};
    maxTicks = std::max(maxTicks, 1);
    for (double step : kSteps)
        if (spanS / step <= maxTicks)
            return step;
    return kSteps.back();
}

double AxisScaling::niceStep(double span, int maxTicks)
{
    maxTicks = std::max(maxTicks, 1);
    if (!(span > 0.0) || !std::isfinite(span))
        return 1.0;
    const double raw = span / maxTicks;
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (span / (m * decade) <= maxTicks + 1e-9)
            return m * decade;
    return 10.0 * decade;
}

int AxisScaling::decimalsFor(double step)
{
    if (!(step > 0.0) || !std::isfinite(step))
        return 0;
    return std::clamp(int(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
}

AxisScaling::Range AxisScaling::autoRange(const Range &current, bool haveCurrent, double lo, double hi,
                                          double minSpan, double margin)
{
    if (!std::isfinite(lo) || !std::isfinite(hi) || hi < lo)
        return haveCurrent ? current : Range{};
    const double span = std::max(hi - lo, minSpan);
    const double mid = 0.5 * (lo + hi);
    const double needLo = std::min(lo, mid - 0.5 * span);
    const double needHi = std::max(hi, mid + 0.5 * span);
    if (haveCurrent && current.min <= needLo && current.max >= needHi && current.span() <= 2.0 * (1 + 2 * margin) * span)
        return current;
    return {needLo - margin * span, needHi + margin * span};
}

} // namespace imudesk::plot
