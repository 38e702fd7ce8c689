// NMEA GGA/RMC with checksum: the manual's RMC example, a GGA, error cases.
#include "../common/golden.h"
#include "protocol/nmea/nmea_parser.h"

#include <QTest>

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

    void otherSentencesKeepFields()
    {
        const auto r = parseSentence(buildSentence("GPVTG,054.7,T,034.4,M,005.5,N,010.2,K"));
        QVERIFY(r.ok());
        QCOMPARE(r.sentence->type, std::string("VTG"));
        QCOMPARE(r.sentence->fields.size(), size_t(8));
        QVERIFY(!r.sentence->gga && !r.sentence->rmc);
    }
};

QTEST_GUILESS_MAIN(TstNmea)
#include "tst_nmea_parser.moc"
