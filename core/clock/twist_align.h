#pragma once
// "Twist to align": two IMU modules on one fixture, the fixture turned sharply a few times.
// A rigid body turns at one angular rate everywhere on it, so the two modules' gyro
// magnitudes are one signal, seen on two time axes that differ by a constant. The offset is
// the peak of the signals' normalised cross-correlation: a coarse search on a uniform grid,
// then a fine one (golden section, to about 1 µs) that interpolates `other` at the
// reference's own sample times, both series lightly smoothed first (twist_align.cpp says why).
//
// Sign: offsetNs is added to `other`'s times to put them on the reference's, i.e. other's
// value at t matches the reference's at t + offsetNs. The correlation curve's lag is the same
// quantity (its peak is at offsetNs).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace imudesk::clock {

// One device's gyro magnitude on the (approximately) common time axis.
struct TwistSeries {
    std::vector<int64_t> timeNs; // increasing (samples may be missing)
    std::vector<double> gyroDps; // |gyro| in deg/s, one per time
    std::string name;            // for the messages ("device B"); empty: "the reference device" / "the other device"
};

struct TwistAlignOptions {
    int64_t maxLagNs = 250'000'000;        // search offsets within ±this
    int64_t gridNs = 500'000;              // resampling grid of the coarse search (made coarser for long recordings)
    double minPeakDps = 60;                // a twist: |gyro| above this (on both devices)
    int minTwists = 3;                     // fewer distinct twists on either device: refused
    double minCorrelation = 0.8;           // normalised correlation at the peak below this: refused
    int64_t minOverlapNs = 5'000'000'000;  // the recordings must share at least this much time
    double ambiguityRatio = 0.95;          // a separate peak this close to the best: refused
    double fineToleranceNs = 1'000;        // the fine search stops when its bracket is this narrow
};

struct TwistAlignResult {
    bool ok = false;
    std::string whyNot;         // an English sentence for the user when !ok
    double offsetNs = 0;        // add to `other`'s times to put them on `reference`'s
    double correlation = 0;     // normalised correlation at the peak (-1..1), of the fine search's smoothed series
    double uncertaintyNs = 0;   // one standard deviation (see twist_align.cpp), at least half the fine step
    int twistsReference = 0, twistsOther = 0; // distinct twists found in each series
    double secondPeakNs = 0;               // the best separate peak of the coarse curve, if any
    double secondPeakCorrelation = 0;      // its correlation (0 when there is none)
    int64_t coarseGridNs = 0;              // the grid the coarse search used
    std::vector<std::pair<double, double>> curve; // (lag ms, correlation), coarse, at most 1001 points
};

TwistAlignResult alignByTwist(const TwistSeries &reference, const TwistSeries &other, const TwistAlignOptions &o = {});

// Distinct excursions of |gyro| above minPeakDps, each ended by the signal falling below half
// of it, among the samples with fromNs <= time <= toNs.
int countTwists(const TwistSeries &s, double minPeakDps, int64_t fromNs, int64_t toNs);

} // namespace imudesk::clock
