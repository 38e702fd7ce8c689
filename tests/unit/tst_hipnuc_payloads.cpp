// Payload codecs: the manual's HI91 example, round trips of every payload, HI83 bitmaps.
#include "../common/golden.h"
#include "../common/test_main.h"
#include "model/main_status.h"
#include "protocol/hipnuc/payloads.h"

#include <QTest>

#include <cstring>

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
        d.eventCounter = {1000, 500, 10, 10, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0xFFFFFFFFu};
        d.kfAccBias = {0.01f, -0.02f, 0.03f};
        d.kfGyrBias = {1e-4f, -2e-4f, 3e-4f};
        d.gnssStd = {1.5f, 0.05f, 0};
        d.gnssHeadingInfo = {1.2f, 0.5f, 123.4f};
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
        QCOMPARE(encode(Packet(d)).size(), size_t(348)); // every bit the manual sizes
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
        QTest::newRow("the SDK's bits") << 0xC00FFFFFu << 236;
        QTest::newRow("bits 25-29: 64 + 4 x 12") << 0x3E000000u << 8 + 64 + 48;
        QTest::newRow("all the manual sizes") << 0xFE0FFFFFu << 348;
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
        // Bits 20-24 are reserved in the v1.7.1 manual (5.9.12), without a size: reported, never guessed.
        std::vector<uint8_t> p = {0x83, 0, 0, 0, 0x01, 0, 0x10, 0};
        p.resize(8 + 12 + 64, 0);
        const auto res = decodePayload(p);
        QCOMPARE(res.error, PayloadError::UnsupportedBits);
        QVERIFY(res.packets.empty());
        for (int bit = 20; bit <= 24; ++bit)
            QVERIFY(!Hi83::payloadSize(1u << bit));
    }

    void hi83Bits25To29InManualOrder()
    {
        // Built by hand in the manual's order (5.9.11: fields follow the bitmap from the lowest
        // bit up): event_counter (16 x u32), gnss_std (3 x f32), then gnss_lon_lat_msl (3 x f64).
        std::vector<uint8_t> p = {0x83, 0x08, 0x00, 0x03};
        auto u32 = [&p](uint32_t v) {
            for (int i = 0; i < 4; ++i)
                p.push_back(uint8_t(v >> (8 * i)));
        };
        auto f32 = [&u32](float f) {
            uint32_t v;
            std::memcpy(&v, &f, 4);
            u32(v);
        };
        auto f64 = [&u32](double d) {
            uint64_t v;
            std::memcpy(&v, &d, 8);
            u32(uint32_t(v));
            u32(uint32_t(v >> 32));
        };
        u32((1u << 25) | (1u << 28) | (1u << 30));
        for (uint32_t i = 0; i < 16; ++i)
            u32(100 + i);
        f32(1.5f);
        f32(0.05f);
        f32(0);
        f64(121.5);
        f64(31.25);
        f64(40.0);
        QCOMPARE(p.size(), size_t(8 + 64 + 12 + 24));
        const auto res = decodePayload(p);
        QVERIFY2(res.ok(), payloadErrorText(res.error));
        const Hi83 &h = std::get<Hi83>(res.packets.at(0));
        QCOMPARE(h.mainStatus, uint16_t(0x0008));
        QCOMPARE(h.insStatus, uint8_t(3));
        QCOMPARE(h.eventCounter[0], 100u);
        QCOMPARE(h.eventCounter[15], 115u);
        QCOMPARE(h.gnssStd[0], 1.5f);
        QCOMPARE(h.gnssStd[1], 0.05f);
        QCOMPARE(h.gnssLonLatMsl[0], 121.5);
        QCOMPARE(h.gnssLonLatMsl[1], 31.25);
        QCOMPARE(h.gnssLonLatMsl[2], 40.0);

        // As a sample: the fields the values table shows.
        const imudesk::model::Sample s = toSample(res.packets[0]);
        QVERIFY(s.has(imudesk::model::FieldHi83Extra));
        QVERIFY(s.hi83);
        QCOMPARE(s.hi83->bits, (1u << 25) | (1u << 28) | (1u << 30));
        QCOMPARE(s.hi83->eventCounter[2], 102u);
        QCOMPARE(s.hi83->gnssStd[0], 1.5f);
        QCOMPARE(s.hi83->gnssLonLatMsl[1], 31.25);
        // No UTC, no fix: FieldGnss stays off.
        QVERIFY(!s.has(imudesk::model::FieldGnss));
    }

    void hi83UtcAndFixAsSample()
    {
        Hi83 h;
        h.bitmap = (1u << 6) | (1u << 15);
        h.utc = {26, 11, 26, 23, 59, 0x6C, 0xE8, 0}; // 59.500 s: 0xE86C ms
        h.gnssQualityNv = {4, 21, 5, 17};
        imudesk::model::Sample s = toSample(Packet(h));
        QVERIFY(s.has(imudesk::model::FieldGnss));
        QCOMPARE(s.gnssQuality, 4);
        QCOMPARE(s.gnssSatellites, 21);
        QCOMPARE(s.utcTimeOfDayS, 23 * 3600.0 + 59 * 60.0 + 59.5);
        QVERIFY(s.hi83);
        QCOMPARE(s.hi83->utcDate, (std::array<uint16_t, 3>{2026, 11, 26}));
        QCOMPARE(int(s.hi83->solqHeading), 5);
        QCOMPARE(int(s.hi83->nvHeading), 17);
        // A zero date: GNSS time not known yet (the manual), so no UTC.
        h.utc = {0, 0, 0, 0, 0, 0, 0, 0};
        s = toSample(Packet(h));
        QCOMPARE(s.utcTimeOfDayS, -1.0);
        QVERIFY(!s.hi83->has(6));
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

IMUDESK_TEST_GUILESS_MAIN(TstPayloads)
#include "tst_hipnuc_payloads.moc"
