#pragma once
// A bench of simulated devices for the sweep to find (the window's demo, bench_discover, the
// tests), each at a rate and address that is not its factory one: a HiPNUC module at 460800
// baud, an HEC495 compass at 4800 baud with address 7, a HiPNUC Modbus module at 38400 baud
// with id 17, a port where nothing answers, and on one virtualcan bus a J1939 module (address
// 12) and two CANopen modules that both took node 5 (the conflict).
#include <QString>
#include <QStringList>

#include <memory>
#include <vector>

namespace imudesk::sim {
class CanSimulator;
class ModbusSimulator;
class PtySimulator;
}

namespace imudesk::discovery {

class SimulatedBench {
public:
    // canInterface: the virtualcan interface ("can1", or "tcp://127.0.0.1:PORT/can0" for a
    // server of one's own); empty: no CAN bus.
    explicit SimulatedBench(QString canInterface = QStringLiteral("can1"));
    ~SimulatedBench();
    SimulatedBench(const SimulatedBench &) = delete;
    SimulatedBench &operator=(const SimulatedBench &) = delete;

    // Starts every device; false with why when one cannot start (the others are stopped).
    bool start(QString *error);
    void stop();

    // The serial ports, in the order above (HiPNUC, HEC495, Modbus, silent).
    QStringList ports() const;
    // "virtualcan:<interface>", or empty.
    QStringList canBuses() const;
    QString hipnucPort() const;
    QString hec495Port() const;
    QString modbusPort() const;
    QString silentPort() const;

private:
    QString m_canInterface;
    std::vector<std::unique_ptr<sim::PtySimulator>> m_ptys;
    std::unique_ptr<sim::ModbusSimulator> m_modbus;
    std::vector<std::unique_ptr<sim::CanSimulator>> m_can;
};

} // namespace imudesk::discovery
