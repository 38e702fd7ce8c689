#pragma once
// Stillness over a sliding time window (device time): the standard deviation of the
// gyro and of the accelerometer (root of the summed per-axis variances) must stay below
// their limits over a window at least windowS long, and the mean rate must be small
// (a steady turn has no variance). Used before ATT RST (level/heading
// reset), before the gyro scale run (bias window) and by the level check
// (calibration-notes.md §4: PX4 still-detector, level window 0.5..5 s).
#include <Eigen/Core>

#include <deque>

namespace imudesk::calib {

class StillnessDetector {
public:
    static constexpr size_t kMaxSamples = 20000; // bounded whatever the rate

    struct Options {
        double windowS = 1.0;
        double maxGyroStdDps = 0.3;  // typical MEMS noise 0.02..0.1 deg/s
        double maxAccStdG = 0.005;   // 5 mG
        double maxGyroMeanDps = 2.0; // |mean rate|: a steady turn has no variance (bias < 1 deg/s)
    };

    StillnessDetector();
    explicit StillnessDetector(Options options);
    const Options &options() const { return m_options; }

    void reset();
    // One sample: device time (ms, increasing), gyro (deg/s), accelerometer (G).
    // Returns isStill() after it.
    bool add(double timeMs, const Eigen::Vector3d &gyrDps, const Eigen::Vector3d &accG);

    bool isStill() const { return m_still; }
    bool windowFull() const;
    double windowSpanS() const;
    double gyroStdDps() const { return m_gyroStd; }
    double accStdG() const { return m_accStd; }
    Eigen::Vector3d meanGyro() const { return m_meanGyro; }
    Eigen::Vector3d meanAcc() const { return m_meanAcc; }
    // Seconds the detector has been still without a break (0 when moving).
    double stillForS() const;

private:
    struct Entry {
        double timeMs;
        Eigen::Vector3d gyr, acc;
    };
    void evaluate();

    Options m_options;
    std::deque<Entry> m_window;
    bool m_still = false;
    double m_stillSinceMs = 0;
    double m_lastMs = 0;
    double m_gyroStd = 0, m_accStd = 0;
    Eigen::Vector3d m_meanGyro = Eigen::Vector3d::Zero(), m_meanAcc = Eigen::Vector3d::Zero();
};

} // namespace imudesk::calib
