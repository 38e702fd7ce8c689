#pragma once
// Shared plumbing for imudesk-cli commands: output streams, exit codes, waiting on
// a DeviceSession with an event loop, and SIGINT/SIGTERM handling.
#include "device/device_session.h"
#include "sim/motion_model.h"

#include <QCommandLineParser>
#include <QString>
#include <QStringList>

#include <functional>

namespace imudesk::sim {
class PtySimulator;
class CanSimDevice;
}

namespace imudesk::cli {

// ExitUnconfirmed: a setting was written but the module's read-back did not say whether it
// was taken (config set, profile apply); ExitFailure covers "the module holds another value".
// ExitNotFound: a query ran and found nothing (results serial SN of no module, a yield of no
// module, an export of no record), as grep says "no match" apart from an error.
enum ExitCode { ExitOk = 0, ExitFailure = 1, ExitUsage = 2, ExitUnconfirmed = 3, ExitNotFound = 4, ExitInterrupted = 130 };

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
int cmdModbus(const QStringList &args);
// commands_modbus.cpp: `simulate --pty --modbus [--device hec495] [--id N]`.
void addModbusSimulateOptions(QCommandLineParser &p);
int simulateModbus(const QCommandLineParser &p);
int cmdConfig(const QStringList &args); // commands_config.cpp
int cmdRecord(const QStringList &args);
int cmdExport(const QStringList &args);
int cmdAlign(const QStringList &args); // commands_session.cpp
int cmdImport(const QStringList &args);
int cmdRepair(const QStringList &args);
int cmdBridge(const QStringList &args); // commands_bridge.cpp
int cmdResults(const QStringList &args); // commands_results.cpp
int cmdAnalyze(const QStringList &args);
int cmdUpdate(const QStringList &args);
// commands_update_can.cpp: update --can PLUGIN:INTERFACE (cmdUpdate hands over when --can is given),
// and the CAN simulator's --flash-dump.
bool isCanUpdate(const QStringList &args);
int cmdUpdateCan(const QStringList &args);
int writeCanFlashDump(sim::CanSimDevice &device, const QString &path);

// simulate --flash-dump FILE (commands_update.cpp)
void addFlashDumpOption(QCommandLineParser &p);
int writeFlashDump(sim::PtySimulator &simulator, const QCommandLineParser &p);
int cmdHec495(const QStringList &args);
// commands_hec495.cpp: what probe prints for an HEC495 it found, and simulate --device hec495.
void printHec495Probe(const QString &port, int baud, int address, bool json);
int simulateHec495(const QCommandLineParser &p);
int cmdCan(const QStringList &args);
// simulate --can PLUGIN:INTERFACE: serves a simulated CAN device until SIGINT/SIGTERM (commands_can.cpp).
int simulateCan(const QString &canSpec, const QString &protocol, const QString &deviceKind, int node, sim::Motion motion,
                uint64_t seed, const QString &firmware, bool canFd, const QString &flashDump = QString());
int cmdMagcal(const QStringList &args);
int cmdCalibrate(const QStringList &args); // commands_calibrate.cpp
int cmdStation(const QStringList &args);   // commands_station.cpp
int cmdVerify(const QStringList &args);    // commands_verify.cpp
int cmdDiscover(const QStringList &args);  // commands_discover.cpp

// --from and --to (seconds >= 0) into *from and *to where given; false (usage printed) on a bad value.
bool fromToOptions(const QCommandLineParser &p, double *from, double *to);
// Parses args with the given parser; on error prints it and returns false.
bool parseArgs(QCommandLineParser &p, const QStringList &args, const QString &usage);

} // namespace imudesk::cli
