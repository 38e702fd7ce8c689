// Payload codecs: the manual's HI91 example, round trips of every payload, HI83 bitmaps.
#include "../common/golden.h"
#include "model/main_status.h"
#include "protocol/hipnuc/payloads.h"

#include <QTest>

using namespace imudesk::protocol::hipnuc;
using imudesk::model::MainStatus;

class TstPayloads : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void manualHi91Example()
    {
        const auto f = golden::bytes(golden::hi91Frame());
        const auto res = decodePayload(f.data() + 6, 76);
        QVERIFY(res.ok());
        QCOMPARE(res.packets.size(), size_t(1));
        const Hi91 h = std::get<Hi91>(res.packets[0]);
        QCOMPARE(h.mainStatus, uint16_t(0x1508));
        QCOMPARE(int(h.temperature), 35);
        QVERIFY(qAbs(h.pressure - 100676.0703125f) < 1e-3f);
        QCOMPARE(h.systemTime, uint32_t(1840392));
        auto near = [](double a, double b, double tol) { return qAbs(a - b) <= tol; };
        QVERIFY(near(h.acc[0], -0.220615, 1e-6));
        QVERIFY(near(h.acc[1], 0.209189, 1e-6));
        QVERIFY(near(h.acc[2], 0.948889, 1e-6));
        QVERIFY(near(h.gyr[0], -0.061722, 1e-6));
        QVERIFY(near(h.gyr[1], -0.00603836, 1e-8));
        QVERIFY(near(h.gyr[2], -0.0100611, 1e-7));
        QVERIFY(near(h.mag[0], 7.89167, 1e-5));
        QVERIFY(near(h.mag[1], 14.625, 1e-6));
        QVERIFY(near(h.mag[2], -60.0417, 1e-4));
        QVERIFY(near(h.roll, 13.0519, 1e-4));
        QVERIFY(near(h.pitch, 12.1885, 1e-4));
        QVERIFY(near(h.yaw, -122.477, 1e-3));
        QVERIFY(near(h.quat[0], -0.485922, 1e-6));
        QVERIFY(near(h.quat[1], -0.14982, 1e-5));
        QVERIFY(near(h.quat[2], 0.0380868, 1e-7));
        QVERIFY(near(h.quat[3], 0.860223, 1e-6));
        // Fast path agrees.
        Hi91 fast;
        QVERIFY(decodeHi91(f.data() + 6, 76, fast));
        QCOMPARE(fast, h);
        // Sample in ImuDesk units.
        const auto s = toSample(res.packets[0]);
        QCOMPARE(s.source, std::string("HI91"));
        QVERIFY(near(s.yaw, -122.477, 1e-3));
        QCOMPARE(s.deviceTimeMs, 1840392.0);
        // 0x1508: bits 3 (WB_CONV), 8 (reserved), 10 (MAG_AIDING), 12 (SOUT_PULSE).
        const MainStatus st(h.mainStatus);
        QVERIFY(st.test(MainStatus::WbConv));
        QVERIFY(st.test(MainStatus::MagAiding));
        QVERIFY(st.test(MainStatus::SoutPulse));
        QVERIFY(!st.test(MainStatus::MagDist));
        QCOMPARE(st.setFlagNames(), (std::vector<std::string>{"WB_CONV", "MAG_AIDING", "SOUT_PULSE"}));
        QCOMPARE(st.undefinedBits(), uint16_t(0x0100));
    }

    void roundTrips()
    {
        Hi91 a;
        a.mainStatus = 0x0C88;
        a.temperature = -12;
        a.pressure = 99876.5f;
        a.systemTime = 86399999;
        a.acc = {0.1f, -0.2f, 0.98f};
        a.gyr = {1.5f, -2.5f, 300.f};
        a.mag = {20.f, -30.f, 40.f};
        a.roll = 1;
        a.pitch = -2;
        a.yaw = 179.9f;
        a.quat = {0.7071f, 0, 0, 0.7071f};
        Hi92 b;
        b.temperature = 40;
        b.pressure = 2000;
        b.heave = -123;
        b.gyr = {100, -200, 300};
        b.acc = {-2009, 0, 2009};
        b.mag = {1000, -1000, 32767};
        b.roll = -179999;
        b.pitch = 89999;
        b.yaw = 123456;
        b.quat = {10000, -1, 2, -3};
        Hi81 c;
        c.mainStatus = 0x0800;
        c.insStatus = 3;
        c.gpsWeek = 2300;
        c.gpsTowMs = 123456789;
        c.yaw = 35999;
        c.lat = 399401294;
        c.lon = 1163456789;
        c.msl = 52996;
        c.undulation = -1234;
        c.velEnu = {100, -200, 3};
        c.tail[13] = 7;
        Hi83 d;
        d.bitmap = Hi83::kSupportedMask;
        d.accB = {1, 2, 9.8f};
        d.systemTimeUs = 123456789012345ull;
        d.utc = {24, 2, 29, 23, 59, 0xE8, 0xEE, 0};
        d.insLonLatMsl = {116.1, 39.9, 50.5};
        d.gnssLonLatMsl = {116.2, 39.8, 51.5};
        d.gnssVel = {1, 2, 3};
        d.nodeInfo = {8, 0, 0, 0};
        const std::vector<Packet> all = {a, b, c, d};
        for (const auto &p : all) {
            const auto bytes = encode(p);
            const auto res = decodePayload(bytes);
            QVERIFY2(res.ok(), payloadErrorText(res.error));
            QCOMPARE(res.packets.size(), size_t(1));
            QVERIFY(res.packets[0] == p);
            QCOMPARE(encode(res.packets[0]), bytes);
        }
        QCOMPARE(encode(Packet(a)).size(), Hi91::kSize);
        QCOMPARE(encode(Packet(b)).size(), Hi92::kSize);
        QCOMPARE(encode(Packet(c)).size(), Hi81::kSize);
        QCOMPARE(encode(Packet(d)).size(), size_t(236)); // every supported bit
    }

    void severalTagsInOneFrame()
    {
        Hi91 a;
        a.systemTime = 5;
        Hi81 b;
        b.gpsTowMs = 6;
        Hi83 c;
        c.bitmap = 0x1F;
        const auto bytes = encode(std::vector<Packet>{a, b, c});
        const auto res = decodePayload(bytes);
        QVERIFY(res.ok());
        QCOMPARE(res.packets.size(), size_t(3));
        QCOMPARE(packetName(res.packets[0]), std::string("HI91"));
        QCOMPARE(packetName(res.packets[1]), std::string("HI81"));
        QCOMPARE(packetName(res.packets[2]), std::string("HI83"));
    }

    void hi83Sizes_data()
    {
        QTest::addColumn<quint32>("bitmap");
        QTest::addColumn<int>("size");
        QTest::newRow("default 0xFF") << 0xFFu << 92;
        QTest::newRow("imu 0x1F") << 0x1Fu << 72;
        QTest::newRow("all supported") << 0xC00FFFFFu << 236;
        QTest::newRow("empty") << 0u << 8;
    }
    void hi83Sizes()
    {
        QFETCH(quint32, bitmap);
        QFETCH(int, size);
        QCOMPARE(Hi83::payloadSize(bitmap).value(), size_t(size));
        Hi83 h;
        h.bitmap = bitmap;
        QCOMPARE(encode(h).size(), size_t(size));
    }

    void hi83UnknownBitIsRefused()
    {
        // Bit 25 (internal diagnostics) has no documented size: reported, never guessed.
        std::vector<uint8_t> p = {0x83, 0, 0, 0, 0x01, 0, 0, 0x02};
        p.resize(8 + 12 + 64, 0);
        const auto res = decodePayload(p);
        QCOMPARE(res.error, PayloadError::UnsupportedBits);
        QVERIFY(res.packets.empty());
        QVERIFY(!Hi83::payloadSize(1u << 20));
    }

    void hi83LengthMismatch()
    {
        Hi83 h;
        h.bitmap = 0xFF;
        auto bytes = encode(h);
        bytes.pop_back();
        QCOMPARE(decodePayload(bytes).error, PayloadError::Truncated);
        bytes.push_back(0);
        bytes.push_back(0);
        QCOMPARE(decodePayload(bytes).error, PayloadError::SizeMismatch);
    }

    void hi83LegacyTimestamp()
    {
        Hi83 h;
        h.bitmap = 0x20;
        h.legacyTime32 = true;
        h.systemTimeUs = 5000000; // 5000 ms
        const auto bytes = encode(h);
        QCOMPARE(bytes.size(), size_t(12));
        const auto res = decodePayload(bytes);
        QVERIFY(res.ok());
        const auto &d = std::get<Hi83>(res.packets[0]);
        QVERIFY(d.legacyTime32);
        QCOMPARE(d.systemTimeUs, uint64_t(5000000));
    }

    void hi83UnitsToSample()
    {
        Hi83 h;
        h.bitmap = 0x1B; // acc, gyr, rpy, quat
        h.accB = {0, 0, 9.8f};
        h.gyrB = {0, 0, 1.0f};
        h.rpy = {1, 2, 3};
        const auto s = toSample(h);
        QVERIFY(qAbs(s.acc.z - 1.0) < 1e-6);           // m/s^2 -> G
        QVERIFY(qAbs(s.gyr.z - 57.29577951) < 1e-5);    // rad/s -> deg/s
        QVERIFY(s.has(imudesk::model::FieldEuler));
        QVERIFY(!s.has(imudesk::model::FieldMag));
    }

    void hi92Scales()
    {
        Hi92 h;
        h.pressure = 2000; // 102000 Pa
        h.acc = {0, 0, 2007};
        h.gyr = {1000, 0, 0};
        h.yaw = -90000;
        const auto s = toSample(h);
        QCOMPARE(s.pressurePa, 102000.0);
        QVERIFY(qAbs(s.acc.z - 2007 * 0.0048828 / 9.8) < 1e-9);
        QVERIFY(qAbs(s.gyr.x - 57.29577951) < 1e-5);
        QCOMPARE(s.yaw, -90.0);
    }

    void badPayloads()
    {
        std::vector<uint8_t> unknown = {0x90, 1, 2, 3};
        QCOMPARE(decodePayload(unknown).error, PayloadError::UnknownTag);
        Hi91 h;
        auto trunc = encode(h);
        trunc.resize(50);
        QCOMPARE(decodePayload(trunc).error, PayloadError::Truncated);
        QCOMPARE(decodePayload(nullptr, 0).error, PayloadError::Empty);
        Hi91 out;
        QVERIFY(!decodeHi91(trunc.data(), trunc.size(), out));
    }
};

QTEST_GUILESS_MAIN(TstPayloads)
#include "tst_hipnuc_payloads.moc"
