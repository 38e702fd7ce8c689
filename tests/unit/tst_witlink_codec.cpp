// Witlink (HEC495) codec: every example command of the manual byte-exact, packed BCD,
// the 84-byte record, typed replies and the streaming decoder (chunking, garbage, damage).
#include "protocol/witlink/all_data_record.h"
#include "protocol/witlink/bcd.h"
#include "protocol/witlink/commands.h"
#include "protocol/witlink/frame_decoder.h"
#include "protocol/witlink/reply.h"
#include "../common/test_main.h"

#include <QRandomGenerator>
#include <QTest>

#include <cmath>
#include <functional>

using namespace imudesk::protocol::witlink;
using Bytes = std::vector<uint8_t>;
using Builder = std::function<Bytes()>;
Q_DECLARE_METATYPE(Builder)

namespace {

Bytes hex(const char *h)
{
    const QByteArray b = QByteArray::fromHex(h);
    return Bytes(b.begin(), b.end());
}

// Feeds a stream in the given chunking (0 whole, 1 byte by byte, -1 random).
std::vector<Frame> decodeWith(const Bytes &stream, int chunking, FrameDecoder *out = nullptr, quint32 seed = 3)
{
    FrameDecoder d;
    std::vector<Frame> frames;
    QRandomGenerator rng(seed);
    size_t i = 0;
    while (i < stream.size()) {
        size_t n = stream.size() - i;
        if (chunking == 1)
            n = 1;
        else if (chunking < 0)
            n = std::min<size_t>(n, size_t(rng.bounded(1, 40)));
        d.feed(stream.data() + i, n, frames);
        if (d.pendingBytes() > kMaxLength + 40)
            qFatal("the decoder holds more than one unfinished candidate");
        i += n;
    }
    if (out)
        *out = d;
    return frames;
}

AllDataRecord sampleRecord(uint32_t t)
{
    AllDataRecord r;
    r.pitch = -12.5f;
    r.roll = 33.25f;
    r.heading = -170.75f;
    r.acc = {0.1f, -0.2f, 0.97f};
    r.mag = {0.5f, 0.8f, -1.2f};
    r.gyr = {1.5f, -2.5f, 30.0f};
    r.magRoll = 45.0f;
    r.reserved[6] = 7.0f;
    r.timeMs = t;
    return r;
}

} // namespace

class TstWitlinkCodec : public QObject {
    Q_OBJECT
private Q_SLOTS:
    // Manual "通讯协议" 2.1-2.19 and the calibration chapter: every printed command.
    void manualCommands_data()
    {
        QTest::addColumn<Builder>("build");
        QTest::addColumn<QByteArray>("expected");
        using namespace commands;
        auto row = [](const char *name, Builder b, const char *h) { QTest::newRow(name) << b << QByteArray::fromHex(h); };
        row("2.1 read pitch", [] { return readPitch(); }, "7704000105");
        row("2.2 read roll", [] { return readRoll(); }, "7704000206");
        row("2.3 read heading", [] { return readHeading(); }, "7704000307");
        row("2.4 read angles", [] { return readAngles(); }, "7704000408");
        row("2.5 read all", [] { return readAll(); }, "7704001418");
        row("2.6 declination +20.8", [] { return setDeclination(20.8); }, "77060006020816");
        row("2.6 declination -3.2", [] { return setDeclination(-3.2); }, "7706000610324E");
        row("2.7 read declination", [] { return readDeclination(); }, "770400070B");
        row("2.8 / cal 1 auto 12-point", [] { return startCalibration(CalibrationMethod::Auto12); }, "7704006367");
        row("cal 2 manual", [] { return startCalibration(CalibrationMethod::Manual); }, "7704006569");
        row("cal 3 all-orientation", [] { return startCalibration(CalibrationMethod::AllOrientation); }, "770400080C");
        row("cal 4 small tilt", [] { return startCalibration(CalibrationMethod::SmallTilt12); }, "7704006468");
        row("cal 5 planar", [] { return startCalibration(CalibrationMethod::Planar); }, "7704006064");
        row("2.11 collect point", [] { return collectPoint(); }, "770400676B");
        row("2.10 stop calibration", [] { return stopCalibration(); }, "7704001216");
        row("2.9 save calibration", [] { return saveCalibration(); }, "770400090D");
        row("2.12 clear calibration", [] { return clearCalibration(); }, "7704001014");
        row("2.13 baud 9600", [] { return setBaud(9600); }, "7705000B0212");
        row("2.13 baud 19200", [] { return setBaud(19200); }, "7705000B0313");
        row("2.14 question/answer", [] { return setOutputRate(0); }, "7705000C0011");
        row("2.15 content default", [] { return setOutputContent(OutputContent::Default); }, "770500490 04E");
        row("2.16 set address 1", [] { return setAddress(1); }, "7705000F0115");
        row("2.17 query address", [] { return queryAddress(); }, "7704001F23");
        row("2.18 save settings", [] { return saveSettings(); }, "7704000A0E");
        row("2.19 factory reset", [] { return factoryReset(); }, "7704000E12");
    }
    void manualCommands()
    {
        QFETCH(Builder, build);
        QFETCH(QByteArray, expected);
        const Bytes b = build();
        QCOMPARE(QByteArray(reinterpret_cast<const char *>(b.data()), qsizetype(b.size())).toHex(' '),
                 expected.toHex(' '));
        // And each decodes back to itself.
        const auto frames = FrameDecoder().feed(b);
        QCOMPARE(frames.size(), size_t(1));
        QCOMPARE(encodeFrame(frames[0]), b);
    }

