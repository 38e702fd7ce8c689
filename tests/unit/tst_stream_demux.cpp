// One UART stream carries binary frames, NMEA sentences and ASCII replies.
#include "../common/golden.h"
#include "../common/test_main.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/nmea/nmea_parser.h"
#include "protocol/stream/stream_demux.h"

#include <QRandomGenerator>
#include <QTest>

using namespace imudesk::protocol;

class TstStreamDemux : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void mixedStream_data()
    {
        QTest::addColumn<int>("chunk");
        QTest::newRow("whole") << 0;
        QTest::newRow("bytes") << 1;
        QTest::newRow("7") << 7;
    }
    void mixedStream()
    {
        QFETCH(int, chunk);
        QByteArray s;
        s += golden::hi91Frame();
        s += "PNAME=HI14R3\r\nAPP_VER=171\r\n";
        s += golden::hi91Frame();
        s += QByteArray(golden::kRmc) + "\r\n";
        s += "OK\r\n";
        s += golden::hi91Frame();
        s += QByteArray::fromHex("5AA5FFFF0102");          // false sync, bad length
        s += QByteArray(nmea::buildSentence("GPGGA,010101.00,3112.5,N,12127.5,E,1,08,1.0,10.0,M,0.0,M,,").c_str());
        s += "$GPRMC,1*00\r\n";                           // bad checksum
        s += "ERR\r\n";
        StreamDemux d;
        std::vector<StreamEvent> ev;
        const int n = chunk == 0 ? int(s.size()) : chunk;
        for (int i = 0; i < s.size(); i += n)
            d.feed(reinterpret_cast<const uint8_t *>(s.constData()) + i, size_t(qMin(n, int(s.size()) - i)), ev);
        d.finish(ev);
        QStringList kinds;
        for (const auto &e : ev) {
            switch (e.kind) {
            case StreamEvent::Kind::Frame: kinds << QStringLiteral("F%1").arg(e.payload.size()); break;
            case StreamEvent::Kind::Nmea: kinds << QStringLiteral("N:") + QString::fromStdString(e.text.substr(0, 6)); break;
            case StreamEvent::Kind::NmeaError: kinds << QStringLiteral("NE"); break;
            case StreamEvent::Kind::Line: kinds << QString::fromStdString(e.text); break;
            }
        }
        QCOMPARE(kinds, (QStringList{"F76", "PNAME=HI14R3", "APP_VER=171", "F76", "N:$GPRMC", "OK", "F76",
                                     "N:$GPGGA", "NE", "ERR"}));
        QCOMPARE(d.frameCounters().frames, uint64_t(3));
        QCOMPARE(d.counters().nmeaSentences, uint64_t(2));
        QCOMPARE(d.counters().nmeaErrors, uint64_t(1));
        QCOMPARE(d.counters().lines, uint64_t(4));
        QCOMPARE(d.frameCounters().lengthErrors, uint64_t(1));
    }

    void garbageBeforeReplyIsDropped()
    {
        // Binary junk glued to a reply: the reply line survives, the junk is counted.
        QByteArray s = QByteArray::fromHex("00FF8001") + "OK\r\n";
        StreamDemux d;
        d.endQuarantine(); // as the session does when it sends a command
        const auto ev = d.feed(reinterpret_cast<const uint8_t *>(s.constData()), size_t(s.size()));
        QCOMPARE(ev.size(), size_t(1));
        QCOMPARE(ev[0].text, std::string("OK"));
        QCOMPARE(d.counters().garbageBytes, uint64_t(4));
        QCOMPARE(d.counters().lineBytes, uint64_t(4)); // "OK\r\n"
        QCOMPARE(d.frameCounters().bytesSkipped, uint64_t(8));
    }

    void replyBytesAreNotDamage()
    {
        // A reply with CR CR LF, an NMEA sentence, junk and a line cut by the end: of what the
        // frame decoder skips, the reply and the sentence are text (lineBytes), the rest is
        // garbage, and together they are everything it skipped.
        const QByteArray nmea = "$GPZDA,160012.71,11,03,2004,-1,00*7D\r\n";
        QByteArray s = "OK\r\r\n" + nmea + QByteArray::fromHex("00FF") + "half";
        StreamDemux d;
        d.endQuarantine();
        std::vector<StreamEvent> ev = d.feed(reinterpret_cast<const uint8_t *>(s.constData()), size_t(s.size()));
        d.finish(ev);
        QCOMPARE(d.counters().lineBytes, uint64_t(5 + nmea.size() + 4)); // "half" ends with the stream
        QCOMPARE(d.counters().garbageBytes, uint64_t(2));
        QCOMPARE(d.counters().lineBytes + d.counters().garbageBytes, d.frameCounters().bytesSkipped);
    }

    void bytesAbove0x7FAfterALineStartAreKept()
    {
        // A serial read from erased flash (0xFF) or written in UTF-8 arrives as it was sent; the
        // same bytes before a line's first character are junk, dropped as before.
        QByteArray s = QByteArray("UUID=\xff\xfe\x80SN-\xc3\r\n") + QByteArray::fromHex("FF80") + "OK\r\n"
            + "NAME=\xe6\xb5\x8b\xe8\xaf\x95\r\n";
        StreamDemux d;
        d.endQuarantine();
        const auto ev = d.feed(reinterpret_cast<const uint8_t *>(s.constData()), size_t(s.size()));
        QCOMPARE(ev.size(), size_t(3));
        QCOMPARE(ev[0].text, std::string("UUID=\xff\xfe\x80SN-\xc3"));
        QCOMPARE(ev[1].text, std::string("OK"));
        QCOMPARE(QString::fromStdString(ev[2].text), QStringLiteral("NAME=\u6d4b\u8bd5"));
        QCOMPARE(d.counters().garbageBytes, uint64_t(2));
    }

    void overlongLineDiscarded()
    {
        QByteArray s(2000, 'x');
        s += "\r\nOK\r\n";
        StreamDemux d;
        d.endQuarantine();
        const auto ev = d.feed(reinterpret_cast<const uint8_t *>(s.constData()), size_t(s.size()));
        QCOMPARE(ev.size(), size_t(1));
        QCOMPARE(ev[0].text, std::string("OK"));
    }

    void quarantineAtStartAndAfterDamage()
    {
        // Joining a stream: a frame's tail with a 0x0A in it looks like a text line ",BW".
        // It is dropped until a valid frame proves a boundary; text after that is kept.
        const QByteArray f = golden::hi91Frame();
        QByteArray s = ",BW\n" + f + "OK\r\n";
        StreamDemux d;
        QVERIFY(d.quarantined());
        auto ev = d.feed(reinterpret_cast<const uint8_t *>(s.constData()), size_t(s.size()));
        QCOMPARE(ev.size(), size_t(2));
        QCOMPARE(ev[0].kind, StreamEvent::Kind::Frame);
        QCOMPARE(ev[1].text, std::string("OK"));
        QCOMPARE(d.counters().quarantinedLines, uint64_t(1));
        QVERIFY(!d.quarantined());
        // A damaged frame (CRC error) quarantines text again until the next good frame.
        QByteArray bad = f;
        bad[20] = char(bad[20] ^ 0x55);
        s = bad + "ZZ\n";
        ev = d.feed(reinterpret_cast<const uint8_t *>(s.constData()), size_t(s.size()));
        QVERIFY(ev.empty());
        QVERIFY(d.quarantined());
        // A valid NMEA sentence also ends it.
        s = QByteArray(golden::kRmc) + "\r\nOK\r\n";
        ev = d.feed(reinterpret_cast<const uint8_t *>(s.constData()), size_t(s.size()));
        QCOMPARE(ev.size(), size_t(2));
        QCOMPARE(ev[0].kind, StreamEvent::Kind::Nmea);
        QCOMPARE(ev[1].text, std::string("OK"));
    }

    void frameTailDoesNotPrefixReply()
    {
        // Connecting mid-stream: the tail of a frame ends in printable bytes, then a
        // whole frame, then a reply. The tail must not be glued to the reply.
        const QByteArray f = golden::hi91Frame();
        QByteArray s = f.right(5) + ">>" + f + "ERR\r\n";
        StreamDemux d;
        const auto ev = d.feed(reinterpret_cast<const uint8_t *>(s.constData()), size_t(s.size()));
        QCOMPARE(ev.size(), size_t(2));
        QCOMPARE(ev[0].kind, StreamEvent::Kind::Frame);
        QCOMPARE(ev[1].text, std::string("ERR"));
        QVERIFY(d.counters().garbageBytes >= 2);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstStreamDemux)
#include "tst_stream_demux.moc"
