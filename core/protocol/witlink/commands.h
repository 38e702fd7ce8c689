#pragma once
// Every command of the HEC495 manual ("通讯协议" section 2), as complete frames.
// Builders take the module address (default 0x00) and return the frame bytes; a builder
// whose argument the format cannot carry returns an empty vector.
//
// Request  Meaning (manual section)                  Reply
//   01 02 03  read pitch / roll / heading (2.1-2.3)    81 82 83, 3-byte BCD angle
//   04        read pitch, roll, heading (2.4)          84, 3 x 3-byte BCD
//   14        read all parameters (2.5)                14, 84-byte record
//   06        set magnetic declination (2.6)           86, 00 ok / FF failed
//   07        read magnetic declination (2.7)          87, 2-byte declination
//   63 65 08 64 60  start calibration (2.8 and the calibration chapter): automatic
//             12-point, manual, automatic all-orientation, 12-point small tilt, planar
//                                                      88 (2.8 prints 88 for 63), 00 / FF
//   67        collect a calibration point (2.11)       66 + 15 bytes + point count
//             (2.11 prints LEN 14 and command 26; the calibration chapter prints 66)
//   12        stop calibration (2.10)                  printed 72 (not 92), 00 / FF
//   09        save calibration (2.9)                   89 + float fit error + u8 points
//   10        clear calibration (2.12)                 90, 00 / FF
//   0B        baud (2.13): 00 2400, 01 4800, 02 9600, 03 19200, 04 115200; the reply
//             comes at the old rate, then the new one applies      8B, 00 / FF
//   0C        auto-output rate (2.14): 00 question/answer, 01 5 Hz, 02 10, 03 15, 04 25,
//             05 50, 06 100 Hz                         8C, 00 / FF
//   49        auto-output content (2.15): 00 default, 01 internal, 02 the other record,
//             03 NMEA 0183                             printed 49 (not C9), 00 / FF
//   0F        set address (2.16)                       8F (printed with address FF), 00 / FF
//   1F        query address (2.17), always sent to 00  1F, the address
//   0A        save settings (2.18)                     8A, 00 / FF
//   0E        factory reset (2.19)                     8E, 00 / FF
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace imudesk::protocol::witlink {

enum class Command : uint8_t {
    ReadPitch = 0x01,
    ReadRoll = 0x02,
    ReadHeading = 0x03,
    ReadAngles = 0x04,
    ReadAll = 0x14,
    SetDeclination = 0x06,
    ReadDeclination = 0x07,
    CalibrateAuto12 = 0x63,
    CalibrateManual = 0x65,
    CalibrateAllOrientation = 0x08,
    CalibrateSmallTilt12 = 0x64,
    CalibratePlanar = 0x60,
    CollectPoint = 0x67,
    StopCalibration = 0x12,
    SaveCalibration = 0x09,
    ClearCalibration = 0x10,
    SetBaud = 0x0B,
    SetOutputRate = 0x0C,
    SetOutputContent = 0x49,
    SetAddress = 0x0F,
    QueryAddress = 0x1F,
    SaveSettings = 0x0A,
    FactoryReset = 0x0E,
};

// Reply command bytes that are not request | 0x80.
inline constexpr uint8_t kReplyCalibrationStarted = 0x88;
inline constexpr uint8_t kReplyCalibrationPoint = 0x66;
inline constexpr uint8_t kReplyCalibrationPointAlt = 0x26; // as printed in 2.11
inline constexpr uint8_t kReplyStopCalibration = 0x72;     // as printed in 2.10
inline constexpr uint8_t kReplySetAddressAddress = 0xFF;   // 2.16: the reply's address byte

enum class CalibrationMethod : uint8_t {
    Auto12 = 0x63,
    Manual = 0x65,
    AllOrientation = 0x08,
    SmallTilt12 = 0x64,
    Planar = 0x60,
};

enum class OutputContent : uint8_t {
    Default = 0x00,  // the 0x84 frame (pitch, roll, heading)
    Internal = 0x01, // the 0x14 record with the uncompensated magnetometer
    AllData = 0x02,  // the 0x14 record
    Nmea0183 = 0x03, // $HCHDT sentences
};

namespace commands {

inline constexpr uint8_t kDefaultAddress = 0x00;
inline constexpr int kDefaultBaud = 9600;

bool isKnownCommand(uint8_t cmd);
const char *commandName(uint8_t cmd); // "read pitch", ...; "unknown" otherwise
bool isCalibrationStart(uint8_t cmd);
// Reply command bytes that answer a request (the printed one first).
std::vector<uint8_t> expectedReplies(uint8_t request);

// Baud codes of 2.13; nullopt / -1 when not in the table.
std::optional<uint8_t> baudCode(int baud);
int baudFromCode(uint8_t code);
const std::vector<int> &supportedBauds(); // 2400 4800 9600 19200 115200
// Rate codes of 2.14 (0 Hz = question/answer); nullopt / -1 when not in the table.
std::optional<uint8_t> rateCode(int hz);
int rateFromCode(uint8_t code);
const std::vector<int> &supportedRates(); // 0 5 10 15 25 50 100

// "auto12", "manual", "all", "small-tilt", "planar"
bool parseCalibrationMethod(std::string_view text, CalibrationMethod &out);
const char *calibrationMethodName(CalibrationMethod m);
// "default", "internal", "all", "nmea"
bool parseOutputContent(std::string_view text, OutputContent &out);
const char *outputContentName(OutputContent c);

std::vector<uint8_t> request(Command cmd, uint8_t address = kDefaultAddress, const std::vector<uint8_t> &data = {});
std::vector<uint8_t> readPitch(uint8_t address = kDefaultAddress);
std::vector<uint8_t> readRoll(uint8_t address = kDefaultAddress);
std::vector<uint8_t> readHeading(uint8_t address = kDefaultAddress);
std::vector<uint8_t> readAngles(uint8_t address = kDefaultAddress);
std::vector<uint8_t> readAll(uint8_t address = kDefaultAddress);
std::vector<uint8_t> setDeclination(double deg, uint8_t address = kDefaultAddress); // +-99.9
std::vector<uint8_t> readDeclination(uint8_t address = kDefaultAddress);
std::vector<uint8_t> startCalibration(CalibrationMethod m, uint8_t address = kDefaultAddress);
std::vector<uint8_t> collectPoint(uint8_t address = kDefaultAddress);
std::vector<uint8_t> stopCalibration(uint8_t address = kDefaultAddress);
std::vector<uint8_t> saveCalibration(uint8_t address = kDefaultAddress);
std::vector<uint8_t> clearCalibration(uint8_t address = kDefaultAddress);
std::vector<uint8_t> setBaud(int baud, uint8_t address = kDefaultAddress);
std::vector<uint8_t> setOutputRate(int hz, uint8_t address = kDefaultAddress);
std::vector<uint8_t> setOutputContent(OutputContent c, uint8_t address = kDefaultAddress);
std::vector<uint8_t> setAddress(uint8_t newAddress, uint8_t address = kDefaultAddress);
std::vector<uint8_t> queryAddress(); // always to address 0x00 (2.17)
std::vector<uint8_t> saveSettings(uint8_t address = kDefaultAddress);
std::vector<uint8_t> factoryReset(uint8_t address = kDefaultAddress);

} // namespace commands

} // namespace imudesk::protocol::witlink
