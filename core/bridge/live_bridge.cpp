#include "live_bridge.h"

#include "bridge/foxglove_protocol.h"
#include "clock/host_clock.h"
#include "format/mcap/channel_sink.h"
#include "format/mcap/sample_channels.h"
#include "format/sample_json.h"
#include "capture/device_name.h"
#include "capture/mcap_recording.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QElapsedTimer>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>
#include <QUdpSocket>
#include <QUuid>
#include <QWebSocket>
#include <QWebSocketServer>

#include <algorithm>
#include <cstdio>
#include <list>
#include <map>
#include <set>

namespace imudesk::bridge {

namespace fm = format::mcap;

namespace {
constexpr int kPollMs = 10;
constexpr int kStatsMs = 500;
constexpr int64_t kTimePeriodNs = 50'000'000; // the time message, 20 times a second at most
constexpr int kLogsPerClient = 5;             // a client's bad requests logged one by one, then counted

QString peerOf(const QWebSocket *s)
{
    return QStringLiteral("%1:%2").arg(s->peerAddress().toString()).arg(s->peerPort());
}
} // namespace

// Lives in the bridge's thread; LiveBridge calls it through queued (or, to start and stop,
// blocking) invocations.
class BridgeWorker : public QObject {
public:
    explicit BridgeWorker(LiveBridge *owner) : m_owner(owner) {}

    QString start(const BridgeOptions &o, quint16 *port);
    void stop();
    void addDevice(std::shared_ptr<device::SampleStore> store, const capture::CaptureHeader &header, const QString &label);
    void removeDevice(const device::SampleStore *store);

private:
    struct Client {
        QWebSocket *socket = nullptr;
        QString peer;
        std::map<uint32_t, uint32_t> channelOfSub; // subscription id -> channel id
        quint64 sent = 0, dropped = 0, droppedNow = 0;
        int badRequests = 0;
        bool slow = false;
    };
    struct Subscriber {
        Client *client;
        uint32_t subscription;
    };
    struct Channel {
        foxglove::Channel info;
        std::set<const device::SampleStore *> devices; // the devices that write it (/tf: all)
        std::vector<Subscriber> subscribers;
    };
    // One device's side of the bridge's channels: SampleChannels adds and writes through it.
    class DeviceSink : public fm::ChannelSink {
    public:
        DeviceSink(BridgeWorker &w, const device::SampleStore *key) : m_w(w), m_key(key) {}
        uint16_t addSchema(const std::string &name, const std::string &encoding, const std::string &data) override
        {
            m_schemas.push_back({name, encoding, data});
            return uint16_t(m_schemas.size());
        }
        uint16_t addChannel(uint16_t schemaId, const std::string &topic, const std::string &messageEncoding,
                            const StringMap &) override
        {
            if (schemaId == 0 || schemaId > m_schemas.size())
                return 0;
            const auto &s = m_schemas[schemaId - 1];
            return uint16_t(m_w.channelFor(m_key, topic, messageEncoding, s.name, s.data, s.encoding));
        }
        bool write(uint16_t channelId, uint32_t, uint64_t, uint64_t publishTime, const void *data, size_t size) override
        {
            m_w.publish(channelId, publishTime, static_cast<const char *>(data), size);
            return true;
        }

    private:
        struct Schema {
            std::string name, encoding, data;
        };
        BridgeWorker &m_w;
        const device::SampleStore *m_key;
        std::vector<Schema> m_schemas;
    };
    struct Device {
        device::SampleCursor cursor;
        std::string name;
        std::unique_ptr<DeviceSink> sink;
        std::unique_ptr<fm::SampleChannels> channels;
        uint64_t missedUntold = 0; // overwritten in the store before the bridge read them, not yet told
    };

    uint32_t channelFor(const device::SampleStore *device, const std::string &topic, const std::string &encoding,
                        const std::string &schemaName, const std::string &schema, const std::string &schemaEncoding);
    void publish(uint32_t channelId, uint64_t timeNs, const char *data, size_t size);
    void poll();
    void sendTime(uint64_t ns);
    void onTcpConnection();
    void onConnection();
    void onText(Client *c, const QString &text);
    void onBinary(Client *c, const QByteArray &data);
    void onDisconnected(Client *c);
    void dropSubscriptions(Client *c, const std::vector<uint32_t> &subscriptionIds);
    void refuse(Client *c, const QString &what);
    void checkCaughtUp();
    void tellMissed();
    void log(const QString &line);
    void publishStats();
    void sendDatagram(const Device &d, const model::Sample &s);

