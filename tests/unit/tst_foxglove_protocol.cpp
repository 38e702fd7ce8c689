// The Foxglove WebSocket protocol's server side (core/bridge/foxglove_protocol.h), byte for byte
// and field by field as the protocol's specification (ws-protocol docs/spec.md) lays it out:
// the binary frames, the JSON the server sends and the client requests it reads, good and bad.
#include "bridge/foxglove_protocol.h"
#include "../common/test_main.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace imudesk::bridge;

namespace {
QJsonObject object(const QByteArray &text)
{
    return QJsonDocument::fromJson(text).object();
}
} // namespace

class TstFoxgloveProtocol : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void messageDataFrame()
    {
        // opcode 0x01, subscription id uint32 LE, timestamp uint64 LE, payload
        const QByteArray f = foxglove::messageData(0x01020304u, 0x1122334455667788ull, "\xAA\xBB", 2);
        QCOMPARE(f, QByteArray::fromHex("01" "04030201" "8877665544332211" "aabb"));
        QCOMPARE(foxglove::messageData(7, 0, nullptr, 0), QByteArray::fromHex("01" "07000000" "0000000000000000"));
    }

    void timeFrame()
    {
        // opcode 0x02, timestamp uint64 LE: 1 700 000 000 000 000 000 ns
        QCOMPARE(foxglove::time(1700000000000000000ull), QByteArray::fromHex("02" "00002a36fe9c9717"));
    }

    void serverInfoNamesTheTimeCapability()
    {
        const QJsonObject o = object(foxglove::serverInfo(QStringLiteral("ImuDesk"), {QStringLiteral("time")},
                                                          {QStringLiteral("cdr"), QStringLiteral("json")},
                                                          {{"imudesk_version", "0.1.0"}}, QStringLiteral("s1")));
        QCOMPARE(o.value(QStringLiteral("op")).toString(), QStringLiteral("serverInfo"));
        QCOMPARE(o.value(QStringLiteral("name")).toString(), QStringLiteral("ImuDesk"));
        QCOMPARE(o.value(QStringLiteral("capabilities")).toArray(), QJsonArray{QStringLiteral("time")});
        QCOMPARE(o.value(QStringLiteral("supportedEncodings")).toArray(),
                 (QJsonArray{QStringLiteral("cdr"), QStringLiteral("json")}));
        QCOMPARE(o.value(QStringLiteral("metadata")).toObject().value(QStringLiteral("imudesk_version")).toString(),
                 QStringLiteral("0.1.0"));
        QCOMPARE(o.value(QStringLiteral("sessionId")).toString(), QStringLiteral("s1"));
    }

    void advertiseUnadvertiseStatus()
    {
        foxglove::Channel c{3, "/imu/SN1/imu", "cdr", "sensor_msgs/msg/Imu", "std_msgs/Header header\n", "ros2msg"};
        const QJsonObject a = object(foxglove::advertise({c}));
        QCOMPARE(a.value(QStringLiteral("op")).toString(), QStringLiteral("advertise"));
        const QJsonObject ch = a.value(QStringLiteral("channels")).toArray().at(0).toObject();
        QCOMPARE(ch.value(QStringLiteral("id")).toInt(), 3);
        QCOMPARE(ch.value(QStringLiteral("topic")).toString(), QStringLiteral("/imu/SN1/imu"));
        QCOMPARE(ch.value(QStringLiteral("encoding")).toString(), QStringLiteral("cdr"));
        QCOMPARE(ch.value(QStringLiteral("schemaName")).toString(), QStringLiteral("sensor_msgs/msg/Imu"));
        QCOMPARE(ch.value(QStringLiteral("schema")).toString(), QStringLiteral("std_msgs/Header header\n"));
        QCOMPARE(ch.value(QStringLiteral("schemaEncoding")).toString(), QStringLiteral("ros2msg"));

        const QJsonObject u = object(foxglove::unadvertise({3, 4}));
        QCOMPARE(u.value(QStringLiteral("channelIds")).toArray(), (QJsonArray{3, 4}));

        const QJsonObject s = object(foxglove::status(foxglove::StatusLevel::Warning, QStringLiteral("slow")));
        QCOMPARE(s.value(QStringLiteral("op")).toString(), QStringLiteral("status"));
        QCOMPARE(s.value(QStringLiteral("level")).toInt(), 1);
        QCOMPARE(s.value(QStringLiteral("message")).toString(), QStringLiteral("slow"));
        QVERIFY(!s.contains(QStringLiteral("id")));
    }

    void clientRequests_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<int>("kind");
        QTest::addColumn<QString>("detail"); // subscriptions "id:channel ...", ids "1 2", op, or error text
        using K = foxglove::ClientRequest::Kind;
        QTest::newRow("subscribe") << QByteArray(R"({"op":"subscribe","subscriptions":[{"id":0,"channelId":3},{"id":1,"channelId":9}]})")
                                   << int(K::Subscribe) << QStringLiteral("0:3 1:9");
        QTest::newRow("unsubscribe") << QByteArray(R"({"op":"unsubscribe","subscriptionIds":[0,1]})")
                                     << int(K::Unsubscribe) << QStringLiteral("0 1");
        QTest::newRow("an op not offered") << QByteArray(R"({"op":"getParameters","parameterNames":[]})")
                                           << int(K::Unsupported) << QStringLiteral("getParameters");
        QTest::newRow("client advertise (no clientPublish)") << QByteArray(R"({"op":"advertise","channels":[]})")
                                                             << int(K::Unsupported) << QStringLiteral("advertise");
        QTest::newRow("not JSON") << QByteArray("{{{ not json") << int(K::Invalid) << QStringLiteral("not JSON");
        QTest::newRow("bytes") << QByteArray("\xff\xfe\x00\x01", 4) << int(K::Invalid) << QStringLiteral("not JSON");
        QTest::newRow("an array") << QByteArray("[1,2]") << int(K::Invalid) << QStringLiteral("not a JSON object");
        QTest::newRow("no op") << QByteArray(R"({"subscriptions":[]})") << int(K::Invalid) << QStringLiteral("no \"op\"");
        QTest::newRow("op not a string") << QByteArray(R"({"op":5})") << int(K::Invalid) << QStringLiteral("no \"op\"");
        QTest::newRow("subscribe without a list") << QByteArray(R"({"op":"subscribe"})") << int(K::Invalid)
                                                  << QStringLiteral("subscribe without");
        QTest::newRow("channel id missing") << QByteArray(R"({"op":"subscribe","subscriptions":[{"id":0}]})")
                                            << int(K::Invalid) << QStringLiteral("numeric");
        QTest::newRow("negative id") << QByteArray(R"({"op":"subscribe","subscriptions":[{"id":-1,"channelId":1}]})")
                                     << int(K::Invalid) << QStringLiteral("numeric");
        QTest::newRow("fractional id") << QByteArray(R"({"op":"unsubscribe","subscriptionIds":[1.5]})")
                                       << int(K::Invalid) << QStringLiteral("whole number");
        QTest::newRow("id past 32 bits") << QByteArray(R"({"op":"subscribe","subscriptions":[{"id":4294967296,"channelId":1}]})")
                                         << int(K::Invalid) << QStringLiteral("numeric");
        QTest::newRow("id as a string") << QByteArray(R"({"op":"unsubscribe","subscriptionIds":["1"]})")
                                        << int(K::Invalid) << QStringLiteral("whole number");
    }
    void clientRequests()
    {
        QFETCH(QByteArray, text);
        QFETCH(int, kind);
        QFETCH(QString, detail);
        const foxglove::ClientRequest r = foxglove::parseClientText(text);
        QCOMPARE(int(r.kind), kind);
        using K = foxglove::ClientRequest::Kind;
        switch (r.kind) {
        case K::Subscribe: {
            QStringList got;
            for (const auto &s : r.subscriptions)
                got << QStringLiteral("%1:%2").arg(s.id).arg(s.channelId);
            QCOMPARE(got.join(QLatin1Char(' ')), detail);
            break;
        }
        case K::Unsubscribe: {
            QStringList got;
            for (uint32_t id : r.subscriptionIds)
                got << QString::number(id);
            QCOMPARE(got.join(QLatin1Char(' ')), detail);
            break;
        }
        case K::Unsupported:
            QCOMPARE(r.op, detail);
            break;
        case K::Invalid:
            QVERIFY2(r.error.contains(detail), qPrintable(r.error));
            QVERIFY(r.subscriptions.empty() && r.subscriptionIds.empty());
            break;
        }
    }

    void bothSubprotocolNames()
    {
        QCOMPARE(foxglove::subprotocols(), (QStringList{QStringLiteral("foxglove.sdk.v1"), QStringLiteral("foxglove.websocket.v1")}));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstFoxgloveProtocol)
#include "tst_foxglove_protocol.moc"
