// Capture files (core/record): CRC-32 check value, header round trip, writer/reader round
// trip with random chunking, a file cut at every offset of its last chunk, a damaged chunk,
// a disk that fills (an emulated device and a real file under RLIMIT_FSIZE), split by size
// and the at-least-once-a-second flush.
#include "format/crc32.h"
#include "capture/capture_format.h"
#include "capture/capture_reader.h"
#include "capture/capture_writer.h"
#include "../common/file_size_limit.h"
#include "../common/test_main.h"

#include <QBuffer>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <random>


using namespace imudesk;
using namespace imudesk::capture;

namespace {

struct Written {
    QByteArray bytes;
    int64_t mono;
    int64_t wall;
};

CaptureHeader sampleHeader()
{
    CaptureHeader h;
    h.set(CaptureHeader::kProduct, "HI14R3");
    h.set(CaptureHeader::kFirmware, "1.7.1");
    h.set(CaptureHeader::kSerial, "0123456789ABCDEF");
    h.set(CaptureHeader::kLinkKind, "HiPNUC serial");
    h.set(CaptureHeader::kPort, "/dev/ttyUSB0");
    h.set(CaptureHeader::kBaud, "921600");
    h.setConfig({{"HI91", "ONTIME 0.001"}, {"URFR", "24"}});
    return h;
}

std::vector<Written> randomChunks(int count, uint32_t seed, int maxLen = 3000)
{
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> len(1, maxLen), byte(0, 255);
    std::vector<Written> out;
    int64_t t = 1'000'000'000;
    for (int i = 0; i < count; ++i) {
        QByteArray b(len(rng), Qt::Uninitialized);
        for (auto &c : b)
            c = char(byte(rng));
        t += 1'000'000 + len(rng);
        out.push_back({b, t, 1'700'000'000'000'000 + t / 1000});
    }
    return out;
}

std::vector<Written> readAll(const QString &path, CaptureReader::Result *last = nullptr, CaptureHeader *header = nullptr)
{
    CaptureReader r;
    QString error;
    std::vector<Written> out;
    if (!r.open(path, &error)) {
        qWarning() << error;
        if (last)
            *last = CaptureReader::Result::Error;
        return out;
    }
    if (header)
        *header = r.header();
    CaptureReader::Chunk c;
    CaptureReader::Result res;
    while ((res = r.next(c)) == CaptureReader::Result::Chunk || res == CaptureReader::Result::Damaged)
        if (res == CaptureReader::Result::Chunk)
            out.push_back({QByteArray(reinterpret_cast<const char *>(c.data), qsizetype(c.size)), c.monotonicNs,
                           c.wallUs});
    if (last)
        *last = res;
    return out;
}

// A device that accepts `limit` bytes, then fails as a full disk does.
class FullDisk : public QBuffer {
public:
    explicit FullDisk(qint64 limit, QByteArray *storage) : m_limit(limit) { setBuffer(storage); }

protected:
    qint64 writeData(const char *data, qint64 len) override
    {
        const qint64 room = m_limit - size();
        if (room <= 0) {
            setErrorString(QStringLiteral("No space left on device"));
            return -1;
        }
        return QBuffer::writeData(data, std::min(len, room));
    }

private:
    qint64 m_limit;
};

bool sameChunks(const std::vector<Written> &a, const std::vector<Written> &b, size_t count)
{
    if (a.size() < count || b.size() < count)
        return false;
    for (size_t i = 0; i < count; ++i)
        if (a[i].bytes != b[i].bytes || a[i].mono != b[i].mono || a[i].wall != b[i].wall)
            return false;
    return true;
}

} // namespace

class TstCaptureFile : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    QString writeFile(const QString &name, const std::vector<Written> &chunks, CaptureWriter::Options o = {})
    {
        const QString path = m_dir.filePath(name);
        CaptureWriter w;
        QString error;
        if (!w.start(path, sampleHeader(), o, &error))
            qWarning() << error;
        for (const auto &c : chunks)
            w.append(c.bytes.constData(), size_t(c.bytes.size()), c.mono, c.wall);
        w.stop();
        return path;
    }

private Q_SLOTS:
    void crc32CheckValue()
    {
        using imudesk::format::crc32;
        // The CRC catalogue's check value for CRC-32/ISO-HDLC.
        QCOMPARE(crc32(0, "123456789", 9), 0xCBF43926u);
        QCOMPARE(crc32(crc32(0, "12345", 5), "6789", 4), 0xCBF43926u);
        QCOMPARE(crc32(0, "", 0), 0u);
    }

    void headerRoundTrip_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("value");
        QTest::newRow("plain") << "config.HI91" << "ONTIME 0.01";
        QTest::newRow("newline") << "config.note" << "two\nlines";
        QTest::newRow("backslash") << "config.path" << "C:\\logs\\x";
        QTest::newRow("equals in key") << "config.a=b" << "c=d";
        QTest::newRow("empty value") << "device.build" << "";
        QTest::newRow("utf-8") << "config.name" << QString::fromUtf8("陀螺仪");
    }
    void headerRoundTrip()
    {
        QFETCH(QString, key);
        QFETCH(QString, value);
        CaptureHeader h = sampleHeader();
        h.set(key.toStdString(), value.toStdString());
        const auto bytes = capture::encodeFileHeader(h);
        QByteArray file(reinterpret_cast<const char *>(bytes.data()), qsizetype(bytes.size()));
        QBuffer buf(&file);
        QVERIFY(buf.open(QIODevice::ReadOnly));
        CaptureReader r;
        QString error;
        QVERIFY2(r.open(&buf, &error), qPrintable(error));
        QCOMPARE(r.header(), h);
        QCOMPARE(r.header().baud(), 921600);
        QCOMPARE(r.header().identity().firmware->toString(), std::string("1.7.1"));
        QCOMPARE(r.header().config().at("URFR"), std::string("24"));
        CaptureReader::Chunk c;
        QCOMPARE(r.next(c), CaptureReader::Result::End);
    }

