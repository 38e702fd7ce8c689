#include "update_runner.h"

#include "device/thread_sync.h"

#include <QThread>

#include <atomic>
#include <mutex>

namespace imudesk::firmware {

// Shared by this object and the worker: the cancel request and how to cancel the current flow.
struct UpdateRunner::Shared {
    std::atomic<bool> cancel{false};
    std::mutex mutex;
    Canceller canceller; // guarded by mutex

    void setCanceller(Canceller c)
    {
        const std::lock_guard lock(mutex);
        canceller = std::move(c);
        if (canceller && cancel)
            canceller();
    }
    void requestCancel()
    {
        cancel = true;
        const std::lock_guard lock(mutex);
        if (canceller)
            canceller();
    }
};

UpdateRunner::UpdateRunner(QObject *parent) : QObject(parent) {}

UpdateRunner::~UpdateRunner()
{
    if (m_thread) {
        cancel();
        device::waitForThread(*m_thread);
        delete m_thread;
        m_thread = nullptr;
    }
}

bool UpdateRunner::launch(const QString &threadName, Job job)
{
    if (m_thread)
        return false;
    m_shared = std::make_shared<Shared>();
    m_outcome = std::make_shared<Outcome>();
    auto shared = m_shared;
    auto outcome = m_outcome;
    // The outcome is written by the worker and read here only after the thread has ended.
    m_thread = QThread::create([job = std::move(job), shared, outcome] {
        *outcome = job([&shared](Canceller c) { shared->setCanceller(std::move(c)); });
        shared->setCanceller({});
    });
    m_thread->setObjectName(threadName);
    connect(m_thread, &QThread::finished, this, &UpdateRunner::onWorkerDone);
    device::announceJoin(*m_thread);
    m_thread->start();
    return true;
}

void UpdateRunner::cancel()
{
    if (m_shared)
        m_shared->requestCancel();
}

void UpdateRunner::onWorkerDone()
{
    if (!m_thread)
        return;
    device::waitForThread(*m_thread); // the outcome below was written by the thread
    delete m_thread;
    m_thread = nullptr;
    m_shared.reset();
    const auto outcome = std::move(m_outcome);
    if (outcome->apply)
        outcome->apply();
    Q_EMIT finished(outcome->ok, outcome->message);
}

} // namespace imudesk::firmware
