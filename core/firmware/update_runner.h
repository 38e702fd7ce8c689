#pragma once
// The worker-thread part shared by the firmware updaters (FirmwareUpdater over a serial port,
// CanFirmwareUpdater over a CAN bus): one update job at a time runs in its own QThread and is
// reported with queued signals; cancel() is safe from any thread. A subclass's start() builds
// the job (link + flow, made and used in the worker thread) and hands it to launch().
#include "jobs/background_job.h"

#include <QObject>
#include <QString>

#include <functional>
#include <memory>

namespace imudesk::firmware {

// The update's worker thread is a jobs::BackgroundJob (cancel, finished); this adds the
// flows' own reports.
class UpdateRunner : public jobs::BackgroundJob {
    Q_OBJECT

Q_SIGNALS:
    void stateChanged(int state, const QString &name); // the flow's State
    void progressChanged(qulonglong done, qulonglong total, double bytesPerSecond, double secondsLeft);
    void logMessage(const QString &line);

protected:
    explicit UpdateRunner(QObject *parent = nullptr) : jobs::BackgroundJob(parent) {}

    using RegisterCancel = std::function<void(Canceller)>;
    using Job = std::function<Outcome(const RegisterCancel &)>;

    // Runs job in a new worker thread named threadName; false when a job is already running.
    bool launch(const QString &threadName, Job job)
    {
        return jobs::BackgroundJob::launch(threadName,
                                           [job = std::move(job)](const Context &c) { return job(c.registerCancel); });
    }

    // For jobs (worker thread): an observer for a flow type (UpdateFlow, CanUpdateFlow) whose
    // state and log callbacks emit stateChanged() and logMessage(); the caller adds progress.
    template <class Flow>
    typename Flow::Observer signallingObserver()
    {
        typename Flow::Observer obs;
        obs.stateChanged = [this](typename Flow::State s) { Q_EMIT stateChanged(int(s), Flow::stateName(s)); };
        obs.log = [this](const QString &line) { Q_EMIT logMessage(line); };
        return obs;
    }
    // For jobs: runs flow on image with its cancel registered; the outcome stores the flow's
    // result in store (a member of the subclass) in this object's thread.
    template <class Flow, class Image>
    static Outcome runFlow(const RegisterCancel &registerCancel, const std::shared_ptr<Flow> &flow, const Image &image,
                           typename Flow::Result &store)
    {
        registerCancel([flow] { flow->cancel(); });
        auto result = flow->run(image);
        registerCancel({});
        Outcome outcome{result.ok, result.message, {}};
        outcome.apply = [&store, result = std::move(result)] { store = result; };
        return outcome;
    }
};

} // namespace imudesk::firmware
