#include "modbus_simulator.h"

#include "jobs/thread_sync.h"
#include "sim/modbus_rtu_server.h"

#include <QLoggingCategory>
#include <QThread>

namespace imudesk::sim {

namespace {
Q_LOGGING_CATEGORY(lcModbusSimulator, "imudesk.core.sim.modbussimulator", QtInfoMsg)
} // namespace

ModbusSimulator::ModbusSimulator(ModbusSimOptions options) : m_options(std::move(options)) {}

ModbusSimulator::~ModbusSimulator()
{
    stop();
}

bool ModbusSimulator::start(QString *error)
{
    if (m_thread)
        return true;
    if (!m_bridge.start(error))
        return false;
    m_thread = new QThread;
    m_thread->setObjectName(QStringLiteral("modbus-simulator"));
    m_server = new ModbusRtuServer(m_options);
    m_server->moveToThread(m_thread);
    jobs::announceJoin(*m_thread);
    m_thread->start();
    bool ok = false;
    QString why;
    ModbusRtuServer *server = m_server;
    const QString path = m_bridge.serverPath();
    jobs::callAndWait(m_server, [server, path, &ok, &why] {
        ok = server->listen(path);
        if (!ok)
            why = server->errorString();
    });
    if (!ok) {
        if (error)
            *error = tr("The simulated Modbus device could not open %1: %2").arg(path, why);
        stop();
        return false;
    }
    qCInfo(lcModbusSimulator) << "simulated Modbus device on" << devicePath();
    return true;
}

void ModbusSimulator::stop()
{
    if (m_thread) {
        ModbusRtuServer *server = m_server;
        jobs::callAndWait(m_server, [server] {
            server->disconnectDevice();
            delete server;
        });
        m_server = nullptr;
        jobs::joinThread(*m_thread);
        delete m_thread;
        m_thread = nullptr;
    }
    m_bridge.stop();
}

void ModbusSimulator::withDevice(const std::function<void(ModbusDeviceModel &)> &fn)
{
    if (!m_thread)
        return;
    ModbusRtuServer *server = m_server;
    jobs::callAndWait(m_server, [server, &fn] { fn(server->model()); });
}

int ModbusSimulator::nodeId()
{
    int id = 0;
    if (m_thread) {
        ModbusRtuServer *server = m_server;
        jobs::callAndWait(m_server, [server, &id] { id = server->serverAddress(); });
    }
    return id;
}

int ModbusSimulator::baud()
{
    int b = 0;
    if (m_thread) {
        ModbusRtuServer *server = m_server;
        jobs::callAndWait(m_server, [server, &b] { b = server->connectionParameter(QModbusDevice::SerialBaudRateParameter).toInt(); });
    }
    return b;
}

} // namespace imudesk::sim
