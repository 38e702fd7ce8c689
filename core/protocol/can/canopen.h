#pragma once
// CANopen as HiPNUC modules use it (v1.7.1 manual chapter 8, v1.6.6 chapter 5; CiA 301 for
// NMT, SYNC and heartbeat): 11-bit COB-IDs = function base + node ID, TPDO1/2/3/4/6/7.
#include "can_frame.h"
#include "model/sample.h"

#include <cstdint>
#include <optional>

namespace imudesk::protocol::can::canopen {

inline constexpr uint8_t kDefaultNode = 8;

enum CobBase : uint32_t {
    CobNmt = 0x000,
    CobSync = 0x080,
    CobTpdo1 = 0x180, // acc, int16 x3, mG
    CobTpdo2 = 0x280, // gyr, int16 x3, 0.1 deg/s
    CobTpdo3 = 0x380, // roll, pitch, yaw, int16 x3, 0.01 deg
    CobTpdo4 = 0x480, // quaternion w,x,y,z, int16 x4, 1e-4
    CobSdoTx = 0x580, // device -> host
    CobSdoRx = 0x600, // host -> device
    CobTpdo6 = 0x680, // pressure, int32, Pa
    CobHeartbeat = 0x700,
    CobTpdo7 = 0x780, // inclinometer x, y, int32 x2, 0.01 deg
};

inline constexpr double kAccScale = 0.001;  // G
inline constexpr double kGyrScale = 0.1;    // deg/s
inline constexpr double kEulerScale = 0.01; // deg
inline constexpr double kQuatScale = 0.0001;
inline constexpr double kInclScale = 0.01;  // deg

// The six TPDO channels: index 0..5 = TPDO1,2,3,4,6,7 = communication objects 0x1800..0x1805.
inline constexpr int kTpdoCount = 6;
uint32_t tpdoBase(int channel);           // 0x180 ... 0x780
int tpdoNumber(int channel);              // 1,2,3,4,6,7
int tpdoLength(int channel);              // 6,6,6,8,4,8
uint16_t tpdoCommIndex(int channel);      // 0x1800 + channel
int tpdoChannelOfBase(uint32_t base);     // -1 when not a TPDO base
const char *tpdoContent(int channel);     // "acc", ...

bool isStandardNodeId(int node);          // 1..127
uint8_t nodeOf(uint32_t cobId);           // cobId & 0x7F
uint32_t baseOf(uint32_t cobId);          // cobId & 0x780

enum class TpdoError { None, NotTpdo, Extended, Remote, WrongLength };

struct TpdoResult {
    TpdoError error = TpdoError::NotTpdo;
    int channel = -1;
    uint8_t node = 0;
    model::Sample sample;
    bool ok() const { return error == TpdoError::None; }
};

// Decodes a HiPNUC TPDO (the DLC must be the manual's; HEC495 PDOs share the bases).
TpdoResult decodeTpdo(const CanFrame &f);
CanFrame encodeTpdo(int channel, uint8_t node, const model::Sample &s);

// NMT (CiA 301): 0x000 [command, node]; node 0 addresses every node.
enum NmtCommand : uint8_t {
    NmtStart = 0x01,
    NmtStop = 0x02,
    NmtPreOperational = 0x80,
    NmtResetNode = 0x81,
    NmtResetCommunication = 0x82,
};
CanFrame encodeNmt(NmtCommand cmd, uint8_t node);
struct NmtMessage {
    uint8_t command = 0;
    uint8_t node = 0;
};
std::optional<NmtMessage> parseNmt(const CanFrame &f);

CanFrame encodeSync(); // 0x080, no data
bool isSync(const CanFrame &f);

// Heartbeat / boot-up: 0x700 + node, one byte of NMT state.
enum NmtState : uint8_t { StateBootUp = 0x00, StateStopped = 0x04, StateOperational = 0x05, StatePreOperational = 0x7F };
CanFrame encodeHeartbeat(uint8_t node, uint8_t state);
struct Heartbeat {
    uint8_t node = 0;
    uint8_t state = 0;
};
std::optional<Heartbeat> parseHeartbeat(const CanFrame &f);
const char *stateName(uint8_t state);

} // namespace imudesk::protocol::can::canopen
