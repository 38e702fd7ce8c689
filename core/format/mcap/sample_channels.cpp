#include "sample_channels.h"

#include "format/mcap/ros2_messages.h"
#include "format/sample_json.h"

namespace imudesk::format::mcap {

namespace {
// The JSON channel's schema: an object per sample; the keys are the JSON Lines export's
// (README, "JSON Lines"), each present only when the sample has the quantity.
constexpr const char *kStatusSchema = R"({"title":"imudesk/Sample","description":"What of a sample no ROS message holds, with the keys of ImuDesk's JSON Lines export: main_status, Euler angles (deg), the HEC495's fields, system_time, host_time_ns, common_time_ns, common_uncertainty_ns.","type":"object"})";
} // namespace

SampleChannels::SampleChannels(McapWriter &writer, Device device) : m_writer(writer), m_device(std::move(device))
{
    m_prefix = "/imu/" + topicName(m_device.name) + "/";
}

std::string SampleChannels::topicName(const std::string &text)
{
    std::string out;
    for (char c : text)
        out.push_back((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ? c : '_');
    return out.empty() ? std::string("device") : out;
}

SampleChannels::Channel *SampleChannels::channel(const std::string &topic, const char *type, const char *definition)
{
    auto it = m_channels.find(topic);
    if (it != m_channels.end())
        return &it->second;
    const uint16_t schema = m_writer.addSchema(type, "ros2msg", definition);
    // /tf is the file's, not the device's: no device metadata, so every device shares one channel.
    const uint16_t id = schema ? m_writer.addChannel(schema, topic, "cdr", topic == "/tf" ? McapWriter::StringMap{}
                                                                                           : m_device.metadata)
                               : 0;
    if (!id)
        return nullptr;
    return &(m_channels[topic] = Channel{id, 0});
}

SampleChannels::Channel *SampleChannels::jsonChannel()
{
    const std::string topic = m_prefix + "status";
    auto it = m_channels.find(topic);
    if (it != m_channels.end())
        return &it->second;
    const uint16_t schema = m_writer.addSchema("imudesk/Sample", "jsonschema", kStatusSchema);
    const uint16_t id = schema ? m_writer.addChannel(schema, topic, "json", m_device.metadata) : 0;
    if (!id)
        return nullptr;
    return &(m_channels[topic] = Channel{id, 0});
}

bool SampleChannels::put(Channel *c, const std::string &topic, const model::Sample &s, uint64_t logTime,
                         uint64_t publishTime, const std::string &data)
{
    if (!c)
        return false;
    const uint32_t sequence = s.has(model::FieldDeviceTime) ? uint32_t(int64_t(s.deviceTimeMs)) : c->sequence++;
    ++m_counts[topic];
    return m_writer.write(c->id, sequence, logTime, publishTime, data.data(), data.size());
}

bool SampleChannels::write(const model::Sample &s, int64_t epochOffsetNs)
{
    using namespace model;
    const uint64_t logTime = uint64_t(s.hostTimeNs + epochOffsetNs);
    const uint64_t publishTime = uint64_t((s.commonTimeNs != 0 ? s.commonTimeNs : s.hostTimeNs) + epochOffsetNs);
    const Stamp stamp = Stamp::fromNs(publishTime);
    const std::string &frame = m_device.frameId;
    bool ok = true;
    if (s.fields & (FieldAcc | FieldGyr | FieldQuat)) {
        const std::string topic = m_prefix + "imu";
        ok = ok && put(channel(topic, imuType().name, imuType().definition), topic, s, logTime, publishTime,
                       encodeImu(s, stamp, frame));
    }
    if (s.has(FieldMag)) {
        const std::string topic = m_prefix + "mag";
        ok = ok && put(channel(topic, magneticFieldType().name, magneticFieldType().definition), topic, s, logTime,
                       publishTime, encodeMagneticField(s, stamp, frame));
    }
    if (s.has(FieldPressure)) {
        const std::string topic = m_prefix + "pressure";
        ok = ok && put(channel(topic, fluidPressureType().name, fluidPressureType().definition), topic, s, logTime,
                       publishTime, encodeFluidPressure(s, stamp, frame));
    }
    if (s.has(FieldTemperature)) {
        const std::string topic = m_prefix + "temperature";
        ok = ok && put(channel(topic, temperatureType().name, temperatureType().definition), topic, s, logTime,
                       publishTime, encodeTemperature(s, stamp, frame));
    }
    if (s.has(FieldPosition)) {
        const std::string topic = m_prefix + "fix";
        ok = ok && put(channel(topic, navSatFixType().name, navSatFixType().definition), topic, s, logTime,
                       publishTime, encodeNavSatFix(s, stamp, frame));
    }
    if (s.has(FieldQuat)) {
        const std::string world = m_device.worldFrame == WorldFrame::Nwu ? "nwu" : "enu";
        ok = ok && put(channel("/tf", tfMessageType().name, tfMessageType().definition), "/tf", s, logTime,
                       publishTime, encodeTf(s, stamp, world, frame));
    }
    // The rest (what no ROS message holds): the same keys as the JSON Lines export, without the
    // quantities the messages above carry.
    model::Sample rest = s;
    rest.fields &= ~uint32_t(FieldAcc | FieldGyr | FieldMag | FieldQuat | FieldPressure | FieldTemperature | FieldPosition);
    const std::string topic = m_prefix + "status";
    ok = ok && put(jsonChannel(), topic, s, logTime, publishTime, sampleToJson(rest, m_device.worldFrame));
    return ok;
}

} // namespace imudesk::format::mcap
