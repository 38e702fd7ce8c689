// SimFaults in text form, as `imudesk-cli simulate --pty --faults LIST` takes them:
// parseSimFaults and simFaultsText (declared in hipnuc_simulator.h).
#include "hipnuc_simulator.h"

#include <cctype>
#include <charconv>
#include <cmath>

namespace imudesk::sim {

namespace {

constexpr const char *kAccepted =
    "noisy-gyro, noisy-gyro=F, mounting=R/P/Y, wrong-mounting, mag-disturbance, mag-disturbance=U, unplug=T, fixture, "
    "comconfig=spaced|unlabelled";

std::string_view trimmed(std::string_view s)
{
    while (!s.empty() && std::isspace(uint8_t(s.front())))
        s.remove_prefix(1);
    while (!s.empty() && std::isspace(uint8_t(s.back())))
        s.remove_suffix(1);
    return s;
}

std::string lower(std::string_view s)
{
    std::string out;
    for (char c : s)
        out.push_back(char(std::tolower(uint8_t(c))));
    return out;
}

// A finite decimal number, the whole of s (an optional leading '+').
bool parseNumber(std::string_view s, double &out)
{
    s = trimmed(s);
    if (!s.empty() && s.front() == '+')
        s.remove_prefix(1);
    if (s.empty())
        return false;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
    return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(out);
}

// The shortest text that reads back as the same double.
std::string number(double v)
{
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

} // namespace

bool parseSimFaults(std::string_view text, SimFaults &out, std::string *error)
{
    auto fail = [error](std::string message) {
        if (error)
            *error = std::move(message);
        return false;
    };
    SimFaults f = out;
    while (!text.empty()) {
        const size_t comma = text.find(',');
        const std::string_view item = trimmed(text.substr(0, comma));
        text = comma == std::string_view::npos ? std::string_view{} : text.substr(comma + 1);
        if (item.empty())
            continue;
        const size_t eq = item.find('=');
        const std::string word = lower(trimmed(item.substr(0, eq)));
        const bool hasValue = eq != std::string_view::npos;
        const std::string_view value = hasValue ? trimmed(item.substr(eq + 1)) : std::string_view{};
        const std::string shown(item);

        if (word == "noisy-gyro") {
            double factor = SimFaults::kNoisyGyroFactor;
            if (hasValue && (!parseNumber(value, factor) || factor < 0))
                return fail("noisy-gyro=F needs a noise factor >= 0 (1 is a good gyro), got '" + shown + "'");
            f.gyroNoiseFactor = factor;
        } else if (word == "wrong-mounting") {
            if (hasValue)
                return fail("wrong-mounting takes no value (mounting=R/P/Y gives the angles), got '" + shown + "'");
            f.mountingErrorDeg = {SimFaults::kWrongMountingRollDeg, 0, 0};
        } else if (word == "mounting") {
            std::array<double, 3> angles{};
            size_t parts = 0;
            bool good = hasValue;
            for (std::string_view rest = value; good;) {
                const size_t slash = rest.find('/');
                good = parts < 3 && parseNumber(rest.substr(0, slash), angles[parts]);
                ++parts;
                if (slash == std::string_view::npos)
                    break;
                rest = rest.substr(slash + 1);
            }
            if (!good || parts != 3)
                return fail("mounting=R/P/Y needs roll/pitch/yaw in degrees (e.g. mounting=90/0/0), got '" + shown + "'");
            f.mountingErrorDeg = angles;
        } else if (word == "mag-disturbance") {
            double ut = SimFaults::kMagDisturbanceUt;
            if (hasValue && (!parseNumber(value, ut) || ut < 0))
                return fail("mag-disturbance=U needs a field in uT >= 0, got '" + shown + "'");
            f.magDisturbanceUt = ut;
        } else if (word == "unplug") {
            double seconds = 0;
            if (!hasValue || !parseNumber(value, seconds) || seconds < 0)
                return fail("unplug=T needs the seconds after the start >= 0 (e.g. unplug=2.5), got '" + shown + "'");
            f.unplugAtS = seconds;
        } else if (word == "fixture") {
            if (hasValue)
                return fail("fixture takes no value, got '" + shown + "'");
            f.magCalFixture = true;
        } else if (word == "comconfig") {
            const std::string style = lower(value);
            if (style == "spaced")
                f.comConfigStyle = SimFaults::ComConfigStyle::Spaced;
            else if (style == "unlabelled")
                f.comConfigStyle = SimFaults::ComConfigStyle::Unlabelled;
            else
                return fail("comconfig= needs spaced or unlabelled, got '" + shown + "'");
        } else {
            return fail("unknown fault '" + shown + "' (accepted: " + kAccepted + ")");
        }
    }
    out = f;
    return true;
}

std::string simFaultsText(const SimFaults &faults)
{
    const SimFaults none;
    std::string out;
    auto add = [&out](const std::string &item) { out += (out.empty() ? "" : ",") + item; };
    if (faults.gyroNoiseFactor != none.gyroNoiseFactor)
        add("noisy-gyro=" + number(faults.gyroNoiseFactor));
    if (faults.mountingErrorDeg != none.mountingErrorDeg) {
        const auto &m = faults.mountingErrorDeg;
        add("mounting=" + number(m[0]) + "/" + number(m[1]) + "/" + number(m[2]));
    }
    if (faults.magDisturbanceUt != none.magDisturbanceUt)
        add("mag-disturbance=" + number(faults.magDisturbanceUt));
    if (faults.unplugAtS >= 0)
        add("unplug=" + number(faults.unplugAtS));
    if (faults.magCalFixture)
        add("fixture");
    if (faults.comConfigStyle == SimFaults::ComConfigStyle::Spaced)
        add("comconfig=spaced");
    else if (faults.comConfigStyle == SimFaults::ComConfigStyle::Unlabelled)
        add("comconfig=unlabelled");
    return out;
}

} // namespace imudesk::sim
