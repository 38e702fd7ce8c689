#include "core/results/results_query.h"

#include "core/jobs/thread_sync.h"

#include <QThread>

namespace imudesk::results {

// Lives in the query thread; its store's connection is opened, used and closed there.
class ResultsQuery::Worker : public QObject {
public:
    ResultsStore store;
};

ResultsQuery::ResultsQuery(QObject *parent) : QObject(parent)
{
    m_thread = new QThread;
    m_thread->setObjectName(QStringLiteral("imudesk-results-query"));
    m_worker = new Worker;
    m_worker->moveToThread(m_thread);
    jobs::announceJoin(*m_thread);
    m_thread->start();
}

ResultsQuery::~ResultsQuery()
{
    m_shared->closing = true;
    // The jobs still queued see `closing` and do nothing; the connection closes in its thread.
    jobs::callAndWait(m_worker, [w = m_worker] { w->store.close(); });
    jobs::joinThread(*m_thread);
    delete m_worker;
    delete m_thread;
}

void ResultsQuery::post(int channel, Job job)
{
    Q_ASSERT(channel >= 0 && channel < kChannels);
    const quint64 generation = ++m_shared->generation[size_t(channel)];
    if (++m_outstanding == 1)
        Q_EMIT busyChanged(true);
    jobs::postTo(m_worker, [this, w = m_worker, shared = m_shared, channel, generation, job = std::move(job)] {
        std::function<void()> apply;
        if (!shared->closing && shared->generation[size_t(channel)] == generation)
            apply = job(w->store);
        // Even a skipped job answers: the owner counts what is outstanding. An owner that is
        // gone (its destructor waits for this thread) drops the event with itself.
        jobs::postTo(this, [this, apply = std::move(apply), channel, generation] { answered(apply, channel, generation); });
    });
}

void ResultsQuery::dropAll()
{
    for (auto &g : m_shared->generation)
        ++g;
}

void ResultsQuery::answered(const std::function<void()> &apply, int channel, quint64 generation)
{
    --m_outstanding;
    // A job posted on the channel since this one started makes its answer stale.
    if (apply && !m_shared->closing && m_shared->generation[size_t(channel)] == generation)
        apply();
    if (m_outstanding == 0)
        Q_EMIT busyChanged(false);
}

} // namespace imudesk::results
