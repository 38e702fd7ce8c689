#include "setting_catalog.h"

#include "model/mounting.h"
#include "protocol/hipnuc/payloads.h"

#include <cmath>

namespace imudesk::settings {

namespace hp = protocol::hipnuc;
using model::ManualEdition;
using Msg = protocol::hipnuc::Message;

namespace {

constexpr const char *kCtx = "SettingCatalog";

SettingDefinition message(const char *key, const char *comKey, Msg m, bool v166, bool v171, const char *label)
{
    return SettingDefinition{key, comKey, SettingKind::MessageOutput, v166, v171, Feature::None, Persistence::Immediate,
                             label,
                             QT_TRANSLATE_NOOP("SettingCatalog",
                                               "Output of this message on this port: off, every period (ONTIME "
                                               "0.001 s = 1 kHz .. 1 s = 1 Hz) or on each SYNC_IN/PPS rising edge "
                                               "(ONMARK 1)."),
                             m};
}

std::vector<SettingDefinition> buildSettings()
{
    std::vector<SettingDefinition> s;
    s.push_back({"SERIAL.BAUD", "BAUD", SettingKind::Baud, true, true, Feature::None, Persistence::Immediate,
                 QT_TRANSLATE_NOOP("SettingCatalog", "Serial baud rate"),
                 QT_TRANSLATE_NOOP("SettingCatalog",
                                   "SERIALCONFIG: the UART switches at once; ImuDesk follows and confirms with LOG "
                                   "VERSION. v1.7.1: 4800 .. 921600; v1.6.6: 9600, 115200, 256000, 460800, 921600.")});
    s.push_back({"LOG", "LOG", SettingKind::LogSwitch, true, true, Feature::None, Persistence::NeverSaved,
                 QT_TRANSLATE_NOOP("SettingCatalog", "Data output"),
                 QT_TRANSLATE_NOOP("SettingCatalog",
                                   "LOG ENABLE / LOG DISABLE: all data frames on or off. Output is enabled again after "
                                   "every start."),
                 Msg::HI91, 0, 0, 0, false});
    s.push_back(message("LOG.HI91", "HI91", Msg::HI91, true, true,
                        QT_TRANSLATE_NOOP("SettingCatalog", "HI91 output (float IMU frame)")));
    s.push_back(message("LOG.HI92", "HI92", Msg::HI92, true, false,
                        QT_TRANSLATE_NOOP("SettingCatalog", "HI92 output (integer IMU frame)")));
    s.push_back(message("LOG.HI81", "HI81", Msg::HI81, false, true,
                        QT_TRANSLATE_NOOP("SettingCatalog", "HI81 output (INS frame)")));
    s.push_back(message("LOG.HI83", "HI83", Msg::HI83, false, true,
                        QT_TRANSLATE_NOOP("SettingCatalog", "HI83 output (variable frame)")));
    s.push_back(message("LOG.GGA", "GGA", Msg::GGA, false, true,
                        QT_TRANSLATE_NOOP("SettingCatalog", "NMEA GGA output")));
    s.push_back(message("LOG.RMC", "RMC", Msg::RMC, false, true,
                        QT_TRANSLATE_NOOP("SettingCatalog", "NMEA RMC output")));
    s.push_back(message("LOG.SXT", "SXT", Msg::SXT, false, true,
                        QT_TRANSLATE_NOOP("SettingCatalog", "NMEA SXT output")));
    s.push_back({"LOG.HI83.MAP", "HI83_MAP", SettingKind::Hi83Map, false, true, Feature::None, Persistence::Immediate,
                 QT_TRANSLATE_NOOP("SettingCatalog", "HI83 fields (data_bitmap)"),
                 QT_TRANSLATE_NOOP("SettingCatalog",
                                   "LOG HI83 MAP: one bit per data segment (bit 0 acc, 1 gyr, 2 mag, 3 Euler, 4 "
                                   "quaternion, 5 time us, 6 UTC, 7 pressure, ..., 25 filter update counters, 26 and "
                                   "27 filter biases, 28 GNSS accuracy, 29 dual-antenna heading, 30 and 31 GNSS "
                                   "position and velocity; 20 to 24 are reserved); default 0x000000FF.")});
    s.push_back({"ATT.MODE", "ATT_MODE", SettingKind::Choice, true, true, Feature::None, Persistence::SaveAndReset,
                 QT_TRANSLATE_NOOP("SettingCatalog", "Working mode"),
                 QT_TRANSLATE_NOOP("SettingCatalog",
                                   "CONFIG ATT MODE: 0 VRU (6-axis), 1 AHRS (9-axis, magnetometer aided; calibrate "
                                   "the magnetometer first, avoid near motors and indoors), 4 humanoid robot "
                                   "(v1.7.1).")});
    s.push_back({"IMU.URFR", "URFR", SettingKind::Mounting, true, true, Feature::None, Persistence::SaveAndReset,
                 QT_TRANSLATE_NOOP("SettingCatalog", "Mounting (URFR)"),
                 QT_TRANSLATE_NOOP("SettingCatalog",
                                   "CONFIG IMU URFR: which sensor direction each user axis is (code ABC, 24 "
                                   "right-handed codes; 24 = X right, Y forward, Z up). Firmware below 1.7.1 takes "
                                   "the nine numbers of the matrix C as the manual's named mountings print it (X_U = C * X_B; "
                                   "1,0,0,0,0,1,0,-1,0 is Y down).")});
    s.push_back({"IMU.COORD", "COORD", SettingKind::Choice, false, true, Feature::None, Persistence::SaveAndReset,
                 QT_TRANSLATE_NOOP("SettingCatalog", "World frame"),
                 QT_TRANSLATE_NOOP("SettingCatalog",
                                   "CONFIG IMU COORD: 0 East-North-Up (ENU, default), 4 North-West-Up (NWU).")});
    for (int fn = 1; fn <= 3; ++fn) {
        static const char *keys[] = {"PMUX1", "PMUX2", "PMUX3"};
        static const char *labels[] = {
            QT_TRANSLATE_NOOP("SettingCatalog", "PMUX1 pin (SYNC_IN/PPS input)"),
            QT_TRANSLATE_NOOP("SettingCatalog", "PMUX2 pin (SOUT sync output)"),
            QT_TRANSLATE_NOOP("SettingCatalog", "PMUX3 pin (status LED)")};
        SettingDefinition d{keys[fn - 1], keys[fn - 1], SettingKind::PinMap, true, true, Feature::Pmux,
                            Persistence::SaveAndReset, labels[fn - 1],
                            QT_TRANSLATE_NOOP("SettingCatalog",
                                              "CONFIG PMUXn IOm: the IO pin that carries this function (defaults "
                                              "PMUX1 IO1, PMUX2 IO2, PMUX3 IO5). Not every IO is brought out on "
                                              "every product.")};
        d.pmuxFunction = fn;
        s.push_back(d);
    }
    SettingDefinition div{"PMUX2.DIV", "PMUX2_DIV", SettingKind::Integer, false, true, Feature::Pmux,
                          Persistence::SaveAndReset,
                          QT_TRANSLATE_NOOP("SettingCatalog", "SOUT divider"),
                          QT_TRANSLATE_NOOP("SettingCatalog",
                                            "CONFIG PMUX2 DIV: one SOUT pulse every N frames (1 .. 1000, default 1): "
                                            "at 100 Hz output, 5 gives 20 Hz pulses for a camera.")};
    div.minimum = 1;
    div.maximum = 1000;
    s.push_back(div);
    s.push_back({"IMU_EN_MCAL", "IMU_EN_MCAL", SettingKind::Choice, true, false, Feature::Magnetometer,
                 Persistence::Immediate,
                 QT_TRANSLATE_NOOP("SettingCatalog", "Background magnetometer calibration"),
                 QT_TRANSLATE_NOOP("SettingCatalog",
                                   "CONFIG IMU_EN_MCAL (v1.6.6): 1 calibrates the magnetometer in the background "
                                   "(factory default), 0 stops it; SAVECONFIG keeps it.")});
    return s;
}

std::vector<ActionDefinition> buildActions()
{
    return {
        {"ATT.RST.1", [] { return hp::commands::attReset(1); }, false, true, Feature::AttitudeCalibration,
         QT_TRANSLATE_NOOP("SettingCatalog", "Heading reset"),
         QT_TRANSLATE_NOOP("SettingCatalog",
                           "Sets the current heading to 0. Keep the device still while it runs.")},
        {"ATT.RST.2", [] { return hp::commands::attReset(2); }, true, true, Feature::AttitudeCalibration,
         QT_TRANSLATE_NOOP("SettingCatalog", "Relative level (zero pitch and roll)"),
         QT_TRANSLATE_NOOP("SettingCatalog",
                           "Makes the current pitch and roll the zero, whatever the tilt (no check). Keep the device "
                           "still; ATT RST 5 undoes it; SAVECONFIG keeps it.")},
        {"ATT.RST.3", [] { return hp::commands::attReset(3); }, true, true, Feature::AttitudeCalibration,
         QT_TRANSLATE_NOOP("SettingCatalog", "Automatic levelling"),
         QT_TRANSLATE_NOOP("SettingCatalog",
                           "Only when nearly level: pitch and roll both below 5 deg levels to 0/0, pitch below 5 deg "
                           "and roll near 180 deg levels to 0/180; otherwise refused (ERR). Keep the device still. "
                           "Permanent: ATT RST 5 does not undo it, only a factory reset does.")},
        {"ATT.RST.5", [] { return hp::commands::attReset(5); }, true, true, Feature::AttitudeCalibration,
         QT_TRANSLATE_NOOP("SettingCatalog", "Cancel relative level"),
         QT_TRANSLATE_NOOP("SettingCatalog",
                           "Clears the relative pitch/roll zero of ATT RST 2 and returns to absolute angles.")},
        {"YAW", nullptr, true, false, Feature::None,
         QT_TRANSLATE_NOOP("SettingCatalog", "Set heading (v1.6.6)"),
         QT_TRANSLATE_NOOP("SettingCatalog",
                           "CONFIG YAW MODE DEG: MODE 1 sets the heading to DEG (absolute), MODE 0 adds DEG "
                           "(relative); -180 .. 180 deg; at once, not saved. Value \"MODE,DEG\", e.g. 1,16.")},
        {"SAVECONFIG", hp::commands::saveConfig, true, true, Feature::None,
         QT_TRANSLATE_NOOP("SettingCatalog", "Save to flash"),
         QT_TRANSLATE_NOOP("SettingCatalog",
                           "Saves every setting to flash so that it survives a reset.")},
        {"REBOOT", hp::commands::reboot, true, true, Feature::None, QT_TRANSLATE_NOOP("SettingCatalog", "Reboot"),
         QT_TRANSLATE_NOOP("SettingCatalog",
                           "Resets the module (same as a power cycle): unsaved settings are lost, saved CONFIG "
                           "settings take effect.")},
        {"FRESET", hp::commands::factoryReset, true, true, Feature::None,
         QT_TRANSLATE_NOOP("SettingCatalog", "Factory reset"),
         QT_TRANSLATE_NOOP("SettingCatalog",
                           "Restores the factory settings, saves them and resets: baud 115200, HI91 at 100 Hz, "
                           "mounting 24, working mode, PMUX pins, output messages and ATT RST 3 levelling are all "
                           "lost.")},
    };
}

bool editionHas(bool v166, bool v171, const model::DeviceIdentity &id)
{
    return id.edition() == ManualEdition::V171 ? v171 : v166;
}

QString editionName(ManualEdition e)
{
    return e == ManualEdition::V171 ? QStringLiteral("1.7.1") : QStringLiteral("1.5.5 - 1.7.0");
}

bool parseInt(const QString &t, int *out)
{
    bool ok = false;
    const int v = t.trimmed().toInt(&ok, 10);
    if (ok)
        *out = v;
    return ok;
}

std::optional<double> parsePeriod(const QString &t)
{
    bool ok = false;
    const double v = t.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v))
        return std::nullopt;
    return v;
}

