#pragma once
// Modbus RTU application data units (server address, PDU, CRC-16/Modbus low byte first) as
// bytes: the live session's requests and replies (device::ModbusFamily), golden frames from
// the manuals, what a pseudo-terminal bridge carried, and fuzzing. The simulator's server is
// QtSerialBus's QModbusRtuSerialServer. Nothing here sends or receives.
#include <QByteArray>
#include <QModbusPdu>
#include <QModbusResponse>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace imudesk::protocol::modbus {

class RtuAdu {
public:
    enum class Error { None, Incomplete, TooLong, CrcMismatch, UnknownFunction };
    static const char *errorName(Error e);

    struct Parsed {
        Error error = Error::None;
        uint8_t serverAddress = 0;
        uint8_t functionCode = 0; // as sent (0x80 set for an exception)
        QByteArray data;          // the PDU after the function code; valid when error == None
        int expectedSize = 0;    // the ADU length the header declares (0 when unknown)
        bool ok() const { return error == Error::None; }
        QModbusResponse response() const;
    };

    // CRC-16/Modbus (poly 0xA001 reflected, init 0xFFFF): check("123456789") == 0x4B37.
    static uint16_t crc(const uint8_t *data, size_t len);
    static uint16_t crc(const QByteArray &bytes);

    static QByteArray frame(uint8_t serverAddress, const QModbusPdu &pdu);
    static QByteArray readRequest(uint8_t serverAddress, uint16_t start, uint16_t count);
    static QByteArray writeSingleRequest(uint8_t serverAddress, uint16_t address, uint16_t value);

    // One whole ADU (the bytes of one frame, nothing more) as a response or a request.
    static Parsed parseResponse(const QByteArray &adu);
    static Parsed parseRequest(const QByteArray &adu);

    // The registers of a Read Holding Registers (0x03) response PDU; nullopt when the byte
    // count is odd or does not match the data.
    static std::optional<std::vector<uint16_t>> readRegisters(const QModbusResponse &response);
    // A 0x03 response PDU carrying the registers.
    static QModbusResponse readResponse(const std::vector<uint16_t> &registers);
};

} // namespace imudesk::protocol::modbus
