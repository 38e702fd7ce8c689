#pragma once
// The gyro Z scale-factor run (manual v1.7.1 4.6.7.11: CONFIG USRCAL START <ANGLE>,
// 720..1800 deg, 20..100 deg/s, stop within +-5 deg of the angle; calibration-notes.md §5):
// our own estimate from the samples the device sends, integrated with the device's own
// timestamps.
//
// States: MeasuringBias (still for biasWindowS: gyro bias and the up axis from gravity)
// -> WaitingForTurn -> Turning (one leg: from the last still sample to the next stop held
// for stopHoldS) -> WaitingForTurn for the next leg ... -> Finished. A stop more than
// pauseShortDeg before the target is a pause: the leg goes on, and is flagged.
// The rate is the bias-free gyro projected on the measured up axis (z when no accelerometer
// is given). With two legs in opposite directions (strategy C of the notes: clockwise,
// stop, counter-clockwise, back on the same mark) the residual bias cancels:
//   scale error = (theta_1 - theta_2) * sign(theta_1) / (2 * target) - 1
// with one leg: |theta_1| / target - 1. The user must stop on the mechanical mark: the
// estimate takes the target angle as the truth.
#include "calib/stillness_detector.h"

#include <Eigen/Core>

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <vector>

namespace imudesk::calib {

class GyroScaleRun {
    Q_DECLARE_TR_FUNCTIONS(GyroScaleRun)

public:
    static constexpr int kMinTargetDeg = 720, kMaxTargetDeg = 1800; // the manual's ANGLE range
    static constexpr size_t kMaxLegSamples = 400000;                // rate statistics per leg
    enum class State { Idle, MeasuringBias, WaitingForTurn, Turning, Finished };

    struct Options {
        double targetDeg = 720;        // per leg
        int legs = 2;                  // 1: one direction; 2: there and back (bias cancels)
        double biasWindowS = 2.0;
        double stillRateDps = 0.5;     // a leg is integrated from the last sample below this
        double startRateDps = 5.0;     // a leg starts above this
        double stopRateDps = 2.0;      // and ends when below this for stopHoldS
        double stopHoldS = 0.5;
        double minLegDeg = 90;         // shorter turns are nudges, not legs
        double minRateDps = 20, maxRateDps = 100; // the manual's band
        double stopToleranceDeg = 5;   // the manual's window
        double pauseShortDeg = 45;     // a stop further than this before the target is a pause
        double maxUniformityPct = 20;  // std/mean of the rate in the even part
    };

    struct Leg {
        double angleDeg = 0;           // signed, bias removed
        double durationS = 0;
        double meanRateDps = 0, minRateDps = 0, maxRateDps = 0; // |rate| in the middle 80 % of the leg
        double inBandPct = 0;          // share of that part within the band
        double uniformityPct = 0;      // std / mean of |rate| there
        bool stoppedInWindow = false;  // |angle| within target +- tolerance
        bool paused = false;           // stopped on the way and went on
    };

    struct Result {
        bool complete = false;
        double scaleErrorPct = 0;      // estimate: measured / true - 1, in %
        double biasDps = 0;            // along the axis
        double axisTiltDeg = 0;        // between the up axis and sensor z
        double odrHz = 0;              // from the device timestamps
        std::vector<Leg> legs;
        bool acceptable = false;       // rates in band, even, stopped in the window
        QString summary;               // translated
    };

    GyroScaleRun();
    explicit GyroScaleRun(Options options);
    const Options &options() const { return m_options; }

    // Starts over: MeasuringBias. Call before feeding samples.
    void start();
    // One device sample: device time (ms), gyro (deg/s), accelerometer (G; zero: use z).
    State addSample(double deviceTimeMs, const Eigen::Vector3d &gyrDps,
                    const Eigen::Vector3d &accG = Eigen::Vector3d::Zero());

    State state() const { return m_state; }
    int legIndex() const { return int(m_legs.size()); }      // legs completed
    double currentAngleDeg() const { return m_angle; }       // signed, current leg
    double currentRateDps() const { return m_rate; }
    double turns() const { return std::abs(m_angle) / 360.0; }
    double remainingDeg() const { return m_options.targetDeg - std::abs(m_angle); }
    bool inStopWindow() const { return std::abs(remainingDeg()) <= m_options.stopToleranceDeg; }
    bool rateInBand() const;
    // What to tell the user now (translated).
    QString guidance() const;
    Result result() const;

private:
    void finishLeg();
    Leg legStats() const;

    Options m_options;
    State m_state = State::Idle;
    StillnessDetector m_still;
    Eigen::Vector3d m_bias = Eigen::Vector3d::Zero();
    Eigen::Vector3d m_axis = Eigen::Vector3d::UnitZ();
    double m_lastMs = 0;
    double m_lastRate = 0;
    bool m_haveLast = false;
    double m_angle = 0;
    double m_rate = 0;
    double m_legStartMs = 0;
    double m_belowSinceMs = -1;
    bool m_paused = false;
    double m_firstMs = -1;
    uint64_t m_samples = 0;
    std::vector<std::pair<double, double>> m_legRates; // (time ms, |rate|)
    std::vector<Leg> m_legs;
};

} // namespace imudesk::calib
