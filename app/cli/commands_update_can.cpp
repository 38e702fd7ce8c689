// imudesk-cli update --can PLUGIN:INTERFACE [--node N] [--bitrate B] FILE: firmware update over
// CANopen SDO (hipnuc-protocol-notes 4.5) with a progress line; and the CAN simulator's
// --flash-dump.
#include "cli_context.h"
#include "update_common.h"

#include "core/firmware/can_firmware_updater.h"
#include "io/can_transport.h"
#include "sim/can_sim_device.h"

#include <QCommandLineParser>
#include <QFile>

namespace imudesk::cli {

bool isCanUpdate(const QStringList &args)
{
    for (const QString &a : args)
        if (a == QLatin1String("--can") || a.startsWith(QLatin1String("--can=")))
            return true;
    return false;
}

int cmdUpdateCan(const QStringList &args)
{
    using firmware::CanFirmwareUpdater;
    using firmware::CanUpdateFlow;
    QCommandLineParser p;
    p.addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("Firmware: Intel HEX, or .bin with --bin-start."));
    p.addOption(QCommandLineOption(QStringLiteral("can"), QStringLiteral("CAN bus as PLUGIN:INTERFACE, e.g. socketcan:can0."),
                                   QStringLiteral("SPEC")));
    p.addOption(QCommandLineOption(QStringLiteral("node"), QStringLiteral("CANopen node ID of the module, 1..127 (default 8)."),
                                   QStringLiteral("N"), QStringLiteral("8")));
    p.addOption(QCommandLineOption(QStringLiteral("bitrate"),
                                   QStringLiteral("CAN bit rate in bit/s (default: leave the interface's setting)."),
                                   QStringLiteral("B"), QStringLiteral("0")));
    addUpdateCommonOptions(p);
    const QString usage = QStringLiteral("imudesk-cli update --can PLUGIN:INTERFACE [--node N] [--bitrate B] FILE "
                                         "[--json] [--bin-start ADDR] [--flash-layout START:SIZE:APP] [--no-finish]");
    if (!parseArgs(p, args, usage))
        return ExitUsage;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 1)
        return fail(QStringLiteral("update --can needs exactly one FILE (usage: %1)").arg(usage), ExitUsage);
    const QString spec = p.value(QStringLiteral("can"));
    const io::CanAddress address = io::CanAddress::parse(spec);
    if (!address.complete())
        return fail(QStringLiteral("--can needs PLUGIN:INTERFACE, e.g. socketcan:can0 or virtualcan:can0"), ExitUsage);
    CanUpdateFlow::Options o;
    const auto node = parseNumber(p.value(QStringLiteral("node")));
    if (!node || *node < 1 || *node > 127)
        return fail(QStringLiteral("--node must be a CANopen node ID 1..127"), ExitUsage);
    o.node = uint8_t(*node);
    const auto bitrate = parseNumber(p.value(QStringLiteral("bitrate")));
    if (!bitrate || *bitrate > 8000000)
        return fail(QStringLiteral("--bitrate needs a bit rate in bit/s such as 500000"), ExitUsage);
    UpdateCommonOptions common;
    if (const int code = readUpdateCommonOptions(p, common, o); code != ExitOk)
        return code;
    const auto image = loadUpdateImage(pos[0], common, &CanUpdateFlow::checkImage);
    if (!image)
        return ExitFailure;
    CanFirmwareUpdater updater;
    const CanFirmwareUpdater::Bus bus{address.plugin, address.interfaceName, int(*bitrate)};
    runUpdate(updater, common.json, [&] { updater.start(bus, *image, o); });
    const auto &r = updater.result();
    if (common.json) {
        QJsonObject res = updateResultJson(r.ok, CanUpdateFlow::stateName(r.finalState), r.message, r.verifyMethod,
                                           r.resumed);
        res.insert(QStringLiteral("bytes_sent"), qint64(r.bytesSent));
        res.insert(QStringLiteral("download_seconds"), r.downloadSeconds);
        if (r.bootloaderCrc)
            res.insert(QStringLiteral("bootloader_crc32"), hex32(*r.bootloaderCrc));
        if (r.before)
            res.insert(QStringLiteral("firmware_before"), QString::fromStdString(r.before->toString()));
        if (r.after)
            res.insert(QStringLiteral("firmware_after"), QString::fromStdString(r.after->toString()));
        jsonLine(res);
    }
    return updateExit(r.ok, r.finalState == CanUpdateFlow::State::Cancelled && interrupted(), r.message, common.json);
}

int writeCanFlashDump(sim::CanSimDevice &device, const QString &path)
{
    if (path.isEmpty())
        return ExitOk;
    const std::vector<uint8_t> area = device.bootloader().applicationArea();
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)
        || f.write(reinterpret_cast<const char *>(area.data()), qint64(area.size())) != qint64(area.size()))
        return fail(QStringLiteral("cannot write the flash dump %1: %2").arg(f.fileName(), f.errorString()));
    return ExitOk;
}

} // namespace imudesk::cli
