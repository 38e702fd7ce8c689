#pragma once
// A simulated serial device in the same process, as a session transport (io::Transport): no
// pseudo-terminal and no simulator thread. Session tests use it to drive the real session
// engine against a simulator quickly and deterministically in the bytes.
//
// Every kTickMs of real time the device's clock runs forward and what it sent is delivered
// (bytesReceived). UART model, as PtySimulator's: bytes from the host at a rate other than
// the device's are lost, and each byte the device sends at another rate arrives as one byte
// of deterministic garbage. unplug() fails the link as a pulled cable does; replug() lets
// reopen() succeed again.
//
// setTimeScale(k) runs the device's clock k times faster than real time, for tests whose checks
// are on the device's own clock (a station plan's seconds of data, a fixture's turns): they
// spend 1/k of the real time, while the host's timeouts stay in real time.
#include "io/transport.h"
#include "sim/simulated_serial_device.h"

#include <QElapsedTimer>
#include <QTimer>

#include <atomic>
#include <memory>

namespace imudesk::sim {

class SimulatedTransport : public io::Transport {
    Q_OBJECT
public:
    static constexpr int kTickMs = 1;

    explicit SimulatedTransport(std::unique_ptr<SimulatedSerialDevice> device, QObject *parent = nullptr);
    ~SimulatedTransport() override;

    bool open(const QString &address, int baud, QString *error) override;
    void close() override;
    bool isOpen() const override { return m_open; }
    bool setBaud(int baud) override;
    int baud() const override { return m_baud; }
    QString address() const override { return m_address; }
    qint64 write(const QByteArray &bytes) override;
    void clear() override;
    QString locateAgain() const override { return m_plugged ? m_address : QString(); }
    bool reopen(int baud, QString *error) override;

    // Thread of the transport (the session's engine thread).
    void unplug();
    void replug() { m_plugged = true; }
    // The host's transmit wire is broken (any thread): what the host writes goes nowhere, so
    // requests go unanswered while the device's own output still arrives.
    void setDeaf(bool on) { m_deaf = on; }
    SimulatedSerialDevice &device() { return *m_device; }
    // Before the session opens the link (or in its thread): device seconds per real second.
    void setTimeScale(double scale);
    // Pulls the cable (unplug()) once the device's clock reaches atUs (< 0: never); before open.
    void unplugAt(int64_t atUs) { m_unplugAtUs = atUs; }
    // Bytes the host has written (any thread).
    quint64 bytesWritten() const { return m_written.load(); }

private:
    void tick();
    int64_t deviceNowUs() const;

    std::unique_ptr<SimulatedSerialDevice> m_device;
    QTimer m_timer{this};
    QElapsedTimer m_clock;
    double m_timeScale = 1.0;
    int64_t m_baseUs = 0; // device time when m_clock started
    int64_t m_unplugAtUs = -1;
    std::atomic<quint64> m_written{0};
    std::atomic<bool> m_deaf{false};
    QString m_address;
    int m_baud = 0;
    bool m_open = false;
    bool m_plugged = true;
    uint8_t m_garbage = 0x5A;
};

} // namespace imudesk::sim
