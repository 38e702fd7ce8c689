#pragma once
// One sweep of a bench (issue 56): every serial port and every CAN bus at once, each on its
// own, bounded in time and cancellable, writing no setting and leaving no port open.
//
// A serial port: the link opener's detection (every serial family at its rates, one open);
// a family found is identified through its own session, then closed. A port where no family
// answered is asked as a Modbus RTU line: the families' default ids at every documented rate
// first, then every id at the rates fastest first, until a device answers (a bus runs at one
// rate) or the time is up. A port another program holds is busy; one that sent bytes that
// formed no frame is garbage; one that sent nothing is silent.
//
// A CAN bus: listened to at each bit rate until one shows traffic and no error (an interface
// that takes no bit rate, as Qt's virtualcan, is listened to once), then the nodes are asked
// (CanSurvey) at that rate only; never at a rate that showed errors.
#include "discovery/can_survey.h"
#include "discovery/discovery_result.h"

#include <QElapsedTimer>
#include <QObject>
#include <QStringList>
#include <QTimer>

#include <memory>
#include <vector>

namespace imudesk::discovery {

struct SweepOptions {
    QStringList ports;           // serial ports to sweep beside the machine's (pseudo-terminals)
    bool machinePorts = true;    // every serial port QSerialPortInfo lists
    QStringList canBuses;        // PLUGIN:INTERFACE to sweep beside the machine's
    bool machineCan = true;      // every interface of the socketcan plugin
    bool serialFamilies = true;  // look for the serial families (false: Modbus only, as its scan dialog)
    bool modbus = true;          // ask silent ports as Modbus RTU lines
    int budgetMs = 60000;        // the whole sweep, at most
    QList<int> canBitrates;      // empty: the families' documented rates, the defaults first
    int canListenMs = 1200;      // per bit rate
    int canAnswerMs = 250;       // per question
};

class PortSweep;
class CanSweep;
struct SweepSink;

class BenchSweep : public QObject {
    Q_OBJECT
public:
    explicit BenchSweep(QObject *parent = nullptr);
    ~BenchSweep() override;

    // The ports and buses a sweep with these options looks at.
    static QStringList serialPortsOf(const SweepOptions &options);
    static QStringList canBusesOf(const SweepOptions &options);
    // The order a silent port is asked as a Modbus line in.
    static QList<std::pair<int, int>> modbusPlan(int *likelyCount = nullptr);
    // The bit rates a CAN bus is listened at: the factory rates first, then the rest fastest first.
    static QList<int> canBitratesToTry();

    void start(const SweepOptions &options);
    // Stops every probe now (ports closed); finished() follows with what was found so far.
    void cancel();
    bool running() const { return m_running; }
    const SweepResult &result() const { return m_result; }

Q_SIGNALS:
    // done / total in thousandths of the whole; what is happening now on one port or bus.
    void progress(int done, int total, const QString &port, const QString &detail);
    void deviceFound(const imudesk::discovery::FoundDevice &device);
    // Two devices at one address, as soon as it shows (before the devices it concerns).
    void conflictFound(const imudesk::discovery::Conflict &conflict);
    void finished();

private:
    void probeDone();
    SweepSink sinkFor(const QString &port);
    void finish(bool cancelled);
    void publishProgress(const QString &port, const QString &detail);

    SweepOptions m_options;
    std::vector<std::unique_ptr<PortSweep>> m_ports;
    std::vector<std::unique_ptr<CanSweep>> m_buses;
    QTimer m_budget;
    QElapsedTimer m_clock;
    SweepResult m_result;
    bool m_running = false;
};

} // namespace imudesk::discovery

Q_DECLARE_METATYPE(imudesk::discovery::FoundDevice)
Q_DECLARE_METATYPE(imudesk::discovery::Conflict)
