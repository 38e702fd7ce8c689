#pragma once
// Modbus RTU register maps as data: every register of the HiPNUC manuals (v1.7.1 chapter 6,
// v1.6.6 chapter 4) and of the HEC495 manual ("Modbus 通讯协议"). Registers are 16-bit,
// big-endian on the wire (high byte first).
//
// Types
//   U16, I16  one register
//   I32       two registers, high word first (R_H/R_L, P_H/P_L, Y_H/Y_L, PRS_H/PRS_L)
//   F32LE     two registers holding an IEEE-754 float whose four bytes are sent least significant
//             first (HEC495: 3.5 is sent as 00 00 60 40)
//   Ascii     `words` registers of ASCII text, two characters per register, first character in
//             the high byte, NUL padded (PNAME)
//   Bytes     `words` registers shown as hex (SN)
//
// Notes on the manuals
//   * Q0..Q3 are printed as u16, but a quaternion component is signed: they are I16 here.
//   * 0xA5 is "ATT_RST" in v1.7.1 and "SET_LV" in v1.6.6. Both texts say 3 starts a levelling
//     and 5 cancels it, while both examples write 2 to start: 2 and 3 are accepted.
//   * 0xA6 URFR: v1.6.6 takes 0..4 (horizontal, Y down, Y up, X up, X down); v1.7.1 takes the
//     mounting code itself (0x18 = 024, 0x2B = 043, 0x34 = 052, 0x208 = 520, 0x1A5 = 421).
//     v1.7.1 lists the register only in its examples (6.17.25), so it is write-only in both.
//   * 0x4E is spelled "HEVAE" in both manuals (heave).
//   * The HEC495 manual reads all three angles from 0x0004 (pitch 0x0004, roll 0x0006, heading
//     0x0008), but its single-angle examples read pitch at 0x0005 and roll at 0x0006. The map
//     follows the block; the simulator also answers the manual's pitch request (0x0005, 2).
#include "model/device_identity.h"

#include <QCoreApplication>
#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

namespace imudesk::protocol::modbus {

enum class RegType { U16, I16, I32, F32LE, Ascii, Bytes };
enum Access : uint8_t { Read = 1, Write = 2, ReadWrite = 3 };
enum EditionMask : uint8_t { EditionV166 = 1, EditionV171 = 2, EditionBoth = 3 };

// What values a writable register takes (checked by the session before sending and by the simulator).
enum class ValueRule { Any, Ctrl, BaudCode, NodeId, HeadingMode, AutoLevel, UrfrIndex, UrfrCode };

struct RegisterDef {
    uint16_t address = 0;
    const char *name = "";
    RegType type = RegType::U16;
    uint16_t words = 1;     // registers occupied
    double scale = 1.0;     // physical = raw * scale
    const char *unit = "";  // "G", "deg/s", "uT", "deg", "degC", "Pa", "m", "s", ""
    uint8_t access = Read;
    uint8_t editions = EditionBoth;
    ValueRule rule = ValueRule::Any;
    const char *description = ""; // English, translated through RegisterMap::describe()

    bool readable() const { return (access & Read) != 0; }
    bool writable() const { return (access & Write) != 0; }
};

// Addresses used by code (the map holds the rest).
namespace reg {
inline constexpr uint16_t kCtrl = 0x00;
inline constexpr uint16_t kBaud = 0x04;
inline constexpr uint16_t kNodeId = 0x05;
inline constexpr uint16_t kHeadingMode = 0x06;
inline constexpr uint16_t kSensorStart = 0x34; // ACCX
inline constexpr uint16_t kSensorCount = 24;   // 0x34..0x4B
inline constexpr uint16_t kTemp = 0x43;
inline constexpr uint16_t kHeave = 0x4E;
inline constexpr uint16_t kHeavePeriod = 0x51;
inline constexpr uint16_t kShipCount = 30;     // 0x34..0x51
inline constexpr uint16_t kIdentityStart = 0x70;
inline constexpr uint16_t kIdentityCount = 20; // 0x70..0x83, as in the manual's request
inline constexpr uint16_t kSwVersion = 0x78;
inline constexpr uint16_t kBlVersion = 0x79;
inline constexpr uint16_t kSerial = 0x7F;
inline constexpr uint16_t kAutoLevel = 0xA5;
inline constexpr uint16_t kUrfr = 0xA6;
// HEC495
inline constexpr uint16_t kHecAngles = 0x04;   // pitch, roll, heading: 3 floats, 6 registers
inline constexpr uint16_t kHecAngleCount = 6;
inline constexpr uint16_t kHecPitchSingle = 0x05; // the manual's single-pitch request address
} // namespace reg

inline constexpr int kHipnucDefaultId = 80;
inline constexpr int kHec495DefaultId = 1;

enum class DeviceKind { Hipnuc, Hec495 };

class RegisterMap {
    Q_DECLARE_TR_FUNCTIONS(RegisterMap)

public:
    // Every HiPNUC register of both manuals (entries carry their edition).
    static const RegisterMap &hipnucAll();
    // The registers of one edition.
    static const RegisterMap &hipnuc(model::ManualEdition edition);
    static const RegisterMap &hec495();
    static const RegisterMap &forDevice(DeviceKind kind, model::ManualEdition edition = model::ManualEdition::V171);

    const std::vector<RegisterDef> &registers() const { return m_regs; }
    // The register starting at address (for an entry: the first word), nullptr if none.
    const RegisterDef *find(uint16_t address) const;
    // The register covering address (also the second word of an I32), nullptr if none.
    const RegisterDef *covering(uint16_t address) const;
    const RegisterDef *findByName(const QString &name) const;

    // Whether a value may be written to a register under its rule.
    static bool accepts(const RegisterDef &def, uint16_t value);
    // The translated description.
    static QString describe(const RegisterDef &def);
    static const char *typeName(RegType t);

private:
    explicit RegisterMap(std::vector<RegisterDef> regs);
    std::vector<RegisterDef> m_regs;
};

} // namespace imudesk::protocol::modbus
