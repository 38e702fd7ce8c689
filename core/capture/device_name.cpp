#include "device_name.h"

#include "format/mcap/sample_channels.h"

#include <algorithm>

namespace imudesk::capture {

namespace {

std::string safe(const std::string &text)
{
    return format::mcap::SampleChannels::topicName(text);
}

int numberOf(const std::string &text)
{
    if (text.empty() || text.size() > 9 || !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return -1;
    return std::stoi(text);
}

} // namespace

std::string usableSerial(const CaptureHeader &header)
{
    std::string serial = header.value(CaptureHeader::kSerial);
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\0'; };
    while (!serial.empty() && blank(serial.back()))
        serial.pop_back();
    serial.erase(serial.begin(), std::find_if_not(serial.begin(), serial.end(), blank));
    const bool text = !serial.empty() && std::all_of(serial.begin(), serial.end(), [](char c) {
        return static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7F;
    });
    return text ? serial : std::string();
}

std::string deviceName(const CaptureHeader &header, const std::string &label)
{
    if (const std::string serial = usableSerial(header); !serial.empty())
        return safe(serial);
    const std::string protocol = header.value(CaptureHeader::kCanProtocol);
    const int node = numberOf(header.value(CaptureHeader::kCanNode));
    if (!protocol.empty() && protocol != "auto" && node >= 0)
        return safe(protocol + "_node" + std::to_string(node));
    const std::string product = header.value(CaptureHeader::kProduct);
    const int address = numberOf(header.value(CaptureHeader::kAddress));
    if (address >= 0)
        return safe((product.empty() ? std::string("device") : product) + "_addr" + std::to_string(address));
    if (!label.empty())
        return safe(label);
    return safe(product);
}

std::string matlabDeviceName(const CaptureHeader &header, const std::string &label)
{
    const std::string serial = usableSerial(header);
    if (serial.empty())
        return deviceName(header, label);
    const std::string name = safe(serial);
    const bool prefixed = name.size() > 3 && (name[0] == 'S' || name[0] == 's') && (name[1] == 'N' || name[1] == 'n')
        && name[2] == '_';
    return prefixed ? name : "SN_" + name;
}

} // namespace imudesk::capture
