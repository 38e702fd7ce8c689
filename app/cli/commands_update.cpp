// imudesk-cli update: serial firmware update (KBOOT) with a progress line; and the
// simulator's --flash-dump option.
#include "cli_context.h"
#include "update_common.h"

#include "core/firmware/firmware_updater.h"
#include "sim/pty_simulator.h"

#include <QCommandLineParser>
#include <QFile>

namespace imudesk::cli {

int cmdUpdate(const QStringList &args)
{
    using firmware::UpdateFlow;
    if (isCanUpdate(args))
        return cmdUpdateCan(args);
    QCommandLineParser p;
    p.addPositionalArgument(QStringLiteral("PORT"), QStringLiteral("Serial port of the module."));
    p.addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("Firmware: Intel HEX, or .bin with --bin-start."));
    p.addOption(QCommandLineOption(QStringLiteral("baud"), QStringLiteral("The module's current baud rate (default 115200)."),
                                   QStringLiteral("B"), QStringLiteral("115200")));
    addUpdateCommonOptions(p);
    const QString usage = QStringLiteral("imudesk-cli update PORT FILE [--baud B] [--json] [--bin-start ADDR] "
                                         "[--flash-layout START:SIZE:APP] [--no-finish]");
    if (!parseArgs(p, args, usage))
        return ExitUsage;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2)
        return fail(QStringLiteral("update needs PORT and FILE (usage: %1)").arg(usage), ExitUsage);
    UpdateFlow::Options o;
    bool ok = false;
    o.baud = p.value(QStringLiteral("baud")).toInt(&ok);
    if (!ok || o.baud <= 0)
        return fail(QStringLiteral("--baud needs a baud rate such as 115200"), ExitUsage);
    UpdateCommonOptions common;
    if (const int code = readUpdateCommonOptions(p, common, o); code != ExitOk)
        return code;
    const auto image = loadUpdateImage(pos[1], common, &UpdateFlow::checkImage);
    if (!image)
        return ExitFailure;
    firmware::FirmwareUpdater updater;
    runUpdate(updater, common.json, [&] { updater.start(pos[0], *image, o); });
    const auto &r = updater.result();
    if (common.json) {
        QJsonObject res = updateResultJson(r.ok, UpdateFlow::stateName(r.finalState), r.message, r.verifyMethod,
                                           r.resumed);
        res.insert(QStringLiteral("bytes_written"), qint64(r.bytesWritten));
        res.insert(QStringLiteral("write_seconds"), r.writeSeconds);
        if (r.before && r.before->firmware)
            res.insert(QStringLiteral("firmware_before"), QString::fromStdString(r.before->firmware->toString()));
        if (r.after && r.after->firmware)
            res.insert(QStringLiteral("firmware_after"), QString::fromStdString(r.after->firmware->toString()));
        jsonLine(res);
    }
    return updateExit(r.ok, r.finalState == UpdateFlow::State::Cancelled && interrupted(), r.message, common.json);
}

void addFlashDumpOption(QCommandLineParser &p)
{
    p.addOption(QCommandLineOption(QStringLiteral("flash-dump"),
                                   QStringLiteral("On exit, write the simulated application flash (0x8000 to the end) "
                                                  "to FILE."),
                                   QStringLiteral("FILE")));
}

int writeFlashDump(sim::PtySimulator &simulator, const QCommandLineParser &p)
{
    if (!p.isSet(QStringLiteral("flash-dump")))
        return ExitOk;
    std::vector<uint8_t> area;
    simulator.withDevice([&area](sim::HipnucSimulator &s) { area = s.bootloader().applicationArea(); });
    QFile f(p.value(QStringLiteral("flash-dump")));
    if (!f.open(QIODevice::WriteOnly)
        || f.write(reinterpret_cast<const char *>(area.data()), qint64(area.size())) != qint64(area.size()))
        return fail(QStringLiteral("cannot write the flash dump %1: %2").arg(f.fileName(), f.errorString()));
    return ExitOk;
}

} // namespace imudesk::cli
