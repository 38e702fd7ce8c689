// bench_record: records HI91 at 1000 Hz from the simulator on a pseudo-terminal at 921600
// baud through DeviceSession's recording for --seconds (default 600, the ten
// minutes), then reads the capture back and counts the frames and the gaps in system_time.
// Prints frames recorded, frames the simulator could not send (its UART model) and frames
// lost between the port and the file (gaps the simulator did not cause); the target is zero.
// Headless: the GUI's share of the CPU is not part of this figure (bench_gui_live measures
// the live views).
//
//   bench_record [--seconds N] [--dir DIR]
//
// Exit status: 0 when no frame was lost; 1 otherwise; 2 on bad arguments.
#include "device/device_session.h"
#include "capture/capture_decoder.h"
#include "capture/capture_reader.h"
#include "sim/pty_simulator.h"
#include "record/recording.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QTimer>

#include <cstdio>
#include <cstring>

using namespace imudesk;

namespace {

// Frames and the 1 ms slots their system_time spans (a stamp may sit a slot early or late:
// the deficit over the whole run is what was lost).
struct Counter : capture::CaptureDecoder::Sink {
    uint64_t frames = 0, gaps = 0;
    bool have = false;
    uint32_t first = 0, last = 0;
    uint64_t slots() const { return have ? uint64_t(last - first) + 1 : 0; }
    void onSample(const model::Sample &, const decode::Record &r) override
    {
        const auto *p = r.family == std::string_view("HiPNUC serial") ? static_cast<const protocol::hipnuc::Packet *>(r.native) : nullptr;
        const auto *h = p ? std::get_if<protocol::hipnuc::Hi91>(p) : nullptr;
        if (!h)
            return;
        ++frames;
        if (have && h->systemTime > last + 1)
            ++gaps;
        if (!have)
            first = h->systemTime;
        have = true;
        last = h->systemTime;
    }
};

bool waitUntil(const std::function<bool()> &pred, int ms)
{
    QElapsedTimer t;
    t.start();
    while (!pred() && t.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    return pred();
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    int seconds = 600;
    QString dir = QDir::tempPath();
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--seconds") && i + 1 < argc)
            seconds = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--dir") && i + 1 < argc)
            dir = QString::fromLocal8Bit(argv[++i]);
        else {
            std::fprintf(stderr, "usage: bench_record [--seconds N] [--dir DIR]\n");
            return 2;
        }
    }
    if (seconds <= 0)
        return 2;
    sim::SimOptions o;
    o.baud = 921600;
    sim::PtySimulator simulator(o);
    QString error;
    if (!simulator.start(&error)) {
        std::fprintf(stderr, "bench_record: %s\n", qPrintable(error));
        return 1;
    }
    device::DeviceSession session;
    bool identified = false;
    QObject::connect(&session, &device::DeviceSession::identityQueryFinished, &app, [&](bool) { identified = true; });
    session.open(simulator.devicePath(), 921600);
    if (!waitUntil([&] { return identified; }, 10000)) {
        std::fprintf(stderr, "bench_record: the simulator did not answer\n");
        return 1;
    }
    bool answered = false;
    QObject::connect(&session, &device::DeviceSession::commandFinished, &app, [&] { answered = true; });
    session.sendText(QStringLiteral("LOG HI91 ONTIME 0.001"));
    waitUntil([&] { return answered; }, 3000);
    waitUntil([] { return false; }, 300);
    const QString path = QDir(dir).filePath(QStringLiteral("bench_record_%1.imucap").arg(app.applicationPid()));
    bool started = false, stopped = false;
    QString reason;
    QObject::connect(&session, &device::DeviceSession::recordingStarted, &app, [&] { started = true; });
    QObject::connect(&session, &device::DeviceSession::recordingStopped, &app, [&](const QString &r) {
        stopped = true;
        reason = r;
    });
    uint64_t droppedBefore = 0;
    simulator.withDevice([&](sim::HipnucSimulator &d) { droppedBefore = d.droppedFrames(); });
    const uint64_t stalledBefore = simulator.stats().chunksDropped;
    record::startRecording(session, path);
    waitUntil([&] { return started || stopped; }, 5000);
    waitUntil([&] { return stopped; }, seconds * 1000);
    session.stopRecording();
    waitUntil([&] { return stopped; }, 10000);
    uint64_t dropped = 0;
    simulator.withDevice([&](sim::HipnucSimulator &d) { dropped = d.droppedFrames() - droppedBefore; });
    dropped += simulator.stats().chunksDropped - stalledBefore;
    session.close();

    capture::CaptureReader reader;
    if (!reader.open(path, &error)) {
        std::fprintf(stderr, "bench_record: %s\n", qPrintable(error));
        return 1;
    }
    Counter counter;
    capture::CaptureDecoder decoder;
    decoder.configure(reader.header());
    capture::CaptureReader::Chunk c;
    while (reader.next(c) == capture::CaptureReader::Result::Chunk)
        decoder.feedChunk(c, counter);
    decoder.finish(counter);
    const qint64 size = QFile(path).size();
    QFile::remove(path);
    // Gaps the simulator caused (frames its UART or the stalled reader dropped) are not the recorder's.
    const uint64_t missing = counter.slots() > counter.frames ? counter.slots() - counter.frames : 0;
    const uint64_t lost = missing > dropped ? missing - dropped : 0;
    std::printf("recorded %d s of HI91 at 1000 Hz over 921600 baud: %llu frames, %.1f MB; system_time slots "
                "without a frame: %llu (%llu late/early stamps), of them dropped by the simulator: %llu; CRC errors: %llu; lost by the recorder: %llu "
                "(target 0)%s\n",
                seconds, static_cast<unsigned long long>(counter.frames), double(size) / 1e6,
                static_cast<unsigned long long>(missing), static_cast<unsigned long long>(counter.gaps),
                static_cast<unsigned long long>(dropped),
                static_cast<unsigned long long>(decoder.counters().crcErrors),
                static_cast<unsigned long long>(lost), reason.isEmpty() ? "" : qPrintable(QStringLiteral("; ") + reason));
    return lost == 0 && reason.isEmpty() && counter.frames > uint64_t(seconds) * 900 ? 0 : 1;
}
