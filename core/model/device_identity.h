#pragma once
// What a device says about itself (HiPNUC `LOG VERSION`), and the firmware gates
// that follow from it.
#include <map>
#include <optional>
#include <string>

namespace imudesk::model {

struct FirmwareVersion {
    int major = 0, minor = 0, patch = 0;
    // "171", "1.7.1", "v1.7.1"
    static std::optional<FirmwareVersion> parse(const std::string &text);
    std::string toString() const;
    friend auto operator<=>(const FirmwareVersion &, const FirmwareVersion &) = default;
};

// Which manual describes a firmware: v1.7.1 for >= 1.7.1, else v1.6.6 (1.5.5 - 1.7.0).
enum class ManualEdition { V166, V171 };

// The navigation frame a module reports its attitude in (v1.7.1 4.6.7.10, CONFIG IMU COORD):
// 0 East-North-Up (the default, and every module before 1.7.1), 4 North-West-Up.
enum class WorldFrame { Enu, Nwu };
const char *worldFrameName(WorldFrame f); // "ENU", "NWU"
// The frame of a COORD value ("0", "4"); nullopt for anything else.
std::optional<WorldFrame> worldFrameOfCoord(const std::string &coord);
// "ENU" / "NWU" (any case) back to the frame; nullopt for anything else.
std::optional<WorldFrame> parseWorldFrame(const std::string &name);

// Product families of the v1.7.1 feature table (chapter 3).
enum class ProductFamily { Unknown, HI02, HI05_06, CH0x0_HI04_12_13_14, HI50, HI7x_9x };

struct DeviceIdentity {
    std::string productName;   // PNAME, e.g. "HI14R3"
    std::string build;         // BUILD
    std::string serial;        // UUID or SN
    std::optional<FirmwareVersion> firmware;   // APP_VER or SW_VERSION
    std::optional<FirmwareVersion> bootloader; // BL_VER or BL_VERSION
    int busAddress = -1;       // a Witlink HEC495's module address (0..255); -1 for families without one
    // Not from LOG VERSION: the frame of the module's quaternion and Euler angles, read with
    // LOG COMCONFIG (COORD=) after the identity on firmware 1.7.1 and later.
    WorldFrame worldFrame = WorldFrame::Enu;
    // The module did not say its frame: its LOG COMCONFIG reply named no COORD (or there was no
    // reply), so worldFrame is ENU by assumption (the default), not by its word. Firmware before
    // 1.7.1 has no COORD setting: always ENU, not assumed.
    bool worldFrameAssumed = false;

    // Builds an identity from the KEY=VALUE lines of a LOG VERSION reply.
    static DeviceIdentity fromKeyValues(const std::map<std::string, std::string> &kv);
    // Usable when a product name and a firmware version, serial or bus address exist.
    bool usable() const { return !productName.empty() && (firmware || !serial.empty() || busAddress >= 0); }

    ProductFamily family() const;
    ManualEdition edition() const;
    bool hasMainStatus() const;   // firmware >= 1.7.0
    bool hasMagnetometer() const; // the feature table: HI02 and HI50 have no mag aiding
};

ProductFamily familyOfProduct(const std::string &productName);
const char *familyName(ProductFamily f);

} // namespace imudesk::model