std::optional<model::Matrix3> parseMatrix(const QString &t)
{
    const QStringList parts = t.split(QLatin1Char(','));
    if (parts.size() != 9)
        return std::nullopt;
    model::Matrix3 m{};
    for (int i = 0; i < 9; ++i) {
        bool ok = false;
        const double v = parts.at(i).trimmed().toDouble(&ok);
        if (!ok || !std::isfinite(v))
            return std::nullopt;
        m[size_t(i / 3)][size_t(i % 3)] = v;
    }
    return m;
}

QString matrixText(const model::Matrix3 &m)
{
    QStringList parts;
    for (const auto &row : m)
        for (double v : row)
            parts << QString::fromStdString(hp::commands::formatNumber(v));
    return parts.join(QLatin1Char(','));
}

struct ChoiceRow {
    const char *key;
    int value;
    bool v166, v171;
    Feature feature;
    const char *label;
};

const ChoiceRow kChoices[] = {
    {"ATT.MODE", 0, true, true, Feature::None, QT_TRANSLATE_NOOP("SettingCatalog", "VRU (6-axis)")},
    {"ATT.MODE", 1, true, true, Feature::Magnetometer,
     QT_TRANSLATE_NOOP("SettingCatalog", "AHRS (9-axis, magnetometer aided)")},
    {"ATT.MODE", 4, false, true, Feature::None, QT_TRANSLATE_NOOP("SettingCatalog", "Humanoid robot")},
    {"IMU.COORD", 0, false, true, Feature::None,
     QT_TRANSLATE_NOOP("SettingCatalog", "East-North-Up (ENU)")},
    {"IMU.COORD", 4, false, true, Feature::None,
     QT_TRANSLATE_NOOP("SettingCatalog", "North-West-Up (NWU)")},
    {"IMU_EN_MCAL", 0, true, false, Feature::None, QT_TRANSLATE_NOOP("SettingCatalog", "Off")},
    {"IMU_EN_MCAL", 1, true, false, Feature::None,
     QT_TRANSLATE_NOOP("SettingCatalog", "On (factory default)")},
};

