#include "capture_sample_stream.h"

namespace imudesk::record {

bool CaptureSampleStream::open(const QString &path, QString *error)
{
    if (!m_reader.open(path, error))
        return false;
    // A family without an offline decoder (Modbus) gives no samples: the session's export
    // leaves the device out and says so.
    m_decoder.configure(m_reader.header());
    return true;
}

const model::Sample *CaptureSampleStream::peek()
{
    while (m_queue.empty() && !m_ended) {
        capture::CaptureReader::Chunk c;
        const capture::CaptureReader::Result r = m_reader.next(c);
        if (r == capture::CaptureReader::Result::Chunk) {
            m_decoder.feedChunk(c, *this);
        } else if (r != capture::CaptureReader::Result::Damaged) {
            m_decoder.finish(*this);
            m_ended = true;
        }
    }
    return m_queue.empty() ? nullptr : &m_queue.front();
}

model::Sample CaptureSampleStream::take()
{
    model::Sample s = std::move(m_queue.front());
    m_queue.pop_front();
    ++samples;
    return s;
}

void CaptureSampleStream::onSample(const model::Sample &sample, const decode::Record &)
{
    push(sample);
}

void CaptureSampleStream::push(model::Sample s)
{
    if (s.commonTimeNs != 0)
        s.commonTimeNs += offsetNs; // the aligned time is what a reader sees
    m_queue.push_back(std::move(s));
}

} // namespace imudesk::record
