// Export of a capture (vendor CSV, tidy CSV, JSON Lines; time range; progress and cancel)
// and import of the vendor's HI91 CSV: an export re-imports to the same values, and a
// malformed line is reported with its line number.
#include "../common/synthetic_capture.h"
#include "../common/test_main.h"
#include "format/sample_json.h"
#include "capture/capture_decoder.h"
#include "record/capture_exporter.h"
#include "capture/capture_reader.h"
#include "record/capture_source.h"
#include "decode/hipnuc_vendor_csv.h"
#include "decode/hipnuc_vendor_csv_reader.h"

#include <QBuffer>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

using namespace imudesk;
using record::CaptureExporter;
using decode::VendorCsvImporter;

namespace {

struct Decoded {
    std::vector<model::Sample> samples;
    std::vector<std::string> nmea;
};

// What the live decoder path makes of a capture.
Decoded decodeCapture(const QString &path)
{
    struct Sink : capture::CaptureDecoder::Sink {
        Decoded d;
        void onSample(const model::Sample &s, const decode::Record &) override { d.samples.push_back(s); }
        void onText(decode::TextKind kind, const std::string &s, int64_t) override
        {
            if (kind != decode::TextKind::Line)
                d.nmea.push_back(s);
        }
    } sink;
    capture::CaptureReader r;
    QString error;
    r.open(path, &error);
    capture::CaptureDecoder decoder;
    decoder.configure(r.header());
    capture::CaptureReader::Chunk c;
    while (r.next(c) == capture::CaptureReader::Result::Chunk)
        decoder.feedChunk(c, sink);
    decoder.finish(sink);
    return sink.d;
}

QStringList lines(const QString &path)
{
    QFile f(path);
    f.open(QIODevice::ReadOnly);
    QStringList out = QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'));
    if (!out.isEmpty() && out.last().isEmpty())
        out.removeLast();
    return out;
}

} // namespace

class TstCaptureExport : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_capture;
    Decoded m_decoded;