const ChoiceRow *choiceRow(const SettingDefinition &d, int value)
{
    for (const auto &c : kChoices)
        if (QLatin1String(c.key) == QLatin1String(d.key) && c.value == value)
            return &c;
    return nullptr;
}

} // namespace

const std::vector<SettingDefinition> &SettingCatalog::settings()
{
    static const std::vector<SettingDefinition> s = buildSettings();
    return s;
}

const std::vector<ActionDefinition> &SettingCatalog::actions()
{
    static const std::vector<ActionDefinition> a = buildActions();
    return a;
}

const SettingDefinition *SettingCatalog::find(const QString &key)
{
    for (const auto &d : settings())
        if (key.compare(QLatin1String(d.key), Qt::CaseInsensitive) == 0)
            return &d;
    return nullptr;
}

const ActionDefinition *SettingCatalog::findAction(const QString &key)
{
    for (const auto &a : actions())
        if (key.compare(QLatin1String(a.key), Qt::CaseInsensitive) == 0)
            return &a;
    return nullptr;
}

QStringList SettingCatalog::keys()
{
    QStringList k;
    for (const auto &d : settings())
        k << QLatin1String(d.key);
    return k;
}

bool SettingCatalog::hasFeature(Feature f, model::ProductFamily family)
{
    using model::ProductFamily;
    switch (f) {
    case Feature::None: return true;
    case Feature::Magnetometer: return family != ProductFamily::HI02 && family != ProductFamily::HI50;
    case Feature::AttitudeCalibration: return family != ProductFamily::HI02;
    case Feature::Pmux:
        return family != ProductFamily::HI02 && family != ProductFamily::HI50 && family != ProductFamily::HI7x_9x;
    }
    return true;
}

