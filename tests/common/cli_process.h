#pragma once
// A long-running imudesk-cli process (IMUDESK_CLI_PATH) for the integration tests, e.g.
// `simulate --can ...`: started and waited on until its stdout shows that it is ready, and
// stopped with SIGTERM (killed if it does not end).
#include <QByteArray>
#include <QElapsedTimer>
#include <QProcess>
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