    void builderLimits()
    {
        QVERIFY(commands::setBaud(38400).empty());
        QVERIFY(commands::setOutputRate(20).empty());
        QVERIFY(commands::setDeclination(100.0).empty());
        QVERIFY(commands::setDeclination(std::nan("")).empty());
        QCOMPARE(commands::setOutputRate(50), hex("7705000C0516"));
        QCOMPARE(commands::setBaud(115200, 3), hex("7705030B0417"));
        for (int b : commands::supportedBauds())
            QCOMPARE(commands::baudFromCode(*commands::baudCode(b)), b);
        for (int r : commands::supportedRates())
            QCOMPARE(commands::rateFromCode(*commands::rateCode(r)), r);
    }

    void angles_data()
    {
        QTest::addColumn<QByteArray>("bcd");
        QTest::addColumn<double>("deg");
        // 2.1 note and 2.4 example.
        QTest::newRow("2.1 -26.8") << QByteArray::fromHex("102680") << -26.8;
        QTest::newRow("2.4 33.65") << QByteArray::fromHex("003365") << 33.65;
        QTest::newRow("2.4 313.71") << QByteArray::fromHex("031371") << 313.71;
        QTest::newRow("zero") << QByteArray::fromHex("000000") << 0.0;
        QTest::newRow("-0.01") << QByteArray::fromHex("100001") << -0.01;
        QTest::newRow("max") << QByteArray::fromHex("199999") << -999.99;
    }
    void angles()
    {
        QFETCH(QByteArray, bcd);
        QFETCH(double, deg);
        const auto v = decodeAngle(reinterpret_cast<const uint8_t *>(bcd.constData()));
        QVERIFY(v);
        QCOMPARE(*v, deg);
        const auto e = encodeAngle(deg);
        QVERIFY(e);
        QCOMPARE(QByteArray(reinterpret_cast<const char *>(e->data()), 3), bcd);
    }

    void badBcd()
    {
        const uint8_t sign2[3] = {0x20, 0x00, 0x00}, digitA[3] = {0x00, 0x0A, 0x00};
        QVERIFY(!decodeAngle(sign2));
        QVERIFY(!decodeAngle(digitA));
        const uint8_t decl[2] = {0x0F, 0x00};
        QVERIFY(!decodeDeclination(decl));
        QVERIFY(!encodeAngle(1000.0));
    }

    void declination_data()
    {
        QTest::addColumn<QByteArray>("bcd");
        QTest::addColumn<double>("deg");
        // 2.6 note.
        QTest::newRow("2.6 +20.8") << QByteArray::fromHex("0208") << 20.8;
        QTest::newRow("2.6 -3.2") << QByteArray::fromHex("1032") << -3.2;
        QTest::newRow("-99.9") << QByteArray::fromHex("1999") << -99.9;
    }
    void declination()
    {
        QFETCH(QByteArray, bcd);
        QFETCH(double, deg);
        const auto v = decodeDeclination(reinterpret_cast<const uint8_t *>(bcd.constData()));
        QVERIFY(v);
        QCOMPARE(*v, deg);
        const auto e = encodeDeclination(deg);
        QVERIFY(e);
        QCOMPARE(QByteArray(reinterpret_cast<const char *>(e->data()), 2), bcd);
    }

