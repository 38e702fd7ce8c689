#pragma once
// The worker-thread part shared by the firmware updaters (FirmwareUpdater over a serial port,
// CanFirmwareUpdater over a CAN bus): one update job at a time runs in its own QThread and is
// reported with queued signals; cancel() is safe from any thread. A subclass's start() builds
// the job (link + flow, made and used in the worker thread) and hands it to launch().
#include <QObject>
#include <QString>

#include <functional>
#include <memory>

QT_BEGIN_NAMESPACE
class QThread;
QT_END_NAMESPACE

namespace imudesk::firmware {

class UpdateRunner : public QObject {
    Q_OBJECT

public:
    ~UpdateRunner() override;

    // Asks the running job to stop (the flow stops at its next safe point); no effect when idle.
    void cancel();
    bool isRunning() const { return m_thread != nullptr; }

Q_SIGNALS:
    void stateChanged(int state, const QString &name); // the flow's State
    void progressChanged(qulonglong done, qulonglong total, double bytesPerSecond, double secondsLeft);
    void logMessage(const QString &line);
    void finished(bool ok, const QString &message);

protected:
    explicit UpdateRunner(QObject *parent = nullptr);

    // What a job hands back from the worker thread. apply (optional) runs in this object's
    // thread after the worker has ended and before finished() is emitted: a subclass stores
    // its typed result there.
    struct Outcome {
        bool ok = false;
        QString message;
        std::function<void()> apply;
    };
    // A job registers how to cancel the flow it made (and registers an empty function before
    // that flow goes away); a cancel asked before the registration reaches it at once.
    using Canceller = std::function<void()>;
    using RegisterCancel = std::function<void(Canceller)>;
    using Job = std::function<Outcome(const RegisterCancel &)>;

    // Runs job in a new worker thread named threadName; false when a job is already running.
    bool launch(const QString &threadName, Job job);

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

private:
    struct Shared;
    void onWorkerDone();

    QThread *m_thread = nullptr;
    std::shared_ptr<Shared> m_shared;
    std::shared_ptr<Outcome> m_outcome;
};

} // namespace imudesk::firmware
