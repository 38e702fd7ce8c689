#pragma once
// Store-and-forward of a station's results to the line's database (issue 38): the station
// commits every module to its own SQLite file first (results_store.h, the outbox); this uploader
// sends what the server does not have yet, in batches, from a thread of its own. When the network
// or the server is down it retries with back-off (1 s, 2 s, 4 s … up to a minute) and nothing is
// lost: a module leaves the outbox only once the server has committed it. The server's inserts
// are keyed by UUID, so a batch sent again after a lost answer is stored once.
//
// Artifacts (the PDF reports, recordings) are copied into a shared folder when one is set
// (<folder>/<module uuid>/<file name>), checked against their SHA-256 there, and the server
// records that location.
#include "core/results/results_store.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <memory>

class QThread;

namespace imudesk::results {

struct UploaderOptions {
    QString outbox;         // the station's results.sqlite
    QString server;         // postgresql://…
    QString artifactFolder; // empty: artifacts keep their station paths
    int batch = 100;        // modules per transaction
    int firstRetryMs = 1000, maxRetryMs = 60000;
    int pollMs = 2000;      // the outbox is looked at this often even without kick()
};

// One pass over the outbox in the calling thread: every pending module sent (or as many as go
// before an error). *sent counts the modules the server confirmed; false with *error.
bool uploadPending(ResultsStore &outbox, ResultsStore &server, const QString &artifactFolder, int batch, int *sent,
                   QString *error);

class UploadWorker;

class ResultsUploader : public QObject {
    Q_OBJECT

public:
    explicit ResultsUploader(UploaderOptions options, QObject *parent = nullptr);
    ~ResultsUploader() override;

    const UploaderOptions &options() const { return m_options; }
    void start();
    void stop();
    bool isRunning() const;
    // A module was just committed to the outbox: look now instead of at the next poll.
    void kick();

    // As last seen by the uploader's thread.
    int pending() const { return m_pending.load(); }
    bool connected() const { return m_connected.load(); }
    quint64 uploadedCount() const { return m_uploaded.load(); }

Q_SIGNALS:
    // After every pass: modules still waiting, whether the server answered, and the last error
    // (empty after a pass that reached the server), translated.
    void stateChanged(int pending, bool connected, const QString &error);
    void uploaded(int modules);

private:
    friend class UploadWorker;
    UploaderOptions m_options;
    QThread *m_thread = nullptr;
    UploadWorker *m_worker = nullptr;
    std::atomic<int> m_pending{0};
    std::atomic<bool> m_connected{false};
    std::atomic<quint64> m_uploaded{0};
};

} // namespace imudesk::results
