#include "channel_history.h"

#include "plot/channel_catalog.h"

#include <QtGlobal>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace imudesk::plot {

namespace {

constexpr float kNoValue = std::numeric_limits<float>::quiet_NaN();

} // namespace

uint32_t ChannelHistory::channelsOfField(uint32_t fields)
{
    uint32_t b = 0;
    for (const ChannelInfo &i : channelCatalog())
        if (fields & i.field)
            b |= channelBit(i.channel);
    return b;
}

ChannelHistory::ChannelHistory(double maxDurationS, size_t maxRows)
{
    m_maxDuration = kMaxDurationS;
    m_maxRows = kMaxRows;
    m_channelSeen.fill(-std::numeric_limits<double>::infinity());
    setLimits(maxDurationS, maxRows);
}

void ChannelHistory::setLimits(double maxDurationS, size_t maxRows)
{
    m_maxDuration = (maxDurationS > 0.0 && maxDurationS <= kMaxDurationS) ? maxDurationS : kMaxDurationS;
    m_maxRows = std::clamp<size_t>(maxRows, 1, kMaxRows);
    if (m_size > m_maxRows)
        dropFront(m_size - m_maxRows);
    if (m_size > 0) {
        const double oldest = newestTime(TimeAxis::Host) - m_maxDuration;
        dropFront(lowerBound(TimeAxis::Host, oldest));
    }
    if (m_capacity > m_maxRows)
        reserveRows(m_maxRows);
    ++m_revision;
}

void ChannelHistory::clear()
{
    m_head = 0;
    m_size = 0;
    m_totalAppended = 0;
    m_presentChannels = 0;
    m_channelSeen.fill(-std::numeric_limits<double>::infinity());
    m_segments = 0;
    m_hostOriginNs = 0;
    m_haveOrigin = false;
    m_lastHost = 0.0;
    m_lastDevice = 0.0;
    m_lastRawDevice = 0.0;
    m_haveRawDevice = false;
    m_deviceOffset = 0.0;
    m_clockSource.clear();
    m_clockSeenHost = 0.0;
    m_clockDevice = 0.0;
    m_clockRow = 0;
    m_standing = false;
    m_clockOwnerRows = m_clockOtherRows = 0;
    m_clockOther.clear();
    m_stepCount = 0;
    m_stepNext = 0;
    m_period = 0.0;
    ++m_revision;
    ++m_generation;
}

void ChannelHistory::append(const model::Sample &sample)
{
    appendOne(sample);
    ++m_revision;
}

void ChannelHistory::append(const std::vector<model::Sample> &batch)
{
    for (const auto &s : batch)
        appendOne(s);
    if (!batch.empty())
        ++m_revision;
}

void ChannelHistory::reserveRows(size_t rows)
{
    rows = std::max(rows, m_size);
    if (rows == m_capacity && m_head == 0)
        return;
    // One column at a time: the peak is the old storage plus one new column.
    auto move = [this, rows](auto &column) {
        std::remove_reference_t<decltype(column)> fresh(rows);
        for (size_t i = 0; i < m_size; ++i)
            fresh[i] = column[phys(i)];
        column.swap(fresh);
    };
    for (int c = 0; c < kChannelCount; ++c)
        if (m_allocated & channelBit(Channel(c)))
            move(m_values[size_t(c)]);
    move(m_host);
    move(m_device);
    move(m_flags);
    m_capacity = rows;
    m_head = 0;
}

void ChannelHistory::dropFront(size_t count)
{
    count = std::min(count, m_size);
    if (count == 0)
        return;
    m_head = phys(count);
    m_size -= count;
    if (m_size == 0)
        m_head = 0;
}

void ChannelHistory::updatePeriod(double step)
{
    m_steps[size_t(m_stepNext)] = step;
    m_stepNext = (m_stepNext + 1) % kPeriodWindow;
    m_stepCount = std::min(m_stepCount + 1, kPeriodWindow);
    std::array<double, kPeriodWindow> sorted;
    std::copy_n(m_steps.begin(), m_stepCount, sorted.begin());
    auto mid = sorted.begin() + m_stepCount / 2;
    std::nth_element(sorted.begin(), mid, sorted.begin() + m_stepCount);
    m_period = *mid;
}

