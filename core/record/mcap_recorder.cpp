#include "mcap_recorder.h"

#include "clock/host_clock.h"

#include <QCoreApplication>
#include <QDateTime>

#include <algorithm>
#include <chrono>

namespace imudesk::record {

// A member's tap: the recorder's file is shared, so begin() and end() leave it alone.
class McapRecorder::MemberTap : public device::StreamTap {
public:
    MemberTap(std::shared_ptr<Inbox> inbox, size_t device) : m_inbox(std::move(inbox)), m_device(device) {}
    bool begin(const capture::CaptureHeader &, QString *) override
    {
        m_ended = false;
        return true;
    }
    void samples(const std::vector<model::Sample> &batch) override
    {
        if (!m_ended)
            m_inbox->append(m_device, batch);
    }
    Progress progress() const override
    {
        return {m_inbox->bytes.load(), m_device < m_inbox->written.size() ? m_inbox->written[m_device].load() : 0};
    }
    QString end() override
    {
        m_ended = true;
        return m_inbox->errorText();
    }

private:
    std::shared_ptr<Inbox> m_inbox;
    size_t m_device;
    bool m_ended = false; // the engine's thread only
};

void McapRecorder::Inbox::append(size_t device, const std::vector<model::Sample> &batch)
{
    std::lock_guard lock(mutex);
    if (stop || device >= queues.size())
        return;
    std::vector<model::Sample> &q = queues[device];
    const size_t room = kQueueSamples > q.size() ? kQueueSamples - q.size() : 0;
    const size_t taken = std::min(room, batch.size());
    q.insert(q.end(), batch.begin(), batch.begin() + std::ptrdiff_t(taken));
    missed += batch.size() - taken;
}

QString McapRecorder::Inbox::errorText()
{
    std::lock_guard lock(mutex);
    return error;
}

McapRecorder::~McapRecorder()
{
    stop();
}

bool McapRecorder::start(const QString &path, const std::vector<Device> &devices, QString *error)
{
    stop();
    const int64_t epochOffsetNs = QDateTime::currentMSecsSinceEpoch() * 1'000'000 - clock::hostNowNs();
    if (!m_recording.start(path, devices, epochOffsetNs, error))
        return false;
    m_path = path;
    // A new inbox: the taps of an earlier recording, if any still exist, keep the old one.
    m_inbox = std::make_shared<Inbox>();
    m_inbox->queues.assign(devices.size(), {});
    m_inbox->written = std::vector<std::atomic<uint64_t>>(devices.size());
    m_inbox->bytes = m_recording.bytesWritten();
    m_inbox->stop = false;
    m_thread = std::thread([this] { run(); });
    return true;
}

void McapRecorder::append(size_t device, const std::vector<model::Sample> &batch)
{
    m_inbox->append(device, batch);
}

void McapRecorder::failWith(const QString &message)
{
    {
        std::lock_guard lock(m_inbox->mutex);
        m_inbox->error = message;
        m_inbox->stop = true;
        for (auto &q : m_inbox->queues)
            q.clear();
    }
    if (m_failed)
        m_failed(message);
}

bool McapRecorder::drain()
{
    std::vector<std::vector<model::Sample>> batches;
    {
        std::lock_guard lock(m_inbox->mutex);
        batches.resize(m_inbox->queues.size());
        for (size_t i = 0; i < batches.size(); ++i)
            batches[i].swap(m_inbox->queues[i]);
    }
    for (size_t i = 0; i < batches.size(); ++i) {
        for (const model::Sample &s : batches[i]) {
            if (!m_recording.append(i, s)) {
                failWith(QCoreApplication::translate("capture::McapRecording",
                                                     "Recording to %1 stopped: %2. Check the free disk space.")
                             .arg(m_recording.path(), m_recording.error()));
                return false;
            }
        }
        m_inbox->written[i] += batches[i].size();
    }
    m_inbox->bytes = m_recording.bytesWritten();
    return true;
}

void McapRecorder::run()
{
    for (;;) {
        {
            std::unique_lock lock(m_inbox->mutex);
            m_inbox->wake.wait_for(lock, std::chrono::milliseconds(20), [this] { return m_inbox->stop; });
            if (m_inbox->stop)
                return;
        }
        if (!drain())
            return;
        m_recording.tick(); // a chunk closed at least every second
        m_inbox->bytes = m_recording.bytesWritten();
    }
}

QString McapRecorder::stop()
{
    if (!m_thread.joinable())
        return error();
    bool failed;
    {
        std::lock_guard lock(m_inbox->mutex);
        failed = !m_inbox->error.isEmpty();
        m_inbox->stop = true;
    }
    m_inbox->wake.notify_all();
    m_thread.join();
    if (!failed)
        drain(); // what came since the writer's last round (the taps queue no more now)
    const QString closed = m_recording.stop();
    m_inbox->bytes = m_recording.bytesWritten();
    std::lock_guard lock(m_inbox->mutex);
    if (m_inbox->error.isEmpty() && !closed.isEmpty())
        m_inbox->error = closed;
    return m_inbox->error;
}

std::vector<uint64_t> McapRecorder::samples() const
{
    std::vector<uint64_t> out;
    for (const auto &w : m_inbox->written)
        out.push_back(w.load());
    return out;
}

std::shared_ptr<device::StreamTap> McapRecorder::tap(size_t device)
{
    return std::make_shared<MemberTap>(m_inbox, device);
}

bool McapTap::begin(const capture::CaptureHeader &header, QString *error)
{
    m_recorder.setFailedHandler([this](const QString &reason) { stoppedByItself(reason); });
    return m_recorder.start(m_path, {{header, std::string()}}, error);
}

device::StreamTap::Progress McapTap::progress() const
{
    const std::vector<uint64_t> written = m_recorder.samples();
    return {m_recorder.bytesWritten(), written.empty() ? 0 : written[0]};
}

} // namespace imudesk::record