    // 2.4: 77 0D 00 84 10 26 80 00 33 65 03 13 71 66.
    void manualAnglesReply()
    {
        const auto frames = FrameDecoder().feed(hex("770D00841026800033650313716 6"));
        QCOMPARE(frames.size(), size_t(1));
        const Reply r = decodeReply(frames[0]);
        QVERIFY(r.ok());
        QCOMPARE(r.kind, Reply::Kind::Angles);
        QCOMPARE(r.request, uint8_t(0x04));
        QCOMPARE(r.pitch, -26.8);
        QCOMPARE(r.roll, 33.65);
        QCOMPARE(r.heading, 313.71);
        QCOMPARE(encodeFrame(anglesReply(0, -26.8, 33.65, 313.71)), hex("770D0084102680003365031371 66"));
    }

    // 2.9: the page prints 77 09 00 89 00 00 80 3F 0C E9, but the bytes sum to 0x5D.
    void manualSaveCalibrationReply()
    {
        FrameDecoder d;
        QVERIFY(d.feed(hex("77090089000080 3F0CE9")).empty());
        QCOMPARE(d.counters().checksumErrors, uint64_t(1));
        QCOMPARE(d.counters().frames, uint64_t(0));
        const auto frames = d.feed(hex("770900890000803F0C5D"));
        QCOMPARE(frames.size(), size_t(1));
        const Reply r = decodeReply(frames[0]);
        QVERIFY(r.ok());
        QCOMPARE(r.kind, Reply::Kind::CalibrationSaved);
        QCOMPARE(r.fitError, 1.0f);
        QCOMPARE(r.points, 12);
        QCOMPARE(encodeFrame(calibrationSavedReply(0, 1.0f, 12)), hex("770900890000803F0C5D"));
    }

    void statusReplies_data()
    {
        QTest::addColumn<QByteArray>("frame");
        QTest::addColumn<int>("request");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<bool>("success");
        auto f = [](uint8_t addr, uint8_t cmd, Bytes data) {
            const Bytes b = encodeFrame(addr, cmd, data);
            return QByteArray(reinterpret_cast<const char *>(b.data()), qsizetype(b.size()));
        };
        QTest::newRow("2.6 86 ok") << f(0, 0x86, {0x00}) << 0x06 << true << true;
        QTest::newRow("2.6 86 failed") << f(0, 0x86, {0xFF}) << 0x06 << true << false;
        QTest::newRow("2.8 88 ok") << f(0, 0x88, {0x00}) << 0x08 << true << true;
        QTest::newRow("2.10 72 ok") << f(0, 0x72, {0x00}) << 0x12 << true << true;
        QTest::newRow("2.12 90 failed") << f(0, 0x90, {0xFF}) << 0x10 << true << false;
        QTest::newRow("2.13 8B ok") << f(0, 0x8B, {0x00}) << 0x0B << true << true;
        QTest::newRow("2.14 8C ok") << f(0, 0x8C, {0x00}) << 0x0C << true << true;
        QTest::newRow("2.15 49 ok") << f(0, 0x49, {0x00}) << 0x49 << true << true;
        QTest::newRow("2.16 8F from FF") << f(0xFF, 0x8F, {0x00}) << 0x0F << true << true;
        QTest::newRow("2.18 8A ok") << f(0, 0x8A, {0x00}) << 0x0A << true << true;
        QTest::newRow("2.19 8E failed") << f(0, 0x8E, {0xFF}) << 0x0E << true << false;
        QTest::newRow("2.9 89 failed") << f(0, 0x89, {0xFF}) << 0x09 << true << false;
        QTest::newRow("status 01 is no status") << f(0, 0x8A, {0x01}) << 0x0A << false << false;
        QTest::newRow("status too long") << f(0, 0x8A, {0x00, 0x00}) << 0x0A << false << false;
        QTest::newRow("unknown") << f(0, 0xAB, {0x00}) << 0 << false << false;
    }
    void statusReplies()
    {
        QFETCH(QByteArray, frame);
        QFETCH(int, request);
        QFETCH(bool, ok);
        QFETCH(bool, success);
        const auto frames = FrameDecoder().feed(reinterpret_cast<const uint8_t *>(frame.constData()), size_t(frame.size()));
        QCOMPARE(frames.size(), size_t(1));
        const Reply r = decodeReply(frames[0]);
        QCOMPARE(r.ok(), ok);
        QCOMPARE(r.success, success);
        QCOMPARE(int(r.request), request);
        QVERIFY(!r.describe().isEmpty());
    }

