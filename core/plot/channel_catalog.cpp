#include "channel_catalog.h"

#include <QCoreApplication>

namespace imudesk::plot {

namespace {

constexpr uint32_t kRed = 0xd62728, kGreen = 0x2ca02c, kBlue = 0x1f77b4, kGrey = 0x7f7f7f, kPurple = 0x9467bd,
                   kOrange = 0xff7f0e;
constexpr const char *kContext = "imudesk::plot::Channel";

using G = ChannelGroup;
using S = model::Sample;

// clang-format off
constexpr ChannelInfo kCatalog[] = {
    {Channel::AccX, G::Accelerometer, "X", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Acceleration %1"), model::FieldAcc, kRed, [](const S &s) { return s.acc.x; }},
    {Channel::AccY, G::Accelerometer, "Y", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Acceleration %1"), model::FieldAcc, kGreen, [](const S &s) { return s.acc.y; }},
    {Channel::AccZ, G::Accelerometer, "Z", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Acceleration %1"), model::FieldAcc, kBlue, [](const S &s) { return s.acc.z; }},
    {Channel::GyrX, G::Gyroscope, "X", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Angular velocity %1"), model::FieldGyr, kRed, [](const S &s) { return s.gyr.x; }},
    {Channel::GyrY, G::Gyroscope, "Y", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Angular velocity %1"), model::FieldGyr, kGreen, [](const S &s) { return s.gyr.y; }},
    {Channel::GyrZ, G::Gyroscope, "Z", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Angular velocity %1"), model::FieldGyr, kBlue, [](const S &s) { return s.gyr.z; }},
    {Channel::MagX, G::Magnetometer, "X", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Magnetic field %1"), model::FieldMag, kRed, [](const S &s) { return s.mag.x; }},
    {Channel::MagY, G::Magnetometer, "Y", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Magnetic field %1"), model::FieldMag, kGreen, [](const S &s) { return s.mag.y; }},
    {Channel::MagZ, G::Magnetometer, "Z", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Magnetic field %1"), model::FieldMag, kBlue, [](const S &s) { return s.mag.z; }},
    {Channel::Roll, G::Euler, "", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Roll"), model::FieldEuler, kRed, [](const S &s) { return s.roll; }},
    {Channel::Pitch, G::Euler, "", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Pitch"), model::FieldEuler, kGreen, [](const S &s) { return s.pitch; }},
    {Channel::Yaw, G::Euler, "", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Yaw"), model::FieldEuler, kBlue, [](const S &s) { return s.yaw; }},
    {Channel::QuatW, G::Quaternion, "W", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Quaternion %1"), model::FieldQuat, kGrey, [](const S &s) { return s.quat.w; }},
    {Channel::QuatX, G::Quaternion, "X", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Quaternion %1"), model::FieldQuat, kRed, [](const S &s) { return s.quat.x; }},
    {Channel::QuatY, G::Quaternion, "Y", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Quaternion %1"), model::FieldQuat, kGreen, [](const S &s) { return s.quat.y; }},
    {Channel::QuatZ, G::Quaternion, "Z", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Quaternion %1"), model::FieldQuat, kBlue, [](const S &s) { return s.quat.z; }},
    {Channel::Pressure, G::Pressure, "", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Air pressure"), model::FieldPressure, kPurple, [](const S &s) { return s.pressurePa; }},
    {Channel::Temperature, G::Temperature, "", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Temperature"), model::FieldTemperature, kOrange, [](const S &s) { return s.temperatureC; }},
    {Channel::MagRelX, G::MagneticRelative, "X", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Relative magnetic field %1"), model::FieldMagRelative, kRed, [](const S &s) { return s.magRelative.x; }},
    {Channel::MagRelY, G::MagneticRelative, "Y", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Relative magnetic field %1"), model::FieldMagRelative, kGreen, [](const S &s) { return s.magRelative.y; }},
    {Channel::MagRelZ, G::MagneticRelative, "Z", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Relative magnetic field %1"), model::FieldMagRelative, kBlue, [](const S &s) { return s.magRelative.z; }},
    // An angle beside the Euler angles, on their chart (deg).
    {Channel::MagRoll, G::Euler, "", QT_TRANSLATE_NOOP("imudesk::plot::Channel", "Magnetic roll"), model::FieldMagRoll, kPurple, [](const S &s) { return s.magRollDeg; }},
};
// clang-format on

static_assert(std::size(kCatalog) == size_t(kChannelCount));

constexpr bool inChannelOrder()
{
    for (size_t i = 0; i < std::size(kCatalog); ++i)
        if (size_t(kCatalog[i].channel) != i)
            return false;
    return true;
}
static_assert(inChannelOrder(), "the catalogue lists the channels in plot::Channel order");

} // namespace

std::span<const ChannelInfo> channelCatalog()
{
    return kCatalog;
}

const ChannelInfo &channelInfo(Channel c)
{
    return kCatalog[size_t(c)];
}

std::vector<Channel> channelsOf(ChannelGroup group)
{
    std::vector<Channel> out;
    for (const ChannelInfo &i : kCatalog)
        if (i.group == group)
            out.push_back(i.channel);
    return out;
}

QString channelName(Channel c)
{
    const ChannelInfo &i = channelInfo(c);
    const QString name = QCoreApplication::translate(kContext, i.name);
    return *i.axis ? name.arg(QLatin1String(i.axis)) : name;
}

} // namespace imudesk::plot
