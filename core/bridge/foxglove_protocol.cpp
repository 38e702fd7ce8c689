#include "foxglove_protocol.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonParseError>

#include <cstring>

namespace imudesk::bridge::foxglove {

namespace {

QByteArray compact(const QJsonObject &o)
{
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

QString fromStd(const std::string &s)
{
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}

void putLe(char *at, uint64_t v, int bytes)
{
    for (int i = 0; i < bytes; ++i)
        at[i] = char((v >> (8 * i)) & 0xff);
}

// A JSON number that is a whole, non-negative id that fits 32 bits.
bool idOf(const QJsonValue &v, uint32_t *out)
{
    if (!v.isDouble())
        return false;
    const double d = v.toDouble();
    if (d < 0 || d > 4294967295.0 || d != double(uint64_t(d)))
        return false;
    *out = uint32_t(d);
    return true;
}

} // namespace

QByteArray serverInfo(const QString &name, const QStringList &capabilities, const QStringList &encodings,
                      const std::map<std::string, std::string> &metadata, const QString &sessionId)
{
    QJsonObject meta;
    for (const auto &[k, v] : metadata)
        meta.insert(fromStd(k), fromStd(v));
    return compact({{QStringLiteral("op"), QStringLiteral("serverInfo")},
                    {QStringLiteral("name"), name},
                    {QStringLiteral("capabilities"), QJsonArray::fromStringList(capabilities)},
                    {QStringLiteral("supportedEncodings"), QJsonArray::fromStringList(encodings)},
                    {QStringLiteral("metadata"), meta},
                    {QStringLiteral("sessionId"), sessionId}});
}

QByteArray advertise(const std::vector<Channel> &channels)
{
    QJsonArray list;
    for (const Channel &c : channels)
        list.append(QJsonObject{{QStringLiteral("id"), double(c.id)},
                                {QStringLiteral("topic"), fromStd(c.topic)},
                                {QStringLiteral("encoding"), fromStd(c.encoding)},
                                {QStringLiteral("schemaName"), fromStd(c.schemaName)},
                                {QStringLiteral("schema"), fromStd(c.schema)},
                                {QStringLiteral("schemaEncoding"), fromStd(c.schemaEncoding)}});
    return compact({{QStringLiteral("op"), QStringLiteral("advertise")}, {QStringLiteral("channels"), list}});
}

QByteArray unadvertise(const std::vector<uint32_t> &channelIds)
{
    QJsonArray ids;
    for (uint32_t id : channelIds)
        ids.append(double(id));
    return compact({{QStringLiteral("op"), QStringLiteral("unadvertise")}, {QStringLiteral("channelIds"), ids}});
}

QByteArray status(StatusLevel level, const QString &message, const QString &id)
{
    QJsonObject o{{QStringLiteral("op"), QStringLiteral("status")},
                  {QStringLiteral("level"), int(level)},
                  {QStringLiteral("message"), message}};
    if (!id.isEmpty())
        o.insert(QStringLiteral("id"), id);
    return compact(o);
}

QByteArray messageData(uint32_t subscriptionId, uint64_t timestampNs, const char *payload, size_t size)
{
    QByteArray out(qsizetype(1 + 4 + 8 + size), Qt::Uninitialized);
    char *p = out.data();
    p[0] = 1;
    putLe(p + 1, subscriptionId, 4);
    putLe(p + 5, timestampNs, 8);
    if (size)
        std::memcpy(p + 13, payload, size);
    return out;
}

QByteArray time(uint64_t timestampNs)
{
    QByteArray out(9, Qt::Uninitialized);
    out[0] = 2;
    putLe(out.data() + 1, timestampNs, 8);
    return out;
}

ClientRequest parseClientText(const QByteArray &text)
{
    ClientRequest r;
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(text, &error);
    if (error.error != QJsonParseError::NoError || !doc.isObject()) {
        r.error = error.error != QJsonParseError::NoError
                      ? QStringLiteral("not JSON (%1 at byte %2)").arg(error.errorString()).arg(error.offset)
                      : QStringLiteral("not a JSON object");
        return r;
    }
    const QJsonObject o = doc.object();
    const QJsonValue op = o.value(QStringLiteral("op"));
    if (!op.isString()) {
        r.error = QStringLiteral("no \"op\"");
        return r;
    }
    r.op = op.toString();
    if (r.op == QLatin1String("subscribe")) {
        const QJsonValue list = o.value(QStringLiteral("subscriptions"));
        if (!list.isArray()) {
            r.error = QStringLiteral("subscribe without \"subscriptions\"");
            return r;
        }
        for (const QJsonValue &v : list.toArray()) {
            ClientRequest::Subscription s;
            const QJsonObject e = v.toObject();
            if (!idOf(e.value(QStringLiteral("id")), &s.id) || !idOf(e.value(QStringLiteral("channelId")), &s.channelId)) {
                r.error = QStringLiteral("a subscription needs a numeric \"id\" and \"channelId\"");
                r.subscriptions.clear();
                return r;
            }
            r.subscriptions.push_back(s);
        }
        r.kind = ClientRequest::Kind::Subscribe;
    } else if (r.op == QLatin1String("unsubscribe")) {
        const QJsonValue list = o.value(QStringLiteral("subscriptionIds"));
        if (!list.isArray()) {
            r.error = QStringLiteral("unsubscribe without \"subscriptionIds\"");
            return r;
        }
        for (const QJsonValue &v : list.toArray()) {
            uint32_t id = 0;
            if (!idOf(v, &id)) {
                r.error = QStringLiteral("a subscription id must be a whole number");
                r.subscriptionIds.clear();
                return r;
            }
            r.subscriptionIds.push_back(id);
        }
        r.kind = ClientRequest::Kind::Unsubscribe;
    } else {
        r.kind = ClientRequest::Kind::Unsupported;
    }
    return r;
}

} // namespace imudesk::bridge::foxglove
