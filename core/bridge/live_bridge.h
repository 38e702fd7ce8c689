#pragma once
// The live bridge: the samples of connected devices, as they arrive, to the field's tools.
//   - A Foxglove WebSocket server (foxglove_protocol.h) that Foxglove, Lichtblick and
//     PlotJuggler's Foxglove client connect to: the same topics, schemas and ROS 2 messages as
//     an MCAP recording (format/mcap/sample_channels.h), each message stamped with its sample's
//     common time, and the time capability.
//   - PlotJuggler's UDP JSON stream: every sample as one datagram, a JSON object with the
//     sample's common time as "timestamp" (s since the Unix epoch) and its values under the
//     device's name; sent in bursts every 10 ms. PlotJuggler's JSON parser takes one object and
//     one time stamp per datagram, so samples are not packed together.
//
// The server, the encoding and the sending run in a thread of their own that reads each
// device's sample store (device/sample_store.h) every 10 ms, as the views do: the session and
// the window never wait for a client. A client that does not read fast enough loses messages
// once its unsent bytes pass Options::clientBufferBytes (counted, logged, and told in a
// status message when it catches up), so memory stays bounded whatever clients do.
//
// Listens on the loopback address unless told otherwise: the protocol has no authentication.
#include "device/sample_store.h"
#include "capture/capture_header.h"

#include <QHostAddress>
#include <QObject>
#include <QString>
#include <QThread>

#include <memory>
#include <mutex>

namespace imudesk::bridge {

class BridgeWorker;

struct BridgeOptions {
    bool websocket = true;
    QHostAddress address = QHostAddress(QHostAddress::LocalHost);
    quint16 port = 8765; // Foxglove's usual port; 0: any free port
    bool udp = false;
    QHostAddress udpHost = QHostAddress(QHostAddress::LocalHost);
    quint16 udpPort = 9870; // PlotJuggler's UDP server's default
    qint64 clientBufferBytes = 8 << 20; // a client's unsent bytes, at most
    int maxClients = 16;
    qint64 maxClientMessageBytes = 64 << 10; // a client's request, at most (larger: it is disconnected)
};

struct BridgeStats {
    int clients = 0;              // connected now
    quint64 connections = 0;      // accepted since the start
    quint64 messagesSent = 0;     // to WebSocket clients, all together
    quint64 messagesDropped = 0;  // not sent to a client that did not keep up
    quint64 datagramsSent = 0;    // UDP
    quint64 datagramErrors = 0;   // UDP datagrams the system refused (nothing listening, ...)
    quint64 samples = 0;          // taken from the devices
    quint64 samplesMissed = 0;    // overwritten in a device's store before the bridge read them
    int devices = 0;
    qint64 queuedBytes = 0;       // unsent to the clients now, all together
    qint64 mostQueuedBytes = 0;   // the most any one client had unsent since the start
};

class LiveBridge : public QObject {
    Q_OBJECT
public:
    explicit LiveBridge(QObject *parent = nullptr);
    ~LiveBridge() override;

    // Listens (WebSocket) and opens the UDP socket as options say; false with why. Samples that
    // arrive from then on are sent.
    bool start(const BridgeOptions &options, QString *error);
    void stop();
    bool isRunning() const { return m_running; }
    const BridgeOptions &options() const { return m_options; }
    // The WebSocket port listened on (the one chosen when the options asked for 0).
    quint16 port() const { return m_port; }
    QString url() const;
    static bool isLoopback(const QHostAddress &address);
    // ADDR:PORT, [IPv6]:PORT or PORT alone (the address left as it is); "localhost" is 127.0.0.1.
    // false with why (the CLI's --listen and --udp, the window's --bridge).
    static bool parseHostPort(const QString &text, QHostAddress *address, quint16 *port, QString *error);

    // A device whose samples go out, under the topic namespace /imu/<name>/ (name:
    // capture::deviceName(header, label), its serial number first; made unique); header: its
    // identity, link and configuration, as a capture's. The store is what the bridge knows it by.
    void addDevice(std::shared_ptr<device::SampleStore> store, const capture::CaptureHeader &header,
                   const QString &label = QString());
    void removeDevice(const device::SampleStore *store);

    BridgeStats stats() const;

Q_SIGNALS:
    // Twice a second while running.
    void statsChanged(const imudesk::bridge::BridgeStats &stats);
    // What a person reading a log wants to know: clients coming and going, requests refused,
    // hostile input, messages dropped.
    void logged(const QString &line);

private:
    friend class BridgeWorker;
    void setStats(const BridgeStats &s);

    QThread m_thread;
    BridgeWorker *m_worker = nullptr;
    BridgeOptions m_options;
    bool m_running = false;
    quint16 m_port = 0;
    mutable std::mutex m_statsMutex;
    BridgeStats m_stats;
};

} // namespace imudesk::bridge

Q_DECLARE_METATYPE(imudesk::bridge::BridgeStats)
