#pragma once
// The recent history of one device's chartable channels, column by column, for the
// live charts. Bounded by a duration (host time) and by a row cap; stores floats,
// not Samples.
//
// Memory, at full size (kMaxRows = 600 000 rows = 10 min at 1 kHz):
//   18 channels x 4 B (float)      72 B   (a module's: a channel's column is allocated when a
//                                         sample first carries it, so the compass's four
//                                         channels cost a module nothing)
//   host time   (double, s)         8 B
//   device time (double, s)         8 B
//   flags       (uint32)            4 B
//   ----------------------------------
//                                  92 B  -> 55.2 MB (52.6 MiB) for 600 000 rows;
//   kBytesPerRow, every channel:  108 B  -> 64.8 MB.
// The ring starts at kInitialRows and doubles on demand (one column at a time, so
// the transient peak is the full size plus one column), so a 100 Hz device never
// allocates more than about 6 MB.
//
// Time axes (both in seconds, both non-decreasing from row to row, so every range
// query is a binary search):
//   Host   the host clock: the sample's common time (its sampling instant on the host's
//          clock, core/clock) where it has one, else its arrival (hostTimeNs), relative to
//          hostOriginNs() (the first sample after clear()): every device on one time base.
//          The host clock is monotonic; a sample stamped earlier than its predecessor
//          is clamped to the predecessor's time.
//   Device deviceTimeMs, "stitched": within one segment the device clock is kept as
//          it is, gaps included. When the device clock jumps backwards (reboot,
//          wrap, UTC midnight) a new segment starts: it continues right after the
//          previous row (by the host-time step, or one sample period), and its first
//          row carries FlagSegmentStart. deviceTimeOffset() is stitched minus raw
//          device time in the current segment, so the newest data can be shown on the
//          device's own clock. A row without a device time between the clock's rows (another
//          frame type interleaved) stands at the previous row's device time until the clock's
//          next row comes, then goes where its host time since the clock's row puts it (never
//          past the next row); once the clock is overdue (silent for more than kOverduePeriods
//          of its period) such rows follow the host clock from the clock's last row at once,
//          and the rows that stood at its time are restamped the same way (an HEC495 that streams angles without a time after its
//          polled records: no pile of rows at one instant, no frozen axis). Before any device
//          time, and once the clock's frame type has been silent for kClockHandOverS with no
//          other clock to take over, rows advance the axis by their host-time step (a device
//          that stops sending its clock still charts); a device time that comes back after
//          that starts a segment.
//          One frame type's clock drives the axis (the first with a device time, then the
//          busiest: another type with more than twice its rows in kClockWindow takes over);
//          the rows of other types count as rows without one; when the owner has sent
//          nothing for kClockHandOverS the next type's clock takes over. A hand-over starts
//          a segment.
//
// Row flags: bit n (n < kChannelCount) = channel n present. A sample that lacks a
// field leaves those channels empty (NaN, bit clear) for that row; non-finite
// values are treated as absent. FlagGap marks a row that follows a device-clock
// gap of more than kGapPeriods sample periods (the period is the median of the
// recent positive steps); FlagSegmentStart the first row of a new segment. Charts
// break their lines before rows carrying either flag.
//
// Not thread-safe: the GUI thread owns it (it is fed from the sample store on the
// view clock).
#include "model/sample.h"

#include <array>
#include <cstddef>
#include <bit>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace imudesk::plot {

enum class Channel : uint8_t {
    AccX,
    AccY,
    AccZ,
    GyrX,
    GyrY,
    GyrZ,
    MagX,
    MagY,
    MagZ,
    Roll,
    Pitch,
    Yaw,
    QuatW,
    QuatX,
    QuatY,
    QuatZ,
    Pressure,
    Temperature,
    // A compass's (HEC495): its relative magnetic field (no unit) and its magnetic roll (deg).
    MagRelX,
    MagRelY,
    MagRelZ,
    MagRoll,
};
inline constexpr int kChannelCount = 22;

constexpr uint32_t channelBit(Channel c)
{
    return 1u << unsigned(c);
}

enum class TimeAxis : uint8_t { Device, Host };

