#pragma once
// The J1939 configuration protocol (v1.7.1 manual 7.22-7.23, v1.6.6 6.2): PGN 0xEF00 frames
// 0x0CEF[DA][SA] carrying ADDR (u16) + CMD (0x03 read, 0x06 write) + STATUS + VAL (u32), all
// little-endian; the device answers with the same layout from its address to the host's.
#include "can_frame.h"
#include "j1939.h"

#include <QString>

#include <cstdint>
#include <optional>

namespace imudesk::protocol::can::j1939 {

enum RegCmd : uint8_t { CmdRead = 0x03, CmdWrite = 0x06 };

// Register addresses of chapter 7.23 (the Modbus register map).
enum Register : uint16_t {
    RegCommand = 0x0000,       // write 0 = save, 1 = factory defaults (saves and resets), 0xFF = reset
    RegVersion = 0x0078,       // firmware version (vendor tools' "version" action)
    RegTrigger = 0x0096,       // write a PGN: the device sends that data frame once, no reply
    RegBaud = 0x009A,          // 0:1000K 1:800K 2:500K 3:250K 4:125K, after save + reset
    RegNodeId = 0x009C,        // 1..127
    RegOutputEnable = 0x009D,  // 1 = all data output on, 0 = off
    RegInclSignX = 0x009E,     // 0 default, 1 reversed
    RegInclSignY = 0x009F,
    RegAttitudeReset = 0x00A5, // 1 heading reset, 2 relative zero, 3 auto level, 5 clear zero
};

enum CommandValue : uint32_t { CommandSave = 0x00, CommandFactory = 0x01, CommandReset = 0xFF };

inline constexpr int kMinIntervalMs = 5;
inline constexpr int kMaxIntervalMs = 1000;

// Register of a data PGN's output interval: 0x0100 | PS (e.g. 0x0137 for 0xFF37).
uint16_t intervalRegister(uint32_t pgn);
// The data PGN whose interval the register holds, if it is one.
std::optional<uint32_t> pgnOfIntervalRegister(uint16_t reg);
bool validInterval(uint32_t ms);

// Baud codes of register 0x9A; 0 for an unknown code / -1 for an unknown rate.
int baudFromCode(uint32_t code);
int codeFromBaud(int bitrate);

struct RegMessage {
    uint8_t da = 0;     // destination (device for a request, host for a reply)
    uint8_t sa = 0;     // source
    uint16_t addr = 0;
    uint8_t cmd = CmdRead;
    uint8_t status = 0;
    uint32_t value = 0;
    friend bool operator==(const RegMessage &, const RegMessage &) = default;
};

CanFrame encodeReg(const RegMessage &m);
// Any frame with PGN 0xEF00 and 8 data bytes; nullopt otherwise.
std::optional<RegMessage> parseReg(const CanFrame &f);

// Builders of the manual's requests (host sa -> device da).
RegMessage readRequest(uint8_t da, uint8_t sa, uint16_t addr); // VAL = 1 (register count), as vendor tools send
RegMessage writeRequest(uint8_t da, uint8_t sa, uint16_t addr, uint32_t value);
RegMessage intervalRequest(uint8_t da, uint8_t sa, uint32_t pgn, uint32_t ms);
RegMessage triggerRequest(uint8_t da, uint8_t sa, uint32_t pgn);

// Does reply answer request (from the addressed device, or any device for a request to the
// broadcast address 255, to the requester; same ADDR and CMD)?
bool answers(const RegMessage &reply, const RegMessage &request);

// What a configuration frame means, e.g. "write PGN FF37 interval = 100 ms".
QString describe(const RegMessage &m);

} // namespace imudesk::protocol::can::j1939
