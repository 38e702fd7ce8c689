#include "reference_filter.h"

#include <Eigen/Dense>

#include <cmath>

namespace imudesk::verify {

namespace {

constexpr double kDegToRad = 0.017453292519943295;
constexpr double kBiasWalkDpsPerRootS = 1e-3; // how fast the gyro's bias may wander

Eigen::Matrix3d skew(const Eigen::Vector3d &v)
{
    Eigen::Matrix3d m;
    m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return m;
}

Eigen::Quaterniond rotation(const Eigen::Vector3d &angleRad)
{
    const double a = angleRad.norm();
    return a > 0 ? Eigen::Quaterniond(Eigen::AngleAxisd(a, angleRad / a)) : Eigen::Quaterniond::Identity();
}

} // namespace

ReferenceFilter::ReferenceFilter(const Sensors &sensors) : m_s(sensors)
{
    m_bias = sensors.gyroBias * kDegToRad;
    m_s.fieldNav.normalize();
}

void ReferenceFilter::start(const Eigen::Quaterniond &q, double sigmaDeg)
{
    m_q = q.normalized();
    m_p.setZero();
    m_p.topLeftCorner<3, 3>() = Eigen::Matrix3d::Identity() * std::pow(sigmaDeg * kDegToRad, 2);
    m_p.bottomRightCorner<3, 3>() = Eigen::Matrix3d::Identity() * std::pow(0.02 * kDegToRad, 2);
    m_started = true;
    m_lastS = 0;
    m_lastRate.setZero();
}

double ReferenceFilter::attitudeSigmaDeg() const
{
    return std::sqrt(std::max(0.0, m_p.topLeftCorner<3, 3>().trace())) / kDegToRad;
}

void ReferenceFilter::correct(const Eigen::Vector3d &measured, const Eigen::Vector3d &reference, double sigma)
{
    const Eigen::Vector3d h = m_q.conjugate() * reference;
    Eigen::Matrix<double, 3, 6> hm = Eigen::Matrix<double, 3, 6>::Zero();
    hm.leftCols<3>() = skew(h);
    const Eigen::Matrix3d s = hm * m_p * hm.transpose() + Eigen::Matrix3d::Identity() * sigma * sigma;
    const Eigen::Matrix<double, 6, 3> k = m_p * hm.transpose() * s.inverse();
    const Eigen::Matrix<double, 6, 1> dx = k * (measured - h);
    m_q = (m_q * rotation(dx.head<3>())).normalized();
    m_bias += dx.tail<3>();
    const Eigen::Matrix<double, 6, 6> ikh = Eigen::Matrix<double, 6, 6>::Identity() - k * hm;
    m_p = ikh * m_p * ikh.transpose() + k * (Eigen::Matrix3d::Identity() * sigma * sigma) * k.transpose();
    m_p = 0.5 * (m_p + m_p.transpose()).eval();
}

void ReferenceFilter::update(double tS, const Eigen::Vector3d &acc, const Eigen::Vector3d &gyr, const Eigen::Vector3d &mag,
                             bool hasMag)
{
    const Eigen::Vector3d rate = m_s.gyroCorrection * gyr * kDegToRad; // rad/s, bias not yet removed
    if (m_lastS > 0 && tS > m_lastS) {
        const double dt = tS - m_lastS;
        const Eigen::Vector3d w = 0.5 * (rate + m_lastRate) - m_bias;
        m_q = (m_q * rotation(w * dt)).normalized();
        Eigen::Matrix<double, 6, 6> phi = Eigen::Matrix<double, 6, 6>::Identity();
        phi.topLeftCorner<3, 3>() = rotation(w * dt).conjugate().toRotationMatrix();
        phi.topRightCorner<3, 3>() = -Eigen::Matrix3d::Identity() * dt;
        Eigen::Matrix<double, 6, 6> q = Eigen::Matrix<double, 6, 6>::Zero();
        q.topLeftCorner<3, 3>() = Eigen::Matrix3d::Identity() * std::pow(m_s.gyroNoiseDps * kDegToRad * dt, 2);
        q.bottomRightCorner<3, 3>() = Eigen::Matrix3d::Identity() * std::pow(kBiasWalkDpsPerRootS * kDegToRad, 2) * dt;
        m_p = phi * m_p * phi.transpose() + q;
    }
    m_lastS = tS;
    m_lastRate = rate;

    const Eigen::Vector3d a = m_s.accCorrection * (acc - m_s.accBias);
    const double turning = ((rate - m_bias) / kDegToRad).norm();
    if (std::fabs(a.norm() - m_s.gravityG) <= kAccGate * m_s.gravityG && turning <= kAccGateDps)
        correct(a.normalized(), Eigen::Vector3d::UnitZ(), 0.003 + 0.5 * std::fabs(a.norm() - m_s.gravityG));
    if (m_s.useMag && hasMag) {
        const Eigen::Vector3d m = mag - m_s.hardIron;
        if (std::fabs(m.norm() - m_s.fieldUt) <= kMagGate * m_s.fieldUt)
            correct(m.normalized(), m_s.fieldNav, m_s.magSigmaRad);
    }
}

} // namespace imudesk::verify
