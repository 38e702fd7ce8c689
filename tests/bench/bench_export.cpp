// bench_export: export speed of a one-hour HI91 capture at 1000 Hz (3.6 million frames,
// about 300 MB) to vendor CSV and tidy CSV with CaptureExporter, against a simple reference
// exporter in the same run (the same capture reader and decoder path, then one fprintf per
// row in the vendor layout). Prints frames/s, the ratio to the reference, the time against
// the 10 s target, and the peak resident memory after each phase (it must stay flat: the
// export streams).
//
//   bench_export [--frames N] [--dir DIR] [--keep]
//
// The capture and the outputs go to DIR, by default /dev/shm when it exists (else the temp
// folder), so that the figures are the exporter's and not the disk's: the vendor CSV of an
// hour is about 820 MB, which a 100 MB/s disk alone needs 8 s to take.
//
// MCAP (issues 37 and 54) is measured against the vendor CSV of the same run: at least as fast
// (its chunks compressed and written by a thread of the writer's own), and the file at most 65 %
// of its size with every index kept (Imu, MagneticField and the Euler angles each sample;
// pressure and temperature when they change; the status ten times a second or when it changes).
// The capture is a module's as one sends it: the status word steady, the barometer at 50 Hz.
//
// Exit status: 0 when each format meets the target and every frame was exported; 1 otherwise;
// 2 on bad arguments.
#include "../common/synthetic_capture.h"
#include "capture/capture_decoder.h"
#include "record/capture_exporter.h"
#include "capture/capture_reader.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>

#include <cstdio>
#include <cstring>

#include <sys/resource.h>

namespace {

using namespace imudesk;

constexpr double kTargetSeconds = 10.0;

long peakRssKb()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss; // kB on Linux
}

// The reference: decode, then printf-style formatting of every field, one row per frame.
struct ReferenceSink : capture::CaptureDecoder::Sink {
    FILE *out = nullptr;
    int64_t firstNs = 0;
    uint64_t rows = 0;
    void onSample(const model::Sample &s, const decode::Record &r) override
    {
        const int64_t hostNs = s.hostTimeNs;
        const auto *p = r.family == std::string_view("HiPNUC serial") ? static_cast<const protocol::hipnuc::Packet *>(r.native) : nullptr;
        const auto *h = p ? std::get_if<protocol::hipnuc::Hi91>(p) : nullptr;
        if (!h)
            return;
        const double an = std::sqrt(h->acc[0] * h->acc[0] + h->acc[1] * h->acc[1] + h->acc[2] * h->acc[2]);
        const double gn = std::sqrt(h->gyr[0] * h->gyr[0] + h->gyr[1] * h->gyr[1] + h->gyr[2] * h->gyr[2]);
        const double mn = std::sqrt(h->mag[0] * h->mag[0] + h->mag[1] * h->mag[1] + h->mag[2] * h->mag[2]);
        std::fprintf(out,
                     "HI91,%.9g,%u,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,0,0,0,%.9g,%.9g,%.9g,"
                     "%.9g,%d,%.9g,%.9g,%.9g,%.9g\n",
                     double(hostNs - firstNs) / 1e6, h->systemTime, h->acc[0], h->acc[1], h->acc[2], h->gyr[0],
                     h->gyr[1], h->gyr[2], h->mag[0], h->mag[1], h->mag[2], h->roll, h->pitch, h->yaw, h->quat[0],
                     h->quat[1], h->quat[2], h->quat[3], h->temperature, h->pressure, an, gn, mn);
        ++rows;
    }
};

