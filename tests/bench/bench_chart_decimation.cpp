// bench_chart_decimation: what one chart refresh costs with min/max decimation
// against the naive way, for every time window a chart offers.
//
// A ChannelHistory is filled with 10 min of 1 kHz samples (600 000 rows, the full
// size). For each window (2 s ... 10 min), one chart's three axes (acc x/y/z) are
// brought into QLineSeries for a 1000 px plot:
//   decimated      MinMaxDecimator -> QLineSeries::replace()   (what ChartView does)
//   naive append   QLineSeries::clear(), then append() every point of the window
//   naive replace  every point of the window into a QList, then replace()
// Each is timed best of N in the same run. With --render (default on for three
// windows), the chart is also painted offscreen with either series, which is where
// the naive way really hurts.
//
//   bench_chart_decimation [--runs N] [--width PX] [--no-render]
//
// Exit status: 0 when every decimated series kept within 4 points per pixel column,
// 1 otherwise, 2 on bad arguments.
#include "plot/channel_history.h"
#include "plot/minmax_decimator.h"

#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QLineSeries>
#include <QPixmap>
#include <QValueAxis>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <vector>

namespace {

using imudesk::model::Sample;
using imudesk::plot::Channel;
using imudesk::plot::ChannelHistory;
using imudesk::plot::IndexRange;
using imudesk::plot::MinMaxDecimator;
using imudesk::plot::TimeAxis;
namespace model = imudesk::model;

using Clock = std::chrono::steady_clock;

constexpr std::array<double, 8> kWindows = {2, 5, 10, 30, 60, 120, 300, 600};
constexpr std::array<Channel, 3> kAxes = {Channel::AccX, Channel::AccY, Channel::AccZ};

double bestOfMs(int runs, const std::function<void()> &work)
{
    double best = 1e300;
    for (int r = 0; r < runs; ++r) {
        const auto t0 = Clock::now();
        work();
        best = std::min(best, std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
    return best;
}

void fill(ChannelHistory &h)
{
    std::vector<Sample> batch;
    batch.reserve(1000);
    uint64_t noise = 12345;
    for (int i = 0; i < 600000; ++i) {
        noise = noise * 6364136223846793005ull + 1442695040888963407ull;
        const double n = double(noise >> 40) / double(1u << 24) - 0.5;
        const double t = i / 1000.0;
        Sample s;
        s.fields = model::FieldAcc | model::FieldGyr | model::FieldMag | model::FieldEuler | model::FieldQuat |
                   model::FieldPressure | model::FieldTemperature | model::FieldDeviceTime;
        s.hostTimeNs = int64_t(i / 5) * 5'000'000; // arrival in 5 ms batches
        s.deviceTimeMs = 100000.0 + i;
        s.acc = {std::sin(6.283 * t) + 0.01 * n, 0.3 * std::cos(0.7 * t) + 0.01 * n, 1.0 + 0.002 * n};
        s.gyr = {10.0 * n, -5.0 * n, 0.1};
        s.mag = {20.0, -5.0, 40.0};
        s.yaw = std::fmod(10.0 * t, 360.0);
        s.pressurePa = 101325.0 + n;
        s.temperatureC = 25.0 + 0.001 * t;
        batch.push_back(s);
        if (batch.size() == 1000) {
            h.append(batch);
            batch.clear();
        }
    }
}

QList<QPointF> allPoints(const ChannelHistory &h, Channel c, IndexRange r)
{
    QList<QPointF> points;
    points.reserve(qsizetype(r.size()));
    for (size_t i = r.first; i < r.last; ++i)
        if (h.has(c, i))
            points.append(QPointF(h.deviceTime(i), double(h.value(c, i))));
    return points;
}

} // namespace

int main(int argc, char **argv)
{
    int runs = 5;
    int width = 1000;
    bool render = true;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--runs") && i + 1 < argc) {
            runs = std::atoi(argv[++i]);
        } else if (!std::strcmp(argv[i], "--width") && i + 1 < argc) {
            width = std::atoi(argv[++i]);
        } else if (!std::strcmp(argv[i], "--no-render")) {
            render = false;
        } else {
            std::fprintf(stderr, "usage: %s [--runs N] [--width PX] [--no-render]\n", argv[0]);
            return 2;
        }
    }
    if (runs < 1 || width < 10) {
        std::fprintf(stderr, "bad --runs or --width\n");
        return 2;
    }
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);

    ChannelHistory history;
    const double fillMs = bestOfMs(1, [&] { fill(history); });
    std::printf("bench_chart_decimation: %zu rows (10 min at 1 kHz) in %.0f ms, %.1f MB of columns (%zu B/row)\n",
                history.size(), fillMs, double(history.memoryBytes()) / 1e6, ChannelHistory::kBytesPerRow);
    std::printf("one chart = %zu axes, %d px, best of %d; times per refresh of the chart\n\n", kAxes.size(), width,
                runs);
    std::printf("%-7s %10s %9s %12s %13s %8s %14s %8s\n", "window", "rows/axis", "pts/axis", "decimated ms",
                "naive app. ms", "ratio", "naive repl. ms", "ratio");

    MinMaxDecimator decimator;
    std::array<QList<QPointF>, kAxes.size()> buffers;
    std::array<QLineSeries *, kAxes.size()> series{};
    for (auto &s : series)
        s = new QLineSeries(&app);
    bool ok = true;
    const double t1 = history.newestTime(TimeAxis::Device);

    for (double window : kWindows) {
        const double t0 = t1 - window;
        const IndexRange rows = history.range(TimeAxis::Device, t0, t1);
        size_t points = 0;
        const double decimatedMs = bestOfMs(runs, [&] {
            points = 0;
            for (size_t a = 0; a < kAxes.size(); ++a) {
                decimator.decimate(history, kAxes[a], TimeAxis::Device, t0, t1, width, buffers[a]);
                series[a]->replace(buffers[a]);
                points = std::max(points, size_t(buffers[a].size()));
            }
        });
        if (points > MinMaxDecimator::maxPoints(width))
            ok = false;
        const double appendMs = bestOfMs(std::min(runs, 3), [&] {
            for (size_t a = 0; a < kAxes.size(); ++a) {
                series[a]->clear();
                for (size_t i = rows.first; i < rows.last; ++i)
                    if (history.has(kAxes[a], i))
                        series[a]->append(history.deviceTime(i), double(history.value(kAxes[a], i)));
            }
        });
        const double replaceMs = bestOfMs(std::min(runs, 3), [&] {
            for (size_t a = 0; a < kAxes.size(); ++a)
                series[a]->replace(allPoints(history, kAxes[a], rows));
        });
        std::printf("%-7s %10zu %9zu %12.3f %13.3f %7.1fx %14.3f %7.1fx\n",
                    window >= 60 ? qPrintable(QStringLiteral("%1 min").arg(window / 60))
                                 : qPrintable(QStringLiteral("%1 s").arg(window)),
                    rows.size(), points, decimatedMs, appendMs, appendMs / decimatedMs, replaceMs,
                    replaceMs / decimatedMs);
    }

    if (render) {
        // Paint a chart offscreen with the decimated or the full series.
        QChart *chart = new QChart;
        chart->setAnimationOptions(QChart::NoAnimation);
        chart->legend()->hide();
        auto *axisX = new QValueAxis;
        auto *axisY = new QValueAxis;
        chart->addAxis(axisX, Qt::AlignBottom);
        chart->addAxis(axisY, Qt::AlignLeft);
        std::array<QLineSeries *, kAxes.size()> shown{};
        for (auto &s : shown) {
            s = new QLineSeries;
            chart->addSeries(s);
            s->attachAxis(axisX);
            s->attachAxis(axisY);
        }
        QChartView view(chart);
        view.resize(width + 80, 300);
        view.show();
        QCoreApplication::processEvents();
        std::printf("\npainting the chart offscreen (%d px plot), best of %d:\n", int(chart->plotArea().width()),
                    std::min(runs, 3));
        std::printf("%-7s %16s %14s %8s\n", "window", "decimated ms", "all points ms", "ratio");
        for (double window : {10.0, 60.0, 600.0}) {
            const double t0 = t1 - window;
            const IndexRange rows = history.range(TimeAxis::Device, t0, t1);
            axisX->setRange(t0, t1);
            axisY->setRange(-1.5, 1.5);
            auto paint = [&](bool decimated) {
                return bestOfMs(std::min(runs, 3), [&] {
                    for (size_t a = 0; a < kAxes.size(); ++a) {
                        if (decimated) {
                            decimator.decimate(history, kAxes[a], TimeAxis::Device, t0, t1,
                                               int(chart->plotArea().width()), buffers[a]);
                            shown[a]->replace(buffers[a]);
                        } else {
                            shown[a]->replace(allPoints(history, kAxes[a], rows));
                        }
                    }
                    const QPixmap pixmap = view.grab();
                    if (pixmap.isNull())
                        std::abort();
                });
            };
            const double dec = paint(true);
            const double all = paint(false);
            std::printf("%-7s %16.2f %14.2f %7.1fx\n",
                        window >= 60 ? qPrintable(QStringLiteral("%1 min").arg(window / 60))
                                     : qPrintable(QStringLiteral("%1 s").arg(window)),
                        dec, all, all / dec);
        }
    }
    std::printf("\n%s\n", ok ? "OK: every decimated series within 4 points per pixel column"
                             : "FAIL: a decimated series exceeded 4 points per pixel column");
    return ok ? 0 : 1;
}
