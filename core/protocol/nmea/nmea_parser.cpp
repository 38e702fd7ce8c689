#include "nmea_parser.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace imudesk::protocol::nmea {
namespace {

int hexDigit(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

std::optional<double> toDouble(const std::string &s)
{
    if (s.empty())
        return std::nullopt;
    double v = 0;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

std::optional<int> toInt(const std::string &s)
{
    if (s.empty())
        return std::nullopt;
    int v = 0;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    if (r.ec != std::errc() || r.ptr != s.data() + s.size())
        return std::nullopt;
    return v;
}

bool allDigits(const std::string &s, size_t from, size_t to)
{
    for (size_t i = from; i < to; ++i)
        if (s[i] < '0' || s[i] > '9')
            return false;
    return true;
}

// hhmmss(.sss)
std::optional<UtcTime> parseTime(const std::string &s, bool &bad)
{
    if (s.empty())
        return std::nullopt;
    if (s.size() < 6 || !allDigits(s, 0, 6)) {
        bad = true;
        return std::nullopt;
    }
    UtcTime t;
    t.hour = (s[0] - '0') * 10 + (s[1] - '0');
    t.minute = (s[2] - '0') * 10 + (s[3] - '0');
    const auto sec = toDouble(s.substr(4));
    if (!sec || t.hour > 23 || t.minute > 59 || *sec >= 61.0) {
        bad = true;
        return std::nullopt;
    }
    t.second = *sec;
    return t;
}

// ddmmyy; two-digit years below 80 are 20yy.
std::optional<UtcDate> parseDate(const std::string &s, bool &bad)
{
    if (s.empty())
        return std::nullopt;
    if (s.size() != 6 || !allDigits(s, 0, 6)) {
        bad = true;
        return std::nullopt;
    }
    UtcDate d;
    d.day = (s[0] - '0') * 10 + (s[1] - '0');
    d.month = (s[2] - '0') * 10 + (s[3] - '0');
    const int yy = (s[4] - '0') * 10 + (s[5] - '0');
    d.year = yy < 80 ? 2000 + yy : 1900 + yy;
    if (d.day < 1 || d.day > 31 || d.month < 1 || d.month > 12) {
        bad = true;
        return std::nullopt;
    }
    return d;
}

// (d)ddmm.mmmm + hemisphere -> signed decimal degrees.
std::optional<double> parseLatLon(const std::string &v, const std::string &hemi, int degDigits, bool &bad)
{
    if (v.empty() && hemi.empty())
        return std::nullopt;
    const auto raw = toDouble(v);
    if (!raw || v.size() < size_t(degDigits + 2) || hemi.size() != 1) {
        bad = true;
        return std::nullopt;
    }
    const double deg = std::floor(*raw / 100.0);
    const double min = *raw - deg * 100.0;
    double out = deg + min / 60.0;
    // The sign belongs to the hemisphere letter; the value itself is never negative.
    if (*raw < 0 || min >= 60.0 || out > (degDigits == 2 ? 90.0 : 180.0)) {
        bad = true;
        return std::nullopt;
    }
    const char h = hemi[0];
    if (h == 'S' || h == 'W')
        out = -out;
    else if (h != 'N' && h != 'E') {
        bad = true;
        return std::nullopt;
    }
    return out;
}

const std::string &field(const std::vector<std::string> &f, size_t i)
{
    static const std::string empty;
    return i < f.size() ? f[i] : empty;
}

} // namespace

unsigned checksum(std::string_view body)
{
    unsigned c = 0;
    for (char ch : body)
        c ^= uint8_t(ch);
    return c;
}

std::string buildSentence(std::string_view body)
{
    char tail[8];
    std::snprintf(tail, sizeof tail, "*%02X\r\n", checksum(body));
    std::string s = "$";
    s.append(body);
    s.append(tail);
    return s;
}

const char *errorText(NmeaError e)
{
    switch (e) {
    case NmeaError::None: return "ok";
    case NmeaError::NoDollar: return "sentence does not start with '$'";
    case NmeaError::NoChecksum: return "no '*hh' checksum";
    case NmeaError::BadChecksumDigits: return "checksum is not two hex digits";
    case NmeaError::ChecksumMismatch: return "checksum mismatch";
    case NmeaError::TooLong: return "sentence too long";
    case NmeaError::NonPrintable: return "non-printable byte in sentence";
    case NmeaError::BadField: return "malformed field";
    }
    return "?";
}

ParseResult parseSentence(std::string_view line)
{
    ParseResult res;
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r'))
        line.remove_suffix(1);
    if (line.empty() || line.front() != '$') {
        res.error = NmeaError::NoDollar;
        return res;
    }
    if (line.size() > kMaxSentenceLength) {
        res.error = NmeaError::TooLong;
        return res;
    }
    for (char c : line)
        if (uint8_t(c) < 0x20 || uint8_t(c) > 0x7E) {
            res.error = NmeaError::NonPrintable;
            return res;
        }
    const size_t star = line.rfind('*');
    if (star == std::string_view::npos || star < 1) {
        res.error = NmeaError::NoChecksum;
        return res;
    }
    if (line.size() != star + 3) {
        res.error = NmeaError::BadChecksumDigits;
        return res;
    }
    const int h = hexDigit(line[star + 1]);
    const int l = hexDigit(line[star + 2]);
    if (h < 0 || l < 0) {
        res.error = NmeaError::BadChecksumDigits;
        return res;
    }
    const std::string_view body = line.substr(1, star - 1);
    if (checksum(body) != unsigned(h * 16 + l)) {
        res.error = NmeaError::ChecksumMismatch;
        return res;
    }

    Sentence s;
    std::vector<std::string> parts;
    size_t start = 0;
    for (;;) {
        const size_t comma = body.find(',', start);
        parts.emplace_back(body.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
        if (comma == std::string_view::npos)
            break;
        start = comma + 1;
    }
    const std::string &addr = parts.front();
    if (addr.size() == 5) {
        s.talker = addr.substr(0, 2);
        s.type = addr.substr(2);
    } else if (addr.size() > 3) { // proprietary such as "GPSXT" / "KSXT"
        s.talker = addr.substr(0, addr.size() - 3);
        s.type = addr.substr(addr.size() - 3);
    } else {
        res.error = NmeaError::BadField;
        return res;
    }
    s.fields.assign(parts.begin() + 1, parts.end());
    const auto &f = s.fields;
    bool bad = false;
    if (s.type == "GGA") {
        Gga g;
        g.time = parseTime(field(f, 0), bad);
        g.latitudeDeg = parseLatLon(field(f, 1), field(f, 2), 2, bad);
        g.longitudeDeg = parseLatLon(field(f, 3), field(f, 4), 3, bad);
        g.quality = toInt(field(f, 5)).value_or(0);
        g.satellites = toInt(field(f, 6)).value_or(0);
        g.hdop = toDouble(field(f, 7));
        g.altitudeM = toDouble(field(f, 8));
        g.geoidSeparationM = toDouble(field(f, 10));
        g.diffAgeS = toDouble(field(f, 12));
        g.stationId = field(f, 13);
        s.gga = g;
    } else if (s.type == "RMC") {
        Rmc r;
        r.time = parseTime(field(f, 0), bad);
        r.valid = field(f, 1) == "A";
        if (!field(f, 1).empty() && field(f, 1) != "A" && field(f, 1) != "V")
            bad = true;
        r.latitudeDeg = parseLatLon(field(f, 2), field(f, 3), 2, bad);
        r.longitudeDeg = parseLatLon(field(f, 4), field(f, 5), 3, bad);
        r.speedKnots = toDouble(field(f, 6));
        r.courseDeg = toDouble(field(f, 7));
        r.date = parseDate(field(f, 8), bad);
        if (auto mv = toDouble(field(f, 9)))
            r.magVarDeg = field(f, 10) == "W" ? -*mv : *mv;
        if (field(f, 11).size() == 1)
            r.mode = field(f, 11)[0];
        s.rmc = r;
    } else if (s.type == "SXT" && f.size() >= kSxtFields) {
        Sxt x;
        const std::string &when = field(f, 0); // yyyymmddhhmmss.ss
        if (!when.empty()) {
            if (when.size() < 14 || !allDigits(when, 0, 8)) {
                bad = true;
            } else {
                x.date = parseDate(when.substr(6, 2) + when.substr(4, 2) + when.substr(2, 2), bad);
                if (x.date)
                    x.date->year = std::stoi(when.substr(0, 4));
                x.time = parseTime(when.substr(8), bad);
            }
        }
        std::optional<double> *numbers[] = {&x.longitudeDeg, &x.latitudeDeg, &x.altitudeM, &x.headingDeg,
                                             &x.pitchDeg,     &x.trackDeg,    &x.speedMs,   &x.rollDeg};
        for (size_t i = 0; i < std::size(numbers); ++i) {
            *numbers[i] = toDouble(field(f, i + 1));
            bad = bad || (!field(f, i + 1).empty() && !*numbers[i]);
        }
        if ((x.latitudeDeg && std::abs(*x.latitudeDeg) > 90) || (x.longitudeDeg && std::abs(*x.longitudeDeg) > 180))
            bad = true;
        x.quality = toInt(field(f, 9)).value_or(0);
        x.headingQuality = toInt(field(f, 10)).value_or(0);
        x.satellites = toInt(field(f, 11)).value_or(0);
        x.headingSatellites = toInt(field(f, 12)).value_or(0);
        for (size_t i = 0; i < 3; ++i) {
            x.gyrDps[i] = toDouble(field(f, 13 + i));
            x.velEnuMs[i] = toDouble(field(f, 16 + i));
        }
        x.insStatus = toInt(field(f, 19)).value_or(0);
        x.antennaStatus = toInt(field(f, 20)).value_or(0);
        s.sxt = x;
    } else if (s.type == "HDT" || s.type == "HDM") {
        // One number and its reference letter; an empty number is "no heading" (no sample).
        const bool trueNorth = s.type == "HDT";
        const std::string &unit = field(f, 1);
        if (!unit.empty() && unit != (trueNorth ? "T" : "M"))
            bad = true;
        if (!field(f, 0).empty()) {
            const auto v = toDouble(field(f, 0));
            if (!v || *v < 0 || *v > 360)
                bad = true;
            else
                s.heading = Heading{*v, trueNorth};
        }
    }
    if (bad) {
        res.error = NmeaError::BadField;
        return res;
    }
    res.sentence = std::move(s);
    return res;
}

} // namespace imudesk::protocol::nmea
