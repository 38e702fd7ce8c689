// bench_allan: overlapping Allan deviation of 3.6 million samples per axis (one hour at
// 1000 Hz) at 10 log-spaced tau per decade, one axis and six axes; target <= 2 s per axis.
//
//   bench_allan [--samples N]
//
// Exit status: 0 when the target is met and sigma(1 s) of the simulated white noise is within
// 5 % of its density; 1 otherwise; 2 on bad arguments.
#include "record/allan_deviation.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

using imudesk::record::AllanDeviation;

int main(int argc, char **argv)
{
    size_t n = 3'600'000;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--samples") && i + 1 < argc) {
            n = std::strtoull(argv[++i], nullptr, 10);
        } else {
            std::fprintf(stderr, "usage: bench_allan [--samples N]\n");
            return 2;
        }
    }
    if (n < 1000) {
        std::fprintf(stderr, "bench_allan: --samples needs at least 1000\n");
        return 2;
    }
    constexpr double kRate = 1000, kDensity = 0.005, kTarget = 2.0;
    std::mt19937_64 rng(1);
    std::normal_distribution<double> noise(0.0, kDensity * std::sqrt(kRate));
    std::vector<std::vector<float>> axes(6, std::vector<float>(n));
    for (auto &a : axes)
        for (auto &v : a)
            v = float(noise(rng));
    using Clock = std::chrono::steady_clock;
    auto t0 = Clock::now();
    const auto curve = AllanDeviation::compute(axes[0].data(), n, 1.0 / kRate);
    const double one = std::chrono::duration<double>(Clock::now() - t0).count();
    t0 = Clock::now();
    for (const auto &a : axes)
        AllanDeviation::compute(a.data(), n, 1.0 / kRate);
    const double six = std::chrono::duration<double>(Clock::now() - t0).count();
    const auto s = AllanDeviation::summarize(curve);
    const double err = std::abs(s.atOneSecond / kDensity - 1.0);
    std::printf("Allan deviation, %zu samples per axis, %zu tau values: one axis %.3f s, six axes %.3f s "
                "(%.3f s per axis); target <= %.1f s per axis: %s\n",
                n, curve.size(), one, six, six / 6, kTarget, one <= kTarget ? "met" : "MISSED");
    std::printf("sigma(1 s) = %.5g for a density of %.5g (%.2f %% off)\n", s.atOneSecond, kDensity, err * 100);
    return one <= kTarget && err < 0.05 ? 0 : 1;
}
