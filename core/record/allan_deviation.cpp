#include "allan_deviation.h"

#include <algorithm>
#include <cmath>

namespace imudesk::record {

std::vector<size_t> AllanDeviation::logSpacedClusters(size_t n, int perDecade)
{
    std::vector<size_t> out;
    if (n < 3 || perDecade <= 0)
        return out;
    const size_t maxM = (n - 1) / 2;
    for (int i = 0;; ++i) {
        const auto m = size_t(std::llround(std::pow(10.0, double(i) / perDecade)));
        if (m > maxM)
            break;
        if (out.empty() || m != out.back())
            out.push_back(m);
    }
    return out;
}

std::vector<AllanDeviation::Point> AllanDeviation::compute(const float *data, size_t n, double tau0, int perDecade)
{
    std::vector<Point> out;
    const auto clusters = logSpacedClusters(n, perDecade);
    if (clusters.empty() || tau0 <= 0)
        return out;
    double mean = 0;
    for (size_t i = 0; i < n; ++i)
        mean += data[i];
    mean /= double(n);
    // theta[k] = tau0 * sum_{i<k} (y_i - mean): the integrated signal.
    std::vector<double> theta(n + 1);
    theta[0] = 0;
    for (size_t i = 0; i < n; ++i)
        theta[i + 1] = theta[i] + (double(data[i]) - mean) * tau0;
    for (size_t m : clusters) {
        const size_t terms = n + 1 - 2 * m;
        const double *a = theta.data();
        const double *b = theta.data() + m;
        const double *c = theta.data() + 2 * m;
        double sum = 0;
        for (size_t k = 0; k < terms; ++k) {
            const double d = c[k] - 2.0 * b[k] + a[k];
            sum += d * d;
        }
        const double tau = double(m) * tau0;
        Point p;
        p.tau = tau;
        p.adev = std::sqrt(sum / (2.0 * tau * tau * double(terms)));
        const double k = double(n) / double(m);
        p.error = k > 1 ? 1.0 / std::sqrt(2.0 * (k - 1.0)) : 1.0;
        out.push_back(p);
    }
    return out;
}

bool AllanDeviation::at(const std::vector<Point> &curve, double tau, double *value)
{
    if (curve.empty() || tau < curve.front().tau || tau > curve.back().tau)
        return false;
    for (size_t i = 1; i < curve.size(); ++i) {
        if (tau > curve[i].tau)
            continue;
        const Point &a = curve[i - 1], &b = curve[i];
        if (a.adev <= 0 || b.adev <= 0) { // no logarithm of 0: a straight line between them
            const double g = (tau - a.tau) / (b.tau - a.tau);
            *value = a.adev + g * (b.adev - a.adev);
            return true;
        }
        const double f = (std::log(tau) - std::log(a.tau)) / (std::log(b.tau) - std::log(a.tau));
        *value = std::exp(std::log(a.adev) + f * (std::log(b.adev) - std::log(a.adev)));
        return true;
    }
    *value = curve.front().adev; // tau == the only point
    return true;
}

AllanDeviation::Summary AllanDeviation::summarize(const std::vector<Point> &curve)
{
    Summary s;
    s.flat = !curve.empty() && std::all_of(curve.begin(), curve.end(), [](const Point &p) { return p.adev <= 0; });
    if (s.flat)
        return s;
    s.haveOneSecond = at(curve, 1.0, &s.atOneSecond);
    // The minimum, ignoring the last points whose uncertainty is above 30 %.
    for (const Point &p : curve) {
        if (p.error > 0.3 || p.adev <= 0)
            continue;
        if (!s.haveMinimum || p.adev < s.minimum) {
            s.haveMinimum = true;
            s.minimum = p.adev;
            s.minimumTau = p.tau;
        }
    }
    if (s.haveMinimum)
        s.biasInstability = s.minimum / 0.664;
    return s;
}

double AllanDeviation::recommendedLength(double tauMax, double relError)
{
    return tauMax * (1.0 + 1.0 / (2.0 * relError * relError));
}

} // namespace imudesk::record
