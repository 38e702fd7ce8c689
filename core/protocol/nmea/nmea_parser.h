#pragma once
// NMEA 0183 sentences that HiPNUC modules emit or accept: GGA, RMC and HiPNUC's own SXT;
// the heading sentences HDT (true) and HDM (magnetic), as a compass such as the HEC495 sends
// them (decoded); anything else with a valid checksum is kept with its fields, undecoded.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace imudesk::protocol::nmea {

enum class NmeaError { None, NoDollar, NoChecksum, BadChecksumDigits, ChecksumMismatch, TooLong, NonPrintable, BadField };

struct UtcTime {
    int hour = 0, minute = 0;
    double second = 0;
};
struct UtcDate {
    int year = 0, month = 0, day = 0;
};

struct Gga {
    std::optional<UtcTime> time;
    std::optional<double> latitudeDeg;  // south negative
    std::optional<double> longitudeDeg; // west negative
    int quality = 0;                    // 0 none, 1 single, 2 DGNSS, 4 RTK fixed, 5 RTK float
    int satellites = 0;
    std::optional<double> hdop;
    std::optional<double> altitudeM;    // above MSL
    std::optional<double> geoidSeparationM;
    std::optional<double> diffAgeS;
    std::string stationId;
};

struct Rmc {
    std::optional<UtcTime> time;
    bool valid = false;                 // status A
    std::optional<double> latitudeDeg;
    std::optional<double> longitudeDeg;
    std::optional<double> speedKnots;
    std::optional<double> courseDeg;
    std::optional<UtcDate> date;
    std::optional<double> magVarDeg;    // west negative
    char mode = 0;                      // A, D, R, F, E, N or 0
    double speedMs() const { return speedKnots.value_or(0) * 0.514444; }
};

// HiPNUC's $GPSXT / $GNSXT (21 fields; layout from the vendor's SDK decoder): INS position,
// attitude and velocity in one line.
struct Sxt {
    std::optional<UtcDate> date;        // field 0: yyyymmddhhmmss.ss
    std::optional<UtcTime> time;
    std::optional<double> longitudeDeg; // decimal degrees, west negative
    std::optional<double> latitudeDeg;
    std::optional<double> altitudeM;
    std::optional<double> headingDeg;
    std::optional<double> pitchDeg;
    std::optional<double> trackDeg;     // course over ground
    std::optional<double> speedMs;
    std::optional<double> rollDeg;
    int quality = 0;                    // GGA style
    int headingQuality = 0;
    int satellites = 0;
    int headingSatellites = 0;
    std::optional<double> gyrDps[3];
    std::optional<double> velEnuMs[3];
    int insStatus = 0;
    int antennaStatus = 0;
};
inline constexpr size_t kSxtFields = 21;

// $--HDT,x.x,T (true heading) and $--HDM,x.x,M (magnetic heading), degrees 0..360.
struct Heading {
    double headingDeg = 0;
    bool trueNorth = true;
};

struct Sentence {
    std::string talker;    // "GP", "GN", ...
    std::string type;      // "GGA", "RMC", ...
    std::vector<std::string> fields; // after the address, before '*'
    std::optional<Gga> gga;
    std::optional<Rmc> rmc;
    std::optional<Sxt> sxt;
    std::optional<Heading> heading; // HDT, HDM
};

struct ParseResult {
    std::optional<Sentence> sentence;
    NmeaError error = NmeaError::None;
    bool ok() const { return error == NmeaError::None; }
};

inline constexpr size_t kMaxSentenceLength = 160; // the standard's 82; HiPNUC $GPSXT has 21 fields

// Parses one sentence, "$...*hh" with or without the trailing CR/LF.
ParseResult parseSentence(std::string_view line);
const char *errorText(NmeaError e);

// XOR of the bytes between '$' and '*'.
unsigned checksum(std::string_view body);
// Builds "$<body>*HH\r\n".
std::string buildSentence(std::string_view body);

} // namespace imudesk::protocol::nmea
