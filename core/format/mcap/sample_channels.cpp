#include "sample_channels.h"

#include "format/mcap/ros2_messages.h"
#include "format/sample_json.h"

namespace imudesk::format::mcap {

namespace {
// The JSON channel's schema: an object per sample; the keys are the JSON Lines export's
// (docs/FILE_FORMATS.md, "JSON Lines"), each present only when the sample has the quantity.
constexpr const char *kStatusSchema = R"({"title":"imudesk/Sample","description":"What of a sample no ROS message holds, with the keys of ImuDesk's JSON Lines export: main_status, the HEC495's and GNSS fields, system_time, host_time_ns, common_time_ns, common_uncertainty_ns.","type":"object"})";
} // namespace

SampleChannels::SampleChannels(ChannelSink &sink, Device device) : m_sink(sink), m_device(std::move(device))
{
    m_prefix = "/imu/" + topicName(m_device.name) + "/";
    m_world = m_device.worldFrame == model::WorldFrame::Nwu ? "nwu" : "enu";
}

std::string SampleChannels::topicName(const std::string &text)
{
    std::string out;
    for (char c : text)
        out.push_back((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ? c : '_');
    return out.empty() ? std::string("device") : out;
}

std::string SampleChannels::uniqueName(const std::string &name, const std::function<bool(const std::string &)> &taken)
{
    std::string unique = name;
    for (int n = 2; taken(unique); ++n)
        unique = name + "_" + std::to_string(n);
    return unique;
}

SampleChannels::Channel *SampleChannels::open(const std::string &topic, const std::string &schemaName,
                                              const char *schemaEncoding, const char *schemaData,
                                              const char *messageEncoding)
{
    const uint16_t schema = m_sink.addSchema(schemaName, schemaEncoding, schemaData);
    // /tf is the file's, not the device's: no device metadata, so every device shares one channel.
    const uint16_t id = schema ? m_sink.addChannel(schema, topic, messageEncoding,
                                                     topic == "/tf" ? ChannelSink::StringMap{} : m_device.metadata)
                               : 0;
    if (!id)
        return nullptr;
    return &(m_channels[topic] = Channel{id, 0, 0});
}

bool SampleChannels::put(Kind kind, const model::Sample &s, uint64_t logTime, uint64_t publishTime,
                         std::string_view data)
{
    Channel *&c = m_byKind[kind];
    if (!c) {
        static const struct {
            const char *suffix;
            const Ros2Type &(*type)();
        } kinds[] = {{"imu", imuType},           {"mag", magneticFieldType},   {"pressure", fluidPressureType},
                     {"temperature", temperatureType}, {"fix", navSatFixType}, {"/tf", tfMessageType},
                     {"euler", vector3StampedType}, {"status", nullptr}};
        const auto &k = kinds[kind];
        const std::string topic = kind == Tf ? std::string(k.suffix) : m_prefix + k.suffix;
        c = k.type ? open(topic, k.type().name, "ros2msg", k.type().definition, "cdr")
                   : open(topic, "imudesk/Sample", "jsonschema", kStatusSchema, "json");
        if (!c)
            return false;
    }
    const uint32_t sequence = s.has(model::FieldDeviceTime) ? uint32_t(int64_t(s.deviceTimeMs)) : c->sequence++;
    ++c->count;
    return m_sink.write(c->id, sequence, logTime, publishTime, data.data(), data.size());
}

std::map<std::string, uint64_t> SampleChannels::counts() const
{
    std::map<std::string, uint64_t> out;
    for (const auto &[topic, c] : m_channels)
        out[topic] = c.count;
    return out;
}

bool SampleChannels::write(const model::Sample &s, int64_t epochOffsetNs)
{
    using namespace model;
    const uint64_t logTime = uint64_t(s.hostTimeNs + epochOffsetNs);
    const uint64_t publishTime = uint64_t((s.commonTimeNs != 0 ? s.commonTimeNs : s.hostTimeNs) + epochOffsetNs);
    const Stamp stamp = Stamp::fromNs(publishTime);
    const std::string &frame = m_device.frameId;
    bool ok = true;
    if (s.fields & (FieldAcc | FieldGyr | FieldQuat))
        ok = ok && put(Imu, s, logTime, publishTime, encodeImu(m_cdr, s, stamp, frame));
    if (s.has(FieldMag))
        ok = ok && put(Mag, s, logTime, publishTime, encodeMagneticField(m_cdr, s, stamp, frame));
    if (s.has(FieldPressure))
        ok = ok && put(Pressure, s, logTime, publishTime, encodeFluidPressure(m_cdr, s, stamp, frame));
    if (s.has(FieldTemperature))
        ok = ok && put(Temperature, s, logTime, publishTime, encodeTemperature(m_cdr, s, stamp, frame));
    if (s.has(FieldPosition))
        ok = ok && put(Fix, s, logTime, publishTime, encodeNavSatFix(m_cdr, s, stamp, frame));
    // The 3D view's transform: 50 times a second is smooth, and a 1 kHz module's every sample
    // would double the file for nothing the view shows.
    if (s.has(FieldQuat) && (m_lastTf < 0 || s.hostTimeNs - m_lastTf >= kTfPeriodNs || s.hostTimeNs < m_lastTf)) {
        m_lastTf = s.hostTimeNs;
        ok = ok && put(Tf, s, logTime, publishTime, encodeTf(m_cdr, s, stamp, m_world, frame));
    }
    if (s.has(FieldEuler))
        ok = ok && put(Euler, s, logTime, publishTime, encodeEuler(m_cdr, s, stamp, frame));
    // The rest (what no ROS message holds), with the JSON Lines export's keys: at once when it
    // holds more than the status word and the device's time stamp, or the status word changed;
    // else ten times a second.
    model::Sample rest = s;
    rest.fields &= ~uint32_t(FieldAcc | FieldGyr | FieldMag | FieldQuat | FieldPressure | FieldTemperature
                             | FieldPosition | FieldEuler);
    const bool more = (rest.fields & ~uint32_t(FieldMainStatus | FieldDeviceTime)) != 0;
    const bool changed = s.has(FieldMainStatus) && (!m_haveStatus || s.mainStatus != m_lastStatus);
    if (more || changed || m_lastStatusNs < 0 || s.hostTimeNs - m_lastStatusNs >= kStatusPeriodNs
        || s.hostTimeNs < m_lastStatusNs) {
        m_lastStatusNs = s.hostTimeNs;
        if (s.has(FieldMainStatus)) {
            m_lastStatus = s.mainStatus;
            m_haveStatus = true;
        }
        ok = ok && put(Status, s, logTime, publishTime, sampleToJson(rest, m_device.worldFrame));
    }
    return ok;
}

} // namespace imudesk::format::mcap
