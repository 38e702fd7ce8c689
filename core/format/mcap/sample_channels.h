#pragma once
// One device's samples as MCAP channels (ros2_messages.h) of a ChannelSink (an MCAP file, the
// live bridge), under a topic namespace of its own, /imu/<name>/...:
//   imu          sensor_msgs/msg/Imu            attitude, rates, accelerations
//   mag          sensor_msgs/msg/MagneticField
//   pressure     sensor_msgs/msg/FluidPressure  (a file's: when it changes, Device::onChangeOnly)
//   temperature  sensor_msgs/msg/Temperature    (likewise)
//   fix          sensor_msgs/msg/NavSatFix      GNSS position
//   euler        geometry_msgs/msg/Vector3Stamped  roll, pitch, yaw in deg (x, y, z)
//   status       JSON (jsonschema)              what no ROS message holds, with the keys of the
//                                               JSON Lines export: MAIN_STATUS, the HEC495's and
//                                               GNSS fields, the three times; at once when the
//                                               status word changes or the sample has more, else
//                                               ten times a second
//   /tf          tf2_msgs/msg/TFMessage         the world frame to the device's frame, at most
//                                               50 times a second
// A channel is added when the first sample that has its quantity arrives.
//
// Times: log_time is the sample's arrival, publish_time and header.stamp its common time (its
// arrival where it has none), both on the Unix epoch (epochOffsetNs added to the host clock's
// times). sequence: the device's time stamp (ms) where it has one, else a count per channel.
#include "format/mcap/channel_sink.h"
#include "format/mcap/ros2_messages.h"
#include "model/device_identity.h"
#include "model/sample.h"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace imudesk::format::mcap {

class SampleChannels {
public:
    struct Device {
        std::string name;    // the topic namespace's last part: a serial number or a name ([A-Za-z0-9_])
        std::string frameId; // the device's frame in header.frame_id and /tf
        model::WorldFrame worldFrame = model::WorldFrame::Enu;
        ChannelSink::StringMap metadata; // on every channel of the device (product, serial, ...)
        // A file's layout (issue 54, point 7): pressure and temperature written when their
        // value changes (and first), never dropped; a live client (the bridge) gets each with
        // every sample.
        bool onChangeOnly = false;
    };
    SampleChannels(ChannelSink &sink, Device device);
    const Device &device() const { return m_device; }

    // A topic-safe name: letters, digits and '_' kept, anything else '_'; "device" when empty.
    static std::string topicName(const std::string &text);
    // A namespace no other device of the file (or the bridge) has: name, else name_2, name_3, ...
    static std::string uniqueName(const std::string &name, const std::function<bool(const std::string &)> &taken);

    bool write(const model::Sample &s, int64_t epochOffsetNs);
    // Messages written per topic.
    std::map<std::string, uint64_t> counts() const;

private:
    struct Channel {
        uint16_t id = 0;
        uint32_t sequence = 0;
        uint64_t count = 0;
    };
    enum Kind { Imu, Mag, Pressure, Temperature, Fix, Tf, Euler, Status, KindCount };
    // The channel (and its schema) added to the file when the first sample that has it comes.
    Channel *open(const std::string &topic, const std::string &schemaName, const char *schemaEncoding,
                  const char *schemaData, const char *messageEncoding);
    Channel *channel(Kind kind);
    // The message that encode(CdrWriter &) writes, in place where the sink allows (an MCAP chunk).
    template <typename Encode>
    bool put(Kind kind, const model::Sample &s, uint64_t logTime, uint64_t publishTime, Encode &&encode);
    bool putJson(Kind kind, const model::Sample &s, uint64_t logTime, uint64_t publishTime, const std::string &json);
    uint32_t sequenceOf(Channel &c, const model::Sample &s);
    static constexpr int64_t kTfPeriodNs = 20'000'000;
    static constexpr int64_t kStatusPeriodNs = 100'000'000;

    ChannelSink &m_sink;
    Device m_device;
    std::string m_prefix;
    std::map<std::string, Channel> m_channels; // by topic (a map: its elements stay where they are)
    Channel *m_byKind[KindCount] = {};
    std::string m_world;
    CdrWriter m_cdr; // reused by every message
    int64_t m_lastTf = -1;
    int64_t m_lastStatusNs = -1;
    std::optional<double> m_lastPressure, m_lastTemperature; // the last written (onChangeOnly)
    uint16_t m_lastStatus = 0;
    bool m_haveStatus = false;
};

} // namespace imudesk::format::mcap
