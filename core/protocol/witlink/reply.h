#pragma once
// Typed decoding of what an HEC495 sends (manual "通讯协议" section 2). A status reply's
// 00 is success and FF failure; any other status byte, a wrong data length or a bad BCD
// digit is an error result, never a guess.
#include "all_data_record.h"
#include "frame.h"

#include <QCoreApplication>
#include <QString>

#include <array>
#include <cstdint>
#include <optional>

namespace imudesk::protocol::witlink {

struct Reply {
    Q_DECLARE_TR_FUNCTIONS(Reply)

public:
    enum class Kind {
        Unknown,          // a command byte no reply of the manual uses
        Angle,            // 81 82 83: angle
        Angles,           // 84: pitch, roll, heading
        AllData,          // 14: record
        Declination,      // 87: declination
        Status,           // 86 88 E0/E3/E4/E5 72/92 90 8B 8C 49/C9 8F 8A 8E, and 89 with one byte
        CalibrationSaved, // 89 with 5 bytes: fitError, points
        CalibrationPoint, // 66 (26): pointBytes, points
        Address,          // 1F: deviceAddress
    };
    enum class Error { None, UnknownCommand, BadLength, BadBcd, BadStatus };

    Kind kind = Kind::Unknown;
    Error error = Error::None;
    uint8_t address = 0;    // the frame's address byte
    uint8_t command = 0;    // the reply's command byte
    uint8_t request = 0;    // the request it answers (0x08 for 88: any calibration start)
    bool success = false;   // Status: 00; CalibrationSaved: always; others: decoded
    double angle = 0;                  // Angle
    double pitch = 0, roll = 0, heading = 0; // Angles
    AllDataRecord record;              // AllData
    double declination = 0;            // Declination
    float fitError = 0;                // CalibrationSaved
    int points = 0;                    // CalibrationSaved, CalibrationPoint
    std::array<uint8_t, 15> pointBytes{}; // CalibrationPoint ("no practical meaning", 2.11)
    uint8_t deviceAddress = 0;         // Address

    bool ok() const { return error == Error::None; }
    // "set baud: success", "read angles: pitch -26.80 roll 33.65 heading 313.71", ...
    QString describe() const;
    static QString errorText(Error e);
};

// Decodes one frame sent by the device.
Reply decodeReply(const Frame &frame);
// The data a valid reply carries as a sample (source "HEC495"): the 0x14 record, or the 0x84
// angles (Euler only, yaw = heading); nullopt for any other reply.
std::optional<model::Sample> sampleOf(const Reply &reply, int64_t hostTimeNs);
// Builders for the device side (the simulator, tests). Data as the decoder expects it.
Frame statusReply(uint8_t address, uint8_t command, bool success);
Frame angleReply(uint8_t address, uint8_t command, double deg);
Frame anglesReply(uint8_t address, double pitch, double roll, double heading);
Frame calibrationSavedReply(uint8_t address, float fitError, uint8_t points);
Frame calibrationPointReply(uint8_t address, const std::array<uint8_t, 15> &bytes, uint8_t points);

} // namespace imudesk::protocol::witlink
