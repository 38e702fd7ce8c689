#include "can_decoder.h"
#include "canopen.h"
#include "hec495_can.h"
#include "j1939.h"
#include "j1939_config.h"
#include "sdo.h"

namespace imudesk::protocol::can {

const char *protocolName(CanProtocol p)
{
    switch (p) {
    case CanProtocol::Auto: return "auto";
    case CanProtocol::J1939: return "j1939";
    case CanProtocol::CanOpen: return "canopen";
    case CanProtocol::Hec495: return "hec495";
    }
    return "?";
}

std::optional<CanProtocol> parseProtocol(const QString &text)
{
    const QString t = text.trimmed().toLower();
    for (CanProtocol p : {CanProtocol::Auto, CanProtocol::J1939, CanProtocol::CanOpen, CanProtocol::Hec495})
        if (t == QLatin1String(protocolName(p)))
            return p;
    return std::nullopt;
}

CanDecoder::CanDecoder(CanProtocol protocol) : m_protocol(protocol) {}

void CanDecoder::setProtocol(CanProtocol p)
{
    m_protocol = p;
    m_detected = CanProtocol::Auto;
}

namespace {
QString vec(const model::Vec3 &v, int prec)
{
    return QStringLiteral("%1, %2, %3").arg(v.x, 0, 'f', prec).arg(v.y, 0, 'f', prec).arg(v.z, 0, 'f', prec);
}

QString sampleText(const model::Sample &s)
{
    QStringList parts;
    if (s.has(model::FieldAcc)) parts << QStringLiteral("acc %1 G").arg(vec(s.acc, 4));
    if (s.has(model::FieldGyr)) parts << QStringLiteral("gyr %1 deg/s").arg(vec(s.gyr, 2));
    if (s.has(model::FieldMag)) parts << QStringLiteral("mag %1 uT").arg(vec(s.mag, 3));
    if (s.has(model::FieldMagRelative)) parts << QStringLiteral("mag %1 (relative)").arg(vec(s.magRelative, 3));
    if (s.has(model::FieldEuler))
        parts << QStringLiteral("roll %1 pitch %2 yaw %3 deg").arg(s.roll, 0, 'f', 2).arg(s.pitch, 0, 'f', 2).arg(s.yaw, 0, 'f', 2);
    if (s.has(model::FieldQuat))
        parts << QStringLiteral("q %1, %2, %3, %4").arg(s.quat.w, 0, 'f', 4).arg(s.quat.x, 0, 'f', 4).arg(s.quat.y, 0, 'f', 4).arg(s.quat.z, 0, 'f', 4);
    if (s.has(model::FieldPressure)) parts << QStringLiteral("pressure %1 Pa").arg(s.pressurePa, 0, 'f', 0);
    if (s.has(model::FieldInclination))
        parts << QStringLiteral("incl %1, %2 deg").arg(s.inclinationX, 0, 'f', 3).arg(s.inclinationY, 0, 'f', 3);
    if (s.has(model::FieldTemperature)) parts << QStringLiteral("%1 degC").arg(s.temperatureC, 0, 'f', 2);
    return parts.join(QStringLiteral("; "));
}
} // namespace

DecodedFrame CanDecoder::decode(const CanFrame &f)
{
    ++m_counters.frames;
    DecodedFrame d;
    const bool known = f.extended ? decodeJ1939(f, d) : decodeStandard(f, d);
    if (!known) {
        ++m_counters.unknownFrames;
        if (d.meaning.isEmpty())
            d.meaning = tr("unknown");
    } else if (d.sample) {
        ++m_counters.dataFrames;
    } else if (d.kind != FrameKind::Unknown) {
        ++m_counters.configFrames;
    }
    return d;
}

bool CanDecoder::decodeJ1939(const CanFrame &f, DecodedFrame &d)
{
    if (const auto h = hec495::decodeExtended(f)) {
        d.kind = FrameKind::Hec495Data;
        d.protocol = CanProtocol::Hec495;
        d.sample = h->sample;
        d.components = h->components;
        d.meaning = tr("HEC495 %1 axis: %2").arg(h->slot ? QStringLiteral("Y") : QStringLiteral("X"), sampleText(h->sample));
        if (m_detected == CanProtocol::Auto)
            m_detected = CanProtocol::Hec495;
        return true;
    }
    if (const auto w = hec495::parseWrite(f); w && w->extended) {
        d.kind = FrameKind::Hec495Sdo;
        d.protocol = CanProtocol::Hec495;
        d.meaning = w->reply ? tr("HEC495 write 0x%1 confirmed").arg(w->index, 4, 16, QLatin1Char('0'))
                             : tr("HEC495 write %1").arg(hec495::describeObject(w->index, w->value));
        return true;
    }
    const j1939::DecodeResult r = j1939::decodeData(f);
    const j1939::Id id = j1939::parseId(f.id);
    if (r.ok()) {
        d.kind = FrameKind::J1939Data;
        d.protocol = CanProtocol::J1939;
        d.node = r.data.sourceAddress;
        const char *name = j1939::pgnName(r.data.pgn);
        if (r.data.time && !r.data.time->dateKnown()) {
            // No UTC: the frame's clock is the module's own (its running time), so it becomes no
            // UTC time of day in the samples; the monitor says so.
            const auto &t = *r.data.time;
            d.meaning = tr("PGN %1 %2: date unknown, not UTC (module clock %3:%4:%5.%6)")
                            .arg(QString::number(r.data.pgn, 16).toUpper(), QLatin1String(name))
                            .arg(t.hour, 2, 10, QLatin1Char('0')).arg(t.minute, 2, 10, QLatin1Char('0'))
                            .arg(t.second, 2, 10, QLatin1Char('0')).arg(t.ms, 3, 10, QLatin1Char('0'));
        } else if (r.data.time) {
            const auto &t = *r.data.time;
            d.meaning = tr("PGN %1 %2: %3-%4-%5 %6:%7:%8.%9")
                            .arg(QString::number(r.data.pgn, 16).toUpper(), QLatin1String(name))
                            .arg(t.year).arg(t.month, 2, 10, QLatin1Char('0')).arg(t.day, 2, 10, QLatin1Char('0'))
                            .arg(t.hour, 2, 10, QLatin1Char('0')).arg(t.minute, 2, 10, QLatin1Char('0'))
                            .arg(t.second, 2, 10, QLatin1Char('0')).arg(t.ms, 3, 10, QLatin1Char('0'));
            // The UTC time of day (7.21.31) joins the samples like the serial side's (values
            // table, recording, JSON "utc_time_s"); the date stays in the monitor's line.
            model::Sample s = r.data.sample;
            s.utcTimeOfDayS = t.hour * 3600.0 + t.minute * 60.0 + t.second + t.ms / 1000.0;
            s.fields |= model::FieldGnss;
            d.sample = s;
            d.components = CompUtcTime;
        } else {
            d.sample = r.data.sample;
            d.components = componentsOf(r.data.sample.fields);
            if (r.data.pgn == j1939::PgnRollPitch)
                d.components &= ~uint32_t(CompYaw);
            else if (r.data.pgn == j1939::PgnHeading)
                d.components &= ~uint32_t(CompRoll | CompPitch);
            QString text = sampleText(r.data.sample);
            if (r.data.pgn == j1939::PgnHeading)
                text = tr("heading %1 deg (CW); %2").arg(r.data.headingCwDeg, 0, 'f', 3).arg(text);
            d.meaning = QStringLiteral("PGN %1 %2: %3").arg(QString::number(r.data.pgn, 16).toUpper(), QLatin1String(name), text);
        }
        if (m_detected == CanProtocol::Auto)
            m_detected = CanProtocol::J1939;
        return true;
    }
    if (r.error == j1939::DecodeError::TooShort || r.error == j1939::DecodeError::RemoteFrame) {
        ++m_counters.malformed;
        d.meaning = tr("PGN %1: %2").arg(QString::number(id.pgn(), 16).toUpper(), QLatin1String(j1939::errorName(r.error)));
        return false;
    }
    if (const auto m = j1939::parseReg(f)) {
        d.kind = FrameKind::J1939Config;
        d.protocol = CanProtocol::J1939;
        d.node = m->sa;
        d.meaning = tr("config %1 -> %2: %3").arg(m->sa).arg(m->da).arg(j1939::describe(*m));
        return true;
    }
    return false;
}

bool CanDecoder::decodeStandard(const CanFrame &f, DecodedFrame &d)
{
    using namespace canopen;
    if (f.id > 0x7FF)
        return false;
    if (const auto n = parseNmt(f)) {
        d.kind = FrameKind::Nmt;
        d.node = n->node;
        d.meaning = tr("NMT command 0x%1 to node %2").arg(n->command, 2, 16, QLatin1Char('0')).arg(n->node);
        return true;
    }
    if (isSync(f)) {
        d.kind = FrameKind::Sync;
        d.protocol = CanProtocol::CanOpen;
        d.meaning = tr("SYNC");
        return true;
    }
    if (const auto h = parseHeartbeat(f)) {
        d.kind = FrameKind::Heartbeat;
        d.node = h->node;
        d.meaning = tr("heartbeat node %1: %2").arg(h->node).arg(QLatin1String(stateName(h->state)));
        return true;
    }
    if (const auto s = parseSdo(f)) {
        d.node = s->node;
        if (effective() == CanProtocol::Hec495 && (s->cs == 0x22 || s->cs == 0x60)) {
            d.kind = FrameKind::Hec495Sdo;
            d.protocol = CanProtocol::Hec495;
            d.meaning = s->fromDevice ? tr("HEC495 write 0x%1 confirmed").arg(s->index, 4, 16, QLatin1Char('0'))
                                      : tr("HEC495 write %1").arg(hec495::describeObject(s->index, uint8_t(s->value)));
        } else {
            d.kind = FrameKind::Sdo;
            d.meaning = (s->fromDevice ? tr("node %1: ") : tr("to node %1: ")).arg(s->node) + describe(*s);
        }
        return true;
    }
    const CanProtocol eff = effective();
    const int hecSlot = hec495::pdoSlotOfId(f.id);
    const bool hecOnly = hecSlot >= 4 || (f.len == 8 && (hecSlot == 0 || hecSlot == 1 || hecSlot == 2));
    if (eff == CanProtocol::Hec495 || (eff == CanProtocol::Auto && hecOnly)) {
        if (const auto p = hec495::decodePdo(f, m_hecMode)) {
            d.kind = FrameKind::Hec495Data;
            d.protocol = CanProtocol::Hec495;
            d.node = p->node;
            d.sample = p->sample;
            d.components = p->components;
            d.meaning = tr("HEC495 PDO %1 (%2): %3")
                            .arg(QStringLiteral("%1").arg(hec495::pdoBase(p->slot), 3, 16).toUpper())
                            .arg(p->fixed ? tr("fixed") : tr("float"), sampleText(p->sample));
            if (m_detected == CanProtocol::Auto)
                m_detected = CanProtocol::Hec495;
            return true;
        }
    }
    const TpdoResult t = decodeTpdo(f);
    if (t.ok()) {
        d.kind = FrameKind::TpdoData;
        d.protocol = CanProtocol::CanOpen;
        d.node = t.node;
        d.sample = t.sample;
        d.components = componentsOf(t.sample.fields);
        d.meaning = tr("TPDO%1 %2: %3").arg(tpdoNumber(t.channel)).arg(QLatin1String(tpdoContent(t.channel)), sampleText(t.sample));
        if (m_detected == CanProtocol::Auto && t.channel <= 2)
            m_detected = CanProtocol::CanOpen;
        return true;
    }
    if (t.error == TpdoError::WrongLength || t.error == TpdoError::Remote) {
        ++m_counters.malformed;
        d.meaning = tr("TPDO with a wrong length (%1 bytes)").arg(f.len);
    }
    return false;
}

void mergeComponents(model::Sample &dst, const model::Sample &src, uint32_t c)
{
    if (c & CompAccX) dst.acc.x = src.acc.x;
    if (c & CompAccY) dst.acc.y = src.acc.y;
    if (c & CompAccZ) dst.acc.z = src.acc.z;
    if (c & CompGyrX) dst.gyr.x = src.gyr.x;
    if (c & CompGyrY) dst.gyr.y = src.gyr.y;
    if (c & CompGyrZ) dst.gyr.z = src.gyr.z;
    if (c & CompMagX) dst.mag.x = src.mag.x;
    if (c & CompMagY) dst.mag.y = src.mag.y;
    if (c & CompMagZ) dst.mag.z = src.mag.z;
    if (c & CompRoll) dst.roll = src.roll;
    if (c & CompPitch) dst.pitch = src.pitch;
    if (c & CompYaw) {
        dst.yaw = src.yaw;
        dst.headingDeg = src.headingDeg;
        dst.headingTrue = src.headingTrue;
        dst.fields |= src.fields & model::FieldHeading;
    }
    if (c & CompQuat) dst.quat = src.quat;
    if (c & CompPressure) dst.pressurePa = src.pressurePa;
    if (c & CompTemperature) dst.temperatureC = src.temperatureC;
    if (c & CompInclination) {
        dst.inclinationX = src.inclinationX;
        dst.inclinationY = src.inclinationY;
    }
    if (c & CompDeviceTime) dst.deviceTimeMs = src.deviceTimeMs;
    if (c & CompMainStatus) dst.mainStatus = src.mainStatus;
    if (c & CompUtcTime) dst.utcTimeOfDayS = src.utcTimeOfDayS;
    dst.fields |= src.fields;
    dst.source = src.source;
}


const char *frameKindName(FrameKind k)
{
    switch (k) {
    case FrameKind::J1939Data: return "J1939 data";
    case FrameKind::J1939Config: return "J1939 config";
    case FrameKind::TpdoData: return "TPDO";
    case FrameKind::Hec495Data: return "HEC495 PDO";
    case FrameKind::Sdo: return "SDO";
    case FrameKind::Hec495Sdo: return "HEC495 SDO";
    case FrameKind::Nmt: return "NMT";
    case FrameKind::Sync: return "SYNC";
    case FrameKind::Heartbeat: return "heartbeat";
    case FrameKind::Unknown: break;
    }
    return "other";
}

} // namespace imudesk::protocol::can
