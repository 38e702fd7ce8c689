// imudesk-cli update --can PLUGIN:INTERFACE [--node N] [--bitrate B] FILE: firmware update over
// CANopen SDO (hipnuc-protocol-notes 4.5) with a progress line; and the CAN simulator's
// --flash-dump.
#include "cli_context.h"

#include "firmware/can_firmware_updater.h"
#include "protocol/ihex/intel_hex_loader.h"
#include "sim/can_sim_device.h"

#include <QCommandLineParser>
#include <QEventLoop>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>

#include <cstdio>
#include <optional>

namespace imudesk::cli {

namespace {

using firmware::CanFirmwareUpdater;
using firmware::CanUpdateFlow;

std::optional<uint32_t> parseNumber(const QString &text)
{
    bool ok = false;
    const qulonglong v = text.trimmed().toULongLong(&ok, 0);
    if (!ok || v > 0xFFFFFFFFull)
        return std::nullopt;
    return uint32_t(v);
}

void jsonLine(const QJsonObject &o)
{
    out(QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact)));
    std::fflush(stdout);
}

QString hex32(uint32_t v)
{
    return QStringLiteral("0x") + QString::number(v, 16).toUpper().rightJustified(8, QLatin1Char('0'));
}

} // namespace

bool isCanUpdate(const QStringList &args)
{
    for (const QString &a : args)
        if (a == QLatin1String("--can") || a.startsWith(QLatin1String("--can=")))
            return true;
    return false;
}

