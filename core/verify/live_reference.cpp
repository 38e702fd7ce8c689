#include "live_reference.h"

#include "verify/motion_input.h"

#include <cmath>

namespace imudesk::verify {


void LiveReference::reset()
{
    m_source.clear();
    m_window.clear();
    m_filter.reset();
}

void LiveReference::add(const model::Sample &s)
{
    if (!s.has(model::FieldAcc) || !s.has(model::FieldGyr))
        return;
    if (m_source.empty())
        m_source = s.source;
    if (s.source != m_source)
        return;
    const double t = sampleTimeS(s);
    const Eigen::Vector3d acc(s.acc.x, s.acc.y, s.acc.z), gyr(s.gyr.x, s.gyr.y, s.gyr.z);
    if (m_filter) {
        m_filter->update(t, acc, gyr, Eigen::Vector3d::Zero(), false);
        return;
    }
    // Not started: wait for kRestS of rest (the stillness limits of the module check).
    if (!m_window.empty() && t <= m_window.back().tS)
        m_window.clear(); // the module's clock restarted
    m_window.push_back(Rest{t, acc, gyr});
    while (!m_window.empty() && t - m_window.front().tS > kRestS)
        m_window.pop_front();
    if (m_window.size() < 10 || t - m_window.front().tS < 0.95 * kRestS)
        return;
    Eigen::Vector3d ma = Eigen::Vector3d::Zero(), mg = Eigen::Vector3d::Zero();
    for (const Rest &r : m_window) {
        ma += r.acc;
        mg += r.gyr;
    }
    ma /= double(m_window.size());
    mg /= double(m_window.size());
    double va = 0, vg = 0;
    for (const Rest &r : m_window) {
        va += (r.acc - ma).squaredNorm();
        vg += (r.gyr - mg).squaredNorm();
    }
    const CheckOptions limits;
    if (std::sqrt(va / double(m_window.size())) > limits.maxAccStdG || std::sqrt(vg / double(m_window.size())) > limits.maxGyroStdDps
        || mg.norm() > limits.maxGyroMeanDps)
        return;
    Eigen::Quaterniond reported;
    if (!reportedAttitude(s, reported))
        return;
    // The tilt from gravity, the heading from the module: the module's attitude turned so that
    // its up matches the accelerometer's.
    const Eigen::Vector3d upBody = ma.normalized();
    const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(reported * upBody, Eigen::Vector3d::UnitZ()) * reported;
    ReferenceFilter::Sensors sensors;
    sensors.gravityG = ma.norm();
    sensors.gyroBias = mg;
    sensors.gyroNoiseDps = std::max(0.005, std::sqrt(vg / double(m_window.size()) / 3.0));
    m_filter = std::make_unique<ReferenceFilter>(sensors);
    m_filter->start(q.normalized(), 0.2);
    m_filter->update(t, acc, gyr, Eigen::Vector3d::Zero(), false);
    m_window.clear();
}

Eigen::Quaterniond LiveReference::attitude() const
{
    return m_filter ? m_filter->attitude() : Eigen::Quaterniond::Identity();
}

double LiveReference::sigmaDeg() const
{
    return m_filter ? m_filter->attitudeSigmaDeg() : 0.0;
}

double LiveReference::differenceDeg(const Eigen::Quaterniond &reported) const
{
    if (!m_filter)
        return 0;
    return 2.0 * std::acos(std::min(1.0, std::fabs(m_filter->attitude().dot(reported.normalized())))) * 57.29577951308232;
}

} // namespace imudesk::verify
