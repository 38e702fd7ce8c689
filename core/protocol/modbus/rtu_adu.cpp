#include "rtu_adu.h"

#include <QModbusRequest>
#include <QModbusResponse>

namespace imudesk::protocol::modbus {

namespace {

constexpr int kMaxAdu = 256; // Modbus RTU: at most 256 bytes per ADU

template <typename Pdu>
RtuAdu::Parsed parse(const QByteArray &adu)
{
    RtuAdu::Parsed r;
    if (adu.size() < 4) {
        r.error = RtuAdu::Error::Incomplete;
        return r;
    }
    if (adu.size() > kMaxAdu) {
        r.error = RtuAdu::Error::TooLong;
        return r;
    }
    r.serverAddress = uint8_t(adu.at(0));
    // The size is known from the bytes after the function code (a byte count, a fixed length).
    const int dataSize = Pdu::calculateDataSize(Pdu(QModbusPdu::FunctionCode(uint8_t(adu.at(1))), adu.mid(2)));
    if (dataSize < 0) {
        r.error = RtuAdu::Error::UnknownFunction;
        return r;
    }
    r.expectedSize = 1 + 1 + dataSize + 2;
    if (adu.size() < r.expectedSize) {
        r.error = RtuAdu::Error::Incomplete;
        return r;
    }
    if (adu.size() > r.expectedSize) {
        r.error = RtuAdu::Error::TooLong;
        return r;
    }
    const uint16_t expected = uint16_t(uint8_t(adu.at(adu.size() - 2)) | (uint8_t(adu.at(adu.size() - 1)) << 8));
    if (RtuAdu::crc(reinterpret_cast<const uint8_t *>(adu.constData()), size_t(adu.size() - 2)) != expected) {
        r.error = RtuAdu::Error::CrcMismatch;
        return r;
    }
    r.functionCode = uint8_t(adu.at(1));
    r.data = adu.mid(2, adu.size() - 4);
    return r;
}

} // namespace

QModbusResponse RtuAdu::Parsed::response() const
{
    return QModbusResponse(QModbusPdu::FunctionCode(functionCode), data);
}

const char *RtuAdu::errorName(Error e)
{
    switch (e) {
    case Error::None: return "ok";
    case Error::Incomplete: return "incomplete";
    case Error::TooLong: return "too long";
    case Error::CrcMismatch: return "CRC mismatch";
    case Error::UnknownFunction: return "unknown function";
    }
    return "?";
}

uint16_t RtuAdu::crc(const uint8_t *data, size_t len)
{
    uint16_t c = 0xFFFF;
    for (size_t i = 0; i < len; ++i) {
        c ^= data[i];
        for (int bit = 0; bit < 8; ++bit)
            c = (c & 1) ? uint16_t((c >> 1) ^ 0xA001) : uint16_t(c >> 1);
    }
    return c;
}

uint16_t RtuAdu::crc(const QByteArray &bytes)
{
    return crc(reinterpret_cast<const uint8_t *>(bytes.constData()), size_t(bytes.size()));
}

QByteArray RtuAdu::frame(uint8_t serverAddress, const QModbusPdu &pdu)
{
    QByteArray out;
    out.append(char(serverAddress));
    out.append(char(pdu.isException() ? (pdu.functionCode() | QModbusPdu::ExceptionByte) : pdu.functionCode()));
    out.append(pdu.data());
    const uint16_t c = crc(out);
    out.append(char(c & 0xFF));
    out.append(char(c >> 8));
    return out;
}

QByteArray RtuAdu::readRequest(uint8_t serverAddress, uint16_t start, uint16_t count)
{
    return frame(serverAddress, QModbusRequest(QModbusPdu::ReadHoldingRegisters, quint16(start), quint16(count)));
}

QByteArray RtuAdu::writeSingleRequest(uint8_t serverAddress, uint16_t address, uint16_t value)
{
    return frame(serverAddress, QModbusRequest(QModbusPdu::WriteSingleRegister, quint16(address), quint16(value)));
}

RtuAdu::Parsed RtuAdu::parseResponse(const QByteArray &adu)
{
    return parse<QModbusResponse>(adu);
}

RtuAdu::Parsed RtuAdu::parseRequest(const QByteArray &adu)
{
    return parse<QModbusRequest>(adu);
}

std::optional<std::vector<uint16_t>> RtuAdu::readRegisters(const QModbusResponse &response)
{
    if (response.functionCode() != QModbusPdu::ReadHoldingRegisters || response.isException())
        return std::nullopt;
    const QByteArray d = response.data();
    if (d.isEmpty())
        return std::nullopt;
    const int count = uint8_t(d.at(0));
    if (count % 2 != 0 || d.size() != 1 + count)
        return std::nullopt;
    std::vector<uint16_t> regs(size_t(count / 2));
    for (size_t i = 0; i < regs.size(); ++i)
        regs[i] = uint16_t((uint8_t(d.at(int(1 + 2 * i))) << 8) | uint8_t(d.at(int(2 + 2 * i))));
    return regs;
}

QModbusResponse RtuAdu::readResponse(const std::vector<uint16_t> &registers)
{
    QByteArray d;
    d.append(char(registers.size() * 2));
    for (uint16_t r : registers) {
        d.append(char(r >> 8));
        d.append(char(r & 0xFF));
    }
    return QModbusResponse(QModbusPdu::ReadHoldingRegisters, d);
}

} // namespace imudesk::protocol::modbus