// Rows [first, last) in time order (row 0 is the oldest).
struct IndexRange {
    size_t first = 0;
    size_t last = 0;
    bool empty() const { return last <= first; }
    size_t size() const { return empty() ? 0 : last - first; }
    friend bool operator==(const IndexRange &, const IndexRange &) = default;
};

class ChannelHistory {
public:
    static constexpr double kMaxDurationS = 600.0;  // default and maximum
    static constexpr size_t kMaxRows = 600000;     // 10 min at 1 kHz; default and maximum
    static constexpr size_t kInitialRows = 4096;
    static constexpr size_t kBytesPerRow =
        kChannelCount * sizeof(float) + 2 * sizeof(double) + sizeof(uint32_t);
    static constexpr double kGapPeriods = 5.0;     // a device-clock step above this many periods is a gap
    static constexpr int kPeriodWindow = 15;       // recent positive steps in the period median
    static constexpr double kClockHandOverS = 1.0; // the axis's frame type silent this long (host s): another's clock takes over
    static constexpr double kOverduePeriods = 2.0; // the clock silent this many periods: rows without one follow the host clock
    static constexpr int kClockWindow = 100;       // rows with a device time per check of which type is busiest

    static constexpr uint32_t kChannelMask = (1u << kChannelCount) - 1;
    static constexpr uint32_t FlagDeviceTime = 1u << 24;   // the sample carried a device time
    static constexpr uint32_t FlagSegmentStart = 1u << 25; // device clock went backwards before this row
    static constexpr uint32_t FlagGap = 1u << 26;          // device clock gap before this row
    static constexpr uint32_t kBreakFlags = FlagSegmentStart | FlagGap;

    // A contiguous stretch of physical storage, [begin, end).
    struct Run {
        size_t begin = 0;
        size_t end = 0;
    };

    // The channels a Sample field fills (0 for fields that are not charted).
    static uint32_t channelsOfField(uint32_t sampleFields);

    explicit ChannelHistory(double maxDurationS = kMaxDurationS, size_t maxRows = kMaxRows);

    // Clamped to (0, kMaxDurationS] and [1, kMaxRows]; drops the oldest rows that no longer fit.
    void setLimits(double maxDurationS, size_t maxRows);
    double maxDuration() const { return m_maxDuration; }
    size_t maxRows() const { return m_maxRows; }

    // O(1) amortised per sample.
    void append(const model::Sample &sample);
    void append(const std::vector<model::Sample> &batch);
    // Forgets every row and the time origins; keeps the storage.
    void clear();

    size_t size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    size_t capacity() const { return m_capacity; }
    // Bytes held by the columns (capacity x the bytes of a row of the allocated columns).
    size_t memoryBytes() const
    {
        return m_capacity * (kBytesPerRow - (kChannelCount - size_t(std::popcount(m_allocated))) * sizeof(float));
    }
    // Changes whenever rows are appended, dropped or cleared.
    uint64_t revision() const { return m_revision; }
    // Changes on clear() only: rows of another generation are not comparable.
    uint64_t generation() const { return m_generation; }
    // Samples appended since construction or clear(), and how many of them were dropped again.
    uint64_t totalAppended() const { return m_totalAppended; }
    uint64_t dropped() const { return m_totalAppended - m_size; }
    // Union of the channels present in any row appended since clear().
    uint32_t presentChannels() const { return m_presentChannels; }
    // Host time (s) of the newest row that had the channel since clear(); -inf before one.
    double channelSeenHost(Channel c) const { return m_channelSeen[size_t(c)]; }
    // Segments of the device clock since clear() (0 when empty).
    int segmentCount() const { return m_segments; }

    // Row access, row 0 = oldest. No bounds checks beyond Q_ASSERT.
    double time(TimeAxis axis, size_t row) const;
    double hostTime(size_t row) const { return m_host[phys(row)]; }
    double deviceTime(size_t row) const { return m_device[phys(row)]; }
    // NaN where the row lacks the channel (and for a channel no row has carried).
    float value(Channel channel, size_t row) const
    {
        const auto &column = m_values[size_t(channel)];
        return column.empty() ? std::numeric_limits<float>::quiet_NaN() : column[phys(row)];
    }
    uint32_t flags(size_t row) const { return m_flags[phys(row)]; }
    bool has(Channel channel, size_t row) const { return (flags(row) & channelBit(channel)) != 0; }

