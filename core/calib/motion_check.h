#pragma once
// Was a recording that should be still moved? (issue 53) The Allan deviation, the angle random
// walk and the bias instability describe a sensor at rest: on a module moved by hand they are
// the motion's, not the sensor's, and must not be shown or judged as its noise.
//
// The criterion, over the whole recording and over 1-s windows of it (device time):
//   1. the gyro's standard deviation (root of the summed per-axis variances) above 5 °/s: a
//      MEMS gyro at rest shows 0.02..0.5 °/s of noise (a "noisy" one a few tenths), a hand
//      moving the module tens to hundreds;
//   2. the mean rate of a window differs from the median window's by more than 1 °/s on an axis,
//      or by more than 6 times what the noise allows a window's mean (6·s/√n): a turn slow
//      enough to hide in the noise;
//   3. the mean acceleration of a window differs from the median window's by more than 0.05 G
//      (about 3° of tilt) or 6·s/√n: the module was tilted or pushed;
//   4. the mean rate over the recording above 10 °/s on an axis: a steady turn (a turntable),
//      which has no spread; a MEMS gyro's bias stays within a few °/s.
// The stillness detector (stillness_detector.h) is not used: its 0.3 °/s suits a good module
// before a level reset, and would call a still but noisy module moving, which the station must
// fail on its noise, not excuse.
#include <Eigen/Core>

#include <QCoreApplication>
#include <QString>

#include <vector>

namespace imudesk::calib {

class MotionCheck {
    Q_DECLARE_TR_FUNCTIONS(MotionCheck)

public:
    static constexpr double kMaxGyroStdDps = 5.0;
    static constexpr double kWindowS = 1.0;
    static constexpr double kMaxWindowRateDps = 1.0;
    static constexpr double kMaxWindowAccG = 0.05;
    static constexpr double kNoiseSigmas = 6.0;
    static constexpr double kMaxMeanRateDps = 10.0;
    static constexpr size_t kMaxWindows = 1000000; // about eleven days of 1-s windows

    enum class Why { Still, GyroNoise, RateChanged, AccChanged, SteadyTurn };
    struct Result {
        bool moved = false;
        Why why = Why::Still;
        uint64_t samples = 0;
        double gyroStdDps = 0;          // over the whole recording
        double rateChangeDps = 0;       // largest departure of a window's mean rate (any axis)
        double accChangeG = 0;          // of a window's mean acceleration (any axis)
        double meanRateDps = 0;         // largest |mean rate| of an axis over the recording
        // "the module moved: Allan deviation needs a still recording" and what showed it
        // (translated); empty when still.
        QString reason() const;
        QString detail() const;
    };

    // timeS: device time in seconds (increasing; a step back starts a new window).
    void add(double timeS, const Eigen::Vector3d &gyrDps, const Eigen::Vector3d &accG);
    Result result() const;

private:
    struct Window {
        int n = 0;
        Eigen::Vector3d gyrSum = Eigen::Vector3d::Zero(), gyrSum2 = Eigen::Vector3d::Zero();
        Eigen::Vector3d accSum = Eigen::Vector3d::Zero(), accSum2 = Eigen::Vector3d::Zero();
    };
    void closeWindow();

    // The whole recording (Welford per axis).
    uint64_t m_n = 0;
    Eigen::Vector3d m_mean = Eigen::Vector3d::Zero(), m_m2 = Eigen::Vector3d::Zero();
    Window m_open;
    double m_openStartS = 0;
    std::vector<Window> m_windows;
};

} // namespace imudesk::calib
