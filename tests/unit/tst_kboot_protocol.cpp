// KBOOT framing, commands, status messages and the streaming decoder. Golden packets from
// hipnuc-protocol-notes.md 3.1 (ping response) and 3.5 (example packets).
#include "protocol/kboot/command.h"
#include "protocol/kboot/packet.h"
#include "protocol/kboot/packet_decoder.h"
#include "protocol/kboot/status_code.h"
#include "../common/test_main.h"

#include <QRandomGenerator>
#include <QTest>

using namespace imudesk::protocol::kboot;

namespace {
std::vector<uint8_t> hex(const char *s)
{
    const QByteArray b = QByteArray::fromHex(s);
    return std::vector<uint8_t>(b.begin(), b.end());
}
} // namespace

Q_DECLARE_METATYPE(imudesk::protocol::kboot::Command)

class TstKbootProtocol : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void goldenCommands_data()
    {
        QTest::addColumn<Command>("command");
        QTest::addColumn<QByteArray>("packet");
        QTest::newRow("3.5 GetProperty 0x0B (NEW, 1 param)")
            << getProperty(PropertyTag::MaxPacketSize) << QByteArray("5aa40800d8bc070000010b000000");
        QTest::newRow("3.5 GetProperty 0x0B (OLD, 2 params)")
            << getProperty(PropertyTag::MaxPacketSize, true) << QByteArray("5aa40c0037a2070000020b00000000000000");
        QTest::newRow("3.5 GetProperty 0x01") << getProperty(PropertyTag::CurrentVersion)
                                              << QByteArray("5aa4080073d40700000101000000");
        QTest::newRow("3.5 FlashEraseRegion(0x08004000, 90712)")
            << flashEraseRegion(0x08004000, 90712) << QByteArray("5aa40c003a9302000002004000085862 0100");
        QTest::newRow("3.5 WriteMemory(0x08004000, 90712)")
            << writeMemory(0x08004000, 90712) << QByteArray("5aa40c000498040000020040000858620100");
        QTest::newRow("3.5 Reset") << reset() << QByteArray("5aa404006f460b000000");
        QTest::newRow("3.5 GenericResponse ok for erase")
            << genericResponse(0, 0x02) << QByteArray("5aa40c00ba55a00000020000000002000000");
        QTest::newRow("3.5 GetPropertyResponse value 512")
            << getPropertyResponse(0, {512}) << QByteArray("5aa40c00f9dea70000020000000000020000");
    }
    void goldenCommands()
    {
        QFETCH(Command, command);
        QFETCH(QByteArray, packet);
        const auto expected = hex(packet.replace(' ', "").constData());
        QCOMPARE(encodeFramed(PacketType::Command, command.encode()), expected);
        // and back
        PacketDecoder d;
        const auto got = d.feed(expected);
        QCOMPARE(got.size(), size_t(1));
        QCOMPARE(got[0].type, PacketType::Command);
        const auto c = Command::decode(got[0].payload);
        QVERIFY(c);
        QCOMPARE(*c, command);
    }

    void goldenDataAndControl()
    {
        const uint8_t data[] = {0xDE, 0xAD, 0xBE, 0xEF};
        QCOMPARE(encodeFramed(PacketType::Data, data, 4), hex("5aa504004624deadbeef")); // 3.5
        QCOMPARE(encodePing(), hex("5aa6"));
        QCOMPARE(encodeControl(PacketType::Ack), hex("5aa1"));
        QCOMPARE(encodeControl(PacketType::Nak), hex("5aa2"));
        QCOMPARE(encodeControl(PacketType::AckAbort), hex("5aa3"));
        // 3.1: vendor fake ping response, P2.0.0, options 0.
        QCOMPARE(encodePingResponse(PingResponse{0, 0, 2, 'P', 0}), hex("5aa700000250 0000f535"));
    }

    void decodeMixedStream()
    {
        std::vector<uint8_t> s = hex("00ff5a");            // garbage, then a lone start byte
        const auto add = [&s](const std::vector<uint8_t> &b) { s.insert(s.end(), b.begin(), b.end()); };
        add(hex("5aa1"));
        add(hex("5aa700000250 0000f535"));
        add(hex("5a77"));                                    // unknown type
        add(hex("5aa40c00f9dea70000020000000000020000"));
        auto bad = hex("5aa504004624deadbeee");              // CRC error
        add(bad);
        add(hex("5aa504004624deadbeef"));
        add(hex("5aa2"));
        // byte by byte, in one piece and random chunks must give the same packets
        PacketDecoder whole;
        const auto ref = whole.feed(s);
        QCOMPARE(ref.size(), size_t(5));
        QCOMPARE(ref[0].type, PacketType::Ack);
        QCOMPARE(ref[1].type, PacketType::PingResponse);
        QCOMPARE(ref[1].ping.major, uint8_t(2));
        QCOMPARE(ref[1].ping.name, uint8_t('P'));
        QCOMPARE(ref[2].type, PacketType::Command);
        QCOMPARE(ref[3].type, PacketType::Data);
        QCOMPARE(ref[3].payload, hex("deadbeef"));
        QCOMPARE(ref[4].type, PacketType::Nak);
        QCOMPARE(whole.counters().crcErrors, uint64_t(1));
        QCOMPARE(whole.counters().packets, uint64_t(5));
        QVERIFY(whole.counters().bytesSkipped >= 3 + 2 + bad.size() - 1);
        QCOMPARE(whole.pendingBytes(), size_t(0));

        PacketDecoder bytewise;
        std::vector<Packet> got;
        for (uint8_t b : s)
            bytewise.feed(&b, 1, got);
        QCOMPARE(got, ref);
        for (int round = 0; round < 50; ++round) {
            PacketDecoder d;
            std::vector<Packet> g;
            size_t at = 0;
            while (at < s.size()) {
                const size_t n = std::min(s.size() - at, size_t(QRandomGenerator::global()->bounded(1, 24)));
                d.feed(s.data() + at, n, g);
                at += n;
            }
            QCOMPARE(g, ref);
        }
    }

    void packetInsideDamagedCandidate()
    {
        // A length field that claims 4 bytes, 2 of which are a real ACK: the bad candidate's CRC
        // fails once enough bytes arrived, and the ACK inside it must still be found.
        std::vector<uint8_t> s = hex("5aa50400ffff5aa10000");
        PacketDecoder d;
        auto got = d.feed(s);
        QCOMPARE(got.size(), size_t(1));
        QCOMPARE(got[0].type, PacketType::Ack);
        QCOMPARE(d.counters().crcErrors, uint64_t(1));
    }

    void lengthBounded()
    {
        PacketDecoder d(512);
        auto got = d.feed(hex("5aa50102000000005aa1")); // 513 > 512
        QCOMPARE(got.size(), size_t(1));
        QCOMPARE(d.counters().lengthErrors, uint64_t(1));
        QVERIFY(d.pendingBytes() <= kFramedHeaderSize + 512);
        // a command must hold at least tag/flags/reserved/count
        PacketDecoder e;
        QCOMPARE(e.feed(hex("5aa402000000abcd")).size(), size_t(0));
        QCOMPARE(e.counters().lengthErrors, uint64_t(1));
    }

    void commandDecodeRejects()
    {
        QVERIFY(!Command::decode(hex("07000001")));             // says 1 param, holds none
        QVERIFY(!Command::decode(hex("070000")));               // too short
        QVERIFY(!Command::decode(hex("0700000100000000ff")));   // trailing byte
        QVERIFY(Command::decode(hex("0b000000")));
    }

    void statusMessages_data()
    {
        QTest::addColumn<uint>("code");
        QTest::addColumn<QString>("needle");
        QTest::newRow("success") << 0u << QStringLiteral("kStatus_Success (0)");
        QTest::newRow("alignment") << 101u << QStringLiteral("aligned");
        QTest::newRow("protection") << 104u << QStringLiteral("protected");
        QTest::newRow("unknown command") << 10000u << QStringLiteral("kStatus_UnknownCommand");
        QTest::newRow("cumulative write") << 10203u << QStringLiteral("not erased");
        QTest::newRow("unknown property") << 10300u << QStringLiteral("property");
        QTest::newRow("unknown code") << 4242u << QStringLiteral("unknown status 4242");
    }
    void statusMessages()
    {
        QFETCH(uint, code);
        QFETCH(QString, needle);
        QVERIFY2(KbootStatus::message(code).contains(needle), qPrintable(KbootStatus::message(code)));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstKbootProtocol)
#include "tst_kboot_protocol.moc"
