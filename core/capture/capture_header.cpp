#include "capture_header.h"

#include <algorithm>
#include <charconv>

namespace imudesk::capture {

namespace {

void escapeInto(std::vector<uint8_t> &out, const std::string &s, bool isKey)
{
    for (char c : s) {
        if (c == '\\') {
            out.push_back('\\');
            out.push_back('\\');
        } else if (c == '\n') {
            out.push_back('\\');
            out.push_back('n');
        } else if (c == '=' && isKey) {
            out.push_back('\\');
            out.push_back('e');
        } else {
            out.push_back(uint8_t(c));
        }
    }
}

bool unescape(const std::string &in, std::string &out)
{
    out.clear();
    for (size_t i = 0; i < in.size(); ++i) {
        if (in[i] != '\\') {
            out += in[i];
            continue;
        }
        if (++i >= in.size())
            return false;
        switch (in[i]) {
        case '\\': out += '\\'; break;
        case 'n': out += '\n'; break;
        case 'e': out += '='; break;
        default: return false;
        }
    }
    return true;
}

} // namespace

std::string CaptureHeader::value(const std::string &key) const
{
    const auto it = values.find(key);
    return it == values.end() ? std::string() : it->second;
}

void CaptureHeader::setIdentity(const model::DeviceIdentity &id)
{
    set(kProduct, id.productName);
    set(kFirmware, id.firmware ? id.firmware->toString() : std::string());
    set(kBootloader, id.bootloader ? id.bootloader->toString() : std::string());
    set(kSerial, id.serial);
    set(kBuild, id.build);
    if (id.busAddress >= 0)
        set(kAddress, std::to_string(id.busAddress));
    else
        values.erase(kAddress);
    if (id.worldFrame == model::WorldFrame::Enu)
        values.erase(kWorldFrame);
    else
        set(kWorldFrame, model::worldFrameName(id.worldFrame));
}

model::DeviceIdentity CaptureHeader::identity() const
{
    model::DeviceIdentity id;
    id.productName = value(kProduct);
    id.serial = value(kSerial);
    id.build = value(kBuild);
    id.firmware = model::FirmwareVersion::parse(value(kFirmware));
    id.bootloader = model::FirmwareVersion::parse(value(kBootloader));
    id.worldFrame = model::parseWorldFrame(value(kWorldFrame)).value_or(model::WorldFrame::Enu);
    if (const std::string a = value(kAddress); !a.empty() && a.size() < 4
        && std::all_of(a.begin(), a.end(), [](char c) { return c >= '0' && c <= '9'; }))
        id.busAddress = std::stoi(a);
    return id;
}

std::string CaptureHeader::family() const
{
    const std::string f = value(kFamily);
    return f.empty() ? value(kLinkKind) : f;
}

int CaptureHeader::baud() const
{
    const std::string v = value(kBaud);
    int b = 0;
    const auto r = std::from_chars(v.data(), v.data() + v.size(), b);
    return r.ec == std::errc() && b > 0 ? b : 0;
}

std::map<std::string, std::string> CaptureHeader::config() const
{
    std::map<std::string, std::string> out;
    const std::string prefix = kConfigPrefix;
    for (auto it = values.lower_bound(prefix); it != values.end() && it->first.compare(0, prefix.size(), prefix) == 0;
         ++it)
        out[it->first.substr(prefix.size())] = it->second;
    return out;
}

void CaptureHeader::setConfig(const std::map<std::string, std::string> &kv)
{
    for (const auto &[k, v] : kv)
        values[kConfigPrefix + k] = v;
}

std::vector<uint8_t> CaptureHeader::encodeBody() const
{
    std::vector<uint8_t> out;
    for (const auto &[k, v] : values) {
        escapeInto(out, k, true);
        out.push_back('=');
        escapeInto(out, v, false);
        out.push_back('\n');
    }
    return out;
}

bool CaptureHeader::decodeBody(const uint8_t *data, size_t n, CaptureHeader &out, QString *error)
{
    out.values.clear();
    size_t start = 0;
    int lineNo = 0;
    while (start < n) {
        ++lineNo;
        size_t end = start;
        while (end < n && data[end] != '\n')
            ++end;
        const std::string line(reinterpret_cast<const char *>(data + start), end - start);
        start = end + 1;
        const size_t eq = line.find('=');
        std::string key, value;
        if (eq == std::string::npos || !unescape(line.substr(0, eq), key) || !unescape(line.substr(eq + 1), value)) {
            if (error)
                *error = tr("line %1 of the capture header is not a key=value entry").arg(lineNo);
            return false;
        }
        out.values[key] = value;
    }
    return true;
}

} // namespace imudesk::capture