    void otherReplies()
    {
        Reply r = decodeReply(Frame{0, 0x87, {0x10, 0x32}});
        QCOMPARE(r.kind, Reply::Kind::Declination);
        QCOMPARE(r.declination, -3.2);
        r = decodeReply(Frame{0, 0x1F, {0x05}});
        QCOMPARE(r.kind, Reply::Kind::Address);
        QCOMPARE(r.deviceAddress, uint8_t(5));
        r = decodeReply(Frame{0, 0x83, {0x03, 0x13, 0x71}});
        QCOMPARE(r.kind, Reply::Kind::Angle);
        QCOMPARE(r.angle, 313.71);
        r = decodeReply(Frame{0, 0x83, {0x03, 0x1A, 0x71}});
        QCOMPARE(r.error, Reply::Error::BadBcd);
        std::array<uint8_t, 15> pb{};
        pb[0] = 9;
        const Bytes point = encodeFrame(calibrationPointReply(0, pb, 7));
        QCOMPARE(point[1], uint8_t(0x14)); // 2.11: LEN 14 = 15 field bytes + count
        r = decodeReply(FrameDecoder().feed(point).at(0));
        QCOMPARE(r.kind, Reply::Kind::CalibrationPoint);
        QCOMPARE(r.points, 7);
        QCOMPARE(r.pointBytes[0], uint8_t(9));
        QCOMPARE(r.request, uint8_t(0x67));
    }

    void expectedReplies()
    {
        QCOMPARE(commands::expectedReplies(0x04), Bytes{0x84});
        QCOMPARE(commands::expectedReplies(0x14), Bytes{0x14});
        QCOMPARE(commands::expectedReplies(0x63).front(), uint8_t(0x88));
        QCOMPARE(commands::expectedReplies(0x12).front(), uint8_t(0x72));
        QVERIFY(commands::expectedReplies(0x55).empty());
    }

    void allDataRecord()
    {
        const AllDataRecord r = sampleRecord(123456);
        const Bytes data = r.encode();
        QCOMPARE(data.size(), AllDataRecord::kSize);
        const Bytes frame = encodeFrame(0, 0x14, data);
        QCOMPARE(frame.size(), size_t(89));
        QCOMPARE(frame[1], uint8_t(0x58)); // 2.5: LEN 58
        const Reply rep = decodeReply(FrameDecoder().feed(frame).at(0));
        QVERIFY(rep.ok());
        QCOMPARE(rep.kind, Reply::Kind::AllData);
        QCOMPARE(rep.record, r);
        // Field order: the time is the last 4 bytes, little-endian.
        QCOMPARE(data[80], uint8_t(123456 & 0xFF));
        QCOMPARE(data[83], uint8_t(0));
        // pitch first: -12.5f = 0xC1480000 LE.
        QCOMPARE(Bytes(data.begin(), data.begin() + 4), hex("000048C1"));
        const auto s = rep.record.toSample(42);
        QCOMPARE(s.source, std::string("HEC495"));
        QVERIFY(s.has(imudesk::model::FieldEuler) && s.has(imudesk::model::FieldAcc) && s.has(imudesk::model::FieldGyr));
        QVERIFY(!s.has(imudesk::model::FieldMag)); // relative, not uT: magRelative
        QVERIFY(s.has(imudesk::model::FieldMagRelative) && s.has(imudesk::model::FieldMagRoll));
        QCOMPARE(s.magRelative.x, 0.5);
        QCOMPARE(s.magRelative.z, double(-1.2f));
        QCOMPARE(s.magRollDeg, 45.0);
        QCOMPARE(s.pitch, -12.5);
        QCOMPARE(s.roll, 33.25);
        QCOMPARE(s.headingDeg, 189.25); // the record's -170.75, clockwise 0..360
        QCOMPARE(s.yaw, 170.75);        // the world frame's yaw, ENU (issue 53 point 7)
        QCOMPARE(s.gyr.z, 30.0);
        QCOMPARE(s.deviceTimeMs, 123456.0);
        QCOMPARE(s.hostTimeNs, int64_t(42));
        QVERIFY(!AllDataRecord::decode(data.data(), 80));
        QCOMPARE(decodeReply(Frame{0, 0x14, Bytes(80)}).error, Reply::Error::BadLength);
    }

