#pragma once
// Every setting a CAN device documents, with the request that reads it and the one that writes
// it, for the configuration panel and `imudesk-cli can get|set|config`: the counterpart of the
// serial settings catalogue (setting_catalog.h) on CAN.
//   * J1939 (v1.7.1 manual 7.22-7.23): registers read with the manual's read request (CMD 0x03)
//     and written with CMD 0x06: the data PGNs' intervals (0x0100 | PS), bit rate 0x9A, node
//     address 0x9C, output 0x9D, inclinometer signs 0x9E/0x9F, firmware version 0x78 (read only),
//     and the registers 7.22.41 maps to the Modbus register list (6.16), by the list's names:
//     UART1_BAUD, MD_ID and HEADING_MODE (read and written), the sensor registers 0x34..0x51,
//     PNAME, BL_VERSION and SN (read only), URFR 0xA6 (written only). Each J1939 register holds
//     one Modbus register (16 bits) in VAL; a value of several registers (R_H/R_L, PNAME, SN) is
//     read register by register and shown whole (CanSetting::showWords).
//   * HiPNUC CANopen (8.28): objects read by SDO upload and written by SDO download: the TPDO
//     channels' event timer (sub 5) and transmission type (sub 2, SYNC or not), heartbeat
//     0x1017, bit rate 0x209A, node ID 0x209C (0x20A0 on 1.6.6), inclinometer signs
//     0x209E/0x209F.
//   * HEC495 (its manual, "CAN 通讯协议"): objects written with "Write Object" (0x22); the manual
//     documents no read, so none is readable: ImuDesk says so instead of showing a guess.
// Values are shown and entered as a person thinks of them (bit/s, ms, 0/1), stored as the
// module's codes.
#include "protocol/can/can_decoder.h"

#include <QString>

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace imudesk::protocol::can {

struct CanSetting {
    enum class Access { J1939Register, CanOpenObject, Hec495Object };
    QString name;   // the CLI's name: "bitrate", "node-id", "interval-ff34", "tpdo1-period", ...
    QString label;  // what the panel calls it, translated
    QString unit;   // "ms", "bit/s" or empty
    Access access = Access::J1939Register;
    uint16_t address = 0; // register or object index
    uint8_t sub = 0;
    int size = 4;         // SDO download size in bytes
    bool readable = true;
    bool writable = true;
    QString note;         // when it takes effect, what limits it ("after save and reset")
    // The module's codes and what each means ("500000"); empty: the value is a number in
    // [min, max], the same on the wire.
    std::vector<std::pair<uint32_t, QString>> choices;
    uint32_t min = 0;
    uint32_t max = 0xFFFFFFFF;
    // How the value reads (a register of the Modbus list): a code or number as it is, a signed
    // 16- or 32-bit number times `scale` in `unit`, ASCII text (two characters a register, the
    // first in the high byte) or hex bytes; `words` consecutive registers hold it.
    enum class Format { Code, Signed16, Signed32, Ascii, Hex };
    Format format = Format::Code;
    double scale = 1.0;
    int words = 1;
    // Besides [min, max] or the choices: what else the module takes (nullptr: nothing else).
    bool (*accepts)(uint32_t raw) = nullptr;

    // The module's raw value as shown ("500000", "100", "-0.0156"); a code it does not document
    // as such.
    QString show(uint32_t raw) const;
    // A value of `words` registers, in register order (each register's 16 bits in the low half).
    QString showWords(const std::vector<uint32_t> &registers) const;
    // What a person typed ("500000", "500k", "0x64", "100") as the module's raw value;
    // nullopt with why when it is not one the module takes.
    std::optional<uint32_t> parse(const QString &text, QString *error) const;
    // "0-1", "5-1000 ms", "1000000, 800000, 500000, 250000, 125000"
    QString range() const;
};

// The settings of a device of that protocol. nodeIdObject: the HiPNUC CANopen firmware's
// node-ID object (0x209C on 1.7.x, 0x20A0 on 1.6.6); hec495Extended: the HEC495's
// extended-frame variant (its manual lists 30 kbit/s for that variant only).
std::vector<CanSetting> canSettings(protocol::can::CanProtocol protocol, uint16_t nodeIdObject = 0x209C,
                                    bool hec495Extended = false);
// The setting of that name (case-insensitive); nullopt when the protocol has none.
std::optional<CanSetting> findCanSetting(protocol::can::CanProtocol protocol, const QString &name,
                                         uint16_t nodeIdObject = 0x209C);

// The rates a bus of that protocol runs at, as its manual lists them (fastest first), and the
// device's factory rate. Auto: every rate any of them uses, 500 kbit/s first chosen.
struct CanBitrates {
    std::vector<int> rates;
    int factory = 500000;
};
CanBitrates canBitrates(protocol::can::CanProtocol protocol, bool hec495Extended = false);
// The bit rates an HEC495 takes (its object 0x1020): 30 kbit/s on the extended variant only.
bool hec495TakesBitrate(int bitrate, bool extended);

} // namespace imudesk::protocol::can
