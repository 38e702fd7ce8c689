#include "register_map.h"

#include "model/mounting.h"

namespace imudesk::protocol::modbus {

namespace {

constexpr double kAccScale = 0.00048828;
constexpr double kGyrScale = 0.061035;
constexpr double kMagScale = 0.030517;

// v1.7.1 chapter 6.16 and v1.6.6 chapter 4.2, in address order.
std::vector<RegisterDef> hipnucTable()
{
    using R = RegType;
    return {
        {0x00, "CTRL", R::U16, 1, 1, "", Write, EditionBoth, ValueRule::Ctrl,
         QT_TRANSLATE_NOOP("RegisterMap", "Control: 0 saves the configuration to flash, 1 restores factory settings, 0xFF resets")},
        {0x04, "UART1_BAUD", R::U16, 1, 1, "", ReadWrite, EditionBoth, ValueRule::BaudCode,
         QT_TRANSLATE_NOOP("RegisterMap", "Baud rate code: 0=4800 1=9600 2=19200 3=38400 4=57600 5=115200 6=230400 7=460800 8=921600")},
        {0x05, "MD_ID", R::U16, 1, 1, "", ReadWrite, EditionBoth, ValueRule::NodeId,
         QT_TRANSLATE_NOOP("RegisterMap", "Modbus node ID, 1-128; takes effect at once")},
        {0x06, "HEADING_MODE", R::U16, 1, 1, "", ReadWrite, EditionBoth, ValueRule::HeadingMode,
         QT_TRANSLATE_NOOP("RegisterMap", "0: 6-axis (relative heading, 0 at power-up), 1: 9-axis (magnetic, absolute heading)")},
        {0x34, "ACCX", R::I16, 1, kAccScale, "G", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Acceleration X")},
        {0x35, "ACCY", R::I16, 1, kAccScale, "G", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Acceleration Y")},
        {0x36, "ACCZ", R::I16, 1, kAccScale, "G", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Acceleration Z")},
        {0x37, "GYRX", R::I16, 1, kGyrScale, "deg/s", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Angular rate X")},
        {0x38, "GYRY", R::I16, 1, kGyrScale, "deg/s", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Angular rate Y")},
        {0x39, "GYRZ", R::I16, 1, kGyrScale, "deg/s", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Angular rate Z")},
        {0x3A, "MAGX", R::I16, 1, kMagScale, "uT", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Magnetic field X")},
        {0x3B, "MAGY", R::I16, 1, kMagScale, "uT", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Magnetic field Y")},
        {0x3C, "MAGZ", R::I16, 1, kMagScale, "uT", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Magnetic field Z")},
        {0x3D, "R_H", R::I32, 2, 0.001, "deg", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Roll (R_H high word, R_L low word)")},
        {0x3F, "P_H", R::I32, 2, 0.001, "deg", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Pitch (P_H high word, P_L low word)")},
        {0x41, "Y_H", R::I32, 2, 0.001, "deg", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Yaw (Y_H high word, Y_L low word)")},
        {0x43, "TEMP", R::I16, 1, 0.01, "degC", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Temperature")},
        {0x44, "PRS_H", R::I32, 2, 0.01, "Pa", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Pressure (PRS_H high word, PRS_L low word)")},
        {0x46, "Q0", R::I16, 1, 0.0001, "", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Quaternion W")},
        {0x47, "Q1", R::I16, 1, 0.0001, "", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Quaternion X")},
        {0x48, "Q2", R::I16, 1, 0.0001, "", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Quaternion Y")},
        {0x49, "Q3", R::I16, 1, 0.0001, "", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Quaternion Z")},
        {0x4A, "INCL_X", R::I16, 1, 0.011, "deg", Read, EditionBoth, ValueRule::Any,
         QT_TRANSLATE_NOOP("RegisterMap", "Inclinometer X angle (dual axis: +-180; single axis: 0-360)")},
        {0x4B, "INCL_Y", R::I16, 1, 0.011, "deg", Read, EditionBoth, ValueRule::Any,
         QT_TRANSLATE_NOOP("RegisterMap", "Inclinometer Y angle (dual axis: +-90; single axis: reserved)")},
        {0x4E, "HEAVE", R::I16, 1, 0.01, "m", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Ship heave displacement")},
        {0x51, "HEAVE_PERIOD", R::I16, 1, 0.001, "s", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Ship heave period")},
        {0x70, "PNAME", R::Ascii, 8, 1, "", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Device name (ASCII, 8 registers)")},
        {0x78, "SW_VERSION", R::U16, 1, 1, "", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Software version (152 = V1.52)")},
        {0x79, "BL_VERSION", R::U16, 1, 1, "", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Bootloader version (107 = V1.07)")},
        {0x7F, "SN", R::Bytes, 4, 1, "", Read, EditionBoth, ValueRule::Any, QT_TRANSLATE_NOOP("RegisterMap", "Unique serial number (4 registers)")},
        {0xA5, "ATT_RST", R::U16, 1, 1, "", Write, EditionV171, ValueRule::AutoLevel,
         QT_TRANSLATE_NOOP("RegisterMap", "Auto-level: 3 levels once when pitch and roll are within 15 deg of 0/0 or 0/180, 5 cancels (the register table, which calls other values invalid). The manual's worked example writes 2 to level; ImuDesk accepts 2 and 3, and its own level action sends 2, byte for byte as the example")},
        {0xA5, "SET_LV", R::U16, 1, 1, "", Write, EditionV166, ValueRule::AutoLevel,
         QT_TRANSLATE_NOOP("RegisterMap", "Auto-level: 3 levels once when pitch and roll are within 15 deg of 0/0 or 0/180, 5 cancels (the register table, which calls other values invalid). The manual's worked example writes 2 to level; ImuDesk accepts 2 and 3, and its own level action sends 2, byte for byte as the example")},
        {0xA6, "URFR", R::U16, 1, 1, "", Write, EditionV171, ValueRule::UrfrCode,
         QT_TRANSLATE_NOOP("RegisterMap", "Mounting: the URFR code (0x18 = 024 horizontal, 0x2B = 043, 0x34 = 052, 0x208 = 520, 0x1A5 = 421)")},
        {0xA6, "URFR", R::U16, 1, 1, "", Write, EditionV166, ValueRule::UrfrIndex,
         QT_TRANSLATE_NOOP("RegisterMap", "Mounting: 0 horizontal, 1 Y axis down, 2 Y axis up, 3 X axis up, 4 X axis down")},
    };
}

std::vector<RegisterDef> forEdition(uint8_t mask)
{
    std::vector<RegisterDef> out;
    for (const RegisterDef &d : hipnucTable())
        if (d.editions & mask)
            out.push_back(d);
    return out;
}

} // namespace

RegisterMap::RegisterMap(std::vector<RegisterDef> regs) : m_regs(std::move(regs)) {}

const RegisterMap &RegisterMap::hipnucAll()
{
    static const RegisterMap map(hipnucTable());
    return map;
}

const RegisterMap &RegisterMap::hipnuc(model::ManualEdition edition)
{
    static const RegisterMap v166(forEdition(EditionV166));
    static const RegisterMap v171(forEdition(EditionV171));
    return edition == model::ManualEdition::V166 ? v166 : v171;
}

const RegisterMap &RegisterMap::hec495()
{
    static const RegisterMap map({
        {0x04, "PITCH", RegType::F32LE, 2, 1, "deg", Read, EditionBoth, ValueRule::Any,
         QT_TRANSLATE_NOOP("RegisterMap", "Pitch (X axis) angle, float")},
        {0x06, "ROLL", RegType::F32LE, 2, 1, "deg", Read, EditionBoth, ValueRule::Any,
         QT_TRANSLATE_NOOP("RegisterMap", "Roll (Y axis) angle, float")},
        {0x08, "HEADING", RegType::F32LE, 2, 1, "deg", Read, EditionBoth, ValueRule::Any,
         QT_TRANSLATE_NOOP("RegisterMap", "Heading (Z axis) angle, float")},
    });
    return map;
}

const RegisterMap &RegisterMap::forDevice(DeviceKind kind, model::ManualEdition edition)
{
    return kind == DeviceKind::Hec495 ? hec495() : hipnuc(edition);
}

const RegisterDef *RegisterMap::find(uint16_t address) const
{
    for (const RegisterDef &d : m_regs)
        if (d.address == address)
            return &d;
    return nullptr;
}

const RegisterDef *RegisterMap::covering(uint16_t address) const
{
    for (const RegisterDef &d : m_regs)
        if (address >= d.address && address < d.address + d.words)
            return &d;
    return nullptr;
}

const RegisterDef *RegisterMap::findByName(const QString &name) const
{
    for (const RegisterDef &d : m_regs)
        if (name.compare(QLatin1String(d.name), Qt::CaseInsensitive) == 0)
            return &d;
    return nullptr;
}

bool RegisterMap::accepts(const RegisterDef &def, uint16_t value)
{
    if (!def.writable())
        return false;
    switch (def.rule) {
    case ValueRule::Any: return true;
    case ValueRule::Ctrl: return value == 0x0000 || value == 0x0001 || value == 0x00FF;
    case ValueRule::BaudCode: return value <= 8;
    case ValueRule::NodeId: return value >= 1 && value <= 128;
    case ValueRule::HeadingMode: return value <= 1;
    case ValueRule::AutoLevel: return value == 2 || value == 3 || value == 5;
    case ValueRule::UrfrIndex: return value <= 4;
    case ValueRule::UrfrCode: return model::Mounting::isValidCode(int(value));
    }
    return false;
}

QString RegisterMap::describe(const RegisterDef &def)
{
    return tr(def.description);
}

const char *RegisterMap::typeName(RegType t)
{
    switch (t) {
    case RegType::U16: return "u16";
    case RegType::I16: return "i16";
    case RegType::I32: return "i32";
    case RegType::F32LE: return "f32";
    case RegType::Ascii: return "ascii";
    case RegType::Bytes: return "bytes";
    }
    return "?";
}

} // namespace imudesk::protocol::modbus
