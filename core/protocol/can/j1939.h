#pragma once
// SAE J1939 on HiPNUC modules (v1.7.1 manual chapter 7, v1.6.6 chapter 6): the 29-bit
// identifier fields and the proprietary data PGNs (PF 0xFF, PS = the data block's register
// address), decoded to Sample in ImuDesk's units and encoded back for the simulator.
#include "can_frame.h"
#include "model/sample.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace imudesk::protocol::can::j1939 {

inline constexpr uint8_t kDefaultAddress = 0x08; // factory node address
inline constexpr uint8_t kHostAddress = 0x55;    // host source address used by vendor tools
inline constexpr uint8_t kBroadcast = 0xFF;
inline constexpr uint8_t kDataPriority = 3;

enum Pgn : uint32_t {
    PgnTime = 0xFF2F,
    PgnAcc = 0xFF34,
    PgnGyr = 0xFF37,
    PgnMag = 0xFF3A,
    PgnRollPitch = 0xFF3D,
    PgnHeading = 0xFF41,
    PgnQuat = 0xFF46,
    PgnIncl = 0xFF4A,
    PgnCanFd0 = 0xFF5A,
    PgnConfig = 0xEF00, // proprietary A, PDU1: the configuration protocol
};

// Scales of chapter 7.21 (the manual's rounded factors are 1/2048, 2000/32768 and 1000/32768).
inline constexpr double kAccScale = 1.0 / 2048.0;     // G
inline constexpr double kGyrScale = 2000.0 / 32768.0; // deg/s
inline constexpr double kMagScale = 1000.0 / 32768.0; // uT
inline constexpr double kAngleScale = 0.001;          // deg
inline constexpr double kQuatScale = 0.0001;
inline constexpr double kTempScale = 0.01;            // degC

struct Id {
    uint8_t priority = 0; // bits 26..28
    uint8_t edp = 0;      // bit 25 (reserved / extended data page)
    uint8_t dp = 0;       // bit 24
    uint8_t pf = 0;       // bits 16..23
    uint8_t ps = 0;       // bits 8..15 (destination address when pf < 0xF0)
    uint8_t sa = 0;       // bits 0..7

    bool pdu1() const { return pf < 0xF0; }
    // Parameter group number: PS is part of it only for PDU2 (pf >= 0xF0).
    uint32_t pgn() const { return (uint32_t(edp) << 17) | (uint32_t(dp) << 16) | (uint32_t(pf) << 8) | (pdu1() ? 0u : ps); }
    uint8_t destination() const { return pdu1() ? ps : kBroadcast; }
};

Id parseId(uint32_t canId);
// For a PDU1 PGN, da goes into PS; for PDU2 the PGN's low byte is PS and da is ignored.
uint32_t makeId(uint8_t priority, uint32_t pgn, uint8_t sa, uint8_t da = kBroadcast);

struct UtcTime {
    int year = 0, month = 0, day = 0, hour = 0, minute = 0, second = 0, ms = 0;
    // A module without UTC sends month 0 and day 0 (v1.6.6 6.1.1: year byte 20, month 0, day 0
    // "when the UTC time cannot be obtained"; v1.7.1 7.21.31: month and day 0..12 / 0..31) and
    // its running time in the hour, minute and second: such a frame is no UTC time.
    bool dateKnown() const { return month >= 1 && month <= 12 && day >= 1 && day <= 31; }
    friend bool operator==(const UtcTime &, const UtcTime &) = default;
};

enum class DecodeError { None, NotExtended, NotDataPgn, TooShort, RemoteFrame };
const char *errorName(DecodeError e);

struct DataFrame {
    uint32_t pgn = 0;
    uint8_t sourceAddress = 0;
    model::Sample sample;           // the fields this PGN carries
    std::optional<UtcTime> time;    // PGN 0xFF2F
    double headingCwDeg = 0;        // PGN 0xFF41 word 0: 0..360 clockwise
    bool hasYawPm180 = false;       // PGN 0xFF41 carried the second (v1.7.1, +-180 CCW) word
};

struct DecodeResult {
    DecodeError error = DecodeError::None;
    DataFrame data;
    bool ok() const { return error == DecodeError::None; }
};

// Data PGNs this codec knows, in the manual's order.
const std::vector<uint32_t> &dataPgns();
bool isDataPgn(uint32_t pgn);
// Minimum DLC the PGN needs (FF41: 4, the v1.6.6 form; FF5A: 64).
int minimumLength(uint32_t pgn);
const char *pgnName(uint32_t pgn); // "acc", "gyr", ... or nullptr

DecodeResult decodeData(const CanFrame &f);

// Encoders (simulator, round-trip tests). encodeData handles every data PGN but the time.
CanFrame encodeTime(uint8_t sa, const UtcTime &t);
CanFrame encodeData(uint32_t pgn, uint8_t sa, const model::Sample &s, bool withYawPm180 = true);

} // namespace imudesk::protocol::can::j1939
