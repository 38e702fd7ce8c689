#pragma once
// One documented HiPNUC setting: its key (the manual's words joined by dots), the
// command that sets it, its range, the firmware editions and product families that have
// it (v1.7.1 chapter 3 feature table), when it takes effect and how it is read back.
// The values themselves are handled by SettingCatalog (canonical text form).
#include "protocol/hipnuc/ascii_command.h"

#include <QString>

namespace imudesk::settings {

enum class SettingKind {
    Baud,          // SERIALCONFIG <baud>
    LogSwitch,     // LOG ENABLE | LOG DISABLE
    MessageOutput, // LOG <MSG> ONTIME <period> | ONMARK 1 | ONTIME 0 (off)
    Hi83Map,       // LOG HI83 MAP 0x........
    Choice,        // a few numbers (ATT MODE, IMU COORD, IMU_EN_MCAL)
    Mounting,      // CONFIG IMU URFR <code> (v1.7.1) or the nine numbers (v1.6.6)
    PinMap,        // CONFIG PMUXn IOm
    Integer,       // CONFIG PMUX2 DIV 1..1000
};

// Rows of the v1.7.1 feature table (chapter 3) a setting depends on.
enum class Feature {
    None,
    Magnetometer,        // 地磁辅助/地磁校准: not HI02, HI50
    AttitudeCalibration, // 用户姿态校准: not HI02
    Pmux,                // IO复用映射(PMUX): HI05/06 and CH0x0/HI04/12/13/14 only
};

// When a new value takes effect and whether it survives a reset.
enum class Persistence {
    SaveAndReset, // CONFIG ...: SAVECONFIG, then REBOOT (v1.7.1 §4.5 "保存后,复位生效")
    Immediate,    // LOG <MSG>, SERIALCONFIG: at once; SAVECONFIG keeps it after a reset
    NeverSaved,   // LOG ENABLE/DISABLE: output is enabled after every start
};

struct SettingDefinition {
    const char *key;          // "ATT.MODE"
    const char *comConfigKey; // the LOG COMCONFIG key that reads it back ("ATT_MODE")
    SettingKind kind;
    bool inV166;              // the v1.6.6 manual (firmware 1.5.5 - 1.7.0) has it
    bool inV171;              // the v1.7.1 manual has it
    Feature feature;
    Persistence persistence;
    const char *label;        // short name (translated in SettingCatalog's context)
    const char *description;  // what it does, from the manual
    protocol::hipnuc::Message message = protocol::hipnuc::Message::HI91; // MessageOutput
    int pmuxFunction = 0;     // PinMap: 1..3
    int minimum = 0;          // Integer
    int maximum = 0;
    bool inProfile = true;    // saved to and applied from profiles
};

// An action: a command that does something once and has no value to read back.
struct ActionDefinition {
    const char *key;          // "ATT.RST.3"
    // The typed builder of its command (CONFIG ATT RST 3, SAVECONFIG, ...); null for CONFIG YAW,
    // which takes arguments (SettingCatalog::actionCommand builds it).
    protocol::hipnuc::Command (*command)();
    bool inV166;
    bool inV171;
    Feature feature;
    const char *label;
    const char *conditions;   // when it works and what it changes (from the manuals)
};

} // namespace imudesk::settings
