#include "pty_bridge.h"

#include "sim/pty_simulator.h"

#include <QLoggingCategory>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <deque>
#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

namespace imudesk::sim {

namespace {

Q_LOGGING_CATEGORY(lcBridge, "imudesk.core.sim.bridge", QtInfoMsg)

bool openRawPty(int &master, int &slave, QString &path, QString *error)
{
    char name[128] = {};
    if (::openpty(&master, &slave, name, nullptr, nullptr) != 0) {
        if (error)
            *error = PtyBridge::tr("Cannot open a pseudo-terminal: %1").arg(QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    }
    termios t{};
    ::tcgetattr(slave, &t);
    ::cfmakeraw(&t);
    t.c_cflag |= CLOCAL | CREAD;
    ::cfsetispeed(&t, B115200);
    ::cfsetospeed(&t, B115200);
    ::tcsetattr(slave, TCSANOW, &t);
    ::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK);
    ::fcntl(master, F_SETFD, FD_CLOEXEC);
    ::fcntl(slave, F_SETFD, FD_CLOEXEC);
    path = QString::fromLocal8Bit(name);
    return true;
}

bool usesParity(int master)
{
    termios t{};
    if (::tcgetattr(master, &t) != 0)
        return false;
    return (t.c_cflag & PARENB) != 0;
}

} // namespace

struct PtyBridge::Side {
    int master = -1;
    int slave = -1;
    struct Due {
        int64_t atNs = 0;
        std::vector<uint8_t> bytes;
    };
    std::deque<Due> queue; // chunks travelling towards this side
    size_t queued = 0;
    int64_t lineFreeNs = 0; // when the wire towards this side is idle again
};

PtyBridge::PtyBridge() : m_client(std::make_unique<Side>()), m_server(std::make_unique<Side>()) {}

PtyBridge::~PtyBridge()
{
    stop();
}

int64_t PtyBridge::nowNs() const
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch()).count()
        - m_epochNs;
}

bool PtyBridge::start(QString *error)
{
    if (isRunning())
        return true;
    if (!openRawPty(m_client->master, m_client->slave, m_clientPath, error))
        return false;
    if (!openRawPty(m_server->master, m_server->slave, m_serverPath, error)) {
        ::close(m_client->master);
        ::close(m_client->slave);
        return false;
    }
    if (::pipe2(m_wake, O_NONBLOCK | O_CLOEXEC) != 0) {
        if (error)
            *error = tr("Cannot create a pipe: %1").arg(QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    }
    m_epochNs = 0;
    m_epochNs = nowNs();
    m_stop = false;
    m_thread = std::thread([this] { run(); });
    qCInfo(lcBridge) << "bridge" << m_clientPath << "<->" << m_serverPath;
    return true;
}

void PtyBridge::stop()
{
    if (!isRunning())
        return;
    m_stop = true;
    const char c = 1;
    [[maybe_unused]] const ssize_t n = ::write(m_wake[1], &c, 1);
    m_thread.join();
    for (Side *s : {m_client.get(), m_server.get()}) {
        ::close(s->master);
        ::close(s->slave);
        s->master = s->slave = -1;
        s->queue.clear();
        s->queued = 0;
    }
    ::close(m_wake[0]);
    ::close(m_wake[1]);
    m_wake[0] = m_wake[1] = -1;
}

void PtyBridge::run()
{
    while (!m_stop) {
        const int64_t now = nowNs();
        int timeoutMs = 100;
        for (Side *s : {m_client.get(), m_server.get()})
            if (!s->queue.empty())
                timeoutMs = std::min<int>(timeoutMs, int(std::max<int64_t>(0, (s->queue.front().atNs - now + 999999) / 1000000)));
        pollfd fds[3] = {{m_client->master, POLLIN, 0}, {m_server->master, POLLIN, 0}, {m_wake[0], POLLIN, 0}};
        const int r = ::poll(fds, 3, timeoutMs);
        if (r < 0 && errno != EINTR) {
            qCWarning(lcBridge) << "poll failed:" << std::strerror(errno);
            return;
        }
        const int64_t t = nowNs();
        if (fds[0].revents & POLLIN)
            pump(*m_client, *m_server, Direction::ClientToServer, t);
        if (fds[1].revents & POLLIN)
            pump(*m_server, *m_client, Direction::ServerToClient, t);
        deliver(*m_client, t);
        deliver(*m_server, t);
    }
}

void PtyBridge::pump(Side &from, Side &to, Direction dir, int64_t now)
{
    uint8_t buf[4096];
    for (;;) {
        const ssize_t n = ::read(from.master, buf, sizeof buf);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return;
        const int sendBaud = PtySimulator::readLineSpeed(from.master);
        const int recvBaud = PtySimulator::readLineSpeed(to.master);
        Chunk c;
        c.direction = dir;
        c.sentNs = now;
        c.baud = sendBaud;
        c.garbled = sendBaud != recvBaud;
        c.bytes.assign(buf, buf + n);
        (dir == Direction::ClientToServer ? m_c2s : m_s2c) += uint64_t(n);

        std::vector<uint8_t> out;
        if (!c.garbled) {
            out = c.bytes;
        } else {
            const double ratio = (sendBaud > 0 && recvBaud > 0) ? std::min(4.0, double(recvBaud) / double(sendBaud)) : 1.0;
            out.resize(std::max<size_t>(1, size_t(double(n) * ratio)));
            for (auto &b : out) {
                m_garbageState ^= m_garbageState >> 12;
                m_garbageState ^= m_garbageState << 25;
                m_garbageState ^= m_garbageState >> 27;
                b = uint8_t((m_garbageState * 0x2545F4914F6CDD1Dull) >> 56);
            }
            m_garbled += uint64_t(n);
        }
        {
            std::lock_guard lock(m_recordMutex);
            if (m_recordBytes + c.bytes.size() <= kMaxRecordBytes) {
                m_recordBytes += c.bytes.size();
                m_record.push_back(std::move(c));
            }
        }
        if (to.queued + out.size() > kMaxQueuedBytes) {
            m_dropped += out.size();
            continue;
        }
        int64_t due = now;
        if (m_paced && sendBaud > 0) {
            const int bits = usesParity(from.master) ? 11 : 10;
            const int64_t start = std::max(now, to.lineFreeNs);
            due = start + int64_t(n) * bits * 1000000000ll / sendBaud;
            to.lineFreeNs = due;
        }
        to.queued += out.size();
        to.queue.push_back({due, std::move(out)});
    }
}

void PtyBridge::deliver(Side &to, int64_t now)
{
    while (!to.queue.empty() && to.queue.front().atNs <= now) {
        Side::Due &d = to.queue.front();
        size_t off = 0;
        while (off < d.bytes.size()) {
            const ssize_t n = ::write(to.master, d.bytes.data() + off, d.bytes.size() - off);
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0) { // the tty is full: the receiver is not reading
                m_dropped += d.bytes.size() - off;
                break;
            }
            off += size_t(n);
        }
        to.queued -= d.bytes.size();
        to.queue.pop_front();
    }
}

std::vector<PtyBridge::Chunk> PtyBridge::recorded() const
{
    std::lock_guard lock(m_recordMutex);
    return m_record;
}

void PtyBridge::clearRecord()
{
    std::lock_guard lock(m_recordMutex);
    m_record.clear();
    m_recordBytes = 0;
}

PtyBridge::Stats PtyBridge::stats() const
{
    return {m_c2s.load(), m_s2c.load(), m_garbled.load(), m_dropped.load()};
}

} // namespace imudesk::sim
