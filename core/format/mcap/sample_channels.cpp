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

SampleChannels::Channel *SampleChannels::channel(Kind kind)
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
    }
    return c;
}

uint32_t SampleChannels::sequenceOf(Channel &c, const model::Sample &s)
{
    ++c.count;
    return s.has(model::FieldDeviceTime) ? uint32_t(int64_t(s.deviceTimeMs)) : c.sequence++;
}

template <typename Encode>
bool SampleChannels::put(Kind kind, const model::Sample &s, uint64_t logTime, uint64_t publishTime, Encode &&encode)
{
    Channel *c = channel(kind);
    if (!c)
        return false;
    const uint32_t sequence = sequenceOf(*c, s);
    if (std::string *out = m_sink.beginMessage(c->id, sequence, logTime, publishTime)) {
        m_cdr.into(*out);
        encode(m_cdr);
        m_cdr.reset();
        return m_sink.endMessage();
    }
    m_cdr.reset();
    const std::string_view data = encode(m_cdr);
    return m_sink.write(c->id, sequence, logTime, publishTime, data.data(), data.size());
}

bool SampleChannels::putJson(Kind kind, const model::Sample &s, uint64_t logTime, uint64_t publishTime,
                             const std::string &json)
{
    Channel *c = channel(kind);
    if (!c)
        return false;
    const uint32_t sequence = sequenceOf(*c, s);
    return m_sink.write(c->id, sequence, logTime, publishTime, json.data(), json.size());
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
        ok = ok && put(Imu, s, logTime, publishTime, [&](CdrWriter &w) { return encodeImu(w, s, stamp, frame); });
    if (s.has(FieldMag))
        ok = ok && put(Mag, s, logTime, publishTime, [&](CdrWriter &w) { return encodeMagneticField(w, s, stamp, frame); });
    // A file's pressure and temperature when they change: a module's temperature moves a degree in
    // minutes, and a message each sample would be a third of the file. A change is never dropped.
    const auto due = [this](std::optional<double> &last, double now) { // and noted as written
        const bool write = !m_device.onChangeOnly || last != now;
        last = now;
        return write;
    };
    if (s.has(FieldPressure) && due(m_lastPressure, s.pressurePa))
        ok = ok && put(Pressure, s, logTime, publishTime, [&](CdrWriter &w) { return encodeFluidPressure(w, s, stamp, frame); });
    if (s.has(FieldTemperature) && due(m_lastTemperature, s.temperatureC))
        ok = ok && put(Temperature, s, logTime, publishTime, [&](CdrWriter &w) { return encodeTemperature(w, s, stamp, frame); });
    if (s.has(FieldPosition))
        ok = ok && put(Fix, s, logTime, publishTime, [&](CdrWriter &w) { return encodeNavSatFix(w, s, stamp, frame); });
    // The 3D view's transform: 50 times a second is smooth, and a 1 kHz module's every sample
    // would double the file for nothing the view shows.
    if (s.has(FieldQuat) && (m_lastTf < 0 || s.hostTimeNs - m_lastTf >= kTfPeriodNs || s.hostTimeNs < m_lastTf)) {
        m_lastTf = s.hostTimeNs;
        ok = ok && put(Tf, s, logTime, publishTime, [&](CdrWriter &w) { return encodeTf(w, s, stamp, m_world, frame); });
    }
    if (s.has(FieldEuler))
        ok = ok && put(Euler, s, logTime, publishTime, [&](CdrWriter &w) { return encodeEuler(w, s, stamp, frame); });
    // The rest (what no ROS message holds), with the JSON Lines export's keys: at once when it
    // holds more than the status word and the device's time stamp, or the status word changed;
    // else ten times a second.
    constexpr uint32_t kInMessages = FieldAcc | FieldGyr | FieldMag | FieldQuat | FieldPressure | FieldTemperature
                                     | FieldPosition | FieldEuler;
    const uint32_t restFields = s.fields & ~kInMessages;
    const bool more = (restFields & ~uint32_t(FieldMainStatus | FieldDeviceTime)) != 0;
    const bool changed = s.has(FieldMainStatus) && (!m_haveStatus || s.mainStatus != m_lastStatus);
    if (more || changed || m_lastStatusNs < 0 || s.hostTimeNs - m_lastStatusNs >= kStatusPeriodNs
        || s.hostTimeNs < m_lastStatusNs) {
        m_lastStatusNs = s.hostTimeNs;
        if (s.has(FieldMainStatus)) {
            m_lastStatus = s.mainStatus;
            m_haveStatus = true;
        }
        model::Sample rest = s; // copied only when written
        rest.fields = restFields;
        ok = ok && putJson(Status, s, logTime, publishTime, sampleToJson(rest, m_device.worldFrame));
    }
    return ok;
}

} // namespace imudesk::format::mcap
