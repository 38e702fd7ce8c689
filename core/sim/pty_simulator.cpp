#include "pty_simulator.h"

#include "clock/host_clock.h"
#include "io/reading_priority.h"
#include "jobs/thread_sync.h"
#include "sim/hipnuc_serial_device.h"

#include <QLoggingCategory>
#include <QObject>
#include <QSocketNotifier>
#include <QThread>
#include <QTimer>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <deque>
#include <optional>
#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

namespace imudesk::sim {

namespace detail {
// pty_speed.cpp: termios2 (TCGETS2) cannot share a translation unit with <termios.h>.
int readTermios2Speed(int fd);
} // namespace detail

namespace {

Q_LOGGING_CATEGORY(lcPty, "imudesk.core.sim", QtInfoMsg)

int speedValue(speed_t s)
{
    switch (s) {
    case B0: return 0;
    case B1200: return 1200;
    case B2400: return 2400;
    case B4800: return 4800;
    case B9600: return 9600;
    case B19200: return 19200;
    case B38400: return 38400;
    case B57600: return 57600;
    case B115200: return 115200;
    case B230400: return 230400;
    case B460800: return 460800;
    case B500000: return 500000;
    case B576000: return 576000;
    case B921600: return 921600;
    case B1000000: return 1000000;
    case B1500000: return 1500000;
    case B2000000: return 2000000;
    default: return -1;
    }
}

} // namespace

int PtySimulator::readLineSpeed(int fd)
{
    const int s = detail::readTermios2Speed(fd);
    if (s > 0)
        return s;
    termios t{};
    if (::tcgetattr(fd, &t) != 0)
        return -1;
    return speedValue(::cfgetospeed(&t));
}

// Everything below runs on the simulator thread (except the atomics).
struct PtySimulator::Engine {
    explicit Engine(std::unique_ptr<SimulatedSerialDevice> d)
        : device(std::move(d)), sim(*device), hipnuc(dynamic_cast<HipnucSerialDevice *>(device.get()))
    {
    }

    struct Pending {
        std::vector<uint8_t> bytes;
        size_t written = 0;
    };

    std::unique_ptr<SimulatedSerialDevice> device;
    SimulatedSerialDevice &sim;
    HipnucSerialDevice *hipnuc = nullptr; // when the device is a HiPNUC module
    int master = -1;
    QSocketNotifier *notifier = nullptr;
    QTimer *timer = nullptr;
    bool clientPresent = false;
    int64_t unplugAtUs = -1; // SimFaults::unplugAtS on the engine's clock; < 0: never

    std::deque<Pending> pending;
    size_t pendingBytes = 0;
    int64_t lastServiceUs = -1;
    uint64_t droppingChunk = 0; // chunk whose remaining segments are dropped
    uint64_t garbageState = 0x9E3779B97F4A7C15ull;
    double garbageCarry = 0;

    std::atomic<uint64_t> bytesIn{0}, bytesDiscarded{0}, bytesOut{0}, bytesGarbled{0}, bytesLost{0}, chunksDropped{0},
        framesPausedInside{0};
    std::atomic<bool> unplugged{false};

    // True time: µs on the host's clock since start() (startHostNs).
    int64_t nowUs() const { return (clock::hostNowNs() - startHostNs) / 1000; }
    // The device's own time (its oscillator, sim_clock.h); the true time is nowUs().
    int64_t deviceNowUs() const { return clockError.deviceUs(nowUs()); }

    ClockError clockError;
    std::optional<AdapterBatcher> adapter; // a USB adapter that batches (sim_clock.h)
    int64_t startHostNs = 0;               // clock::hostNowNs() when clock started
    int64_t syncPeriodNs = 0;              // SYNC_IN pulses (setSyncIn); 0: none
    int64_t nextPulseNs = 0;               // the next edge on the host's clock

    uint8_t garbageByte()
    {
        // xorshift64*: deterministic, never 0x00..0x7F so it can't form a sync, '$' or a text reply.
        garbageState ^= garbageState >> 12;
        garbageState ^= garbageState << 25;
        garbageState ^= garbageState >> 27;
        return uint8_t(0x80u | ((garbageState * 0x2545F4914F6CDD1Dull) >> 57));
    }

