#include "sensor_model.h"

namespace imudesk::sim {

SensorModel::SensorModel(uint64_t seed) : m_rng(seed)
{
    // Constants first, from their own generator, so that they do not depend on how
    // many samples are drawn later.
    std::mt19937_64 g(seed ^ 0x5EED5EED5EED5EEDull);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 3; ++i) {
        const double mag = 0.05 + 0.15 * u(g);
        m_gyroBias[i] = (u(g) < 0.5 ? -1.0 : 1.0) * mag;
    }
    for (int i = 0; i < 3; ++i)
        m_hardIron[i] = -20.0 + 40.0 * u(g);
    // Soft iron: symmetric, close to the identity (diagonal +-3 %, off-diagonal +-2 %).
    m_softIron.setIdentity();
    for (int i = 0; i < 3; ++i)
        m_softIron(i, i) += -0.03 + 0.06 * u(g);
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
            m_softIron(i, j) = m_softIron(j, i) = -0.02 + 0.04 * u(g);
}

Eigen::Matrix3d SensorModel::AccError::matrix() const
{
    Eigen::Matrix3d n = Eigen::Matrix3d::Identity();
    n(1, 0) = misalignmentRad[0];
    n(2, 0) = misalignmentRad[1];
    n(2, 1) = misalignmentRad[2];
    return (Eigen::Vector3d::Ones() + scale).asDiagonal() * n;
}

Eigen::Matrix3d SensorModel::gyroMatrix() const
{
    AccError shape; // the same lower-triangular form as the accelerometer's
    shape.scale = m_gyroScaleError;
    shape.misalignmentRad = m_gyroMisalignment;
    return shape.matrix();
}

void SensorModel::setIronLeft(double fraction)
{
    m_hardIron *= fraction;
    m_softIron = Eigen::Matrix3d::Identity() + fraction * (m_softIron - Eigen::Matrix3d::Identity());
}

SensorReading SensorModel::ideal(const MotionState &s) const
{
    const Eigen::Matrix3d rT = s.q.toRotationMatrix().transpose();
    SensorReading r;
    r.acc = m_accMatrix * (rT * Eigen::Vector3d(0, 0, 1)) + m_accError.biasG;
    r.gyr = gyroMatrix() * s.rateDps + m_gyroBias;
    r.mag = m_softIron * (rT * fieldNav()) + m_hardIron;
    r.pressurePa = kPressurePa;
    r.temperatureC = kTemperatureC;
    return r;
}

SensorReading SensorModel::sample(const MotionState &s)
{
    SensorReading r = ideal(s);
    for (int i = 0; i < 3; ++i)
        r.acc[i] += kAccNoiseG * m_normal(m_rng);
    for (int i = 0; i < 3; ++i)
        r.gyr[i] += m_gyroNoiseFactor * kGyrNoiseDps * m_normal(m_rng);
    for (int i = 0; i < 3; ++i)
        r.mag[i] += kMagNoiseUt * m_normal(m_rng);
    r.pressurePa += kPressureNoisePa * m_normal(m_rng);
    r.temperatureC += 0.05 * m_normal(m_rng);
    return r;
}

} // namespace imudesk::sim
