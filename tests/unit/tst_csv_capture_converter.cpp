// A vendor CSV imported (CaptureSource::convert, or read in place through CaptureSource) and exported
// again as vendor CSV gives back every cell it had (issue 53): pps_sync_stamp, incli_x and
// incli_y, which an HI91 frame does not carry, came back as 0, and pc_counter restarted at 0;
// a norm the vendor's tool wrote with other digits is kept as written too.
#include "../common/test_main.h"
#include "record/capture_exporter.h"
#include "capture/capture_reader.h"
#include "record/capture_source.h"
#include "decode/hipnuc_vendor_csv.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace imudesk::record;
using namespace imudesk::decode;
using namespace imudesk::capture;
using namespace imudesk;

namespace {

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Rows in the vendor's layout (hi91Header): values as the vendor's tool writes them.
QByteArray vendorFile(double pc0, const QByteArray &pps, const QByteArray &incliX, const QByteArray &incliY,
                      bool vendorNorms, int rows = 5)
{
    QByteArray text = QByteArray(vendor_csv::hi91Header()) + "\n";
    for (int i = 0; i < rows; ++i) {
        const QByteArray pc = QByteArray::number(pc0 + 10 * i, 'g', 12);
        const QByteArray accNorm = vendorNorms ? QByteArray("1.000123") : QByteArray();
        // sys_time, acc, gyr, mag, roll pitch yaw
        QByteArray row = "HI91," + pc + "," + QByteArray::number(2000 + 10 * i) + ",0.0123,-0.02,0.98,0.5,-0.25,0.125,"
            + "20.5,-5.25," + QByteArray::number(40 + i) + ",1.5,-0.5," + QByteArray::number(90 + i) + ","
            // pps_sync_stamp, incli_x, incli_y
            + pps + QByteArray::number(i) + "," + incliX + "," + incliY + ","
            // quat, temperature, pressure
            + "0.99,0.01,-0.02,0.1,25,101325.5,";
        if (vendorNorms) {
            row += accNorm + ",0.58630197,45.789";
        } else {
            // ImuDesk's own norms of these values (what the export writes).
            imudesk::protocol::hipnuc::Hi91 h;
            h.acc = {0.0123f, -0.02f, 0.98f};
            h.gyr = {0.5f, -0.25f, 0.125f};
            h.mag = {20.5f, -5.25f, float(40 + i)};
            const std::vector<std::string> cells = vendor_csv::hi91Cells(h, 0);
            row += QByteArray::fromStdString(cells[24] + "," + cells[25] + "," + cells[26]);
        }
        text += row + "\n";
    }
    return text;
}

} // namespace

class TstCsvCaptureConverter : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void vendorCsvRoundTrip_data()
    {
        QTest::addColumn<QByteArray>("csv");
        QTest::addColumn<bool>("inPlace"); // exported straight from the CSV (File > Export of a CSV)
        QTest::newRow("pc_counter from 123456, pps and inclination")
            << vendorFile(123456, "77", "1.25", "-0.75", false) << false;
        QTest::newRow("fractional pc_counter") << vendorFile(987654.25, "1000", "0.001", "-12.5", false) << false;
        QTest::newRow("vendor's own norms") << vendorFile(123456, "5", "3", "4", true) << false;
        QTest::newRow("exported from the CSV in place") << vendorFile(123456, "9", "2.5", "-2.5", false) << true;
    }
    void vendorCsvRoundTrip()
    {
        QFETCH(QByteArray, csv);
        QFETCH(bool, inPlace);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString in = dir.filePath(QStringLiteral("vendor.csv"));
        {
            QFile f(in);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(csv);
        }
        QString source = in;
        if (!inPlace) {
            source = dir.filePath(QStringLiteral("imported.imucap"));
            const auto c = CaptureSource::convert(in, source);
            QVERIFY2(c.ok, qPrintable(c.error));
            QCOMPARE(c.import.badLines, uint64_t(0));
        }
        CaptureExporter::Options o;
        o.format = CaptureExporter::Format::VendorCsv;
        o.output = dir.filePath(QStringLiteral("again.csv"));
        const auto e = CaptureExporter::run(source, o);
        QVERIFY2(e.ok, qPrintable(e.error));
        const QList<QByteArray> want = csv.trimmed().split('\n');
        const QList<QByteArray> got = readAll(o.output).trimmed().split('\n');
        QCOMPARE(got.size(), want.size());
        const QList<QByteArray> names = want.at(0).split(',');
        for (int line = 0; line < want.size(); ++line) {
            const QList<QByteArray> a = want.at(line).split(','), b = got.at(line).split(',');
            QCOMPARE(b.size(), a.size());
            for (int c = 0; c < a.size(); ++c)
                QVERIFY2(a.at(c) == b.at(c), qPrintable(QStringLiteral("line %1, %2: %3 came back as %4")
                                                            .arg(line + 1)
                                                            .arg(QString::fromUtf8(names.at(c)), QString::fromUtf8(a.at(c)),
                                                                 QString::fromUtf8(b.at(c)))));
        }
    }

    // The capture stays readable as before: its frames are HI91, its extra cells in chunks of a
    // kind older readers pass over, and the tidy export still starts its times at 0.
    void importedCaptureStaysACapture()
    {
        QTemporaryDir dir;
        const QString in = dir.filePath(QStringLiteral("vendor.csv"));
        {
            QFile f(in);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(vendorFile(123456, "77", "1.25", "-0.75", false));
        }
        const QString cap = dir.filePath(QStringLiteral("imported.imucap"));
        QVERIFY(CaptureSource::convert(in, cap).ok);
        CaptureReader reader;
        QString error;
        QVERIFY2(reader.open(cap, &error), qPrintable(error));
        QCOMPARE(QString::fromStdString(reader.header().value(CaptureHeader::kPcCounter)), QStringLiteral("chunk time"));
        int received = 0, cells = 0;
        CaptureReader::Chunk c;
        while (reader.next(c) == CaptureReader::Result::Chunk) {
            if (c.kind == capture::ChunkReceived)
                ++received;
            else if (c.kind == capture::ChunkVendorCells)
                ++cells;
        }
        QCOMPARE(received, 5);
        QCOMPARE(cells, 5); // each row has a pps_sync_stamp and an inclination
        CaptureExporter::Options o;
        o.format = CaptureExporter::Format::TidyCsv;
        o.output = dir.filePath(QStringLiteral("tidy.csv"));
        QVERIFY(CaptureExporter::run(cap, o).ok);
        const QList<QByteArray> tidy = readAll(o.output).split('\n');
        const int hostTime = int(tidy.at(0).split(',').indexOf("host_time_s"));
        QVERIFY(hostTime >= 0);
        QCOMPARE(tidy.at(1).split(',').at(hostTime).toDouble(), 0.0);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCsvCaptureConverter)
#include "tst_csv_capture_converter.moc"
