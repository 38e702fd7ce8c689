#include "cli_context.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <atomic>
#include <csignal>
#include <cstdio>

namespace imudesk::cli {

namespace {
std::atomic<bool> g_interrupted{false};

extern "C" void onSignal(int)
{
    g_interrupted.store(true);
}
} // namespace

int fail(const QString &message, int code)
{
    std::fprintf(stderr, "imudesk-cli: %s\n", message.simplified().toLocal8Bit().constData());
    std::fflush(stderr);
    return code;
}

void out(const QString &line)
{
    std::fputs(line.toUtf8().constData(), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
}

void outRaw(const std::string &s)
{
    std::fwrite(s.data(), 1, s.size(), stdout);
    std::fputc('\n', stdout);
}

void installSignalHandlers()
{
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
}

bool interrupted()
{
    return g_interrupted.load();
}

bool waitFor(const std::function<bool()> &pred, int timeoutMs)
{
    QElapsedTimer clock;
    clock.start();
    while (!pred()) {
        if (interrupted() || (timeoutMs >= 0 && clock.elapsed() >= timeoutMs))
            return false;
        QEventLoop loop;
        QTimer::singleShot(10, &loop, &QEventLoop::quit);
        loop.exec();
    }
    return true;
}

bool connectSession(device::DeviceSession &session, const QString &port, int baud, model::DeviceIdentity *identity,
                    int *detectedBaud, QString *error)
{
    bool done = false;
    bool ok = false;
    QString message;
    int found = baud;
    auto c1 = QObject::connect(&session, &device::DeviceSession::identityChanged,
                               [&](const model::DeviceIdentity &id) {
                                   if (identity)
                                       *identity = id;
                               });
    auto c2 = QObject::connect(&session, &device::DeviceSession::baudDetected, [&](int b) { found = b; });
    auto c3 = QObject::connect(&session, &device::DeviceSession::stateChanged,
                               [&](device::SessionState s, const QString &detail) {
                                   if (s == device::SessionState::Connected) {
                                       ok = true;
                                       done = true;
                                   } else if (s == device::SessionState::Failed
                                              || s == device::SessionState::Disconnected) {
                                       message = detail;
                                       done = true;
                                   }
                               });
    session.open(port, baud);
    // Auto-detection visits at most 10 rates (~0.7 s each); leave room.
    waitFor([&] { return done; }, 20000);
    if (ok && baud > 0)
        waitFor([&] { return !session.identityPending(); }, 10000); // the identity query runs after Connected
    QObject::disconnect(c1);
    QObject::disconnect(c2);
    QObject::disconnect(c3);
    if (detectedBaud)
        *detectedBaud = found;
    if (!ok) {
        if (error)
            *error = interrupted() ? QStringLiteral("interrupted")
                                   : (message.isEmpty() ? QStringLiteral("timed out opening %1").arg(port) : message);
        return false;
    }
    return true;
}

bool fromToOptions(const QCommandLineParser &p, double *from, double *to)
{
    for (const char *name : {"from", "to"}) {
        if (!p.isSet(QLatin1String(name)))
            continue;
        bool ok = false;
        const double v = p.value(QLatin1String(name)).toDouble(&ok);
        if (!ok || v < 0) {
            fail(QStringLiteral("--%1 needs seconds >= 0").arg(QLatin1String(name)), ExitUsage);
            return false;
        }
        *(name[0] == 'f' ? from : to) = v;
    }
    return true;
}

bool parseArgs(QCommandLineParser &p, const QStringList &args, const QString &usage)
{
    p.addHelpOption();
    if (!p.parse(args)) {
        fail(p.errorText() + QStringLiteral(" (usage: ") + usage + QLatin1Char(')'), ExitUsage);
        return false;
    }
    if (p.isSet(QStringLiteral("help"))) {
        out(QStringLiteral("usage: ") + usage);
        // Qt's own first line names the program alone ("Usage: /usr/bin/imudesk-cli [options]
        // FILE"), not the command: the usage above says it, so that line goes.
        QString help = p.helpText();
        if (help.startsWith(QLatin1String("Usage:")))
            help = help.mid(help.indexOf(QLatin1Char('\n')) + 1);
        std::fputs(help.toUtf8().constData(), stdout);
        std::exit(ExitOk);
    }
    return true;
}

} // namespace imudesk::cli
