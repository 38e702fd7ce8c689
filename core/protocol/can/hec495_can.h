#pragma once
// Witlink HEC495 compass on CAN (HEC495 manual "CAN 通讯协议"): CANopen-style SDO writes with
// command 0x22 (reply 0x60) to node 5 by default, six 8-byte PDOs at 0x180/0x280/0x380/0x480/
// 0x1C0/0x2C0 + node in float or fixed-point mode, and an extended-frame variant 0x18FA....
// Fixed point: per value a 16-bit magnitude (LE) and a sign byte (1 = negative); angles and
// angular rates / 100 (deg, deg/s), acceleration and field / 10000 (g; the field's unit is not
// given by the manual and is passed through).
#include "can_frame.h"
#include "model/sample.h"

#include <QString>

#include <cstdint>
#include <optional>

namespace imudesk::protocol::can::hec495 {

inline constexpr uint8_t kDefaultNode = 5;
inline constexpr int kDefaultBitrate = 250000;

enum Object : uint16_t {
    ObjNodeId = 0x1010,    // 1..127, after a power cycle
    ObjBaud = 0x1020,      // 1:500K 2:250K 3:125K 4:100K 5:50K 6:30K 7:20K 8:10K, after a power cycle
    ObjPdoMode = 0x1080,   // 0 float, 1 fixed point, 3 float 0x180/0x280 only (extended: 0/1 = message 1 / 1+2)
    ObjHeartbeat = 0x1017, // N: period 100 ms * (N + 1)
    ObjPdoStart = 0x1083,  // 1 start, 0 stop (saved)
    ObjPdoRate = 0x6200,   // 0 off, 1:5Hz 2:10Hz 3:20Hz 4:25Hz 5:50Hz 6:100Hz
    ObjWorkMode = 0x6245,  // 2: pitch, roll, acc, gyr (default); 0x0A: gyro at 500 Hz
};

enum PdoMode : uint8_t { ModeFloat = 0, ModeFixed = 1, ModeFloatShort = 3 };

// Extended-frame variant identifiers.
inline constexpr uint32_t kExtRequestId = 0x18FA0227;
inline constexpr uint32_t kExtReplyId = 0x18FA0216;
inline constexpr uint32_t kExtDataXId = 0x18FA0316;
inline constexpr uint32_t kExtDataYId = 0x18FA0416;

int baudFromCode(uint32_t code);  // 0 when unknown
int codeFromBaud(int bitrate);    // -1 when unknown
double rateHzFromCode(uint32_t code); // 0 = off / unknown
int heartbeatPeriodMs(uint32_t n);
// The N (0x1017's byte) of a heartbeat period: the manual's 100 ms * (N + 1) nearest to ms,
// half-way up (350 ms: N = 3, 400 ms); nullopt outside 100 ms (N = 0) .. 25600 ms (N = 255):
// the manual gives no "off".
inline constexpr int kMinHeartbeatMs = 100;
inline constexpr int kMaxHeartbeatMs = 25600;
std::optional<uint8_t> heartbeatCode(int ms);

// PDO slots, index 0..5 = 0x180, 0x280, 0x380, 0x480, 0x1C0, 0x2C0.
inline constexpr int kPdoCount = 6;
uint32_t pdoBase(int slot);
int pdoSlotOfId(uint32_t cobId); // -1 when not a HEC495 PDO id

// Fixed-point value: 16-bit magnitude + sign byte, e.g. 26 15 01 -> -5414.
double fixedValue(const uint8_t *three, double divisor);
void putFixed(uint8_t *three, double value, double divisor);

struct PdoResult {
    int slot = -1;
    uint8_t node = 0;
    bool fixed = false;
    bool extendedVariant = false;
    uint32_t components = 0; // Component bits
    model::Sample sample;
};

// Decodes a standard PDO in the given mode, or guesses the mode when mode < 0 (fixed point
// has bytes 6..7 zero and sign bytes 0/1; a float there would be a denormal).
std::optional<PdoResult> decodePdo(const CanFrame &f, int mode = -1);
// Decodes 0x18FA0316 / 0x18FA0416.
std::optional<PdoResult> decodeExtended(const CanFrame &f);
bool looksFixed(const CanFrame &f);

// Simulator side: the PDO of slot for sample s (pitch = X angle, roll = Y angle, yaw = heading).
CanFrame encodePdo(int slot, uint8_t node, const model::Sample &s, bool fixed);
CanFrame encodeExtended(bool yAxis, const model::Sample &s);

// SDO write with 0x22 (standard: 0x600 + node; extended: 0x18FA0227) and its 0x60 reply.
CanFrame writeRequest(uint8_t node, uint16_t index, uint8_t value, bool extended = false);
CanFrame writeReply(uint8_t node, uint16_t index, bool extended = false);
struct WriteMessage {
    bool reply = false;
    bool extended = false;
    uint8_t node = 0; // 0 for the extended variant
    uint16_t index = 0;
    uint8_t sub = 0;
    uint8_t value = 0;
};
std::optional<WriteMessage> parseWrite(const CanFrame &f);

// NMT-like start / stop of all nodes: 0x000 [01|02, 00] (not saved).
CanFrame startAll();
CanFrame stopAll();

QString describeObject(uint16_t index, uint8_t value);

} // namespace imudesk::protocol::can::hec495
