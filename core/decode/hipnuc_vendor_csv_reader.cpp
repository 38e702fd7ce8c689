#include "hipnuc_vendor_csv_reader.h"

#include <QFile>

#include <array>
#include <charconv>
#include <map>
#include <string>
#include <cmath>

namespace imudesk::decode {

namespace {

constexpr double kMaxPcCounterMs = 100.0 * 365.25 * 86400e3; // a century, in ms

// Columns the importer reads, by the vendor's header names.
enum Column {
    PcCounter, SysTime, AccX, AccY, AccZ, GyrX, GyrY, GyrZ, MagX, MagY, MagZ, Roll, Pitch, Yaw,
    QuatW, QuatX, QuatY, QuatZ, Temperature, Pressure, ColumnCount
};
constexpr std::array<const char *, ColumnCount> kNames = {
    "pc_counter", "sys_time", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z", "mag_x", "mag_y",
    "mag_z", "roll", "pitch", "yaw", "quat_w", "quat_x", "quat_y", "quat_z", "temperature", "pressure"};

std::vector<std::string_view> split(std::string_view line)
{
    std::vector<std::string_view> out;
    size_t start = 0;
    for (;;) {
        const size_t comma = line.find(',', start);
        out.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
        if (comma == std::string_view::npos)
            return out;
        start = comma + 1;
    }
}

std::string_view trimmed(std::string_view s)
{
    while (!s.empty() && (s.back() == '\r' || s.back() == ' '))
        s.remove_suffix(1);
    while (!s.empty() && s.front() == ' ')
        s.remove_prefix(1);
    return s;
}

bool parseFloat(std::string_view s, float &v)
{
    s = trimmed(s);
    if (!s.empty() && s.front() == '+')
        s.remove_prefix(1);
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    return !s.empty() && r.ec == std::errc() && r.ptr == s.data() + s.size();
}

bool parseDouble(std::string_view s, double &v)
{
    s = trimmed(s);
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    return !s.empty() && r.ec == std::errc() && r.ptr == s.data() + s.size();
}

} // namespace

bool VendorCsvImporter::looksLikeVendorCsv(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return false;
    return f.readLine(kMaxLine).startsWith("HI91,");
}

VendorCsvImporter::Result VendorCsvImporter::read(const QString &path, const SampleFn &onSample)
{
    return readRows(path, [&onSample](const model::Sample &s, const Row &) {
        if (onSample)
            onSample(s);
    });
}

VendorCsvImporter::Result VendorCsvImporter::read(QIODevice &device, const SampleFn &onSample)
{
    return readRows(device, [&onSample](const model::Sample &s, const Row &) {
        if (onSample)
            onSample(s);
    });
}

VendorCsvImporter::Result VendorCsvImporter::readRows(const QString &path, const RowFn &onRow)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        Result r;
        r.error = tr("Cannot open %1: %2").arg(path, f.errorString());
        return r;
    }
    Result r = readRows(f, onRow);
    if (!r.ok)
        r.error = tr("%1: %2").arg(path, r.error);
    return r;
}

