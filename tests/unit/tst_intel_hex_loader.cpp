// Intel HEX and .bin loading: record types 00-05, checksums, ordering, gaps, overlaps,
// missing end record; every error names its line (hipnuc-protocol-notes.md 3.4).
#include "protocol/ihex/intel_hex_loader.h"
#include "protocol/ihex/intel_hex_writer.h"
#include "../common/test_main.h"

#include <QTemporaryDir>
#include <QTest>

#include <string>

using namespace imudesk::protocol::ihex;

namespace {

// Builds one record with a correct checksum.
std::string record(uint8_t type, uint16_t address, const std::vector<uint8_t> &data)
{
    std::vector<uint8_t> r{uint8_t(data.size()), uint8_t(address >> 8), uint8_t(address), type};
    r.insert(r.end(), data.begin(), data.end());
    uint8_t sum = 0;
    for (uint8_t b : r)
        sum = uint8_t(sum + b);
    r.push_back(uint8_t(-sum));
    std::string s = ":";
    static const char *hex = "0123456789ABCDEF";
    for (uint8_t b : r) {
        s += hex[b >> 4];
        s += hex[b & 15];
    }
    return s + "\r\n";
}

const std::string kEof = ":00000001FF\r\n";

} // namespace

class TstIntelHexLoader : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void wikipediaExample()
    {
        // The classic example file (Intel HEX specification / Wikipedia), types 00 and 01.
        const std::string text = ":10010000214601360121470136007EFE09D2190140\n"
                                 ":100110002146017E17C20001FF5F16002148011928\n"
                                 ":10012000194E79234623965778239EDA3F01B2CAA7\n"
                                 ":100130003F0156702B5E712B722B732146013421C7\n"
                                 ":00000001FF\n";
        const auto r = IntelHexLoader::parseHex(text);
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.image->startAddress, 0x0100u);
        QCOMPARE(r.image->size(), 64u);
        QCOMPARE(r.image->data[0], uint8_t(0x21));
        QCOMPARE(r.image->data[63], uint8_t(0x21));
    }

    void addressing_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<uint>("start");
        QTest::addColumn<QByteArray>("data");
        QTest::addColumn<qlonglong>("entry");
        QTest::newRow("04 linear base") << QByteArray((record(4, 0, {0x08, 0x00}) + record(0, 0x4000, {1, 2}) + kEof).c_str())
                                        << 0x08004000u << QByteArray("\x01\x02", 2) << qlonglong(-1);
        QTest::newRow("02 segment base") << QByteArray((record(2, 0, {0x10, 0x00}) + record(0, 0x0010, {7}) + kEof).c_str())
                                         << 0x00010010u << QByteArray("\x07", 1) << qlonglong(-1);
        QTest::newRow("05 entry") << QByteArray((record(0, 0x8000, {9}) + record(5, 0, {0x00, 0x00, 0x80, 0xC1}) + kEof).c_str())
                                  << 0x8000u << QByteArray("\x09", 1) << qlonglong(0x80C1);
        QTest::newRow("03 entry CS:IP") << QByteArray((record(0, 0x8000, {9}) + record(3, 0, {0x12, 0x34, 0x00, 0x05}) + kEof).c_str())
                                        << 0x8000u << QByteArray("\x09", 1) << qlonglong(0x12345);
        QTest::newRow("out of order, gap 0xFF")
            << QByteArray((record(0, 0x8004, {5, 6}) + record(0, 0x8000, {1, 2}) + kEof).c_str()) << 0x8000u
            << QByteArray("\x01\x02\xFF\xFF\x05\x06", 6) << qlonglong(-1);
        QTest::newRow("zero-length data ignored, LF only, blank lines")
            << QByteArray(("\n" + record(0, 0x9000, {}) + record(0, 0x9000, {0xAA}) + "\n" + kEof + "\n\n").c_str())
            << 0x9000u << QByteArray("\xAA", 1) << qlonglong(-1);
        QTest::newRow("lowercase hex") << QByteArray(":02800000aabb19\n:00000001ff\n") << 0x8000u
                                       << QByteArray("\xAA\xBB", 2) << qlonglong(-1);
    }
    void addressing()
    {
        QFETCH(QByteArray, text);
        QFETCH(uint, start);
        QFETCH(QByteArray, data);
        QFETCH(qlonglong, entry);
        const auto r = IntelHexLoader::parseHex(std::string_view(text.constData(), size_t(text.size())));
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.image->startAddress, uint32_t(start));
        QCOMPARE(QByteArray(reinterpret_cast<const char *>(r.image->data.data()), int(r.image->data.size())), data);
        QCOMPARE(r.image->entryPoint ? qlonglong(*r.image->entryPoint) : -1, entry);
    }

    void errors_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("needle");
        const std::string a = record(0, 0x8000, {1, 2, 3, 4});
        std::string badSum = a;
        badSum[badSum.size() - 3] = badSum[badSum.size() - 3] == '0' ? '1' : '0';
        QTest::newRow("bad checksum") << QByteArray((a + badSum + kEof).c_str()) << 2 << QStringLiteral("checksum");
        QTest::newRow("missing end record") << QByteArray((a + record(0, 0x8004, {5})).c_str()) << 2
                                            << QStringLiteral("end-of-file");
        QTest::newRow("truncated mid-record") << QByteArray((a + a.substr(0, 9)).c_str()) << 2
                                              << QStringLiteral("too short");
        QTest::newRow("truncated data") << QByteArray((a + ":04800400010203F0\n" + kEof).c_str()) << 2
                                        << QStringLiteral("data bytes");
        QTest::newRow("empty file") << QByteArray() << 0 << QStringLiteral("empty");
        QTest::newRow("only blank lines") << QByteArray("\r\n\n") << 0 << QStringLiteral("empty");
        QTest::newRow("no colon") << QByteArray((a + "hello\n" + kEof).c_str()) << 2 << QStringLiteral("':'");
        QTest::newRow("bad digit") << QByteArray(":0G800000AABBF9\n") << 1 << QStringLiteral("hex digit");
        QTest::newRow("overlap") << QByteArray((a + record(0, 0x8002, {9}) + kEof).c_str()) << 2
                                 << QStringLiteral("line 1 already wrote");
        QTest::newRow("overlap out of order") << QByteArray((record(0, 0x8002, {9}) + a + kEof).c_str()) << 2
                                              << QStringLiteral("overlapping");
        QTest::newRow("unknown type") << QByteArray((record(6, 0, {}) + kEof).c_str()) << 1
                                      << QStringLiteral("unknown record type 06");
        QTest::newRow("data after eof") << QByteArray((a + kEof + a).c_str()) << 3 << QStringLiteral("after the end-of-file");
        QTest::newRow("eof with data") << QByteArray((a + record(1, 0, {1})).c_str()) << 2 << QStringLiteral("no data");
        QTest::newRow("04 wrong length") << QByteArray((record(4, 0, {1}) + kEof).c_str()) << 1
                                         << QStringLiteral("2 data bytes");
        QTest::newRow("05 wrong length") << QByteArray((record(5, 0, {1, 2}) + kEof).c_str()) << 1
                                         << QStringLiteral("4 data bytes");
        QTest::newRow("past 4 GiB") << QByteArray((record(4, 0, {0xFF, 0xFF}) + record(0, 0xFFFF, {1, 2}) + kEof).c_str())
                                    << 2 << QStringLiteral("4 GiB");
        QTest::newRow("span too large") << QByteArray((record(0, 0, {1}) + record(4, 0, {0x10, 0x00}) + record(0, 0, {2}) + kEof).c_str())
                                        << 3 << QStringLiteral("spans");
        QTest::newRow("no data") << QByteArray(kEof.c_str()) << 1 << QStringLiteral("no data records");
    }
    void errors()
    {
        QFETCH(QByteArray, text);
        QFETCH(int, line);
        QFETCH(QString, needle);
        const auto r = IntelHexLoader::parseHex(std::string_view(text.constData(), size_t(text.size())));
        QVERIFY(!r.ok());
        QCOMPARE(r.line, line);
        QVERIFY2(r.error.contains(needle), qPrintable(r.error));
        if (line > 0)
            QVERIFY2(r.error.startsWith(QStringLiteral("line %1:").arg(line)), qPrintable(r.error));
    }

    void fileTooLargeRefusedBeforeParsing()
    {
        IntelHexLoader::Limits l;
        l.maxFileBytes = 10;
        const auto r = IntelHexLoader::parseHex(":00000001FF\n\n\n", l);
        QVERIFY(!r.ok());
        QVERIFY(r.error.contains(QStringLiteral("more than")));
    }

    void binary()
    {
        const auto r = IntelHexLoader::fromBinary(std::string_view("\x01\x02\x03", 3), 0x8000);
        QVERIFY(r.ok());
        QCOMPARE(r.image->startAddress, 0x8000u);
        QCOMPARE(r.image->size(), 3u);
        QVERIFY(!IntelHexLoader::fromBinary({}, 0x8000).ok());
        QVERIFY(IntelHexLoader::fromBinary(std::string_view("\x01\x02", 2), 0xFFFFFFFF).error.contains(QStringLiteral("4 GiB")));
    }

    void files()
    {
        QTemporaryDir dir;
        const QString bin = dir.filePath(QStringLiteral("fw.BIN")), hex = dir.filePath(QStringLiteral("fw.hex"));
        QFile f(bin);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("\xAA\xBB", 2);
        f.close();
        QVERIFY(IntelHexLoader::loadFile(bin).error.contains(QStringLiteral("start address")));
        const auto b = IntelHexLoader::loadFile(bin, 0x10000);
        QVERIFY(b.ok());
        QCOMPARE(b.image->startAddress, 0x10000u);
        QFile h(hex);
        QVERIFY(h.open(QIODevice::WriteOnly));
        h.write((record(0, 0x8000, {0xAA, 0xBB}) + kEof).c_str());
        h.close();
        const auto x = IntelHexLoader::loadFile(hex);
        QVERIFY2(x.ok(), qPrintable(x.error));
        QCOMPARE(x.image->data, b.image->data);
        QVERIFY(!IntelHexLoader::loadFile(dir.filePath(QStringLiteral("missing.hex"))).ok());
    }

    void writerRoundTrip_data()
    {
        QTest::addColumn<uint>("start");
        QTest::addColumn<int>("size");
        QTest::newRow("small") << 0x8000u << 5;
        QTest::newRow("crosses 64 KiB") << 0x0800FFF0u << 300;
        QTest::newRow("at 0") << 0u << 70000;
    }
    void writerRoundTrip()
    {
        QFETCH(uint, start);
        QFETCH(int, size);
        FirmwareImage img;
        img.startAddress = start;
        img.entryPoint = 0x80C1;
        for (int i = 0; i < size; ++i)
            img.data.push_back(uint8_t(i * 7 + 3));
        const std::string text = IntelHexWriter::write(img);
        const auto r = IntelHexLoader::parseHex(text);
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.image->startAddress, img.startAddress);
        QCOMPARE(r.image->data, img.data);
        QCOMPARE(r.image->entryPoint, img.entryPoint);
        QCOMPARE(r.image->crc32(), img.crc32());
    }

    void crc32Check()
    {
        QCOMPARE(crc32(reinterpret_cast<const uint8_t *>("123456789"), 9), 0xCBF43926u);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstIntelHexLoader)
#include "tst_intel_hex_loader.moc"