    void rejectsOtherFiles_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::newRow("raw HI91 dump") << QByteArray::fromHex("5AA54C0014BB91");
        QTest::newRow("empty") << QByteArray();
        QTest::newRow("header cut") << QByteArray("IMUDCAP1\x01\x00\x00\x00\x10\x00\x00\x00key", 19);
        QTest::newRow("huge header") << QByteArray("IMUDCAP1\x01\x00\x00\x00\xFF\xFF\xFF\x7F", 16);
        QTest::newRow("version 2") << QByteArray("IMUDCAP1\x02\x00\x00\x00\x00\x00\x00\x00", 16);
    }
    void rejectsOtherFiles()
    {
        QFETCH(QByteArray, bytes);
        QBuffer buf(&bytes);
        QVERIFY(buf.open(QIODevice::ReadOnly));
        CaptureReader r;
        QString error;
        QVERIFY(!r.open(&buf, &error));
        QVERIFY(!error.isEmpty());
    }

    void roundTrip_data()
    {
        QTest::addColumn<int>("count");
        QTest::addColumn<int>("maxLen");
        QTest::newRow("one byte chunks") << 500 << 1;
        QTest::newRow("uart reads") << 2000 << 600;
        QTest::newRow("big reads") << 50 << 300000;
    }
    void roundTrip()
    {
        QFETCH(int, count);
        QFETCH(int, maxLen);
        const auto chunks = randomChunks(count, uint32_t(count + maxLen), maxLen);
        const QString path = writeFile(QStringLiteral("rt%1.imucap").arg(count), chunks);
        CaptureReader::Result last;
        CaptureHeader header;
        const auto back = readAll(path, &last, &header);
        QCOMPARE(last, CaptureReader::Result::End);
        QCOMPARE(back.size(), chunks.size());
        QVERIFY(sameChunks(back, chunks, chunks.size()));
        QCOMPARE(header.value(CaptureHeader::kProduct), std::string("HI14R3"));
        QCOMPARE(header.value(CaptureHeader::kPart), std::string("0"));
    }

    void killedMidChunkReadsUpToLastComplete()
    {
        const auto chunks = randomChunks(3, 7, 200);
        const QString path = writeFile(QStringLiteral("kill.imucap"), chunks);
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray whole = f.readAll();
        const qint64 lastSize = chunks.back().bytes.size() + qint64(capture::kChunkOverhead);
        const qint64 lastStart = whole.size() - lastSize;
        const QString cut = m_dir.filePath(QStringLiteral("cut.imucap"));
        for (qint64 at = lastStart; at < whole.size(); ++at) {
            QFile out(cut);
            QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
            out.write(whole.left(at));
            out.close();
            CaptureReader::Result last;
            const auto back = readAll(cut, &last);
            QCOMPARE(back.size(), size_t(2));
            QVERIFY(sameChunks(back, chunks, 2));
            QCOMPARE(last, at == lastStart ? CaptureReader::Result::End : CaptureReader::Result::Truncated);
        }
    }

    void damagedChunkIsSkipped_data()
    {
        QTest::addColumn<int>("offsetInChunk");
        QTest::newRow("magic") << 0;
        QTest::newRow("length") << 9;
        QTest::newRow("time") << 14;
        QTest::newRow("payload") << 40;
        QTest::newRow("crc") << 28 + 100 + 2;
    }
    void damagedChunkIsSkipped()
    {
        QFETCH(int, offsetInChunk);
        std::vector<Written> chunks = randomChunks(3, 11, 100);
        chunks[1].bytes = QByteArray(100, 'x'); // no chunk magic inside
        const QString path = writeFile(QStringLiteral("dmg.imucap"), chunks);
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadWrite));
        const qint64 second = f.size() - (chunks[2].bytes.size() + qint64(capture::kChunkOverhead)) - 132;
        QVERIFY(f.seek(second + offsetInChunk));
        char b = 0;
        f.getChar(&b);
        f.seek(second + offsetInChunk);
        f.putChar(char(b ^ 0x10));
        f.close();
        CaptureReader r;
        QString error;
        QVERIFY(r.open(path, &error));
        CaptureReader::Chunk c;
        QCOMPARE(r.next(c), CaptureReader::Result::Chunk);
        QCOMPARE(r.next(c), CaptureReader::Result::Damaged);
        QCOMPARE(r.next(c), CaptureReader::Result::Chunk);
        QCOMPARE(QByteArray(reinterpret_cast<const char *>(c.data), qsizetype(c.size)), chunks[2].bytes);
        QCOMPARE(r.next(c), CaptureReader::Result::End);
        QCOMPARE(r.damagedChunks(), uint64_t(1));
    }

    void fullDiskStopsWithMessage_data()
    {
        QTest::addColumn<int>("limit");
        QTest::newRow("header fits, chunks fill") << 20000;
        QTest::newRow("room for almost nothing") << 300;
    }
    void fullDiskStopsWithMessage()
    {
        QFETCH(int, limit);
        QByteArray storage;
        CaptureWriter w;
        w.setDeviceFactory([&](const QString &, QString *) {
            auto dev = std::make_unique<FullDisk>(limit, &storage);
            dev->open(QIODevice::WriteOnly);
            return std::unique_ptr<QIODevice>(std::move(dev));
        });
        QString reason;
        std::atomic<int> stopped{0};
        w.setStoppedHandler([&](const QString &r) {
            reason = r;
            ++stopped;
        });
        QString error;
        QVERIFY2(w.start(QStringLiteral("full.imucap"), sampleHeader(), {}, &error), qPrintable(error));
        const auto chunks = randomChunks(200, 3, 500);
        for (const auto &c : chunks) {
            w.append(c.bytes.constData(), size_t(c.bytes.size()), c.mono, c.wall);
            QCoreApplication::processEvents(); // events between chunks, without waiting
        }
        QTRY_COMPARE(stopped.load(), 1);
        QVERIFY(reason.contains(QStringLiteral("No space left on device")));
        QVERIFY(reason.contains(QStringLiteral("free some disk space")));
        const auto st = w.status();
        QVERIFY(st.failed);
        QVERIFY(!st.running);
        QVERIFY(!w.append("x", 1, 0, 0)); // refused after the failure
        QCOMPARE(w.stop(), reason);
        QCOMPARE(storage.size(), limit);
        // What was written reads back intact up to the last complete chunk.
        QBuffer buf(&storage);
        QVERIFY(buf.open(QIODevice::ReadOnly));
        CaptureReader r;
        QVERIFY(r.open(&buf, &error));
        CaptureReader::Chunk c;
        size_t n = 0;
        CaptureReader::Result res;
        while ((res = r.next(c)) == CaptureReader::Result::Chunk) {
            QCOMPARE(QByteArray(reinterpret_cast<const char *>(c.data), qsizetype(c.size)), chunks[n].bytes);
            ++n;
        }
        QCOMPARE(n, size_t(st.chunks));
        QVERIFY(res == CaptureReader::Result::Truncated || res == CaptureReader::Result::End);
    }

    void fileSizeLimitLeavesIntactFile()
    {
        // A real file on a "disk" of 64 KiB: RLIMIT_FSIZE makes write() fail with EFBIG.
        const QString path = m_dir.filePath(QStringLiteral("limited.imucap"));
        imudesk::test::FileSizeLimit disk(64 * 1024);
        QVERIFY(disk.ok());
        CaptureWriter w;
        std::atomic<int> stopped{0};
        w.setStoppedHandler([&](const QString &) { ++stopped; });
        QString error;
        const bool started = w.start(path, sampleHeader(), {}, &error);
        const auto chunks = randomChunks(400, 5, 700);
        for (const auto &c : chunks)
            w.append(c.bytes.constData(), size_t(c.bytes.size()), c.mono, c.wall);
        const bool sawStop = imudesk::test::waitFor([&] { return stopped.load() == 1; }, 5000);
        const QString reason = w.stop();
        disk.lift();
        QVERIFY2(started, qPrintable(error));
        QVERIFY(sawStop);
        QVERIFY(!reason.isEmpty());
        QVERIFY(QFileInfo(path).size() <= 64 * 1024);
        // The partly written chunk was cut off: the file ends with a complete chunk.
        CaptureReader::Result last;
        const auto back = readAll(path, &last);
        QCOMPARE(last, CaptureReader::Result::End);
        QCOMPARE(back.size(), size_t(w.status().chunks));
        QVERIFY(back.size() > 50);
        QVERIFY(sameChunks(back, chunks, back.size()));
    }

    void splitsBySize()
    {
        const auto chunks = randomChunks(300, 9, 400);
        CaptureWriter::Options o;
        o.splitBytes = 20000;
        const QString path = m_dir.filePath(QStringLiteral("split.imucap"));
        CaptureWriter w;
        QString error;
        QVERIFY(w.start(path, sampleHeader(), o, &error));
        for (const auto &c : chunks)
            w.append(c.bytes.constData(), size_t(c.bytes.size()), c.mono, c.wall);
        QVERIFY(w.stop().isEmpty());
        const QStringList parts = w.status().paths;
        QVERIFY(parts.size() > 3);
        QCOMPARE(parts.at(1), m_dir.filePath(QStringLiteral("split-001.imucap")));
        std::vector<Written> all;
        for (int i = 0; i < parts.size(); ++i) {
            QVERIFY(QFileInfo(parts.at(i)).size() <= o.splitBytes);
            CaptureReader::Result last;
            CaptureHeader h;
            const auto back = readAll(parts.at(i), &last, &h);
            QCOMPARE(last, CaptureReader::Result::End);
            QCOMPARE(h.value(CaptureHeader::kPart), std::to_string(i));
            QCOMPARE(h.value(CaptureHeader::kSerial), std::string("0123456789ABCDEF"));
            all.insert(all.end(), back.begin(), back.end());
        }
        QCOMPARE(all.size(), chunks.size());
        QVERIFY(sameChunks(all, chunks, chunks.size()));
    }

    void splitsByTime()
    {
        auto chunks = randomChunks(100, 13, 50);
        for (size_t i = 0; i < chunks.size(); ++i)
            chunks[i].mono = int64_t(i) * 100'000'000; // 10 per second
        CaptureWriter::Options o;
        o.splitSeconds = 3;
        const QString path = m_dir.filePath(QStringLiteral("tsplit.imucap"));
        CaptureWriter w;
        QString error;
        QVERIFY(w.start(path, sampleHeader(), o, &error));
        for (const auto &c : chunks)
            w.append(c.bytes.constData(), size_t(c.bytes.size()), c.mono, c.wall);
        w.stop();
        const QStringList parts = w.status().paths;
        QCOMPARE(parts.size(), 4); // 0-2.9 s, 3-5.9 s, 6-8.9 s, 9-9.9 s
        QCOMPARE(readAll(parts.at(1)).size(), size_t(30));
    }

    void flushesWhileRecording()
    {
        const QString path = m_dir.filePath(QStringLiteral("flush.imucap"));
        CaptureWriter w;
        QString error;
        QVERIFY(w.start(path, sampleHeader(), {}, &error));
        const auto chunks = randomChunks(10, 17, 100);
        for (const auto &c : chunks)
            w.append(c.bytes.constData(), size_t(c.bytes.size()), c.mono, c.wall);
        // Readable by another reader within a second, while the writer still runs.
        QTRY_COMPARE_WITH_TIMEOUT(readAll(path).size(), size_t(10), 1000);
        QVERIFY(w.status().running);
        w.stop();
    }

    void unwritableFolderFails()
    {
        CaptureWriter w;
        QString error;
        QVERIFY(!w.start(QStringLiteral("/proc/no/such/dir/x.imucap"), sampleHeader(), {}, &error));
        QVERIFY(error.contains(QStringLiteral("/proc/no/such/dir/x.imucap")));
        QVERIFY(!w.append("x", 1, 0, 0));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCaptureFile)
#include "tst_capture_file.moc"
