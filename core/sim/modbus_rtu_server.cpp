#include "modbus_rtu_server.h"

#include "protocol/modbus/rtu_adu.h"

#include <QLoggingCategory>
#include <QSerialPort>
#include <QTimer>

namespace imudesk::sim {

namespace {
Q_LOGGING_CATEGORY(lcModbusSim, "imudesk.core.sim.modbus", QtInfoMsg)
} // namespace

ModbusRtuServer::ModbusRtuServer(ModbusSimOptions options, QObject *parent)
    : QModbusRtuSerialServer(parent), m_device(std::move(options))
{
    m_clock.start();
}

bool ModbusRtuServer::listen(const QString &portName)
{
    setConnectionParameter(QModbusDevice::SerialPortNameParameter, portName);
    setConnectionParameter(QModbusDevice::SerialBaudRateParameter, m_device.running().baud);
    setConnectionParameter(QModbusDevice::SerialDataBitsParameter, QSerialPort::Data8);
    setConnectionParameter(QModbusDevice::SerialParityParameter, QSerialPort::NoParity);
    setConnectionParameter(QModbusDevice::SerialStopBitsParameter, QSerialPort::OneStop);
    setServerAddress(m_device.running().nodeId);
    return connectDevice();
}

QModbusResponse ModbusRtuServer::processRequest(const QModbusPdu &request)
{
    const QByteArray d = request.data();
    if (request.functionCode() == QModbusPdu::ReadHoldingRegisters && d.size() == 4) {
        const uint16_t start = uint16_t((uint8_t(d[0]) << 8) | uint8_t(d[1]));
        const uint16_t count = uint16_t((uint8_t(d[2]) << 8) | uint8_t(d[3]));
        const auto r = m_device.read(start, count, nowUs());
        if (r.exception != 0)
            return QModbusExceptionResponse(request.functionCode(), QModbusPdu::ExceptionCode(r.exception));
        return protocol::modbus::RtuAdu::readResponse(r.values);
    }
    if (request.functionCode() == QModbusPdu::WriteSingleRegister && d.size() == 4) {
        const uint16_t address = uint16_t((uint8_t(d[0]) << 8) | uint8_t(d[1]));
        const uint16_t value = uint16_t((uint8_t(d[2]) << 8) | uint8_t(d[3]));
        const auto w = m_device.write(address, value, nowUs());
        if (w.exception != 0)
            return QModbusExceptionResponse(request.functionCode(), QModbusPdu::ExceptionCode(w.exception));
        applyEffects(w.effects);
        return QModbusResponse(request.functionCode(), d);
    }
    return QModbusExceptionResponse(request.functionCode(), QModbusPdu::IllegalFunction);
}

void ModbusRtuServer::applyEffects(const ModbusDeviceModel::Effects &effects)
{
    if (effects.nodeId) {
        const int id = *effects.nodeId;
        // Queued: the reply being built now still carries the old address.
        QTimer::singleShot(0, this, [this, id] {
            setServerAddress(id);
            qCInfo(lcModbusSim) << "node ID now" << id;
            Q_EMIT nodeIdSwitched(id);
        });
    }
    if (effects.baud) {
        const int baud = *effects.baud;
        QTimer::singleShot(kBaudSwitchDelayMs, this, [this, baud] { switchBaud(baud); });
    }
}

void ModbusRtuServer::switchBaud(int baud)
{
    setConnectionParameter(QModbusDevice::SerialBaudRateParameter, baud);
    if (auto *port = qobject_cast<QSerialPort *>(device())) {
        port->flush();
        port->setBaudRate(baud);
    }
    qCInfo(lcModbusSim) << "baud now" << baud;
    Q_EMIT baudSwitched(baud);
}

} // namespace imudesk::sim
