#include "charts/chart_settings.h"

#include <QSettings>
#include <QStringList>

#include <algorithm>

namespace imudesk::ui {

namespace {

QString key(const char *k)
{
    return QString::fromLatin1(k);
}

constexpr std::array<const char *, plot::kChannelCount> kChannelKeys = {
    "accX", "accY", "accZ", "gyrX", "gyrY", "gyrZ", "magX",  "magY",  "magZ",
    "roll", "pitch", "yaw", "quatW", "quatX", "quatY", "quatZ", "pressure", "temperature",
    "magRelX", "magRelY", "magRelZ", "magRoll"};

} // namespace

const char *ChartSettings::channelKey(plot::Channel channel)
{
    return kChannelKeys[size_t(channel)];
}

const char *ChartSettings::chartKey(ChartKind kind)
{
    static constexpr std::array<const char *, kChartKindCount> keys = {
        "accelerometer", "gyroscope", "magnetometer", "euler", "quaternion", "pressure", "temperature",
        "magneticRelative"};
    return keys[size_t(kind)];
}

bool ChartSettings::isWindowChoice(double seconds)
{
    return std::find(kWindowChoices.begin(), kWindowChoices.end(), seconds) != kWindowChoices.end();
}

void ChartSettings::load(QSettings &settings)
{
    *this = ChartSettings();
    for (int k = 0; k < kChartKindCount; ++k) {
        bool ok = false;
        const double s = settings.value(key(kWindowKeys[size_t(k)])).toDouble(&ok);
        windowSeconds[size_t(k)] = ok && isWindowChoice(s) ? s : kDefaultWindowSeconds;
    }
    const QString axis = settings.value(key(kTimeAxisKey)).toString();
    timeAxis = axis == QLatin1String("host") ? plot::TimeAxis::Host : plot::TimeAxis::Device;
    const QStringList hidden = settings.value(key(kHiddenChannelsKey)).toStringList();
    for (int c = 0; c < plot::kChannelCount; ++c)
        if (hidden.contains(QLatin1String(kChannelKeys[size_t(c)])))
            hiddenChannels |= plot::channelBit(plot::Channel(c));
    if (settings.contains(key(kHiddenChartsKey))) {
        const QStringList charts = settings.value(key(kHiddenChartsKey)).toStringList();
        hiddenCharts = 0;
        for (int k = 0; k < kChartKindCount; ++k)
            if (charts.contains(QLatin1String(chartKey(ChartKind(k)))))
                hiddenCharts |= 1u << k;
    }
}

void ChartSettings::save(QSettings &settings) const
{
    for (int k = 0; k < kChartKindCount; ++k)
        settings.setValue(key(kWindowKeys[size_t(k)]), windowSeconds[size_t(k)]);
    settings.setValue(key(kTimeAxisKey),
                      timeAxis == plot::TimeAxis::Host ? QStringLiteral("host") : QStringLiteral("device"));
    QStringList hidden;
    for (int c = 0; c < plot::kChannelCount; ++c)
        if (isHidden(plot::Channel(c)))
            hidden << QLatin1String(kChannelKeys[size_t(c)]);
    settings.setValue(key(kHiddenChannelsKey), hidden);
    QStringList charts;
    for (int k = 0; k < kChartKindCount; ++k)
        if (isChartHidden(ChartKind(k)))
            charts << QLatin1String(chartKey(ChartKind(k)));
    settings.setValue(key(kHiddenChartsKey), charts);
}

} // namespace imudesk::ui
