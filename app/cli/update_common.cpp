#include "update_common.h"

#include "cli_context.h"
#include "core/firmware/update_runner.h"
#include "protocol/ihex/intel_hex_loader.h"

#include <QCommandLineParser>
#include <QEventLoop>
#include <QJsonDocument>
#include <QObject>

#include <cstdio>

namespace imudesk::cli {

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

void addUpdateCommonOptions(QCommandLineParser &p)
{
    p.addOption(QCommandLineOption(QStringLiteral("json"), QStringLiteral("JSON lines: states, progress, log, result.")));
    p.addOption(QCommandLineOption(QStringLiteral("bin-start"), QStringLiteral("Start address of a .bin file."),
                                   QStringLiteral("ADDR")));
    p.addOption(QCommandLineOption(QStringLiteral("flash-layout"),
                                   QStringLiteral("Flash start, size and application start (e.g. 0:0x80000:0x8000): "
                                                  "the image is checked against it before anything is sent."),
                                   QStringLiteral("START:SIZE:APP")));
    p.addOption(QCommandLineOption(QStringLiteral("no-finish"),
                                   QStringLiteral("Do not finish an interrupted update found in the bootloader.")));
}

int readUpdateCommonOptions(const QCommandLineParser &p, UpdateCommonOptions &o)
{
    o.json = p.isSet(QStringLiteral("json"));
    o.finishInterrupted = !p.isSet(QStringLiteral("no-finish"));
    if (p.isSet(QStringLiteral("bin-start"))) {
        o.binStart = parseNumber(p.value(QStringLiteral("bin-start")));
        if (!o.binStart)
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
    return ExitOk;
}

std::optional<protocol::ihex::FirmwareImage> loadUpdateImage(const QString &path, const UpdateCommonOptions &o,
                                                             const ImageCheck &check)
{
    // The file is checked completely before the port or bus is opened.
    auto loaded = protocol::ihex::IntelHexLoader::loadFile(path, o.binStart);
    if (!loaded.ok()) {
        fail(QStringLiteral("%1: %2 (nothing was sent to the module)").arg(path, loaded.error));
        return std::nullopt;
    }
    const auto &image = *loaded.image;
    if (const QString e = check(image, o.layout); !e.isEmpty()) {
        fail(QStringLiteral("%1: %2 (nothing was sent to the module)").arg(path, e));
        return std::nullopt;
    }
    if (o.json)
        jsonLine(QJsonObject{{QStringLiteral("event"), QStringLiteral("image")},
                             {QStringLiteral("start"), hex32(image.startAddress)},
                             {QStringLiteral("size"), qint64(image.size())},
                             {QStringLiteral("crc32"), hex32(image.crc32())}});
    else
        out(QStringLiteral("image %1: %2 bytes at %3, CRC-32 %4")
                .arg(path)
                .arg(image.size())
                .arg(hex32(image.startAddress), hex32(image.crc32())));
    return std::move(*loaded.image);
}

void runUpdate(firmware::UpdateRunner &updater, bool json, const std::function<void()> &start)
{
    using firmware::UpdateRunner;
    bool done = false;
    bool progressShown = false;
    QString stateName;
    QObject ctx;
    QObject::connect(&updater, &UpdateRunner::stateChanged, &ctx, [&](int, const QString &name) {
        stateName = name;
        if (json)
            jsonLine(QJsonObject{{QStringLiteral("event"), QStringLiteral("state")}, {QStringLiteral("state"), name}});
    });
    QObject::connect(&updater, &UpdateRunner::logMessage, &ctx, [&](const QString &line) {
        if (json) {
            jsonLine(QJsonObject{{QStringLiteral("event"), QStringLiteral("log")}, {QStringLiteral("text"), line}});
            return;
        }
        if (progressShown)
            std::fputs("\n", stderr);
        progressShown = false;
        std::fprintf(stderr, "%s\n", line.toLocal8Bit().constData());
    });
    QObject::connect(&updater, &UpdateRunner::progressChanged, &ctx,
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
    QObject::connect(&updater, &UpdateRunner::finished, &ctx, [&] { done = true; });
    start();
    waitFor([&] { return done || interrupted(); }, -1);
    if (!done) {
        // Interrupted: the flow stops between packets (serial) or aborts the transfer between
        // segments (CAN) and leaves the module in its bootloader. waitFor() returns at once once a
        // signal has arrived, so wait on the updater itself.
        updater.cancel();
        QEventLoop loop;
        QObject::connect(&updater, &UpdateRunner::finished, &loop, &QEventLoop::quit);
        if (!done)
            loop.exec();
    }
    if (progressShown)
        std::fputs("\n", stderr);
}

QJsonObject updateResultJson(bool ok, const QString &state, const QString &message, const QString &verified,
                             bool resumed)
{
    return QJsonObject{{QStringLiteral("event"), QStringLiteral("result")},
                       {QStringLiteral("ok"), ok},
                       {QStringLiteral("state"), state},
                       {QStringLiteral("message"), message},
                       {QStringLiteral("verified"), verified},
                       {QStringLiteral("resumed"), resumed}};
}

int updateExit(bool ok, bool cancelledBySignal, const QString &message, bool json)
{
    if (cancelledBySignal)
        return fail(message, ExitInterrupted);
    if (!ok)
        return fail(message);
    if (!json)
        out(message);
    return ExitOk;
}

} // namespace imudesk::cli
