// imudesk-cli update: serial firmware update (KBOOT) with a progress line; and the
// simulator's --flash-dump option.
#include "cli_context.h"

#include "firmware/firmware_updater.h"
#include "protocol/ihex/intel_hex_loader.h"
#include "sim/pty_simulator.h"

#include <QCommandLineParser>
#include <QEventLoop>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>

#include <cstdio>
#include <optional>

namespace imudesk::cli {

namespace {

using firmware::UpdateFlow;

std::optional<uint32_t> parseAddress(const QString &text)
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

int cmdUpdate(const QStringList &args)
{
    if (isCanUpdate(args))
        return cmdUpdateCan(args);
    QCommandLineParser p;
    p.addPositionalArgument(QStringLiteral("PORT"), QStringLiteral("Serial port of the module."));
    p.addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("Firmware: Intel HEX, or .bin with --bin-start."));
    p.addOption(QCommandLineOption(QStringLiteral("baud"), QStringLiteral("The module's current baud rate (default 115200)."),
                                   QStringLiteral("B"), QStringLiteral("115200")));
    p.addOption(QCommandLineOption(QStringLiteral("json"), QStringLiteral("JSON lines: states, progress, log, result.")));
    p.addOption(QCommandLineOption(QStringLiteral("bin-start"), QStringLiteral("Start address of a .bin file."),
                                   QStringLiteral("ADDR")));
    p.addOption(QCommandLineOption(QStringLiteral("flash-layout"),
                                   QStringLiteral("Flash start, size and application start (e.g. 0:0x80000:0x8000): "
                                                  "the image is checked against it before anything is sent."),
                                   QStringLiteral("START:SIZE:APP")));
    p.addOption(QCommandLineOption(QStringLiteral("no-finish"),
                                   QStringLiteral("Do not finish an interrupted update found in the bootloader.")));
    const QString usage = QStringLiteral("imudesk-cli update PORT FILE [--baud B] [--json] [--bin-start ADDR] "
                                         "[--flash-layout START:SIZE:APP] [--no-finish]");
    if (!parseArgs(p, args, usage))
        return ExitUsage;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2)
        return fail(QStringLiteral("update needs PORT and FILE (usage: %1)").arg(usage), ExitUsage);
    const bool json = p.isSet(QStringLiteral("json"));
    UpdateFlow::Options o;
    bool ok = false;
    o.baud = p.value(QStringLiteral("baud")).toInt(&ok);
    if (!ok || o.baud <= 0)
        return fail(QStringLiteral("--baud needs a baud rate such as 115200"), ExitUsage);
    o.finishInterrupted = !p.isSet(QStringLiteral("no-finish"));
    std::optional<uint32_t> binStart;
    if (p.isSet(QStringLiteral("bin-start"))) {
        binStart = parseAddress(p.value(QStringLiteral("bin-start")));
        if (!binStart)
            return fail(QStringLiteral("--bin-start needs an address such as 0x8000"), ExitUsage);
    }
    if (p.isSet(QStringLiteral("flash-layout"))) {
        const QStringList parts = p.value(QStringLiteral("flash-layout")).split(QLatin1Char(':'));
        std::optional<uint32_t> a, b, c;
        if (parts.size() == 3) {
            a = parseAddress(parts[0]);
            b = parseAddress(parts[1]);
            c = parseAddress(parts[2]);
        }
        if (!a || !b || !c || *b == 0)
            return fail(QStringLiteral("--flash-layout needs START:SIZE:APP, e.g. 0:0x80000:0x8000"), ExitUsage);
        o.layout = UpdateFlow::FlashLayout{*a, *b, *c};
    }

    // The file is checked completely before the port is opened.
    const auto loaded = protocol::ihex::IntelHexLoader::loadFile(pos[1], binStart);
    if (!loaded.ok())
        return fail(QStringLiteral("%1: %2 (nothing was sent to the module)").arg(pos[1], loaded.error));
    const auto &image = *loaded.image;
    if (const QString e = UpdateFlow::checkImage(image, o.layout); !e.isEmpty())
        return fail(QStringLiteral("%1: %2 (nothing was sent to the module)").arg(pos[1], e));
    if (json)
        jsonLine(QJsonObject{{QStringLiteral("event"), QStringLiteral("image")},
                             {QStringLiteral("start"), hex32(image.startAddress)},
                             {QStringLiteral("size"), qint64(image.size())},
                             {QStringLiteral("crc32"), hex32(image.crc32())}});
    else
        out(QStringLiteral("image %1: %2 bytes at %3, CRC-32 %4")
                .arg(pos[1])
                .arg(image.size())
                .arg(hex32(image.startAddress), hex32(image.crc32())));

    firmware::FirmwareUpdater updater;
    bool done = false;
    bool progressShown = false;
    QString stateName;
    QObject ctx;
    QObject::connect(&updater, &firmware::FirmwareUpdater::stateChanged, &ctx, [&](int, const QString &name) {
        stateName = name;
        if (json)
            jsonLine(QJsonObject{{QStringLiteral("event"), QStringLiteral("state")}, {QStringLiteral("state"), name}});
    });
    QObject::connect(&updater, &firmware::FirmwareUpdater::logMessage, &ctx, [&](const QString &line) {
        if (json) {
            jsonLine(QJsonObject{{QStringLiteral("event"), QStringLiteral("log")}, {QStringLiteral("text"), line}});
            return;
        }
        if (progressShown)
            std::fputs("\n", stderr);
        progressShown = false;
        std::fprintf(stderr, "%s\n", line.toLocal8Bit().constData());
    });
    QObject::connect(&updater, &firmware::FirmwareUpdater::progressChanged, &ctx,
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
    QObject::connect(&updater, &firmware::FirmwareUpdater::finished, &ctx, [&] { done = true; });
    updater.start(pos[0], image, o);
    waitFor([&] { return done || interrupted(); }, -1);
    if (!done) {
        // Interrupted: stop between packets and wait for the flow to leave the module recoverable
        // (waitFor() returns at once once a signal has arrived, so wait on the updater itself).
        updater.cancel();
        QEventLoop loop;
        QObject::connect(&updater, &firmware::FirmwareUpdater::finished, &loop, &QEventLoop::quit);
        if (!done)
            loop.exec();
    }
    if (progressShown)
        std::fputs("\n", stderr);
    const auto &r = updater.result();
    if (json) {
        QJsonObject res{{QStringLiteral("event"), QStringLiteral("result")},
                        {QStringLiteral("ok"), r.ok},
                        {QStringLiteral("state"), UpdateFlow::stateName(r.finalState)},
                        {QStringLiteral("message"), r.message},
                        {QStringLiteral("verified"), r.verifyMethod},
                        {QStringLiteral("resumed"), r.resumed},
                        {QStringLiteral("bytes_written"), qint64(r.bytesWritten)},
                        {QStringLiteral("write_seconds"), r.writeSeconds}};
        if (r.before && r.before->firmware)
            res.insert(QStringLiteral("firmware_before"), QString::fromStdString(r.before->firmware->toString()));
        if (r.after && r.after->firmware)
            res.insert(QStringLiteral("firmware_after"), QString::fromStdString(r.after->firmware->toString()));
        jsonLine(res);
    }
    if (r.finalState == UpdateFlow::State::Cancelled && interrupted())
        return fail(r.message, ExitInterrupted);
    if (!r.ok)
        return fail(r.message);
    if (!json)
        out(r.message);
    return ExitOk;
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
