#pragma once
// Characterises a recording: per-channel mean, standard deviation, min and max; the
// output rate and its jitter (a histogram of frame intervals from the device clock);
// frames lost from gaps in system_time (device/frame_gap_counter.h); and the overlapping
// Allan deviation of the gyro and accelerometer axes with the random walk at tau = 1 s,
// the bias instability at the curve's minimum and the recording length a tau range needs.
//
// Samples of one frame type are analysed (the first type that carries gyro data, or the
// one asked for). Statistics stream; the six IMU axes are kept as floats (24 bytes per
// frame) for the Allan deviation.
//
// A recording of a module that moved (calib/motion_check.h says how that is told) gets no
// Allan deviation, random walk or bias instability: Result::motion says why (issue 53). Nor
// does one too short for the curve to reach τ = 1 s, where the random walk is read (under
// 2 s of still data): Result::allanWhyNot says which, allanReason() and allanDetail() why.
#include "calib/motion_check.h"
#include "device/frame_gap_counter.h"
#include "model/sample.h"
#include "record/allan_deviation.h"

#include <QCoreApplication>
#include <QString>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace imudesk::record {

class SampleAnalyzer {
    Q_DECLARE_TR_FUNCTIONS(SampleAnalyzer)

public:
    static constexpr double kRandomWalkTauS = 1.0; // the random walk is read at τ = 1 s
    enum class AllanWhyNot { Judged, Moved, TooShort };
    struct Channel {
        std::string name;   // "acc_x", ...
        std::string unit;   // "G", ...
        uint64_t count = 0;
        double mean = 0, std = 0, min = 0, max = 0;
    };
    struct Axis {
        std::string name;   // "gyr_x", ...
        std::string unit;
        std::vector<AllanDeviation::Point> curve;
        AllanDeviation::Summary summary;
    };
    struct HistogramBin {
        double fromMs = 0, toMs = 0;
        uint64_t count = 0;
    };
    struct Result {
        std::string source;             // frame type analysed
        uint64_t frames = 0;
        double durationS = 0;           // device clock, first to last frame
        double rateHz = 0;              // frames per second of device time
        double intervalMeanMs = 0, intervalStdMs = 0, intervalMinMs = 0, intervalMaxMs = 0;
        std::vector<HistogramBin> intervals;
        uint64_t framesLost = 0;
        uint64_t deviceResets = 0;
        std::vector<Channel> channels;
        std::vector<Axis> axes;         // gyr_x..z, acc_x..z; empty unless allanWhyNot is Judged
        calib::MotionCheck::Result motion; // motion.moved: no Allan figures, motion.reason() why
        AllanWhyNot allanWhyNot = AllanWhyNot::Judged;
        double tau0S = 0;               // the output period the curve starts at
        bool allanJudged() const { return allanWhyNot == AllanWhyNot::Judged; }
        // "the module moved: …" / "cannot judge: the recording is too short" and what showed it
        // (translated); empty when judged.
        QString allanReason() const;
        QString allanDetail() const;
        double tauMax = 0;              // the tau range asked for
        double recommendedLengthS = 0;  // for tauMax at 10 % uncertainty
    };

    explicit SampleAnalyzer(std::string source = {}) : m_source(std::move(source)) {}
    void add(const model::Sample &s);
    // tauMax: the longest cluster time of interest (s), for the recommended length.
    Result finish(double tauMax = 1000.0, int histogramBins = 20) const;

private:
    struct Running {
        uint64_t n = 0;
        double mean = 0, m2 = 0, min = 0, max = 0;
        void add(double x);
    };
    static constexpr size_t kChannels = 14;

    std::string m_source;
    std::array<Running, kChannels> m_stats{};
    std::array<std::vector<float>, 6> m_axes;
    std::vector<float> m_intervals;  // ms
    device::FrameGapCounter m_gaps;
    calib::MotionCheck m_motion;
    uint64_t m_frames = 0;
    bool m_haveTime = false;
    double m_firstMs = 0, m_lastMs = 0;
};

} // namespace imudesk::record