    LiveBridge *m_owner;
    BridgeOptions m_options;
    std::unique_ptr<QTcpServer> m_tcp;
    std::unique_ptr<QWebSocketServer> m_server;
    std::map<QTcpSocket *, QString> m_handshaking; // connections not yet WebSockets, with their peer
    std::unique_ptr<QUdpSocket> m_udp;
    QTimer *m_poll = nullptr;
    QTimer *m_statsTimer = nullptr;
    std::list<Client> m_clients; // a list: a Client stays where it is while others come and go
    std::map<uint32_t, Channel> m_channels;
    std::map<const device::SampleStore *, Device> m_devices;
    uint32_t m_nextChannel = 1;
    int64_t m_epochOffsetNs = 0;
    uint64_t m_latestTime = 0, m_lastTimeSent = 0;
    QElapsedTimer m_sinceMissedTold; // at most one "fell behind" status a second
    QString m_sessionId;
    BridgeStats m_stats;
    std::string m_datagram; // reused
};

// ---------------------------------------------------------------------------------------------

QString BridgeWorker::start(const BridgeOptions &o, quint16 *port)
{
    stop();
    m_options = o;
    m_stats = BridgeStats{};
    m_stats.devices = int(m_devices.size());
    m_sessionId = QUuid::createUuid().toString(QUuid::WithoutBraces);
    m_epochOffsetNs = QDateTime::currentMSecsSinceEpoch() * 1'000'000 - clock::hostNowNs();
    if (o.websocket) {
        m_server = std::make_unique<QWebSocketServer>(QStringLiteral("ImuDesk"), QWebSocketServer::NonSecureMode);
        m_server->setSupportedSubprotocols(foxglove::subprotocols());
        m_server->setHandshakeTimeout(5000); // a connection that never finishes its handshake goes
        // The TCP side is ours, so that a connection that never becomes a WebSocket (bytes that
        // are no handshake, nothing sent at all) is seen and logged; the WebSocket server takes
        // each connection's handshake.
        m_tcp = std::make_unique<QTcpServer>();
        m_tcp->setMaxPendingConnections(8);
        if (!m_tcp->listen(o.address, o.port)) {
            const QString why = m_tcp->errorString();
            m_tcp.reset();
            m_server.reset();
            return QCoreApplication::translate("imudesk::bridge::LiveBridge", "Cannot listen on %1 port %2: %3")
                .arg(o.address.toString()).arg(o.port).arg(why);
        }
        *port = m_tcp->serverPort();
        QObject::connect(m_tcp.get(), &QTcpServer::newConnection, this, [this] { onTcpConnection(); });
        QObject::connect(m_server.get(), &QWebSocketServer::newConnection, this, [this] { onConnection(); });
        QObject::connect(m_server.get(), &QWebSocketServer::serverError, this,
                         [this](QWebSocketProtocol::CloseCode code) {
                             log(QStringLiteral("a connection was refused during its handshake (%1: %2)")
                                     .arg(int(code)).arg(m_server->errorString()));
                         });
        log(QStringLiteral("Foxglove WebSocket server listening on ws://%1:%2%3")
                .arg(o.address.protocol() == QAbstractSocket::IPv6Protocol ? QLatin1Char('[') + o.address.toString() + QLatin1Char(']')
                                                                           : o.address.toString())
                .arg(*port)
                .arg(LiveBridge::isLoopback(o.address) ? QString()
                                                       : QStringLiteral(" (not loopback: anyone who can reach this address can read the data; "
                                                                        "the protocol has no authentication)")));
    }
    if (o.udp) {
        m_udp = std::make_unique<QUdpSocket>();
        log(QStringLiteral("PlotJuggler UDP stream to %1:%2").arg(o.udpHost.toString()).arg(o.udpPort));
    }
    for (auto &[key, d] : m_devices)
        d.cursor.skipToNow(); // what arrives from now on
    if (!m_poll) {
        m_poll = new QTimer(this);
        m_poll->setTimerType(Qt::PreciseTimer);
        QObject::connect(m_poll, &QTimer::timeout, this, [this] { poll(); });
        m_statsTimer = new QTimer(this);
        QObject::connect(m_statsTimer, &QTimer::timeout, this, [this] { publishStats(); });
    }
    m_poll->start(kPollMs);
    m_statsTimer->start(kStatsMs);
    publishStats();
    return {};
}

void BridgeWorker::stop()
{
    if (m_poll) {
        m_poll->stop();
        m_statsTimer->stop();
    }
    for (Client &c : m_clients) {
        c.socket->disconnect(this);
        c.socket->close(QWebSocketProtocol::CloseCodeGoingAway, QStringLiteral("ImuDesk stopped the bridge"));
        c.socket->deleteLater();
    }
    m_clients.clear();
    for (auto &[id, ch] : m_channels)
        ch.subscribers.clear();
    if (m_server) {
        for (const auto &[tcp, peer] : m_handshaking)
            tcp->deleteLater();
        m_handshaking.clear();
        m_tcp->close();
        m_tcp.reset();
        m_server->close();
        m_server.reset();
        log(QStringLiteral("bridge stopped: %1 messages sent, %2 dropped").arg(m_stats.messagesSent).arg(m_stats.messagesDropped));
    }
    m_udp.reset();
    publishStats();
}

void BridgeWorker::addDevice(std::shared_ptr<device::SampleStore> store, const capture::CaptureHeader &header,
                             const QString &label)
{
    const device::SampleStore *key = store.get();
    if (m_devices.count(key))
        return;
    // A namespace of its own: two devices that give the same name get _2, _3, ...
    const std::string unique = fm::SampleChannels::uniqueName(
        capture::deviceName(header, label.toStdString()), [this](const std::string &n) {
            return std::any_of(m_devices.begin(), m_devices.end(), [&n](const auto &e) { return e.second.name == n; });
        });
    Device d{device::SampleCursor(std::move(store)), unique, nullptr, nullptr};
    d.sink = std::make_unique<DeviceSink>(*this, key);
    d.channels = std::make_unique<fm::SampleChannels>(*d.sink, capture::McapRecording::channelsOf(header, unique));
    m_devices.emplace(key, std::move(d));
    m_stats.devices = int(m_devices.size());
    log(QStringLiteral("device %1 added (/imu/%1/...)").arg(QString::fromStdString(unique)));
}

void BridgeWorker::removeDevice(const device::SampleStore *store)
{
    auto it = m_devices.find(store);
    if (it == m_devices.end())
        return;
    std::vector<uint32_t> gone;
    for (auto c = m_channels.begin(); c != m_channels.end();) {
        c->second.devices.erase(store);
        if (c->second.devices.empty()) {
            gone.push_back(c->first);
            for (Client &cl : m_clients)
                for (auto s = cl.channelOfSub.begin(); s != cl.channelOfSub.end();)
                    s = s->second == c->first ? cl.channelOfSub.erase(s) : std::next(s);
            c = m_channels.erase(c);
        } else {
            ++c;
        }
    }
    if (!gone.empty()) {
        const QByteArray text = foxglove::unadvertise(gone);
        for (Client &c : m_clients)
            c.socket->sendTextMessage(QString::fromUtf8(text));
    }
    log(QStringLiteral("device %1 removed").arg(QString::fromStdString(it->second.name)));
    m_devices.erase(it);
    m_stats.devices = int(m_devices.size());
}

uint32_t BridgeWorker::channelFor(const device::SampleStore *device, const std::string &topic,
                                  const std::string &encoding, const std::string &schemaName,
                                  const std::string &schema, const std::string &schemaEncoding)
{
    for (auto &[id, ch] : m_channels)
        if (ch.info.topic == topic && ch.info.schemaName == schemaName && ch.info.encoding == encoding) {
            ch.devices.insert(device);
            return id;
        }
    const uint32_t id = m_nextChannel++;
    Channel &ch = m_channels[id];
    ch.info = {id, topic, encoding, schemaName, schema, schemaEncoding};
    ch.devices.insert(device);
    const QString text = QString::fromUtf8(foxglove::advertise({ch.info}));
    for (Client &c : m_clients)
        c.socket->sendTextMessage(text);
    return id;
}

void BridgeWorker::publish(uint32_t channelId, uint64_t timeNs, const char *data, size_t size)
{
    m_latestTime = std::max(m_latestTime, timeNs);
    auto it = m_channels.find(channelId);
    if (it == m_channels.end() || it->second.subscribers.empty())
        return;
    for (const Subscriber &s : it->second.subscribers) {
        Client &c = *s.client;
        if (c.socket->bytesToWrite() > m_options.clientBufferBytes) {
            ++c.dropped;
            ++c.droppedNow;
            ++m_stats.messagesDropped;
            if (!c.slow) {
                c.slow = true;
                log(QStringLiteral("client %1 does not keep up (more than %2 MB unsent): its messages are dropped until it does")
                        .arg(c.peer).arg(double(m_options.clientBufferBytes) / (1 << 20), 0, 'f', 1));
            }
            continue;
        }
        c.socket->sendBinaryMessage(foxglove::messageData(s.subscription, timeNs, data, size));
        ++c.sent;
        ++m_stats.messagesSent;
    }
}

// The time goes to a slow client too (its clock goes on while its data is dropped): 17 bytes ten
// times a second, up to 64 kB past the client's buffer (six minutes of a client that reads nothing).
void BridgeWorker::sendTime(uint64_t ns)
{
    const QByteArray frame = foxglove::time(ns);
    for (Client &c : m_clients)
        if (c.socket->bytesToWrite() <= m_options.clientBufferBytes + (64 << 10))
            c.socket->sendBinaryMessage(frame);
}

// What the bridge promises a client: every message it could not send is counted, and told. A
// client that cannot keep up is told how many of its messages were dropped when it catches up
// (checkCaughtUp; its end is logged with the count either way). Samples the bridge itself missed
// (its thread not scheduled before a device's store wrapped, on a busy machine) are told to
// every client here, device by device, at most once a second.
void BridgeWorker::tellMissed()
{
    if (m_sinceMissedTold.isValid() && m_sinceMissedTold.elapsed() < 1000)
        return;
    for (auto &[key, d] : m_devices) {
        if (d.missedUntold == 0)
            continue;
        const QString what = QStringLiteral("%1 samples of %2 were not forwarded: the bridge fell behind the device "
                                            "(the computer is busy); every client misses them")
                                 .arg(d.missedUntold)
                                 .arg(QString::fromStdString(d.name));
        const QString text = QString::fromUtf8(foxglove::status(foxglove::StatusLevel::Warning, what));
        for (Client &c : m_clients)
            c.socket->sendTextMessage(text);
        log(what);
        d.missedUntold = 0;
        m_sinceMissedTold.start();
    }
}

void BridgeWorker::checkCaughtUp()
{
    for (Client &c : m_clients) {
        if (!c.slow || c.socket->bytesToWrite() > m_options.clientBufferBytes / 2)
            continue;
        c.slow = false;
        const QString what = QStringLiteral("%1 messages were dropped because this client did not read them fast enough")
                                 .arg(c.droppedNow);
        c.socket->sendTextMessage(QString::fromUtf8(foxglove::status(foxglove::StatusLevel::Warning, what)));
        log(QStringLiteral("client %1 caught up after %2 messages were dropped").arg(c.peer).arg(c.droppedNow));
        c.droppedNow = 0;
    }
}

void BridgeWorker::sendDatagram(const Device &d, const model::Sample &s)
{
    const int64_t t = (s.commonTimeNs != 0 ? s.commonTimeNs : s.hostTimeNs) + m_epochOffsetNs;
    // Seconds with the µs (9 significant digits, as format::number gives, would keep whole seconds).
    char stamp[32];
    std::snprintf(stamp, sizeof stamp, "%lld.%06lld", static_cast<long long>(t / 1'000'000'000),
                  static_cast<long long>((t % 1'000'000'000) / 1000));
    m_datagram.assign("{\"timestamp\":");
    m_datagram += stamp;
    m_datagram += ",\"";
    m_datagram += d.name;
    m_datagram += "\":";
    m_datagram += format::sampleToJson(s, d.channels->device().worldFrame);
    m_datagram += '}';
    if (m_udp->writeDatagram(m_datagram.data(), qint64(m_datagram.size()), m_options.udpHost, m_options.udpPort) < 0)
        ++m_stats.datagramErrors;
    else
        ++m_stats.datagramsSent;
}

void BridgeWorker::poll()
{
    for (auto &[key, d] : m_devices) {
        uint64_t missed = 0;
        const std::vector<model::Sample> batch = d.cursor.take(&missed);
        m_stats.samplesMissed += missed;
        d.missedUntold += missed;
        for (const model::Sample &s : batch) {
            d.channels->write(s, m_epochOffsetNs);
            if (m_udp)
                sendDatagram(d, s);
        }
        m_stats.samples += batch.size();
    }
    if (m_latestTime != 0 && m_latestTime >= m_lastTimeSent + uint64_t(kTimePeriodNs)) {
        m_lastTimeSent = m_latestTime;
        sendTime(m_latestTime);
    }
    checkCaughtUp();
    tellMissed();
}

void BridgeWorker::onTcpConnection()
{
    while (QTcpSocket *tcp = m_tcp->nextPendingConnection()) {
        const QString peer = QStringLiteral("%1:%2").arg(tcp->peerAddress().toString()).arg(tcp->peerPort());
        // Ours until it is a WebSocket (then the WebSocket's: onConnection), not the TCP
        // server's, which goes when the bridge stops.
        tcp->setParent(this);
        m_handshaking[tcp] = peer;
        QObject::connect(tcp, &QTcpSocket::disconnected, this, [this, tcp] {
            const auto it = m_handshaking.find(tcp);
            if (it == m_handshaking.end())
                return; // a WebSocket by now, or the bridge stopped
            log(QStringLiteral("connection %1 closed without a WebSocket handshake (not a WebSocket client, or it sent "
                               "nothing for 5 s)").arg(it->second));
            m_handshaking.erase(it);
            tcp->deleteLater();
        });
        m_server->handleConnection(tcp);
    }
}

void BridgeWorker::onConnection()
{
    while (QWebSocket *socket = m_server->nextPendingConnection()) {
        const QString peer = peerOf(socket);
        for (auto it = m_handshaking.begin(); it != m_handshaking.end(); ++it)
            if (it->second == peer) {
                if (it->first->parent() == this)
                    it->first->setParent(socket); // goes with its WebSocket
                m_handshaking.erase(it);
                break;
            }
        if (int(m_clients.size()) >= m_options.maxClients) {
            log(QStringLiteral("client %1 refused: %2 clients are connected already").arg(peer).arg(m_clients.size()));
            socket->close(QWebSocketProtocol::CloseCodePolicyViolated, QStringLiteral("too many clients"));
            socket->deleteLater();
            continue;
        }
        if (!foxglove::subprotocols().contains(socket->subprotocol())) {
            log(QStringLiteral("client %1 refused: it offered no Foxglove subprotocol").arg(peer));
            socket->close(QWebSocketProtocol::CloseCodeProtocolError,
                          QStringLiteral("offer the subprotocol foxglove.websocket.v1 or foxglove.sdk.v1"));
            socket->deleteLater();
            continue;
        }
        socket->setParent(this);
        socket->setMaxAllowedIncomingMessageSize(quint64(m_options.maxClientMessageBytes));
        socket->setMaxAllowedIncomingFrameSize(quint64(m_options.maxClientMessageBytes));
        m_clients.push_back(Client{socket, peer});
        Client *c = &m_clients.back();
        ++m_stats.connections;
        QObject::connect(socket, &QWebSocket::textMessageReceived, this, [this, c](const QString &t) { onText(c, t); });
        QObject::connect(socket, &QWebSocket::binaryMessageReceived, this, [this, c](const QByteArray &b) { onBinary(c, b); });
        // Queued: a socket can report its end from inside a send, while publish() walks the
        // subscribers.
        QObject::connect(socket, &QWebSocket::disconnected, this, [this, c] { onDisconnected(c); }, Qt::QueuedConnection);
        log(QStringLiteral("client %1 connected (%2)").arg(peer, socket->subprotocol()));

        std::map<std::string, std::string> meta{{"imudesk_version", QCoreApplication::applicationVersion().toStdString()}};
        socket->sendTextMessage(QString::fromUtf8(foxglove::serverInfo(
            QStringLiteral("ImuDesk"), {QStringLiteral("time")}, {QStringLiteral("cdr"), QStringLiteral("json")}, meta,
            m_sessionId)));
        if (!m_channels.empty()) {
            std::vector<foxglove::Channel> all;
            for (const auto &[id, ch] : m_channels)
                all.push_back(ch.info);
            socket->sendTextMessage(QString::fromUtf8(foxglove::advertise(all)));
        }
        if (m_latestTime)
            socket->sendBinaryMessage(foxglove::time(m_latestTime));
    }
}

void BridgeWorker::refuse(Client *c, const QString &what)
{
    if (++c->badRequests <= kLogsPerClient)
        log(QStringLiteral("client %1: %2").arg(c->peer, what));
    else if (c->badRequests == kLogsPerClient + 1)
        log(QStringLiteral("client %1: more bad requests; counted, no longer logged one by one").arg(c->peer));
    c->socket->sendTextMessage(QString::fromUtf8(foxglove::status(foxglove::StatusLevel::Error, what)));
}

void BridgeWorker::onText(Client *c, const QString &text)
{
    const foxglove::ClientRequest r = foxglove::parseClientText(text.toUtf8());
    switch (r.kind) {
    case foxglove::ClientRequest::Kind::Invalid:
        refuse(c, QStringLiteral("request ignored: %1").arg(r.error));
        return;
    case foxglove::ClientRequest::Kind::Unsupported:
        refuse(c, QStringLiteral("\"%1\" is not supported by this server (it streams; capabilities: time)").arg(r.op));
        return;
    case foxglove::ClientRequest::Kind::Subscribe:
        for (const auto &s : r.subscriptions) {
            auto ch = m_channels.find(s.channelId);
            if (ch == m_channels.end()) {
                refuse(c, QStringLiteral("no channel %1 to subscribe to").arg(s.channelId));
                continue;
            }
            if (c->channelOfSub.count(s.id)) {
                refuse(c, QStringLiteral("subscription id %1 is in use already").arg(s.id));
                continue;
            }
            auto &subs = ch->second.subscribers;
            if (std::any_of(subs.begin(), subs.end(), [c](const Subscriber &x) { return x.client == c; })) {
                refuse(c, QStringLiteral("channel %1 is subscribed already").arg(s.channelId));
                continue;
            }
            c->channelOfSub[s.id] = s.channelId;
            subs.push_back({c, s.id});
        }
        return;
    case foxglove::ClientRequest::Kind::Unsubscribe:
        dropSubscriptions(c, r.subscriptionIds);
        return;
    }
}

void BridgeWorker::dropSubscriptions(Client *c, const std::vector<uint32_t> &subscriptionIds)
{
    for (uint32_t id : subscriptionIds) {
        auto it = c->channelOfSub.find(id);
        if (it == c->channelOfSub.end())
            continue; // unsubscribing twice is harmless
        auto ch = m_channels.find(it->second);
        if (ch != m_channels.end()) {
            auto &subs = ch->second.subscribers;
            subs.erase(std::remove_if(subs.begin(), subs.end(), [c](const Subscriber &x) { return x.client == c; }),
                       subs.end());
        }
        c->channelOfSub.erase(it);
    }
}

void BridgeWorker::onBinary(Client *c, const QByteArray &data)
{
    refuse(c, QStringLiteral("a binary message of %1 bytes ignored: this server takes none (no clientPublish)").arg(data.size()));
}

void BridgeWorker::onDisconnected(Client *c)
{
    if (std::none_of(m_clients.begin(), m_clients.end(), [c](const Client &x) { return &x == c; }))
        return; // the bridge stopped meanwhile
    std::vector<uint32_t> ids;
    for (const auto &[sub, ch] : c->channelOfSub)
        ids.push_back(sub);
    dropSubscriptions(c, ids);
    const QWebSocketProtocol::CloseCode code = c->socket->closeCode();
    const QString reason = c->socket->closeReason();
    log(QStringLiteral("client %1 disconnected (%2%3): %4 messages sent, %5 dropped")
            .arg(c->peer)
            .arg(int(code))
            .arg(reason.isEmpty() ? QString() : QStringLiteral(", ") + reason)
            .arg(c->sent)
            .arg(c->dropped));
    c->socket->disconnect(this);
    c->socket->deleteLater();
    m_clients.remove_if([c](const Client &x) { return &x == c; });
}

void BridgeWorker::log(const QString &line)
{
    QMetaObject::invokeMethod(m_owner, [o = m_owner, line] { Q_EMIT o->logged(line); }, Qt::QueuedConnection);
}

void BridgeWorker::publishStats()
{
    m_stats.clients = int(m_clients.size());
    m_stats.queuedBytes = 0;
    for (const Client &c : m_clients) {
        const qint64 q = c.socket->bytesToWrite();
        m_stats.queuedBytes += q;
        m_stats.mostQueuedBytes = std::max(m_stats.mostQueuedBytes, q);
    }
    const BridgeStats s = m_stats;
    QMetaObject::invokeMethod(m_owner, [o = m_owner, s] { o->setStats(s); }, Qt::QueuedConnection);
}

// ---------------------------------------------------------------------------------------------

LiveBridge::LiveBridge(QObject *parent) : QObject(parent)
{
    qRegisterMetaType<BridgeStats>();
    m_thread.setObjectName(QStringLiteral("imudesk-bridge"));
    m_worker = new BridgeWorker(this);
    m_worker->moveToThread(&m_thread);
    QObject::connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    m_thread.start();
}

LiveBridge::~LiveBridge()
{
    stop();
    m_thread.quit();
    m_thread.wait();
}

bool LiveBridge::isLoopback(const QHostAddress &address)
{
    return address.isLoopback();
}

bool LiveBridge::parseHostPort(const QString &text, QHostAddress *address, quint16 *port, QString *error)
{
    QString host, portText = text;
    const int colon = int(text.lastIndexOf(QLatin1Char(':')));
    if (colon >= 0) {
        host = text.left(colon);
        portText = text.mid(colon + 1);
        if (host.startsWith(QLatin1Char('[')) && host.endsWith(QLatin1Char(']')))
            host = host.mid(1, host.size() - 2);
    }
    bool ok = false;
    const int p = portText.toInt(&ok);
    if (!ok || p < 0 || p > 65535) {
        *error = QStringLiteral("'%1': the port must be 0..65535").arg(text);
        return false;
    }
    *port = quint16(p);
    if (!host.isEmpty()) {
        if (host == QLatin1String("localhost"))
            host = QStringLiteral("127.0.0.1");
        QHostAddress a;
        if (!a.setAddress(host)) {
            *error = QStringLiteral("'%1' is not an IP address (e.g. 127.0.0.1, 0.0.0.0, ::1)").arg(host);
            return false;
        }
        *address = a;
    }
    return true;
}

QString LiveBridge::url() const
{
    QString host = m_options.address.toString();
    if (m_options.address == QHostAddress(QHostAddress::Any) || m_options.address == QHostAddress(QHostAddress::AnyIPv4))
        host = QStringLiteral("127.0.0.1");
    else if (m_options.address.protocol() == QAbstractSocket::IPv6Protocol)
        host = QLatin1Char('[') + host + QLatin1Char(']');
    return QStringLiteral("ws://%1:%2").arg(host).arg(m_port);
}

bool LiveBridge::start(const BridgeOptions &options, QString *error)
{
    QString why;
    quint16 port = 0;
    QMetaObject::invokeMethod(m_worker, [&] { why = m_worker->start(options, &port); }, Qt::BlockingQueuedConnection);
    m_options = options;
    m_running = why.isEmpty();
    m_port = m_running ? port : 0;
    if (!m_running && error)
        *error = why;
    return m_running;
}

void LiveBridge::stop()
{
    if (!m_running)
        return;
    QMetaObject::invokeMethod(m_worker, [this] { m_worker->stop(); }, Qt::BlockingQueuedConnection);
    m_running = false;
    m_port = 0;
}

void LiveBridge::addDevice(std::shared_ptr<device::SampleStore> store, const capture::CaptureHeader &header,
                           const QString &label)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, store = std::move(store), header, label]() mutable {
        w->addDevice(std::move(store), header, label);
    }, Qt::QueuedConnection);
}

void LiveBridge::removeDevice(const device::SampleStore *store)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, store] { w->removeDevice(store); }, Qt::QueuedConnection);
}

BridgeStats LiveBridge::stats() const
{
    std::lock_guard lock(m_statsMutex);
    return m_stats;
}

void LiveBridge::setStats(const BridgeStats &s)
{
    {
        std::lock_guard lock(m_statsMutex);
        m_stats = s;
    }
    Q_EMIT statsChanged(s);
}

} // namespace imudesk::bridge