int cmdUpdateCan(const QStringList &args)
{
    QCommandLineParser p;
    p.addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("Firmware: Intel HEX, or .bin with --bin-start."));
    p.addOption(QCommandLineOption(QStringLiteral("can"), QStringLiteral("CAN bus as PLUGIN:INTERFACE, e.g. socketcan:can0."),
                                   QStringLiteral("SPEC")));
    p.addOption(QCommandLineOption(QStringLiteral("node"), QStringLiteral("CANopen node ID of the module, 1..127 (default 8)."),
                                   QStringLiteral("N"), QStringLiteral("8")));
    p.addOption(QCommandLineOption(QStringLiteral("bitrate"),
                                   QStringLiteral("CAN bit rate in bit/s (default: leave the interface's setting)."),
                                   QStringLiteral("B"), QStringLiteral("0")));
    p.addOption(QCommandLineOption(QStringLiteral("json"), QStringLiteral("JSON lines: states, progress, log, result.")));
    p.addOption(QCommandLineOption(QStringLiteral("bin-start"), QStringLiteral("Start address of a .bin file."),
                                   QStringLiteral("ADDR")));
    p.addOption(QCommandLineOption(QStringLiteral("flash-layout"),
                                   QStringLiteral("Flash start, size and application start (e.g. 0:0x80000:0x8000): "
                                                  "the image is checked against it before anything is sent."),
                                   QStringLiteral("START:SIZE:APP")));
    p.addOption(QCommandLineOption(QStringLiteral("no-finish"),
                                   QStringLiteral("Do not finish an interrupted update found in the bootloader.")));
    const QString usage = QStringLiteral("imudesk-cli update --can PLUGIN:INTERFACE [--node N] [--bitrate B] FILE "
                                         "[--json] [--bin-start ADDR] [--flash-layout START:SIZE:APP] [--no-finish]");
    if (!parseArgs(p, args, usage))
        return ExitUsage;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 1)
        return fail(QStringLiteral("update --can needs exactly one FILE (usage: %1)").arg(usage), ExitUsage);
    const QString spec = p.value(QStringLiteral("can"));
    const int colon = spec.indexOf(QLatin1Char(':'));
    if (colon <= 0 || colon == spec.size() - 1)
        return fail(QStringLiteral("--can needs PLUGIN:INTERFACE, e.g. socketcan:can0 or virtualcan:can0"), ExitUsage);
    const bool json = p.isSet(QStringLiteral("json"));
    CanUpdateFlow::Options o;
    const auto node = parseNumber(p.value(QStringLiteral("node")));
    if (!node || *node < 1 || *node > 127)
        return fail(QStringLiteral("--node must be a CANopen node ID 1..127"), ExitUsage);
    o.node = uint8_t(*node);
    const auto bitrate = parseNumber(p.value(QStringLiteral("bitrate")));
    if (!bitrate || *bitrate > 8000000)
        return fail(QStringLiteral("--bitrate needs a bit rate in bit/s such as 500000"), ExitUsage);
    o.finishInterrupted = !p.isSet(QStringLiteral("no-finish"));
    std::optional<uint32_t> binStart;
    if (p.isSet(QStringLiteral("bin-start"))) {
        binStart = parseNumber(p.value(QStringLiteral("bin-start")));
        if (!binStart)
            return fail(QStringLiteral("--bin-start needs an address such as 0x8000"), ExitUsage);
    }
    if (p.isSet(QStringLiteral("flash-layout"))) {
        const QStringList parts = p.value(QStringLiteral("flash-layout")).split(QLatin1Char(':'));
        std::optional<uint32_t> a, b, c;
        if (parts.size() == 3) {
            a = parseNumber(parts[0]);
            b = parseNumber(parts[1]);
            c = parseNumber(parts[2]);
        }
        if (!a || !b || !c || *b == 0)
            return fail(QStringLiteral("--flash-layout needs START:SIZE:APP, e.g. 0:0x80000:0x8000"), ExitUsage);
        o.layout = firmware::UpdateFlow::FlashLayout{*a, *b, *c};
    }

    // The file is checked completely before the bus is opened.
    const auto loaded = protocol::ihex::IntelHexLoader::loadFile(pos[0], binStart);
    if (!loaded.ok())
        return fail(QStringLiteral("%1: %2 (nothing was sent to the module)").arg(pos[0], loaded.error));
    const auto &image = *loaded.image;
    if (const QString e = CanUpdateFlow::checkImage(image, o.layout); !e.isEmpty())
        return fail(QStringLiteral("%1: %2 (nothing was sent to the module)").arg(pos[0], e));
    if (json)
        jsonLine(QJsonObject{{QStringLiteral("event"), QStringLiteral("image")},
                             {QStringLiteral("start"), hex32(image.startAddress)},
                             {QStringLiteral("size"), qint64(image.size())},
                             {QStringLiteral("crc32"), hex32(image.crc32())}});
    else
        out(QStringLiteral("image %1: %2 bytes at %3, CRC-32 %4")
                .arg(pos[0])
                .arg(image.size())
                .arg(hex32(image.startAddress), hex32(image.crc32())));

    CanFirmwareUpdater updater;
    bool done = false;
    bool progressShown = false;
    QString stateName;
    QObject ctx;
    QObject::connect(&updater, &CanFirmwareUpdater::stateChanged, &ctx, [&](int, const QString &name) {
        stateName = name;
        if (json)
            jsonLine(QJsonObject{{QStringLiteral("event"), QStringLiteral("state")}, {QStringLiteral("state"), name}});
    });
    QObject::connect(&updater, &CanFirmwareUpdater::logMessage, &ctx, [&](const QString &line) {
        if (json) {
            jsonLine(QJsonObject{{QStringLiteral("event"), QStringLiteral("log")}, {QStringLiteral("text"), line}});
            return;
        }
        if (progressShown)
            std::fputs("\n", stderr);
        progressShown = false;
        std::fprintf(stderr, "%s\n", line.toLocal8Bit().constData());
    });
    QObject::connect(&updater, &CanFirmwareUpdater::progressChanged, &ctx,
                     [&](qulonglong d, qulonglong total, double bps, double left) {
                         if (json) {
                             jsonLine(QJsonObject{{QStringLiteral("event"), QStringLiteral("progress")},
                                                  {QStringLiteral("state"), stateName},
                                                  {QStringLiteral("done"), qint64(d)},
                                                  {QStringLiteral("total"), qint64(total)},
                                                  {QStringLiteral("bytes_per_s"), qRound(bps)},
                                                  {QStringLiteral("seconds_left"), left < 0 ? -1.0 : qRound(left * 10) / 10.0}});
                             return;
                         }
                         const QString line = QStringLiteral("\r%1: %2/%3 bytes (%4 %), %5 B/s, %6 s left   ")
                                                  .arg(stateName)
                                                  .arg(d)
                                                  .arg(total)
                                                  .arg(total ? int(100 * d / total) : 0)
                                                  .arg(qRound(bps))
                                                  .arg(left < 0 ? QStringLiteral("?") : QString::number(left, 'f', 0));
                         std::fputs(line.toLocal8Bit().constData(), stderr);
                         progressShown = true;
                     });
    QObject::connect(&updater, &CanFirmwareUpdater::finished, &ctx, [&] { done = true; });
    updater.start(CanFirmwareUpdater::Bus{spec.left(colon), spec.mid(colon + 1), int(*bitrate)}, image, o);
    waitFor([&] { return done || interrupted(); }, -1);
    if (!done) {
        // Interrupted: the flow aborts the transfer between segments and leaves the module in its bootloader.
        updater.cancel();
        QEventLoop loop;
        QObject::connect(&updater, &CanFirmwareUpdater::finished, &loop, &QEventLoop::quit);
        if (!done)
            loop.exec();
    }
    if (progressShown)
        std::fputs("\n", stderr);
    const auto &r = updater.result();
    if (json) {
        QJsonObject res{{QStringLiteral("event"), QStringLiteral("result")},
                        {QStringLiteral("ok"), r.ok},
                        {QStringLiteral("state"), CanUpdateFlow::stateName(r.finalState)},
                        {QStringLiteral("message"), r.message},
                        {QStringLiteral("verified"), r.verifyMethod},
                        {QStringLiteral("resumed"), r.resumed},
                        {QStringLiteral("bytes_sent"), qint64(r.bytesSent)},
                        {QStringLiteral("download_seconds"), r.downloadSeconds}};
        if (r.bootloaderCrc)
            res.insert(QStringLiteral("bootloader_crc32"), hex32(*r.bootloaderCrc));
        if (r.before)
            res.insert(QStringLiteral("firmware_before"), QString::fromStdString(r.before->toString()));
        if (r.after)
            res.insert(QStringLiteral("firmware_after"), QString::fromStdString(r.after->toString()));
        jsonLine(res);
    }
    if (r.finalState == CanUpdateFlow::State::Cancelled && interrupted())
        return fail(r.message, ExitInterrupted);
    if (!r.ok)
        return fail(r.message);
    if (!json)
        out(r.message);
    return ExitOk;
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
