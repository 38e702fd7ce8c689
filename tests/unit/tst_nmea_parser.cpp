// NMEA GGA/RMC/SXT with checksum: the manual's RMC example, a GGA, HiPNUC's SXT, error
// cases, and each sentence as a sample (protocol/nmea/nmea_sample.h).
#include "../common/golden.h"
#include "../common/test_main.h"
#include "protocol/nmea/nmea_parser.h"
#include "protocol/nmea/nmea_sample.h"

#include <QTest>

#include <cmath>

using namespace imudesk::protocol::nmea;

class TstNmea : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void manualRmc()
    {
        const auto r = parseSentence(golden::kRmc);
        QVERIFY(r.ok());
        const auto &s = *r.sentence;
        QCOMPARE(s.talker, std::string("GP"));
        QCOMPARE(s.type, std::string("RMC"));
        QVERIFY(s.rmc);
        const auto &rmc = *s.rmc;
        QVERIFY(rmc.valid);
        QCOMPARE(rmc.time->hour, 23);
        QCOMPARE(rmc.time->minute, 59);
        QCOMPARE(rmc.time->second, 52.0);
        QCOMPARE(rmc.date->day, 14);
        QCOMPARE(rmc.date->month, 11);
        QCOMPARE(rmc.date->year, 2025);
        QVERIFY(qAbs(*rmc.latitudeDeg - (31 + 12.5 / 60)) < 1e-9);
        QVERIFY(qAbs(*rmc.longitudeDeg - (121 + 27.5 / 60)) < 1e-9);
        QCOMPARE(*rmc.speedKnots, 0.0);
        QCOMPARE(*rmc.magVarDeg, 0.0);
        QCOMPARE(rmc.mode, 'A');
    }

    void wrongChecksumRejected()
    {
        std::string bad = golden::kRmc;
        bad.back() = 'C'; // *3C
        QCOMPARE(parseSentence(bad).error, NmeaError::ChecksumMismatch);
        std::string alt = golden::kRmc;
        alt[10] = '3'; // change the time, keep the checksum
        QCOMPARE(parseSentence(alt).error, NmeaError::ChecksumMismatch);
    }

    void errors_data()
    {
        QTest::addColumn<QString>("line");
        QTest::addColumn<int>("error");
        QTest::newRow("no dollar") << "GPRMC,1*00" << int(NmeaError::NoDollar);
        QTest::newRow("no star") << "$GPRMC,1,2" << int(NmeaError::NoChecksum);
        QTest::newRow("one digit") << "$GPRMC,1*3" << int(NmeaError::BadChecksumDigits);
        QTest::newRow("not hex") << "$GPRMC,1*3G" << int(NmeaError::BadChecksumDigits);
        QTest::newRow("too long") << QString("$GPGGA,") + QString(200, '1') + "*00" << int(NmeaError::TooLong);
        QTest::newRow("control char") << QStringLiteral("$GPRMC,\x01*00") << int(NmeaError::NonPrintable);
    }
    void errors()
    {
        QFETCH(QString, line);
        QFETCH(int, error);
        QCOMPARE(int(parseSentence(line.toStdString()).error), error);
    }

    void ggaSouthWest()
    {
        const std::string s = buildSentence("GNGGA,123519.50,4807.038,S,01131.000,W,4,12,0.9,545.4,M,46.9,M,1.2,0001");
        QVERIFY(s.size() > 4 && s.substr(s.size() - 2) == "\r\n");
        const auto r = parseSentence(s);
        QVERIFY(r.ok());
        const auto &g = *r.sentence->gga;
        QCOMPARE(r.sentence->talker, std::string("GN"));
        QVERIFY(qAbs(*g.latitudeDeg + (48 + 7.038 / 60)) < 1e-9);
        QVERIFY(qAbs(*g.longitudeDeg + (11 + 31.0 / 60)) < 1e-9);
        QCOMPARE(g.quality, 4);
        QCOMPARE(g.satellites, 12);
        QCOMPARE(*g.hdop, 0.9);
        QCOMPARE(*g.altitudeM, 545.4);
        QCOMPARE(*g.geoidSeparationM, 46.9);
        QCOMPARE(*g.diffAgeS, 1.2);
        QCOMPARE(g.stationId, std::string("0001"));
    }

    void emptyFieldsAreAbsent()
    {
        const auto r = parseSentence(buildSentence("GPGGA,,,,,,0,00,,,M,,M,,"));
        QVERIFY(r.ok());
        QVERIFY(!r.sentence->gga->time);
        QVERIFY(!r.sentence->gga->latitudeDeg);
        QCOMPARE(r.sentence->gga->quality, 0);
    }

    void malformedFields()
    {
        QCOMPARE(parseSentence(buildSentence("GPRMC,99xx00,A,3112.5,N,12127.5,E,0,0,141125,,,A")).error,
                 NmeaError::BadField);
        QCOMPARE(parseSentence(buildSentence("GPRMC,235952,A,3112.5,Q,12127.5,E,0,0,141125,,,A")).error,
                 NmeaError::BadField);
        QCOMPARE(parseSentence(buildSentence("GPRMC,235952,A,3112.5,N,12127.5,E,0,0,321325,,,A")).error,
                 NmeaError::BadField);
        // Out-of-range coordinates and a sign that contradicts the hemisphere letter.
        QCOMPARE(parseSentence(buildSentence("GPGGA,010101,9059.9999,N,12127.5,E,1,08,1.0,10,M,0,M,,")).error,
                 NmeaError::BadField);
        QCOMPARE(parseSentence(buildSentence("GPGGA,010101,3112.5,N,18059.9999,E,1,08,1.0,10,M,0,M,,")).error,
                 NmeaError::BadField);
        QCOMPARE(parseSentence(buildSentence("GPGGA,010101,-100.0,N,12127.5,E,1,08,1.0,10,M,0,M,,")).error,
                 NmeaError::BadField);
        QVERIFY(parseSentence(buildSentence("GPGGA,010101,9000.0000,S,18000.0000,W,1,08,1.0,10,M,0,M,,")).ok());
    }

    // SXT's 21 fields in the vendor SDK's order (the layout the simulator sends).
    void sxt()
    {
        const auto r = parseSentence(buildSentence(
            "GPSXT,20261126081233.40,121.458333,-31.208333,40.5,35.25,-2.50,90.0,1.5,1.25,4,0,12,0,0.1,0.2,0.3,1.0,2.0,-0.5,3,1"));
        QVERIFY2(r.ok(), errorText(r.error));
        QVERIFY(r.sentence->sxt);
        const Sxt &x = *r.sentence->sxt;
        QCOMPARE(x.date->year, 2026);
        QCOMPARE(x.date->month, 11);
        QCOMPARE(x.date->day, 26);
        QCOMPARE(x.time->hour, 8);
        QCOMPARE(x.time->minute, 12);
        QCOMPARE(x.time->second, 33.4);
        QCOMPARE(*x.longitudeDeg, 121.458333);
        QCOMPARE(*x.latitudeDeg, -31.208333);
        QCOMPARE(*x.altitudeM, 40.5);
        QCOMPARE(*x.headingDeg, 35.25);
        QCOMPARE(*x.pitchDeg, -2.5);
        QCOMPARE(*x.trackDeg, 90.0);
        QCOMPARE(*x.speedMs, 1.5);
        QCOMPARE(*x.rollDeg, 1.25);
        QCOMPARE(x.quality, 4);
        QCOMPARE(x.satellites, 12);
        QCOMPARE(*x.gyrDps[2], 0.3);
        QCOMPARE(*x.velEnuMs[0], 1.0);
        QCOMPARE(*x.velEnuMs[2], -0.5);
        QCOMPARE(x.insStatus, 3);
        QCOMPARE(x.antennaStatus, 1);
        // As a sample: position, attitude, velocity, fix and time.
        const auto s = toSample(*r.sentence);
        QVERIFY(s);
        QCOMPARE(s->source, std::string("SXT"));
        QVERIFY(s->has(imudesk::model::FieldPosition) && s->has(imudesk::model::FieldEuler)
                && s->has(imudesk::model::FieldVelocity) && s->has(imudesk::model::FieldGnss));
        QCOMPARE(s->latitudeDeg, -31.208333);
        QCOMPARE(s->headingDeg, 35.25); // clockwise from true north
        QVERIFY(s->headingTrue);
        QCOMPARE(s->yaw, -35.25); // the world frame's yaw, ENU (issue 53 point 7)
        QCOMPARE(s->velEnu.y, 2.0);
        QCOMPARE(s->gnssQuality, 4);
        QCOMPARE(s->utcTimeOfDayS, 8 * 3600 + 12 * 60 + 33.4);
        // A latitude beyond 90 degrees is damage, not a position.
        QCOMPARE(parseSentence(buildSentence("GPSXT,20261126081233.40,121.4,95.0,40,0,0,0,0,0,1,0,8,0,0,0,0,0,0,0,0,0")).error,
                 NmeaError::BadField);
    }

    void sentencesAsSamples()
    {
        using namespace imudesk::model;
        // The manual's RMC: valid, position and time, no altitude (NaN), at rest.
        auto s = sampleOf(golden::kRmc);
        QVERIFY(s && s->has(FieldPosition) && s->has(FieldGnss) && s->has(FieldVelocity));
        QVERIFY(std::isnan(s->altitudeM));
        QCOMPARE(s->utcTimeOfDayS, 23 * 3600 + 59 * 60 + 52.0);
        // RMC moving east at 10 knots: velocity east 5.14 m/s.
        s = sampleOf(buildSentence("GPRMC,010203,A,3112.5,N,12127.5,E,10.0,90.0,141125,,,A"));
        QVERIFY(std::abs(s->velEnu.x - 5.14444) < 1e-4 && std::abs(s->velEnu.y) < 1e-9);
        // RMC with status V: time only.
        s = sampleOf(buildSentence("GPRMC,010203,V,,,,,,,141125,,,N"));
        QVERIFY(s && !s->has(FieldPosition) && s->has(FieldGnss));
        // GGA: fix quality, satellites, position with altitude.
        s = sampleOf(buildSentence("GNGGA,010203.50,3112.5000,N,12127.5000,E,4,17,0.6,40.25,M,0,M,1.0,0001"));
        QVERIFY(s && s->has(FieldPosition));
        QCOMPARE(s->gnssQuality, 4);
        QCOMPARE(s->gnssSatellites, 17);
        QCOMPARE(s->altitudeM, 40.25);
        // GGA without a fix: quality and satellites, no position.
        s = sampleOf(buildSentence("GPGGA,010203,,,,,0,00,,,M,,M,,"));
        QVERIFY(s && !s->has(FieldPosition));
        QCOMPARE(s->gnssQuality, 0);
        // Sentences that carry nothing a sample holds, and damaged ones, give none.
        QVERIFY(!sampleOf(buildSentence("GPVTG,054.7,T,034.4,M,005.5,N,010.2,K")));
        QVERIFY(!sampleOf("$GPGGA,1*00"));
        // An RMC after a GGA keeps the GGA's altitude.
        Sample merged;
        mergeFields(merged, *sampleOf(buildSentence("GNGGA,010203,3112.5,N,12127.5,E,1,08,1.0,12.5,M,0,M,,")));
        mergeFields(merged, *sampleOf(golden::kRmc));
        QCOMPARE(merged.altitudeM, 12.5);
        QCOMPARE(merged.gnssQuality, 1); // the RMC has no fix quality: the GGA's stays
        QCOMPARE(merged.gnssSatellites, 8);
        QCOMPARE(merged.utcTimeOfDayS, 23 * 3600 + 59 * 60 + 52.0); // the RMC's time is newer
        QCOMPARE(merged.source, std::string("RMC"));
    }

    void headingSentences()
    {
        using namespace imudesk::model;
        // What an HEC495 sends with output content NMEA 0183 (manual 2.x, command 0x49 = 03).
        auto r = parseSentence(buildSentence("HCHDT,123.4,T"));
        QVERIFY(r.ok());
        QCOMPARE(r.sentence->talker, std::string("HC"));
        QVERIFY(r.sentence->heading);
        QCOMPARE(r.sentence->heading->headingDeg, 123.4);
        QVERIFY(r.sentence->heading->trueNorth);
        auto s = sampleOf(buildSentence("HCHDT,359.9,T"));
        QVERIFY(s && s->has(FieldHeading) && !s->has(FieldEuler));
        QCOMPARE(s->headingDeg, 359.9);
        QVERIFY(s->headingTrue);
        s = sampleOf(buildSentence("HCHDM,10.0,M"));
        QVERIFY(s && s->has(FieldHeading));
        QVERIFY(!s->headingTrue);
        // No heading yet: a valid sentence without a sample. A wrong reference letter or an
        // angle beyond 360 is damage.
        QVERIFY(parseSentence(buildSentence("HCHDT,,T")).ok());
        QVERIFY(!sampleOf(buildSentence("HCHDT,,T")));
        QCOMPARE(parseSentence(buildSentence("HCHDT,12.0,M")).error, NmeaError::BadField);
        QCOMPARE(parseSentence(buildSentence("HCHDT,361.0,T")).error, NmeaError::BadField);
        // The heading stays beside the Euler angles when merged.
        Sample merged;
        Sample euler;
        euler.fields = FieldEuler;
        euler.roll = 1;
        euler.yaw = -64;
        mergeFields(merged, euler);
        mergeFields(merged, *sampleOf(buildSentence("HCHDT,296.0,T")));
        QCOMPARE(merged.roll, 1.0);
        QCOMPARE(merged.yaw, -64.0);
        QCOMPARE(merged.headingDeg, 296.0);
    }

    void otherSentencesKeepFields()
    {
        const auto r = parseSentence(buildSentence("GPVTG,054.7,T,034.4,M,005.5,N,010.2,K"));
        QVERIFY(r.ok());
        QCOMPARE(r.sentence->type, std::string("VTG"));
        QCOMPARE(r.sentence->fields.size(), size_t(8));
        QVERIFY(!r.sentence->gga && !r.sentence->rmc);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstNmea)
#include "tst_nmea_parser.moc"
