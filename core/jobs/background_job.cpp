#include "jobs/background_job.h"

#include "jobs/thread_sync.h"

#include <QThread>

#include <mutex>

namespace imudesk::jobs {

// Shared by the owner and the worker: the cancel request and how to cancel the current flow.
struct BackgroundJob::Shared {
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

BackgroundJob::BackgroundJob(QObject *parent) : QObject(parent) {}

BackgroundJob::~BackgroundJob()
{
    if (m_thread) {
        cancel();
        waitForThread(*m_thread);
        delete m_thread;
        m_thread = nullptr;
    }
}

bool BackgroundJob::launch(const QString &threadName, Job job)
{
    if (m_thread)
        return false;
    m_shared = std::make_shared<Shared>();
    m_outcome = std::make_shared<Outcome>();
    m_progress->store(0.0);
    auto shared = m_shared;
    auto outcome = m_outcome;
    auto progress = m_progress;
    // The outcome is written by the worker and read here only after the thread has ended.
    m_thread = QThread::create([job = std::move(job), shared, outcome, progress] {
        Context context;
        context.registerCancel = [&shared](Canceller c) { shared->setCanceller(std::move(c)); };
        context.cancelled = [&shared] { return shared->cancel.load(); };
        context.setProgress = [&progress](double f) { progress->store(f); };
        *outcome = job(context);
        shared->setCanceller({});
    });
    m_thread->setObjectName(threadName);
    connect(m_thread, &QThread::finished, this, &BackgroundJob::onWorkerDone);
    announceJoin(*m_thread);
    m_thread->start();
    return true;
}

void BackgroundJob::cancel()
{
    if (m_shared)
        m_shared->requestCancel();
}

void BackgroundJob::onWorkerDone()
{
    if (!m_thread)
        return;
    waitForThread(*m_thread); // the outcome below was written by the thread
    delete m_thread;
    m_thread = nullptr;
    m_shared.reset();
    const auto outcome = std::move(m_outcome);
    if (outcome->apply)
        outcome->apply();
    Q_EMIT finished(outcome->ok, outcome->message);
}

} // namespace imudesk::jobs