void ChannelHistory::appendOne(const model::Sample &s)
{
    // Host time, relative to the first sample, never decreasing: the sampling instant on the
    // host's clock (the common time, core/clock) where the sample has one, else its arrival.
    const int64_t hostNs = s.commonTimeNs != 0 ? s.commonTimeNs : s.hostTimeNs;
    if (!m_haveOrigin) {
        m_hostOriginNs = hostNs;
        m_haveOrigin = true;
    }
    double host = double(hostNs - m_hostOriginNs) / 1e9;
    const bool first = m_totalAppended == 0;
    if (!first && host < m_lastHost)
        host = m_lastHost;
    const double hostStep = first ? 0.0 : host - m_lastHost;

    // Device time, stitched across backward jumps, from one frame type's clock: two types may
    // count on different clocks (after PPS alignment HI91 counts the UTC day, HI83 still the
    // time since power-on), and alternating between them would stitch a jump at every row.
    // Another type's clock takes over when the owner has been silent for kClockHandOverS.
    uint32_t f = 0;
    double device = 0.0;
    bool ownClock = s.has(model::FieldDeviceTime) && std::isfinite(s.deviceTimeMs);
    if (ownClock) {
        // The busiest type carries the axis: over each kClockWindow rows with a device time,
        // another type that brought more than twice the owner's rows takes over.
        if (!m_clockSource.empty()) {
            if (s.source == m_clockSource) {
                ++m_clockOwnerRows;
            } else {
                ++m_clockOtherRows;
                m_clockOther = s.source;
            }
            if (m_clockOwnerRows + m_clockOtherRows >= kClockWindow) {
                if (m_clockOtherRows > 2 * m_clockOwnerRows && m_clockOther != m_clockSource) {
                    m_clockSource = m_clockOther;
                    m_haveRawDevice = false; // a new segment starts on the new clock
                }
                m_clockOwnerRows = m_clockOtherRows = 0;
            }
        }
        if (m_clockSource.empty()) {
            m_clockSource = s.source;
        } else if (s.source != m_clockSource && host - m_clockSeenHost > kClockHandOverS) {
            m_clockSource = s.source;
            m_haveRawDevice = false;
            m_clockOwnerRows = m_clockOtherRows = 0;
        }
        ownClock = s.source == m_clockSource;
    }
    if (ownClock) {
        f |= FlagDeviceTime;
        const double raw = s.deviceTimeMs / 1e3;
        if (first) {
            m_deviceOffset = 0.0;
            device = raw;
            m_segments = 1;
        } else if (!m_haveRawDevice || raw < m_lastRawDevice) {
            // The first device time after host-based rows, or the device clock went back.
            const double step = hostStep > 0.0 ? hostStep : m_period;
            device = m_lastDevice + step;
            m_deviceOffset = device - raw;
            f |= FlagSegmentStart;
            ++m_segments;
        } else {
            const double step = raw - m_lastRawDevice;
            device = raw + m_deviceOffset;
            if (m_period > 0.0 && step > kGapPeriods * m_period)
                f |= FlagGap;
            if (step > 0.0)
                updatePeriod(step);
        }
        m_lastRawDevice = raw;
        m_haveRawDevice = true;
        // The rows that stood at the clock's previous time since (another frame type between
        // two of its rows) go where their host time puts them, before this row.
        restampStanding(device);
        m_clockSeenHost = host;
    } else if (m_haveRawDevice && !(m_period > 0.0 && host - m_clockSeenHost > kOverduePeriods * m_period)
               && host - m_clockSeenHost <= kClockHandOverS) {
        // Between two rows of the clock (another frame type interleaved): at the clock's time,
        // which keeps the device axis non-decreasing.
        device = m_lastDevice;
        m_standing = true;
    } else if (m_haveRawDevice) {
        // The clock is overdue while other rows go on (an HEC495 streams angles without a time
        // after its polled records): the host clock carries the axis on from the clock's last
        // row, so the charts keep moving, and the rows that stood at its time move with it.
        // A device time that comes back within kClockHandOverS continues its segment; after
        // that, it starts a new one.
        restampStanding();
        device = m_clockDevice + (host - m_clockSeenHost);
        if (host - m_clockSeenHost > kClockHandOverS)
            m_haveRawDevice = false;
    } else {
        // No device clock yet, or it was handed over to the host clock: the axis advances by
        // the host time.
        device = first ? host : m_lastDevice + hostStep;
        if (first)
            m_segments = 1;
    }
    if (!first && device < m_lastDevice) // rounding in raw + offset
        device = m_lastDevice;

    // Make room: by count, then by storage.
    if (m_size == m_maxRows)
        dropFront(1);
    if (m_size == m_capacity)
        reserveRows(std::min(m_maxRows, std::max(kInitialRows, m_capacity * 2)));

    const size_t p = phys(m_size);
    const uint32_t want = channelsOfField(s.fields);
    // A channel's first sample: its column, no value in the rows before.
    for (uint32_t fresh = want & ~m_allocated; fresh != 0; fresh &= fresh - 1) {
        m_values[size_t(std::countr_zero(fresh))].assign(m_capacity, kNoValue);
        m_allocated |= fresh & -fresh;
    }
    auto put = [&](Channel c, double v) {
        if (!(m_allocated & channelBit(c)))
            return; // never carried: no column, has() false
        const bool ok = (want & channelBit(c)) && std::isfinite(v);
        m_values[size_t(c)][p] = ok ? float(v) : kNoValue;
        if (ok)
            f |= channelBit(c);
    };
    for (const ChannelInfo &i : channelCatalog())
        put(i.channel, i.read(s));
    m_host[p] = host;
    m_device[p] = device;
    m_flags[p] = f;
    ++m_size;
    ++m_totalAppended;
    m_presentChannels |= f & kChannelMask;
    for (uint32_t bits = f & kChannelMask; bits; bits &= bits - 1)
        m_channelSeen[size_t(std::countr_zero(bits))] = host;
    m_lastHost = host;
    m_lastDevice = device;
    if (f & FlagDeviceTime) {
        m_clockDevice = device;
        m_clockRow = m_totalAppended - 1;
    }

    // Bounded by duration (host clock): drop what fell out of the window.
    const double oldest = host - m_maxDuration;
    while (m_size > 1 && m_host[m_head] < oldest)
        dropFront(1);
}