    void streaming_data()
    {
        QTest::addColumn<int>("chunking");
        QTest::newRow("whole") << 0;
        QTest::newRow("byte by byte") << 1;
        QTest::newRow("random chunks") << -1;
    }
    void streaming()
    {
        QFETCH(int, chunking);
        // Garbage (with false syncs), frames, a damaged frame, a frame that starts inside a
        // false candidate, the manual's bad-checksum reply.
        Bytes stream = hex("0102777700FF77");
        std::vector<Frame> sent;
        for (uint32_t i = 0; i < 20; ++i) {
            Frame f{uint8_t(i % 3), 0x14, sampleRecord(i).encode()};
            if (i % 4 == 1)
                f = anglesReply(0, -1.0 * i, 2.0, 300.0);
            const Bytes b = encodeFrame(f);
            if (i == 7) { // damaged copy first
                Bytes bad = b;
                bad[20] ^= 0x40;
                stream.insert(stream.end(), bad.begin(), bad.end());
            }
            if (i == 11) { // a false sync whose LEN would swallow the real frame
                stream.push_back(0x77);
                stream.push_back(0x30);
            }
            stream.insert(stream.end(), b.begin(), b.end());
            sent.push_back(f);
        }
        const Bytes manual = hex("770900890000803F0CE9");
        stream.insert(stream.end(), manual.begin(), manual.end());
        FrameDecoder d;
        const auto frames = decodeWith(stream, chunking, &d);
        QCOMPARE(frames.size(), sent.size());
        for (size_t i = 0; i < sent.size(); ++i)
            QCOMPARE(frames[i], sent[i]);
        QVERIFY(d.counters().checksumErrors >= 2);
        QVERIFY(d.counters().bytesSkipped > 0);
        QCOMPARE(d.counters().frames, uint64_t(sent.size()));
        QCOMPARE(d.counters().bytesIn, uint64_t(stream.size()));
    }

    void idleFlushReleasesHeldFrame()
    {
        // A false sync with a long LEN holds back the short reply after it until the line is idle.
        FrameDecoder d;
        Bytes s = {0x77, 0x50};
        const Bytes ok = encodeFrame(statusReply(0, 0x8A, true));
        s.insert(s.end(), ok.begin(), ok.end());
        QVERIFY(d.feed(s).empty());
        std::vector<Frame> out;
        d.flushIdle(out);
        QCOMPARE(out.size(), size_t(1));
        QCOMPARE(out[0].command, uint8_t(0x8A));
        QCOMPARE(d.pendingBytes(), size_t(0));
        QCOMPARE(d.takeSkipped(), std::string("\x77\x50", 2));
    }

    void textIsKeptForTheCaller()
    {
        FrameDecoder d;
        const std::string text = "$HCHDT,313.7,T*1F\r\n";
        QVERIFY(d.feed(reinterpret_cast<const uint8_t *>(text.data()), text.size()).empty());
        QCOMPARE(d.takeSkipped(), text);
        QCOMPARE(d.counters().bytesSkipped, uint64_t(text.size()));
    }

    void lengthBounds()
    {
        FrameDecoder d;
        QVERIFY(d.feed(hex("770300")).empty()); // LEN 3 < 4
        QVERIFY(d.feed(hex("7759")).empty());   // LEN 0x59 > 0x58
        QCOMPARE(d.counters().lengthErrors, uint64_t(2));
        QVERIFY(encodeFrame(0, 0x14, Bytes(kMaxData + 1)).empty());
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstWitlinkCodec)
#include "tst_witlink_codec.moc"
