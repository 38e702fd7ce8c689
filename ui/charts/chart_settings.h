#pragma once
// What a ChartPanel remembers between runs: the time window of each chart, the axes
// the user hid and the time axis. The panel never opens QSettings; its owner loads and
// saves this struct (inside a QSettings group of its choosing, e.g. one per device).
#include "plot/channel_history.h"

#include <array>
#include <cstdint>

class QSettings;

namespace imudesk::ui {

// The charts of one device, in the panel's order.
// MagneticRelative: a compass's field without unit (the HEC495's), shown once a device sends it.
enum class ChartKind : int { Accelerometer, Gyroscope, Magnetometer, Euler, Quaternion, Pressure, Temperature, MagneticRelative };
inline constexpr int kChartKindCount = 8;

struct ChartSettings {
    // Bump the version in the keys when a value changes meaning; old keys are then ignored.
    static constexpr int kVersion = 1;
    static constexpr const char *kTimeAxisKey = "ui/v1/charts/timeAxis";         // "device" | "host"
    static constexpr const char *kHiddenChannelsKey = "ui/v1/charts/hiddenAxes"; // list of channelKey()
    // Window of each chart (s), one key per ChartKind, in enum order.
    static constexpr std::array<const char *, kChartKindCount> kWindowKeys = {
        "ui/v1/charts/accelerometer/windowSeconds", "ui/v1/charts/gyroscope/windowSeconds",
        "ui/v1/charts/magnetometer/windowSeconds",  "ui/v1/charts/euler/windowSeconds",
        "ui/v1/charts/quaternion/windowSeconds",    "ui/v1/charts/pressure/windowSeconds",
        "ui/v1/charts/temperature/windowSeconds",   "ui/v1/charts/magneticRelative/windowSeconds"};
    // The time windows the charts offer (s): 2 s ... 10 min.
    static constexpr std::array<double, 8> kWindowChoices = {2, 5, 10, 30, 60, 120, 300, 600};
    static constexpr double kDefaultWindowSeconds = 10;

    // Charts the user switched off (bit = 1 << ChartKind), saved as a list of chart names.
    static constexpr const char *kHiddenChartsKey = "ui/v1/charts/hiddenCharts";
    // By default four charts share the area; the others are a click away.
    static constexpr uint32_t kDefaultHiddenCharts =
        (1u << int(ChartKind::Quaternion)) | (1u << int(ChartKind::Pressure)) | (1u << int(ChartKind::Temperature));

    std::array<double, kChartKindCount> windowSeconds = {10, 10, 10, 10, 10, 10, 10, 10};
    plot::TimeAxis timeAxis = plot::TimeAxis::Device;
    uint32_t hiddenChannels = 0; // plot::channelBit() of each hidden axis
    uint32_t hiddenCharts = kDefaultHiddenCharts;
    bool isChartHidden(ChartKind kind) const { return (hiddenCharts >> int(kind)) & 1u; }

    double window(ChartKind kind) const { return windowSeconds[size_t(kind)]; }
    bool isHidden(plot::Channel channel) const { return (hiddenChannels & plot::channelBit(channel)) != 0; }

    // Values that are missing or not among the choices fall back to the defaults.
    void load(QSettings &settings);
    void save(QSettings &settings) const;

    // Stable names for the settings file ("accX", ..., "temperature").
    static const char *channelKey(plot::Channel channel);
    static const char *chartKey(ChartKind kind); // "accelerometer", ...
    static bool isWindowChoice(double seconds);

    friend bool operator==(const ChartSettings &, const ChartSettings &) = default;
};

} // namespace imudesk::ui