    double oldestTime(TimeAxis axis) const { return empty() ? 0.0 : time(axis, 0); }
    double newestTime(TimeAxis axis) const { return empty() ? 0.0 : time(axis, m_size - 1); }
    // Stitched minus raw device time (s) in the newest segment.
    double deviceTimeOffset() const { return m_deviceOffset; }
    // hostTimeNs of the sample that host time 0 stands for.
    int64_t hostOriginNs() const { return m_hostOriginNs; }
    // Median of the recent positive device-clock steps (s); 0 while unknown.
    double samplePeriod() const { return m_period; }

    // First row with time >= t / > t; size() when there is none. Binary search.
    size_t lowerBound(TimeAxis axis, double t) const;
    size_t upperBound(TimeAxis axis, double t) const;
    // Rows with t0 <= time <= t1.
    IndexRange range(TimeAxis axis, double t0, double t1) const;
    // The row nearest to t that carries `channel`, looking at most maxScan rows either
    // side of t; -1 if none.
    long long nearestRow(TimeAxis axis, double t, Channel channel, size_t maxScan = 256) const;

    // For hot loops: rows [first, last) as at most two runs of physical storage, and
    // the raw columns those runs index.
    std::array<Run, 2> physicalRuns(size_t first, size_t last) const;
    // nullptr for a channel no row has carried since the history was made (its column is not
    // allocated; has() is false for every row).
    const float *columnData(Channel channel) const
    {
        return m_values[size_t(channel)].empty() ? nullptr : m_values[size_t(channel)].data();
    }
    const double *timeData(TimeAxis axis) const
    {
        return axis == TimeAxis::Host ? m_host.data() : m_device.data();
    }
    const uint32_t *flagData() const { return m_flags.data(); }

private:
    size_t phys(size_t row) const
    {
        size_t p = m_head + row;
        return p >= m_capacity ? p - m_capacity : p;
    }
    void appendOne(const model::Sample &sample);
    void dropFront(size_t count);
    void reserveRows(size_t rows);
    void updatePeriod(double step);
    // Rows after the clock's newest row that stood at its time follow the host clock from it,
    // up to upTo (the device time of the clock's next row).
    void restampStanding(double upTo = std::numeric_limits<double>::infinity());

    double m_maxDuration;
    size_t m_maxRows;

    std::array<std::vector<float>, kChannelCount> m_values;
    uint32_t m_allocated = 0; // channelBit() of the columns that m_values holds (capacity rows each)
    std::vector<double> m_host;
    std::vector<double> m_device;
    std::vector<uint32_t> m_flags;
    size_t m_capacity = 0;
    size_t m_head = 0; // physical index of row 0
    size_t m_size = 0;

    uint64_t m_revision = 0;
    uint64_t m_generation = 0;
    uint64_t m_totalAppended = 0;
    uint32_t m_presentChannels = 0;
    std::array<double, kChannelCount> m_channelSeen; // host time of each channel's newest row
    int m_segments = 0;

    // Time bookkeeping.
    int64_t m_hostOriginNs = 0;
    bool m_haveOrigin = false;
    double m_lastHost = 0.0;
    double m_lastDevice = 0.0;      // stitched, of the newest row
    double m_lastRawDevice = 0.0;   // raw device time (s) of the newest row that had one
    bool m_haveRawDevice = false;   // a device time was seen in the current segment
    double m_deviceOffset = 0.0;
    std::string m_clockSource;      // the frame type whose device time drives the device axis
    double m_clockSeenHost = 0.0;   // host time of its newest row
    double m_clockDevice = 0.0;     // stitched device time of its newest row
    uint64_t m_clockRow = 0;        // that row's index among all rows appended since clear()
    bool m_standing = false;        // rows after it stand at its time (restamped once it is overdue)
    int m_clockOwnerRows = 0, m_clockOtherRows = 0; // rows with a device time in this window
    std::string m_clockOther;       // the newest other type among them
    std::array<double, kPeriodWindow> m_steps{};
    int m_stepCount = 0;
    int m_stepNext = 0;
    double m_period = 0.0;
};

} // namespace imudesk::plot
