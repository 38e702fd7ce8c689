// imudesk-cli commands that work on files: decode.
#include "cli_context.h"
#include "format/sample_json.h"
#include "protocol/hipnuc/payloads.h"
#include "protocol/stream/stream_demux.h"

#include <QElapsedTimer>
#include <QFile>

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

    protocol::StreamDemux demux;
    std::vector<protocol::StreamEvent> events;
    uint64_t payloadErrors = 0;
    std::map<std::string, uint64_t> payloadErrorKinds;
    std::vector<char> buf(1 << 20);
    std::string line;
    QElapsedTimer clock;
    clock.start();
    auto handle = [&] {
        for (const auto &e : events) {
            if (e.kind == protocol::StreamEvent::Kind::Nmea && json) {
                line = "{\"type\":\"NMEA\",\"sentence\":\"" + e.text + "\"}";
                outRaw(line);
            }
            if (e.kind != protocol::StreamEvent::Kind::Frame)
                continue;
            const auto res = protocol::hipnuc::forEachPacket(e.payload, [&](const protocol::hipnuc::Packet &pk) {
                if (json)
                    outRaw(format::sampleToJson(protocol::hipnuc::toSample(pk)));
            });
            if (!res.ok()) {
                ++payloadErrors;
                ++payloadErrorKinds[protocol::hipnuc::payloadErrorText(res.error)];
                if (json) {
                    char tag[8];
                    std::snprintf(tag, sizeof tag, "0x%02X", res.errorTag);
                    outRaw(std::string("{\"type\":\"unsupported\",\"error\":\"") + payloadErrorText(res.error)
                           + "\",\"tag\":\"" + tag + "\",\"offset\":" + std::to_string(res.errorOffset) + "}");
                }
            }
        }
        events.clear();
    };
    for (;;) {
        const qint64 n = file.read(buf.data(), qint64(buf.size()));
        if (n < 0)
            return fail(QStringLiteral("read error on %1: %2").arg(path, file.errorString()));
        if (n == 0)
            break;
        demux.feed(reinterpret_cast<const uint8_t *>(buf.data()), size_t(n), events);
        handle();
        if (interrupted())
            return fail(QStringLiteral("interrupted"), ExitInterrupted);
    }
    demux.finish(events);
    handle();
    const double seconds = double(clock.nsecsElapsed()) / 1e9;
    const auto &c = demux.frameCounters();
    if (json) {
        outRaw(format::summaryToJson(c, demux.counters().nmeaSentences, payloadErrors, seconds));
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
        for (const auto &[kind, count] : payloadErrorKinds)
            out(QStringLiteral("undecodable payloads (%1): %2").arg(QString::fromStdString(kind)).arg(count));
        out(QStringLiteral("speed: %1 MB/s").arg(seconds > 0 ? double(c.bytesIn) / 1e6 / seconds : 0.0, 0, 'f', 1));
    }
    std::fflush(stdout);
    return ExitOk;
}

} // namespace imudesk::cli
