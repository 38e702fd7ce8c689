#include "sdo_segmented_download.h"

#include <QCoreApplication>

#include <algorithm>

namespace imudesk::protocol::can::canopen {

SdoSegmentedDownload::SdoSegmentedDownload(uint8_t node, uint16_t index, uint8_t sub, std::vector<uint8_t> data,
                                           LastSegment style)
    : m_node(node), m_index(index), m_sub(sub), m_data(std::move(data)), m_style(style)
{
}

CanFrame SdoSegmentedDownload::start()
{
    CanFrame f;
    f.id = CobSdoRx + m_node;
    f.len = 8;
    f.data[0] = SdoDownloadSegmented;
    putU16(f, 1, m_index);
    f.data[3] = m_sub;
    putU32(f, 4, uint32_t(m_data.size()));
    m_next = f;
    return f;
}

uint8_t SdoSegmentedDownload::segmentCs(int n, bool toggle, bool last, LastSegment style)
{
    uint8_t cs = toggle ? 0x10 : 0x00;
    if (last) {
        n = std::clamp(n, 1, 7);
        cs |= style == LastSegment::Hipnuc ? uint8_t(17 - 2 * n) : uint8_t(((7 - n) << 1) | 1);
    }
    return cs;
}

CanFrame SdoSegmentedDownload::segment()
{
    CanFrame f;
    f.id = CobSdoRx + m_node;
    f.len = 8;
    const size_t n = std::min<size_t>(7, m_data.size() - m_offset);
    const bool last = m_offset + n >= m_data.size();
    f.data[0] = segmentCs(int(n), m_toggle, last, m_style);
    std::copy_n(m_data.begin() + ptrdiff_t(m_offset), n, f.data.begin() + 1);
    m_pendingBytes = n;
    m_lastSent = last;
    return f;
}

bool SdoSegmentedDownload::onFrame(const CanFrame &f)
{
    if (m_status != Status::Running)
        return false;
    const auto m = parseSdo(f);
    if (!m || !m->fromDevice || m->node != m_node)
        return false;
    if (m->kind == SdoKind::Abort) {
        fail(QCoreApplication::translate("SDO", "the device aborted the transfer: %1").arg(abortText(m->value)), m->value);
        return true;
    }
    if (!m_initiated) {
        if (m->kind != SdoKind::DownloadReply || m->index != m_index || m->sub != m_sub)
            return false;
        m_initiated = true;
        if (m_data.empty()) {
            m_status = Status::Done;
            return true;
        }
        m_next = segment();
        return true;
    }
    if (m->kind != SdoKind::DownloadSegmentReply)
        return false;
    const bool toggle = (m->cs & 0x10) != 0;
    if (toggle != m_toggle) {
        fail(QCoreApplication::translate("SDO", "the device confirmed a segment with the wrong toggle bit"), AbortToggle);
        return true;
    }
    m_offset += m_pendingBytes;
    m_toggle = !m_toggle;
    if (m_lastSent) {
        m_status = Status::Done;
        return true;
    }
    m_next = segment();
    return true;
}

int SdoSegmentedDownload::percent() const
{
    return m_data.empty() ? 100 : int(m_offset * 100 / m_data.size());
}

void SdoSegmentedDownload::fail(const QString &why, uint32_t code)
{
    m_status = Status::Failed;
    m_error = why;
    m_abort = code;
}

} // namespace imudesk::protocol::can::canopen
