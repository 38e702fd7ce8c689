#pragma once
// ImuDesk's own attitude filter on a module's raw sensors (issue 55: the reference that the
// module's attitude is judged against while it moves). A multiplicative extended Kalman
// filter: the state is the attitude (body to ENU) and the gyro's bias; its error state the
// attitude error in the body frame and the bias error, with their 6x6 covariance.
//   * predict: the rate, corrected by the bias and the scales the module check found, turns
//     the attitude (the exact rotation of each step); the covariance grows by the gyro's white
//     noise and a slow walk of its bias;
//   * gravity: the calibrated accelerometer's direction, only while the specific force is
//     gravity alone (its magnitude within kAccGate of g and the rate below kAccGateDps): a hand
//     accelerates the module too much for anything else to be gravity;
//   * the magnetometer (when given a field): its direction, hard iron removed, while its
//     magnitude agrees with the field's.
// Plain C++ and Eigen; usable sample by sample (live) as on a recording.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace imudesk::verify {

class ReferenceFilter {
public:
    static constexpr double kAccGate = 0.02;      // |a| within 2 % of g
    static constexpr double kAccGateDps = 30;     // and turning slower than this
    static constexpr double kMagGate = 0.05;      // |m| within 5 % of the field's

    struct Sensors {
        Eigen::Matrix3d accCorrection = Eigen::Matrix3d::Identity(); // a_true = C (a - b)
        Eigen::Vector3d accBias = Eigen::Vector3d::Zero();           // G
        double gravityG = 1;
        Eigen::Vector3d gyroBias = Eigen::Vector3d::Zero();          // deg/s, the start value
        Eigen::Matrix3d gyroCorrection = Eigen::Matrix3d::Identity(); // true = this * measured (scale, axes)
        double gyroNoiseDps = 0.05;                                  // per sample, 1 sigma
        bool useMag = false;
        Eigen::Vector3d hardIron = Eigen::Vector3d::Zero();          // uT
        Eigen::Vector3d fieldNav = Eigen::Vector3d(0, 1, 0);         // the field's direction in ENU
        double fieldUt = 50;
        double magSigmaRad = 0.02; // the field direction's error (1 sigma): its noise and what iron is left
    };

    explicit ReferenceFilter(const Sensors &sensors);
    // Starts at an attitude known to sigmaDeg (1 sigma, each axis).
    void start(const Eigen::Quaterniond &q, double sigmaDeg);
    bool started() const { return m_started; }
    // One sample at tS (s): acc (G), gyro (deg/s), magnetometer (uT, when hasMag).
    void update(double tS, const Eigen::Vector3d &acc, const Eigen::Vector3d &gyr, const Eigen::Vector3d &mag, bool hasMag);

    const Eigen::Quaterniond &attitude() const { return m_q; }
    const Eigen::Vector3d &gyroBias() const { return m_bias; }
    // 1 sigma of the attitude error (deg, root of the summed variances of its three axes).
    double attitudeSigmaDeg() const;

private:
    void correct(const Eigen::Vector3d &measured, const Eigen::Vector3d &reference, double sigma);

    Sensors m_s;
    bool m_started = false;
    double m_lastS = 0;
    Eigen::Vector3d m_lastRate = Eigen::Vector3d::Zero();
    Eigen::Quaterniond m_q = Eigen::Quaterniond::Identity();
    Eigen::Vector3d m_bias = Eigen::Vector3d::Zero();
    Eigen::Matrix<double, 6, 6> m_p = Eigen::Matrix<double, 6, 6>::Identity();
};

} // namespace imudesk::verify
