#pragma once
// The one catalogue of the chartable channels (plot::Channel): for each, the group it is drawn
// in (one chart per group), its axis letter, the Sample field that carries it and how to read
// it, its line colour and its name. The charts (ui/charts), the values table
// (models::LatestValuesModel) and the history (plot::ChannelHistory) all read it, so a name, a
// colour or a new channel is changed here once.
//
// Names are translated in the context "imudesk::plot::Channel" (QT_TRANSLATE_NOOP here;
// channelName() returns the translation for the running language).
#include "plot/channel_history.h"

#include <QString>

#include <cstdint>
#include <span>
#include <vector>

namespace imudesk::plot {

// The groups, in the order of the charts.
// MagneticRelative: a compass's field without unit (the HEC495's; the northward horizontal field is 1).
enum class ChannelGroup : uint8_t {
    Accelerometer,
    Gyroscope,
    Magnetometer,
    Euler,
    Quaternion,
    Pressure,
    Temperature,
    MagneticRelative
};
inline constexpr int kChannelGroupCount = 8;

struct ChannelInfo {
    Channel channel;
    ChannelGroup group;
    const char *axis;  // "X", "Y", "Z", "W"; empty for a quantity of its own (roll, pressure)
    const char *name;  // English source text: "Acceleration %1" (with the axis), "Roll"
    uint32_t field;    // the model::Field bit whose presence carries it
    uint32_t rgb;      // line colour, 0xRRGGBB: X/roll red, Y/pitch green, Z/yaw blue
    double (*read)(const model::Sample &);
};

// Every channel, in plot::Channel order.
std::span<const ChannelInfo> channelCatalog();
const ChannelInfo &channelInfo(Channel c);
// The channels of one group, in axis order.
std::vector<Channel> channelsOf(ChannelGroup group);
// "Acceleration X", "Roll", translated.
QString channelName(Channel c);

} // namespace imudesk::plot
