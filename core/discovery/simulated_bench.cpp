#include "discovery/simulated_bench.h"

#include "sim/can_simulator.h"
#include "sim/hec495_simulator.h"
#include "sim/line_devices.h"
#include "sim/modbus_simulator.h"
#include "sim/pty_simulator.h"

#include <QCoreApplication>

namespace imudesk::discovery {

SimulatedBench::SimulatedBench(QString canInterface) : m_canInterface(std::move(canInterface)) {}

SimulatedBench::~SimulatedBench()
{
    stop();
}

bool SimulatedBench::start(QString *error)
{
    stop();
    const auto failed = [this, error](const QString &what, const QString &why) {
        if (error)
            *error = QCoreApplication::translate("imudesk::discovery::SimulatedBench", "%1 could not start: %2").arg(what, why);
        stop();
        return false;
    };
    QString why;
    sim::SimOptions hipnuc;
    hipnuc.baud = 460800;
    hipnuc.seed = 56;
    m_ptys.push_back(std::make_unique<sim::PtySimulator>(hipnuc));
    sim::Hec495Options hec;
    hec.baud = 4800;
    hec.address = 7;
    m_ptys.push_back(std::make_unique<sim::PtySimulator>(std::make_unique<sim::Hec495Simulator>(hec)));
    m_ptys.push_back(std::make_unique<sim::PtySimulator>(std::make_unique<sim::SilentLine>()));
    for (auto &p : m_ptys)
        if (!p->start(&why))
            return failed(QCoreApplication::translate("imudesk::discovery::SimulatedBench", "A simulated serial device"), why);
    sim::ModbusSimOptions mb;
    mb.nodeId = 17;
    mb.baud = 38400;
    m_modbus = std::make_unique<sim::ModbusSimulator>(mb);
    if (!m_modbus->start(&why))
        return failed(QCoreApplication::translate("imudesk::discovery::SimulatedBench", "The simulated Modbus module"), why);
    if (!m_canInterface.isEmpty()) {
        sim::CanSimOptions j;
        j.protocol = protocol::can::CanProtocol::J1939;
        j.node = 12;
        sim::CanSimOptions a;
        a.protocol = protocol::can::CanProtocol::CanOpen;
        a.node = 5;
        a.seed = 3;
        sim::CanSimOptions b = a;
        b.seed = 4;
        b.firmware = "1.6.6";
        for (const auto &o : {j, a, b}) {
            m_can.push_back(std::make_unique<sim::CanSimulator>(o));
            if (!m_can.back()->start(QStringLiteral("virtualcan"), m_canInterface, &why))
                return failed(QCoreApplication::translate("imudesk::discovery::SimulatedBench", "A simulated CAN module"), why);
        }
    }
    return true;
}

void SimulatedBench::stop()
{
    for (auto &c : m_can)
        c->stop();
    m_can.clear();
    if (m_modbus)
        m_modbus->stop();
    m_modbus.reset();
    for (auto &p : m_ptys)
        p->stop();
    m_ptys.clear();
}

QString SimulatedBench::hipnucPort() const
{
    return m_ptys.size() > 0 ? m_ptys[0]->devicePath() : QString();
}

QString SimulatedBench::hec495Port() const
{
    return m_ptys.size() > 1 ? m_ptys[1]->devicePath() : QString();
}

QString SimulatedBench::silentPort() const
{
    return m_ptys.size() > 2 ? m_ptys[2]->devicePath() : QString();
}

QString SimulatedBench::modbusPort() const
{
    return m_modbus ? m_modbus->devicePath() : QString();
}

QStringList SimulatedBench::ports() const
{
    return {hipnucPort(), hec495Port(), modbusPort(), silentPort()};
}

QStringList SimulatedBench::canBuses() const
{
    return m_canInterface.isEmpty() || m_can.empty() ? QStringList{} : QStringList{QStringLiteral("virtualcan:") + m_canInterface};
}

} // namespace imudesk::discovery
