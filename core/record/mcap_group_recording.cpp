#include "mcap_group_recording.h"

#include "clock/host_clock.h"

#include <QCoreApplication>
#include <QDateTime>

#include <chrono>

namespace imudesk::record {

McapGroupRecording::~McapGroupRecording()
{
    stop();
}

bool McapGroupRecording::start(const QString &path, std::vector<Member> members, QString *error)
{
    stop();
    m_members = std::move(members);
    std::vector<capture::McapRecording::Device> devices;
    for (const Member &m : m_members)
        devices.push_back({m.header, m.label});
    const int64_t epochOffsetNs = QDateTime::currentMSecsSinceEpoch() * 1'000'000 - clock::hostNowNs();
    if (!m_recording.start(path, devices, epochOffsetNs, error))
        return false;
    m_cursors.clear();
    for (const Member &m : m_members)
        m_cursors.emplace_back(m.store); // what arrives from now on
    m_written = std::vector<std::atomic<uint64_t>>(m_members.size());
    m_missed = 0;
    m_stop = false;
    {
        std::lock_guard lock(m_errorMutex);
        m_error.clear();
    }
    m_thread = std::thread([this] { run(); });
    return true;
}

void McapGroupRecording::drain()
{
    for (size_t i = 0; i < m_members.size(); ++i) {
        uint64_t missed = 0;
        const std::vector<model::Sample> batch = m_cursors[i].take(&missed);
        m_missed += missed;
        for (const model::Sample &s : batch) {
            if (!m_recording.append(i, s)) {
                std::lock_guard lock(m_errorMutex);
                m_error = QCoreApplication::translate("capture::McapRecording", "Recording to %1 stopped: %2. Check the free disk space.")
                              .arg(m_recording.path(), m_recording.error());
                m_stop = true;
                return;
            }
            ++m_written[i];
        }
    }
    m_bytes = m_recording.bytesWritten();
}

void McapGroupRecording::run()
{
    while (!m_stop.load()) {
        drain();
        m_recording.tick(); // a chunk closed at least every second
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

QString McapGroupRecording::stop()
{
    if (!m_thread.joinable())
        return error();
    m_stop = true;
    m_thread.join();
    if (error().isEmpty())
        drain(); // what came in the last 20 ms
    const QString closed = m_recording.stop();
    std::lock_guard lock(m_errorMutex);
    if (m_error.isEmpty() && !closed.isEmpty())
        m_error = closed;
    return m_error;
}

QString McapGroupRecording::error() const
{
    std::lock_guard lock(m_errorMutex);
    return m_error;
}

std::vector<uint64_t> McapGroupRecording::samples() const
{
    std::vector<uint64_t> out;
    for (const auto &w : m_written)
        out.push_back(w.load());
    return out;
}

} // namespace imudesk::record
