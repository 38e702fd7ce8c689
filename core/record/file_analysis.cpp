#include "file_analysis.h"

#include "capture/capture_decoder.h"
#include "capture/capture_reader.h"
#include "record/capture_source.h"

namespace imudesk::record {

FileAnalysis::Outcome FileAnalysis::run(const QString &path, const std::string &frameType, double tauMax,
                                        const std::function<bool(double)> &progress)
{
    Outcome o;
    SampleAnalyzer analyzer(frameType);
    // Recognised by content: a capture, or a file a family's importer converts to one (a
    // vendor CSV, a raw byte dump).
    CaptureSource source;
    if (!source.prepare(path, &o.error))
        return o;
    o.warnings << source.notes();
    {
        struct Sink : capture::CaptureDecoder::Sink {
            SampleAnalyzer *a = nullptr;
            void onSample(const model::Sample &s, const decode::Record &) override { a->add(s); }
        } sink;
        sink.a = &analyzer;
        capture::CaptureReader reader;
        if (!reader.open(source.capturePath(), &o.error))
            return o;
        const double total = double(std::max<qint64>(reader.size(), 1));
        capture::CaptureDecoder decoder;
        if (!decoder.configure(reader.header())) {
            o.error = decoder.error();
            return o;
        }
        capture::CaptureReader::Chunk c;
        capture::CaptureReader::Result r;
        qint64 nextReport = 0;
        while ((r = reader.next(c)) == capture::CaptureReader::Result::Chunk || r == capture::CaptureReader::Result::Damaged) {
            if (r == capture::CaptureReader::Result::Chunk)
                decoder.feedChunk(c, sink);
            if (progress && reader.position() >= nextReport) {
                nextReport = reader.position() + (1 << 20);
                if (!progress(double(reader.position()) / total)) {
                    o.cancelled = true;
                    o.error = tr("Analysis cancelled.");
                    return o;
                }
            }
        }
        decoder.finish(sink);
        if (r == capture::CaptureReader::Result::Truncated)
            o.warnings << reader.message();
        if (reader.damagedChunks() > 0)
            o.warnings << tr("%n damaged chunk(s) were skipped", nullptr, int(reader.damagedChunks()));
    }
    o.result = analyzer.finish(tauMax);
    if (o.result.frames == 0) {
        o.error = tr("%1 holds no IMU frames to analyse").arg(path);
        return o;
    }
    if (progress)
        progress(1.0);
    o.ok = true;
    return o;
}

} // namespace imudesk::record
