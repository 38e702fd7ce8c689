#include "calib/stillness_detector.h"

#include <cmath>

namespace imudesk::calib {

StillnessDetector::StillnessDetector() = default;

StillnessDetector::StillnessDetector(Options options)
    : m_options(options)
{
}

void StillnessDetector::reset()
{
    m_window.clear();
    m_still = false;
    m_stillSinceMs = m_lastMs = 0;
    m_gyroStd = m_accStd = 0;
    m_meanGyro.setZero();
    m_meanAcc.setZero();
}

bool StillnessDetector::windowFull() const
{
    return windowSpanS() >= m_options.windowS * 0.999;
}

double StillnessDetector::windowSpanS() const
{
    if (m_window.size() < 2)
        return 0;
    return (m_window.back().timeMs - m_window.front().timeMs) / 1000.0;
}

double StillnessDetector::stillForS() const
{
    return m_still ? (m_lastMs - m_stillSinceMs) / 1000.0 : 0.0;
}

bool StillnessDetector::add(double timeMs, const Eigen::Vector3d &gyrDps, const Eigen::Vector3d &accG)
{
    if (!std::isfinite(timeMs) || !gyrDps.allFinite() || !accG.allFinite())
        return m_still;
    if (!m_window.empty() && timeMs < m_window.back().timeMs) {
        // The device restarted (time went back): start over.
        reset();
    }
    m_window.push_back({timeMs, gyrDps, accG});
    m_lastMs = timeMs;
    // Keep just enough history to span the window.
    while (m_window.size() > 2 && (timeMs - m_window[1].timeMs) / 1000.0 >= m_options.windowS)
        m_window.pop_front();
    while (m_window.size() > kMaxSamples)
        m_window.pop_front();
    evaluate();
    return m_still;
}

void StillnessDetector::evaluate()
{
    const double n = double(m_window.size());
    Eigen::Vector3d sg = Eigen::Vector3d::Zero(), sa = Eigen::Vector3d::Zero();
    for (const Entry &e : m_window) {
        sg += e.gyr;
        sa += e.acc;
    }
    m_meanGyro = sg / n;
    m_meanAcc = sa / n;
    double vg = 0, va = 0;
    for (const Entry &e : m_window) {
        vg += (e.gyr - m_meanGyro).squaredNorm();
        va += (e.acc - m_meanAcc).squaredNorm();
    }
    m_gyroStd = std::sqrt(vg / n);
    m_accStd = std::sqrt(va / n);
    const bool still = windowFull() && m_gyroStd <= m_options.maxGyroStdDps && m_accStd <= m_options.maxAccStdG
        && m_meanGyro.norm() <= m_options.maxGyroMeanDps;
    if (still && !m_still)
        m_stillSinceMs = m_window.front().timeMs;
    m_still = still;
}

} // namespace imudesk::calib
