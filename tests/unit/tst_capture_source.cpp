// CaptureSource: files recognised by content, whatever their names (a capture, a vendor CSV,
// a raw byte dump, anything else refused with a reason), and a raw dump made readable as a
// capture: every byte kept in order, times from the device's clock carried across a restart,
// the header saying that arrival times are absent. Export and analysis take the raw dump.
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"
#include "protocol/nmea/nmea_parser.h"
#include "record/capture_exporter.h"
#include "capture/capture_format.h"
#include "capture/capture_reader.h"
#include "record/capture_source.h"
#include "record/file_analysis.h"
#include "../common/test_main.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <vector>

using namespace imudesk;
using namespace imudesk::record;
using namespace imudesk::capture;
namespace hp = imudesk::protocol::hipnuc;

namespace {

void append(std::vector<uint8_t> &out, const std::vector<uint8_t> &bytes)
{
    out.insert(out.end(), bytes.begin(), bytes.end());
}

// n HI91 frames 10 ms apart from startMs, with a line of noise after every 50th.
void hi91Run(std::vector<uint8_t> &out, uint32_t startMs, int n)
{
    for (int i = 0; i < n; ++i) {
        hp::Hi91 h;
        h.systemTime = startMs + uint32_t(i) * 10;
        h.acc = {0, 0, 1};
        append(out, hp::buildFrame(hp::encode(h)));
        if (i % 50 == 49) {
            const std::string noise = "\x01\x02noise\xff";
            out.insert(out.end(), noise.begin(), noise.end());
        }
    }
}

QString write(const QTemporaryDir &dir, const QString &name, const QByteArray &bytes)
{
    const QString path = dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
        qFatal("cannot write %s", qPrintable(path));
    return path;
}

QByteArray bytesOf(const std::vector<uint8_t> &v)
{
    return QByteArray(reinterpret_cast<const char *>(v.data()), qsizetype(v.size()));
}

} // namespace

