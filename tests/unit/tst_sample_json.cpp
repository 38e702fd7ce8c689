// JSON Lines output of decoded samples and the decode summary.
#include "../common/golden.h"
#include "../common/test_main.h"
#include "format/sample_json.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>
#include <QTest>

#include <clocale>

using namespace imudesk;
using namespace imudesk::protocol::hipnuc;

class TstSampleJson : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void hi91Keys()
    {
        const auto f = golden::bytes(golden::hi91Frame());
        Hi91 h;
        QVERIFY(decodeHi91(f.data() + 6, 76, h));
        const std::string text = format::sampleToJson(toSample(h));
        QJsonParseError err;
        const auto doc = QJsonDocument::fromJson(QByteArray::fromStdString(text), &err);
        QCOMPARE(err.error, QJsonParseError::NoError);
        const auto o = doc.object();
        const QStringList keys = o.keys();
        for (const char *k : {"type", "main_status", "temperature", "pressure", "system_time", "acc", "gyr", "mag",
                              "roll", "pitch", "yaw", "quat"})
            QVERIFY2(keys.contains(QLatin1String(k)), k);
        QCOMPARE(o.value("type").toString(), QStringLiteral("HI91"));
        QCOMPARE(o.value("main_status").toInt(), 0x1508);
        QCOMPARE(o.value("temperature").toInt(), 35);
        QCOMPARE(o.value("system_time").toInteger(), 1840392);
        QVERIFY(qAbs(o.value("yaw").toDouble() + 122.477) < 1e-3);
        QCOMPARE(o.value("acc").toArray().size(), 3);
        QCOMPARE(o.value("quat").toArray().size(), 4);
        QVERIFY(qAbs(o.value("quat").toArray().at(3).toDouble() - 0.860223) < 1e-6);
        // Floats survive the text exactly.
        QCOMPARE(float(o.value("mag").toArray().at(2).toDouble()), h.mag[2]);
    }

    void hi83DetailsGnssAndHeadingKeys()
    {
        // An HI83 with UTC, the GNSS fix and bits 25, 28 and 30: the manual's names, valid JSON.
        Hi83 h;
        h.bitmap = (1u << 6) | (1u << 15) | (1u << 25) | (1u << 28) | (1u << 30);
        h.utc = {26, 11, 26, 8, 0, 0x10, 0x27, 0}; // 08:00:10.000
        h.gnssQualityNv = {4, 20, 5, 18};
        h.eventCounter[0] = 1200;
        h.gnssStd = {1.5f, 0.05f, 0};
        h.gnssLonLatMsl = {121.5, 31.25, 40.0};
        QJsonParseError err;
        const auto o = QJsonDocument::fromJson(QByteArray::fromStdString(format::sampleToJson(toSample(Packet(h)))), &err)
                           .object();
        QCOMPARE(err.error, QJsonParseError::NoError);
        QCOMPARE(o.value("utc_date").toString(), QStringLiteral("2026-11-26"));
        QCOMPARE(o.value("utc_time_s").toDouble(), 8 * 3600 + 10.0);
        QCOMPARE(o.value("gnss_quality").toInt(), 4);
        QCOMPARE(o.value("satellites").toInt(), 20);
        QCOMPARE(o.value("solq_heading").toInt(), 5);
        QCOMPARE(o.value("event_counter").toArray().size(), 16);
        QCOMPARE(o.value("event_counter").toArray().at(0).toInt(), 1200);
        QCOMPARE(o.value("gnss_std").toArray().at(0).toDouble(), 1.5);
        QCOMPARE(o.value("gnss_lon_lat_msl").toArray().at(1).toDouble(), 31.25);
        QVERIFY(!o.contains("kf_acc_bias")); // not in the bitmap
        // A compass's NMEA heading.
        imudesk::model::Sample hdt;
        hdt.source = "HDT";
        hdt.fields = imudesk::model::FieldHeading;
        hdt.headingDeg = 296.5;
        const auto p = QJsonDocument::fromJson(QByteArray::fromStdString(format::sampleToJson(hdt))).object();
        QCOMPARE(p.value("heading_true").toDouble(), 296.5);
    }

    void localeIndependent()
    {
        // A decimal comma locale must not leak into the JSON.
        const char *old = std::setlocale(LC_NUMERIC, nullptr);
        const std::string saved = old ? old : "C";
        if (!std::setlocale(LC_NUMERIC, "de_DE.UTF-8"))
            QSKIP("de_DE locale not installed");
        const std::string text = format::number(1.5);
        std::setlocale(LC_NUMERIC, saved.c_str());
        QCOMPARE(text, std::string("1.5"));
    }

    void nonFiniteIsNull()
    {
        QCOMPARE(format::number(std::numeric_limits<double>::quiet_NaN()), std::string("null"));
    }

    void summary()
    {
        FrameDecoder d;
        const auto s = golden::bytes(golden::hi91Frame() + QByteArray(1, '\0') + golden::hi91Frame());
        d.feed(s.data(), s.size());
        const auto text = format::summaryToJson(d.counters(), 0, 0, 0.5);
        const auto o = QJsonDocument::fromJson(QByteArray::fromStdString(text)).object().value("summary").toObject();
        QCOMPARE(o.value("frames").toObject().value("HI91").toInt(), 2);
        QCOMPARE(o.value("bytes").toInt(), 165);
        QCOMPARE(o.value("bytes_skipped").toInt(), 1);
        QCOMPARE(o.value("crc_errors").toInt(), 0);
        QCOMPARE(o.value("length_errors").toInt(), 0);
        QCOMPARE(o.value("seconds").toDouble(), 0.5);
        QVERIFY(o.contains("mb_per_s"));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstSampleJson)
#include "tst_sample_json.moc"
