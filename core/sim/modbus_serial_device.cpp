#include "modbus_serial_device.h"

#include "protocol/modbus/rtu_adu.h"

#include <QModbusRequest>
#include <QModbusResponse>

namespace imudesk::sim {

using protocol::modbus::RtuAdu;

ModbusSerialDevice::ModbusSerialDevice(ModbusSimOptions options)
    : m_model(options), m_nodeId(m_model.running().nodeId), m_baud(m_model.running().baud)
{
}

void ModbusSerialDevice::receive(const uint8_t *data, size_t n)
{
    m_in.append(reinterpret_cast<const char *>(data), qsizetype(n));
    while (!m_in.isEmpty()) {
        RtuAdu::Parsed p = RtuAdu::parseRequest(m_in.left(256));
        if (p.error == RtuAdu::Error::TooLong && p.expectedSize > 0)
            p = RtuAdu::parseRequest(m_in.left(p.expectedSize));
        if (p.error == RtuAdu::Error::Incomplete)
            return;
        if (!p.ok()) { // noise or a broken request: a device waits for the next frame gap
            m_in.clear();
            return;
        }
        const QByteArray adu = m_in.left(p.expectedSize);
        m_in.remove(0, p.expectedSize);
        if (p.serverAddress == m_nodeId)
            answer(adu);
    }
}

void ModbusSerialDevice::answer(const QByteArray &adu)
{
    ++m_requests;
    if (m_echo)
        send(adu);
    const RtuAdu::Parsed p = RtuAdu::parseRequest(adu);
    const QByteArray d = p.data;
    const auto word = [&d](int i) { return uint16_t((uint8_t(d.at(i)) << 8) | uint8_t(d.at(i + 1))); };
    QModbusResponse response;
    ModbusDeviceModel::Effects effects;
    if (p.functionCode == QModbusPdu::ReadHoldingRegisters && d.size() == 4) {
        const auto r = m_model.read(word(0), word(2), m_nowUs);
        response = r.exception ? QModbusExceptionResponse(QModbusPdu::ReadHoldingRegisters,
                                                          QModbusPdu::ExceptionCode(r.exception))
                               : RtuAdu::readResponse(r.values);
    } else if (p.functionCode == QModbusPdu::WriteSingleRegister && d.size() == 4) {
        const auto w = m_model.write(word(0), word(2), m_nowUs);
        response = w.exception ? QModbusExceptionResponse(QModbusPdu::WriteSingleRegister,
                                                          QModbusPdu::ExceptionCode(w.exception))
                               : QModbusResponse(QModbusPdu::WriteSingleRegister, d);
        effects = w.effects;
    } else {
        response = QModbusExceptionResponse(QModbusPdu::FunctionCode(p.functionCode), QModbusPdu::IllegalFunction);
    }
    QByteArray reply = RtuAdu::frame(uint8_t(m_nodeId), response);
    if (m_corrupt > 0) {
        --m_corrupt;
        reply[reply.size() - 1] = char(~uint8_t(reply.at(reply.size() - 1)));
    }
    send(reply);
    // After the reply: it went out with the old ID at the old rate.
    if (effects.nodeId)
        m_nodeId = *effects.nodeId;
    if (effects.baud)
        m_baud = *effects.baud;
}

void ModbusSerialDevice::send(const QByteArray &bytes)
{
    SerialSegment s;
    s.baud = m_baud;
    s.bytes.assign(bytes.begin(), bytes.end());
    s.chunk = ++m_chunk;
    s.chunkStart = s.chunkEnd = true;
    m_out.push_back(std::move(s));
}

void ModbusSerialDevice::advanceTo(int64_t nowUs)
{
    if (nowUs > m_nowUs)
        m_nowUs = nowUs;
}

std::vector<SerialSegment> ModbusSerialDevice::takeOutputSegments()
{
    return std::exchange(m_out, {});
}

} // namespace imudesk::sim