class TstCaptureSource : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void recognisedByContent()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        std::vector<uint8_t> raw;
        hi91Run(raw, 1000, 20);
        // A raw dump named .csv, a vendor CSV named .bin, a capture named .txt.
        const QString dump = write(dir, QStringLiteral("dump.csv"), bytesOf(raw));
        const QString csv = write(dir, QStringLiteral("log.bin"),
                                  "HI91,pc_counter,main_status,temperature,air_pressure,system_time\n");
        CaptureHeader h;
        std::vector<uint8_t> cap = capture::encodeFileHeader(h);
        const QString capture = write(dir, QStringLiteral("rec.txt"), bytesOf(cap));
        const QString nmea = write(dir, QStringLiteral("gnss.log"),
                                   QByteArray::fromStdString(protocol::nmea::buildSentence("GPGGA,010203,3112.5,N,12127.5,E,1,08,1.0,12.5,M,0,M,,")));
        QCOMPARE(CaptureSource::detect(dump), CaptureSource::Kind::RawDump);
        QCOMPARE(CaptureSource::detect(csv), CaptureSource::Kind::VendorCsv);
        QCOMPARE(CaptureSource::detect(capture), CaptureSource::Kind::Capture);
        QCOMPARE(CaptureSource::detect(nmea), CaptureSource::Kind::RawDump);
        // Text without frames or sentences, an empty file, a missing one: refused, with why.
        QString why;
        const QString text = write(dir, QStringLiteral("notes.imucap"), "hello, this is not a capture\n");
        QCOMPARE(CaptureSource::detect(text, &why), CaptureSource::Kind::Unknown);
        QVERIFY2(why.contains(QStringLiteral("HiPNUC frames or NMEA sentences in its first 64 KiB")), qPrintable(why));
        QCOMPARE(CaptureSource::detect(write(dir, QStringLiteral("empty"), {}), &why), CaptureSource::Kind::Unknown);
        QVERIFY(why.contains(QStringLiteral("empty")));
        QCOMPARE(CaptureSource::detect(dir.filePath(QStringLiteral("missing")), &why), CaptureSource::Kind::Unknown);
        CaptureSource s;
        QVERIFY(!s.prepare(text, &why));
        QVERIFY(s.prepare(capture, &why));
        QCOMPARE(s.capturePath(), capture); // read in place
        QVERIFY(s.notes().isEmpty());
    }

    void rawDumpKeepsEveryByteWithDeviceTimes()
    {
        // 300 frames from 1000 ms, then the module restarts (time back to 0) and sends 200 more.
        std::vector<uint8_t> raw;
        hi91Run(raw, 1000, 300);
        hi91Run(raw, 0, 200);
        QTemporaryDir dir;
        const QString dump = write(dir, QStringLiteral("dump.bin"), bytesOf(raw));
        CaptureSource source;
        QString error;
        QVERIFY2(source.prepare(dump, &error), qPrintable(error));
        QCOMPARE(source.kind(), CaptureSource::Kind::RawDump);
        QVERIFY(source.capturePath() != dump);
        QCOMPARE(source.notes().size(), 2); // no arrival times; one clock restart
        QVERIFY(source.notes().at(0).contains(QStringLiteral("device's own clock")));

        CaptureReader reader;
        QVERIFY2(reader.open(source.capturePath(), &error), qPrintable(error));
        QCOMPARE(reader.header().value(CaptureHeader::kHostTime), std::string("absent"));
        std::vector<uint8_t> back;
        std::vector<int64_t> times;
        CaptureReader::Chunk c;
        while (reader.next(c) == CaptureReader::Result::Chunk) {
            back.insert(back.end(), c.data, c.data + c.size);
            times.push_back(c.monotonicNs);
        }
        QCOMPARE(back, raw); // every byte, in order
        QVERIFY(std::is_sorted(times.begin(), times.end()));
        // 499 intervals of 10 ms, the restart carried across: the last block's stamp is the
        // last complete frame's time within a block (up to 6 frames of 82 bytes per 512).
        const double lastS = double(times.back()) / 1e9;
        QVERIFY2(lastS > 4.9 && lastS <= 4.99, qPrintable(QString::number(lastS)));

        const auto r = CaptureSource::convert(dump, dir.filePath(QStringLiteral("again.imucap")));
        QVERIFY(r.ok);
        QCOMPARE(r.import.frames, uint64_t(500));
        QCOMPARE(r.import.clockJumps, uint64_t(1));
        QVERIFY(r.import.deviceClock);
        QCOMPARE(r.import.bytes, uint64_t(raw.size()));
    }

    void rawDumpFollowsTheModulesCounterOverGnssTime()
    {
        // HI91 at 100 Hz with HI81 at 10 Hz on one line, as `LOG HI91 ONTIME 0.01` + `LOG HI81
        // ONTIME 0.1` send it, and the dump begins with an HI81 frame. HI81 carries the GNSS time
        // of week, 0 until the receiver has a fix: it never moves. The module's own counter in
        // HI91 times the dump (before: the first frame's clock was followed, every stamp was 0).
        std::vector<uint8_t> raw;
        for (int i = 0; i < 200; ++i) {
            if (i % 10 == 0) {
                hp::Hi81 g;
                g.gpsTowMs = 0;
                append(raw, hp::buildFrame(hp::encode(g)));
            }
            hp::Hi91 h;
            h.systemTime = 7000 + uint32_t(i) * 10;
            append(raw, hp::buildFrame(hp::encode(h)));
        }
        QTemporaryDir dir;
        const QString dump = write(dir, QStringLiteral("hi81-first.bin"), bytesOf(raw));
        const auto r = CaptureSource::convert(dump, dir.filePath(QStringLiteral("c.imucap")));
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.import.frames, uint64_t(220));
        QCOMPARE(r.import.clockJumps, uint64_t(0));
        QVERIFY(r.import.deviceClock);
        CaptureReader reader;
        QString error;
        QVERIFY2(reader.open(dir.filePath(QStringLiteral("c.imucap")), &error), qPrintable(error));
        CaptureReader::Chunk c;
        int64_t last = 0;
        while (reader.next(c) == CaptureReader::Result::Chunk)
            last = c.monotonicNs;
        // 199 intervals of 10 ms; the last block is stamped with its last complete frame.
        const double lastS = double(last) / 1e9;
        QVERIFY2(lastS > 1.9 && lastS <= 1.99, qPrintable(QString::number(lastS)));
    }

    void exportAndAnalysisTakeARawDump()
    {
        std::vector<uint8_t> raw;
        hi91Run(raw, 5000, 400);
        QTemporaryDir dir;
        const QString dump = write(dir, QStringLiteral("terminal.log"), bytesOf(raw));
        CaptureExporter::Options o;
        o.format = CaptureExporter::Format::TidyCsv;
        o.output = dir.filePath(QStringLiteral("out.csv"));
        const auto r = CaptureExporter::run(dump, o);
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.frames, uint64_t(400));
        QVERIFY(!r.notes.isEmpty());
        // A time range in seconds of the device clock: the first second is 100 frames.
        o.output = dir.filePath(QStringLiteral("first.csv"));
        o.toS = 0.995;
        const auto first = CaptureExporter::run(dump, o);
        QVERIFY2(first.ok, qPrintable(first.error));
        QVERIFY2(first.frames >= 94 && first.frames <= 106, qPrintable(QString::number(first.frames)));

        const auto a = FileAnalysis::run(dump);
        QVERIFY2(a.ok, qPrintable(a.error));
        QCOMPARE(a.result.frames, uint64_t(400));
        QVERIFY(std::abs(a.result.rateHz - 100.0) < 1.0);
        QVERIFY(!a.warnings.isEmpty());
        // Not a capture at all: said.
        const auto bad = FileAnalysis::run(write(dir, QStringLiteral("x.imucap"), "plain text\n"));
        QVERIFY(!bad.ok);
        QVERIFY(bad.error.contains(QStringLiteral("neither")));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCaptureSource)
#include "tst_capture_source.moc"
