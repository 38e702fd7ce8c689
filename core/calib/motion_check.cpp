#include "calib/motion_check.h"

#include <algorithm>
#include <cmath>

namespace imudesk::calib {

void MotionCheck::add(double timeS, const Eigen::Vector3d &gyrDps, const Eigen::Vector3d &accG)
{
    if (!gyrDps.allFinite() || !accG.allFinite() || !std::isfinite(timeS))
        return;
    ++m_n;
    const Eigen::Vector3d d = gyrDps - m_mean;
    m_mean += d / double(m_n);
    m_m2 += d.cwiseProduct(gyrDps - m_mean);
    if (m_open.n > 0 && (timeS - m_openStartS >= kWindowS || timeS < m_openStartS))
        closeWindow();
    if (m_open.n == 0)
        m_openStartS = timeS;
    ++m_open.n;
    m_open.gyrSum += gyrDps;
    m_open.gyrSum2 += gyrDps.cwiseProduct(gyrDps);
    m_open.accSum += accG;
    m_open.accSum2 += accG.cwiseProduct(accG);
}

void MotionCheck::closeWindow()
{
    if (m_open.n >= 2 && m_windows.size() < kMaxWindows)
        m_windows.push_back(m_open);
    m_open = Window{};
}

MotionCheck::Result MotionCheck::result() const
{
    Result r;
    r.samples = m_n;
    if (m_n < 2)
        return r;
    r.gyroStdDps = std::sqrt(m_m2.sum() / double(m_n - 1));
    std::vector<Window> windows = m_windows;
    if (m_open.n >= 2)
        windows.push_back(m_open);
    // Each window's mean against the median window's, on each axis, beside what the noise
    // allows a mean of n samples (the window's own spread).
    auto largestChange = [&windows](bool gyro, double floor, double *change) {
        bool beyond = false;
        *change = 0;
        for (int a = 0; a < 3; ++a) {
            std::vector<double> means;
            means.reserve(windows.size());
            for (const Window &w : windows)
                means.push_back((gyro ? w.gyrSum : w.accSum)[a] / w.n);
            if (means.empty())
                return false;
            std::nth_element(means.begin(), means.begin() + ptrdiff_t(means.size() / 2), means.end());
            const double median = means[means.size() / 2];
            for (const Window &w : windows) {
                const double sum = (gyro ? w.gyrSum : w.accSum)[a], sum2 = (gyro ? w.gyrSum2 : w.accSum2)[a];
                const double mean = sum / w.n;
                const double var = std::max(0.0, (sum2 - sum * mean) / (w.n - 1));
                const double allowed = std::max(floor, kNoiseSigmas * std::sqrt(var / w.n));
                const double departure = std::fabs(mean - median);
                *change = std::max(*change, departure);
                beyond = beyond || departure > allowed;
            }
        }
        return beyond;
    };
    const bool rateChanged = largestChange(true, kMaxWindowRateDps, &r.rateChangeDps);
    const bool accChanged = largestChange(false, kMaxWindowAccG, &r.accChangeG);
    r.meanRateDps = m_mean.cwiseAbs().maxCoeff();
    if (r.gyroStdDps > kMaxGyroStdDps)
        r.why = Why::GyroNoise;
    else if (r.meanRateDps > kMaxMeanRateDps)
        r.why = Why::SteadyTurn;
    else if (rateChanged)
        r.why = Why::RateChanged;
    else if (accChanged)
        r.why = Why::AccChanged;
    r.moved = r.why != Why::Still;
    return r;
}

QString MotionCheck::Result::reason() const
{
    return moved ? MotionCheck::tr("the module moved: Allan deviation needs a still recording") : QString();
}

QString MotionCheck::Result::detail() const
{
    switch (why) {
    case Why::Still: return QString();
    case Why::GyroNoise:
        return MotionCheck::tr("gyro std dev %1 °/s, a module at rest stays below %2 °/s")
            .arg(gyroStdDps, 0, 'f', 1)
            .arg(kMaxGyroStdDps, 0, 'f', 0);
    case Why::RateChanged:
        return MotionCheck::tr("its rate changed by %1 °/s between 1-s windows: it was turned").arg(rateChangeDps, 0, 'f', 2);
    case Why::SteadyTurn:
        return MotionCheck::tr("it turned steadily at %1 °/s; a gyro's bias stays below %2 °/s")
            .arg(meanRateDps, 0, 'f', 1)
            .arg(kMaxMeanRateDps, 0, 'f', 0);
    case Why::AccChanged:
        return MotionCheck::tr("its acceleration changed by %1 G between 1-s windows: it was tilted or pushed")
            .arg(accChangeG, 0, 'f', 3);
    }
    return QString();
}

} // namespace imudesk::calib
