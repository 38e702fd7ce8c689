#pragma once
// The Foxglove WebSocket protocol (version 1, https://github.com/foxglove/ws-protocol,
// docs/spec.md), server side: the JSON text messages the server sends, the binary frames that
// carry messages and the time, and the client's requests read from text. What the live bridge
// (foxglove_bridge.h) speaks; plain functions, no sockets, so the wire format is tested alone.
//
// Subprotocols: "foxglove.websocket.v1" (the protocol's name) and "foxglove.sdk.v1" (the name
// the Foxglove SDK's servers and newer clients use for the same messages); a client must offer
// one of them.
#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace imudesk::bridge::foxglove {

inline const QStringList &subprotocols()
{
    static const QStringList names{QStringLiteral("foxglove.sdk.v1"), QStringLiteral("foxglove.websocket.v1")};
    return names;
}

enum class StatusLevel { Info = 0, Warning = 1, Error = 2 };

struct Channel {
    uint32_t id = 0;
    std::string topic, encoding, schemaName, schema, schemaEncoding;
};

// {"op":"serverInfo",...}: the server's name, capabilities ("time"), the message encodings it
// sends and metadata (key/value).
QByteArray serverInfo(const QString &name, const QStringList &capabilities, const QStringList &encodings,
                      const std::map<std::string, std::string> &metadata, const QString &sessionId);
QByteArray advertise(const std::vector<Channel> &channels);
QByteArray unadvertise(const std::vector<uint32_t> &channelIds);
QByteArray status(StatusLevel level, const QString &message, const QString &id = {});

// Binary: opcode 1, subscription id (uint32 LE), timestamp (uint64 LE, ns), the payload.
QByteArray messageData(uint32_t subscriptionId, uint64_t timestampNs, const char *payload, size_t size);
// Binary: opcode 2, timestamp (uint64 LE, ns): the server's current time (capability "time").
QByteArray time(uint64_t timestampNs);

// A client's text message, read.
struct ClientRequest {
    enum class Kind { Subscribe, Unsubscribe, Unsupported, Invalid };
    Kind kind = Kind::Invalid;
    struct Subscription {
        uint32_t id = 0;
        uint32_t channelId = 0;
    };
    std::vector<Subscription> subscriptions; // Subscribe
    std::vector<uint32_t> subscriptionIds;   // Unsubscribe
    QString op;                              // Unsupported: the op named
    QString error;                           // Invalid: what is wrong, in words
};
ClientRequest parseClientText(const QByteArray &text);

} // namespace imudesk::bridge::foxglove
