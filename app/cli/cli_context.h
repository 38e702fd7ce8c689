#pragma once
// Shared plumbing for imudesk-cli commands: output streams, exit codes, waiting on
// a DeviceSession with an event loop, and SIGINT/SIGTERM handling.
#include "device/device_session.h"

#include <QCommandLineParser>
#include <QString>
#include <QStringList>

#include <functional>

namespace imudesk::cli {

enum ExitCode { ExitOk = 0, ExitFailure = 1, ExitUsage = 2, ExitInterrupted = 130 };

// Writes a one-line error "imudesk-cli: <message>" to stderr and returns ExitFailure.
int fail(const QString &message, int code = ExitFailure);
void out(const QString &line);      // stdout, one line
void outRaw(const std::string &s);  // stdout, as is (plus newline)

// Installs SIGINT/SIGTERM handlers; interrupted() turns true once one arrives.
void installSignalHandlers();
bool interrupted();

// Runs the event loop until pred() is true, the timeout passes or a signal arrives.
// Returns true when pred() became true.
bool waitFor(const std::function<bool()> &pred, int timeoutMs);

// Opens a session and waits until it is connected (identity read) or failed.
// On failure returns false with a message that says what to do.
bool connectSession(device::DeviceSession &session, const QString &port, int baud, model::DeviceIdentity *identity,
                    int *detectedBaud, QString *error);

using CommandFn = int (*)(const QStringList &args);
int cmdPorts(const QStringList &args);
int cmdProbe(const QStringList &args);
int cmdRead(const QStringList &args);
int cmdSend(const QStringList &args);
int cmdDecode(const QStringList &args);
int cmdSimulate(const QStringList &args);
int cmdMagcal(const QStringList &args);

// Parses args with the given parser; on error prints it and returns false.
bool parseArgs(QCommandLineParser &p, const QStringList &args, const QString &usage);

} // namespace imudesk::cli
