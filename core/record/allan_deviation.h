#pragma once
// Overlapping Allan deviation (IEEE Std 952 / 1554) of a rate signal sampled every tau0,
// at log-spaced cluster times. The angle (integral) is built once as a cumulative sum
// in double precision after removing the mean, so each tau costs one O(N) pass:
//   sigma^2(m tau0) = sum_k (theta[k+2m] - 2 theta[k+m] + theta[k])^2 / (2 (m tau0)^2 (N+1-2m))
// Noise terms read from the curve: white noise (angle / velocity random walk) N = sigma(1 s)
// on the -1/2 slope; bias instability B = min sigma / 0.664 (flicker floor); rate random
// walk shows as a +1/2 slope.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace imudesk::record {

class AllanDeviation {
public:
    struct Point {
        double tau = 0;        // s
        double adev = 0;       // units of the signal
        double error = 0;      // relative 1-sigma uncertainty of adev, ~1/sqrt(2 (N/m - 1))
    };
    struct Summary {
        bool haveOneSecond = false;
        double atOneSecond = 0;        // sigma(1 s): the random-walk coefficient, units*sqrt(s)
        bool haveMinimum = false;
        double minimum = 0;            // smallest sigma on the curve
        double minimumTau = 0;
        double biasInstability = 0;    // minimum / 0.664
        // Every point of the curve is 0: the values never changed (the noise is below the
        // file's resolution, or the column is a constant), so there is no noise to measure and
        // neither figure above is given.
        bool flat = false;
    };

    // Cluster sizes m (1..(n-1)/2), about perDecade per decade, unique.
    static std::vector<size_t> logSpacedClusters(size_t n, int perDecade = 10);
    // data: n samples at tau0 seconds.
    static std::vector<Point> compute(const float *data, size_t n, double tau0, int perDecade = 10);
    // Log-log interpolation at tau; false if tau is outside the curve.
    static bool at(const std::vector<Point> &curve, double tau, double *value);
    static Summary summarize(const std::vector<Point> &curve);
    // Recording length (s) for adev at tauMax within relError: T = tauMax (1 + 1 / (2 e^2)).
    static double recommendedLength(double tauMax, double relError = 0.1);
};

} // namespace imudesk::record