SettingCatalog::Availability SettingCatalog::availability(const SettingDefinition &d, const model::DeviceIdentity &id)
{
    if (!editionHas(d.inV166, d.inV171, id))
        return {false, tr("not in the manual for firmware %1").arg(editionName(id.edition()))};
    if (!hasFeature(d.feature, id.family()))
        return {false, tr("%1 has no %2 (v1.7.1 feature table)")
                           .arg(QString::fromLatin1(model::familyName(id.family())), featureText(d.feature))};
    return {};
}

SettingCatalog::Availability SettingCatalog::availability(const ActionDefinition &a, const model::DeviceIdentity &id)
{
    if (!editionHas(a.inV166, a.inV171, id))
        return {false, tr("not in the manual for firmware %1").arg(editionName(id.edition()))};
    if (!hasFeature(a.feature, id.family()))
        return {false, tr("%1 has no %2 (v1.7.1 feature table)")
                           .arg(QString::fromLatin1(model::familyName(id.family())), featureText(a.feature))};
    return {};
}

std::optional<QString> SettingCatalog::normalize(const SettingDefinition &d, const QString &input,
                                                 const model::DeviceIdentity *id, QString *error)
{
    const QString t = input.trimmed().toUpper();
    auto refuse = [&](const QString &why) -> std::optional<QString> {
        if (error)
            *error = tr("%1=%2: %3").arg(QLatin1String(d.key), input.trimmed(), why);
        return std::nullopt;
    };
    const bool legacy = id && id->edition() == ManualEdition::V166;
    switch (d.kind) {
    case SettingKind::Baud: {
        int b = 0;
        if (!parseInt(t, &b))
            return refuse(tr("a baud rate is a whole number"));
        const bool ok = id ? hp::commands::isSupportedBaud(b, id->edition())
                           : (hp::commands::isSupportedBaud(b, ManualEdition::V171)
                              || hp::commands::isSupportedBaud(b, ManualEdition::V166));
        if (!ok)
            return refuse(legacy ? tr("firmware below 1.7.1 takes 9600, 115200, 256000, 460800 or 921600")
                                 : tr("supported rates are 4800, 9600, 19200, 38400, 57600, 115200, 230400, 256000, "
                                      "460800 and 921600"));
        return QString::number(b);
    }
    case SettingKind::LogSwitch:
        if (t == QLatin1String("ENABLE") || t == QLatin1String("1") || t == QLatin1String("ON"))
            return QStringLiteral("ENABLE");
        if (t == QLatin1String("DISABLE") || t == QLatin1String("0") || t == QLatin1String("OFF"))
            return QStringLiteral("DISABLE");
        return refuse(tr("use ENABLE or DISABLE"));
    case SettingKind::MessageOutput: {
        if (t == QLatin1String("OFF"))
            return QStringLiteral("OFF");
        if (t == QLatin1String("ONMARK") || t == QLatin1String("ONMARK 1"))
            return QStringLiteral("ONMARK");
        QString num = t;
        if (num.startsWith(QLatin1String("ONTIME")))
            num = num.mid(6).trimmed();
        const auto p = parsePeriod(num);
        if (!p)
            return refuse(tr("use a period in seconds (0.001 .. 1, 0 = off), ONMARK or OFF"));
        if (*p == 0)
            return QStringLiteral("OFF");
        const auto c = hp::commands::logOnTime(d.message, *p);
        if (!c.ok())
            return refuse(QString::fromStdString(c.error));
        return QString::fromStdString(hp::commands::formatPeriod(*p));
    }
    case SettingKind::Hi83Map: {
        bool ok = false;
        const uint32_t v = t.startsWith(QLatin1String("0X")) ? t.mid(2).toUInt(&ok, 16) : t.toUInt(&ok, 10);
        if (!ok)
            return refuse(tr("use a bitmap such as 0x000000FF"));
        const auto c = hp::commands::logHi83Map(v);
        if (!c.ok())
            return refuse(QString::fromStdString(c.error));
        return QStringLiteral("0x") + QStringLiteral("%1").arg(v, 8, 16, QLatin1Char('0')).toUpper();
    }
    case SettingKind::Choice: {
        int v = 0;
        const ChoiceRow *row = parseInt(t, &v) ? choiceRow(d, v) : nullptr;
        if (!row)
            return refuse(tr("not one of the documented values"));
        if (id && (!editionHas(row->v166, row->v171, *id) || !hasFeature(row->feature, id->family())))
            return refuse(tr("%1 (%2) is not available on this model or firmware").arg(t, tr(row->label)));
        return QString::number(v);
    }
    case SettingKind::Mounting: {
        if (!t.contains(QLatin1Char(','))) {
            const auto code = model::Mounting::parseCode(t.toStdString());
            if (!code)
                return refuse(tr("not one of the 24 right-handed URFR codes"));
            return QString::fromStdString(model::Mounting::codeText(*code));
        }
        const auto m = parseMatrix(t);
        if (!m)
            return refuse(tr("the matrix is nine numbers C00,C01,...,C22"));
        const auto c = hp::commands::imuUrfrMatrix(*m);
        if (!c.ok())
            return refuse(QString::fromStdString(c.error));
        if (const auto code = model::Mounting::codeForLegacyMatrix(*m))
            return QString::fromStdString(model::Mounting::codeText(*code));
        if (id && !legacy)
            return refuse(tr("firmware 1.7.1 takes only the 24 URFR codes"));
        return matrixText(*m);
    }
    case SettingKind::PinMap: {
        QString n = t;
        if (n.startsWith(QLatin1String("IO")))
            n = n.mid(2);
        int io = 0;
        const int maxIo = legacy || !id ? 9 : 5;
        if (!parseInt(n, &io) || io < 1 || io > maxIo)
            return refuse(tr("use a pin IO1 .. IO%1").arg(maxIo));
        return QStringLiteral("IO%1").arg(io);
    }
    case SettingKind::Integer: {
        int v = 0;
        if (!parseInt(t, &v) || v < d.minimum || v > d.maximum)
            return refuse(tr("use a whole number %1 .. %2").arg(d.minimum).arg(d.maximum));
        return QString::number(v);
    }
    }
    return refuse(tr("unknown setting kind"));
}

