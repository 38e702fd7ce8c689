#pragma once
// The header of a capture file (docs/FILE_FORMATS.md, "Capture file format"): a string map with
// well-known keys for the device identity, the link and the recording, plus the
// device's configuration snapshot under "config.". Encoded as UTF-8 "key=value" lines.
#include "model/device_identity.h"

#include <QCoreApplication>
#include <QMetaType>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace imudesk::capture {

class CaptureHeader {
    Q_DECLARE_TR_FUNCTIONS(CaptureHeader)

public:
    // Well-known keys.
    static constexpr const char *kProduct = "device.product";
    static constexpr const char *kFirmware = "device.firmware";
    static constexpr const char *kBootloader = "device.bootloader";
    static constexpr const char *kSerial = "device.serial";
    static constexpr const char *kBuild = "device.build";
    // The module's address on its bus (DeviceIdentity::busAddress): a Witlink HEC495's, a Modbus node's.
    static constexpr const char *kAddress = "device.address";
    // "NWU" for a module set to CONFIG IMU COORD 4; absent: ENU.
    static constexpr const char *kWorldFrame = "device.world_frame";
    static constexpr const char *kLinkKind = "link.kind";   // "HiPNUC serial"
    // The family whose decoder reads the stream (decode::decoderFor), where the link kind names
    // something else (a converted file: "raw byte dump" of a HiPNUC module's bytes).
    static constexpr const char *kFamily = "link.family";
    static constexpr const char *kPort = "link.port";
    static constexpr const char *kBaud = "link.baud";
    // A CAN capture: the protocol ("j1939", "canopen", "hec495", "auto"), the node followed, the
    // HEC495 PDO mode (CanFamily::describeCapture).
    static constexpr const char *kCanProtocol = "can.protocol";
    static constexpr const char *kCanNode = "can.node";
    static constexpr const char *kCanHec495Mode = "can.hec495_mode";
    static constexpr const char *kStartedUtc = "capture.started_utc"; // ISO 8601
    static constexpr const char *kPart = "capture.part";    // 0 for the first file of a split recording
    static constexpr const char *kApplication = "capture.application";
    // "1": the recorder marked every idle-line release (ChunkLineIdle), so a replay decodes exactly as live.
    static constexpr const char *kIdleMarkers = "capture.idle_markers";
    // "absent": the bytes came without arrival times (a raw byte dump); the chunk times are the
    // device's own clock (CaptureSource).
    static constexpr const char *kHostTime = "capture.host_time";
    // "chunk time": an imported vendor CSV's chunk times are its pc_counter column (ms) on the
    // file's own origin, which its vendor CSV export writes back as they were (not from 0).
    static constexpr const char *kPcCounter = "capture.pc_counter";
    static constexpr const char *kConfigPrefix = "config.";
    static constexpr size_t kMaxBodyBytes = 1u << 20;

    std::map<std::string, std::string> values;

    std::string value(const std::string &key) const;
    void set(const std::string &key, const std::string &v) { values[key] = v; }
    void setIdentity(const model::DeviceIdentity &id);
    model::DeviceIdentity identity() const;
    int baud() const; // 0 when unknown
    // The family of the stream: kFamily, else the link kind (a live recording's link is its family).
    std::string family() const;
    // The configuration snapshot (keys without the "config." prefix).
    std::map<std::string, std::string> config() const;
    void setConfig(const std::map<std::string, std::string> &kv);

    // "key=value\n" per entry, keys sorted; '\\' and '\n' in keys and values escaped.
    std::vector<uint8_t> encodeBody() const;
    // Parses a body; false (with a message) on a line without '=' or a bad escape.
    static bool decodeBody(const uint8_t *data, size_t n, CaptureHeader &out, QString *error);

    friend bool operator==(const CaptureHeader &, const CaptureHeader &) = default;
};

} // namespace imudesk::capture

Q_DECLARE_METATYPE(imudesk::capture::CaptureHeader)
