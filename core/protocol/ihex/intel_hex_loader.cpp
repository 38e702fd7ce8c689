#include "intel_hex_loader.h"

#include <QFile>
#include <QLoggingCategory>

#include <algorithm>
#include <vector>

namespace imudesk::protocol::ihex {

namespace {

Q_LOGGING_CATEGORY(lcIhex, "imudesk.core.protocol.ihex", QtInfoMsg)

struct Piece {
    uint64_t address = 0;
    size_t offset = 0; // into the collected data bytes
    size_t length = 0;
    int line = 0;
};

int hexNibble(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    return -1;
}

LoadResult failure(int line, const QString &message)
{
    LoadResult r;
    r.line = line;
    r.error = line > 0 ? IntelHexLoader::tr("line %1: %2").arg(line).arg(message) : message;
    return r;
}

QString hex32(uint64_t v)
{
    return QStringLiteral("0x") + QString::number(qulonglong(v), 16).toUpper().rightJustified(8, QLatin1Char('0'));
}

} // namespace

LoadResult IntelHexLoader::parseHex(std::string_view text, const Limits &limits)
{
    if (text.size() > limits.maxFileBytes)
        return failure(0, tr("the file is %1 bytes, more than the %2 bytes a firmware file may have")
                              .arg(qulonglong(text.size()))
                              .arg(qulonglong(limits.maxFileBytes)));
    std::vector<uint8_t> bytes;     // data bytes of all data records, in file order
    std::vector<Piece> pieces;
    std::vector<uint8_t> rec;
    std::optional<uint32_t> entry;
    uint64_t base = 0;
    bool ended = false;
    int endLine = 0;
    int lineNo = 0;
    int lastLine = 0;
    size_t pos = 0;
    while (pos < text.size()) {
        size_t eol = text.find('\n', pos);
        if (eol == std::string_view::npos)
            eol = text.size();
        std::string_view line = text.substr(pos, eol - pos);
        pos = eol + 1;
        ++lineNo;
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
            line.remove_suffix(1);
        if (line.empty())
            continue;
        lastLine = lineNo;
        if (ended)
            return failure(lineNo, tr("data after the end-of-file record of line %1; the file is damaged").arg(endLine));
        if (line.front() != ':')
            return failure(lineNo, tr("a record must start with ':'; this is not an Intel HEX file"));
        const std::string_view digits = line.substr(1);
        if (digits.size() % 2 != 0 || digits.size() < 10)
            return failure(lineNo, tr("the record is too short or has an odd number of hex digits; the file is truncated "
                                      "or damaged"));
        rec.resize(digits.size() / 2);
        for (size_t i = 0; i < rec.size(); ++i) {
            const int hi = hexNibble(digits[2 * i]), lo = hexNibble(digits[2 * i + 1]);
            if (hi < 0 || lo < 0)
                return failure(lineNo, tr("'%1' is not a hex digit").arg(QChar(hi < 0 ? digits[2 * i] : digits[2 * i + 1])));
            rec[i] = uint8_t(hi << 4 | lo);
        }
        const size_t len = rec[0];
        if (rec.size() != len + 5)
            return failure(lineNo, tr("the record says %1 data bytes but holds %2; the file is truncated or damaged")
                                       .arg(len)
                                       .arg(int(rec.size()) - 5));
        uint8_t sum = 0;
        for (uint8_t b : rec)
            sum = uint8_t(sum + b);
        if (sum != 0) {
            uint8_t expected = 0;
            for (size_t i = 0; i + 1 < rec.size(); ++i)
                expected = uint8_t(expected + rec[i]);
            expected = uint8_t(-expected);
            return failure(lineNo, tr("checksum error (record says %1, bytes give %2); the file is damaged")
                                       .arg(rec.back(), 2, 16, QLatin1Char('0'))
                                       .arg(expected, 2, 16, QLatin1Char('0')));
        }
        const uint32_t offset = uint32_t(rec[1]) << 8 | rec[2];
        const uint8_t type = rec[3];
        const uint8_t *data = rec.data() + 4;
        auto be = [&](size_t n) {
            uint32_t v = 0;
            for (size_t i = 0; i < n; ++i)
                v = v << 8 | data[i];
            return v;
        };
        switch (type) {
        case 0x00: {
            if (len == 0)
                break;
            const uint64_t at = base + offset;
            if (at + len > (uint64_t(1) << 32))
                return failure(lineNo, tr("the record runs past the 4 GiB address space"));
            pieces.push_back(Piece{at, bytes.size(), len, lineNo});
            bytes.insert(bytes.end(), data, data + len);
            break;
        }
        case 0x01:
            if (len != 0 || offset != 0)
                return failure(lineNo, tr("an end-of-file record must have no data and address 0"));
            ended = true;
            endLine = lineNo;
            break;
        case 0x02:
        case 0x04:
            if (len != 2 || offset != 0)
                return failure(lineNo, tr("an extended address record must have 2 data bytes and address 0"));
            base = type == 0x02 ? uint64_t(be(2)) << 4 : uint64_t(be(2)) << 16;
            break;
        case 0x03:
        case 0x05:
            if (len != 4 || offset != 0)
                return failure(lineNo, tr("a start address record must have 4 data bytes and address 0"));
            entry = type == 0x05 ? be(4) : ((be(4) >> 16) << 4) + (be(4) & 0xFFFFu);
            break;
        default:
            return failure(lineNo, tr("unknown record type %1 (Intel HEX has types 00 to 05)")
                                       .arg(type, 2, 16, QLatin1Char('0')));
        }
    }
    if (lineNo == 0 || lastLine == 0)
        return failure(0, tr("the file is empty; choose the firmware's .hex file"));
    if (!ended)
        return failure(lastLine, tr("the file ends without an end-of-file record (type 01); it is truncated, download "
                                    "it again"));
    if (pieces.empty())
        return failure(endLine, tr("the file holds no data records"));

    std::sort(pieces.begin(), pieces.end(), [](const Piece &a, const Piece &b) { return a.address < b.address; });
    for (size_t i = 1; i < pieces.size(); ++i) {
        const Piece &a = pieces[i - 1], &b = pieces[i];
        if (b.address < a.address + a.length)
            return failure(std::max(a.line, b.line), tr("the record writes %1, which line %2 already wrote (overlapping "
                                                        "records); the file is damaged")
                                                         .arg(hex32(b.address))
                                                         .arg(std::min(a.line, b.line)));
    }
    const uint64_t start = pieces.front().address;
    const uint64_t end = pieces.back().address + pieces.back().length;
    if (end - start > limits.maxImageBytes)
        return failure(pieces.back().line, tr("the image spans %1 bytes from %2, more than %3; the addresses are wrong "
                                              "or this is not a firmware for this device")
                                               .arg(qulonglong(end - start))
                                               .arg(hex32(start))
                                               .arg(qulonglong(limits.maxImageBytes)));
    FirmwareImage img;
    img.startAddress = uint32_t(start);
    img.entryPoint = entry;
    img.data.assign(size_t(end - start), 0xFF);
    for (const Piece &p : pieces)
        std::copy_n(bytes.begin() + long(p.offset), p.length, img.data.begin() + long(p.address - start));
    qCDebug(lcIhex) << "loaded" << img.data.size() << "bytes at" << hex32(start) << "from" << pieces.size() << "records";
    LoadResult r;
    r.image = std::move(img);
    return r;
}

LoadResult IntelHexLoader::fromBinary(std::string_view bytes, uint32_t startAddress, const Limits &limits)
{
    if (bytes.empty())
        return failure(0, tr("the file is empty; choose the firmware's .bin file"));
    if (bytes.size() > limits.maxImageBytes)
        return failure(0, tr("the file is %1 bytes, more than %2; this is not a firmware for this device")
                              .arg(qulonglong(bytes.size()))
                              .arg(qulonglong(limits.maxImageBytes)));
    if (uint64_t(startAddress) + bytes.size() > (uint64_t(1) << 32))
        return failure(0, tr("the image runs past the 4 GiB address space; check the start address"));
    FirmwareImage img;
    img.startAddress = startAddress;
    img.data.assign(bytes.begin(), bytes.end());
    LoadResult r;
    r.image = std::move(img);
    return r;
}

LoadResult IntelHexLoader::loadFile(const QString &path, std::optional<uint32_t> binStart, const Limits &limits)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return failure(0, tr("cannot read %1: %2").arg(path, f.errorString()));
    const bool bin = path.endsWith(QLatin1String(".bin"), Qt::CaseInsensitive);
    const uint64_t cap = bin ? limits.maxImageBytes : limits.maxFileBytes;
    if (uint64_t(f.size()) > cap)
        return failure(0, tr("%1 is %2 bytes, more than the %3 bytes a firmware file may have")
                              .arg(path)
                              .arg(qulonglong(f.size()))
                              .arg(qulonglong(cap)));
    const QByteArray content = f.read(qint64(cap) + 1);
    const std::string_view view(content.constData(), size_t(content.size()));
    if (bin) {
        if (!binStart)
            return failure(0, tr("a .bin file has no address: give its start address (e.g. 0x8000)"));
        return fromBinary(view, *binStart, limits);
    }
    return parseHex(view, limits);
}

} // namespace imudesk::protocol::ihex
