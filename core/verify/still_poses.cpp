// Step 1 of the module check (module_check.h): still intervals and distinct poses.
#include "module_check.h"

#include <algorithm>
#include <cmath>

namespace imudesk::verify {

namespace {

constexpr double kEdgeS = 0.1;

// Running sums of a vector series, centred on its first value (so that the squares do not
// swamp a small variance), for O(1) window statistics.
class RunningSums {
public:
    void reserve(size_t n)
    {
        m_sum.reserve(n + 1);
        m_sq.reserve(n + 1);
    }
    void add(const Eigen::Vector3d &v)
    {
        if (m_sum.empty()) {
            m_origin = v;
            m_sum.push_back(Eigen::Vector3d::Zero());
            m_sq.push_back(Eigen::Vector3d::Zero());
        }
        const Eigen::Vector3d d = v - m_origin;
        m_sum.push_back(m_sum.back() + d);
        m_sq.push_back(m_sq.back() + d.cwiseProduct(d));
    }
    // Samples [a, b): mean, and the root of the summed per-axis variances.
    Eigen::Vector3d mean(size_t a, size_t b) const { return m_origin + (m_sum[b] - m_sum[a]) / double(b - a); }
    double spread(size_t a, size_t b) const
    {
        const double n = double(b - a);
        const Eigen::Vector3d m = (m_sum[b] - m_sum[a]) / n;
        const Eigen::Vector3d var = (m_sq[b] - m_sq[a]) / n - m.cwiseProduct(m);
        return std::sqrt(std::max(0.0, var.sum()));
    }

private:
    Eigen::Vector3d m_origin = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> m_sum, m_sq;
};

// The standard deviation of the mean of samples [a, b) per axis: from batch means (noise that
// is not white, a hand's tremor, shows there), never below the white-noise figure.
template <typename Get>
Eigen::Vector3d sigmaOfMean(size_t a, size_t b, Get get)
{
    const size_t n = b - a;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (size_t i = a; i < b; ++i)
        mean += get(i);
    mean /= double(n);
    Eigen::Vector3d var = Eigen::Vector3d::Zero();
    for (size_t i = a; i < b; ++i)
        var += (get(i) - mean).cwiseAbs2();
    Eigen::Vector3d white = (var / double(std::max<size_t>(1, n - 1)) / double(n)).cwiseSqrt();
    const size_t batches = std::min<size_t>(20, n / 10);
    if (batches < 4)
        return white;
    Eigen::Vector3d bvar = Eigen::Vector3d::Zero();
    for (size_t k = 0; k < batches; ++k) {
        const size_t from = a + k * n / batches, to = a + (k + 1) * n / batches;
        Eigen::Vector3d m = Eigen::Vector3d::Zero();
        for (size_t i = from; i < to; ++i)
            m += get(i);
        m /= double(to - from);
        bvar += (m - mean).cwiseAbs2();
    }
    const Eigen::Vector3d batch = (bvar / double(batches - 1) / double(batches)).cwiseSqrt();
    return white.cwiseMax(batch);
}

} // namespace

std::vector<Pose> findStillPoses(const std::vector<MotionSample> &samples, const CheckOptions &options)
{
    std::vector<Pose> poses;
    const size_t n = samples.size();
    if (n < 3)
        return poses;
    RunningSums gyr, acc;
    gyr.reserve(n);
    acc.reserve(n);
    for (const MotionSample &s : samples) {
        gyr.add(s.gyr);
        acc.add(s.acc);
    }
    const double w = options.stillWindowS;
    // still[i]: the window that ends at sample i is full and still.
    std::vector<char> still(n, 0);
    std::vector<size_t> windowStart(n, 0);
    size_t j = 0;
    for (size_t i = 0; i < n; ++i) {
        while (j < i && samples[i].tS - samples[j].tS > w)
            ++j;
        windowStart[i] = j;
        if (i - j + 1 < 5 || samples[i].tS - samples[j].tS < 0.8 * w)
            continue;
        still[i] = gyr.spread(j, i + 1) <= options.maxGyroStdDps && acc.spread(j, i + 1) <= options.maxAccStdG
            && gyr.mean(j, i + 1).norm() <= options.maxGyroMeanDps;
    }
    for (size_t i = 0; i < n;) {
        if (!still[i]) {
            ++i;
            continue;
        }
        size_t last = i;
        while (last + 1 < n && still[last + 1])
            ++last;
        size_t a = windowStart[i], b = last + 1;
        i = b;
        // A hand starts and ends a move gently: the first and last few tens of ms of a move
        // pass for still. kEdgeS off each end keeps them out of the pose's means.
        const double from = samples[a].tS + kEdgeS, to = samples[b - 1].tS - kEdgeS;
        while (a < b && samples[a].tS < from)
            ++a;
        while (b > a && samples[b - 1].tS > to)
            --b;
        if (b <= a || samples[b - 1].tS - samples[a].tS < options.minHoldS)
            continue;
        Pose p;
        p.fromS = samples[a].tS;
        p.toS = samples[b - 1].tS;
        p.samples = int(b - a);
        p.acc = acc.mean(a, b);
        p.gyr = gyr.mean(a, b);
        p.accSigma = sigmaOfMean(a, b, [&](size_t k) { return samples[k].acc; });
        p.gyrSigma = sigmaOfMean(a, b, [&](size_t k) { return samples[k].gyr; });
        int mags = 0, atts = 0;
        Eigen::Vector4d q = Eigen::Vector4d::Zero();
        Eigen::Vector4d first = Eigen::Vector4d::Zero();
        for (size_t k = a; k < b; ++k) {
            const MotionSample &s = samples[k];
            if (s.hasMag) {
                p.mag += s.mag;
                ++mags;
            }
            if (s.hasAttitude) {
                Eigen::Vector4d v(s.q.w(), s.q.x(), s.q.y(), s.q.z());
                if (atts == 0)
                    first = v;
                q += v.dot(first) < 0 ? Eigen::Vector4d(-v) : v;
                ++atts;
            }
        }
        // A quantity counts when most of the interval carries it.
        p.hasMag = mags * 2 > p.samples;
        if (p.hasMag)
            p.mag /= mags;
        p.hasAttitude = atts * 2 > p.samples && q.norm() > 0;
        if (p.hasAttitude) {
            q.normalize();
            p.reported = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
        }
        poses.push_back(p);
    }
    return poses;
}

int groupPoses(std::vector<Pose> &poses, double samePoseDeg)
{
    std::vector<Eigen::Vector3d> directions;
    const double cosLimit = std::cos(samePoseDeg * 3.141592653589793 / 180.0);
    for (Pose &p : poses) {
        const Eigen::Vector3d d = p.acc.normalized();
        p.distinct = -1;
        for (size_t k = 0; k < directions.size(); ++k)
            if (directions[k].dot(d) >= cosLimit) {
                p.distinct = int(k);
                break;
            }
        if (p.distinct < 0) {
            p.distinct = int(directions.size());
            directions.push_back(d);
        }
    }
    return int(directions.size());
}

} // namespace imudesk::verify
