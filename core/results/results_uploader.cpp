#include "results_uploader.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLoggingCategory>
#include <QThread>
#include <QTimer>

#include <algorithm>

Q_LOGGING_CATEGORY(lcUpload, "imudesk.results.upload")

namespace imudesk::results {

namespace {
// The artifact in the shared folder, copied there unless a file with its SHA-256 is there
// already; its new location, or empty with *error.
QString shareArtifact(const ArtifactRecord &a, const QString &moduleUuid, const QString &folder, QString *error)
{
    const QFileInfo source(a.location);
    const QString dir = QDir(folder).filePath(moduleUuid);
    const QString target = QDir(dir).filePath(source.fileName());
    if (QFileInfo::exists(target) && fileSha256(target) == a.sha256)
        return target;
    if (!source.exists()) {
        *error = ResultsUploader::tr("%1 is gone from the station; its record keeps the station's path").arg(a.location);
        return a.location; // nothing to copy: the record says where it was
    }
    if (!QDir().mkpath(dir)) {
        *error = ResultsUploader::tr("Cannot create %1 in the shared artifact folder: check that it is mounted and writable.").arg(dir);
        return {};
    }
    QFile::remove(target + QStringLiteral(".part"));
    if (!QFile::copy(a.location, target + QStringLiteral(".part"))) {
        *error = ResultsUploader::tr("Cannot copy %1 to %2: check that the shared folder is mounted and has room.").arg(a.location, dir);
        return {};
    }
    if (fileSha256(target + QStringLiteral(".part")) != a.sha256) {
        QFile::remove(target + QStringLiteral(".part"));
        *error = ResultsUploader::tr("The copy of %1 in the shared folder does not match its SHA-256; it will be copied again.").arg(a.location);
        return {};
    }
    QFile::remove(target);
    if (!QFile::rename(target + QStringLiteral(".part"), target)) {
        *error = ResultsUploader::tr("Cannot copy %1 to %2: check that the shared folder is mounted and has room.").arg(a.location, dir);
        return {};
    }
    return target;
}
} // namespace

bool uploadPending(ResultsStore &outbox, ResultsStore &server, const QString &artifactFolder, int batch, int *sent,
                   QString *error)
{
    *sent = 0;
    // As many batches as were waiting when it began (and one more for a module finished
    // meanwhile): a pass always ends.
    for (int rounds = outbox.pendingCount() / std::max(1, batch) + 2; rounds > 0; --rounds) {
        const auto pending = outbox.pendingUploads(batch, error);
        if (pending.empty())
            return error == nullptr || error->isEmpty();
        std::vector<ModuleRecord> records;
        records.reserve(pending.size());
        for (const auto &[uuid, rev] : pending) {
            auto m = outbox.module(uuid, error);
            if (!m)
                return false;
            if (!artifactFolder.isEmpty())
                for (ArtifactRecord &a : m->artifacts) {
                    QString why;
                    const QString shared = shareArtifact(a, m->uuid, artifactFolder, &why);
                    if (shared.isEmpty()) {
                        if (error)
                            *error = why;
                        return false;
                    }
                    if (!why.isEmpty())
                        qCWarning(lcUpload).noquote() << why;
                    a.location = shared;
                }
            records.push_back(std::move(*m));
        }
        if (!server.commit(records, error))
            return false;
        if (!outbox.markUploaded(pending, error))
            return false;
        *sent += int(pending.size());
    }
    return true;
}

// Lives in the uploader's thread; owns both database connections there (Qt SQL's rule).
class UploadWorker : public QObject {
public:
    // The timer is the worker's child, so that it moves into the uploader's thread with it.
    explicit UploadWorker(ResultsUploader *owner) : m_owner(owner), m_opts(owner->options()), m_timer(this)
    {
        m_timer.setSingleShot(true);
        connect(&m_timer, &QTimer::timeout, this, &UploadWorker::pass);
    }
    void begin() { m_timer.start(0); }
    void kick()
    {
        if (m_delayMs == 0) // not backing off: go now
            m_timer.start(0);
    }
    void end()
    {
        m_timer.stop();
        m_server.close();
        m_outbox.close();
    }

private:
    void pass()
    {
        QString error;
        int sent = 0;
        bool ok = (m_outbox.isOpen() || m_outbox.open(m_opts.outbox, &error))
            && (m_server.isOpen() || m_server.open(m_opts.server, &error))
            && uploadPending(m_outbox, m_server, m_opts.artifactFolder, m_opts.batch, &sent, &error);
        if (ok) {
            m_delayMs = 0;
        } else {
            // The server may have gone away under an open connection: connect anew next time.
            m_server.close();
            m_delayMs = m_delayMs == 0 ? m_opts.firstRetryMs : std::min(2 * m_delayMs, m_opts.maxRetryMs);
            qCInfo(lcUpload).noquote() << "upload failed, retrying in" << m_delayMs << "ms:" << error;
        }
        const int pending = m_outbox.isOpen() ? m_outbox.pendingCount() : m_owner->m_pending.load();
        m_owner->m_pending = pending;
        m_owner->m_connected = ok;
        m_owner->m_uploaded += quint64(sent);
        if (sent > 0)
            Q_EMIT m_owner->uploaded(sent);
        Q_EMIT m_owner->stateChanged(pending, ok, ok ? QString() : error);
        m_timer.start(ok ? m_opts.pollMs : m_delayMs);
    }

    ResultsUploader *m_owner;
    UploaderOptions m_opts;
    ResultsStore m_outbox, m_server;
    QTimer m_timer;
    int m_delayMs = 0;
};

ResultsUploader::ResultsUploader(UploaderOptions options, QObject *parent) : QObject(parent), m_options(std::move(options)) {}

ResultsUploader::~ResultsUploader()
{
    stop();
}

void ResultsUploader::start()
{
    if (m_thread)
        return;
    m_thread = new QThread;
    m_thread->setObjectName(QStringLiteral("imudesk-upload"));
    m_worker = new UploadWorker(this);
    m_worker->moveToThread(m_thread);
    m_thread->start();
    QMetaObject::invokeMethod(m_worker, [w = m_worker] { w->begin(); });
}

void ResultsUploader::stop()
{
    if (!m_thread)
        return;
    // The connections close in their own thread; the worker, idle, goes once the thread ended.
    QMetaObject::invokeMethod(m_worker, [w = m_worker] { w->end(); }, Qt::BlockingQueuedConnection);
    m_thread->quit();
    m_thread->wait();
    delete m_worker;
    m_worker = nullptr;
    delete m_thread;
    m_thread = nullptr;
}

bool ResultsUploader::isRunning() const
{
    return m_thread != nullptr;
}

void ResultsUploader::kick()
{
    if (m_worker)
        QMetaObject::invokeMethod(m_worker, [w = m_worker] { w->kick(); });
}

} // namespace imudesk::results
