#pragma once
// A QModbusRtuSerialServer that answers from a ModbusDeviceModel: Read Holding Registers
// (0x03) and Write Single Register (0x06); every other function is ILLEGAL FUNCTION.
// A write that changes the node ID or the baud takes effect after the reply went out (the
// reply carries the old ID, at the old rate), as on the device.
#include "sim/modbus_device_model.h"

#include <QElapsedTimer>
#include <QModbusRtuSerialServer>

namespace imudesk::sim {

class ModbusRtuServer : public QModbusRtuSerialServer {
    Q_OBJECT
public:
    // Time after a reply before a baud change: the reply is on its way by then.
    static constexpr int kBaudSwitchDelayMs = 50;

    explicit ModbusRtuServer(ModbusSimOptions options, QObject *parent = nullptr);

    ModbusDeviceModel &model() { return m_device; }
    int64_t nowUs() const { return m_clock.nsecsElapsed() / 1000; }
    // Opens portName at the device's running baud and node ID.
    bool listen(const QString &portName);

Q_SIGNALS:
    void nodeIdSwitched(int id);
    void baudSwitched(int baud);

protected:
    QModbusResponse processRequest(const QModbusPdu &request) override;

private:
    void applyEffects(const ModbusDeviceModel::Effects &effects);
    void switchBaud(int baud);

    ModbusDeviceModel m_device;
    QElapsedTimer m_clock;
};

} // namespace imudesk::sim