std::optional<QString> SettingCatalog::fromComConfig(const SettingDefinition &d, const std::string &value)
{
    const QString v = QString::fromStdString(value).trimmed();
    if (d.kind == SettingKind::MessageOutput) {
        const QString u = v.toUpper();
        if (u == QLatin1String("OFF") || u == QLatin1String("ONTIME 0"))
            return QStringLiteral("OFF");
        if (u.startsWith(QLatin1String("ONMARK")))
            return QStringLiteral("ONMARK");
    }
    QString error;
    return normalize(d, v, nullptr, &error);
}

std::vector<hp::Command> SettingCatalog::commands(const SettingDefinition &d, const QString &canonical,
                                                  const model::DeviceIdentity &id, QString *error)
{
    const Availability a = availability(d, id);
    if (!a.available) {
        if (error)
            *error = tr("%1: %2").arg(QLatin1String(d.key), a.reason);
        return {};
    }
    const auto value = normalize(d, canonical, &id, error);
    if (!value)
        return {};
    const bool legacy = id.edition() == ManualEdition::V166;
    hp::Command c;
    switch (d.kind) {
    case SettingKind::Baud: c = hp::commands::serialConfig(value->toInt(), id.edition()); break;
    case SettingKind::LogSwitch:
        c = *value == QLatin1String("ENABLE") ? hp::commands::logEnable() : hp::commands::logDisable();
        break;
    case SettingKind::MessageOutput:
        if (*value == QLatin1String("OFF"))
            c = hp::commands::logOnTime(d.message, 0);
        else if (*value == QLatin1String("ONMARK"))
            c = hp::commands::logOnMark(d.message, false);
        else
            c = hp::commands::logOnTime(d.message, value->toDouble());
        break;
    case SettingKind::Hi83Map: c = hp::commands::logHi83Map(value->mid(2).toUInt(nullptr, 16)); break;
    case SettingKind::Choice:
        if (QLatin1String(d.key) == QLatin1String("ATT.MODE"))
            c = hp::commands::attMode(value->toInt());
        else if (QLatin1String(d.key) == QLatin1String("IMU.COORD"))
            c = hp::commands::imuCoord(value->toInt());
        else
            c = hp::commands::enableBackgroundMagCal(value->toInt() == 1);
        break;
    case SettingKind::Mounting:
        if (value->contains(QLatin1Char(',')))
            c = hp::commands::imuUrfrMatrix(*parseMatrix(*value));
        else if (legacy)
            c = hp::commands::imuUrfrMatrix(model::Mounting::legacyMatrixForCode(value->toInt()));
        else
            c = hp::commands::imuUrfr(value->toInt());
        break;
    case SettingKind::PinMap: c = hp::commands::pmux(d.pmuxFunction, value->mid(2).toInt(), legacy); break;
    case SettingKind::Integer: c = hp::commands::pmux2Div(value->toInt()); break;
    }
    if (!c.ok()) {
        if (error)
            *error = tr("%1: %2").arg(QLatin1String(d.key), QString::fromStdString(c.error));
        return {};
    }
    return {c};
}