double referenceExport(const QString &capture, const QString &output, uint64_t *rows)
{
    QElapsedTimer t;
    t.start();
    capture::CaptureReader reader;
    QString error;
    if (!reader.open(capture, &error))
        return -1;
    ReferenceSink sink;
    sink.out = std::fopen(output.toLocal8Bit().constData(), "w");
    if (!sink.out)
        return -1;
    std::fputs("HI91,pc_counter,sys_time,...\n", sink.out);
    capture::CaptureDecoder decoder;
    capture::CaptureReader::Chunk c;
    bool first = true;
    while (reader.next(c) == capture::CaptureReader::Result::Chunk) {
        if (first) {
            sink.firstNs = c.monotonicNs;
            first = false;
        }
        decoder.feedChunk(c, sink);
    }
    decoder.finish(sink);
    std::fclose(sink.out);
    *rows = sink.rows;
    return double(t.nsecsElapsed()) / 1e9;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    uint64_t frames = 3'600'000;
    QString dir = QDir(QStringLiteral("/dev/shm")).exists() ? QStringLiteral("/dev/shm") : QDir::tempPath();
    bool keep = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--frames") && i + 1 < argc)
            frames = std::strtoull(argv[++i], nullptr, 10);
        else if (!std::strcmp(argv[i], "--dir") && i + 1 < argc)
            dir = QString::fromLocal8Bit(argv[++i]);
        else if (!std::strcmp(argv[i], "--keep"))
            keep = true;
        else {
            std::fprintf(stderr, "usage: bench_export [--frames N] [--dir DIR] [--keep]\n");
            return 2;
        }
    }
    if (frames == 0) {
        std::fprintf(stderr, "bench_export: --frames needs a positive number\n");
        return 2;
    }
    const QString base = QDir(dir).filePath(QStringLiteral("bench_export_%1").arg(QCoreApplication::applicationPid()));
    const QString capture = base + QStringLiteral(".imucap");
    QElapsedTimer t;
    t.start();
    synthetic::CaptureSpec spec;
    spec.frames = frames;
    spec.rateHz = 1000;
    // A module's: its status word steady (a change a second here), its barometer at 50 Hz.
    spec.statusEveryFrames = 1000;
    spec.pressureEveryFrames = 20;
    const qint64 bytes = synthetic::writeCapture(capture, spec);
    if (bytes <= 0) {
        std::fprintf(stderr, "bench_export: cannot write %s\n", qPrintable(capture));
        return 1;
    }
    std::printf("capture: %llu HI91 frames at 1000 Hz, %.1f MB, generated in %.1f s; peak RSS %ld kB\n",
                static_cast<unsigned long long>(frames), double(bytes) / 1e6, double(t.nsecsElapsed()) / 1e9,
                peakRssKb());

    uint64_t refRows = 0;
    const QString refOut = base + QStringLiteral("_reference.csv");
    const double ref = referenceExport(capture, refOut, &refRows);
    QFile::remove(refOut);
    std::printf("reference (decode + fprintf):  %6.2f s  %10.0f frames/s  peak RSS %ld kB\n", ref,
                double(refRows) / ref, peakRssKb());

    bool ok = refRows == frames;
    struct Run {
        const char *name;
        record::CaptureExporter::Format format;
        QString output;
        QString written;
    };
    const Run runs[] = {
        {"vendor CSV", record::CaptureExporter::Format::VendorCsv, base + QStringLiteral(".csv"),
         base + QStringLiteral(".csv")}, // HI91 alone: the file named
        {"tidy CSV", record::CaptureExporter::Format::TidyCsv, base + QStringLiteral("_tidy.csv"),
         base + QStringLiteral("_tidy.csv")},
        {"MCAP", record::CaptureExporter::Format::Mcap, base + QStringLiteral(".mcap"), base + QStringLiteral(".mcap")},
    };
    double vendorSeconds = 0, vendorMb = 0;
    for (const Run &run : runs) {
        record::CaptureExporter::Options o;
        o.format = run.format;
        o.output = run.output;
        t.restart();
        const auto r = record::CaptureExporter::run(capture, o);
        const double s = double(t.nsecsElapsed()) / 1e9;
        const bool met = r.ok && r.frames == frames && s <= kTargetSeconds;
        ok = ok && met;
        std::printf("%-12s (ImuDesk):      %6.2f s  %10.0f frames/s  %.2fx the reference's speed  %.1f MB  peak RSS "
                    "%ld kB  target <= %.0f s: %s\n",
                    run.name, s, double(r.frames) / s, ref / s, double(QFileInfo(run.written).size()) / 1e6,
                    peakRssKb(), kTargetSeconds, met ? "met" : "MISSED");
        const double mb = double(QFileInfo(run.written).size()) / 1e6;
        if (run.format == record::CaptureExporter::Format::VendorCsv) {
            vendorSeconds = s;
            vendorMb = mb;
        } else if (run.format == record::CaptureExporter::Format::Mcap) {
            // r.frames counts samples (each is several messages).
            const bool fast = s <= vendorSeconds, small = mb <= 0.65 * vendorMb;
            ok = ok && fast && small;
            std::printf("  MCAP against vendor CSV:     %.2fx its speed (target >= 1: %s), %.1f %% of its size (target "
                        "<= 65 %%: %s)\n",
                        vendorSeconds / s, fast ? "met" : "MISSED", 100.0 * mb / std::max(vendorMb, 1e-9),
                        small ? "met" : "MISSED");
        }
        if (!r.ok)
            std::printf("  error: %s\n", qPrintable(r.error));
        if (!keep)
            for (const QString &f : r.files)
                QFile::remove(f);
    }
    if (!keep)
        QFile::remove(capture);
    return ok ? 0 : 1;
}
