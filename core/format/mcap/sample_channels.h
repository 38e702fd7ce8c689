#pragma once
// One device's samples as MCAP channels (mcap_writer.h, ros2_messages.h), under a topic
// namespace of its own, /imu/<name>/...:
//   imu          sensor_msgs/msg/Imu            attitude, rates, accelerations
//   mag          sensor_msgs/msg/MagneticField
//   pressure     sensor_msgs/msg/FluidPressure
//   temperature  sensor_msgs/msg/Temperature
//   fix          sensor_msgs/msg/NavSatFix      GNSS position
//   status       JSON (jsonschema)              what no ROS message holds, with the keys of the
//                                               JSON Lines export: MAIN_STATUS, Euler angles,
//                                               the HEC495's fields, the three times
//   /tf          tf2_msgs/msg/TFMessage         the world frame to the device's frame
// A channel is added when the first sample that has its quantity arrives.
//
// Times: log_time is the sample's arrival, publish_time and header.stamp its common time (its
// arrival where it has none), both on the Unix epoch (epochOffsetNs added to the host clock's
// times). sequence: the device's time stamp (ms) where it has one, else a count per channel.
#include "format/mcap/mcap_writer.h"
#include "model/device_identity.h"
#include "model/sample.h"

#include <map>
#include <string>

namespace imudesk::format::mcap {

class SampleChannels {
public:
    struct Device {
        std::string name;    // the topic namespace's last part: a serial number or a name ([A-Za-z0-9_])
        std::string frameId; // the device's frame in header.frame_id and /tf
        model::WorldFrame worldFrame = model::WorldFrame::Enu;
        McapWriter::StringMap metadata; // on every channel of the device (product, serial, ...)
    };
    SampleChannels(McapWriter &writer, Device device);

    // A topic-safe name: letters, digits and '_' kept, anything else '_'; "device" when empty.
    static std::string topicName(const std::string &text);

    bool write(const model::Sample &s, int64_t epochOffsetNs);
    // Messages written per topic.
    const std::map<std::string, uint64_t> &counts() const { return m_counts; }

private:
    struct Channel {
        uint16_t id = 0;
        uint32_t sequence = 0;
    };
    Channel *channel(const std::string &suffix, const char *type, const char *definition);
    Channel *jsonChannel();
    bool put(Channel *c, const std::string &topic, const model::Sample &s, uint64_t logTime, uint64_t publishTime,
             const std::string &data);

    McapWriter &m_writer;
    Device m_device;
    std::string m_prefix;
    std::map<std::string, uint16_t> m_schemas; // by type name (shared by every device of the file)
    std::map<std::string, Channel> m_channels; // by topic
    std::map<std::string, uint64_t> m_counts;
};

} // namespace imudesk::format::mcap