std::optional<hp::Command> SettingCatalog::actionCommand(const ActionDefinition &a, const QString &argument, QString *error)
{
    if (QLatin1String(a.key) != QLatin1String("YAW")) {
        if (!argument.trimmed().isEmpty() && argument.trimmed() != QLatin1String("1")) {
            if (error)
                *error = tr("%1 takes no value").arg(QLatin1String(a.key));
            return std::nullopt;
        }
        return a.command();
    }
    const QStringList parts = argument.split(QLatin1Char(','));
    int mode = -1;
    const auto deg = parts.size() == 2 ? parsePeriod(parts.at(1)) : std::nullopt;
    if (parts.size() != 2 || !parseInt(parts.at(0), &mode) || !deg) {
        if (error)
            *error = tr("YAW needs MODE,DEG (MODE 0 relative or 1 absolute, DEG -180 .. 180), e.g. YAW=1,16");
        return std::nullopt;
    }
    const auto c = hp::commands::setYaw(mode, *deg);
    if (!c.ok()) {
        if (error)
            *error = tr("YAW: %1").arg(QString::fromStdString(c.error));
        return std::nullopt;
    }
    return c;
}

QString SettingCatalog::valueText(const SettingDefinition &d, const QString &canonical)
{
    switch (d.kind) {
    case SettingKind::MessageOutput: {
        if (canonical == QLatin1String("OFF"))
            return tr("off");
        if (canonical == QLatin1String("ONMARK"))
            return tr("on SYNC_IN pulse (ONMARK 1)");
        const double p = canonical.toDouble();
        return p > 0 ? tr("%1 Hz (%2 s)").arg(1.0 / p, 0, 'g', 4).arg(canonical) : canonical;
    }
    case SettingKind::Choice: {
        const ChoiceRow *row = choiceRow(d, canonical.toInt());
        return row ? tr("%1 (%2)").arg(canonical, tr(row->label)) : canonical;
    }
    case SettingKind::Mounting: {
        if (canonical.contains(QLatin1Char(',')))
            return tr("matrix %1").arg(canonical);
        return canonical;
    }
    default: return canonical;
    }
}