void ChannelHistory::restampStanding(double upTo)
{
    if (!m_standing)
        return;
    m_standing = false;
    if (m_totalAppended == 0)
        return;
    // Row indices among the rows kept: the oldest kept row is m_totalAppended - m_size.
    const uint64_t oldest = m_totalAppended - m_size;
    const uint64_t from = std::max(m_clockRow + 1, oldest);
    for (uint64_t r = from; r < m_totalAppended; ++r) {
        const size_t p = phys(size_t(r - oldest));
        if (m_flags[p] & FlagDeviceTime)
            continue;
        m_device[p] = std::max(m_device[p], std::min(upTo, m_clockDevice + (m_host[p] - m_clockSeenHost)));
    }
    if (m_size > 0)
        m_lastDevice = m_device[phys(m_size - 1)];
}

double ChannelHistory::time(TimeAxis axis, size_t row) const
{
    Q_ASSERT(row < m_size);
    return axis == TimeAxis::Host ? m_host[phys(row)] : m_device[phys(row)];
}

size_t ChannelHistory::lowerBound(TimeAxis axis, double t) const
{
    const double *column = timeData(axis);
    size_t lo = 0, hi = m_size;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (column[phys(mid)] < t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

size_t ChannelHistory::upperBound(TimeAxis axis, double t) const
{
    const double *column = timeData(axis);
    size_t lo = 0, hi = m_size;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (column[phys(mid)] <= t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

IndexRange ChannelHistory::range(TimeAxis axis, double t0, double t1) const
{
    if (!(t0 <= t1))
        return {};
    const size_t first = lowerBound(axis, t0);
    return {first, std::max(first, upperBound(axis, t1))};
}

long long ChannelHistory::nearestRow(TimeAxis axis, double t, Channel channel, size_t maxScan) const
{
    if (m_size == 0)
        return -1;
    const size_t at = lowerBound(axis, t);
    long long best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (size_t i = at, n = 0; i < m_size && n < maxScan; ++i, ++n) {
        if (has(channel, i)) {
            best = (long long)i;
            bestDistance = time(axis, i) - t;
            break;
        }
    }
    for (size_t i = at, n = 0; i > 0 && n < maxScan; --i, ++n) {
        if (has(channel, i - 1)) {
            if (t - time(axis, i - 1) <= bestDistance)
                best = (long long)(i - 1);
            break;
        }
    }
    return best;
}

std::array<ChannelHistory::Run, 2> ChannelHistory::physicalRuns(size_t first, size_t last) const
{
    last = std::min(last, m_size);
    if (first >= last)
        return {};
    const size_t begin = phys(first);
    const size_t count = last - first;
    if (begin + count <= m_capacity)
        return {Run{begin, begin + count}, Run{}};
    return {Run{begin, m_capacity}, Run{0, begin + count - m_capacity}};
}

} // namespace imudesk::plot
