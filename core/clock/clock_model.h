#pragma once
// One device's clock against the host's: host = device + offset + skew * device, fitted from
// the arrival times of the device's stamped samples only (one-way), so it must not be pulled
// by the transport's delays, which are never negative and often large (a USB serial adapter
// holds bytes up to its latency timer, 16 ms by default).
//
// The method is the lower bound of Olson ("A passive solution to the sensor synchronization
// problem", 2010) with a min-filter in front: arrivals are grouped in bins of device time and
// each bin keeps its earliest arrival (the sample that waited least); the line is an edge of
// the lower convex hull of those minima over a sliding window, below every one of them: the
// longest edge (clock_model.cpp says why not Olson's edge under the mean). The window slides
// with the data, so a drift that changes (temperature) is followed.
// What the line cannot see is the least delay every sample had (the time on the wire): the
// common time it gives is the arrival of a sample that waited least, a constant for a link,
// less Options::knownDelayNs when the caller knows it.
//
// Devices without a counter are stamped by a request and its answer: bracketTime gives the
// midpoint and the half-width as its uncertainty.
#include <cstdint>
#include <deque>
#include <optional>

namespace imudesk::clock {

struct ClockFit {
    bool valid = false;
    double skew = 0;          // host seconds per device second, minus 1 (40 ppm = 40e-6)
    double offsetNs = 0;      // host - device at device time 0 of this epoch
    double jitterNs = 0;      // RMS distance of the bins' minima from the line
    double meanDelayNs = 0;   // mean arrival delay above the line (the transport's batching)
    int bins = 0;             // minima in the window
    double spanS = 0;         // device time the window covers
    double driftPpm() const { return skew * 1e6; }
    // How fast the device's clock runs against the host's (ppm, + : fast): what a sync panel shows.
    double deviceDriftPpm() const { return -skew / (1 + skew) * 1e6; }
};

class ClockModel {
public:
    struct Options {
        int64_t binNs = 250'000'000;        // one minimum per quarter second of device time
        int64_t windowNs = 120'000'000'000; // the fit looks at the last two minutes
        int minBins = 4;                    // before that: not aligned yet
        double minSpanS = 2.0;              // the skew needs some device time under it
        // The least delay every sample has, when it is known (a frame's time on the wire:
        // its bytes x 10 / baud): taken off the common time.
        int64_t knownDelayNs = 0;
    };
    enum class State { FreeRunning, Uncertain, Aligned };

    ClockModel();
    explicit ClockModel(Options options);

    // One stamped sample: its device time and the host time it arrived at.
    void add(int64_t deviceNs, int64_t hostNs);
    // The common (host) time of a device time; nullopt before the first sample.
    std::optional<int64_t> toHost(int64_t deviceNs) const;
    const ClockFit &fit() const { return m_fit; }
    State state() const;
    // Everything forgotten (the device's counter was reset).
    void reset();

private:
    struct Point {
        double x; // device time - m_originNs, ns
        double y; // host - device, ns
    };
    void closeBin();
    void refit();
    double lineAt(double x) const { return m_lineY0 + m_lineSlope * x; }

    Options m_o;
    bool m_started = false;
    int64_t m_originNs = 0; // device time of the first sample (the points are relative to it)
    int64_t m_binStartNs = 0;
    bool m_binHasPoint = false;
    Point m_binMin{};
    std::deque<Point> m_minima;
    double m_lineY0 = 0, m_lineSlope = 0;
    ClockFit m_fit;
    double m_delaySum = 0;
    int64_t m_delayCount = 0;
};

// A device polled by request and answer: its sample was taken somewhere between the request's
// send and the answer's arrival. The midpoint, and half the interval as the uncertainty.
struct BracketTime {
    int64_t hostNs = 0;
    int64_t uncertaintyNs = 0;
};
inline BracketTime bracketTime(int64_t sentNs, int64_t receivedNs)
{
    if (receivedNs < sentNs)
        return {receivedNs, 0};
    return {sentNs + (receivedNs - sentNs) / 2, (receivedNs - sentNs + 1) / 2};
}

// The brackets of a polled device over its session: how many, and their mean half-width.
struct BracketTally {
    uint64_t count = 0;
    double sumNs = 0;
    void add(const BracketTime &b)
    {
        ++count;
        sumNs += double(b.uncertaintyNs);
    }
    double meanNs() const { return count ? sumNs / double(count) : 0; }
};

} // namespace imudesk::clock
