#pragma once
// One shape for work that runs off the caller's thread (firmware updates, exports, analyses,
// probes): a job runs in a QThread of its own, reports its progress through an atomic the
// caller's view clock reads, stops at its next safe point when cancelled (cancel() is safe from
// any thread), and ends with finished(ok, message) in the owner's thread. The job never sees
// the owner: what it hands back (Outcome::apply) runs in the owner's thread after the worker has
// ended, so a dialog closed meanwhile loses nothing but the result it no longer shows.
// Destroying a running job cancels it and waits for the worker.
#include <QObject>
#include <QString>

#include <atomic>
#include <functional>
#include <memory>

QT_BEGIN_NAMESPACE
class QThread;
QT_END_NAMESPACE

namespace imudesk::jobs {

class BackgroundJob : public QObject {
    Q_OBJECT

public:
    // What a job hands back from the worker thread. apply (optional) runs in the owner's
    // thread before finished() is emitted.
    struct Outcome {
        bool ok = false;
        QString message;
        std::function<void()> apply;
    };
    // A job registers how to cancel the flow it made (and registers an empty function before
    // that flow goes away); a cancel asked before the registration reaches it at once.
    using Canceller = std::function<void()>;
    // What a job may use from the worker thread.
    struct Context {
        std::function<void(Canceller)> registerCancel;
        std::function<bool()> cancelled;          // cancel() was asked
        std::function<void(double)> setProgress;  // 0..1
    };
    using Job = std::function<Outcome(const Context &)>;

    explicit BackgroundJob(QObject *parent = nullptr);
    ~BackgroundJob() override;

    // Runs job in a new worker thread named threadName; false when a job is already running.
    bool launch(const QString &threadName, Job job);
    // Asks the running job to stop; no effect when idle.
    void cancel();
    bool isRunning() const { return m_thread != nullptr; }
    // The running (or last) job's progress, 0..1, as it last reported it.
    double progress() const { return m_progress->load(); }

Q_SIGNALS:
    void finished(bool ok, const QString &message);

private:
    struct Shared;
    void onWorkerDone();

    QThread *m_thread = nullptr;
    std::shared_ptr<Shared> m_shared;
    std::shared_ptr<Outcome> m_outcome;
    std::shared_ptr<std::atomic<double>> m_progress = std::make_shared<std::atomic<double>>(0.0);
};

} // namespace imudesk::jobs
