#pragma once
// Runs imudesk-cli (IMUDESK_CLI_PATH) as a separate process for the integration tests:
// exit code, stdout and stderr, with a timeout after which the process is killed.
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QString>
#include <QStringList>

namespace imudesk::test {

struct CliResult {
    int code = -1; // -1: crashed or timed out
    QString out, err;
    // stdout as one JSON object (for commands run with --json that print one).
    QJsonObject json() const { return QJsonDocument::fromJson(out.trimmed().toUtf8()).object(); }
};

// Where a process that did not end is: every thread's stack, by gdb when it is installed.
inline QString stacksOf(qint64 pid)
{
    const QString gdb = QStandardPaths::findExecutable(QStringLiteral("gdb"));
    if (gdb.isEmpty() || pid <= 0)
        return QStringLiteral("(gdb is not installed: no stacks)");
    QProcess g;
    g.start(gdb, {QStringLiteral("-p"), QString::number(pid), QStringLiteral("-batch"), QStringLiteral("-nx"),
                  QStringLiteral("-ex"), QStringLiteral("thread apply all bt 30")});
    if (!g.waitForFinished(60000)) {
        g.kill();
        g.waitForFinished();
    }
    return QString::fromUtf8(g.readAllStandardOutput());
}

// Runs any program (e.g. imudesk-cli under prlimit) and collects its exit code and output.
// One that has not ended within timeoutMs is killed: err then starts with "timed out" and
// has what it printed so far and where its threads were.
inline CliResult runProgram(const QString &program, const QStringList &args, int timeoutMs)
{
    QProcess p;
    p.start(program, args);
    CliResult r;
    if (!p.waitForFinished(timeoutMs)) {
        const QString stacks = stacksOf(p.processId());
        p.kill();
        p.waitForFinished();
        r.out = QString::fromUtf8(p.readAllStandardOutput());
        r.err = QStringLiteral("timed out after %1 ms: %2 %3\n-- its stderr so far:\n%4\n-- its stdout so far:\n%5\n"
                               "-- its threads:\n%6")
                    .arg(timeoutMs)
                    .arg(program, args.join(QLatin1Char(' ')), QString::fromUtf8(p.readAllStandardError()), r.out,
                         stacks);
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
