// imudesk-cli commands that work on files: decode.
#include "cli_context.h"
#include "format/sample_json.h"
#include "protocol/hipnuc/payloads.h"
#include "decode/hipnuc_stream_decoder.h"

#include <QElapsedTimer>
#include <QFile>

#include <algorithm>
#include <cstdio>
#include <map>

namespace imudesk::cli {

int cmdDecode(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(QCommandLineOption(QStringLiteral("json"), QStringLiteral("JSON Lines: one object per frame, then a summary.")));
    p.addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("Raw capture (bytes as received)."));
    if (!parseArgs(p, args, QStringLiteral("imudesk-cli decode FILE [--json]")))
        return ExitUsage;
    if (p.positionalArguments().size() != 1)
        return fail(QStringLiteral("decode needs exactly one FILE"), ExitUsage);
    const QString path = p.positionalArguments().front();
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return fail(QStringLiteral("cannot read %1: %2").arg(path, file.errorString()));
    const bool json = p.isSet(QStringLiteral("json"));

    // The HiPNUC family's decoder, as the live session and a replay decode (decode/); a raw
    // file has no arrival times, so nothing is released by a pause, only by the end of the file.
    struct Printer : decode::Sink {
        bool json = false;
        std::string line;
        std::map<std::string, uint64_t> errorKinds;
        void onSample(const model::Sample &sample, const decode::Record &) override
        {
            if (json)
                outRaw(format::sampleToJson(sample));
        }
        void onText(decode::TextKind kind, const std::string &sentence, int64_t) override
        {
            if (!json || kind == decode::TextKind::Line)
                return;
            line = "{\"type\":\"NMEA\",\"sentence\":\"" + sentence + "\"}";
            outRaw(line);
        }
        void onPayloadError(const decode::PayloadError &e, int64_t) override
        {
            ++errorKinds[e.what];
            if (!json)
                return;
            char tag[8];
            std::snprintf(tag, sizeof tag, "0x%02X", e.tag);
            outRaw(std::string("{\"type\":\"unsupported\",\"error\":\"") + e.what + "\",\"tag\":\"" + tag
                   + "\",\"offset\":" + std::to_string(e.offset) + "}");
        }
    } printer;
    printer.json = json;
    decode::HipnucStreamDecoder decoder;
    std::vector<char> buf(1 << 20);
    QElapsedTimer clock;
    clock.start();
    for (;;) {
        const qint64 n = file.read(buf.data(), qint64(buf.size()));
        if (n < 0)
            return fail(QStringLiteral("read error on %1: %2").arg(path, file.errorString()));
        if (n == 0)
            break;
        decoder.feed(reinterpret_cast<const uint8_t *>(buf.data()), size_t(n), 0, printer);
        if (interrupted())
            return fail(QStringLiteral("interrupted"), ExitInterrupted);
    }
    decoder.finish(0, printer);
    const double seconds = double(clock.nsecsElapsed()) / 1e9;
    const protocol::StreamDemux &demux = decoder.demux();
    // Skipped: bytes that were neither a frame nor an NMEA sentence nor a text line (a reply's
    // OK is not damage), as the live statistics count them.
    auto c = demux.frameCounters();
    c.bytesSkipped -= std::min<uint64_t>(c.bytesSkipped, demux.counters().lineBytes);
    if (json) {
        outRaw(format::summaryToJson(c, demux.counters().nmeaSentences, decoder.counters().payloadErrors, seconds));
    } else {
        out(QStringLiteral("bytes: %1").arg(c.bytesIn));
        for (int tag = 0; tag < 256; ++tag)
            if (c.perTag[size_t(tag)])
                out(QStringLiteral("frames HI%1: %2")
                        .arg(QString::number(tag, 16).toUpper().rightJustified(2, QLatin1Char('0')))
                        .arg(c.perTag[size_t(tag)]));
        out(QStringLiteral("nmea sentences: %1").arg(demux.counters().nmeaSentences));
        out(QStringLiteral("crc errors: %1").arg(c.crcErrors));
        out(QStringLiteral("length errors: %1").arg(c.lengthErrors));
        out(QStringLiteral("bytes skipped: %1").arg(c.bytesSkipped));
        for (const auto &[kind, count] : printer.errorKinds)
            out(QStringLiteral("undecodable payloads (%1): %2").arg(QString::fromStdString(kind)).arg(count));
        out(QStringLiteral("speed: %1 MB/s").arg(seconds > 0 ? double(c.bytesIn) / 1e6 / seconds : 0.0, 0, 'f', 1));
    }
    std::fflush(stdout);
    return ExitOk;
}

} // namespace imudesk::cli
