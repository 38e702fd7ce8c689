#pragma once
// Axis arithmetic shared by the charts: tick steps for a scrolling time axis, label
// decimals, and autoscale with hysteresis (so the vertical axis does not twitch on
// every refresh).
namespace imudesk::plot {

class AxisScaling {
public:
    struct Range {
        double min = 0.0;
        double max = 1.0;
        double span() const { return max - min; }
        friend bool operator==(const Range &, const Range &) = default;
    };

    // A round tick step (0.1 s ... 10 min) that cuts spanS into at most maxTicks intervals.
    static double timeTickInterval(double spanS, int maxTicks = 6);
    // A 1-2-5 step (times a power of ten) that cuts span into at most maxTicks intervals.
    static double niceStep(double span, int maxTicks = 5);
    // Decimals that tell labels `step` apart (0..6).
    static int decimalsFor(double step);
    // The vertical range for data in [lo, hi]: `current` while it still holds the data
    // and is at most twice as wide as needed, else the data widened by `margin` of its
    // span on each side, and at least minSpan wide.
    static Range autoRange(const Range &current, bool haveCurrent, double lo, double hi, double minSpan,
                           double margin = 0.1);
};

} // namespace imudesk::plot
