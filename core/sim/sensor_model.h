#pragma once
// Synthesises what a module's sensors measure for a true motion state, in the sensor
// (body) frame and the manual's units:
//   acc (G)    = A * R^T * (0, 0, 1) + b     specific force of gravity in ENU (no centripetal term);
//                A = diag(1 + scale) * (I + N), N strictly lower triangular (the y axis leans
//                towards x by N(1,0), z towards x by N(2,0) and towards y by N(2,1), radians),
//                b the bias: the identity and zero unless AccError is set
//   gyr (deg/s) = diag(1 + scale errors) (I + N_g) * true rate + bias + white noise (kGyrNoiseDps * noise
//                factor), N_g the gyro's misalignment as the accelerometer's N
//   mag (uT)   = S * (R^T * B_nav) + h + white noise, B_nav = (0, 28, -42) uT in ENU
//   pressure about 100 kPa, temperature about 30 degC, each with a little noise.
// Bias, hard iron h and soft iron S are drawn from the seed; the noise comes from a
// std::mt19937_64 seeded with it, so a given seed and call sequence repeat exactly.
#include "motion_model.h"

#include <Eigen/Core>

#include <cstdint>
#include <random>

namespace imudesk::sim {

struct SensorReading {
    Eigen::Vector3d acc = Eigen::Vector3d::Zero(); // G
    Eigen::Vector3d gyr = Eigen::Vector3d::Zero(); // deg/s
    Eigen::Vector3d mag = Eigen::Vector3d::Zero(); // uT
    double pressurePa = 0;
    double temperatureC = 0;
};

class SensorModel {
public:
    static constexpr double kAccNoiseG = 0.0008;
    static constexpr double kGyrNoiseDps = 0.02;
    static constexpr double kMagNoiseUt = 0.15;
    static constexpr double kPressureNoisePa = 4.0;
    static constexpr double kPressurePa = 100000.0;
    static constexpr double kTemperatureC = 30.0;

    // Earth field in the ENU navigation frame: 28 uT horizontal (north), 42 uT down.
    static Eigen::Vector3d fieldNav() { return {0.0, 28.0, -42.0}; }

    explicit SensorModel(uint64_t seed = 1);

    // One noisy measurement (advances the random generator).
    SensorReading sample(const MotionState &s);
    // The same without white noise: bias and iron effects only (does not touch the generator).
    SensorReading ideal(const MotionState &s) const;

    // Gyro scale error (fraction, all axes): measured rate = (1 + e) * true rate + bias.
    void setGyroScaleError(double e) { m_gyroScaleError = Eigen::Vector3d::Constant(e); }
    // The same per axis.
    void setGyroScaleErrors(const Eigen::Vector3d &e) { m_gyroScaleError = e; }
    // The gyro's axes leaning as the accelerometer's may (AccError::misalignmentRad's order):
    // measured = diag(1 + scale) (I + N) true + bias.
    void setGyroMisalignment(const Eigen::Vector3d &rad) { m_gyroMisalignment = rad; }
    const Eigen::Vector3d &gyroMisalignment() const { return m_gyroMisalignment; }
    // diag(1 + scale) (I + N): the gyro's measured per true.
    Eigen::Matrix3d gyroMatrix() const;
    const Eigen::Vector3d &gyroScaleErrors() const { return m_gyroScaleError; }
    // The accelerometer's errors (a module's factory calibration left imperfect).
    struct AccError {
        Eigen::Vector3d biasG = Eigen::Vector3d::Zero();
        Eigen::Vector3d scale = Eigen::Vector3d::Zero();        // fractions
        Eigen::Vector3d misalignmentRad = Eigen::Vector3d::Zero(); // N(1,0), N(2,0), N(2,1)
        // A: measured = A * true + bias.
        Eigen::Matrix3d matrix() const;
    };
    void setAccError(const AccError &e) { m_accError = e; m_accMatrix = e.matrix(); }
    const AccError &accError() const { return m_accError; }
    // The magnetometer's iron as a module calibrated by its MCAL has it left: hard iron and soft
    // iron scaled by `fraction` (0: a perfect calibration, 1: none).
    void setIronLeft(double fraction);
    // Gyro white noise: the standard deviation per axis is factor * kGyrNoiseDps (1: a good
    // module; a larger factor is a noisy one, SimFaults::gyroNoiseFactor).
    void setGyroNoiseFactor(double factor) { m_gyroNoiseFactor = factor; }
    double gyroNoiseFactor() const { return m_gyroNoiseFactor; }
    const Eigen::Vector3d &gyroBias() const { return m_gyroBias; }
    const Eigen::Vector3d &hardIron() const { return m_hardIron; }
    const Eigen::Matrix3d &softIron() const { return m_softIron; }

private:
    std::mt19937_64 m_rng;
    std::normal_distribution<double> m_normal{0.0, 1.0};
    Eigen::Vector3d m_gyroBias;
    Eigen::Vector3d m_hardIron;
    Eigen::Matrix3d m_softIron;
    Eigen::Vector3d m_gyroScaleError = Eigen::Vector3d::Zero();
    Eigen::Vector3d m_gyroMisalignment = Eigen::Vector3d::Zero();
    AccError m_accError;
    Eigen::Matrix3d m_accMatrix = Eigen::Matrix3d::Identity();
    double m_gyroNoiseFactor = 1;
};

} // namespace imudesk::sim