private Q_SLOTS:
    void initTestCase()
    {
        m_capture = m_dir.filePath(QStringLiteral("mixed.imucap"));
        synthetic::CaptureSpec spec;
        spec.frames = 3000; // 3 s at 1 kHz
        spec.mixed = true;
        QVERIFY(synthetic::writeCapture(m_capture, spec) > 0);
        m_decoded = decodeCapture(m_capture);
        QCOMPARE(m_decoded.samples.size(), size_t(3000 + 2 * 300));
        QCOMPARE(m_decoded.nmea.size(), size_t(30));
    }

    // The HEC495's own quantities in the tidy CSV (issue 53, 13): its heading, its relative
    // field (no unit) and its magnetic roll, named columns at the end; empty for a module.
    void tidyCsvCarriesTheCompassQuantities()
    {
        const QStringList head = QString::fromLatin1(record::CaptureExporter::tidyHeader()).split(QLatin1Char(','));
        QCOMPARE(head.mid(head.size() - 5), (QStringList{QStringLiteral("heading_deg"), QStringLiteral("mag_rel_x"),
                                                          QStringLiteral("mag_rel_y"), QStringLiteral("mag_rel_z"),
                                                          QStringLiteral("mag_roll_deg")}));
        model::Sample s;
        s.fields = model::FieldHeading | model::FieldMagRelative | model::FieldMagRoll;
        s.headingDeg = 296.4;
        s.magRelative = {0.5, -0.25, 0.75};
        s.magRollDeg = 12.5;
        std::string row;
        record::CaptureExporter::appendTidyRow(row, s, 0, 0);
        QStringList cells = QString::fromStdString(row).trimmed().split(QLatin1Char(','));
        QCOMPARE(cells.size(), head.size());
        QCOMPARE(cells.mid(cells.size() - 5), (QStringList{QStringLiteral("296.4"), QStringLiteral("0.5"),
                                                            QStringLiteral("-0.25"), QStringLiteral("0.75"),
                                                            QStringLiteral("12.5")}));
        s.fields = model::FieldAcc; // a module: the compass's columns empty
        row.clear();
        record::CaptureExporter::appendTidyRow(row, s, 0, 0);
        cells = QString::fromStdString(row).split(QLatin1Char(','));
        QCOMPARE(cells.size(), head.size());
        for (const QString &c : cells.mid(cells.size() - 5))
            QVERIFY(c.trimmed().isEmpty());
    }

    void vendorCsvLayout()
    {
        CaptureExporter::Options o;
        o.format = CaptureExporter::Format::VendorCsv;
        o.output = m_dir.filePath(QStringLiteral("vendor.csv"));
        const auto r = CaptureExporter::run(m_capture, o);
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.files.size(), 4);
        const QStringList hi91 = lines(m_dir.filePath(QStringLiteral("vendor_HI91.csv")));
        // The header, exactly.
        QCOMPARE(hi91.front(), QStringLiteral("HI91,pc_counter,sys_time,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,mag_x,mag_y,"
                                              "mag_z,roll,pitch,yaw,pps_sync_stamp,incli_x,incli_y,quat_w,quat_x,quat_y,"
                                              "quat_z,temperature,pressure,acc_norm,gyr_norm,mag_norm"));
        QCOMPARE(hi91.size(), 3001);
        QVERIFY(hi91.at(1).startsWith(QStringLiteral("HI91,")));
        QCOMPARE(hi91.at(1).split(QLatin1Char(',')).size(), 27);
        const QStringList hi81 = lines(m_dir.filePath(QStringLiteral("vendor_HI81.csv")));
        QCOMPARE(hi81.size(), 301);
        QCOMPARE(hi81.at(1).split(QLatin1Char(',')).size(), hi81.at(0).split(QLatin1Char(',')).size());
        QVERIFY(hi81.at(0).contains(QStringLiteral(",lat,")));
        const QStringList hi83 = lines(m_dir.filePath(QStringLiteral("vendor_HI83.csv")));
        QCOMPARE(hi83.size(), 301);
        const QStringList h83 = hi83.at(0).split(QLatin1Char(','));
        const QStringList row83 = hi83.at(1).split(QLatin1Char(','));
        QCOMPARE(row83.size(), h83.size());
        QCOMPARE(row83.at(h83.indexOf(QStringLiteral("incli_y"))), QStringLiteral("2"));
        QCOMPARE(row83.at(h83.indexOf(QStringLiteral("heave"))), QString()); // not in the bitmap
        QCOMPARE(row83.at(h83.indexOf(QStringLiteral("data_bitmap"))), QStringLiteral("0x000002FF"));
        const QStringList nmea = lines(m_dir.filePath(QStringLiteral("vendor_NMEA.txt")));
        QCOMPARE(nmea.size(), 30);
        QCOMPARE(nmea.front(), QString::fromLatin1(golden_rmc()));
    }

    // Written where it is told (issue 37): one frame type goes to the file named; several to a
    // file each, which the result names and a note explains.
    void vendorCsvWritesWhereItIsTold()
    {
        const QString single = m_dir.filePath(QStringLiteral("hi91_only.imucap"));
        synthetic::CaptureSpec spec;
        spec.frames = 500;
        QVERIFY(synthetic::writeCapture(single, spec) > 0);
        CaptureExporter::Options o;
        o.format = CaptureExporter::Format::VendorCsv;
        o.output = m_dir.filePath(QStringLiteral("one.csv"));
        auto r = CaptureExporter::run(single, o);
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.files, QStringList{o.output});
        QVERIFY(r.notes.isEmpty());
        QCOMPARE(lines(o.output).size(), 501);
        QVERIFY(!QFile::exists(m_dir.filePath(QStringLiteral("one_HI91.csv"))));
        o.output = m_dir.filePath(QStringLiteral("several.csv"));
        r = CaptureExporter::run(m_capture, o);
        QVERIFY2(r.ok, qPrintable(r.error));
        const QStringList want{m_dir.filePath(QStringLiteral("several_HI91.csv")), m_dir.filePath(QStringLiteral("several_HI81.csv")),
                               m_dir.filePath(QStringLiteral("several_HI83.csv")), m_dir.filePath(QStringLiteral("several_NMEA.txt"))};
        QCOMPARE(QSet<QString>(r.files.begin(), r.files.end()), QSet<QString>(want.begin(), want.end()));
        QVERIFY(!QFile::exists(o.output));
        QCOMPARE(lines(want[0]).size(), 3001); // the first type's rows, moved aside whole
        QCOMPARE(r.notes.size(), 1);
        QVERIFY2(r.notes.front().contains(QStringLiteral("4 frame types")) && r.notes.front().contains(want[1]),
                 qPrintable(r.notes.front()));
    }

    void vendorCsvReimportsToSameValues()
    {
        CaptureExporter::Options o;
        o.format = CaptureExporter::Format::VendorCsv;
        o.output = m_dir.filePath(QStringLiteral("rt.csv"));
        QVERIFY(CaptureExporter::run(m_capture, o).ok);
        std::vector<model::Sample> back;
        const auto r = VendorCsvImporter::read(m_dir.filePath(QStringLiteral("rt_HI91.csv")),
                                               [&](const model::Sample &s) { back.push_back(s); });
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.badLines, uint64_t(0));
        std::vector<model::Sample> want;
        for (const auto &s : m_decoded.samples)
            if (s.source == "HI91")
                want.push_back(s);
        QCOMPARE(back.size(), want.size());
        const int64_t firstNs = 5'000'000'000 + 8'000'000; // the first chunk's time
        for (size_t i = 0; i < want.size(); ++i) {
            const auto &a = want[i];
            const auto &b = back[i];
            QCOMPARE(b.fields, a.fields & ~uint32_t(model::FieldMainStatus)); // the layout has no status column
            QCOMPARE(b.deviceTimeMs, a.deviceTimeMs);
            QVERIFY(b.acc == a.acc && b.gyr == a.gyr && b.mag == a.mag);
            QVERIFY(b.roll == a.roll && b.pitch == a.pitch && b.yaw == a.yaw);
            QVERIFY(b.quat == a.quat);
            QCOMPARE(b.temperatureC, a.temperatureC);
            QCOMPARE(b.pressurePa, a.pressurePa);
            QVERIFY(std::abs(b.hostTimeNs - (a.hostTimeNs - firstNs)) <= 1);
        }
    }

    void vendorCsvConvertsToCapture()
    {
        // An old log becomes a capture that decodes to the same values (status aside).
        CaptureExporter::Options o;
        o.format = CaptureExporter::Format::VendorCsv;
        o.output = m_dir.filePath(QStringLiteral("old.csv"));
        QVERIFY(CaptureExporter::run(m_capture, o).ok);
        const QString converted = m_dir.filePath(QStringLiteral("old.imucap"));
        const auto r = record::CaptureSource::convert(m_dir.filePath(QStringLiteral("old_HI91.csv")), converted);
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.import.rows, uint64_t(3000));
        const Decoded back = decodeCapture(converted);
        std::vector<model::Sample> want;
        for (const auto &s : m_decoded.samples)
            if (s.source == "HI91")
                want.push_back(s);
        QCOMPARE(back.samples.size(), want.size());
        for (size_t i = 0; i < want.size(); ++i) {
            model::Sample a = want[i], b = back.samples[i];
            a.mainStatus = 0;
            // The converted capture's times are the CSV's (ms), not the original arrivals.
            a.hostTimeNs = a.commonTimeNs = b.hostTimeNs = b.commonTimeNs = 0;
            QCOMPARE(format::sampleToJson(b), format::sampleToJson(a));
        }
        // Not a vendor CSV: nothing is left behind.
        const auto bad = record::CaptureSource::convert(m_capture, m_dir.filePath(QStringLiteral("bad.imucap")));
        QVERIFY(!bad.ok);
        QVERIFY(!QFile::exists(m_dir.filePath(QStringLiteral("bad.imucap"))));
    }

    void idleMarkersDecideLikeTheSession_data()
    {
        QTest::addColumn<bool>("markersRecorded");
        QTest::addColumn<bool>("marker");  // a line-idle chunk between the two halves
        QTest::addColumn<int>("gapMs");    // between the two halves of one frame
        QTest::addColumn<int>("frames");
        QTest::newRow("marker: released, frame broken") << true << true << 31 << 0;
        QTest::newRow("no marker despite a pause: the session did not release") << true << false << 100 << 1;
        QTest::newRow("older capture: a 100 ms pause releases") << false << false << 100 << 0;
        QTest::newRow("older capture: 5 ms is no pause") << false << false << 5 << 1;
    }
    void idleMarkersDecideLikeTheSession()
    {
        QFETCH(bool, markersRecorded);
        QFETCH(bool, marker);
        QFETCH(int, gapMs);
        QFETCH(int, frames);
        struct Sink : capture::CaptureDecoder::Sink {
            int packets = 0;
            void onSample(const model::Sample &, const decode::Record &) override { ++packets; }
        } sink;
        capture::CaptureHeader h;
        if (markersRecorded)
            h.set(capture::CaptureHeader::kIdleMarkers, "1");
        capture::CaptureDecoder d;
        d.configure(h);
        std::mt19937 rng(1);
        const auto frame = protocol::hipnuc::buildFrame(protocol::hipnuc::encode(synthetic::hi91(0, rng, 100)));
        auto chunk = [](capture::ChunkKind kind, int64_t ns, const uint8_t *p, size_t n) {
            capture::CaptureReader::Chunk c;
            c.kind = kind;
            c.monotonicNs = ns;
            c.data = p;
            c.size = n;
            return c;
        };
        const uint8_t zero = 0;
        d.feedChunk(chunk(capture::ChunkReceived, 0, frame.data(), 40), sink);
        if (marker)
            d.feedChunk(chunk(capture::ChunkLineIdle, 30'000'000, &zero, 1), sink);
        d.feedChunk(chunk(capture::ChunkReceived, int64_t(gapMs) * 1'000'000, frame.data() + 40,
                          frame.size() - 40),
                    sink);
        QCOMPARE(sink.packets, frames);
    }

    void tidyCsv()
    {
        CaptureExporter::Options o;
        o.format = CaptureExporter::Format::TidyCsv;
        o.output = m_dir.filePath(QStringLiteral("tidy.csv"));
        const auto r = CaptureExporter::run(m_capture, o);
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.files, QStringList{o.output});
        const QStringList l = lines(o.output);
        QCOMPARE(l.size(), 1 + 3600);
        const QStringList head = l.front().split(QLatin1Char(','));
        QCOMPARE(head.at(0), QStringLiteral("time_s"));
        QVERIFY(head.contains(QStringLiteral("acc_x_mps2")) && head.contains(QStringLiteral("gyr_z_radps")));
        // Row 1 is the first HI91: device time in s, acceleration in m/s^2.
        const QStringList row = l.at(1).split(QLatin1Char(','));
        QCOMPARE(row.size(), head.size());
        const auto &s = m_decoded.samples.front();
        QCOMPARE(row.at(0).toDouble(), s.deviceTimeMs / 1000.0);
        QCOMPARE(row.at(head.indexOf(QStringLiteral("frame_tag"))), QStringLiteral("145"));
        QCOMPARE(row.at(head.indexOf(QStringLiteral("acc_z_mps2"))).toFloat(), float(s.acc.z * 9.8));
        QCOMPARE(row.at(head.indexOf(QStringLiteral("gyr_x_radps"))).toFloat(), float(s.gyr.x * model::kDegToRad));
        // Issue 36 point 7: the three times. The common time is the live decoder's (the same
        // clock model fed with the same chunks), counted from the same origin as host_time_s;
        // it is never after the arrival.
        const int host = head.indexOf(QStringLiteral("host_time_s")), common = head.indexOf(QStringLiteral("common_time_s"));
        QVERIFY(host >= 0 && common >= 0 && head.contains(QStringLiteral("common_uncertainty_s")));
        int checked = 0;
        for (int i = 1000; i < 3600; i += 97) {
            const QStringList r = l.at(i + 1).split(QLatin1Char(','));
            const model::Sample &d = m_decoded.samples.at(size_t(i));
            if (d.source != "HI91" || d.commonTimeNs == 0)
                continue;
            const double got = r.at(common).toDouble() - r.at(host).toDouble();
            QVERIFY2(std::abs(got - double(d.commonTimeNs - d.hostTimeNs) / 1e9) < 2e-6, qPrintable(r.join(QLatin1Char(','))));
            QVERIFY(got <= 1e-6);
            ++checked;
        }
        QVERIFY(checked > 20);
    }

    void jsonLinesMatchDecode()
    {
        CaptureExporter::Options o;
        o.format = CaptureExporter::Format::JsonLines;
        o.output = m_dir.filePath(QStringLiteral("out.jsonl"));
        QVERIFY(CaptureExporter::run(m_capture, o).ok);
        const QStringList l = lines(o.output);
        QCOMPARE(l.size(), int(m_decoded.samples.size() + m_decoded.nmea.size()));
        QCOMPARE(l.front().toStdString(), format::sampleToJson(m_decoded.samples.front()));
        QCOMPARE(l.count(QStringLiteral("{\"type\":\"NMEA\",\"sentence\":\"%1\"}").arg(QLatin1String(golden_rmc()))), 30);
    }

    void timeRange_data()
    {
        QTest::addColumn<double>("from");
        QTest::addColumn<double>("to");
        QTest::addColumn<int>("hi91");
        // Chunks of 8 frames, the first stamped at 8 ms: chunk k holds frames 8k..8k+7 at (8k) ms from the start.
        QTest::newRow("whole") << 0.0 << 1e9 << 3000;
        QTest::newRow("first second") << 0.0 << 1.0 << 1008;
        QTest::newRow("from 2 s") << 2.0 << 1e9 << 1000;
        QTest::newRow("empty") << 10.0 << 20.0 << 0;
    }
    void timeRange()
    {
        QFETCH(double, from);
        QFETCH(double, to);
        QFETCH(int, hi91);
        CaptureExporter::Options o;
        o.format = CaptureExporter::Format::TidyCsv;
        o.output = m_dir.filePath(QStringLiteral("range.csv"));
        o.fromS = from;
        o.toS = to;
        QVERIFY(CaptureExporter::run(m_capture, o).ok);
        int n = 0;
        for (const QString &line : lines(o.output))
            n += line.split(QLatin1Char(',')).at(2) == QLatin1String("145");
        QCOMPARE(n, hi91);
    }

    void progressAndCancel()
    {
        CaptureExporter::Options o;
        o.format = CaptureExporter::Format::VendorCsv;
        o.output = m_dir.filePath(QStringLiteral("cancel.csv"));
        std::vector<double> seen;
        auto r = CaptureExporter::run(m_capture, o, [&](double f) {
            seen.push_back(f);
            return true;
        });
        QVERIFY(r.ok);
        QVERIFY(!seen.empty());
        QCOMPARE(seen.back(), 1.0);
        QVERIFY(std::is_sorted(seen.begin(), seen.end()));
        r = CaptureExporter::run(m_capture, o, [](double) { return false; });
        QVERIFY(r.cancelled);
        QVERIFY(!r.ok);
        QVERIFY(!QFile::exists(m_dir.filePath(QStringLiteral("cancel_HI91.csv"))));
    }

    void malformedLinesReported_data()
    {
        QTest::addColumn<QByteArray>("csv");
        QTest::addColumn<int>("samples");
        QTest::addColumn<int>("badLine");
        QTest::addColumn<QString>("message");
        const QByteArray head = QByteArray(decode::vendor_csv::hi91Header()) + "\n";
        const QByteArray good = "HI91,1,100,0.1,0.2,1,0,0,0,20,-5,40,1,2,3,0,0,0,1,0,0,0,25,100000,1,0,45\n";
        QTest::newRow("good") << head + good + good << 2 << 0 << QString();
        QTest::newRow("bad number") << head + good + QByteArray(good).replace("0.2", "0.2x") + good << 2 << 3
                                    << QStringLiteral("acc_y");
        QTest::newRow("short row") << head + good + "HI91,1,2,3\n" << 1 << 3 << QStringLiteral("columns");
        QTest::newRow("other type") << head + "HI81,1,2\n" + good << 1 << 2 << QStringLiteral("HI81");
        QTest::newRow("blank lines and CRLF") << head + "\r\n" + QByteArray(good).replace("\n", "\r\n") << 1 << 0
                                              << QString();
        QTest::newRow("overlong line") << head + QByteArray(5000, '1') + "\n" + good << 1 << 2
                                       << QStringLiteral("longer");
    }
    void malformedLinesReported()
    {
        QFETCH(QByteArray, csv);
        QFETCH(int, samples);
        QFETCH(int, badLine);
        QFETCH(QString, message);
        QBuffer buf(&csv);
        QVERIFY(buf.open(QIODevice::ReadOnly));
        std::vector<model::Sample> got;
        const auto r = VendorCsvImporter::read(buf, [&](const model::Sample &s) { got.push_back(s); });
        QVERIFY(r.ok);
        QCOMPARE(int(got.size()), samples);
        if (badLine == 0) {
            QCOMPARE(r.badLines, uint64_t(0));
            QCOMPARE(got.front().deviceTimeMs, 100.0);
            QCOMPARE(got.front().acc.y, double(0.2f));
            return;
        }
        QCOMPARE(r.badLines, uint64_t(1));
        QCOMPARE(int(r.errors.front().line), badLine);
        QVERIFY2(r.errors.front().message.contains(message), qPrintable(r.errors.front().message));
        QVERIFY(r.errors.front().message.contains(QStringLiteral("line %1").arg(badLine)));
    }

    void notAVendorCsv_data()
    {
        QTest::addColumn<QByteArray>("csv");
        QTest::newRow("empty") << QByteArray();
        QTest::newRow("tidy csv") << QByteArray("time_s,host_time_s\n1,2\n");
        QTest::newRow("missing column") << QByteArray("HI91,pc_counter,sys_time,acc_x\n");
    }
    void notAVendorCsv()
    {
        QFETCH(QByteArray, csv);
        QBuffer buf(&csv);
        QVERIFY(buf.open(QIODevice::ReadOnly));
        const auto r = VendorCsvImporter::read(buf, {});
        QVERIFY(!r.ok);
        QVERIFY(!r.error.isEmpty());
    }

    // Found by fuzz_vendor_csv (10-minute run): a pc_counter far beyond any time in ms made
    // the ns conversion overflow (undefined behaviour); the line is now reported and skipped.
    void vendorCsvOutOfRangeCounter()
    {
        QByteArray csv = "HI91,pc_counter,sys_time,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,mag_x,mag_y,mag_z,roll,pitch,"
                         "yaw,quat_w,quat_x,quat_y,quat_z,temperature,pressure\n";
        const QByteArray rest = ",3000,0,0,1,0,0,0,20,0,-40,0,0,0,1,0,0,0,25,101325\n";
        csv += "HI91,10" + rest + "HI91,4.44444e+31" + rest + "HI91,inf" + rest + "HI91,30" + rest;
        QBuffer buf(&csv);
        QVERIFY(buf.open(QIODevice::ReadOnly));
        std::vector<model::Sample> got;
        const auto r = VendorCsvImporter::read(buf, [&](const model::Sample &s) { got.push_back(s); });
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(got.size(), size_t(2));
        QCOMPARE(got[1].hostTimeNs, int64_t(30'000'000));
        QCOMPARE(r.badLines, uint64_t(2));
        QCOMPARE(r.errors.size(), size_t(2));
        QCOMPARE(r.errors[0].line, uint64_t(3));
    }

private:
    static const char *golden_rmc() { return "$GPRMC,235952.00,A,3112.5000,N,12127.5000,E,0.0,0.0,141125,0.0,E,A*3B"; }
};

IMUDESK_TEST_GUILESS_MAIN(TstCaptureExport)
#include "tst_capture_export.moc"
