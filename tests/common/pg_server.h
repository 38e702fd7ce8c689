#pragma once
// A real PostgreSQL server for the results tests (issue 38), from Debian's postgresql package:
// initdb into a temporary folder and pg_ctl start with its own Unix socket folder and port, no
// TCP. PostgreSQL refuses to run as root, so under root (CI, the fresh Debian root) initdb and
// the server run as the unprivileged user nobody (setpriv); otherwise as the test's own user.
// The owner role is imudesk_admin, local connections trust (the socket folder is the test's).
// stop() and start() again keep the data: a server that goes away in the middle of a run.
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRandomGenerator>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

#include <algorithm>
#include <memory>

#include <unistd.h>

namespace imudesk::test {

class PgServer {
public:
    static constexpr const char *kOwner = "imudesk_admin";

    ~PgServer() { stop(); }

    // The folder of Debian's server programs (/usr/lib/postgresql/<version>/bin); empty when
    // the postgresql package is not installed.
    static QString binDir()
    {
        const QDir base(QStringLiteral("/usr/lib/postgresql"));
        QStringList versions = base.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name);
        std::sort(versions.begin(), versions.end(), [](const QString &a, const QString &b) { return a.toInt() > b.toInt(); });
        for (const QString &v : versions)
            if (QFileInfo::exists(base.filePath(v + QStringLiteral("/bin/pg_ctl"))))
                return base.filePath(v + QStringLiteral("/bin"));
        return {};
    }

    // initdb (first time) and start; false with *error.
    bool start(QString *error)
    {
        if (m_running)
            return true;
        if (m_bin.isEmpty())
            m_bin = binDir();
        if (m_bin.isEmpty()) {
            *error = QStringLiteral("PostgreSQL's server is not installed (Debian: postgresql); scripts/setup.sh installs it");
            return false;
        }
        if (!m_dir) {
            m_dir = std::make_unique<QTemporaryDir>(QDir::tempPath() + QStringLiteral("/imudesk-pg-XXXXXX"));
            if (!m_dir->isValid()) {
                *error = QStringLiteral("no temporary folder");
                return false;
            }
            QDir().mkpath(socketDir());
            if (::geteuid() == 0) {
                // nobody must own its folders; the test (root) reaches them anyway.
                for (const QString &p : {m_dir->path(), socketDir()})
                    if (::chown(QFile::encodeName(p).constData(), 65534, 65534) != 0) {
                        *error = QStringLiteral("cannot give %1 to nobody").arg(p);
                        return false;
                    }
            }
            if (!runAsServer(m_bin + QStringLiteral("/initdb"),
                             {QStringLiteral("-D"), dataDir(), QStringLiteral("-U"), QLatin1String(kOwner),
                              QStringLiteral("--auth=trust"), QStringLiteral("-E"), QStringLiteral("UTF8"),
                              QStringLiteral("--no-locale"), QStringLiteral("--no-sync")},
                             error))
                return false;
            m_port = 20000 + int(QRandomGenerator::global()->bounded(20000));
        }
        const QString options = QStringLiteral("-k %1 -p %2 -c listen_addresses= -c fsync=off -c max_connections=60")
                                    .arg(socketDir())
                                    .arg(m_port);
        if (!runAsServer(m_bin + QStringLiteral("/pg_ctl"),
                         {QStringLiteral("-D"), dataDir(), QStringLiteral("-o"), options, QStringLiteral("-l"),
                          m_dir->filePath(QStringLiteral("server.log")), QStringLiteral("-w"), QStringLiteral("-t"),
                          QStringLiteral("60"), QStringLiteral("start")},
                         error))
            return false;
        m_running = true;
        return true;
    }

    // Stops the server at once (fast: open connections are cut), keeping its data.
    void stop()
    {
        if (!m_running)
            return;
        QString ignored;
        runAsServer(m_bin + QStringLiteral("/pg_ctl"),
                    {QStringLiteral("-D"), dataDir(), QStringLiteral("-m"), QStringLiteral("fast"), QStringLiteral("-w"),
                     QStringLiteral("stop")},
                    &ignored);
        m_running = false;
    }
    bool running() const { return m_running; }

    // A URL for imudesk (ResultsStore, --results) as role on database db.
    QString url(const QString &role = QLatin1String(kOwner), const QString &db = QStringLiteral("postgres")) const
    {
        return QStringLiteral("postgresql://%1@localhost/%2?host=%3&port=%4").arg(role, db, socketDir()).arg(m_port);
    }
    // Runs SQL through psql as the owner; its output, or empty with *error.
    bool psql(const QString &sql, QString *output, QString *error) const
    {
        QProcess p;
        p.start(QStringLiteral("psql"), {QStringLiteral("-X"), QStringLiteral("-q"), QStringLiteral("-A"), QStringLiteral("-t"),
                                         QStringLiteral("-v"), QStringLiteral("ON_ERROR_STOP=1"), QStringLiteral("-h"), socketDir(),
                                         QStringLiteral("-p"), QString::number(m_port), QStringLiteral("-U"),
                                         QLatin1String(kOwner), QStringLiteral("-d"), QStringLiteral("postgres"),
                                         QStringLiteral("-c"), sql});
        if (!p.waitForFinished(60000) || p.exitCode() != 0) {
            *error = QString::fromUtf8(p.readAllStandardError());
            return false;
        }
        if (output)
            *output = QString::fromUtf8(p.readAllStandardOutput()).trimmed();
        return true;
    }
    int port() const { return m_port; }
    QString socketDir() const { return m_dir ? m_dir->filePath(QStringLiteral("sock")) : QString(); }
    QString log() const
    {
        QFile f(m_dir ? m_dir->filePath(QStringLiteral("server.log")) : QString());
        return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
    }

private:
    QString dataDir() const { return m_dir->filePath(QStringLiteral("data")); }

    bool runAsServer(const QString &program, const QStringList &args, QString *error) const
    {
        QProcess p;
        p.setWorkingDirectory(m_dir->path());
        if (::geteuid() == 0)
            p.start(QStringLiteral("setpriv"), QStringList{QStringLiteral("--reuid=65534"), QStringLiteral("--regid=65534"),
                                                           QStringLiteral("--clear-groups"), QStringLiteral("--"), program}
                                                   + args);
        else
            p.start(program, args);
        if (!p.waitForFinished(120000) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) {
            *error = QStringLiteral("%1 failed: %2%3").arg(QFileInfo(program).fileName(), QString::fromUtf8(p.readAllStandardError()),
                                                          QString::fromUtf8(p.readAllStandardOutput()));
            return false;
        }
        return true;
    }

    QString m_bin;
    std::unique_ptr<QTemporaryDir> m_dir;
    int m_port = 0;
    bool m_running = false;
};

} // namespace imudesk::test
