#pragma once
// A simulated Modbus RTU device (HiPNUC module or HEC495 compass) on a pseudo-terminal.
// A ModbusRtuServer (QModbusRtuSerialServer over ModbusDeviceModel) runs in its own QThread
// and opens the server side of a PtyBridge; clients open devicePath() like an RS-485 adapter.
// The bridge models the line (speed mismatch, wire time) and records the bytes.
#include "sim/modbus_device_model.h"
#include "sim/pty_bridge.h"

#include <QCoreApplication>
#include <QString>

#include <functional>
#include <memory>

QT_BEGIN_NAMESPACE
class QThread;
QT_END_NAMESPACE

namespace imudesk::sim {

class ModbusRtuServer;

class ModbusSimulator {
    Q_DECLARE_TR_FUNCTIONS(ModbusSimulator)

public:
    explicit ModbusSimulator(ModbusSimOptions options = {});
    ~ModbusSimulator();
    ModbusSimulator(const ModbusSimulator &) = delete;
    ModbusSimulator &operator=(const ModbusSimulator &) = delete;

    // Creates the pseudo-terminals and starts the server; blocks until it listens.
    bool start(QString *error = nullptr);
    void stop();
    bool isRunning() const { return m_thread != nullptr; }
    // The path a client opens (/dev/pts/N).
    QString devicePath() const { return m_bridge.clientPath(); }
    PtyBridge &bridge() { return m_bridge; }
    // Runs fn on the server thread with the device model and waits.
    void withDevice(const std::function<void(ModbusDeviceModel &)> &fn);
    // The node ID and baud the server currently answers at.
    int nodeId();
    int baud();

private:
    ModbusSimOptions m_options;
    PtyBridge m_bridge;
    QThread *m_thread = nullptr;
    ModbusRtuServer *m_server = nullptr; // lives in m_thread
};

} // namespace imudesk::sim