QList<SettingCatalog::Choice> SettingCatalog::choices(const SettingDefinition &d, const model::DeviceIdentity &id)
{
    QList<Choice> out;
    switch (d.kind) {
    case SettingKind::Baud:
        for (int b : {4800, 9600, 19200, 38400, 57600, 115200, 230400, 256000, 460800, 921600})
            if (hp::commands::isSupportedBaud(b, id.edition()))
                out.push_back({QString::number(b), QString::number(b)});
        break;
    case SettingKind::LogSwitch:
        out.push_back({QStringLiteral("ENABLE"), tr("enabled")});
        out.push_back({QStringLiteral("DISABLE"), tr("disabled")});
        break;
    case SettingKind::MessageOutput:
        out.push_back({QStringLiteral("OFF"), tr("off")});
        for (const char *p : {"1", "0.5", "0.2", "0.1", "0.05", "0.02", "0.01", "0.005", "0.004", "0.002", "0.001"})
            out.push_back({QLatin1String(p), valueText(d, QLatin1String(p))});
        out.push_back({QStringLiteral("ONMARK"), valueText(d, QStringLiteral("ONMARK"))});
        break;
    case SettingKind::Choice:
        for (const auto &c : kChoices)
            if (QLatin1String(c.key) == QLatin1String(d.key) && editionHas(c.v166, c.v171, id)
                && hasFeature(c.feature, id.family()))
                out.push_back({QString::number(c.value), tr("%1 (%2)").arg(c.value).arg(tr(c.label))});
        break;
    case SettingKind::Mounting:
        for (int code : model::Mounting::validCodes())
            out.push_back({QString::fromStdString(model::Mounting::codeText(code)),
                           QString::fromStdString(model::Mounting::codeText(code))});
        break;
    case SettingKind::PinMap: {
        const int maxIo = id.edition() == ManualEdition::V166 ? 9 : 5;
        for (int io = 1; io <= maxIo; ++io)
            out.push_back({QStringLiteral("IO%1").arg(io), QStringLiteral("IO%1").arg(io)});
        break;
    }
    case SettingKind::Hi83Map:
    case SettingKind::Integer: break;
    }
    return out;
}

