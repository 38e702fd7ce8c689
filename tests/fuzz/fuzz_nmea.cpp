// libFuzzer target: NMEA sentence parser.
//
// The input is one line. Whatever it is, parsing must not crash and must not
// depend on a trailing CR/LF. When it parses, the body rebuilt from the parsed
// address and fields must be the original body, and buildSentence() of that body
// must parse again to the same sentence with the same checksum.
#include "protocol/nmea/nmea_parser.h"

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#define FUZZ_CHECK(cond)                                                                        \
    do {                                                                                        \
        if (!(cond)) {                                                                          \
            std::fprintf(stderr, "fuzz_nmea: invariant failed: %s (line %d)\n", #cond, __LINE__); \
            __builtin_trap();                                                                   \
        }                                                                                       \
    } while (0)

using namespace imudesk::protocol::nmea;

namespace {

int hexValue(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

bool sameSentence(const Sentence &a, const Sentence &b)
{
    return a.talker == b.talker && a.type == b.type && a.fields == b.fields && a.gga.has_value() == b.gga.has_value()
        && a.rmc.has_value() == b.rmc.has_value();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const std::string_view in(reinterpret_cast<const char *>(data), size);
    const ParseResult r = parseSentence(in);
    FUZZ_CHECK(errorText(r.error) != nullptr);
    FUZZ_CHECK(r.ok() == r.sentence.has_value());

    // A trailing CR/LF never changes the outcome.
    const std::string withEol = std::string(in) + "\r\n";
    const ParseResult r2 = parseSentence(withEol);
    FUZZ_CHECK(r2.error == r.error);
    FUZZ_CHECK(r2.ok() == r.ok());

    if (!r.ok())
        return 0;
    const Sentence &s = *r.sentence;

    // The line as the parser saw it: CR/LF stripped, "$" body "*" hh.
    std::string_view line = in;
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r'))
        line.remove_suffix(1);
    FUZZ_CHECK(line.size() >= 4 && line.front() == '$' && line[line.size() - 3] == '*');
    FUZZ_CHECK(line.size() <= kMaxSentenceLength);
    const std::string_view body = line.substr(1, line.size() - 4);
    const unsigned sent = unsigned(hexValue(line[line.size() - 2]) * 16 + hexValue(line[line.size() - 1]));
    FUZZ_CHECK(checksum(body) == sent);

    // Address and fields give back the body.
    std::string rebuilt = s.talker + s.type;
    for (const auto &f : s.fields) {
        rebuilt += ',';
        rebuilt += f;
    }
    FUZZ_CHECK(rebuilt == body);
    FUZZ_CHECK(s.type.size() == 3);
    FUZZ_CHECK(s.gga.has_value() == (s.type == "GGA"));
    FUZZ_CHECK(s.rmc.has_value() == (s.type == "RMC"));

    // buildSentence() of the body verifies again, to the same sentence and checksum.
    const std::string built = buildSentence(rebuilt);
    FUZZ_CHECK(built.size() == line.size() + 2);
    FUZZ_CHECK(built.compare(built.size() - 2, 2, "\r\n") == 0);
    char hex[3];
    std::snprintf(hex, sizeof hex, "%02X", sent);
    FUZZ_CHECK(built.compare(built.size() - 4, 2, hex) == 0);
    const ParseResult again = parseSentence(built);
    FUZZ_CHECK(again.ok());
    FUZZ_CHECK(sameSentence(*again.sentence, s));

    // Decoded values stay in their documented ranges.
    auto timeOk = [](const UtcTime &t) { return t.hour >= 0 && t.hour <= 23 && t.minute >= 0 && t.minute <= 59 && t.second >= 0 && t.second < 61; };
    if (s.gga) {
        if (s.gga->time) FUZZ_CHECK(timeOk(*s.gga->time));
    }
    if (s.rmc) {
        if (s.rmc->time) FUZZ_CHECK(timeOk(*s.rmc->time));
        if (s.rmc->date) {
            FUZZ_CHECK(s.rmc->date->month >= 1 && s.rmc->date->month <= 12);
            FUZZ_CHECK(s.rmc->date->day >= 1 && s.rmc->date->day <= 31);
            FUZZ_CHECK(s.rmc->date->year >= 1980 && s.rmc->date->year <= 2079);
        }
        (void)s.rmc->speedMs();
    }
    return 0;
}