VendorCsvImporter::Result VendorCsvImporter::readRows(QIODevice &device, const RowFn &onRow)
{
    Result r;
    std::array<int, ColumnCount> index{};
    index.fill(-1);
    size_t columns = 0;
    std::vector<std::string> names;
    std::vector<std::string_view> cells;
    uint64_t lineNo = 0;
    bool haveHeader = false;
    auto bad = [&](const QString &why) {
        ++r.badLines;
        if (r.errors.size() < kMaxReportedErrors)
            r.errors.push_back({lineNo, why});
    };
    std::vector<char> buf(kMaxLine + 2);
    while (!device.atEnd()) {
        const qint64 n = device.readLine(buf.data(), qint64(buf.size()));
        if (n <= 0)
            break;
        ++lineNo;
        std::string_view line(buf.data(), size_t(n));
        if (line.back() != '\n' && !device.atEnd()) {
            // Longer than any vendor row: report it and skip the rest of it.
            bad(tr("line %1 is longer than %2 characters").arg(lineNo).arg(kMaxLine));
            char c = 0;
            while (device.getChar(&c) && c != '\n') {
            }
            continue;
        }
        while (!line.empty() && (line.back() == '\n' || line.back() == '\r'))
            line.remove_suffix(1);
        if (trimmed(line).empty())
            continue;
        const auto fields = split(line);
        if (!haveHeader) {
            if (trimmed(fields[0]) != "HI91") {
                r.error = tr("line %1 is not the vendor's HI91 CSV header (it starts with \"%2\")")
                              .arg(lineNo)
                              .arg(QString::fromUtf8(line.substr(0, 40).data(), qsizetype(std::min<size_t>(line.size(), 40))));
                return r;
            }
            names.clear();
            for (const auto &f : fields)
                names.emplace_back(trimmed(f));
            for (size_t i = 1; i < fields.size(); ++i)
                for (size_t c = 0; c < kNames.size(); ++c)
                    if (trimmed(fields[i]) == kNames[c])
                        index[c] = int(i);
            for (size_t c = SysTime; c < kNames.size(); ++c) {
                if (index[c] < 0) {
                    r.error = tr("the header has no %1 column").arg(QLatin1String(kNames[c]));
                    return r;
                }
            }
            columns = fields.size();
            haveHeader = true;
            continue;
        }
        if (trimmed(fields[0]) != "HI91") {
            bad(tr("line %1: the first column is \"%2\", not HI91")
                    .arg(lineNo)
                    .arg(QString::fromUtf8(fields[0].data(), qsizetype(std::min<size_t>(fields[0].size(), 20)))));
            continue;
        }
        if (fields.size() != columns) {
            bad(tr("line %1 has %2 columns, the header %3").arg(lineNo).arg(fields.size()).arg(columns));
            continue;
        }
        std::array<float, ColumnCount> v{};
        double sysTime = 0, pc = 0;
        int badColumn = -1;
        for (size_t c = 0; c < kNames.size() && badColumn < 0; ++c) {
            if (index[c] < 0)
                continue;
            const std::string_view f = fields[size_t(index[c])];
            const bool ok = c == SysTime ? parseDouble(f, sysTime) : c == PcCounter ? parseDouble(f, pc) : parseFloat(f, v[c]);
            if (!ok)
                badColumn = int(c);
        }
        if (badColumn >= 0) {
            bad(tr("line %1: %2 is not a number").arg(lineNo).arg(QLatin1String(kNames[size_t(badColumn)])));
            continue;
        }
        // The PC counter is in ms; a value beyond a century (or not finite) is not one.
        if (!(std::fabs(pc) < kMaxPcCounterMs)) {
            bad(tr("line %1: pc_counter %2 is not a time in ms").arg(lineNo).arg(pc));
            continue;
        }
        model::Sample s;
        s.source = "HI91";
        s.fields = model::FieldAcc | model::FieldGyr | model::FieldMag | model::FieldEuler | model::FieldQuat
            | model::FieldPressure | model::FieldTemperature | model::FieldDeviceTime;
        s.hostTimeNs = std::llround(pc * 1e6); // to the ns: pc_counter reads back as written
        s.deviceTimeMs = sysTime;
        s.acc = {v[AccX], v[AccY], v[AccZ]};
        s.gyr = {v[GyrX], v[GyrY], v[GyrZ]};
        s.mag = {v[MagX], v[MagY], v[MagZ]};
        s.roll = v[Roll];
        s.pitch = v[Pitch];
        s.yaw = v[Yaw];
        s.quat = {v[QuatW], v[QuatX], v[QuatY], v[QuatZ]};
        s.temperatureC = v[Temperature];
        s.pressurePa = v[Pressure];
        ++r.samples;
        if (onRow) {
            cells.clear();
            for (const auto &f : fields)
                cells.push_back(trimmed(f));
            onRow(s, Row{names, cells});
        }
    }
    if (!haveHeader) {
        r.error = tr("the file is empty: no HI91 CSV header");
        return r;
    }
    r.ok = true;
    return r;
}

} // namespace imudesk::decode