QString SettingCatalog::label(const SettingDefinition &d) { return QCoreApplication::translate(kCtx, d.label); }
QString SettingCatalog::description(const SettingDefinition &d)
{
    return QCoreApplication::translate(kCtx, d.description);
}
QString SettingCatalog::label(const ActionDefinition &a) { return QCoreApplication::translate(kCtx, a.label); }
QString SettingCatalog::conditions(const ActionDefinition &a)
{
    return QCoreApplication::translate(kCtx, a.conditions);
}

QString SettingCatalog::persistenceText(Persistence p)
{
    switch (p) {
    case Persistence::SaveAndReset: return tr("after SAVECONFIG and a reset");
    case Persistence::Immediate: return tr("at once; SAVECONFIG keeps it after a reset");
    case Persistence::NeverSaved: return tr("at once; not saved (enabled again after every start)");
    }
    return {};
}

QString SettingCatalog::readBackText(const SettingDefinition &d)
{
    return tr("LOG COMCONFIG: %1").arg(QLatin1String(d.comConfigKey));
}

QString SettingCatalog::featureText(Feature f)
{
    switch (f) {
    case Feature::None: return {};
    case Feature::Magnetometer: return tr("magnetometer aiding");
    case Feature::AttitudeCalibration: return tr("user attitude calibration");
    case Feature::Pmux: return tr("IO pin mapping (PMUX)");
    }
    return {};
}

} // namespace imudesk::settings
