// libFuzzer target: ASCII command replies and device identity.
//
// The input is split into lines at LF (CR and other bytes stay in the line). The
// lines are fed to ReplyCollectors for "LOG VERSION" (a new collector starts after
// each complete reply, as in a session), and each line also goes through
// classifyLine, keyValuePairs and FirmwareVersion::parse. Each complete reply's
// KEY=VALUE map is turned into a DeviceIdentity.
#include "model/device_identity.h"
#include "protocol/hipnuc/ascii_reply.h"

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#define FUZZ_CHECK(cond)                                                                               \
    do {                                                                                               \
        if (!(cond)) {                                                                                 \
            std::fprintf(stderr, "fuzz_ascii_reply: invariant failed: %s (line %d)\n", #cond, __LINE__); \
            __builtin_trap();                                                                          \
        }                                                                                              \
    } while (0)

using namespace imudesk::model;
using namespace imudesk::protocol::hipnuc;

namespace {

const std::string kCommand = "LOG VERSION";

bool isSpace(char c)
{
    return std::isspace(uint8_t(c)) != 0;
}

bool trimmed(const std::string &s)
{
    return s.empty() || (!isSpace(s.front()) && !isSpace(s.back()));
}

void checkVersion(const std::string &text)
{
    const auto v = FirmwareVersion::parse(text);
    if (!v)
        return;
    FUZZ_CHECK(v->major >= 0 && v->major <= 999 && v->minor >= 0 && v->minor <= 999 && v->patch >= 0 && v->patch <= 999);
    const auto back = FirmwareVersion::parse(v->toString());
    FUZZ_CHECK(back.has_value());
    FUZZ_CHECK(*back == *v);
    FUZZ_CHECK(back->toString() == v->toString());
}

void checkIdentity(const AsciiReply &reply)
{
    for (const auto &[key, value] : reply.values) {
        FUZZ_CHECK(!key.empty());
        FUZZ_CHECK(key.find('=') == std::string::npos);
        FUZZ_CHECK(trimmed(key) && trimmed(value));
        checkVersion(value);
    }
    const DeviceIdentity id = DeviceIdentity::fromKeyValues(reply.values);
    auto value = [&](const char *k) {
        const auto it = reply.values.find(k);
        return it == reply.values.end() ? std::string() : it->second;
    };
    FUZZ_CHECK(id.productName == value("PNAME"));
    FUZZ_CHECK(id.build == value("BUILD"));
    FUZZ_CHECK(id.serial == (reply.values.count("UUID") ? value("UUID") : value("SN")));
    const std::string fw = reply.values.count("APP_VER") ? value("APP_VER") : value("SW_VERSION");
    FUZZ_CHECK(id.firmware == FirmwareVersion::parse(fw));
    if (id.firmware)
        checkVersion(id.firmware->toString());
    if (id.bootloader)
        checkVersion(id.bootloader->toString());
    FUZZ_CHECK(id.usable() == (!id.productName.empty() && (id.firmware.has_value() || !id.serial.empty())));
    FUZZ_CHECK(familyName(id.family()) != nullptr);
    const bool v171 = id.firmware && *id.firmware >= FirmwareVersion{1, 7, 1};
    FUZZ_CHECK((id.edition() == ManualEdition::V171) == v171);
    FUZZ_CHECK(id.hasMainStatus() == (id.firmware && *id.firmware >= FirmwareVersion{1, 7, 0}));
    (void)id.hasMagnetometer();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const std::string_view in(reinterpret_cast<const char *>(data), size);
    std::vector<std::string_view> lines;
    for (size_t start = 0; start <= in.size();) {
        const size_t lf = in.find('\n', start);
        if (lf == std::string_view::npos) {
            if (start < in.size())
                lines.push_back(in.substr(start));
            break;
        }
        lines.push_back(in.substr(start, lf - start));
        start = lf + 1;
    }

    ReplyCollector collector(kCommand);
    for (const std::string_view line : lines) {
        const LineKind kind = classifyLine(line);
        FUZZ_CHECK(classifyLine(std::string(line) + "\r") == kind); // trailing CR is whitespace

        checkVersion(std::string(line));
        // The tolerant reading of KEY=VALUE lines: keys without separators or blanks, values
        // trimmed; a pair needs a separator in the line.
        for (const auto &[k, v] : keyValuePairs(line)) {
            FUZZ_CHECK(!k.empty() && k.find('=') == std::string::npos && k.find(' ') == std::string::npos);
            FUZZ_CHECK(trimmed(k) && trimmed(v));
            FUZZ_CHECK(line.find('=') != std::string_view::npos || line.find(':') != std::string_view::npos);
            checkVersion(v);
        }

        const size_t before = collector.reply().lines.size();
        const bool done = collector.addLine(line);
        const AsciiReply &r = collector.reply();
        FUZZ_CHECK(done == collector.complete());
        FUZZ_CHECK(r.lines.size() <= before + 1);
        if (done) {
            FUZZ_CHECK(r.lines.size() == before);
            FUZZ_CHECK(r.status == AsciiReply::Status::Ok || r.status == AsciiReply::Status::Refused);
            FUZZ_CHECK((r.status == AsciiReply::Status::Ok) == (kind == LineKind::Ok));
            if (r.status == AsciiReply::Status::Refused) {
                FUZZ_CHECK(kind == LineKind::Error);
                FUZZ_CHECK(!r.errorLine.empty() && trimmed(r.errorLine));
            }
            // A complete reply ignores further lines.
            FUZZ_CHECK(collector.addLine("OK"));
            FUZZ_CHECK(collector.addLine("PNAME=X"));
            FUZZ_CHECK(collector.reply().lines.size() == before);
            FUZZ_CHECK(outcomeName(r.status) != nullptr);
            checkIdentity(r);
            collector = ReplyCollector(kCommand);
        } else {
            FUZZ_CHECK(r.status == AsciiReply::Status::Pending);
            if (r.lines.size() == before + 1) {
                FUZZ_CHECK(kind == LineKind::Info);
                FUZZ_CHECK(!r.lines.back().empty() && trimmed(r.lines.back()));
            }
        }
    }
    checkIdentity(collector.reply()); // an unfinished reply (timeout path) still yields an identity
    const AsciiReply last = collector.take();
    FUZZ_CHECK(last.command == kCommand || last.command.empty());
    return 0;
}
