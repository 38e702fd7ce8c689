#include "can_bootloader.h"

#include "kboot_bootloader.h"
#include "protocol/ihex/firmware_image.h"

#include <QLoggingCategory>

#include <algorithm>
#include <string_view>

namespace imudesk::sim {

namespace {
Q_LOGGING_CATEGORY(lcCanBoot, "imudesk.core.sim.canboot", QtInfoMsg)

namespace co = protocol::can::canopen;
using protocol::can::CanFrame;

constexpr uint16_t kObjUpdate = 0x1F51;
constexpr uint16_t kObjSoftwareId = 0x1F56;
constexpr uint8_t kSubDownload = 0x01;
constexpr uint8_t kSubEnter = 0x05;
constexpr uint8_t kSubConfirm = 0x06;
constexpr uint8_t kSubStart = 0x09;
} // namespace

CanBootloader::CanBootloader(Options options) : m_options(options), m_flash(options.flashSize, 0xFF) {}

void CanBootloader::start(uint8_t node, int64_t tUs)
{
    m_node = node;
    m_pending.clear();
    m_request = Request::None;
    m_downloading = false;
    m_requestAtUs = tUs;
    ++m_stats.starts;
}

std::vector<uint8_t> CanBootloader::applicationArea() const
{
    if (m_options.appStart >= m_flash.size())
        return {};
    return std::vector<uint8_t>(m_flash.begin() + m_options.appStart, m_flash.end());
}

std::optional<std::string> CanBootloader::applicationVersion() const
{
    if (!m_appValid)
        return std::nullopt;
    return KbootBootloader::versionIn(m_flash, m_options.appStart);
}

void CanBootloader::installApplication(const std::vector<uint8_t> &image)
{
    const size_t room = m_flash.size() > m_options.appStart ? m_flash.size() - m_options.appStart : 0;
    std::fill(m_flash.begin() + std::min<size_t>(m_options.appStart, m_flash.size()), m_flash.end(), uint8_t(0xFF));
    const size_t n = std::min(room, image.size());
    std::copy_n(image.begin(), n, m_flash.begin() + m_options.appStart);
    m_appValid = n > 0;
    m_lastDownloadSize = uint32_t(n);
}

void CanBootloader::reply(const CanFrame &f, int64_t dueUs)
{
    m_pending.push_back({f, dueUs});
}

void CanBootloader::abort(uint16_t index, uint8_t sub, uint32_t code, int64_t tUs)
{
    ++m_stats.abortsSent;
    reply(co::sdoAbortFrame(m_node, index, sub, code), tUs + m_options.replyUs);
}

void CanBootloader::handle(const co::SdoMessage &m, const CanFrame &raw, int64_t tUs)
{
    if (m.fromDevice || m.node != m_node || m_request == Request::PowerLoss)
        return;
    switch (m.kind) {
    case co::SdoKind::Abort:
        ++m_stats.abortsReceived;
        m_downloading = false;
        return;
    case co::SdoKind::DownloadSegment:
        handleSegment(raw, tUs);
        return;
    case co::SdoKind::DownloadSegmentedInit:
        if (m.index != kObjUpdate)
            return;
        if (m.sub != kSubDownload)
            return abort(m.index, m.sub, co::AbortNoSubIndex, tUs);
        initiate(m.value, tUs);
        return;
    case co::SdoKind::DownloadExpedited:
        if (m.index != kObjUpdate)
            return;
        if (m.sub == kSubEnter || m.sub == kSubConfirm) {
            reply(co::sdoWriteReply(m_node, m.index, m.sub), tUs + m_options.replyUs);
        } else if (m.sub == kSubStart) {
            if (!m_appValid || m_downloading)
                return abort(m.index, m.sub, co::AbortDeviceState, tUs);
            reply(co::sdoWriteReply(m_node, m.index, m.sub), tUs + m_options.replyUs);
            m_request = Request::StartApplication;
            m_requestAtUs = tUs + m_options.replyUs;
        } else {
            abort(m.index, m.sub, co::AbortNoSubIndex, tUs);
        }
        return;
    case co::SdoKind::UploadRequest:
        if (m.index != kObjSoftwareId || !m_options.crcObject)
            return;
        if (m.sub != 1)
            return abort(m.index, m.sub, co::AbortNoSubIndex, tUs);
        if (m_lastDownloadSize == 0 || m_downloading)
            return abort(m.index, m.sub, co::AbortDeviceState, tUs);
        reply(co::sdoReadReply(m_node, m.index, m.sub,
                               protocol::ihex::crc32(m_flash.data() + m_options.appStart, m_lastDownloadSize), 4),
              tUs + m_options.replyUs);
        return;
    default:
        return;
    }
}

void CanBootloader::initiate(uint32_t size, int64_t tUs)
{
    const uint32_t room = m_options.flashSize > m_options.appStart ? m_options.flashSize - m_options.appStart : 0;
    if (size == 0 || size > room) {
        m_downloading = false;
        return abort(kObjUpdate, kSubDownload, co::AbortOutOfMemory, tUs);
    }
    const uint32_t sector = std::max<uint32_t>(1, m_options.sectorSize);
    const uint32_t sectors = (size + sector - 1) / sector;
    const uint32_t eraseEnd = std::min<uint32_t>(m_options.flashSize, m_options.appStart + sectors * sector);
    std::fill(m_flash.begin() + m_options.appStart, m_flash.begin() + eraseEnd, uint8_t(0xFF));
    m_stats.sectorsErased += sectors;
    m_appValid = false;
    m_lastDownloadSize = 0;
    m_downloading = true;
    m_size = size;
    m_offset = 0;
    m_toggle = false;
    m_segment = 0;
    qCDebug(lcCanBoot) << "download of" << size << "bytes, erasing" << sectors << "sectors";
    reply(co::sdoWriteReply(m_node, kObjUpdate, kSubDownload), tUs + int64_t(sectors) * m_options.eraseUsPerSector);
}

void CanBootloader::handleSegment(const CanFrame &raw, int64_t tUs)
{
    if (!m_downloading)
        return abort(kObjUpdate, kSubDownload, co::AbortCommand, tUs);
    ++m_segment;
    ++m_stats.segments;
    const uint8_t cs = raw.data[0];
    if (m_faults.powerLossSegment == m_segment) {
        m_faults.powerLossSegment = 0;
        m_downloading = false;
        m_appValid = false;
        m_pending.clear();
        m_request = Request::PowerLoss;
        m_requestAtUs = tUs;
        return;
    }
    if (m_faults.silentSegment == m_segment) {
        m_faults.silentSegment = 0;
        --m_segment;
        return;
    }
    if (m_faults.abortSegment == m_segment) {
        m_faults.abortSegment = 0;
        m_downloading = false;
        return abort(kObjUpdate, kSubDownload, co::AbortGeneral, tUs);
    }
    const bool toggle = (cs & 0x10) != 0;
    if (toggle != m_toggle) {
        m_downloading = false;
        return abort(kObjUpdate, kSubDownload, co::AbortToggle, tUs);
    }
    const bool last = (cs & 0x01) != 0;
    const uint32_t n = last ? uint32_t(((15 - (cs & 0x0F)) / 2) + 1) : 7u;
    const uint32_t left = m_size - m_offset;
    if (n > left || (last && n != left) || (!last && n == left)) {
        m_downloading = false;
        return abort(kObjUpdate, kSubDownload, co::AbortLength, tUs);
    }
    for (uint32_t i = 0; i < n; ++i) {
        uint8_t b = raw.data[1 + i];
        if (m_faults.flipByteAt == int64_t(m_offset + i)) {
            m_faults.flipByteAt = -1;
            b ^= 0x01;
        }
        m_flash[m_options.appStart + m_offset + i] &= b;
    }
    m_offset += n;
    m_stats.bytesWritten += n;
    CanFrame r;
    r.id = co::CobSdoTx + m_node;
    r.len = 8;
    bool replyToggle = m_toggle;
    if (m_faults.corruptSegment == m_segment) {
        m_faults.corruptSegment = 0;
        replyToggle = !replyToggle;
    }
    r.data[0] = uint8_t(0x20 | (replyToggle ? 0x10 : 0x00));
    std::copy_n(raw.data.begin() + 1, 7, r.data.begin() + 1);
    if (m_faults.badEchoSegment == m_segment) {
        m_faults.badEchoSegment = 0;
        r.data[1] ^= 0xFF;
    }
    m_toggle = !m_toggle;
    if (last) {
        m_downloading = false;
        m_appValid = true;
        m_lastDownloadSize = m_size;
        ++m_stats.downloads;
        qCDebug(lcCanBoot) << "download complete," << m_size << "bytes";
    }
    reply(r, tUs + m_options.replyUs);
}

std::vector<CanFrame> CanBootloader::takeDue(int64_t tUs)
{
    std::vector<CanFrame> out;
    auto it = m_pending.begin();
    while (it != m_pending.end()) {
        if (it->dueUs <= tUs) {
            out.push_back(it->frame);
            it = m_pending.erase(it);
        } else {
            ++it;
        }
    }
    return out;
}

CanBootloader::Request CanBootloader::takeRequest(int64_t tUs)
{
    if (m_request == Request::None || tUs < m_requestAtUs || (m_request == Request::StartApplication && !m_pending.empty()))
        return Request::None;
    const Request r = m_request;
    m_request = Request::None;
    return r;
}

} // namespace imudesk::sim
