#pragma once
// Test helpers for faults on the serial path: a pseudo-terminal whose master side the test
// writes to (the test plays the device, and closing it pulls the cable), and a watch of the
// owner thread's event loop (the GUI thread in the app).
#include "device/device_session.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTest>
#include <QTimer>

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace imudesk::test {

// Under AddressSanitizer or ThreadSanitizer the GUI thread's stall bounds are not judged: both
// slow every step many times over (the same bounds hold in the release build's suite).
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

// A pseudo-terminal whose master side the test writes to: the "device" is the test.
class RawPty {
public:
    RawPty()
    {
        m_master = posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
        if (m_master < 0 || grantpt(m_master) != 0 || unlockpt(m_master) != 0)
            return;
        m_slave = QString::fromLocal8Bit(ptsname(m_master));
        termios t{};
        tcgetattr(m_master, &t);
        cfmakeraw(&t);
        tcsetattr(m_master, TCSANOW, &t);
    }
    ~RawPty() { pull(); }
    // The cable is pulled: the slave side sees a hang-up.
    void pull()
    {
        if (m_master >= 0)
            ::close(m_master);
        m_master = -1;
    }
    bool ok() const { return m_master >= 0 && !m_slave.isEmpty(); }
    QString slave() const { return m_slave; }
    // Writes all of `bytes`, waiting while the pty's buffer is full until it has room again
    // (poll for POLLOUT, at most 10 ms at a time, keeping the event loop turning).
    void write(const std::vector<uint8_t> &bytes)
    {
        size_t done = 0;
        while (m_master >= 0 && done < bytes.size()) {
            const ssize_t n = ::write(m_master, bytes.data() + done, bytes.size() - done);
            if (n > 0) {
                done += size_t(n);
                continue;
            }
            pollfd p{m_master, POLLOUT, 0};
            ::poll(&p, 1, 10);
            QCoreApplication::processEvents();
        }
    }
    // Reads and forgets what the session sent (its LOG VERSION queries).
    void drain() { readAvailable(); }
    // What the session has sent and the test has not read yet.
    std::string readAvailable()
    {
        std::string out;
        char buf[512];
        ssize_t n = 0;
        while (m_master >= 0 && (n = ::read(m_master, buf, sizeof buf)) > 0)
            out.append(buf, size_t(n));
        return out;
    }

private:
    int m_master = -1;
    QString m_slave;
};

// An HI91 frame with the device clock at ms (what the tests' "device" sends).
inline std::vector<uint8_t> hi91Frame(uint32_t ms)
{
    protocol::hipnuc::Hi91 p;
    p.systemTime = ms;
    p.acc = {0.01f * float(ms % 100), -0.5f, 1.0f};
    p.yaw = float(ms % 360);
    return protocol::hipnuc::buildFrame(protocol::hipnuc::encode(p));
}

// Longest time the owner's event loop went without running a 5 ms timer.
class StallWatch {
public:
    StallWatch()
    {
        m_timer.setInterval(5);
        QObject::connect(&m_timer, &QTimer::timeout, &m_timer, [this] {
            const qint64 ms = m_clock.restart();
            m_worst = std::max(m_worst, ms);
        });
        m_clock.start();
        m_timer.start();
    }
    qint64 worstMs() const { return m_worst; }

private:
    QTimer m_timer;
    QElapsedTimer m_clock;
    qint64 m_worst = 0;
};

// Opens session on the pty at 921600 baud (no auto-reconnect: the tests pull the cable) and
// waits until it is connected, reading away its identity queries meanwhile.
inline bool openOnPty(device::DeviceSession &session, RawPty &pty)
{
    session.setAutoReconnect(false);
    session.open(pty.slave(), 921600);
    return imudesk::test::waitFor(
        [&] {
            pty.drain();
            return session.state() == device::SessionState::Connected;
        },
        15000);
}

} // namespace imudesk::test