    std::vector<uint8_t> garble(size_t n, int moduleBaud, int clientBaud)
    {
        double ratio = 1.0;
        if (clientBaud > 0 && moduleBaud > 0)
            ratio = std::min(4.0, double(clientBaud) / double(moduleBaud));
        garbageCarry += double(n) * ratio;
        const size_t count = size_t(garbageCarry);
        garbageCarry -= double(count);
        std::vector<uint8_t> out(count);
        for (auto &b : out)
            b = garbageByte();
        bytesGarbled += n;
        return out;
    }

    void setClientPresent(bool present)
    {
        if (present == clientPresent)
            return;
        clientPresent = present;
        if (notifier)
            notifier->setEnabled(present);
        pending.clear();
        pendingBytes = 0;
        droppingChunk = 0;
        qCDebug(lcPty) << (present ? "client opened" : "client closed") << "the pty";
    }

    // The cable is pulled: the master closes (the client sees the hang-up) and nothing runs
    // any more. The notifier and timer are only stopped here (this may run inside the
    // notifier's own signal); stop() deletes them.
    void unplug()
    {
        setClientPresent(false);
        if (notifier)
            notifier->setEnabled(false);
        if (timer)
            timer->stop();
        ::close(master);
        master = -1;
        unplugged = true;
        qCInfo(lcPty) << "cable pulled at" << nowUs() / 1000 << "ms";
    }

    // POLLHUP on the master means that no client has the slave open.
    bool probeClient()
    {
        pollfd p{master, POLLOUT, 0};
        if (::poll(&p, 1, 0) < 0)
            return clientPresent;
        return (p.revents & POLLHUP) == 0;
    }

    void onReadable()
    {
        if (master < 0)
            return;
        uint8_t buf[4096];
        for (;;) {
            const ssize_t n = ::read(master, buf, sizeof buf);
            if (n > 0) {
                const int speed = readLineSpeed(master);
                sim.advanceTo(deviceNowUs());
                if (speed == sim.baud()) {
                    sim.receive(buf, size_t(n));
                    bytesIn += uint64_t(n);
                } else {
                    bytesDiscarded += uint64_t(n); // framing errors at the wrong baud
                }
                continue;
            }
            if (n < 0 && errno == EINTR)
                continue;
            if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK))
                break;
            // EIO (or 0): the last client closed the slave.
            setClientPresent(false);
            break;
        }
        service();
    }

    void push(std::vector<uint8_t> bytes)
    {
        if (bytes.empty())
            return;
        pendingBytes += bytes.size();
        pending.push_back(Pending{std::move(bytes), 0});
    }

    void service()
    {
        if (master < 0)
            return;
        if (unplugAtUs >= 0 && nowUs() >= unplugAtUs) {
            unplug();
            return;
        }
        const int64_t now = nowUs();
        // This thread did not run for a while with part of a frame in the pty and the rest here.
        if (lastServiceUs >= 0 && now - lastServiceUs > kPauseInsideFrameUs && !pending.empty() &&
            pending.front().written > 0)
            ++framesPausedInside;
        lastServiceUs = now;
        // SYNC_IN edges since the last tick, each at its own instant of the module's time.
        if (syncPeriodNs > 0 && hipnuc) {
            const int64_t nowNs = startHostNs + now * 1000;
            for (; nextPulseNs <= nowNs; nextPulseNs += syncPeriodNs) {
                sim.advanceTo(clockError.deviceUs((nextPulseNs - startHostNs) / 1000));
                hipnuc->simulator().syncInPulse();
            }
        }
        sim.advanceTo(clockError.deviceUs(now));
        auto segments = sim.takeOutputSegments();
        setClientPresent(probeClient());
        if (!clientPresent) {
            for (const auto &s : segments)
                bytesLost += s.bytes.size();
            return;
        }
        const int speed = readLineSpeed(master);
        for (auto &s : segments) {
            if (s.chunkStart) {
                const size_t limit = s.data ? kMaxPendingBytes : kHardLimitBytes;
                // What waits here is what the pty would not take: hand it what it takes first. A
                // tick that ran late brings the UART's output of the whole delay at once, which
                // on a wire would have been filling the kernel's buffer meanwhile; only a reader
                // that does not drain that buffer loses frames.
                if (pendingBytes + s.bytes.size() > limit)
                    flush();
                const bool over = pendingBytes + s.bytes.size() > limit;
                droppingChunk = over ? s.chunk : 0;
                if (over)
                    ++chunksDropped;
            }
            if (droppingChunk != 0 && s.chunk == droppingChunk)
                continue;
            std::vector<uint8_t> bytes = s.baud == speed ? std::move(s.bytes) : garble(s.bytes.size(), s.baud, speed);
            if (adapter)
                adapter->push(bytes.data(), bytes.size(), now);
            else
                push(std::move(bytes));
        }
        if (adapter)
            for (AdapterBatcher::Release &r : adapter->take(now))
                push(std::move(r.bytes));
        flush();
    }

    void flush()
    {
        while (!pending.empty()) {
            Pending &p = pending.front();
            const ssize_t n = ::write(master, p.bytes.data() + p.written, p.bytes.size() - p.written);
            if (n < 0) {
                if (errno == EINTR)
                    continue;
                if (errno != EAGAIN && errno != EWOULDBLOCK)
                    setClientPresent(false);
                return; // keep the rest for the next tick
            }
            p.written += size_t(n);
            pendingBytes -= size_t(n);
            bytesOut += uint64_t(n);
            if (p.written < p.bytes.size())
                return; // partial write: the pty is full
            pending.pop_front();
        }
    }
};

