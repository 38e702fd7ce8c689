#pragma once
// MAIN_STATUS word (HI91/HI81/HI83, firmware >= 1.7.0). A set bit is a warning
// or an indication; bit meanings from the v1.7.1 manual section 5.9.13, except bit 9
// STATIC, which that table marks reserved and the vendor's SDK names: each definition
// says its source, and the status tooltip shows it.
#include <cstdint>
#include <string>
#include <vector>

namespace imudesk::model {

// What a set bit tells the user: good news (the 9-axis heading is aided), a plain
// indication, or a warning about the data's quality.
enum class FlagSeverity { Good, Information, Warning };

struct StatusFlagInfo {
    int bit;
    const char *name;        // manual's name, e.g. "WB_CONV"
    const char *meaning;     // what a set bit means (English; translated in ui)
    FlagSeverity severity;   // of a set bit
    const char *source;      // where the meaning comes from (English; translated in ui)
};

class MainStatus {
public:
    enum Bit : int {
        WbConv = 3,
        MagDist = 4,
        AccSat = 5,
        GyrSat = 6,
        AttConv = 7,
        Static = 9,
        MagAiding = 10,
        UtcUnsync = 11,
        SoutPulse = 12,
    };

    MainStatus() = default;
    explicit MainStatus(uint16_t raw) : m_raw(raw) {}

    uint16_t raw() const { return m_raw; }
    bool test(Bit b) const { return (m_raw >> b) & 1u; }
    // Names of the set, defined bits, in ascending bit order.
    std::vector<std::string> setFlagNames() const;
    // Bits that are set but not defined by any manual.
    uint16_t undefinedBits() const;

    static const std::vector<StatusFlagInfo> &definitions();

    // The clock a frame's system_time counts on, for FrameGapCounter::add: 1 while
    // UTC_UNSYNC is set (time since power-on), 0 once PPS aligned it to the UTC day (v1.7.1
    // manual 2.2.2, 5.9.13), and 0 for a frame without a status word.
    static int timeBase(bool hasStatus, uint16_t raw) { return hasStatus ? int((raw >> UtcUnsync) & 1u) : 0; }

private:
    uint16_t m_raw = 0;
};

} // namespace imudesk::model
