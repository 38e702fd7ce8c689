// SimFaults in text form, as `imudesk-cli simulate --pty --faults LIST` takes them:
// parseSimFaults and simFaultsText (declared in hipnuc_simulator.h).
#include "hipnuc_simulator.h"

#include <cctype>
#include <array>
#include <charconv>
#include <cmath>

namespace imudesk::sim {

namespace {

constexpr const char *kAccepted =
    "noisy-gyro, noisy-gyro=F, mounting=R/P/Y, wrong-mounting, mag-disturbance, mag-disturbance=U, unplug=T, fixture, "
    "comconfig=spaced|unlabelled, acc-bias=X/Y/Z, acc-scale=X/Y/Z, acc-misalignment=YX/ZX/ZY, acc-error=MG/PCT, "
    "gyro-scale=PCT or X/Y/Z, gyro-misalignment=YX/ZX/ZY, attitude-bias=R/P/H, filter-lag=MS";

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

// "A/B/C" (or, with `single`, one number for all three): finite numbers.
bool parseTriple(std::string_view value, std::array<double, 3> &out, bool single = false)
{
    std::array<double, 3> v{};
    size_t parts = 0;
    for (std::string_view rest = value;;) {
        const size_t slash = rest.find('/');
        if (parts >= 3 || !parseNumber(rest.substr(0, slash), v[parts]))
            return false;
        ++parts;
        if (slash == std::string_view::npos)
            break;
        rest = rest.substr(slash + 1);
    }
    if (parts == 1 && single)
        v = {v[0], v[0], v[0]};
    else if (parts != 3)
        return false;
    out = v;
    return true;
}

std::string tripleText(const std::array<double, 3> &v)
{
    return number(v[0]) + "/" + number(v[1]) + "/" + number(v[2]);
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
            if (!hasValue || !parseTriple(value, f.mountingErrorDeg))
                return fail("mounting=R/P/Y needs roll/pitch/yaw in degrees (e.g. mounting=90/0/0), got '" + shown + "'");
        } else if (word == "acc-bias") {
            if (!hasValue || !parseTriple(value, f.accBiasMg))
                return fail("acc-bias=X/Y/Z needs the accelerometer's bias per axis in mg (e.g. acc-bias=12/-5/8), got '"
                            + shown + "'");
        } else if (word == "acc-scale") {
            if (!hasValue || !parseTriple(value, f.accScalePct))
                return fail("acc-scale=X/Y/Z needs the accelerometer's scale error per axis in % (e.g. acc-scale=1/0/-0.5), "
                            "got '" + shown + "'");
        } else if (word == "acc-misalignment") {
            if (!hasValue || !parseTriple(value, f.accMisalignmentDeg))
                return fail("acc-misalignment=YX/ZX/ZY needs three angles in degrees (y towards x, z towards x, z towards "
                            "y), got '" + shown + "'");
        } else if (word == "acc-error") {
            std::array<double, 3> pair{};
            const size_t slash = value.find('/');
            if (!hasValue || slash == std::string_view::npos || !parseNumber(value.substr(0, slash), pair[0])
                || !parseNumber(value.substr(slash + 1), pair[1]))
                return fail("acc-error=MG/PCT needs a bias in mg and a scale error in % for every axis (e.g. "
                            "acc-error=20/1), got '" + shown + "'");
            f.accBiasMg = {pair[0], pair[0], pair[0]};
            f.accScalePct = {pair[1], pair[1], pair[1]};
        } else if (word == "gyro-scale") {
            if (!hasValue || !parseTriple(value, f.gyroScalePct, true))
                return fail("gyro-scale=PCT (or X/Y/Z) needs the gyro's scale error in % (e.g. gyro-scale=0.5), got '"
                            + shown + "'");
        } else if (word == "gyro-misalignment") {
            if (!hasValue || !parseTriple(value, f.gyroMisalignmentDeg))
                return fail("gyro-misalignment=YX/ZX/ZY needs three angles in degrees (y towards x, z towards x, z "
                            "towards y), got '" + shown + "'");
        } else if (word == "attitude-bias") {
            if (!hasValue || !parseTriple(value, f.attitudeBiasDeg))
                return fail("attitude-bias=R/P/H needs roll/pitch/heading offsets in degrees (heading clockwise, e.g. "
                            "attitude-bias=0/0/3), got '" + shown + "'");
        } else if (word == "filter-lag") {
            double ms = 0;
            if (!hasValue || !parseNumber(value, ms) || ms < 0 || ms > 10000)
                return fail("filter-lag=MS needs the attitude's lag in ms (0..10000), got '" + shown + "'");
            f.filterLagMs = ms;
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

SensorModel::AccError accErrorOf(const SimFaults &faults)
{
    SensorModel::AccError e;
    for (int i = 0; i < 3; ++i) {
        e.biasG[i] = faults.accBiasMg[size_t(i)] * 1e-3;
        e.scale[i] = faults.accScalePct[size_t(i)] * 1e-2;
        e.misalignmentRad[i] = faults.accMisalignmentDeg[size_t(i)] * 3.141592653589793 / 180.0;
    }
    return e;
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
        add("mounting=" + tripleText(m));
    }
    if (faults.accBiasMg != none.accBiasMg)
        add("acc-bias=" + tripleText(faults.accBiasMg));
    if (faults.accScalePct != none.accScalePct)
        add("acc-scale=" + tripleText(faults.accScalePct));
    if (faults.accMisalignmentDeg != none.accMisalignmentDeg)
        add("acc-misalignment=" + tripleText(faults.accMisalignmentDeg));
    if (faults.gyroScalePct != none.gyroScalePct)
        add("gyro-scale=" + tripleText(faults.gyroScalePct));
    if (faults.gyroMisalignmentDeg != none.gyroMisalignmentDeg)
        add("gyro-misalignment=" + tripleText(faults.gyroMisalignmentDeg));
    if (faults.attitudeBiasDeg != none.attitudeBiasDeg)
        add("attitude-bias=" + tripleText(faults.attitudeBiasDeg));
    if (faults.filterLagMs != none.filterLagMs)
        add("filter-lag=" + number(faults.filterLagMs));
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
