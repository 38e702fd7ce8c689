#pragma once
// A long-running imudesk-cli process (IMUDESK_CLI_PATH) for the integration tests, e.g.
// `simulate --can ...`: started and waited on until its stdout shows that it is ready, and
// stopped with SIGTERM (killed if it does not end).
#include <QByteArray>
#include <QElapsedTimer>
#include <QProcess>
#include <QString>
#include <QStringList>

namespace imudesk::test {

// Starts imudesk-cli with args in p; true once its stdout contains ready within timeoutMs.
inline bool startCliUntil(QProcess &p, const QStringList &args, const QByteArray &ready, int timeoutMs = 5000)
{
    p.start(QString::fromUtf8(IMUDESK_CLI_PATH), args);
    if (!p.waitForStarted(timeoutMs))
        return false;
    QElapsedTimer t;
    t.start();
    QByteArray seen;
    while (t.elapsed() < timeoutMs) {
        p.waitForReadyRead(100);
        seen += p.readAllStandardOutput();
        if (seen.contains(ready))
            return true;
    }
    return false;
}

// A simulated HiPNUC module on a pseudo-terminal at 921600 baud (`imudesk-cli simulate --pty`,
// seed: its serial number and noise), told to send `log` (e.g. "LOG HI91 ONTIME 0.001"); the
// pty's path, or empty when it did not start or did not take the command.
inline QString startPtySimulator(QProcess &p, int seed, const QString &log)
{
    p.start(QString::fromUtf8(IMUDESK_CLI_PATH), {QStringLiteral("simulate"), QStringLiteral("--pty"), QStringLiteral("--baud"),
                                                   QStringLiteral("921600"), QStringLiteral("--seed"), QString::number(seed)});
    if (!p.waitForStarted(10000))
        return {};
    QElapsedTimer t;
    t.start();
    while (!p.canReadLine() && t.elapsed() < 30000)
        p.waitForReadyRead(100);
    const QString first = QString::fromUtf8(p.readLine()).trimmed();
    if (!first.startsWith(QLatin1String("pty: /dev/")))
        return {};
    const QString pty = first.mid(5);
    QProcess send;
    send.start(QString::fromUtf8(IMUDESK_CLI_PATH), {QStringLiteral("send"), pty, QStringLiteral("--baud"), QStringLiteral("921600"), log});
    if (!send.waitForFinished(15000) || send.exitCode() != 0)
        return {};
    return pty;
}

// Terminates p and waits for it; kills it when it has not ended within graceMs.
inline void stopCli(QProcess &p, int graceMs = 5000)
{
    if (p.state() == QProcess::NotRunning)
        return;
    p.terminate();
    if (!p.waitForFinished(graceMs))
        p.kill();
    p.waitForFinished();
}

} // namespace imudesk::test
