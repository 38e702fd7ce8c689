#pragma once
// The values written by the manuals' configuration examples (v1.7.1 6.17, v1.6.6 4.3), as
// (register, value) pairs. The Modbus framing (ID, function 0x06, CRC) is QtSerialBus's.
#include "model/device_identity.h"

#include <QCoreApplication>

#include <cstdint>
#include <optional>
#include <vector>

namespace imudesk::protocol::modbus {

struct WriteRequest {
    uint16_t address = 0;
    uint16_t value = 0;
    friend bool operator==(const WriteRequest &, const WriteRequest &) = default;
};

class HipnucWrites {
    Q_DECLARE_TR_FUNCTIONS(HipnucWrites)

public:
    static WriteRequest save();          // CTRL = 0x0000
    static WriteRequest factoryReset();  // CTRL = 0x0001
    static WriteRequest reset();         // CTRL = 0x00FF
    // UART1_BAUD code for a baud (4800 -> 0 ... 921600 -> 8); nullopt for other rates.
    static std::optional<WriteRequest> baud(int baud);
    static const std::vector<int> &bauds();        // the table, by code
    static std::optional<int> baudForCode(uint16_t code);
    static std::optional<uint16_t> codeForBaud(int baud);
    // MD_ID, 1..128.
    static std::optional<WriteRequest> nodeId(int id);
    // HEADING_MODE: 0 = 6-axis, 1 = 9-axis.
    static WriteRequest headingMode(bool nineAxis);
    // ATT_RST / SET_LV: 2 starts levelling (the examples' value), 5 cancels.
    static WriteRequest autoLevel(bool on);
    // URFR for a mounting code: v1.7.1 writes the code itself (any of the 24), v1.6.6 the index
    // of the five mountings it knows (024, 043, 052, 520, 421 -> 0..4).
    static std::optional<WriteRequest> mounting(model::ManualEdition edition, int code);
    // The five mountings of the manuals' tables, in v1.6.6 index order.
    static const std::vector<int> &legacyMountings();
    // The mounting code a URFR register value means for an edition.
    static std::optional<int> mountingCode(model::ManualEdition edition, uint16_t value);
    // What a write does, for messages ("save the configuration to flash").
    static QString describe(const WriteRequest &w);
};

} // namespace imudesk::protocol::modbus
