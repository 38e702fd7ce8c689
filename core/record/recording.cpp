#include "recording.h"

#include "record/mcap_recorder.h"

namespace imudesk::record {

CaptureTap::CaptureTap(const QString &path, const capture::CaptureWriter::Options &options)
    : m_path(path), m_options(options)
{
}

bool CaptureTap::begin(const capture::CaptureHeader &header, QString *error)
{
    m_writer.setStoppedHandler([this](const QString &reason) { stoppedByItself(reason); });
    if (!m_writer.start(m_path, header, m_options, error))
        return false;
    m_decoder = capture::CaptureDecoder{};
    m_decoder.configure(header);
    return true;
}

void CaptureTap::received(const QByteArray &bytes, int64_t hostNs, int64_t utcUs)
{
    if (m_writer.append(bytes.constData(), size_t(bytes.size()), hostNs, utcUs))
        m_decoder.feed(reinterpret_cast<const uint8_t *>(bytes.constData()), size_t(bytes.size()), hostNs, m_noSink);
}

void CaptureTap::sent(const QByteArray &bytes, int64_t hostNs, int64_t utcUs)
{
    m_writer.appendSent(bytes.constData(), size_t(bytes.size()), hostNs, utcUs);
}

void CaptureTap::lineIdle(int64_t hostNs, int64_t utcUs)
{
    if (m_writer.appendLineIdle(hostNs, utcUs))
        m_decoder.lineIdle(hostNs, m_noSink);
}

device::StreamTap::Progress CaptureTap::progress() const
{
    return {m_writer.status().bytesWritten, m_decoder.counters().frames};
}

QString CaptureTap::end()
{
    const QString error = m_writer.stop();
    m_decoder.finish(m_noSink); // the end of the file, as a reader reaches it
    return error;
}

std::shared_ptr<device::StreamTap> recordingFor(const QString &path, const capture::CaptureWriter::Options &options)
{
    if (capture::McapRecording::isMcapPath(path))
        return std::make_shared<McapTap>(path);
    return std::make_shared<CaptureTap>(path, options);
}

void startRecording(device::Session &session, const QString &path, const capture::CaptureHeader &header,
                    const capture::CaptureWriter::Options &options)
{
    session.startRecording(path, recordingFor(path, options), header);
}

} // namespace imudesk::record
