#pragma once
// What `imudesk-cli update` (serial, KBOOT) and `update --can` (CANopen) share: number parsing,
// JSON lines, the common options (--json, --bin-start, --flash-layout, --no-finish), loading and
// checking the image before any link is opened, and driving an updater to its end with a
// progress line on stderr or JSON lines on stdout.
#include "core/firmware/update_flow.h"
#include "protocol/ihex/firmware_image.h"

#include <QJsonObject>
#include <QString>

#include <cstdint>
#include <functional>
#include <optional>

QT_BEGIN_NAMESPACE
class QCommandLineParser;
QT_END_NAMESPACE

namespace imudesk::firmware {
class UpdateRunner;
}

namespace imudesk::cli {

// A decimal or 0x-prefixed number up to 0xFFFFFFFF; nullopt otherwise.
std::optional<uint32_t> parseNumber(const QString &text);
// One compact JSON object as one stdout line, flushed at once.
void jsonLine(const QJsonObject &o);
// "0x0000ABCD".
QString hex32(uint32_t v);

struct UpdateCommonOptions {
    bool json = false;
    bool finishInterrupted = true;
    std::optional<uint32_t> binStart;
    std::optional<firmware::UpdateFlow::FlashLayout> layout;
};

// Adds --json, --bin-start, --flash-layout and --no-finish.
void addUpdateCommonOptions(QCommandLineParser &p);
// Reads those options; ExitOk, or ExitUsage after the error has been printed.
int readUpdateCommonOptions(const QCommandLineParser &p, UpdateCommonOptions &o);
// The same, and copies --no-finish and --flash-layout into a flow's options (UpdateFlow::Options,
// CanUpdateFlow::Options).
template <class FlowOptions>
int readUpdateCommonOptions(const QCommandLineParser &p, UpdateCommonOptions &o, FlowOptions &flow)
{
    const int code = readUpdateCommonOptions(p, o);
    flow.finishInterrupted = o.finishInterrupted;
    flow.layout = o.layout;
    return code;
}

// How a flow checks an image offline (against the flash layout if given): empty when fine.
using ImageCheck = std::function<QString(const protocol::ihex::FirmwareImage &,
                                         const std::optional<firmware::UpdateFlow::FlashLayout> &)>;
// Loads path (Intel HEX, or .bin at o.binStart), checks it and prints what it holds (a line, or
// an "image" JSON event). nullopt after the error has been printed (exit with ExitFailure).
std::optional<protocol::ihex::FirmwareImage> loadUpdateImage(const QString &path, const UpdateCommonOptions &o,
                                                             const ImageCheck &check);

// Connects to updater, calls start() and runs the event loop until the update has finished,
// printing states, progress and log lines. On SIGINT/SIGTERM it cancels the update and waits
// for the flow to leave the module recoverable.
void runUpdate(firmware::UpdateRunner &updater, bool json, const std::function<void()> &start);

// The start of the "result" JSON event; the caller adds the link's own keys.
QJsonObject updateResultJson(bool ok, const QString &state, const QString &message, const QString &verified,
                             bool resumed);
// The exit code of a finished update: ExitInterrupted when a signal cancelled it, ExitFailure with
// the message on stderr when it failed, ExitOk with the message on stdout (unless json) otherwise.
int updateExit(bool ok, bool cancelledBySignal, const QString &message, bool json);

} // namespace imudesk::cli
