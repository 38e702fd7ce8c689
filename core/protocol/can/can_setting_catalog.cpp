#include "protocol/can/can_setting_catalog.h"

#include "protocol/can/canopen.h"
#include "protocol/can/hec495_can.h"
#include "protocol/can/hipnuc_canopen_objects.h"
#include "protocol/can/j1939.h"
#include "protocol/can/j1939_config.h"
#include "protocol/modbus/register_map.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>

namespace imudesk::protocol::can {

namespace hip = protocol::can::canopen::hipnuc;

namespace {

struct Texts {
    Q_DECLARE_TR_FUNCTIONS(CanSettingCatalog)
};

// The codes of a device's own bit-rate setting (J1939 register 0x9A, CANopen object 0x209A,
// HEC495 object 0x1020) and the rate each stands for, fastest first (the codes' order).
std::vector<std::pair<uint32_t, int>> rateCodes(CanProtocol protocol, bool hec495Extended)
{
    int (*rateOf)(uint32_t) = nullptr;
    switch (protocol) {
    case CanProtocol::J1939: rateOf = &j1939::baudFromCode; break;  // 7.20: 125K-1000K incl. 800K
    case CanProtocol::CanOpen: rateOf = &hip::baudFromCode; break;  // 0x209A's four
    case CanProtocol::Hec495: rateOf = &hec495::baudFromCode; break;
    case CanProtocol::Auto: return {};
    }
    std::vector<std::pair<uint32_t, int>> out;
    for (uint32_t code = 0; code <= 8; ++code)
        if (const int rate = rateOf(code);
            rate > 0 && (protocol != CanProtocol::Hec495 || hec495TakesBitrate(rate, hec495Extended)))
            out.emplace_back(code, rate);
    return out;
}

// The bit-rate setting of a protocol's catalogue: shown and typed in bit/s, stored as its code.
CanSetting bitRate(CanProtocol protocol, CanSetting::Access access, uint16_t address, const QString &note,
                   bool hec495Extended = false)
{
    CanSetting s;
    s.name = QStringLiteral("bitrate");
    s.label = Texts::tr("CAN bit rate");
    s.unit = QStringLiteral("bit/s");
    s.access = access;
    s.address = address;
    for (const auto &[code, rate] : rateCodes(protocol, hec495Extended))
        s.choices.emplace_back(code, QString::number(rate));
    s.min = s.choices.front().first;
    s.max = s.choices.back().first;
    s.note = note;
    return s;
}

CanSetting number(const QString &name, const QString &label, const QString &unit, CanSetting::Access access,
                  uint16_t address, uint32_t min, uint32_t max)
{
    CanSetting s;
    s.name = name;
    s.label = label;
    s.unit = unit;
    s.access = access;
    s.address = address;
    s.min = min;
    s.max = max;
    return s;
}

CanSetting sign(const QString &name, const QString &label, CanSetting::Access access, uint16_t address)
{
    CanSetting s = number(name, label, QString(), access, address, 0, 1);
    s.choices = {{0, Texts::tr("default")}, {1, Texts::tr("reversed")}};
    return s;
}

// URFR 0xA6 takes the v1.6.6 index (0..4) or a v1.7.1 URFR code (6.17.25): the J1939 session
// does not know which manual its module follows, and the two sets do not overlap.
bool urfrAccepts(uint32_t raw)
{
    namespace mb = protocol::modbus;
    if (raw > 0xFFFF)
        return false;
    for (const mb::RegisterDef &d : mb::RegisterMap::hipnucAll().registers())
        if (d.address == mb::reg::kUrfr && mb::RegisterMap::accepts(d, uint16_t(raw)))
            return true;
    return false;
}

// 7.22.41: "the register address map: see the register list of the Modbus chapter" (6.16). Its
// registers by the list's names, but for CTRL (the save, factory and reset actions), SW_VERSION
// (the catalogue's "version") and 0xA5 (the attitude-reset actions).
void modbusListRegisters(std::vector<CanSetting> &out)
{
    namespace mb = protocol::modbus;
    using A = CanSetting::Access;
    using F = CanSetting::Format;
    for (const mb::RegisterDef &d : mb::RegisterMap::hipnuc(model::ManualEdition::V171).registers()) {
        if (d.address == mb::reg::kCtrl || d.address == mb::reg::kSwVersion || d.address == mb::reg::kAutoLevel)
            continue;
        CanSetting s = number(QString::fromLatin1(d.name), mb::RegisterMap::describe(d), QString::fromLatin1(d.unit),
                              A::J1939Register, d.address, 0, 0xFFFF);
        s.readable = d.readable();
        s.writable = d.writable();
        s.words = d.words;
        s.scale = d.scale;
        switch (d.type) {
        case mb::RegType::I16: s.format = F::Signed16; break;
        case mb::RegType::I32: s.format = F::Signed32; break;
        case mb::RegType::Ascii: s.format = F::Ascii; break;
        case mb::RegType::Bytes: s.format = F::Hex; break;
        case mb::RegType::U16:
        case mb::RegType::F32LE: break;
        }
        switch (d.rule) {
        case mb::ValueRule::BaudCode: {
            static const int bauds[] = {4800, 9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600};
            for (uint32_t code = 0; code < 9; ++code)
                s.choices.emplace_back(code, QString::number(bauds[code]));
            s.unit = QStringLiteral("bit/s");
            s.note = Texts::tr("the serial port's baud rate; takes effect after save and reset");
            break;
        }
        case mb::ValueRule::NodeId:
            s.min = 1;
            s.max = 128;
            s.note = Texts::tr("the Modbus address of the serial port");
            break;
        case mb::ValueRule::HeadingMode:
            s.choices = {{0, Texts::tr("6-axis (relative heading)")}, {1, Texts::tr("9-axis (absolute heading)")}};
            break;
        case mb::ValueRule::UrfrCode:
        case mb::ValueRule::UrfrIndex:
            s.accepts = &urfrAccepts;
            s.min = 1; // [min, max] empty: urfrAccepts alone decides
            s.max = 0;
            s.note = Texts::tr("v1.6.6: 0-4; v1.7.1: the URFR code (0x18 = 024 ...); the manual gives no read");
            break;
        default: break;
        }
        if (!s.writable && s.note.isEmpty())
            s.note = Texts::tr("read only");
        out.push_back(s);
    }
}

std::vector<CanSetting> j1939Settings()
{
    using A = CanSetting::Access;
    std::vector<CanSetting> out;
    const std::pair<uint32_t, const char *> pgns[] = {
        {j1939::PgnTime, QT_TRANSLATE_NOOP("CanSettingCatalog", "UTC time (FF2F) interval")},
        {j1939::PgnAcc, QT_TRANSLATE_NOOP("CanSettingCatalog", "Acceleration (FF34) interval")},
        {j1939::PgnGyr, QT_TRANSLATE_NOOP("CanSettingCatalog", "Angular rate (FF37) interval")},
        {j1939::PgnMag, QT_TRANSLATE_NOOP("CanSettingCatalog", "Magnetic field (FF3A) interval")},
        {j1939::PgnRollPitch, QT_TRANSLATE_NOOP("CanSettingCatalog", "Pitch and roll (FF3D) interval")},
        {j1939::PgnHeading, QT_TRANSLATE_NOOP("CanSettingCatalog", "Heading (FF41) interval")},
        {j1939::PgnQuat, QT_TRANSLATE_NOOP("CanSettingCatalog", "Quaternion (FF46) interval")},
        {j1939::PgnIncl, QT_TRANSLATE_NOOP("CanSettingCatalog", "Inclinometer (FF4A) interval")},
        {j1939::PgnCanFd0, QT_TRANSLATE_NOOP("CanSettingCatalog", "CAN FD frame 0 (FF5A) interval")},
    };
    for (const auto &[pgn, label] : pgns) {
        CanSetting s = number(QStringLiteral("interval-%1").arg(pgn, 0, 16), Texts::tr(label), QStringLiteral("ms"),
                              A::J1939Register, j1939::intervalRegister(pgn), uint32_t(j1939::kMinIntervalMs),
                              uint32_t(j1939::kMaxIntervalMs));
        if (pgn == j1939::PgnCanFd0)
            s.note = Texts::tr("only on a module with CAN FD output enabled; the manual gives no command to enable it");
        out.push_back(s);
    }
    out.push_back(bitRate(CanProtocol::J1939, A::J1939Register, j1939::RegBaud,
                          Texts::tr("takes effect after save and reset")));
    out.push_back(number(QStringLiteral("node-id"), Texts::tr("Source address (node ID)"), QString(), A::J1939Register,
                         j1939::RegNodeId, 1, 127));
    CanSetting output = number(QStringLiteral("output"), Texts::tr("Data output"), QString(), A::J1939Register,
                               j1939::RegOutputEnable, 0, 1);
    output.choices = {{0, Texts::tr("off")}, {1, Texts::tr("on")}};
    out.push_back(output);
    out.push_back(sign(QStringLiteral("incl-sign-x"), Texts::tr("Inclinometer X direction"), A::J1939Register,
                       j1939::RegInclSignX));
    out.push_back(sign(QStringLiteral("incl-sign-y"), Texts::tr("Inclinometer Y direction"), A::J1939Register,
                       j1939::RegInclSignY));
    CanSetting version = number(QStringLiteral("version"), Texts::tr("Firmware version"), QString(), A::J1939Register,
                                j1939::RegVersion, 0, 0xFFFFFFFF);
    version.writable = false;
    out.push_back(version);
    modbusListRegisters(out);
    return out;
}

std::vector<CanSetting> canopenSettings(uint16_t nodeIdObject)
{
    using A = CanSetting::Access;
    std::vector<CanSetting> out;
    for (int c = 0; c < canopen::kTpdoCount; ++c) {
        const int n = canopen::tpdoNumber(c);
        CanSetting period = number(QStringLiteral("tpdo%1-period").arg(n),
                                   Texts::tr("TPDO%1 (%2) period").arg(n).arg(QLatin1String(canopen::tpdoContent(c))),
                                   QStringLiteral("ms"), A::CanOpenObject, canopen::tpdoCommIndex(c), 0, 0xFFFF);
        period.sub = hip::kSubEventTimer;
        period.size = 2;
        period.note = Texts::tr("0 = off");
        out.push_back(period);
        CanSetting mode = number(QStringLiteral("tpdo%1-mode").arg(n), Texts::tr("TPDO%1 transmission").arg(n), QString(),
                                 A::CanOpenObject, canopen::tpdoCommIndex(c), 0, 0xFF);
        mode.sub = hip::kSubTransmissionType;
        mode.size = 1;
        mode.choices = {{hip::kTransmissionSync, Texts::tr("on each SYNC")},
                        {0xFE, Texts::tr("timed (0xFE)")},
                        {hip::kTransmissionAsync, Texts::tr("timed (0xFF)")}};
        out.push_back(mode);
    }
    CanSetting heartbeat = number(QStringLiteral("heartbeat"), Texts::tr("Heartbeat period"), QStringLiteral("ms"),
                                  A::CanOpenObject, hip::ObjHeartbeat, 0, 0xFFFF);
    heartbeat.size = 2;
    heartbeat.note = Texts::tr("0 = off");
    out.push_back(heartbeat);
    out.push_back(bitRate(CanProtocol::CanOpen, A::CanOpenObject, hip::ObjBaud,
                          Texts::tr("takes effect after save and reset")));
    CanSetting node = number(QStringLiteral("node-id"), Texts::tr("Node ID"), QString(), A::CanOpenObject, nodeIdObject,
                             1, 127);
    node.note = Texts::tr("takes effect after save and reset");
    out.push_back(node);
    out.push_back(sign(QStringLiteral("incl-sign-x"), Texts::tr("Inclinometer X direction"), A::CanOpenObject,
                       hip::ObjInclSignX));
    out.push_back(sign(QStringLiteral("incl-sign-y"), Texts::tr("Inclinometer Y direction"), A::CanOpenObject,
                       hip::ObjInclSignY));
    return out;
}

std::vector<CanSetting> hec495Settings(bool extended)
{
    using A = CanSetting::Access;
    const QString notRead = Texts::tr("written only: the manual documents no way to read it back");
    std::vector<CanSetting> out;
    auto add = [&](CanSetting s) {
        s.readable = false;
        s.size = 1;
        s.note = s.note.isEmpty() ? notRead : s.note + QStringLiteral("; ") + notRead;
        out.push_back(std::move(s));
    };
    CanSetting rate = number(QStringLiteral("pdo-rate"), Texts::tr("Output rate"), QString(), A::Hec495Object,
                             hec495::ObjPdoRate, 0, 6);
    rate.choices = {{0, Texts::tr("off")}};
    for (uint32_t code = 1; code <= 6; ++code)
        rate.choices.emplace_back(code, Texts::tr("%1 Hz").arg(hec495::rateHzFromCode(code)));
    add(rate);
    CanSetting pdo = number(QStringLiteral("pdo-mode"), Texts::tr("PDO mode"), QString(), A::Hec495Object,
                            hec495::ObjPdoMode, 0, 3);
    pdo.choices = {{0, Texts::tr("float")}, {1, Texts::tr("fixed point")}, {3, Texts::tr("float, 0x180/0x280 only")}};
    add(pdo);
    CanSetting work = number(QStringLiteral("work-mode"), Texts::tr("Work mode"), QString(), A::Hec495Object,
                             hec495::ObjWorkMode, 0x02, 0x0A);
    work.choices = {{0x02, Texts::tr("angles, acceleration, rate")}, {0x0A, Texts::tr("rate at 500 Hz")}};
    add(work);
    CanSetting start = number(QStringLiteral("output"), Texts::tr("Data output"), QString(), A::Hec495Object,
                              hec495::ObjPdoStart, 0, 1);
    start.choices = {{0, Texts::tr("off")}, {1, Texts::tr("on")}};
    add(start);
    CanSetting heartbeat = number(QStringLiteral("heartbeat"), Texts::tr("Heartbeat (100 ms x (N + 1))"), QString(),
                                  A::Hec495Object, hec495::ObjHeartbeat, 0, 255);
    add(heartbeat);
    add(bitRate(CanProtocol::Hec495, A::Hec495Object, hec495::ObjBaud, Texts::tr("takes effect after a power cycle"),
                extended));
    CanSetting node = number(QStringLiteral("node-id"), Texts::tr("Node ID"), QString(), A::Hec495Object,
                             hec495::ObjNodeId, 1, 127);
    node.note = Texts::tr("takes effect after a power cycle");
    add(node);
    return out;
}

} // namespace

QString CanSetting::show(uint32_t raw) const
{
    if (format == Format::Signed16)
        return QString::number(double(int16_t(uint16_t(raw))) * scale, 'g', 6);
    if (format == Format::Signed32)
        return QString::number(double(int32_t(raw)) * scale, 'g', 8);
    if (format != Format::Code)
        return showWords({raw});
    if (choices.empty())
        return QString::number(raw);
    for (const auto &[code, text] : choices)
        if (code == raw)
            return text;
    return Texts::tr("code %1 (not in the manual)").arg(raw);
}

QString CanSetting::showWords(const std::vector<uint32_t> &registers) const
{
    switch (format) {
    case Format::Signed32:
        // High word first (R_H, R_L).
        if (registers.size() >= 2)
            return show((registers[0] & 0xFFFF) << 16 | (registers[1] & 0xFFFF));
        break;
    case Format::Ascii: {
        QByteArray text;
        for (uint32_t r : registers)
            text.append(char((r >> 8) & 0xFF)).append(char(r & 0xFF));
        const int end = text.indexOf('\0');
        return QString::fromLatin1(end < 0 ? text : text.left(end)).trimmed();
    }
    case Format::Hex: {
        QString text;
        for (uint32_t r : registers)
            text += QStringLiteral("%1").arg(r & 0xFFFF, 4, 16, QLatin1Char('0')).toUpper();
        return text;
    }
    case Format::Code:
    case Format::Signed16: break;
    }
    return registers.empty() ? QString() : show(registers.back());
}

std::optional<uint32_t> CanSetting::parse(const QString &input, QString *error) const
{
    QString text = input.trimmed();
    auto fail = [&](const QString &why) -> std::optional<uint32_t> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (!writable)
        return fail(Texts::tr("%1 is read only").arg(name));
    // A choice by its text ("500000", "on", "reversed"), else a number.
    for (const auto &[code, shown] : choices)
        if (shown.compare(text, Qt::CaseInsensitive) == 0)
            return code;
    bool ok = false;
    qulonglong v = 0;
    QString digits = text;
    double scale = 1;
    if (unit == QLatin1String("bit/s") && (digits.endsWith(QLatin1Char('k'), Qt::CaseInsensitive))) {
        digits.chop(1);
        scale = 1000;
    } else if (unit == QLatin1String("bit/s") && digits.endsWith(QLatin1Char('M'), Qt::CaseInsensitive)) {
        digits.chop(1);
        scale = 1000000;
    }
    if (digits.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
        v = digits.mid(2).toULongLong(&ok, 16);
    else if (scale != 1)
        v = qulonglong(digits.toDouble(&ok) * scale + 0.5);
    else
        v = digits.toULongLong(&ok, 10);
    if (!ok || v > 0xFFFFFFFFull)
        return fail(Texts::tr("%1: \"%2\" is not a number (%3)").arg(name, input, range()));
    if (!choices.empty()) {
        // A bit rate is given in bit/s (the module takes its code); any choice by its code.
        for (const auto &[code, shown] : choices)
            if (shown == QString::number(v))
                return code;
        for (const auto &[code, shown] : choices)
            if (code == v)
                return code;
        return fail(Texts::tr("%1 takes %2").arg(name, range()));
    }
    if ((v < min || v > max) && !(accepts && accepts(uint32_t(v))))
        return fail(Texts::tr("%1 takes %2").arg(name, range()));
    return uint32_t(v);
}

QString CanSetting::range() const
{
    if (!choices.empty()) {
        QStringList shown;
        for (const auto &[code, text] : choices)
            shown << text;
        return shown.join(QStringLiteral(", "));
    }
    if (accepts && min > max)
        return note;
    if (!writable && format != Format::Code)
        return unit.isEmpty() ? Texts::tr("read only") : unit;
    const QString r = QStringLiteral("%1-%2").arg(min).arg(max);
    return unit.isEmpty() ? r : r + QLatin1Char(' ') + unit;
}

bool hec495TakesBitrate(int bitrate, bool extended)
{
    return bitrate > 0 && (extended || bitrate != 30000);
}

std::vector<CanSetting> canSettings(CanProtocol protocol, uint16_t nodeIdObject, bool hec495Extended)
{
    switch (protocol) {
    case CanProtocol::J1939: return j1939Settings();
    case CanProtocol::CanOpen: return canopenSettings(nodeIdObject);
    case CanProtocol::Hec495: return hec495Settings(hec495Extended);
    case CanProtocol::Auto: break;
    }
    return {};
}

std::optional<CanSetting> findCanSetting(CanProtocol protocol, const QString &name, uint16_t nodeIdObject)
{
    for (CanSetting &s : canSettings(protocol, nodeIdObject))
        if (s.name.compare(name, Qt::CaseInsensitive) == 0)
            return std::move(s);
    return std::nullopt;
}

CanBitrates canBitrates(CanProtocol protocol, bool hec495Extended)
{
    CanBitrates b;
    for (const auto &[code, rate] : rateCodes(protocol, hec495Extended))
        b.rates.push_back(rate);
    switch (protocol) {
    case CanProtocol::J1939:   // 7.20: 500K from the factory
    case CanProtocol::CanOpen: // 8.25: 500K
        break;
    case CanProtocol::Hec495:
        b.factory = hec495::kDefaultBitrate; // 250K
        break;
    case CanProtocol::Auto:
        for (CanProtocol p : {CanProtocol::J1939, CanProtocol::CanOpen, CanProtocol::Hec495})
            for (int r : canBitrates(p).rates)
                if (std::find(b.rates.begin(), b.rates.end(), r) == b.rates.end())
                    b.rates.push_back(r);
        std::sort(b.rates.begin(), b.rates.end(), std::greater<>());
        break;
    }
    return b;
}

} // namespace imudesk::protocol::can
