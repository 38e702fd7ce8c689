#include "mcap_recording.h"

#include "capture/device_name.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QJsonDocument>
#include <QJsonObject>

#include <set>

namespace imudesk::capture {

namespace fm = format::mcap;

McapRecording::McapRecording() = default;
McapRecording::~McapRecording() = default;

bool McapRecording::isMcapPath(const QString &path)
{
    return path.endsWith(QLatin1String(".mcap"), Qt::CaseInsensitive);
}

fm::McapWriter::Options McapRecording::writerOptions()
{
    fm::McapWriter::Options o;
    o.library = (QStringLiteral("ImuDesk ") + QCoreApplication::applicationVersion()).trimmed().toStdString();
    return o;
}

fm::McapWriter::StringMap McapRecording::deviceMetadata(const CaptureHeader &header)
{
    const model::DeviceIdentity id = header.identity();
    fm::McapWriter::StringMap device;
    const auto put = [&device](const char *key, const std::string &v) {
        if (!v.empty())
            device[key] = v;
    };
    put("product", id.productName);
    put("serial", id.serial);
    put("build", id.build);
    put("firmware", header.value(CaptureHeader::kFirmware));
    put("bootloader", header.value(CaptureHeader::kBootloader));
    put("link", header.value(CaptureHeader::kLinkKind));
    put("port", header.value(CaptureHeader::kPort));
    put("baud", header.value(CaptureHeader::kBaud));
    put("recorded_utc", header.value(CaptureHeader::kStartedUtc));
    put("recorded_by", header.value(CaptureHeader::kApplication));
    device["world_frame"] = id.worldFrame == model::WorldFrame::Nwu ? "NWU" : "ENU";
    return device;
}

fm::McapWriter::StringMap McapRecording::timeMetadata()
{
    return {{"log_time", "arrival on the recording host (its steady clock, on the Unix epoch)"},
            {"publish_time", "the sample's common time: its sampling instant on the same clock, from the device's "
                             "counter through ImuDesk's clock model, or the arrival where there is none"},
            {"sequence", "the device's time stamp in ms where it has one"}};
}

std::string McapRecording::configurationJson(const CaptureHeader &header)
{
    if (header.config().empty())
        return {};
    QJsonObject config;
    for (const auto &[k, v] : header.config())
        config.insert(QString::fromStdString(k), QString::fromStdString(v));
    return QJsonDocument(config).toJson(QJsonDocument::Indented).toStdString();
}

fm::SampleChannels::Device McapRecording::channelsOf(const CaptureHeader &header, const std::string &name)
{
    const model::DeviceIdentity id = header.identity();
    fm::SampleChannels::Device d;
    d.name = name.empty() ? deviceName(header) : fm::SampleChannels::topicName(name);
    d.frameId = "imu_" + d.name;
    d.worldFrame = id.worldFrame;
    d.metadata = deviceMetadata(header);
    return d;
}

bool McapRecording::start(const QString &path, const CaptureHeader &header, int64_t epochOffsetNs, QString *error)
{
    return start(path, std::vector<Device>{{header, {}}}, epochOffsetNs, error);
}

bool McapRecording::start(const QString &path, const std::vector<Device> &devices, int64_t epochOffsetNs,
                          QString *error)
{
    m_path = path;
    m_epochOffsetNs = epochOffsetNs;
    m_samples = 0;
    m_channels.clear();
    m_writer = std::make_unique<fm::McapWriter>();
    if (!m_writer->open(path, writerOptions())) {
        if (error)
            *error = QCoreApplication::translate("McapRecording", "Cannot write %1: %2").arg(path, m_writer->error());
        return false;
    }
    m_writer->addMetadata("time", timeMetadata());
    const uint64_t now = uint64_t(QDateTime::currentMSecsSinceEpoch()) * 1'000'000u;
    // One device: its metadata "device" and attachment "configuration.json", as an export has them.
    const bool one = devices.size() == 1;
    std::set<std::string> names;
    for (const Device &dev : devices) {
        const std::string name = fm::SampleChannels::uniqueName(deviceName(dev.header, dev.label),
                                                                [&names](const std::string &n) { return names.count(n) > 0; });
        names.insert(name);
        fm::SampleChannels::Device d = channelsOf(dev.header, name);
        d.onChangeOnly = true; // a file's layout
        m_writer->addMetadata(one ? std::string("device") : "device " + d.name, d.metadata);
        if (const std::string config = configurationJson(dev.header); !config.empty())
            m_writer->attach(one ? std::string("configuration.json") : d.name + "/configuration.json", "application/json",
                             config, now, now);
        m_channels.push_back(std::make_unique<fm::SampleChannels>(*m_writer, d));
    }
    m_sinceFlush.start();
    if (!m_writer->flush()) { // the header and metadata on disk before the first sample
        if (error)
            *error = m_writer->error();
        return false;
    }
    return true;
}

bool McapRecording::append(size_t device, const model::Sample &s)
{
    if (device >= m_channels.size() || !m_channels[device]->write(s, m_epochOffsetNs))
        return false;
    ++m_samples;
    return true;
}

bool McapRecording::append(const std::vector<model::Sample> &batch)
{
    for (const model::Sample &s : batch)
        if (!append(s))
            return false;
    return true;
}

void McapRecording::tick()
{
    // Called every half second (the session's statistics): a chunk closes 0.5 to 1 s after it
    // opened, so a kill loses less than a second.
    if (m_writer && m_writer->isOpen() && m_sinceFlush.elapsed() >= 450) {
        m_writer->endChunk(); // compressed, written and flushed by the writer's thread
        m_sinceFlush.restart();
    }
}

QString McapRecording::stop()
{
    if (!m_writer)
        return {};
    m_writer->close();
    return m_writer->error();
}

void McapRecording::abandon()
{
    if (m_writer)
        m_writer->abandon();
}

} // namespace imudesk::capture
