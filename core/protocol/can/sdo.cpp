#include "sdo.h"

#include <QCoreApplication>

namespace imudesk::protocol::can::canopen {

QString abortText(uint32_t code)
{
    const char *t = nullptr;
    switch (code) {
    case AbortToggle: t = QT_TRANSLATE_NOOP("SDO", "toggle bit not alternated"); break;
    case AbortTimeout: t = QT_TRANSLATE_NOOP("SDO", "SDO protocol timed out"); break;
    case AbortCommand: t = QT_TRANSLATE_NOOP("SDO", "command specifier not valid or unknown"); break;
    case AbortOutOfMemory: t = QT_TRANSLATE_NOOP("SDO", "out of memory"); break;
    case AbortUnsupported: t = QT_TRANSLATE_NOOP("SDO", "unsupported access to an object"); break;
    case AbortWriteOnly: t = QT_TRANSLATE_NOOP("SDO", "attempt to read a write-only object"); break;
    case AbortReadOnly: t = QT_TRANSLATE_NOOP("SDO", "attempt to write a read-only object"); break;
    case AbortNoObject: t = QT_TRANSLATE_NOOP("SDO", "object does not exist in the object dictionary"); break;
    case AbortLength: t = QT_TRANSLATE_NOOP("SDO", "data type does not match, length of service parameter does not match"); break;
    case AbortNoSubIndex: t = QT_TRANSLATE_NOOP("SDO", "sub-index does not exist"); break;
    case AbortValueRange: t = QT_TRANSLATE_NOOP("SDO", "invalid value for parameter"); break;
    case AbortValueHigh: t = QT_TRANSLATE_NOOP("SDO", "value of parameter written too high"); break;
    case AbortValueLow: t = QT_TRANSLATE_NOOP("SDO", "value of parameter written too low"); break;
    case AbortGeneral: t = QT_TRANSLATE_NOOP("SDO", "general error"); break;
    case AbortStore: t = QT_TRANSLATE_NOOP("SDO", "data cannot be transferred or stored to the application"); break;
    case AbortDeviceState: t = QT_TRANSLATE_NOOP("SDO", "data cannot be transferred because of the present device state"); break;
    default: break;
    }
    if (!t)
        return QCoreApplication::translate("SDO", "abort code 0x%1").arg(code, 8, 16, QLatin1Char('0'));
    return QCoreApplication::translate("SDO", t);
}

namespace {
CanFrame sdoFrame(uint32_t cob, uint8_t cs, uint16_t index, uint8_t sub, uint32_t value)
{
    CanFrame f;
    f.id = cob;
    f.len = 8;
    f.data[0] = cs;
    putU16(f, 1, index);
    f.data[3] = sub;
    putU32(f, 4, value);
    return f;
}
uint32_t masked(uint32_t value, int size)
{
    return size >= 4 ? value : value & ((1u << (8 * size)) - 1u);
}
} // namespace

std::optional<SdoMessage> parseSdo(const CanFrame &f)
{
    if (f.extended || f.remote || f.len != 8 || f.id > 0x7FF)
        return std::nullopt;
    const uint32_t base = f.id & 0x780;
    const uint8_t node = uint8_t(f.id & 0x7F);
    if ((base != 0x580 && base != 0x600) || node == 0)
        return std::nullopt;
    SdoMessage m;
    m.node = node;
    m.fromDevice = base == 0x580;
    m.cs = f.data[0];
    m.index = u16At(f, 1);
    m.sub = f.data[3];
    m.value = u32At(f, 4);
    const uint8_t ccs = m.cs >> 5;
    if (m.cs == SdoAbort) {
        m.kind = SdoKind::Abort;
    } else if (!m.fromDevice) {
        if (ccs == 1) {
            if (m.cs & 0x02) {
                m.kind = SdoKind::DownloadExpedited;
                m.size = (m.cs & 0x01) ? 4 - ((m.cs >> 2) & 0x3) : 0;
                if (m.size)
                    m.value = masked(m.value, m.size);
            } else {
                m.kind = SdoKind::DownloadSegmentedInit;
            }
        } else if (ccs == 0) {
            m.kind = SdoKind::DownloadSegment;
        } else if (ccs == 2) {
            m.kind = SdoKind::UploadRequest;
        }
    } else {
        if (ccs == 3)
            m.kind = SdoKind::DownloadReply;
        else if (ccs == 1)
            m.kind = SdoKind::DownloadSegmentReply;
        else if (ccs == 2) {
            if (m.cs & 0x02) {
                m.kind = SdoKind::UploadExpedited;
                m.size = (m.cs & 0x01) ? 4 - ((m.cs >> 2) & 0x3) : 0;
                if (m.size)
                    m.value = masked(m.value, m.size);
            } else {
                m.kind = SdoKind::UploadSegmentedInit;
            }
        }
    }
    return m;
}

CanFrame sdoWrite(uint8_t node, uint16_t index, uint8_t sub, uint32_t value, int size)
{
    if (size < 1 || size > 4)
        size = 4;
    const uint8_t cs = uint8_t(0x23 | ((4 - size) << 2));
    return sdoFrame(CobSdoRx + node, cs, index, sub, masked(value, size));
}

CanFrame sdoWriteUnsized(uint8_t node, uint16_t index, uint8_t sub, uint32_t value)
{
    return sdoFrame(CobSdoRx + node, SdoDownloadUnsized, index, sub, value);
}

CanFrame sdoRead(uint8_t node, uint16_t index, uint8_t sub)
{
    return sdoFrame(CobSdoRx + node, SdoUploadRequest, index, sub, 0);
}

CanFrame sdoWriteReply(uint8_t node, uint16_t index, uint8_t sub)
{
    return sdoFrame(CobSdoTx + node, SdoDownloadReply, index, sub, 0);
}

CanFrame sdoReadReply(uint8_t node, uint16_t index, uint8_t sub, uint32_t value, int size)
{
    if (size < 1 || size > 4)
        size = 4;
    const uint8_t cs = uint8_t(0x43 | ((4 - size) << 2));
    return sdoFrame(CobSdoTx + node, cs, index, sub, masked(value, size));
}

CanFrame sdoAbortFrame(uint8_t node, uint16_t index, uint8_t sub, uint32_t code, bool fromDevice)
{
    return sdoFrame((fromDevice ? CobSdoTx : CobSdoRx) + node, SdoAbort, index, sub, code);
}

bool sdoAnswers(const SdoMessage &reply, const SdoMessage &request)
{
    return reply.fromDevice && !request.fromDevice && reply.node == request.node && reply.index == request.index
        && reply.sub == request.sub;
}

QString describe(const SdoMessage &m)
{
    const QString obj = QStringLiteral("0x%1.%2").arg(QString::number(m.index, 16).toUpper().rightJustified(4, QLatin1Char('0')),
                                                      QString::number(m.sub, 16).toUpper().rightJustified(2, QLatin1Char('0')));
    switch (m.kind) {
    case SdoKind::DownloadExpedited:
        return QCoreApplication::translate("SDO", "SDO write %1 = %2 (%3 bytes)").arg(obj).arg(m.value).arg(m.size ? m.size : 4);
    case SdoKind::DownloadSegmentedInit:
        return QCoreApplication::translate("SDO", "SDO segmented write %1, %2 bytes").arg(obj).arg(m.value);
    case SdoKind::DownloadSegment: return QCoreApplication::translate("SDO", "SDO segment");
    case SdoKind::DownloadReply: return QCoreApplication::translate("SDO", "SDO write %1 confirmed").arg(obj);
    case SdoKind::DownloadSegmentReply: return QCoreApplication::translate("SDO", "SDO segment confirmed");
    case SdoKind::UploadRequest: return QCoreApplication::translate("SDO", "SDO read %1").arg(obj);
    case SdoKind::UploadExpedited: return QCoreApplication::translate("SDO", "SDO read %1 -> %2").arg(obj).arg(m.value);
    case SdoKind::UploadSegmentedInit:
        return QCoreApplication::translate("SDO", "SDO read %1: segmented, %2 bytes").arg(obj).arg(m.value);
    case SdoKind::Abort: return QCoreApplication::translate("SDO", "SDO abort %1: %2").arg(obj, abortText(m.value));
    case SdoKind::Unknown: break;
    }
    return QCoreApplication::translate("SDO", "SDO command 0x%1").arg(m.cs, 2, 16, QLatin1Char('0'));
}

} // namespace imudesk::protocol::can::canopen
