// Heap allocations per decoded frame on the live path (issue 20): HI91 frames at 1 kHz, one
// frame per delivery as a serial port hands them over, through the whole session (engine
// thread: raw-byte log, family decoder, statistics, sample store; owner thread: the signals
// it receives). Every operator new in the process is counted while it runs. The bytes come
// from an in-process feed, so the serial port's own read (one QByteArray per delivery in
// io::SerialTransport) and the GUI are not in this figure.
//
// Baseline, measured in the same run: the bare codec path (StreamDemux + forEachPacket +
// toSample) over the same bytes, which no session can beat.
//
// usage: bench_alloc_live [--seconds N]   (default 5)
#include "device/device_session.h"
#include "io/transport.h"
#include "protocol/hipnuc/payloads.h"
#include "protocol/stream/stream_demux.h"
#include "sim/hipnuc_serial_device.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTimer>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>

namespace {
std::atomic<uint64_t> g_allocations{0};
}

void *operator new(std::size_t n)
{
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    if (void *p = std::malloc(n ? n : 1))
        return p;
    throw std::bad_alloc();
}
void *operator new[](std::size_t n)
{
    return operator new(n);
}
void operator delete(void *p) noexcept
{
    std::free(p);
}
void operator delete[](void *p) noexcept
{
    std::free(p);
}
void operator delete(void *p, std::size_t) noexcept
{
    std::free(p);
}
void operator delete[](void *p, std::size_t) noexcept
{
    std::free(p);
}

using namespace imudesk;

namespace {

// HI91 frames from the simulator at 1 kHz, one QByteArray per frame.
QList<QByteArray> makeFrames(int count)
{
    sim::HipnucSerialDevice dev;
    const char cmd[] = "LOG HI91 ONTIME 0.001\r\n";
    dev.receive(reinterpret_cast<const uint8_t *>(cmd), sizeof cmd - 1);
    QList<QByteArray> frames;
    QByteArray current;
    for (int64_t us = 0; frames.size() < count; us += 1000) {
        dev.advanceTo(us);
        for (const auto &s : dev.takeOutputSegments()) {
            if (s.chunkStart)
                current.clear();
            current.append(reinterpret_cast<const char *>(s.bytes.data()), qsizetype(s.bytes.size()));
            if (s.chunkEnd && s.data && current.size() > 2 && uint8_t(current[0]) == 0x5A)
                frames.append(current);
        }
    }
    return frames;
}

// Hands over one frame per millisecond, as a port's readyRead does.
class FrameFeed : public io::Transport {
public:
    explicit FrameFeed(QList<QByteArray> frames) : m_frames(std::move(frames))
    {
        m_timer.setInterval(1);
        m_timer.setTimerType(Qt::PreciseTimer);
        QObject::connect(&m_timer, &QTimer::timeout, this, [this] {
            if (m_next < m_frames.size())
                Q_EMIT bytesReceived(m_frames.at(m_next++));
        });
    }
    bool open(const QString &address, int baud, QString *) override
    {
        m_address = address;
        m_baud = baud;
        m_timer.start();
        return true;
    }
    void close() override { m_timer.stop(); }
    bool isOpen() const override { return m_timer.isActive(); }
    bool setBaud(int baud) override { return (m_baud = baud), true; }
    int baud() const override { return m_baud; }
    QString address() const override { return m_address; }
    qint64 write(const QByteArray &bytes) override { return bytes.size(); }
    void clear() override {}
    bool reopen(int, QString *) override { return false; }

private:
    QList<QByteArray> m_frames;
    qsizetype m_next = 0;
    QTimer m_timer{this};
    QString m_address;
    int m_baud = 0;
};

void spin(int ms)
{
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    int seconds = 5;
    for (int i = 1; i + 1 < argc; ++i)
        if (QByteArray(argv[i]) == "--seconds")
            seconds = std::max(2, QByteArray(argv[i + 1]).toInt());
    const int warmupFrames = 1000;
    const QList<QByteArray> frames = makeFrames(warmupFrames + seconds * 1000 + 500);

    // Baseline: the codec alone.
    protocol::StreamDemux demux;
    std::vector<protocol::StreamEvent> events;
    std::vector<model::Sample> batch;
    uint64_t codecFrames = 0;
    for (int i = 0; i < warmupFrames; ++i) // warm the reused buffers
        demux.feed(reinterpret_cast<const uint8_t *>(frames[i].constData()), size_t(frames[i].size()), events);
    events.clear();
    const uint64_t base0 = g_allocations.load();
    for (qsizetype i = warmupFrames; i < frames.size(); ++i) {
        events.clear();
        batch.clear();
        demux.feed(reinterpret_cast<const uint8_t *>(frames[i].constData()), size_t(frames[i].size()), events);
        for (const auto &e : events)
            if (e.kind == protocol::StreamEvent::Kind::Frame)
                protocol::hipnuc::forEachPacket(e.payload, [&](const protocol::hipnuc::Packet &p) {
                    batch.push_back(protocol::hipnuc::toSample(p));
                    ++codecFrames;
                });
    }
    const double codecPerFrame = double(g_allocations.load() - base0) / double(std::max<uint64_t>(1, codecFrames));

    // The session.
    device::DeviceSession session(nullptr, std::make_unique<FrameFeed>(frames));
    session.open(QStringLiteral("feed"), 921600);
    for (int waited = 0; session.store().totalAppended() < uint64_t(warmupFrames) && waited < 10000; waited += 10)
        spin(10);
    const uint64_t a0 = g_allocations.load();
    const uint64_t f0 = session.store().totalAppended();
    spin(seconds * 1000);
    const uint64_t a1 = g_allocations.load();
    const uint64_t f1 = session.store().totalAppended();
    session.close();
    const uint64_t decoded = f1 - f0;
    const double perFrame = double(a1 - a0) / double(std::max<uint64_t>(1, decoded));
    constexpr double kTarget = 10.0;
    std::printf("bench_alloc_live: HI91 at 1 kHz, one frame per delivery, %d s\n", seconds);
    std::printf("  %-44s %10llu\n", "frames decoded by the session", (unsigned long long)decoded);
    std::printf("  %-44s %10.2f   (baseline, same bytes)\n", "allocations per frame, codec alone", codecPerFrame);
    std::printf("  %-44s %10.2f   target <= %.0f  %s\n", "allocations per frame, whole live session", perFrame,
                kTarget, perFrame <= kTarget ? "ok" : "MISSED");
    return perFrame <= kTarget && decoded > 0 ? 0 : 1;
}
