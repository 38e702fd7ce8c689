#pragma once
// Two pseudo-terminals joined like two UARTs on one RS-485 pair, so that a serial-port
// server (QModbusRtuSerialServer) and a client can each open a real tty path.
//
//   client  <->  clientPath() (/dev/pts/A)  ==master A==  bridge thread  ==master B==  serverPath() (/dev/pts/B)  <->  server
//
// The bridge thread polls both masters and forwards what one side writes to the other.
// Line model:
//   * Speed: before forwarding, the line speed each side set on its tty is read
//     (PtySimulator::readLineSpeed). When the speeds differ, the receiver gets deterministic
//     garbage instead (about receiverBaud / senderBaud bytes per byte sent, never more than
//     4x), as a UART hears a frame sent at another rate.
//   * Timing: a chunk is delivered once it would have finished on the wire: a byte takes
//     11 bit times when the sender uses parity, 10 otherwise; a direction sends one chunk after
//     the other. So a poll rate the baud cannot carry is not reached here either.
// Both slave ends are held open by the bridge, so a side that closes and reopens its port
// finds the same line (its settings stay) and nothing blocks while nobody listens: bytes
// sent while the other side is closed are dropped.
//
// Record: the bridge keeps what each side sent (before any garbling), bounded by
// kMaxRecordBytes; tests read it with recorded()/clearRecord().
#include <QCoreApplication>
#include <QString>

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace imudesk::sim {

class PtyBridge {
    Q_DECLARE_TR_FUNCTIONS(PtyBridge)

public:
    static constexpr size_t kMaxRecordBytes = 1 << 20;
    static constexpr size_t kMaxQueuedBytes = 64 * 1024; // per direction; more is dropped

    enum class Direction { ClientToServer, ServerToClient };
    struct Chunk {
        Direction direction = Direction::ClientToServer;
        int64_t sentNs = 0;   // steady clock, since start()
        int baud = 0;         // sender's line speed
        bool garbled = false; // speeds differed: the receiver got garbage
        std::vector<uint8_t> bytes;
    };
    struct Stats {
        uint64_t clientToServer = 0;
        uint64_t serverToClient = 0;
        uint64_t garbled = 0;  // bytes replaced by garbage
        uint64_t dropped = 0;  // bytes dropped (queue full)
    };

    PtyBridge();
    ~PtyBridge();
    PtyBridge(const PtyBridge &) = delete;
    PtyBridge &operator=(const PtyBridge &) = delete;

    bool start(QString *error = nullptr);
    void stop();
    bool isRunning() const { return m_thread.joinable(); }
    QString clientPath() const { return m_clientPath; }
    QString serverPath() const { return m_serverPath; }

    std::vector<Chunk> recorded() const;
    void clearRecord();
    Stats stats() const;
    // Whether the bridge models wire time (on by default).
    void setPaced(bool on) { m_paced = on; }

private:
    struct Side;
    void run();
    void pump(Side &from, Side &to, Direction dir, int64_t now);
    void deliver(Side &to, int64_t now);
    int64_t nowNs() const;

    std::unique_ptr<Side> m_client, m_server;
    int m_wake[2] = {-1, -1};
    std::thread m_thread;
    std::atomic<bool> m_stop{false};
    std::atomic<bool> m_paced{true};
    QString m_clientPath, m_serverPath;
    int64_t m_epochNs = 0;

    mutable std::mutex m_recordMutex;
    std::vector<Chunk> m_record;
    size_t m_recordBytes = 0;
    std::atomic<uint64_t> m_c2s{0}, m_s2c{0}, m_garbled{0}, m_dropped{0};
    uint64_t m_garbageState = 0x9E3779B97F4A7C15ull;
};

} // namespace imudesk::sim
