#pragma once
// HiPNUC's CANopen object dictionary entries (v1.7.1 manual 8.28, v1.6.6 5.4): written with
// expedited SDO. Firmware 1.7.1 keeps the node ID in 0x209C, 1.6.6 in 0x20A0.
#include "can_frame.h"

#include <cstdint>
#include <optional>

namespace imudesk::protocol::can::canopen::hipnuc {

enum Object : uint16_t {
    ObjCommand = 0x2000,       // sub 0: 0 save, 1 factory defaults, 0xFF reset
    ObjBaud = 0x209A,          // 0:1000K 2:500K 3:250K 4:125K (8.28.44.23; no 800K code)
    ObjNodeId = 0x209C,        // v1.7.1
    ObjNodeIdV166 = 0x20A0,    // v1.6.6
    ObjInclSignX = 0x209E,
    ObjInclSignY = 0x209F,
    ObjInclZero = 0x20A5,      // 2 set zero here, 5 clear zero
    ObjHeartbeat = 0x1017,     // u16 ms, 0 = off
};

inline constexpr uint8_t kSubTransmissionType = 2; // u8: 1 = SYNC, 0xFE/0xFF = asynchronous (event timer)
inline constexpr uint8_t kSubEventTimer = 5;       // u16 ms, 0 = off
inline constexpr uint8_t kTransmissionSync = 0x01;
inline constexpr uint8_t kTransmissionAsync = 0xFF;

enum CommandValue : uint32_t { CommandSave = 0x00, CommandFactory = 0x01, CommandReset = 0xFF };

// Node-ID object of a firmware version (major, minor, patch): 0x20A0 before 1.7.0.
uint16_t nodeIdObject(int major, int minor, int patch);
bool isNodeIdObject(uint16_t index); // 0x209C or 0x20A0

// The firmware version a module reports: the identity object's revision number (0x1018:3),
// major << 16 | minor << 8 | patch (the manuals name no version object; ImuDesk's CAN update
// reads the same entry). 0 is no version.
inline constexpr uint16_t ObjIdentity = 0x1018;
inline constexpr uint8_t kSubRevision = 3;
CanFrame readRevision(uint8_t node); // 40 18 10 03 00 00 00 00
// The node-ID object of the firmware that revision names; nullopt for 0.
std::optional<uint16_t> nodeIdObjectOfRevision(uint32_t revision);
// Does the revision name a firmware of the v1.6.6 manual (before 1.7.0)? Its factory defaults
// (0x2000 = 1) take effect at the next power-up (5.4.1) instead of at once (v1.7.1 8.28.44.22).
bool isV166Revision(uint32_t revision);
// The same expedited SDO request (a write or a read) addressed to another object.
CanFrame retarget(const CanFrame &sdoRequest, uint16_t index);

// The manual's requests, byte for byte.
CanFrame setNodeId(uint8_t node, uint8_t newId, uint16_t object = ObjNodeId); // 23 9C 20 00 id 00 00 00
CanFrame command(uint8_t node, CommandValue v);                                // 23 00 20 00 v ..
CanFrame setBaud(uint8_t node, uint8_t code);                                  // 23 9A 20 00 code ..
CanFrame setTpdoPeriod(uint8_t node, int channel, uint16_t ms);                // 2B 0x 18 05 ms ..
CanFrame setTransmissionType(uint8_t node, int channel, uint8_t type);         // 2F 0x 18 02 type ..
CanFrame setHeartbeat(uint8_t node, uint16_t ms);                              // 2B 17 10 00 ms ..
CanFrame setInclZero(uint8_t node, uint8_t mode);                              // 23 A5 20 00 mode ..
CanFrame setInclSign(uint8_t node, bool yAxis, bool reversed);                 // 23 9E/9F 20 00 v ..

// Baud codes of 0x209A: the J1939 register 0x9A's codes without 1 (800K); 0 / -1 for others.
int baudFromCode(uint32_t code);
int codeFromBaud(int bitrate);

} // namespace imudesk::protocol::can::canopen::hipnuc
