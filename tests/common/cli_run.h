#pragma once
// Runs imudesk-cli (IMUDESK_CLI_PATH) as a separate process for the integration tests:
// exit code, stdout and stderr, with a timeout after which the process is killed.
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QString>
#include <QStringList>

namespace imudesk::test {

struct CliResult {
    int code = -1; // -1: crashed or timed out
    QString out, err;
    // stdout as one JSON object (for commands run with --json that print one).
    QJsonObject json() const { return QJsonDocument::fromJson(out.trimmed().toUtf8()).object(); }
};

// Runs any program (e.g. imudesk-cli under prlimit) and collects its exit code and output.
inline CliResult runProgram(const QString &program, const QStringList &args, int timeoutMs)
{
    QProcess p;
    p.start(program, args);
    CliResult r;
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished();
        r.err = QStringLiteral("timed out");
        return r;
    }
    r.code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

inline CliResult runCli(const QStringList &args, int timeoutMs = 60000)
{
    return runProgram(QString::fromUtf8(IMUDESK_CLI_PATH), args, timeoutMs);
}

} // namespace imudesk::test
