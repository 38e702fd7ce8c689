#include "kboot_bootloader.h"

#include "protocol/kboot/command.h"
#include "protocol/kboot/status_code.h"

#include <QLoggingCategory>

#include <algorithm>
#include <cstring>
#include <limits>

namespace imudesk::sim {

namespace {

Q_LOGGING_CATEGORY(lcBoot, "imudesk.core.sim.kboot", QtInfoMsg)

using namespace protocol::kboot;

constexpr int64_t kNoEvent = std::numeric_limits<int64_t>::max();
// A partial packet is dropped when the line stays quiet this long (KBOOT's packet timeout).
constexpr int64_t kInterByteTimeoutUs = 20000;

uint64_t splitmix(uint64_t &s)
{
    uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

} // namespace

KbootBootloader::KbootBootloader(Options options) : m_options(options), m_decoder(kMaxPayload)
{
    m_flash.assign(m_options.flashSize, 0xFF);
    // The bootloader area holds "code"; its content is never read back by the host.
    uint64_t s = 0xB007;
    for (uint32_t i = 0; i < std::min(m_options.appStart, m_options.flashSize); ++i)
        m_flash[i] = uint8_t(splitmix(s));
}

std::vector<uint8_t> KbootBootloader::makeApplication(const std::string &version, size_t size, uint64_t seed)
{
    std::vector<uint8_t> img(size);
    uint64_t s = seed;
    for (auto &b : img)
        b = uint8_t(splitmix(s));
    const std::string tag = std::string(kVersionMarker) + version;
    // Behind a vector-table-sized header, as a real image keeps its version string in .rodata.
    const size_t at = std::min<size_t>(0x200, size > tag.size() + 1 ? size - tag.size() - 1 : 0);
    if (size >= tag.size() + 1) {
        std::memcpy(img.data() + at, tag.c_str(), tag.size() + 1);
    }
    return img;
}

void KbootBootloader::installApplication(const std::vector<uint8_t> &image)
{
    const size_t room = m_options.flashSize > m_options.appStart ? m_options.flashSize - m_options.appStart : 0;
    std::fill(m_flash.begin() + m_options.appStart, m_flash.end(), uint8_t(0xFF));
    std::copy_n(image.begin(), std::min(room, image.size()), m_flash.begin() + m_options.appStart);
    m_appValid = !image.empty();
}

std::vector<uint8_t> KbootBootloader::applicationArea() const
{
    if (m_options.appStart >= m_flash.size())
        return {};
    return std::vector<uint8_t>(m_flash.begin() + m_options.appStart, m_flash.end());
}

std::optional<std::string> KbootBootloader::versionIn(const std::vector<uint8_t> &flash, size_t from)
{
    const std::string_view marker(kVersionMarker);
    const auto begin = flash.begin() + long(std::min(from, flash.size()));
    const auto it = std::search(begin, flash.end(), marker.begin(), marker.end());
    if (it == flash.end())
        return std::nullopt;
    std::string v;
    for (auto p = it + long(marker.size()); p != flash.end() && *p != 0 && v.size() < 16; ++p)
        v.push_back(char(*p));
    return v;
}

std::optional<std::string> KbootBootloader::applicationVersion() const
{
    return versionIn(m_flash, m_options.appStart);
}

void KbootBootloader::start(int baud, int64_t t)
{
    m_byteUs = 1e7 / double(baud > 0 ? baud : 115200);
    m_rx.clear();
    m_rxFreeUs = t;
    m_decoder.reset();
    m_phase = Phase::Idle;
    m_busyUntilUs = 0;
    m_deferred.clear();
    m_lastChunk.clear();
    m_dataPackets = 0;
    m_request = Request::None;
}

void KbootBootloader::receive(const uint8_t *data, size_t n, int64_t t)
{
    double at = double(std::max(t, m_rxFreeUs));
    for (size_t i = 0; i < n; ++i) {
        at += m_byteUs;
        if (m_rx.size() >= kMaxRxQueue) {
            ++m_stats.rxOverruns;
            continue;
        }
        m_rx.push_back(RxByte{data[i], int64_t(at)});
    }
    m_rxFreeUs = int64_t(at);
}

int64_t KbootBootloader::nextEventUs() const
{
    int64_t n = kNoEvent;
    if (!m_deferred.empty())
        n = m_busyUntilUs;
    if (!m_rx.empty())
        n = std::min(n, std::max(m_rx.front().atUs, m_busyUntilUs));
    return n;
}

KbootBootloader::Request KbootBootloader::runUntil(int64_t t)
{
    m_request = Request::None;
    int64_t lastByteUs = -1;
    while (m_busyUntilUs <= t) {
        if (!m_deferred.empty()) {
            sendPacket(m_deferred);
            m_deferred.clear();
        }
        if (m_rx.empty() || m_rx.front().atUs > t)
            break;
        const RxByte b = m_rx.front();
        m_rx.pop_front();
        if (lastByteUs >= 0 && b.atUs - lastByteUs > kInterByteTimeoutUs && m_decoder.pendingBytes() > 0)
            m_decoder.reset();
        lastByteUs = b.atUs;
        const uint64_t crcBefore = m_decoder.counters().crcErrors;
        const auto packets = m_decoder.feed(&b.value, 1);
        if (m_decoder.counters().crcErrors != crcBefore) {
            ++m_stats.crcErrors;
            ++m_stats.naksSent;
            sendPacket(encodeControl(PacketType::Nak));
        }
        for (const Packet &p : packets)
            handle(p, b.atUs);
        if (m_request != Request::None) {
            m_rx.clear();
            break;
        }
    }
    return m_request;
}

void KbootBootloader::sendPacket(const std::vector<uint8_t> &bytes)
{
    m_out.push_back(bytes);
}

std::vector<std::vector<uint8_t>> KbootBootloader::takeOutput()
{
    std::vector<std::vector<uint8_t>> out;
    out.swap(m_out);
    return out;
}

void KbootBootloader::sendResponse(const std::vector<uint8_t> &payload)
{
    sendPacket(encodeFramed(PacketType::Command, payload));
}

void KbootBootloader::handle(const Packet &p, int64_t t)
{
    switch (p.type) {
    case PacketType::Ping:
        ++m_stats.pings;
        m_phase = Phase::Idle;
        sendPacket(encodePingResponse(PingResponse{0, 0, 2, 'P', 0}));
        return;
    case PacketType::Ack:
        if (m_phase == Phase::ReadData)
            sendReadChunk();
        return;
    case PacketType::Nak:
        if (m_phase == Phase::ReadData && !m_lastChunk.empty())
            sendPacket(m_lastChunk);
        return;
    case PacketType::AckAbort:
        m_phase = Phase::Idle;
        return;
    case PacketType::PingResponse: return;
    case PacketType::Command:
        ++m_stats.commands;
        if (m_phase == Phase::WriteData)
            qCDebug(lcBoot) << "command aborts a write with" << m_remaining << "bytes missing";
        m_phase = Phase::Idle;
        sendPacket(encodeControl(PacketType::Ack));
        handleCommand(p.payload, t);
        return;
    case PacketType::Data: break;
    }
    if (m_phase != Phase::WriteData) {
        sendPacket(encodeControl(PacketType::AckAbort));
        return;
    }
    ++m_stats.dataPackets;
    const int n = ++m_dataPackets;
    if (m_faults.powerLossDataPacket == n) {
        m_faults.powerLossDataPacket = 0;
        qCInfo(lcBoot) << "fault: power lost at data packet" << n;
        m_request = Request::PowerLoss;
        return;
    }
    if (m_faults.silentDataPacket == n) {
        m_faults.silentDataPacket = 0;
        qCInfo(lcBoot) << "fault: no answer to data packet" << n;
        return;
    }
    if (m_faults.nakDataPacket == n) {
        m_faults.nakDataPacket = 0;
        qCInfo(lcBoot) << "fault: NAK for data packet" << n;
        ++m_stats.naksSent;
        sendPacket(encodeControl(PacketType::Nak));
        return;
    }
    if (m_faults.corruptAckDataPacket == n) {
        m_faults.corruptAckDataPacket = 0;
        qCInfo(lcBoot) << "fault: damaged ACK for data packet" << n;
        sendPacket({kStartByte, 0xE1});
    } else {
        sendPacket(encodeControl(PacketType::Ack));
    }
    handleData(p.payload);
}

void KbootBootloader::handleData(const std::vector<uint8_t> &payload)
{
    const size_t n = std::min<size_t>(payload.size(), m_remaining);
    for (size_t i = 0; i < n; ++i) {
        uint8_t &cell = m_flash[m_address + i];
        if ((cell & payload[i]) != payload[i])
            m_writeStatus = kStatusMemoryCumulativeWrite;
        cell &= payload[i];
    }
    if (payload.size() > n)
        m_writeStatus = kStatusInvalidArgument;
    m_address += uint32_t(n);
    m_remaining -= uint32_t(n);
    m_stats.bytesWritten += n;
    if (m_remaining == 0)
        finishWrite();
}

void KbootBootloader::finishWrite()
{
    m_phase = Phase::Idle;
    if (m_writeStatus == kStatusSuccess && m_writeStart == m_options.appStart)
        m_appValid = true;
    sendResponse(genericResponse(m_writeStatus, uint8_t(CommandTag::WriteMemory)).encode());
}

void KbootBootloader::sendReadChunk()
{
    if (m_remaining == 0) {
        m_phase = Phase::Idle;
        m_lastChunk.clear();
        sendResponse(genericResponse(kStatusSuccess, uint8_t(CommandTag::ReadMemory)).encode());
        return;
    }
    const uint32_t n = std::min(m_remaining, m_options.maxPacketSize);
    m_lastChunk = encodeFramed(PacketType::Data, m_flash.data() + m_address, n);
    m_address += n;
    m_remaining -= n;
    m_stats.bytesRead += n;
    sendPacket(m_lastChunk);
}

void KbootBootloader::handleCommand(const std::vector<uint8_t> &payload, int64_t t)
{
    const auto c = Command::decode(payload);
    const uint8_t tag = payload.empty() ? 0 : payload[0];
    auto generic = [this](uint32_t status, uint8_t echo) { sendResponse(genericResponse(status, echo).encode()); };
    if (!c) {
        generic(kStatusInvalidArgument, tag);
        return;
    }
    const auto &p = c->params;
    const uint64_t flashEnd = m_options.flashSize;
    switch (CommandTag(tag)) {
    case CommandTag::GetProperty: {
        if (p.empty()) {
            generic(kStatusInvalidArgument, tag);
            return;
        }
        std::optional<uint32_t> v;
        switch (PropertyTag(p[0])) {
        case PropertyTag::CurrentVersion: v = m_options.currentVersion; break;
        case PropertyTag::FlashStartAddress: v = 0; break;
        case PropertyTag::FlashSizeInBytes: v = m_options.flashSize; break;
        case PropertyTag::FlashSectorSize: v = m_options.sectorSize; break;
        case PropertyTag::MaxPacketSize: v = m_options.maxPacketSize; break;
        case PropertyTag::BootloaderVersion: v = m_options.bootloaderVersion; break;
        case PropertyTag::AppVersion: {
            uint32_t num = 0;
            for (char ch : applicationVersion().value_or(std::string()))
                if (ch >= '0' && ch <= '9')
                    num = num * 10 + uint32_t(ch - '0');
            v = num;
            break;
        }
        }
        if (v)
            sendResponse(getPropertyResponse(kStatusSuccess, {*v}).encode());
        else
            sendResponse(getPropertyResponse(kStatusUnknownProperty, {0}).encode());
        return;
    }
    case CommandTag::FlashEraseRegion: {
        if (p.size() != 2) {
            generic(kStatusInvalidArgument, tag);
            return;
        }
        const uint64_t a = p[0], len = p[1];
        uint32_t status = kStatusSuccess;
        if (a % m_options.sectorSize != 0 || len % m_options.sectorSize != 0 || len == 0)
            status = kStatusFlashAlignmentError;
        else if (a + len > flashEnd)
            status = kStatusFlashAddressError;
        else if (a < m_options.appStart)
            status = kStatusFlashProtectionViolation;
        if (status != kStatusSuccess) {
            generic(status, tag);
            return;
        }
        std::fill_n(m_flash.begin() + long(a), size_t(len), uint8_t(0xFF));
        m_appValid = false;
        const uint64_t sectors = len / m_options.sectorSize;
        m_stats.sectorsErased += sectors;
        m_busyUntilUs = t + int64_t(sectors) * m_options.eraseUsPerSector;
        m_deferred = encodeFramed(PacketType::Command, genericResponse(kStatusSuccess, tag).encode());
        return;
    }
    case CommandTag::WriteMemory: {
        if (p.size() != 2 || p[1] == 0) {
            generic(kStatusInvalidArgument, tag);
            return;
        }
        const uint64_t a = p[0], len = p[1];
        uint32_t status = kStatusSuccess;
        if (a % 4 != 0)
            status = kStatusFlashAlignmentError;
        else if (a + len > flashEnd)
            status = kStatusFlashAddressError;
        else if (a < m_options.appStart)
            status = kStatusFlashProtectionViolation;
        generic(status, tag);
        if (status != kStatusSuccess)
            return;
        m_phase = Phase::WriteData;
        m_address = m_writeStart = uint32_t(a);
        m_remaining = uint32_t(len);
        m_writeStatus = kStatusSuccess;
        if (a < uint64_t(m_options.appStart) + m_options.sectorSize)
            m_appValid = false;
        return;
    }
    case CommandTag::ReadMemory: {
        if (!m_options.readMemory) {
            generic(kStatusUnknownCommand, tag);
            return;
        }
        if (p.size() != 2 || p[1] == 0) {
            generic(kStatusInvalidArgument, tag);
            return;
        }
        if (uint64_t(p[0]) + p[1] > flashEnd) {
            generic(kStatusMemoryRangeInvalid, tag);
            return;
        }
        m_phase = Phase::ReadData;
        m_address = p[0];
        m_remaining = p[1];
        // Data follows once the host ACKed this response (as the KBOOT specification has it).
        m_lastChunk = encodeFramed(PacketType::Command, readMemoryResponse(kStatusSuccess, p[1]).encode());
        sendPacket(m_lastChunk);
        return;
    }
    case CommandTag::Reset:
        generic(kStatusSuccess, tag);
        m_request = Request::Reset;
        return;
    default: generic(kStatusUnknownCommand, tag); return;
    }
}

} // namespace imudesk::sim