PtySimulator::PtySimulator(SimOptions options) : m_options(std::move(options)) {}

PtySimulator::PtySimulator(std::unique_ptr<SimulatedSerialDevice> device)
    : m_device(std::move(device)), m_customDevice(m_device != nullptr)
{
}

PtySimulator::~PtySimulator()
{
    stop();
}

bool PtySimulator::isRunning() const
{
    return m_thread != nullptr;
}

QString PtySimulator::devicePath() const
{
    return m_path;
}

bool PtySimulator::start(QString *error)
{
    if (m_thread)
        return true;
    int master = -1, slave = -1;
    char name[128] = {};
    if (::openpty(&master, &slave, name, nullptr, nullptr) != 0) {
        if (error)
            *error = tr("Cannot open a pseudo-terminal: %1").arg(QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    }
    // Raw 8N1 at 115200, like a USB serial adapter before anyone configures it. The
    // settings stay with the pty after this descriptor is closed.
    termios t{};
    ::tcgetattr(slave, &t);
    ::cfmakeraw(&t);
    t.c_cflag |= CLOCAL | CREAD;
    ::cfsetispeed(&t, B115200);
    ::cfsetospeed(&t, B115200);
    ::tcsetattr(slave, TCSANOW, &t);
    ::close(slave);
    ::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK);
    ::fcntl(master, F_SETFD, FD_CLOEXEC);

    m_path = QString::fromLocal8Bit(name);
    const int64_t startHostNs = clock::hostNowNs();
    // Modules on one fixture: every simulator on this host sees the fixture's motion at the
    // same instant, whenever it was started (the motion is counted from the host clock's zero).
    if (m_options.motion == Motion::Twists)
        m_options.motionEpochUs = startHostNs / 1000;
    if (!m_device)
        m_device = std::make_unique<HipnucSerialDevice>(m_options);
    m_engine = std::make_unique<Engine>(std::move(m_device));
    m_engine->master = master;
    m_engine->startHostNs = startHostNs;
    if (m_syncInHz > 0) {
        m_engine->syncPeriodNs = int64_t(1e9 / m_syncInHz);
        m_engine->nextPulseNs = (startHostNs / m_engine->syncPeriodNs + 1) * m_engine->syncPeriodNs;
    }
    m_engine->clockError = m_clock;
    if (!m_adapter.isIdeal())
        m_engine->adapter.emplace(m_adapter);
    if (!m_customDevice && m_options.faults.unplugAtS >= 0)
        m_engine->unplugAtUs = std::llround(m_options.faults.unplugAtS * 1e6);

    m_thread = new QThread;
    m_thread->setObjectName(QStringLiteral("pty-simulator"));
    m_context = new QObject;
    m_context->moveToThread(m_thread);
    jobs::announceJoin(*m_thread);
    m_thread->start();

    Engine *e = m_engine.get();
    QObject *ctx = m_context;
    jobs::callAndWait(m_context, [e, ctx] {
        // The simulated module stands in for a device with a CPU of its own: its thread gets
        // the reading threads' priority (as far as the OS allows), so that a busy host delays
        // the session's reading, which is under test, rather than the device's sending.
        io::raiseCurrentThreadForReading();
        e->notifier = new QSocketNotifier(qintptr(e->master), QSocketNotifier::Read, ctx);
        e->notifier->setEnabled(false);
        QObject::connect(e->notifier, &QSocketNotifier::activated, ctx, [e] { e->onReadable(); });
        e->timer = new QTimer(ctx);
        e->timer->setTimerType(Qt::PreciseTimer);
        e->timer->setInterval(kTickMs);
        QObject::connect(e->timer, &QTimer::timeout, ctx, [e] { e->service(); });
        e->timer->start();
    });
    const std::string faults = m_customDevice ? std::string() : simFaultsText(m_options.faults);
    if (faults.empty())
        qCInfo(lcPty) << "simulated" << QString::fromStdString(m_engine->sim.productName()) << "on" << m_path;
    else
        qCInfo(lcPty) << "simulated" << QString::fromStdString(m_engine->sim.productName()) << "on" << m_path
                      << "with faults" << QString::fromStdString(faults);
    return true;
}

