#include "minmax_decimator.h"

#include <algorithm>
#include <limits>

namespace imudesk::plot {

namespace {

struct Item {
    double t;
    float v;
    size_t seq; // order of the row among the rows that carry the channel
};

} // namespace

MinMaxDecimator::Result MinMaxDecimator::decimate(const ChannelHistory &history, Channel channel, TimeAxis axis,
                                                  double t0, double t1, int widthPx, QList<QPointF> &out,
                                                  double xOffset) const
{
    out.clear();
    Result result;
    if (widthPx < 1 || !(t1 > t0) || !std::isfinite(t0) || !std::isfinite(t1))
        return result;
    const IndexRange rows = history.range(axis, t0, t1);
    if (rows.empty())
        return result;
    if (size_t(out.capacity()) < maxPoints(widthPx))
        out.reserve(qsizetype(maxPoints(widthPx)));

    const float *values = history.columnData(channel);
    if (!values)
        return result; // no row has carried the channel
    const double *times = history.timeData(axis);
    const uint32_t *flags = history.flagData();
    const uint32_t bit = channelBit(channel);
    const uint32_t breakMask = m_breakAtGaps ? ChannelHistory::kBreakFlags : 0u;
    const double scale = double(widthPx) / (t1 - t0);
    const int lastColumn = widthPx - 1;

    bool open = false;
    bool breakBefore = false;
    int column = -1;
    double columnStart = 0.0, columnEnd = 0.0;
    Item first{}, lo{}, hi{}, last{};
    uint32_t pending = 0;
    size_t seq = 0;
    double yMin = 0.0, yMax = 0.0;

    auto emit = [&](const Item &item) { out.append(QPointF(item.t - xOffset, double(item.v))); };
    auto flush = [&] {
        if (breakBefore) {
            out.append(breakPoint());
            ++result.breaks;
        }
        size_t lastSeq = ~size_t(0);
        auto add = [&](const Item &item) {
            if (item.seq != lastSeq) {
                emit(item);
                lastSeq = item.seq;
            }
        };
        if (!m_extremaOnly && (!breakBefore || first.seq == lo.seq || first.seq == hi.seq))
            add(first);
        if (lo.seq <= hi.seq) {
            add(lo);
            add(hi);
        } else {
            add(hi);
            add(lo);
        }
        if (!m_extremaOnly)
            add(last);
        if (result.columns == 0) {
            yMin = lo.v;
            yMax = hi.v;
        } else {
            yMin = std::min(yMin, double(lo.v));
            yMax = std::max(yMax, double(hi.v));
        }
        ++result.columns;
    };

    for (const auto &run : history.physicalRuns(rows.first, rows.last)) {
        for (size_t p = run.begin; p < run.end; ++p) {
            const uint32_t f = flags[p];
            pending |= f;
            if (!(f & bit))
                continue;
            const double t = times[p];
            const Item item{t, values[p], seq++};
            // Still in the open column: two comparisons instead of a division into columns
            // (a clock that went back opens a column again, as the formula would).
            if (open && t >= columnStart && t < columnEnd) {
                if (item.v < lo.v)
                    lo = item;
                if (item.v > hi.v)
                    hi = item;
                if (!m_extremaOnly)
                    last = item;
                pending = 0;
                continue;
            }
            const int c = std::min(int((t - t0) * scale), lastColumn);
            if (open && c == column) {
                if (item.v < lo.v)
                    lo = item;
                if (item.v > hi.v)
                    hi = item;
                last = item;
            } else {
                if (open)
                    flush();
                breakBefore = open && (pending & breakMask) != 0;
                open = true;
                column = c;
                first = lo = hi = last = item;
                columnStart = t;
                columnEnd = c >= lastColumn ? std::numeric_limits<double>::infinity() : t0 + double(c + 1) / scale;
            }
            pending = 0;
        }
    }
    if (open)
        flush();
    result.rows = seq;
    result.yMin = yMin;
    result.yMax = yMax;
    return result;
}

} // namespace imudesk::plot
