#pragma once
// Min/max decimation of one channel of a ChannelHistory for a chart W pixels wide.
//
// The window [t0, t1] is cut into W equal columns; every row inside the window that
// carries the channel falls into column floor((t - t0) / (t1 - t0) * W) (t1 itself
// into the last column). For each non-empty column the output holds, in time order,
// the column's first, minimum, maximum and last row (the earliest row wins a tie;
// rows that are the same are emitted once), so a spike of a single sample always
// survives, and the line enters and leaves each column where the data does.
//
// Breaks: when the first row of a column follows a device-clock gap or a device
// restart (ChannelHistory::kBreakFlags on that row or on any row since the previous
// row that carried the channel), a break marker (breakPoint(): x and y NaN, which
// Qt Charts draws as a gap in a QLineSeries) precedes the column. The column's
// first row is then dropped unless it is also its minimum or maximum: nothing
// connects to it, and min..max already covers it, so the drawing is the same and
// each column costs at most 4 points including the marker. Gaps narrower than a
// column, inside one column, are not visible at this zoom and are joined.
//
// Guarantees: at most 4 * W points; every point but the break markers is a stored
// (time, value) pair, x shifted by -xOffset; cost O(rows in the window) after two
// binary searches; the only allocation is growing `out` (cleared, then reserved to
// 4 * W when its capacity is smaller).
#include "channel_history.h"

#include <QList>
#include <QPointF>

#include <cmath>
#include <cstddef>
#include <limits>

namespace imudesk::plot {

class MinMaxDecimator {
public:
    static constexpr int kPointsPerColumn = 4;

    struct Result {
        size_t rows = 0;    // rows of the window that carry the channel
        size_t columns = 0; // non-empty columns
        size_t breaks = 0;  // break markers in the output
        double yMin = 0.0;  // range of the output's values (valid when rows > 0)
        double yMax = 0.0;
    };

    static QPointF breakPoint()
    {
        return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    }
    static bool isBreak(const QPointF &p) { return std::isnan(p.x()); }
    static size_t maxPoints(int widthPx) { return widthPx > 0 ? size_t(widthPx) * kPointsPerColumn : 0; }

    // Break lines at device-clock gaps and restarts (default on).
    void setBreakAtGaps(bool on) { m_breakAtGaps = on; }
    // Only the min and max of each column (in time order), at most 2 points per column plus
    // breaks: half the points to draw, spikes still kept. Default off (first, min, max, last).
    void setExtremaOnly(bool on) { m_extremaOnly = on; }
    bool extremaOnly() const { return m_extremaOnly; }
    bool breakAtGaps() const { return m_breakAtGaps; }

    // Replaces the content of `out` with the decimated points of `channel` in [t0, t1]
    // on `axis`; x = time - xOffset. Empty when widthPx < 1 or t1 <= t0.
    Result decimate(const ChannelHistory &history, Channel channel, TimeAxis axis, double t0, double t1,
                    int widthPx, QList<QPointF> &out, double xOffset = 0.0) const;

private:
    bool m_breakAtGaps = true;
    bool m_extremaOnly = false;
};

} // namespace imudesk::plot
