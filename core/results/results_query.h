#pragma once
// The results window's reads off the GUI thread (issue 38): one worker thread that owns its own
// ResultsStore (Qt SQL's rule: a connection is used only by the thread that opened it), so a
// search on a slow server or a large file never freezes the window. Jobs run there one after
// another in the order posted; what a job hands back runs in the owner's thread.
//
// Jobs go on channels (the window's kinds of question: search, history, yield, ...). A job
// posted on a channel makes every earlier job of that channel stale: one not started yet is
// skipped, and the answer of one under way is dropped, so a slow answer never overwrites a
// newer one. dropAll() makes every channel stale (another database opened).
#include "core/results/results_store.h"

#include <QObject>

#include <array>
#include <atomic>
#include <functional>
#include <memory>

QT_BEGIN_NAMESPACE
class QThread;
QT_END_NAMESPACE

namespace imudesk::results {

class ResultsQuery : public QObject {
    Q_OBJECT

public:
    static constexpr int kChannels = 8;
    // Runs in the worker thread with its store; returns what to do with the answer in the
    // owner's thread (nothing: an empty function).
    using Job = std::function<std::function<void()>(ResultsStore &store)>;

    explicit ResultsQuery(QObject *parent = nullptr);
    // Waits for the job under way (a server that does not answer: at most its 5 s connect
    // timeout); the jobs still queued are skipped.
    ~ResultsQuery() override;

    void post(int channel, Job job);
    // The same with the answer as a value: job(store) runs in the worker thread, apply(answer)
    // in the owner's (both copyable; apply never runs in the worker).
    template <typename ReadFn, typename ApplyFn>
    void ask(int channel, ReadFn job, ApplyFn apply)
    {
        post(channel, [job = std::move(job), apply = std::move(apply)](ResultsStore &store) -> std::function<void()> {
            auto answer = std::make_shared<decltype(job(store))>(job(store));
            return [apply, answer] { apply(std::move(*answer)); };
        });
    }
    void dropAll();
    // Jobs posted whose answer has not come back yet (stale ones included).
    int outstanding() const { return m_outstanding; }
    bool busy() const { return m_outstanding > 0; }

Q_SIGNALS:
    void busyChanged(bool busy);

private:
    class Worker;
    struct Shared {
        std::array<std::atomic<quint64>, kChannels> generation{};
        std::atomic<bool> closing{false};
    };
    void answered(const std::function<void()> &apply, int channel, quint64 generation);

    QThread *m_thread = nullptr;
    Worker *m_worker = nullptr;
    std::shared_ptr<Shared> m_shared = std::make_shared<Shared>();
    int m_outstanding = 0;
};

} // namespace imudesk::results