void PtySimulator::stop()
{
    if (!m_thread)
        return;
    Engine *e = m_engine.get();
    jobs::callAndWait(m_context, [e] {
        delete e->timer;
        e->timer = nullptr;
        delete e->notifier;
        e->notifier = nullptr;
    });
    jobs::joinThread(*m_thread);
    delete m_context;
    m_context = nullptr;
    delete m_thread;
    m_thread = nullptr;
    if (e->master >= 0) // not when the cable was pulled
        ::close(e->master);
    if (m_customDevice)
        m_device = std::move(e->device);
    m_engine.reset();
}

void PtySimulator::withDevice(const std::function<void(HipnucSimulator &)> &fn)
{
    if (!m_engine || !m_engine->hipnuc)
        return;
    withSerialDevice([&fn](SimulatedSerialDevice &d) { fn(static_cast<HipnucSerialDevice &>(d).simulator()); });
}

void PtySimulator::withSerialDevice(const std::function<void(SimulatedSerialDevice &)> &fn)
{
    if (!m_thread || !m_engine)
        return;
    Engine *e = m_engine.get();
    if (QThread::currentThread() == m_thread) {
        fn(e->sim);
        return;
    }
    jobs::callAndWait(m_context, [e, &fn] {
        e->sim.advanceTo(e->deviceNowUs());
        fn(e->sim);
    });
}

void PtySimulator::unplug()
{
    if (!m_thread || !m_engine)
        return;
    Engine *e = m_engine.get();
    jobs::callAndWait(m_context, [e] {
        if (e->master >= 0)
            e->unplug();
    });
}

void PtySimulator::setClock(ClockError clock)
{
    m_clock = clock;
    m_options.clock = clock;
}

int64_t PtySimulator::trueHostNs(int64_t deviceUs) const
{
    if (!m_engine)
        return 0;
    return m_engine->startHostNs + m_clock.trueUs(deviceUs) * 1000;
}

PtySimulator::Stats PtySimulator::stats() const
{
    Stats s;
    if (!m_engine)
        return s;
    s.bytesIn = m_engine->bytesIn;
    s.bytesDiscarded = m_engine->bytesDiscarded;
    s.bytesOut = m_engine->bytesOut;
    s.bytesGarbled = m_engine->bytesGarbled;
    s.bytesLost = m_engine->bytesLost;
    s.chunksDropped = m_engine->chunksDropped;
    s.framesPausedInside = m_engine->framesPausedInside;
    s.unplugged = m_engine->unplugged;
    return s;
}

} // namespace imudesk::sim
