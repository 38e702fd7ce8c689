#include "device_identity.h"

#include <cctype>

namespace imudesk::model {

std::optional<FirmwareVersion> FirmwareVersion::parse(const std::string &in)
{
    std::string t = in;
    while (!t.empty() && std::isspace(uint8_t(t.back())))
        t.pop_back();
    size_t s = 0;
    while (s < t.size() && (std::isspace(uint8_t(t[s])) || t[s] == 'v' || t[s] == 'V'))
        ++s;
    t = t.substr(s);
    if (t.empty())
        return std::nullopt;
    FirmwareVersion v;
    if (t.find('.') == std::string::npos) {
        if (t.size() != 3)
            return std::nullopt;
        for (char c : t)
            if (!std::isdigit(uint8_t(c)))
                return std::nullopt;
        v.major = t[0] - '0';
        v.minor = t[1] - '0';
        v.patch = t[2] - '0';
        return v;
    }
    int parts[3] = {0, 0, 0};
    int idx = 0;
    bool digit = false;
    for (char c : t) {
        if (std::isdigit(uint8_t(c))) {
            parts[idx] = parts[idx] * 10 + (c - '0');
            digit = true;
            if (parts[idx] > 999)
                return std::nullopt;
        } else if (c == '.' && digit && idx < 2) {
            ++idx;
            digit = false;
        } else {
            return std::nullopt;
        }
    }
    if (!digit || idx < 1)
        return std::nullopt;
    v.major = parts[0];
    v.minor = parts[1];
    v.patch = parts[2];
    return v;
}

std::string FirmwareVersion::toString() const
{
    return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
}

DeviceIdentity DeviceIdentity::fromKeyValues(const std::map<std::string, std::string> &kv)
{
    auto get = [&](std::initializer_list<const char *> keys) -> std::string {
        for (const char *k : keys) {
            const auto it = kv.find(k);
            if (it != kv.end())
                return it->second;
        }
        return {};
    };
    DeviceIdentity id;
    id.productName = get({"PNAME"});
    id.build = get({"BUILD"});
    id.serial = get({"UUID", "SN"});
    id.firmware = FirmwareVersion::parse(get({"APP_VER", "SW_VERSION"}));
    id.bootloader = FirmwareVersion::parse(get({"BL_VER", "BL_VERSION"}));
    return id;
}

ProductFamily familyOfProduct(const std::string &name)
{
    auto starts = [&](const char *p) { return name.rfind(p, 0) == 0; };
    if (starts("HI02")) return ProductFamily::HI02;
    if (starts("HI05") || starts("HI06")) return ProductFamily::HI05_06;
    if (starts("CH0") || starts("CH1") || starts("HI04") || starts("HI12") || starts("HI13") || starts("HI14"))
        return ProductFamily::CH0x0_HI04_12_13_14;
    if (starts("HI50")) return ProductFamily::HI50;
    if (starts("HI7") || starts("HI9")) return ProductFamily::HI7x_9x;
    return ProductFamily::Unknown;
}

const char *worldFrameName(WorldFrame f)
{
    return f == WorldFrame::Nwu ? "NWU" : "ENU";
}

std::optional<WorldFrame> worldFrameOfCoord(const std::string &coord)
{
    size_t b = coord.find_first_not_of(" \t"), e = coord.find_last_not_of(" \t");
    if (b == std::string::npos)
        return std::nullopt;
    const std::string v = coord.substr(b, e - b + 1);
    if (v == "0")
        return WorldFrame::Enu;
    if (v == "4")
        return WorldFrame::Nwu;
    return std::nullopt;
}

std::optional<WorldFrame> parseWorldFrame(const std::string &name)
{
    std::string u;
    for (char c : name)
        u += char(std::toupper(static_cast<unsigned char>(c)));
    if (u == "ENU")
        return WorldFrame::Enu;
    if (u == "NWU")
        return WorldFrame::Nwu;
    return std::nullopt;
}

const char *familyName(ProductFamily f)
{
    switch (f) {
    case ProductFamily::Unknown: return "unknown";
    case ProductFamily::HI02: return "HI02";
    case ProductFamily::HI05_06: return "HI05/06";
    case ProductFamily::CH0x0_HI04_12_13_14: return "CH0x0/HI04/12/13/14";
    case ProductFamily::HI50: return "HI50";
    case ProductFamily::HI7x_9x: return "HI7x/9x";
    }
    return "?";
}

ProductFamily DeviceIdentity::family() const
{
    return familyOfProduct(productName);
}

ManualEdition DeviceIdentity::edition() const
{
    return (firmware && *firmware >= FirmwareVersion{1, 7, 1}) ? ManualEdition::V171 : ManualEdition::V166;
}

bool DeviceIdentity::hasMainStatus() const
{
    return firmware && *firmware >= FirmwareVersion{1, 7, 0};
}

bool DeviceIdentity::hasMagnetometer() const
{
    const auto f = family();
    return f != ProductFamily::HI02 && f != ProductFamily::HI50;
}

} // namespace imudesk::model
